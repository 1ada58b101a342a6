// Polynomial roots from the balanced companion matrix (see roots.hpp for the contract).
#include "nanopush/numerics/roots.hpp"

#include <cmath>

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

double polyval_scaled(const std::vector<double>& c, double x) {
  if (std::fabs(x) <= 1.0) return polyval(c, x);
  const double u = 1.0 / x;
  double p = 0.0;
  for (double ci : c) p = p * u + ci;  // sum c_i u^(n-i) = p(x) / x^n
  const bool odd = (c.size() - 1) % 2 == 1;
  return (odd && x < 0.0) ? -p : p;
}

double poly_relative_residual(const std::vector<double>& c, double x) {
  double num, den;
  if (std::fabs(x) <= 1.0) {
    num = std::fabs(polyval(c, x));
    den = polyscale(c, x);
  } else {
    const double u = 1.0 / x;
    num = 0.0;
    den = 0.0;
    for (double ci : c) {
      num = num * u + ci;
      den = den * std::fabs(u) + std::fabs(ci);
    }
    num = std::fabs(num);
  }
  return den > 0.0 ? num / den : 0.0;
}

namespace {
/// Eigenvalues of the balanced companion matrix of c (ascending, c.back() != 0).
std::vector<std::complex<double>> companion_eigenvalues(const std::vector<double>& c) {
  const int n = static_cast<int>(c.size()) - 1;
  std::vector<std::complex<double>> out;
  if (n < 1) return out;
  // First-row form: A(0, j) = -c[n-1-j]/c[n], ones on the subdiagonal.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) A(0, j) = -c[static_cast<std::size_t>(n - 1 - j)] / c[static_cast<std::size_t>(n)];
  for (int i = 1; i < n; ++i) A(i, i - 1) = 1.0;
  // A root near the overflow threshold (the constrained cubic at a subnormal yn: ~1e300) leaves
  // entries whose squares overflow in the balancing and the QR iteration, which then fails.
  // Scaled by a power of two to a largest entry of order 1, the eigenvalues scale exactly;
  // they are scaled back.
  int scale = 0;
  const double amax = A.cwiseAbs().maxCoeff();
  if (amax > 1e150) {
    scale = std::ilogb(amax);
    A *= std::ldexp(1.0, -scale);
  }
  balance_matrix(A);
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, /*computeEigenvectors=*/false);
  if (es.info() != Eigen::Success) throw SolverError("companion-matrix eigenvalues: Eigen's QR iteration did not converge");
  for (int i = 0; i < n; ++i) {
    const std::complex<double> ev = es.eigenvalues()(i);
    out.emplace_back(std::ldexp(ev.real(), scale), std::ldexp(ev.imag(), scale));
  }
  return out;
}
}  // namespace

int deflate_roots_at_infinity(std::vector<double>& c) {
  // Deflate the leading coefficient while it is zero or so small that the monic
  // companion matrix would overflow: those roots are at infinity.
  const double big = std::numeric_limits<double>::max() / 16.0;
  int at_infinity = 0;
  while (!c.empty()) {
    const double lead = c.back();
    bool infinite = (lead == 0.0);
    if (!infinite)
      for (std::size_t i = 0; i + 1 < c.size(); ++i)
        if (std::fabs(c[i]) > big * std::fabs(lead)) { infinite = true; break; }
    if (!infinite) break;
    c.pop_back();
    ++at_infinity;
  }
  if (c.empty()) throw InputError("polynomial coefficients", "all zero", "at least one coefficient must be non-zero");
  return at_infinity;
}

PolynomialRoots polynomial_roots(const std::vector<double>& c_in) {
  for (std::size_t i = 0; i < c_in.size(); ++i)
    require_finite("polynomial coefficient c[" + std::to_string(i) + "]", c_in[i]);
  std::vector<double> c = c_in;
  PolynomialRoots out;
  out.at_infinity = deflate_roots_at_infinity(c);
  // Zero roots: trailing zero constant terms.
  std::size_t zeros = 0;
  while (zeros + 1 < c.size() && c[zeros] == 0.0) ++zeros;
  for (std::size_t i = 0; i < zeros; ++i) out.roots.emplace_back(0.0, 0.0);
  c.erase(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(zeros));
  const std::size_t n = c.size() - 1;
  if (n >= 1) {
    auto big_roots = companion_eigenvalues(c);
    std::vector<double> rev(c.rbegin(), c.rend());  // x^n p(1/x); rev.back() = c[0] != 0
    bool rev_ok = true;  // the reversed companion matrix must not overflow either
    const double big = std::numeric_limits<double>::max() / 16.0;  // as deflate_roots_at_infinity
    for (std::size_t i = 0; i + 1 < rev.size(); ++i)
      if (std::fabs(rev[i]) > big * std::fabs(rev.back())) rev_ok = false;
    auto inv = rev_ok ? companion_eigenvalues(rev) : std::vector<std::complex<double>>{};
    // Roots of modulus > 1 from p's matrix, the others as 1/mu from the reversed matrix.
    std::sort(big_roots.begin(), big_roots.end(), [](auto& x, auto& y) { return std::abs(x) > std::abs(y); });
    std::sort(inv.begin(), inv.end(), [](auto& x, auto& y) { return std::abs(x) > std::abs(y); });
    std::size_t k = 0;
    while (k < n && (std::abs(big_roots[k]) > 1.0 || !rev_ok)) ++k;
    for (std::size_t i = 0; i < k; ++i) out.roots.push_back(big_roots[i]);
    for (std::size_t i = 0; i < n - k; ++i) out.roots.push_back(1.0 / inv[i]);
  }
  std::sort(out.roots.begin(), out.roots.end(), [](const auto& x, const auto& y) {
    return x.real() < y.real() || (x.real() == y.real() && x.imag() < y.imag());
  });
  return out;
}

}  // namespace nanopush::roots
