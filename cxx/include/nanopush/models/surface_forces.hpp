// Surface and adhesion forces at the nanoscale: docs/models.md section F (thesis Ch. 2 and
// section 3.1, Table 3.1). Closed forms after Israelachvili, "Intermolecular and Surface
// Forces" (the thesis' ref [59]), Johnson-Kendall-Roberts (1971), Parsegian (2006).
//
// CONVENTIONS (stated once, used everywhere in nanopush)
// ------------------------------------------------------
// * SI units throughout: J, N, m, Pa, J/m^2 (= N/m).
// * gamma (surface energy, "surface tension" for liquids) is the energy of ONE surface per
//   unit area [J/m^2]. The work of adhesion W [J/m^2] is the energy to separate unit areas
//   of two surfaces from contact to infinity. For like materials W11 = 2 gamma1 (eq 2.31);
//   for unlike materials W12 = gamma1 + gamma2 - gamma12 (Dupre, eq 2.32), dispersion
//   approximation W12 = 2 sqrt(gamma1 gamma2) (eq 2.35). Every contact model below takes
//   W, never gamma: e.g. JKR pull-off = 1.5 pi R W (= 3 pi R gamma for W = 2 gamma,
//   eq 2.52), Derjaguin/DMT = 2 pi R W (= 4 pi R gamma, eq 2.48).
// * Forces returned by *_force functions are ATTRACTIVE MAGNITUDES: positive pulls the two
//   bodies together (adds to the normal load). Energies are signed (negative = bound).
// * A is the (non-retarded) Hamaker constant [J], A = pi^2 C rho1 rho2.
// * D is the surface-surface separation [m], D > 0. The continuum forms hold for D larger
//   than an atomic size; at contact one uses the cut-off D0 (0.165 nm in Israelachvili,
//   sigma/2.5 = 0.16 nm in the thesis' eq 3.8).
// * K = (4/3) E* is the JKR/Hertz "elastic modulus" of eqs 2.50-2.59, with the effective
//   modulus 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.
//
// Every model function increments a per-model evaluation counter (model_counters()), so a
// test can prove that a scene evaluates only the models it needs.
#pragma once
#include <array>
#include <atomic>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nanopush/models/materials.hpp"

namespace nanopush::forces {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kGasConstant = 8.314462618;  ///< R [J/(mol K)]
inline constexpr double kGravity = 9.81;             ///< g [m/s^2], as in the thesis (eq 3.11)
/// Israelachvili's cut-off D0 [m] used for the "old" column of Table 3.1.
inline constexpr double kD0Israelachvili = 0.165e-9;
/// Thesis' corrected factor A = 1.9302e-18 gamma (eq 3.9) [m^2]: 24 pi (sigma/2.5)^2 with
/// sigma = 0.4 nm, rounded to five digits as printed.
inline constexpr double kThesisHamakerPerGamma = 1.9302e-18;

// ---------------------------------------------------------------------------------------
// Evaluation counters ("model only what a scene requires").
enum class Model : std::size_t {
  molecule_surface,      ///< 2.16-2.17
  sphere_surface_vdw,    ///< 2.21-2.22
  sphere_sphere_vdw,     ///< 2.21 with R -> R1 R2/(R1+R2)
  surface_surface_vdw,   ///< 2.25-2.26
  rod_plane_vdw,         ///< Parsegian (ch. 4)
  layered_vdw,           ///< 2.38-2.41
  metallic_adhesion,     ///< 2.37
  dupre,                 ///< 2.31-2.36
  hamaker_combining,     ///< A132 combining relation
  surface_energy,        ///< 3.6, 3.9
  derjaguin,             ///< 2.45-2.49
  jkr,                   ///< 2.50-2.55
  jkr_line,              ///< JKR cylinder on plane (thesis ref [72])
  hertz,                 ///< 2.56-2.59
  kelvin,                ///< 2.60
  laplace,               ///< 2.61-2.63
  capillary,             ///< 2.64-2.71 and the cylinder/plate extensions
  count_
};
inline constexpr std::size_t kModelCount = static_cast<std::size_t>(Model::count_);
std::string_view model_name(Model m);
/// True for the models that describe adhesion (van der Waals, contact adhesion, capillary,
/// surface energies): none of these may run in a scene without adhesion.
bool is_adhesion_model(Model m);

struct ModelCounters {
  std::array<std::atomic<unsigned long>, kModelCount> n{};
  void reset() noexcept;
  unsigned long operator[](Model m) const noexcept { return n[static_cast<std::size_t>(m)].load(); }
  /// Sum over the adhesion models (is_adhesion_model).
  unsigned long adhesion_total() const noexcept;
};
/// Process-wide counters (atomic; tests reset them before a scene).
ModelCounters& model_counters();

// ---------------------------------------------------------------------------------------
// Van der Waals (pairwise-additive, non-retarded; Israelachvili ch. 13).

/// Molecule (pair constant C [J m^6]) at distance D [m] from a half-space of number density
/// rho [1/m^3]: energy w = -pi C rho / (6 D^3) [J] (eq 2.16). Valid for D >> molecular size.
double molecule_surface_energy(double C, double rho, double D);
/// Its attractive force magnitude pi C rho / (2 D^4) [N] (eq 2.17).
double molecule_surface_force(double C, double rho, double D);

/// Sphere of radius R [m] at gap D [m] from a flat: energy -A R/(6 D) [J] (eq 2.21).
/// Valid for D << R (Derjaguin regime; eq 2.23 gives the D >> R limit).
double sphere_flat_vdw_energy(double A, double R, double D);
/// Attractive force A R / (6 D^2) [N] (eq 2.22). Valid for D << R.
double sphere_flat_vdw_force(double A, double R, double D);
/// Two spheres R1, R2: A Reff/(6 D^2) [N], Reff = R1 R2/(R1+R2) (text after eq 2.23). D << R.
double sphere_sphere_vdw_force(double A, double R1, double R2, double D);

/// Two flat half-spaces: energy per area -A/(12 pi D^2) [J/m^2] (eq 2.25). D << lateral size.
double flat_flat_vdw_energy_per_area(double A, double D);
/// Attractive pressure A/(6 pi D^3) [Pa] (eq 2.26). D << lateral size.
double flat_flat_vdw_pressure(double A, double D);

/// Parsegian rod (cylinder) of length L [m] and diameter d [m] parallel to a plane at gap
/// z0 [m]: attractive force L A d^(1/2) / (16 z0^(5/2)) [N] (thesis section 4.2.3, ref [82];
/// docs/models.md section D). Valid for z0 << d << L.
double rod_plane_vdw_force(double A, double L, double d, double z0);
/// Van der Waals attraction of a rectangular bar (footprint length x width, thickness T) lying
/// flat on a half-space at gap D, by pairwise summation (the thesis' section 3.4.3 route):
/// F = (length width) A/(6 pi) [1/D^3 - 1/(D+T)^3] (the eq 2.26 pressure of a slab of
/// finite thickness), edge effects neglected (D << width) [N].
double bar_plane_vdw_force(double A, double length, double width, double T, double D);

/// Symmetric layered surfaces (eq 2.39): half-spaces 1 coated with layers 2 of thickness
/// T [m], across medium 3 at gap D [m]. Attractive pressure [Pa]
///   (1/(6 pi)) [A232/D^3 - 2 A123/(D+T)^3 + A121/(D+2T)^3].
/// Limits: D << T -> A232/(6 pi D^3) (2.40); D >> T -> (A232 - 2A123 + A121)/(6 pi D^3),
/// which is A131/(6 pi D^3) under the combining relations (2.41).
double layered_vdw_pressure_symmetric(double A232, double A123, double A121, double T, double D);
/// General (asymmetric) form, eq 2.38: surfaces 1 and 1' with layers 2 (thickness T) and
/// 2' (T') across 3. Arguments are the Hamaker constants named in eq 2.38; the geometric
/// means must be of non-negative products. Attractive pressure [Pa].
double layered_vdw_pressure(double A232p, double A121, double A32p3, double A1p2p1p,
                            double A323, double T, double Tp, double D);

/// Metallic surfaces (eq 2.37, universal binding-energy form): energy per area
///   w(D) = -2 gamma [1 + (D - D0)/lambda] exp(-(D - D0)/lambda)   [J/m^2],
/// minimum -2 gamma = -W at D = D0. (The thesis prints "1 - (D-D0)/lambda", which has no
/// minimum at D0; see docs/errata.md.) Valid for D >= D0 (separations below ~0.5 nm).
double metallic_adhesion_energy_per_area(double gamma, double D, double D0, double lambda);
/// Attractive pressure -dw/dD = 2 gamma x exp(-x)/lambda, x = (D - D0)/lambda [Pa].
double metallic_adhesion_pressure(double gamma, double D, double D0, double lambda);

// ---------------------------------------------------------------------------------------
// Surface energies, Dupre and combining relations (eqs 2.31-2.36, 3.6, 3.9).

/// gamma = A/(24 pi D0^2) [J/m^2] (eq 3.6); D0 defaults to Israelachvili's 0.165 nm.
double surface_energy_from_hamaker(double A, double D0 = kD0Israelachvili);
/// Thesis' corrected relation gamma = A / 1.9302e-18 [J/m^2] (eqs 3.8-3.9).
double surface_energy_corrected(double A);
/// Work of cohesion W11 = 2 gamma1 (eq 2.31).
double work_of_cohesion(double gamma1);
/// Dupre: interfacial energy gamma12 = gamma1 + gamma2 - W12 (eq 2.32).
double interfacial_energy(double gamma1, double gamma2, double W12);
/// Dispersion-only work of adhesion W12 = 2 sqrt(gamma1d gamma2d) (eq 2.35).
double work_of_adhesion_dispersion(double gamma1d, double gamma2d);
/// Work of adhesion of 1 and 2 in medium 3: W132 = gamma13 + gamma23 - gamma12 (eq 2.36).
double work_of_adhesion_in_medium(double gamma13, double gamma23, double gamma12);
/// Hamaker combining relation for 1 and 2 across 3:
///   A132 = (sqrt(A11) - sqrt(A33)) (sqrt(A22) - sqrt(A33)) [J]; A33 = 0 for vacuum
/// gives A12 = sqrt(A11 A22). Negative A132 means van der Waals repulsion.
double hamaker_combined(double A11, double A22, double A33 = 0.0);

// ---------------------------------------------------------------------------------------
// Contact mechanics: Derjaguin, JKR, Hertz (eqs 2.45-2.59).

/// Effective radius R1 R2/(R1 + R2); pass R2 = +infinity for a flat.
double effective_radius(double R1, double R2);
/// Effective modulus E* [Pa]: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2. E = +infinity = rigid.
double effective_modulus(double E1, double nu1, double E2, double nu2);
/// Derjaguin adhesion of rigid spheres: F = 2 pi Reff W [N] (eq 2.45); sphere-flat in
/// vacuum, like materials: 2 pi R (2 gamma) = 4 pi R gamma (eq 2.48). Also the DMT pull-off.
double derjaguin_adhesion_force(double Reff, double W);
/// DMT pull-off force 2 pi R W [N]: the Derjaguin force of a rigid sphere (same formula).
inline double dmt_pull_off_force(double Reff, double W) { return derjaguin_adhesion_force(Reff, W); }

/// JKR contact radius a [m] of a sphere (Reff) under external load F [N] (positive
/// compressive, may be negative down to the pull-off), eq 2.50:
///   a^3 = (R/K) [F + 3 pi R W + sqrt(6 pi R W F + (3 pi R W)^2)],  K = 4 E*/3.
/// Throws InputError when F is below the pull-off load -1.5 pi R W.
double jkr_contact_radius(double Reff, double Estar, double W, double F);
/// JKR zero-load radius a0 = (6 pi R^2 W / K)^(1/3) [m] (eq 2.51).
double jkr_zero_load_radius(double Reff, double Estar, double W);
/// JKR pull-off force magnitude 1.5 pi R W [N] (eq 2.52, = 3 pi R gamma for W = 2 gamma).
double jkr_pull_off_force(double Reff, double W);
/// Contact radius at separation a_s = a0 / 4^(1/3) = 0.63 a0 [m] (eq 2.53).
double jkr_separation_radius(double Reff, double Estar, double W);
/// Central displacement delta = (a^2/R) [1 - (2/3) (a0/a)^(3/2)] [m] (eq 2.54).
double jkr_central_displacement(double Reff, double Estar, double W, double a);
/// Contact pressure at x = r/a in [0, 1) (eq 2.55) [Pa], compressive positive:
///   3 K a (1-x^2)^(1/2) / (2 pi R) - (3 K W / (2 pi a))^(1/2) (1-x^2)^(-1/2).
double jkr_pressure(double Reff, double Estar, double W, double a, double x);
/// External load F [N] that produces JKR contact radius a (inverse of eq 2.50):
///   F = K a^3/R - sqrt(6 pi W K a^3).
double jkr_load_for_radius(double Reff, double Estar, double W, double a);

/// Hertz contact radius a = (R F / K)^(1/3) = (3 F R / (4 E*))^(1/3) [m] (eq 2.57), F >= 0.
double hertz_contact_radius(double Reff, double Estar, double F);
/// Hertz approach delta = a^2/R [m] (eq 2.58).
double hertz_displacement(double Reff, double Estar, double F);
/// Hertz pressure 3 F (1-x^2)^(1/2) / (2 pi a^2) [Pa] (eq 2.59), x = r/a in [0, 1].
double hertz_pressure(double Reff, double Estar, double F, double x);

/// Hertz line contact (cylinder on a plane, no adhesion): half-width
/// b = sqrt(4 p R / (pi E*)) [m] for a load per length p >= 0 [N/m] (Johnson, Contact
/// Mechanics, eq 4.43; the W = 0 limit of the JKR line relation below).
double hertz_line_half_width(double R, double Estar, double p);

/// JKR line contact of a cylinder (radius R, length L) on a plane (thesis section 3.3, its
/// ref [72]; Barquins 1988, Chaudhury et al. 1996): half-width b [m] under an external load
/// per unit length p [N/m] (compressive positive):
///   p = pi E* b^2 / (4 R) - sqrt(2 pi E* W b).
/// The thesis writes the same relation with total load P = 2 l p and K = 4E*/3 as
///   W = (3 pi K b^2 l / (8 R) - P)^2 / (6 pi K b l^2)   (l = L/2).
/// Returns the stable (larger) root; throws InputError when p is below the line pull-off.
/// W = 0 gives the Hertz line contact b = sqrt(4 p R / (pi E*)).
double jkr_line_half_width(double R, double Estar, double W, double p);
/// Load per length p(b) of the JKR line contact (the relation above) [N/m].
double jkr_line_load_per_length(double R, double Estar, double W, double b);
/// Thesis' form of the line relation: W(b) = (3 pi K b^2 l/(8R) - P)^2/(6 pi K b l^2).
double jkr_line_thesis_work_of_adhesion(double R, double Estar, double b, double l, double P);

// ---------------------------------------------------------------------------------------
// Capillary condensation (eqs 2.60-2.71).

/// Kelvin radius r_k = gamma V / (R T ln(RH)) [m] (eq 2.60), negative (concave) for RH < 1.
/// Water at 20 C: 0.54 nm / ln(RH). RH in (0, 1].
double kelvin_radius(double surface_tension, double molar_volume, double temperature, double RH);
/// Laplace pressure gamma (1/r1 + 1/r2) [Pa] (eq 2.61-2.62). Radii signed.
double laplace_pressure(double surface_tension, double r1, double r2);
/// Maximum meniscus force sphere-flat 4 pi R gamma_L cos(theta) [N] (eqs 2.64, 2.70).
double capillary_force_max(double R, double surface_tension, double contact_angle);
/// Meniscus force at separation D (eq 2.69): 4 pi R gamma cos(theta) / (1 + D/d),
/// d = 2 r1 cos(theta) with r1 = |r_k| the meniscus radius [N]. Valid for r1 << R.
double capillary_force_sphere(double R, double surface_tension, double contact_angle, double r1,
                              double D);
/// Total adhesion in vapour including the solid contact inside the annulus (eq 2.71):
/// 4 pi R (gamma_L cos(theta) + gamma_SL) [N].
double capillary_force_with_solid_contact(double R, double surface_tension, double contact_angle,
                                          double gamma_SL);
/// Cylinder (radius R, length L) parallel to a plane at gap D, meniscus radius r1 (beyond
/// the thesis; same Laplace-pressure derivation as eq 2.64 for a line contact): the meniscus
/// wets |x| < x_m with x_m^2 = 2 R (d - D), d = 2 r1 cos(theta); F = 2 x_m L gamma / r1 [N]
/// (zero when D >= d). Valid for r1 << R.
double capillary_force_cylinder(double R, double L, double surface_tension, double contact_angle,
                                double r1, double D);
/// Flat contact of area Ac at gap D (beyond the thesis): when D < d = 2 r1 cos(theta) the
/// gap fills and the Laplace pressure 2 gamma cos(theta) / D acts on Ac [N]; else 0.
double capillary_force_plate(double Ac, double surface_tension, double contact_angle, double r1,
                             double D);

// ---------------------------------------------------------------------------------------
// Materials.

// Material and Liquid, the built-in tables and find_material/find_liquid: materials.hpp
// (the one table of constants).

/// One row of the thesis' Table 3.1 (as printed).
struct Table31Row {
  std::string material;
  double permittivity;        ///< epsilon printed beside the name
  double A;                   ///< theoretical Hamaker constant [J] (printed in 1e-20 J)
  int A_decimals;             ///< decimals printed for A in units of 1e-20 J
  double old_printed;         ///< "old" gamma, D0 = 0.165 nm [mJ/m^2]
  int old_decimals;           ///< decimals printed in the old column
  double corrected_printed;   ///< corrected gamma [mJ/m^2], 4 decimals
  std::string experimental;   ///< experimental gamma as printed (text: ranges, notes)
  double experimental_mid;    ///< a number for plotting [mJ/m^2] (midpoint of a range)
};
const std::vector<Table31Row>& thesis_table_3_1();

/// Our values for one Table 3.1 row and how they compare with the printed digits.
struct Table31Check {
  double gamma_old = 0;              ///< A/(24 pi (0.165 nm)^2) [J/m^2]
  double gamma_corrected = 0;        ///< A/1.9302e-18 [J/m^2]
  double gamma_corrected_exact = 0;  ///< A/(24 pi (0.16 nm)^2), the unrounded factor [J/m^2]
  bool old_exact = false;            ///< printed old == ours rounded to the printed digits
  /// Some A' that rounds to the printed A gives the printed old value (interval test).
  bool old_within_A_rounding = false;
  bool corrected_exact = false;      ///< printed == A/1.9302e-18 to the 4 printed decimals
  bool corrected_unrounded = false;  ///< printed == A/(24 pi (0.16 nm)^2) to 4 decimals
};
Table31Check check_table_3_1_row(const Table31Row& row);

}  // namespace nanopush::forces
