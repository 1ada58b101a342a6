// The instantaneous centre of rotation (iCOR) of a pushed nanorod: every principle of
// thesis chapters 4-5 (docs/models.md section D), the constrained cubic (5.4) solved by Brent
// and by companion-matrix eigenvalues, and the inverse maps that estimate the friction
// coefficient from what an experimenter measures.
//
// Geometry (thesis Fig 4.1): a rod of length L = 2b lies along body y'; the push F is
// perpendicular to the rod at distance yn >= 0 from the centre of mass (CM).
// Sign convention of chapter 4 (eqs 4.2-4.13): R > 0 is the distance from the CM to the
// iCOR on the far side of the CM from the push point (the moment arm of F about the iCOR
// is R + yn). The cubic (5.4) is reported with the signs of its own roots: its negative
// root is the one Table 5.1 tabulates (|R| printed; docs/models.md D reads it as the far side,
// see docs/errata.md on the sign); its smallest positive root is the other branch
// (erratum 9).
//
// All functions take SI values, reject bad input with InputError (field, value, range)
// and never return NaN: pure translation is R = +infinity, a root at infinity is counted.
#pragma once
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "nanopush/models/materials.hpp"
#include "nanopush/numerics/names.hpp"

namespace nanopush::icor {

/// Hamaker constant used for graphite on graphite [J]: the material table's one value
/// (materials.hpp; the thesis prints none). Only absolute forces depend on it; every iCOR
/// location, Table 5.1, the error analysis and F/(mu W) are independent of it. Override
/// with --hamaker on the command line.
inline constexpr double kGraphiteHamakerAssumed = forces::kGraphiteHamaker;

/// A thin rod on a plane (docs/models.md section D). SI units.
struct Rod {
  double length = 590e-9;    ///< L [m]
  double radius = 13.5e-9;   ///< [m]
  double density = 2267.0;   ///< graphite [kg/m^3] (docs/models.md erratum 8)
  double hamaker = kGraphiteHamakerAssumed;  ///< H [J]
  double z0 = 0.2e-9;        ///< rod-plane separation [m] (thesis section 4.2.3)
  double gravity = 9.81;     ///< g [m/s^2] (thesis value)

  /// Throws InputError unless every field is finite and positive.
  void validate() const;
  [[nodiscard]] double half_length() const { return 0.5 * length; }
  [[nodiscard]] double mass() const;             ///< rho pi r^2 L [kg]
  [[nodiscard]] double inertia() const;          ///< m L^2 / 12 about the CM [kg m^2]
  [[nodiscard]] double gyration_squared() const; ///< k^2 = I/m = L^2/12 [m^2]
  [[nodiscard]] double vdw_force() const;        ///< Parsegian: L H d^0.5 / (16 z0^2.5) [N]
  [[nodiscard]] double load() const;             ///< W = m g + F_vdw [N]
};

/// The thesis' nanorod: L = 590 nm, radius 13.5 nm, graphite on graphite.
Rod nanorod();

// ---- Chapter 4: quasi-static, free of constraints (R > 0 on the far side) -------------

/// Eq 4.1 (experimental fit of Jung-Hui & Shuo-Hung): alpha = 0.5 sqrt(beta - 0.5) with
/// beta = (b + yn)/L (push point from the lower end) and alpha = rho/L (iCOR from the lower
/// end). Returns R = b - rho. Requires 0 <= yn <= b.
double experimental_fit(double yn, double L);

/// Eq 4.2 (Falvo et al.) in its own coordinates: normalised iCOR x0/L from the normalised
/// push point x1/L, both measured from the lower end.
double falvo_normalised(double x1_hat);
/// Eq 4.2 mapped to R: x1 = b + yn, R = b - L x0_hat.
double falvo(double yn, double L);

/// Eq 4.3 (Li et al.) in its own coordinates: iCOR position S from the left end for a push
/// at l from the left end (both branches, l < L/2 and l > L/2; l = L/2 takes the first).
double li_position(double l, double L);
/// Eq 4.3 mapped to R: l = b - yn, R = S - b.
double li(double yn, double L);

/// Eq 4.13 (unknown pressure, minimum force): R = sqrt(b^2 + yn^2) - yn, evaluated as
/// b^2 / (sqrt(b^2 + yn^2) + yn) (no cancellation).
double unknown_pressure(double yn, double L);

/// Eq 4.8: minimum push force that starts motion, mu W (sqrt(yn^2 + b^2) - yn) / b [N].
double minimum_force(double mu, double W, double yn, double L);

/// Eq 4.7 (known pressure): R(mu, yn, F) = [b F + sqrt(b^2 F^2 - mu W (mu W b^2 - 2 b yn F))]
/// / (mu W). Requires F >= minimum_force (else InputError naming the minimum).
double known_pressure(double mu, double W, double yn, double F, double L);

/// Eq 4.10: F = mu W R / b [N].
double force_from_icor(double mu, double W, double R, double L);

/// Eq 4.11: F = mu W (b^2 + R^2) / (2 b (R + yn)) [N]. Requires R + yn > 0.
double force_unknown_pressure(double mu, double W, double R, double yn, double L);

// ---- Chapter 5 ---------------------------------------------------------------------

/// Eq 5.5 with erratum 6 (k^2 = I/m): R = k^2 / yn; +infinity at yn = 0 (pure translation).
double impulsive(double yn, double k2);

/// Coefficients (ascending: c0, c1, c2, c3) of eq 5.4 exactly as printed, with m, g, F_vdw,
/// I of `rod`: (2 g m^3 + 2 F m^2) yn R^3 + (-3 g m^2 - 3 F m) I R^2 + (-2 g m - 2 F) I^2
/// + (b^2 g m^2 + b^2 F m) I. Units kg^3 m^4 s^-2 (N kg^2 m^3).
std::array<double, 4> constrained_cubic_printed(double yn, const Rod& rod);

/// The same cubic divided by m^2 W (independent of mu, W and m):
/// 2 yn R^3 - 3 k^2 R^2 + k^2 (b^2 - 2 k^2) [m^4], ascending order.
std::array<double, 4> constrained_cubic(double yn, double L, double k2);

/// Eq 5.2 (with erratum 5): the push force for an assumed iCOR R,
/// F = -mu W R (R^2 + 2 k^2 - b^2) / (2 b (yn R - k^2)) [N].
/// At the pole yn R = k^2 (the impulsive iCOR) returns +-infinity.
double constrained_force(double mu, double W, double R, double yn, double L, double k2);

enum class CubicMethod {
  Brent,  ///< van Wijngaarden-Dekker-Brent on brackets found from the critical points
  Eigen,  ///< eigenvalues of the balanced companion matrix (Eigen)
};

/// The roots of the constrained cubic (5.4), with both branches and their signs.
struct CubicSolution {
  double yn = 0.0;
  std::vector<double> real_roots;  ///< all finite real roots, ascending [m]
  int complex_roots = 0;           ///< number of non-real roots (0 or 2)
  int at_infinity = 0;             ///< roots lost to the vanishing leading coefficient (yn -> 0)
  std::optional<double> negative;  ///< the negative root closest to 0: Table 5.1's branch
  std::optional<double> positive;  ///< the smallest positive root: the other side of the CM
  double max_residual = 0.0;       ///< max over real roots of |p(R)| / sum |c_i R^i|
};

/// Solve eq 5.4 for a push at yn >= 0 on a rod of length L with k^2 = I/m (> 0).
/// Works in r = R/b; L <= 0, yn < 0, non-finite input throw InputError.
CubicSolution solve_constrained_cubic(double yn, double L, double k2, CubicMethod method);

/// Real roots of a real polynomial of degree <= 3 (ascending coefficients) by Brent, on
/// brackets between the critical points (the real roots of p'), unbounded ends expanded
/// geometrically until a sign change or overflow (then counted at infinity).
struct BrentRoots {
  std::vector<double> roots;
  int at_infinity = 0;
  int iterations = 0;  ///< total Brent iterations
};
BrentRoots real_roots_brent(const std::vector<double>& c_ascending);

// ---- Extension points: the dynamic iCOR (item 3) and finite contacts (item 4) --------

/// The iCOR read off a rigid-body velocity state (docs/models.md section 0): relative to the CM
/// it sits at c = (-v_y, v_x)/omega, R = |c|. omega = 0 is pure translation: R = +inf and
/// c = (0, 0) with `translation` set. Any frame works (c comes back in the frame of v).
struct VelocityIcor {
  double cx = 0.0, cy = 0.0;  ///< iCOR relative to the CM [m]
  double R = 0.0;             ///< |c| [m] (+inf for pure translation)
  bool translation = false;
};
VelocityIcor icor_from_velocity(double vx, double vy, double omega);

/// Friction resultant on a contact for a rotation about the iCOR c = -R (cos alpha,
/// sin alpha) (body axes, relative to the CM) with omega > 0, per unit mu W: force
/// (fx, fy) in body axes and moment mf about the CM (z). For omega < 0 it is negated.
struct Wrench {
  double fx = 0.0, fy = 0.0, mf = 0.0;
};
using FrictionWrenchFn = std::function<Wrench(double R, double alpha)>;

/// Closed-form wrench of a thin rod of half-length b along body y' (line contact, uniform
/// pressure mu W / (2b)): the a/b -> 0 limit any rectangle closed form must reach.
Wrench line_contact_wrench(double b, double R, double alpha);

/// Quasi-static iCOR for a push of fixed body direction (dir_x, dir_y) applied at the body
/// point (px, py): solve F e + f(R, alpha) = 0 and (p x e) F + mf = 0 for R, alpha and
/// F >= 0 (F per unit mu W), trying both senses of rotation, by Newton's method on
/// (ln R, alpha) with a finite-difference Jacobian and backtracking, from (R0, alpha0).
/// The finite-rectangle iCOR of issue 5 item 4 is this with the closed-form rectangle
/// wrench of docs/models.md B; with line_contact_wrench it is eq 4.13 (tested).
struct QuasiStaticIcor {
  double R = 0.0, alpha = 0.0;
  double force = 0.0;   ///< |F| / (mu W)
  int omega_sign = 0;   ///< +1 counter-clockwise, -1 clockwise
  int iterations = 0;
  bool converged = false;
  double residual = 0.0;  ///< max |balance equation| at the answer (units of mu W, mu W m)
};
QuasiStaticIcor quasi_static_icor(const FrictionWrenchFn& wrench, double px, double py, double dir_x, double dir_y,
                                  double R0, double alpha0, double length_scale);

// ---- Inverse maps: friction coefficient from measurements (Figs 4.4, 4.5) -----------

struct Measured {
  double value = 0.0;  ///< SI
  double sigma = 0.0;  ///< one standard uncertainty, SI (>= 0)
};

struct Contribution {
  std::string input;     ///< e.g. "F", "yn", "L", "H"
  double value = 0.0;
  double sigma = 0.0;
  double derivative = 0.0;  ///< d mu / d input (SI)
};

struct MuEstimate {
  double mu = 0.0;
  double sigma = 0.0;  ///< first-order (linear) propagation, inputs uncorrelated
  double load = 0.0;   ///< W used [N]
  std::vector<Contribution> contributions;
};

/// e.sigma from e.contributions (first order, inputs uncorrelated). A mu or sigma that is not
/// finite is no answer, and it throws InputError naming the input, whichever front end gave it:
/// for mu, the measured values (the first two contributions); for sigma, the input whose
/// contribution (d mu / d input x its uncertainty, "L uncertainty = 1e+308") is not finite, or
/// the value whose derivative is not, or the largest contribution when their squares overflow.
MuEstimate propagate_uncertainty(MuEstimate e);

/// Fig 4.4 / eq 4.8 inverted: mu = F (sqrt(yn^2 + b^2) + yn) / (W b) from a measured
/// minimum push force F at yn. Uncertainty from F, yn, the rod length L and the Hamaker
/// constant H (sigma_L, sigma_H); W = W(L, H) is recomputed, never frozen.
MuEstimate estimate_mu_from_force(const Rod& rod, Measured F, Measured yn, double sigma_L = 0.0,
                                  double sigma_H = 0.0);

/// Fig 4.5 / eq 4.10 inverted: mu = F b / (W R) from a push force and an observed iCOR
/// distance R > 0. (d mu / d L = 0 exactly: b and W both scale with L.)
MuEstimate estimate_mu_from_icor(const Rod& rod, Measured F, Measured R, double sigma_L = 0.0,
                                 double sigma_H = 0.0);

/// Round to `digits` significant digits (for comparing with printed tables).
double round_significant(double x, int digits);

// ---- The thesis' printed values -----------------------------------------------------

/// One row of Table 5.1 as printed: yn [m], the printed |R| [m] and its mantissa text
/// (whose digit count is the printed precision); `plus_minus` where the thesis prints +-.
struct ThesisTableRow {
  double yn;
  double printed;
  const char* mantissa;
  bool plus_minus;
  [[nodiscard]] int digits() const;  ///< significant digits printed
};
/// Table 5.1, top (yn = 295 nm) to bottom (yn = 0), both printed columns being identical.
const std::vector<ThesisTableRow>& thesis_table_5_1();

/// Section 5.6.1.1: sample standard deviations printed for n = 296 push points.
inline constexpr double kThesisStdUnknownPressure = 49.6987;  ///< eq 4.13 [nm]
inline constexpr double kThesisStdConstrained = 5.3950;       ///< eq 5.4 [nm]

/// The error analysis of section 5.6.1.1 as we reproduce it: yn = 0, 1, ..., n-1 nm
/// (n = 296 covers 0..295 nm = 0..b), R in nanometres, sample standard deviation (n - 1
/// in the denominator). For 5.4 the branch is Table 5.1's (negative root), |R|.
struct ErrorAnalysis {
  int n = 0;
  double std_unknown_pressure_nm = 0.0;  ///< eq 4.13
  double std_constrained_nm = 0.0;       ///< eq 5.4
  double mean_unknown_pressure_nm = 0.0;
  double mean_constrained_nm = 0.0;
};
ErrorAnalysis error_analysis(double L, double k2, CubicMethod method, int n = 296);

/// Sample standard deviation (n - 1 denominator, two-pass).
double sample_std(const std::vector<double>& x);

}  // namespace nanopush::icor

namespace nanopush {
NANOPUSH_NAMES(icor::CubicMethod, {icor::CubicMethod::Brent, "brent"}, {icor::CubicMethod::Eigen, "eigen"});
}  // namespace nanopush
