// Adaptive cubature reference for the friction wrench (friction_cubature.hpp).
#include "nanopush/friction_cubature.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "nanopush/cubature.hpp"
#include "nanopush/error.hpp"

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

FrictionCubatureResult cubature_friction_wrench_uniform(double a, double b, double muN, double R, double alpha,
                                                        int sense, double tol) {
  require_positive("tol", tol);
  require_nonnegative("muN", muN, "N");
  const Scaled s = scale(a, b, R, alpha, sense);
  const double y0 = s.yc - s.b, y1 = s.yc + s.b;
  auto inner = [&](double x, double* out) {
    const double X = s.xc + x;
    const double r0 = std::sqrt(X * X + y0 * y0), r1 = std::sqrt(X * X + y1 * y1);
    const double xa0 = x_asinh(X, y0), xa1 = x_asinh(X, y1);  // X asinh(Y/|X|)
    out[0] = xa1 - xa0;                                       // int X/r dY
    out[1] = r1 - r0;                                         // int Y/r dY
    // int (x X + y Y)/r dY with y = Y - yc: x X asinh + (Y r - X^2 asinh)/2 - yc r
    out[2] = x * (xa1 - xa0) + 0.5 * ((y1 * r1 - X * xa1) - (y0 * r0 - X * xa0)) - s.yc * (r1 - r0);
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
  auto g = [&](double x, double y, double* out) {
    const double p = pressure(x * s.L, y * s.L);
    const double X = s.xc + x, Y = s.yc + y;
    const double ir = 1.0 / std::sqrt(X * X + Y * Y);
    out[0] = p * X * ir;
    out[1] = p * Y * ir;
    out[2] = p * (x * X + y * Y) * ir;
    out[3] = p;
  };
  // First the pressure scale, so the tolerance is relative to the mean pressure.
  auto pint = cubature::integrate_rectangle<1>(
      [&](double x, double y, double* o) { o[0] = pressure(x * s.L, y * s.L); }, -s.a, s.a, -s.b, s.b, {}, {},
      1e-10 * 4.0 * s.a * s.b * std::fabs(pressure(0.0, 0.0)) + 1e-300, 4000);
  const double ptot = pint.value[0];
  if (!(ptot > 0.0) || !std::isfinite(ptot))
    throw InputError("pressure", fmt(ptot), "its integral over the contact must be finite and > 0");
  auto res = cubature::integrate_rectangle<4>(g, -s.a, s.a, -s.b, s.b, {-s.xc}, {-s.yc}, tol * ptot, 4000);
  const double P = res.value[3];
  return finish(s, muN, sense, res.value[0] / P, res.value[1] / P, res.value[2] / P, res.error / P,
                res.evaluations + pint.evaluations, res.converged && pint.converged);
}

}  // namespace nanopush
