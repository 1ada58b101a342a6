// Adaptive Gauss-Kronrod cubature, independent of the closed forms it checks.
//
// 1-D: globally adaptive Gauss-Kronrod 7/15 (the QUADPACK QAG scheme without extrapolation;
// Piessens, de Doncker-Kapenga, Ueberhuber & Kahaner, QUADPACK, Springer 1983, rule qk15):
// the interval with the largest error estimate |K15 - G7| is bisected until the summed
// estimate falls below the absolute tolerance. Caller-supplied break points (singular points
// such as the iCOR coordinate) start the subdivision, so a kink or an endpoint singularity
// never falls inside a panel: the nodes of every panel are interior, so the integrand is never
// evaluated at a break point. Vector integrands share the subdivision (error = max component).
//
// 2-D over a rectangle: nested 1-D rules (outer in x, inner in y), each with break points.
// Not a hot path: it allocates (the panel list) and is meant for tests, references and
// non-uniform pressure distributions.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace nanopush::cubature {

/// Kronrod 15-point nodes on [-1, 1] (x >= 0 half; odd indices are the Gauss 7-point nodes).
inline constexpr double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                   0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                   0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                   0.207784955007898467600689403773245, 0.0};
inline constexpr double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                   0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                   0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                   0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
inline constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                  0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

template <std::size_t N>
struct Result {
  std::array<double, N> value{};
  double error = 0.0;   ///< estimated absolute error (max over components)
  long evaluations = 0;
  bool converged = false;
};

/// One GK15 panel of f over [lo, hi]: Kronrod estimate and |K - G| per component.
template <std::size_t N, class F>
void gk15_panel(F& f, double lo, double hi, std::array<double, N>& k, double& err) {
  const double c = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
  std::array<double, N> g{}, fv{}, fw{};
  k.fill(0.0);
  f(c, fv.data());
  for (std::size_t n = 0; n < N; ++n) {
    k[n] = kWgk[7] * fv[n];
    g[n] = kWg[3] * fv[n];
  }
  for (int i = 0; i < 7; ++i) {
    const double dx = h * kXgk[i];
    f(c - dx, fv.data());
    f(c + dx, fw.data());
    for (std::size_t n = 0; n < N; ++n) {
      const double s = fv[n] + fw[n];
      k[n] += kWgk[i] * s;
      if (i % 2 == 1) g[n] += kWg[i / 2] * s;
    }
  }
  err = 0.0;
  for (std::size_t n = 0; n < N; ++n) {
    k[n] *= h;
    err = std::max(err, std::fabs(k[n] - h * g[n]));
  }
}

/// Globally adaptive GK15 integral of the N-vector function f(x, double* out) over [lo, hi],
/// with optional break points (those outside (lo, hi) are ignored). Stops when the summed
/// error estimate is <= abstol or after max_panels panels (converged = false).
template <std::size_t N, class F>
Result<N> integrate(F&& f, double lo, double hi, const std::vector<double>& breaks, double abstol,
                    int max_panels = 2000) {
  struct Panel {
    double lo, hi, err;
    std::array<double, N> k;
  };
  std::vector<double> pts{lo};
  for (double b : breaks)
    if (b > lo && b < hi) pts.push_back(b);
  pts.push_back(hi);
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());

  std::vector<Panel> panels;
  panels.reserve(64);
  Result<N> res;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    Panel p{pts[i], pts[i + 1], 0.0, {}};
    gk15_panel<N>(f, p.lo, p.hi, p.k, p.err);
    res.evaluations += 15;
    panels.push_back(p);
  }
  for (;;) {
    double total = 0.0;
    std::size_t worst = 0;
    for (std::size_t i = 0; i < panels.size(); ++i) {
      total += panels[i].err;
      if (panels[i].err > panels[worst].err) worst = i;
    }
    if (total <= abstol) {
      res.converged = true;
      res.error = total;
      break;
    }
    const Panel w = panels[worst];
    const double mid = 0.5 * (w.lo + w.hi);
    if (static_cast<int>(panels.size()) >= max_panels || !(mid > w.lo && mid < w.hi)) {
      res.error = total;
      break;
    }
    Panel left{w.lo, mid, 0.0, {}}, right{mid, w.hi, 0.0, {}};
    gk15_panel<N>(f, left.lo, left.hi, left.k, left.err);
    gk15_panel<N>(f, right.lo, right.hi, right.k, right.err);
    res.evaluations += 30;
    panels[worst] = left;
    panels.push_back(right);
  }
  res.value.fill(0.0);
  for (const auto& p : panels)
    for (std::size_t n = 0; n < N; ++n) res.value[n] += p.k[n];
  return res;
}

/// Nested adaptive integral over [x0, x1] x [y0, y1] of g(x, y, double* out) (N components),
/// with break points xb (outer) and yb (inner). The inner tolerance is chosen so that the
/// accumulated inner error is at most a tenth of abstol.
template <std::size_t N, class G>
Result<N> integrate_rectangle(G&& g, double x0, double x1, double y0, double y1, const std::vector<double>& xb,
                              const std::vector<double>& yb, double abstol, int max_panels = 2000) {
  const double inner_tol = 0.1 * abstol / (x1 - x0);
  long inner_evals = 0;
  bool inner_ok = true;
  double inner_err = 0.0;
  auto outer = [&](double x, double* out) {
    auto r = integrate<N>([&](double y, double* o) { g(x, y, o); }, y0, y1, yb, inner_tol, max_panels);
    inner_evals += r.evaluations;
    inner_ok = inner_ok && r.converged;
    inner_err = std::max(inner_err, r.error);
    for (std::size_t n = 0; n < N; ++n) out[n] = r.value[n];
  };
  auto res = integrate<N>(outer, x0, x1, xb, 0.9 * abstol, max_panels);
  res.evaluations = inner_evals;
  res.converged = res.converged && inner_ok;
  res.error += inner_err * (x1 - x0);
  return res;
}

}  // namespace nanopush::cubature
