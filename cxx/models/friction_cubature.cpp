// Adaptive cubature reference for the friction wrench (friction_cubature.hpp).
#include "nanopush/models/friction_cubature.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "nanopush/numerics/cubature.hpp"
#include "nanopush/numerics/error.hpp"

namespace nanopush {

namespace {

/// u asinh(v/|u|), 0 at u = 0 (the limit), no overflow for tiny |u|.
double x_asinh(double u, double v) {
  const double au = std::fabs(u);
  if (au == 0.0) return 0.0;
  const double q = v / au;
  if (std::fabs(q) < 1e150) return u * std::asinh(q);
  return std::copysign(u * (std::log(2.0 * std::fabs(v)) - std::log(au)), v);
}

struct Scaled {
  double L, a, b, xc, yc;  // lengths in units of L = max(a, b); (xc, yc) = CM seen from the iCOR
};

Scaled scale(double a, double b, double R, double alpha, int sense) {
  (void)rectangle_friction_wrench_checked(a, b, 0.0, R, alpha, sense);  // validates the inputs
  const double L = a > b ? a : b;
  return {L, a / L, b / L, (R / L) * std::cos(alpha), (R / L) * std::sin(alpha)};
}

FrictionCubatureResult finish(const Scaled& s, double muN, int sense, double ix, double iy, double km,
                              double err, long evals, bool ok) {
  FrictionCubatureResult r;
  const double sg = sense < 0 ? -1.0 : 1.0;
  r.wrench = {muN * sg * iy, -muN * sg * ix, -muN * sg * km * s.L};
  r.error_force = muN * err;
  r.error_moment = muN * err * s.L;
  r.evaluations = evals;
  r.converged = ok;
  return r;
}

}  // namespace

namespace {

/// Point-symmetrised integrand over the half rectangle x in [0, a]: the contributions of
/// (x, y) and (-x, -y) are summed before integration, with the odd part of the moment
/// integrand cancelled analytically (see docs/friction.md):
///   out = {p+ X+/r+ + p- X-/r-,  p+ Y+/r+ + p- Y-/r-,  p+ h+ + p- h-,  p+ + p-}
/// with h = (x X + y Y)/r, h+- = (rho^2 +- d)/r+-, d = x Xc + y Yc, e = x Yc - y Xc.
template <class Pr>
void pair_integrand(const Scaled& s, Pr& pressure, double x, double y, double* out) {
  const double pp = pressure(x, y), pm = pressure(-x, -y);
  const double xp = s.xc + x, yp = s.yc + y, xm = s.xc - x, ym = s.yc - y;
  const double rp = std::sqrt(xp * xp + yp * yp), rm = std::sqrt(xm * xm + ym * ym);
  // r = 0 only at the iCOR itself (a point of measure zero, reached through rounding when the
  // iCOR sits on a break point): its contribution is dropped.
  const double ip = rp > 0.0 ? 1.0 / rp : 0.0, im = rm > 0.0 ? 1.0 / rm : 0.0;
  const double d = x * s.xc + y * s.yc, e = x * s.yc - y * s.xc, rho2 = x * x + y * y;
  const double R2 = s.xc * s.xc + s.yc * s.yc, rr = rp * rm;
  // h(+) + h(-) for equal pressures: for a distant iCOR (R >= 2 max(a,b) > rho) as a sum of
  // non-negative terms; near the contact the direct form (no cancellation there).
  const double hsum = R2 >= 4.0 ? e * e / R2 * (ip + im) + 8.0 * d * d * e * e / (R2 * rr * (rp + rm) * (rr + R2 - rho2))
                                 : rho2 * (ip + im) - 4.0 * d * d * ip * im / (rp + rm);
  out[0] = pp * xp * ip + pm * xm * im;
  out[1] = pp * yp * ip + pm * ym * im;
  out[2] = pm * hsum + (pp - pm) * (rho2 + d) * ip;
  out[3] = pp + pm;
}

template <class Pr>
FrictionCubatureResult pair_cubature(const Scaled& s, double muN, int sense, Pr& pressure, double tol,
                                     double ptot_estimate) {
  // Break points: the iCOR (-xc, -yc) and its mirror (xc, yc), seen from the half rectangle.
  const std::vector<double> xb = {std::fabs(s.xc)}, yb = {-s.yc, s.yc};
  auto g = [&](double x, double y, double* out) { pair_integrand(s, pressure, x, y, out); };
  auto res = cubature::integrate_rectangle<4>(g, 0.0, s.a, -s.b, s.b, xb, yb, tol * ptot_estimate, 4000);
  const double P = res.value[3];
  return finish(s, muN, sense, res.value[0] / P, res.value[1] / P, res.value[2] / P, res.error / P,
                res.evaluations, res.converged);
}

}  // namespace

FrictionCubatureResult cubature_friction_wrench_uniform(double a, double b, double muN, double R, double alpha,
                                                        int sense, double tol) {
  require_positive("tol", tol);
  require_nonnegative("muN", muN, "N");
  const Scaled s = scale(a, b, R, alpha, sense);
  if (std::hypot(s.xc, s.yc) >= 2.0) {
    // Distant iCOR: smooth integrand, fully numerical symmetrised scheme.
    auto one = [](double, double) { return 1.0; };
    return pair_cubature(s, muN, sense, one, tol, 4.0 * s.a * s.b);
  }
  // iCOR on or near the contact: the y' integral analytically (1-D antiderivatives in Y of
  // X/r, Y/r and (x X + y Y)/r, not the 2-D corner form), the x' integral by adaptive GK15 with
  // a break point at the iCOR's x' (where the inner result has its X ln|X| singularity).
  // Near the contact the remaining cancellation (across x') is at most a factor of a few.
  // Differences across y' are formed without cancellation (a thin contact, b << |yc|, would
  // otherwise lose |yc|/b): y1 - y0 = 2b and y1 + y0 = 2 yc exactly, r1 - r0 = 4 b yc/(r1 + r0),
  // and for y0, y1 of one sign asinh(y1/|X|) - asinh(y0/|X|) = asinh(4 b yc/(y1 r0 + y0 r1))
  // (the asinh addition formula; finite even at X = 0, where it equals ln(y1/y0)).
  const double y0 = s.yc - s.b, y1 = s.yc + s.b;
  auto inner = [&](double x, double* out) {
    const double X = s.xc + x;
    const double r0 = std::sqrt(X * X + y0 * y0), r1 = std::sqrt(X * X + y1 * y1);
    const double dr = (r0 + r1 > 0.0) ? 4.0 * s.b * s.yc / (r1 + r0) : 0.0;  // r1 - r0
    double xda;                                                                // X (asinh(y1/|X|) - asinh(y0/|X|))
    if (y0 >= 0.0 || y1 <= 0.0) {
      const double den = y1 * r0 + y0 * r1;
      xda = (den != 0.0) ? X * std::asinh(4.0 * s.b * s.yc / den) : 0.0;
    } else {
      xda = x_asinh(X, y1) - x_asinh(X, y0);
    }
    out[0] = xda;  // int X/r dY
    out[1] = dr;   // int Y/r dY
    // int (x X + y Y)/r dY, y = Y - yc: x X dA + (D[Y r] - X^2 dA)/2 - yc dr with
    // D[Y r] = y1 r1 - y0 r0 = b (r1 + r0) + yc dr.
    out[2] = x * xda + 0.5 * (s.b * (r1 + r0) - s.yc * dr - X * xda);
  };
  const double area = 4.0 * s.a * s.b;
  auto res = cubature::integrate<3>(inner, -s.a, s.a, {-s.xc}, tol * area, 4000);
  return finish(s, muN, sense, res.value[0] / area, res.value[1] / area, res.value[2] / area, res.error / area,
                res.evaluations, res.converged);
}

FrictionCubatureResult cubature_friction_wrench(double a, double b, double muN, double R, double alpha, int sense,
                                                const std::function<double(double, double)>& pressure, double tol) {
  require_positive("tol", tol);
  require_nonnegative("muN", muN, "N");
  if (!pressure) throw InputError("pressure", "(empty)", "must be a callable p(x', y') >= 0");
  const Scaled s = scale(a, b, R, alpha, sense);
  auto p = [&](double x, double y) { return pressure(x * s.L, y * s.L); };
  // First the pressure scale, so the tolerance is relative to the mean pressure.
  auto pint = cubature::integrate_rectangle<1>([&](double x, double y, double* o) { o[0] = p(x, y); }, -s.a, s.a,
                                               -s.b, s.b, {}, {}, 1e-10 * 4.0 * s.a * s.b * std::fabs(p(0.0, 0.0)) + 1e-300,
                                               4000);
  const double ptot = pint.value[0];
  if (!(ptot > 0.0) || !std::isfinite(ptot))
    throw InputError("pressure", fmt(ptot), "its integral over the contact must be finite and > 0");
  auto r = pair_cubature(s, muN, sense, p, tol, ptot);
  r.evaluations += pint.evaluations;
  r.converged = r.converged && pint.converged;
  return r;
}

}  // namespace nanopush
