// Polynomial roots from the balanced companion matrix (see roots.hpp for the contract).
#include "nanopush/roots.hpp"

#include <Eigen/Dense>

namespace nanopush::roots {

double polyval(const std::vector<double>& c, double x) {
  double p = 0.0;
  for (auto it = c.rbegin(); it != c.rend(); ++it) p = p * x + *it;
  return p;
}

double polyscale(const std::vector<double>& c, double x) {
  double p = 0.0;
  const double ax = std::fabs(x);
  for (auto it = c.rbegin(); it != c.rend(); ++it) p = p * ax + std::fabs(*it);
  return p;
}

PolynomialRoots polynomial_roots(const std::vector<double>& c_in) {
  for (std::size_t i = 0; i < c_in.size(); ++i)
    require_finite("polynomial coefficient c[" + std::to_string(i) + "]", c_in[i]);
  std::vector<double> c = c_in;
  PolynomialRoots out;
  // Deflate the leading coefficient while it is zero or so small that the monic
  // companion matrix would overflow: those roots are at infinity.
  const double big = std::numeric_limits<double>::max() / 16.0;
  while (!c.empty()) {
    const double lead = c.back();
    bool infinite = (lead == 0.0);
    if (!infinite)
      for (std::size_t i = 0; i + 1 < c.size(); ++i)
        if (std::fabs(c[i]) > big * std::fabs(lead)) { infinite = true; break; }
    if (!infinite) break;
    c.pop_back();
    ++out.at_infinity;
  }
  if (c.empty()) throw InputError("polynomial coefficients", "all zero", "at least one coefficient must be non-zero");
  // Zero roots: trailing zero constant terms.
  std::size_t zeros = 0;
  while (zeros + 1 < c.size() && c[zeros] == 0.0) ++zeros;
  for (std::size_t i = 0; i < zeros; ++i) out.roots.emplace_back(0.0, 0.0);
  c.erase(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(zeros));
  const int n = static_cast<int>(c.size()) - 1;
  if (n >= 1) {
    // Companion matrix of the monic polynomial: last row... we use the
    // "upper Hessenberg, first row" form: A(0, j) = -c[n-1-j]/c[n], ones on the subdiagonal.
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    for (int j = 0; j < n; ++j) A(0, j) = -c[static_cast<std::size_t>(n - 1 - j)] / c[static_cast<std::size_t>(n)];
    for (int i = 1; i < n; ++i) A(i, i - 1) = 1.0;
    balance_matrix(A);
    Eigen::EigenSolver<Eigen::MatrixXd> es(A, /*computeEigenvectors=*/false);
    if (es.info() != Eigen::Success) throw SolverError("companion-matrix eigenvalues: Eigen's QR iteration did not converge");
    for (int i = 0; i < n; ++i) out.roots.push_back(es.eigenvalues()(i));
  }
  std::sort(out.roots.begin(), out.roots.end(), [](const auto& x, const auto& y) {
    return x.real() < y.real() || (x.real() == y.real() && x.imag() < y.imag());
  });
  return out;
}

}  // namespace nanopush::roots
