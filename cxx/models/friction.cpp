// Checked entry points and the thesis' printed forms for the friction wrench (friction.hpp).
#include "nanopush/models/friction.hpp"

#include <cmath>
#include <string>

#include "nanopush/numerics/error.hpp"

namespace nanopush {

namespace {

void check_rectangle(double a, double b) {
  require_positive("a", a, "m, half-width along body x'");
  require_positive("b", b, "m, half-length along body y'");
  const double lo = a < b ? a : b, hi = a < b ? b : a;
  if (!(lo / hi >= kFrictionMinAspect))
    throw InputError("b/a", fmt(b / a),
                     "aspect ratio must be in [" + fmt(kFrictionMinAspect) + ", " + fmt(1.0 / kFrictionMinAspect) + "]");
}

void check_muN(double muN) { require_nonnegative("muN", muN, "N, friction coefficient times normal load"); }

void check_velocity(double vx, double vy) {
  require_finite("vx", vx, "m/s");
  require_finite("vy", vy, "m/s");
}

}  // namespace

FrictionWrench rectangle_friction_wrench_checked(double a, double b, double muN, double R, double alpha,
                                                 int sense) {
  check_rectangle(a, b);
  check_muN(muN);
  require_nonnegative("R", R, "m, distance from the iCOR to the centre of mass");
  require_finite("alpha", alpha, "rad");
  if (sense != 1 && sense != -1)
    throw InputError("sense", std::to_string(sense), "must be +1 (counter-clockwise) or -1 (clockwise)");
  return rectangle_friction_wrench(a, b, muN, R, alpha, sense);
}

FrictionWrench rectangle_friction_translation_checked(double muN, double vx, double vy) {
  check_muN(muN);
  check_velocity(vx, vy);
  return rectangle_friction_translation(muN, vx, vy);
}

FrictionWrench rectangle_friction_from_velocity_checked(double a, double b, double muN, double vx, double vy,
                                                        double omega) {
  check_rectangle(a, b);
  check_muN(muN);
  check_velocity(vx, vy);
  require_finite("omega", omega, "rad/s");
  return rectangle_friction_from_velocity(a, b, muN, vx, vy, omega);
}

int rectangle_friction_form(double a, double b, double R) {
  const double L = a > b ? a : b;
  const double rho = R / L;
  if (!(rho < kFrictionAsymptotic)) return 5;
  if (rho < kFrictionFarField) return 0;
  if (rho < kFrictionGl8From) return 1;
  if (rho < kFrictionGl6From) return 2;
  return rho < kFrictionGl4From ? 3 : 4;
}

namespace {

/// The thesis' closed forms (3.45)-(3.48) with muN = 1. corrected = false: literally as printed
/// (sign(theta-dot) = +1). corrected = true: fy' with the sign of (3.43), C4 with cubes as in
/// (B.37), and mf multiplied by sign(theta-dot) = sense (docs/errata.md).
FrictionWrench thesis_form(double a, double b, double R, double alpha, bool corrected, int sense) {
  const double h1 = R * std::sin(alpha) - b, h2 = R * std::cos(alpha) + a;
  const double h3 = R * std::sin(alpha) + b, h4 = R * std::cos(alpha) - a;
  const auto sq = [](double u, double v) { return std::sqrt(u * u + v * v); };
  const double s12 = sq(h1, h2), s23 = sq(h2, h3), s34 = sq(h3, h4), s14 = sq(h1, h4);
  const double b45 = h2 * (s23 - s12) + h4 * (s14 - s34) - h1 * h1 * std::log((s14 - h4) / (s12 - h2)) +
                     h3 * h3 * std::log((s34 - h4) / (s23 - h2));
  const double b46 = h1 * (s14 - s12) + h3 * (s23 - s34) + h2 * h2 * std::log((s23 + h3) / (s12 + h1)) -
                     h4 * h4 * std::log((s34 + h3) / (s14 + h1));
  const double c1 = b46, c2 = b45;
  const double c3 = -h1 * h2 * s12 + h2 * h3 * s23 - h3 * h4 * s34 + h1 * h4 * s14;
  const auto p = [corrected](double h) { return corrected ? h * h * h : h * h; };
  const double c4 = p(h1) * std::log((s12 - h2) / (s14 - h4)) + p(h2) * std::log((s23 + h3) / (s12 + h1)) +
                    p(h3) * std::log((s34 - h4) / (s23 - h2)) + p(h4) * std::log((s14 + h1) / (s34 + h3));
  const double ab = a * b, sg = corrected ? (sense < 0 ? -1.0 : 1.0) : 1.0;
  const double mf = (R * std::cos(alpha) * c1 / 2.0 + R * std::sin(alpha) * c2 / 2.0 - c3 / 3.0 - c4 / 6.0) / (4.0 * ab);
  return {sg * b45 / (8.0 * ab), (corrected ? -sg : 1.0) * b46 / (8.0 * ab), sg * mf};
}

}  // namespace

FrictionWrench thesis_printed_friction(double a, double b, double R, double alpha) {
  return thesis_form(a, b, R, alpha, false, 1);
}

FrictionWrench thesis_corrected_friction(double a, double b, double R, double alpha, int sense) {
  return thesis_form(a, b, R, alpha, true, sense);
}


// ---------------------------------------------------------------------------------------------
// The `printed` friction law (docs/rough.md): eqs (3.45)-(3.48) as printed, evaluated at the
// iCOR implied by the velocity. Operation for operation the same as FRPRNT in fortran/rgbar.f,
// so the C++ and F77 engines round identically.

namespace {

/// h^k ln(u/v) (k = 2, or 3 with cube), one corner term of the printed forms, taken as 0 where
/// the printed logarithm is undefined: that happens only on an edge line of the contact (or
/// within rounding of it), where h -> 0 and the term's limit is 0 (the thesis' "lim h ln(1/h) =
/// 0", errata F4).
double printed_term(double h, double u, double v, bool cube = false) noexcept {
  if (h == 0.0 || !(u > 0.0) || !(v > 0.0)) return 0.0;
  return cube ? h * h * h * std::log(u / v) : h * h * std::log(u / v);
}

}  // namespace

PrintedReading printed_reading(int index) {
  PrintedReading r;
  r.fy_sign = (index & 1) == 0;
  r.omega_sign = (index & 2) == 0;
  r.c4_squares = (index & 4) == 0;
  r.eq3_50 = (index & 8) != 0;
  return r;
}

int printed_reading_index(const PrintedReading& r) {
  return (r.fy_sign ? 0 : 1) + (r.omega_sign ? 0 : 2) + (r.c4_squares ? 0 : 4) + (r.eq3_50 ? 8 : 0);
}

std::optional<PrintedReading> printed_reading_named(std::string_view name) {
  for (const auto& [n, i] : kPrintedReadingNames)
    if (n == name) return printed_reading(i);
  return std::nullopt;
}

std::string_view printed_reading_name(const PrintedReading& r) {
  for (const auto& [n, i] : kPrintedReadingNames)
    if (printed_reading(i) == r) return n;
  return "";
}

std::string printed_reading_text(const PrintedReading& r) {
  return std::string("F1 ") + (r.fy_sign ? "printed" : "corrected") + ", F3 " +
         (r.omega_sign ? "printed" : "corrected") + ", C4 " + (r.c4_squares ? "squares (nm)" : "cubes") + ", 3.50 " +
         (r.eq3_50 ? "printed" : "corrected");
}

FrictionWrench thesis_printed_friction_from_velocity(double a, double b, double muN, double vx, double vy,
                                                     double omega, const PrintedReading& reading) noexcept {
  const double v = friction_detail::hypot_portable(vx, vy);
  if (omega == 0.0) {  // R = infinity: pure translation, the limit the thesis states (§3.4.3.3)
    if (!(v > 0.0)) return {0.0, 0.0, 0.0};
    return {-muN * (vx / v), -muN * (vy / v), 0.0};
  }
  const double sg = omega > 0.0 ? 1.0 : -1.0;
  double c = 1.0, s = 0.0;  // any direction at R = 0
  if (v > 0.0) {
    c = sg * vy / v;
    s = -sg * vx / v;
  }
  // Lengths in nanometres (kPrintedLengthUnit): C4 with squares is not dimensionally consistent,
  // and in metres its moment is ~1e6 times too large (no integrator leaves t = 0: docs/rough.md).
  const double U = kPrintedLengthUnit;
  a /= U;
  b /= U;
  const double r = v / std::fabs(omega) / U;
  const double xc = r * c, yc = r * s;  // R cos(alpha), R sin(alpha)
  const double h1 = yc - b, h2 = xc + a, h3 = yc + b, h4 = xc - a;
  const double s12 = std::sqrt(h1 * h1 + h2 * h2), s23 = std::sqrt(h2 * h2 + h3 * h3);
  const double s34 = std::sqrt(h3 * h3 + h4 * h4), s14 = std::sqrt(h1 * h1 + h4 * h4);
  const double b45 = h2 * (s23 - s12) + h4 * (s14 - s34) - printed_term(h1, s14 - h4, s12 - h2) +
                     printed_term(h3, s34 - h4, s23 - h2);
  const double b46 = h1 * (s14 - s12) + h3 * (s23 - s34) + printed_term(h2, s23 + h3, s12 + h1) -
                     printed_term(h4, s34 + h3, s14 + h1);
  const double c3 = -h1 * h2 * s12 + h2 * h3 * s23 - h3 * h4 * s34 + h1 * h4 * s14;
  const bool cube = !reading.c4_squares;  // F2
  const double c4 = printed_term(h1, s12 - h2, s14 - h4, cube) + printed_term(h2, s23 + h3, s12 + h1, cube) +
                    printed_term(h3, s34 - h4, s23 - h2, cube) + printed_term(h4, s14 + h1, s34 + h3, cube);
  const double ab = a * b;
  const double fxb = muN * sg * b45 / (8.0 * ab);  // (3.45)
  double fyb = muN * sg * b46 / (8.0 * ab);        // (3.46), printed sign (F1)
  if (!reading.fy_sign) fyb = -fyb;                // the sign of (3.43)
  // (3.47) with (3.48): C1 = [3.46], C2 = [3.45]; as printed without sign(theta-dot) (F3).
  double mf = U * muN * (xc * b46 / 2.0 + yc * b45 / 2.0 - c3 / 3.0 - c4 / 6.0) / (4.0 * ab);
  if (!reading.omega_sign) mf = sg * mf;
  return {fxb, fyb, mf};
}

}  // namespace nanopush
