// Surface and adhesion forces (docs/models.md section F). See surface_forces.hpp for the
// conventions (gamma vs W = 2 gamma, attractive magnitudes, SI).
#include "nanopush/models/surface_forces.hpp"

#include <cmath>
#include <limits>

#include "nanopush/numerics/error.hpp"

namespace nanopush::forces {
namespace {

void count(Model m) noexcept {
  model_counters().n[static_cast<std::size_t>(m)].fetch_add(1, std::memory_order_relaxed);
}

void need_hamaker(double A) { require_nonnegative("Hamaker constant A", A, "J"); }
void need_gap(const char* field, double D) { require_positive(field, D, "m"); }
/// An energy per area (a surface energy, a work of adhesion), >= 0.
void need_energy(const char* field, double gamma) { require_nonnegative(field, gamma, "J/m^2"); }
/// What every van der Waals model of two continua checks: the model counted, the Hamaker
/// constant >= 0 and the gap (named `gap`) > 0.
void vdw_model(Model m, double A, const char* gap, double D) {
  count(m);
  need_hamaker(A);
  need_gap(gap, D);
}

/// sqrt of a product that must not be negative (combining relations).
double geometric_mean(const char* field, double x, double y) {
  require_finite(field, x * y);
  if (x * y < 0.0)
    throw InputError(field, fmt(x) + " * " + fmt(y), "product of the Hamaker constants must be >= 0");
  return std::sqrt(x * y);
}

}  // namespace

// --------------------------------------------------------------------------- counters
std::string_view model_name(Model m) {
  switch (m) {
    case Model::molecule_surface: return "molecule-surface vdW (2.16-2.17)";
    case Model::sphere_surface_vdw: return "sphere-flat vdW (2.21-2.22)";
    case Model::sphere_sphere_vdw: return "sphere-sphere vdW";
    case Model::surface_surface_vdw: return "flat-flat vdW (2.25-2.26)";
    case Model::rod_plane_vdw: return "rod-plane vdW (Parsegian)";
    case Model::layered_vdw: return "layered surfaces vdW (2.38-2.41)";
    case Model::metallic_adhesion: return "metallic adhesion (2.37)";
    case Model::dupre: return "Dupre relations (2.31-2.36)";
    case Model::hamaker_combining: return "Hamaker combining relation";
    case Model::surface_energy: return "surface energy from A (3.6, 3.9)";
    case Model::derjaguin: return "Derjaguin/DMT (2.45-2.49)";
    case Model::jkr: return "JKR sphere (2.50-2.55)";
    case Model::jkr_line: return "JKR cylinder-plane line contact";
    case Model::hertz: return "Hertz (2.56-2.59)";
    case Model::kelvin: return "Kelvin radius (2.60)";
    case Model::laplace: return "Laplace pressure (2.61-2.63)";
    case Model::capillary: return "capillary meniscus (2.64-2.71)";
    case Model::count_: break;
  }
  return "?";
}

bool is_adhesion_model(Model m) {
  // Hertz is the only pure-elasticity model; everything else describes attraction.
  return m != Model::hertz && m != Model::count_;
}

void ModelCounters::reset() noexcept {
  for (auto& c : n) c.store(0);
}
unsigned long ModelCounters::adhesion_total() const noexcept {
  unsigned long s = 0;
  for (std::size_t i = 0; i < kModelCount; ++i)
    if (is_adhesion_model(static_cast<Model>(i))) s += n[i].load();
  return s;
}
ModelCounters& model_counters() {
  static ModelCounters c;
  return c;
}

// --------------------------------------------------------------------------- van der Waals
double molecule_surface_energy(double C, double rho, double D) {
  count(Model::molecule_surface);
  require_nonnegative("pair constant C", C, "J m^6");
  require_nonnegative("number density rho", rho, "1/m^3");
  need_gap("separation D", D);
  return -kPi * C * rho / (6.0 * D * D * D);
}
double molecule_surface_force(double C, double rho, double D) {
  count(Model::molecule_surface);
  require_nonnegative("pair constant C", C, "J m^6");
  require_nonnegative("number density rho", rho, "1/m^3");
  need_gap("separation D", D);
  return kPi * C * rho / (2.0 * D * D * D * D);
}

double sphere_flat_vdw_energy(double A, double R, double D) {
  vdw_model(Model::sphere_surface_vdw, A, "separation D", D);
  require_positive("sphere radius R", R, "m");
  return -A * R / (6.0 * D);
}
double sphere_flat_vdw_force(double A, double R, double D) {
  vdw_model(Model::sphere_surface_vdw, A, "separation D", D);
  require_positive("sphere radius R", R, "m");
  return A * R / (6.0 * D * D);
}
double sphere_sphere_vdw_force(double A, double R1, double R2, double D) {
  vdw_model(Model::sphere_sphere_vdw, A, "separation D", D);
  require_positive("sphere radius R1", R1, "m");
  require_positive("sphere radius R2", R2, "m");
  return A * (R1 * R2 / (R1 + R2)) / (6.0 * D * D);
}

double flat_flat_vdw_energy_per_area(double A, double D) {
  vdw_model(Model::surface_surface_vdw, A, "separation D", D);
  return -A / (12.0 * kPi * D * D);
}
double flat_flat_vdw_pressure(double A, double D) {
  vdw_model(Model::surface_surface_vdw, A, "separation D", D);
  return A / (6.0 * kPi * D * D * D);
}

double rod_plane_vdw_force(double A, double L, double d, double z0) {
  vdw_model(Model::rod_plane_vdw, A, "rod-plane gap z0", z0);
  require_positive("rod length L", L, "m");
  require_positive("rod diameter d", d, "m");
  return L * A * std::sqrt(d) / (16.0 * std::pow(z0, 2.5));
}

double bar_plane_vdw_force(double A, double length, double width, double T, double D) {
  vdw_model(Model::surface_surface_vdw, A, "bar-plane gap D", D);
  require_positive("bar length", length, "m");
  require_positive("bar width", width, "m");
  require_positive("bar thickness T", T, "m");
  const double DT = D + T;
  return length * width * A / (6.0 * kPi) * (1.0 / (D * D * D) - 1.0 / (DT * DT * DT));
}

double layered_vdw_pressure_symmetric(double A232, double A123, double A121, double T, double D) {
  count(Model::layered_vdw);
  require_finite("A232", A232, "J");
  require_finite("A123", A123, "J");
  require_finite("A121", A121, "J");
  require_nonnegative("layer thickness T", T, "m");
  need_gap("separation D", D);
  const double a = D + T, b = D + 2.0 * T;
  return (A232 / (D * D * D) - 2.0 * A123 / (a * a * a) + A121 / (b * b * b)) / (6.0 * kPi);
}
double layered_vdw_pressure(double A232p, double A121, double A32p3, double A1p2p1p, double A323,
                            double T, double Tp, double D) {
  count(Model::layered_vdw);
  require_finite("A232'", A232p, "J");
  require_nonnegative("layer thickness T", T, "m");
  require_nonnegative("layer thickness T'", Tp, "m");
  need_gap("separation D", D);
  const double g1 = geometric_mean("A121 A32'3", A121, A32p3);
  const double g2 = geometric_mean("A1'2'1' A323", A1p2p1p, A323);
  const double g3 = geometric_mean("A1'2'1' A121", A1p2p1p, A121);
  const double a = D + T, b = D + Tp, c = D + T + Tp;
  return (A232p / (D * D * D) - g1 / (a * a * a) - g2 / (b * b * b) + g3 / (c * c * c)) / (6.0 * kPi);
}

namespace {
/// The metallic-adhesion model's checks, counted once per evaluation; x = (D - D0)/lambda_M.
double metallic_x(double gamma, double D, double D0, double lambda) {
  count(Model::metallic_adhesion);
  need_energy("surface energy gamma", gamma);
  require_positive("equilibrium distance D0", D0, "m");
  require_positive("decay length lambda_M", lambda, "m");
  need_gap("separation D", D);
  if (D < D0) throw InputError("separation D", fmt(D), "must be >= D0 = " + fmt(D0) + " (m)");
  return (D - D0) / lambda;
}
}  // namespace

double metallic_adhesion_energy_per_area(double gamma, double D, double D0, double lambda) {
  const double x = metallic_x(gamma, D, D0, lambda);
  return -2.0 * gamma * (1.0 + x) * std::exp(-x);
}
double metallic_adhesion_pressure(double gamma, double D, double D0, double lambda) {
  const double x = metallic_x(gamma, D, D0, lambda);
  return 2.0 * gamma * x * std::exp(-x) / lambda;
}

// --------------------------------------------------------------------------- energies
double surface_energy_from_hamaker(double A, double D0) {
  count(Model::surface_energy);
  need_hamaker(A);
  require_positive("cut-off distance D0", D0, "m");
  return A / (24.0 * kPi * D0 * D0);
}
double surface_energy_corrected(double A) {
  count(Model::surface_energy);
  need_hamaker(A);
  return A / kThesisHamakerPerGamma;
}
double work_of_cohesion(double gamma1) {
  count(Model::dupre);
  need_energy("surface energy gamma1", gamma1);
  return 2.0 * gamma1;
}
double interfacial_energy(double gamma1, double gamma2, double W12) {
  count(Model::dupre);
  need_energy("surface energy gamma1", gamma1);
  need_energy("surface energy gamma2", gamma2);
  require_finite("work of adhesion W12", W12, "J/m^2");
  return gamma1 + gamma2 - W12;
}
double work_of_adhesion_dispersion(double gamma1d, double gamma2d) {
  count(Model::dupre);
  need_energy("dispersion surface energy gamma1d", gamma1d);
  need_energy("dispersion surface energy gamma2d", gamma2d);
  return 2.0 * std::sqrt(gamma1d * gamma2d);
}
double work_of_adhesion_in_medium(double gamma13, double gamma23, double gamma12) {
  count(Model::dupre);
  require_finite("interfacial energy gamma13", gamma13, "J/m^2");
  require_finite("interfacial energy gamma23", gamma23, "J/m^2");
  require_finite("interfacial energy gamma12", gamma12, "J/m^2");
  return gamma13 + gamma23 - gamma12;
}
double hamaker_combined(double A11, double A22, double A33) {
  count(Model::hamaker_combining);
  require_nonnegative("Hamaker constant A11", A11, "J");
  require_nonnegative("Hamaker constant A22", A22, "J");
  require_nonnegative("Hamaker constant A33", A33, "J");
  return (std::sqrt(A11) - std::sqrt(A33)) * (std::sqrt(A22) - std::sqrt(A33));
}

// --------------------------------------------------------------------------- contact
double effective_radius(double R1, double R2) {
  require_positive("radius R1", R1, "m");
  if (std::isinf(R2) && R2 > 0) return R1;
  require_positive("radius R2", R2, "m");
  return R1 * R2 / (R1 + R2);
}
double effective_modulus(double E1, double nu1, double E2, double nu2) {
  if (!(E1 > 0)) throw InputError("Young's modulus E1", fmt(E1), "must be > 0 (Pa)");
  if (!(E2 > 0)) throw InputError("Young's modulus E2", fmt(E2), "must be > 0 (Pa)");
  require_range("Poisson ratio nu1", nu1, -1.0, 0.5);
  require_range("Poisson ratio nu2", nu2, -1.0, 0.5);
  const double c1 = std::isinf(E1) ? 0.0 : (1.0 - nu1 * nu1) / E1;
  const double c2 = std::isinf(E2) ? 0.0 : (1.0 - nu2 * nu2) / E2;
  if (c1 + c2 == 0.0) return std::numeric_limits<double>::infinity();
  return 1.0 / (c1 + c2);
}
double derjaguin_adhesion_force(double Reff, double W) {
  count(Model::derjaguin);
  require_positive("effective radius R", Reff, "m");
  need_energy("work of adhesion W", W);
  return 2.0 * kPi * Reff * W;
}

namespace {
/// The elastic contact's radius (`radius`: how the model names R) and effective modulus.
void check_elastic(const char* radius, double R, double Estar) {
  require_positive(radius, R, "m");
  require_positive("effective modulus E*", Estar, "Pa");
}
void check_contact(double R, double Estar, double W) {
  check_elastic("effective radius R", R, Estar);
  need_energy("work of adhesion W", W);
}
}  // namespace

double jkr_contact_radius(double R, double Estar, double W, double F) {
  count(Model::jkr);
  check_contact(R, Estar, W);
  require_finite("load F", F, "N");
  const double K = 4.0 * Estar / 3.0;
  const double c = 3.0 * kPi * R * W;
  const double disc = 2.0 * c * F + c * c;  // 6 pi R W F + (3 pi R W)^2
  if (disc < 0.0)
    throw InputError("load F", fmt(F), "must be >= the JKR pull-off load " + fmt(-0.5 * c) + " (N)");
  return std::cbrt(R / K * (F + c + std::sqrt(disc)));
}
double jkr_zero_load_radius(double R, double Estar, double W) {
  count(Model::jkr);
  check_contact(R, Estar, W);
  const double K = 4.0 * Estar / 3.0;
  return std::cbrt(6.0 * kPi * R * R * W / K);
}
double jkr_pull_off_force(double R, double W) {
  count(Model::jkr);
  require_positive("effective radius R", R, "m");
  need_energy("work of adhesion W", W);
  return 1.5 * kPi * R * W;
}
double jkr_separation_radius(double R, double Estar, double W) {
  return jkr_zero_load_radius(R, Estar, W) / std::cbrt(4.0);
}
double jkr_central_displacement(double R, double Estar, double W, double a) {
  const double a0 = jkr_zero_load_radius(R, Estar, W);
  require_positive("contact radius a", a, "m");
  return a * a / R * (1.0 - 2.0 / 3.0 * std::pow(a0 / a, 1.5));
}
double jkr_pressure(double R, double Estar, double W, double a, double x) {
  count(Model::jkr);
  check_contact(R, Estar, W);
  require_positive("contact radius a", a, "m");
  require_range("x = r/a", x, 0.0, 1.0);
  if (x >= 1.0) throw InputError("x = r/a", fmt(x), "must be < 1 (the JKR edge stress is singular)");
  const double K = 4.0 * Estar / 3.0;
  const double s = std::sqrt(1.0 - x * x);
  return 3.0 * K * a * s / (2.0 * kPi * R) - std::sqrt(3.0 * K * W / (2.0 * kPi * a)) / s;
}
double jkr_load_for_radius(double R, double Estar, double W, double a) {
  count(Model::jkr);
  check_contact(R, Estar, W);
  require_positive("contact radius a", a, "m");
  const double K = 4.0 * Estar / 3.0;
  const double a3 = a * a * a;
  return K * a3 / R - std::sqrt(6.0 * kPi * W * K * a3);
}

double hertz_contact_radius(double R, double Estar, double F) {
  count(Model::hertz);
  check_elastic("effective radius R", R, Estar);
  require_nonnegative("load F", F, "N");
  return std::cbrt(3.0 * F * R / (4.0 * Estar));
}
double hertz_displacement(double R, double Estar, double F) {
  const double a = hertz_contact_radius(R, Estar, F);
  return a * a / R;
}
double hertz_pressure(double R, double Estar, double F, double x) {
  require_range("x = r/a", x, 0.0, 1.0);
  const double a = hertz_contact_radius(R, Estar, F);
  if (a == 0.0) return 0.0;
  return 3.0 * F * std::sqrt(1.0 - x * x) / (2.0 * kPi * a * a);
}

double hertz_line_half_width(double R, double Estar, double p) {
  count(Model::hertz);
  check_elastic("radius R", R, Estar);
  require_nonnegative("load per length p", p, "N/m");
  return std::sqrt(4.0 * p * R / (kPi * Estar));
}

double jkr_line_load_per_length(double R, double Estar, double W, double b) {
  count(Model::jkr_line);
  check_contact(R, Estar, W);
  require_nonnegative("half-width b", b, "m");
  return kPi * Estar * b * b / (4.0 * R) - std::sqrt(2.0 * kPi * Estar * W * b);
}
double jkr_line_half_width(double R, double Estar, double W, double p) {
  count(Model::jkr_line);
  check_contact(R, Estar, W);
  require_finite("load per length p", p, "N/m");
  // In s = sqrt(b): g(s) = al s^4 - be s - p, al = pi E*/(4R), be = sqrt(2 pi E* W).
  // g is convex in s >= 0 with its minimum at s* = (be/(4 al))^(1/3); the stable branch is
  // s > s*, where g increases monotonically. Bracket there and bisect with Newton steps.
  const double al = kPi * Estar / (4.0 * R);
  const double be = std::sqrt(2.0 * kPi * Estar * W);
  const double s_min = std::cbrt(be / (4.0 * al));
  auto g = [&](double s) { return al * s * s * s * s - be * s - p; };
  if (g(s_min) > 0.0) {
    const double p_off = al * std::pow(s_min, 4) - be * s_min;
    throw InputError("load per length p", fmt(p), "must be >= the line pull-off load " + fmt(p_off) + " (N/m)");
  }
  double lo = s_min;
  double hi = std::max(2.0 * s_min, std::sqrt(std::sqrt(std::max(p, 0.0) / al)) + std::cbrt(be / al) + 1e-300);
  while (g(hi) < 0.0) hi *= 2.0;
  double s = hi;
  for (int it = 0; it < 200; ++it) {
    const double gs = g(s);
    if (gs > 0.0) hi = s; else lo = s;
    const double dg = 4.0 * al * s * s * s - be;
    double next = s - gs / dg;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - s) <= 1e-16 * s) { s = next; break; }
    s = next;
  }
  return s * s;
}
double jkr_line_thesis_work_of_adhesion(double R, double Estar, double b, double l, double P) {
  count(Model::jkr_line);
  check_elastic("radius R", R, Estar);
  require_positive("half-width b", b, "m");
  require_positive("half-length l", l, "m");
  require_finite("load P", P, "N");
  const double K = 4.0 * Estar / 3.0;
  const double t = 3.0 * kPi * K * b * b * l / (8.0 * R) - P;
  return t * t / (6.0 * kPi * K * b * l * l);
}

// --------------------------------------------------------------------------- capillary
double kelvin_radius(double gammaL, double V, double T, double RH) {
  count(Model::kelvin);
  require_positive("surface tension", gammaL, "N/m");
  require_positive("molar volume", V, "m^3/mol");
  require_positive("temperature", T, "K");
  require_range("relative humidity", RH, 0.0, 1.0);
  if (RH == 0.0) return 0.0;  // no condensate
  if (RH == 1.0) return -std::numeric_limits<double>::infinity();
  return gammaL * V / (kGasConstant * T * std::log(RH));
}
double laplace_pressure(double gammaL, double r1, double r2) {
  count(Model::laplace);
  require_nonnegative("surface tension", gammaL, "N/m");
  if (r1 == 0.0 || !std::isfinite(r1)) throw InputError("radius r1", fmt(r1), "must be finite and != 0 (m)");
  const double inv2 = std::isinf(r2) ? 0.0 : 1.0 / r2;
  return gammaL * (1.0 / r1 + inv2);
}
namespace {
void check_liquid(double gammaL, double theta) {
  require_nonnegative("surface tension", gammaL, "N/m");
  require_range("contact angle", theta, 0.0, kPi / 2.0, "rad");
}
/// Counts a capillary evaluation and checks a sphere of radius R under the liquid.
void check_sphere(double R, double gammaL, double theta) {
  count(Model::capillary);
  require_positive("sphere radius R", R, "m");
  check_liquid(gammaL, theta);
}
/// Checks the meniscus radius r1 and the separation D (> 0 where the model divides by it, else
/// >= 0); returns the meniscus height d = 2 r1 cos(theta).
double meniscus_height(double theta, double r1, double D, bool D_positive = false) {
  require_nonnegative("meniscus radius r1", r1, "m");
  if (D_positive)
    require_positive("separation D", D, "m");
  else
    require_nonnegative("separation D", D, "m");
  return 2.0 * r1 * std::cos(theta);
}
}  // namespace
double capillary_force_max(double R, double gammaL, double theta) {
  check_sphere(R, gammaL, theta);
  return 4.0 * kPi * R * gammaL * std::cos(theta);
}
double capillary_force_sphere(double R, double gammaL, double theta, double r1, double D) {
  check_sphere(R, gammaL, theta);
  const double d = meniscus_height(theta, r1, D);
  if (d == 0.0) return 0.0;
  return 4.0 * kPi * R * gammaL * std::cos(theta) / (1.0 + D / d);
}
double capillary_force_with_solid_contact(double R, double gammaL, double theta, double gamma_SL) {
  check_sphere(R, gammaL, theta);
  need_energy("solid-liquid energy gamma_SL", gamma_SL);
  return 4.0 * kPi * R * (gammaL * std::cos(theta) + gamma_SL);
}
double capillary_force_cylinder(double R, double L, double gammaL, double theta, double r1, double D) {
  count(Model::capillary);
  require_positive("cylinder radius R", R, "m");
  require_positive("cylinder length L", L, "m");
  check_liquid(gammaL, theta);
  const double d = meniscus_height(theta, r1, D);
  if (D >= d || r1 == 0.0) return 0.0;
  const double xm = std::sqrt(2.0 * R * (d - D));
  return 2.0 * xm * L * gammaL / r1;
}
double capillary_force_plate(double Ac, double gammaL, double theta, double r1, double D) {
  count(Model::capillary);
  require_nonnegative("contact area", Ac, "m^2");
  check_liquid(gammaL, theta);
  const double d = meniscus_height(theta, r1, D, true);
  if (D >= d) return 0.0;
  return 2.0 * gammaL * std::cos(theta) / D * Ac;
}

const std::vector<Table31Row>& thesis_table_3_1() {
  // Transcribed from the thesis' Table 3.1 (printed A in 1e-20 J, gammas in mJ/m^2).
  static const std::vector<Table31Row> t = {
      {"Liquid helium", 1.057, 0.057e-20, 3, 0.28, 2, 0.2953, "0.12-0.35 (4-1.6 K)", 0.235},
      {"n-Pentane", 1.8, 3.750e-20, 3, 18.3, 1, 19.4280, "16.1", 16.1},
      {"n-Octane", 1.9, 4.50e-20, 2, 21.9, 1, 23.3313, "21.6", 21.6},
      {"Cyclohexane", 2.0, 5.20e-20, 2, 25.3, 1, 26.9402, "25.5", 25.5},
      {"n-Dodecane", 2.0, 5.00e-20, 2, 24.4, 1, 25.9041, "25.4", 25.4},
      {"n-Hexadecane", 2.1, 5.20e-20, 2, 25.3, 1, 26.9402, "27.5", 27.5},
      {"PTFE", 2.1, 3.80e-20, 2, 18.5, 1, 19.6871, "18.3", 18.3},
      {"CCl4", 2.2, 5.5e-20, 1, 26.8, 1, 28.4945, "29.7", 29.7},
      {"Benzene", 2.3, 5.00e-20, 2, 24.4, 1, 25.9041, "28.8", 28.8},
      {"Polystyrene", 2.6, 6.60e-20, 2, 32.1, 1, 34.1934, "33", 33.0},
      {"Polyvinyl chloride", 3.2, 7.80e-20, 2, 38.0, 1, 40.4104, "39", 39.0},
      {"Acetone", 21.0, 4.10e-20, 2, 20.0, 1, 21.2413, "23.7", 23.7},
      {"Ethanol", 26.0, 4.20e-20, 2, 20.5, 1, 21.7594, "22.8", 22.8},
      {"Methanol", 33.0, 3.60e-20, 2, 18.0, 0, 18.6509, "23", 23.0},
      {"Glycol", 37.0, 5.60e-20, 2, 28.0, 0, 29.0126, "48", 48.0},
      {"Water", 80.0, 3.70e-20, 2, 18.0, 0, 19.1690, "73", 73.0},
      {"H2O2", 84.0, 5.40e-20, 2, 26.0, 0, 27.9764, "76", 76.0},
      {"Formamide", 109.0, 6.10e-20, 2, 30.0, 0, 31.6030, "58", 58.0},
  };
  return t;
}

namespace {
double round_to(double v, int decimals) {
  const double s = std::pow(10.0, decimals);
  return std::round(v * s) / s;
}
}  // namespace

Table31Check check_table_3_1_row(const Table31Row& row) {
  Table31Check c;
  c.gamma_old = surface_energy_from_hamaker(row.A);
  c.gamma_corrected = surface_energy_corrected(row.A);
  c.gamma_corrected_exact = surface_energy_from_hamaker(row.A, 0.4e-9 / 2.5);
  c.old_exact = round_to(c.gamma_old * 1e3, row.old_decimals) == row.old_printed;
  const double halfA = 0.5 * std::pow(10.0, -row.A_decimals) * 1e-20;
  const double lo = surface_energy_from_hamaker(row.A - halfA) * 1e3;
  const double hi = surface_energy_from_hamaker(row.A + halfA) * 1e3;
  const double half_old = 0.5 * std::pow(10.0, -row.old_decimals);
  c.old_within_A_rounding = hi >= row.old_printed - half_old && lo <= row.old_printed + half_old;
  c.corrected_exact = round_to(c.gamma_corrected * 1e3, 4) == round_to(row.corrected_printed, 4);
  c.corrected_unrounded = round_to(c.gamma_corrected_exact * 1e3, 4) == round_to(row.corrected_printed, 4);
  return c;
}

}  // namespace nanopush::forces
