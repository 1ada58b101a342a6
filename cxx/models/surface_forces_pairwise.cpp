// Chapter 2-3 pairwise-summation content (surface_forces_pairwise.hpp).
#include "nanopush/models/surface_forces_pairwise.hpp"

#include <cmath>
#include <limits>

#include "nanopush/models/surface_forces.hpp"
#include "nanopush/numerics/error.hpp"

namespace nanopush::forces {
namespace {
void count(Model m) noexcept { model_counters().n[static_cast<std::size_t>(m)].fetch_add(1, std::memory_order_relaxed); }
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

double london_coefficient(double alpha, double I) {
  require_positive("polarisability volume alpha0/(4 pi eps0)", alpha, "m^3");
  require_positive("ionisation energy I", I, "J");
  return 0.75 * alpha * alpha * I;
}
double hamaker_from_london(double C, double rho1, double rho2) {
  require_positive("London coefficient C", C, "J m^6");
  require_positive("number density rho1", rho1, "1/m^3");
  require_positive("number density rho2", rho2, "1/m^3");
  return kPi * kPi * C * rho1 * rho2;
}
double close_packed_density(double sigma) {
  require_positive("molecular diameter sigma", sigma, "m");
  return std::sqrt(2.0) / (sigma * sigma * sigma);
}

double sphere_flat_vdw_energy_exact(double A, double R, double D) {
  count(Model::sphere_surface_vdw);
  require_nonnegative("Hamaker constant A", A, "J");
  require_positive("sphere radius R", R, "m");
  require_positive("separation D", D, "m");
  // ln(D/(D+2R)) = -log1p(2R/D): accurate for D >> R, where the three terms cancel to O(R^3/D^3).
  const double x = R / D;
  if (x < 1e-2) {
    // Series in x = R/D: R/D + R/(D+2R) - log1p(2x) = (4/3) x^3 - 4 x^4 + (48/5) x^5 - ...
    // (exact coefficients: sum_k>=3 of the expansion), kept to x^9: relative error < 1e-11, as for the closed form just above the switch.
    const double s = x * x * x * (4.0 / 3.0 + x * (-4.0 + x * (48.0 / 5.0 + x * (-64.0 / 3.0 + x * (320.0 / 7.0 + x * (-96.0 + x * 1792.0 / 9.0))))));
    return -A / 6.0 * s;
  }
  return -A / 6.0 * (x + R / (D + 2.0 * R) - std::log1p(2.0 * x));
}
double sphere_flat_vdw_force_exact(double A, double R, double D) {
  count(Model::sphere_surface_vdw);
  require_nonnegative("Hamaker constant A", A, "J");
  require_positive("sphere radius R", R, "m");
  require_positive("separation D", D, "m");
  const double q = D * (D + 2.0 * R);
  return 2.0 * A * R * R * R / (3.0 * q * q);
}

double molecule_surface_contact_energy(double C, double sigma) {
  count(Model::molecule_surface);
  require_positive("London coefficient C", C, "J m^6");
  const double rho = close_packed_density(sigma);
  return -kPi * C * rho / (6.0 * sigma * sigma * sigma);
}
double sphere_surface_contact_energy(double C, double sigma, double R) {
  count(Model::sphere_surface_vdw);
  require_positive("London coefficient C", C, "J m^6");
  const double rho = close_packed_density(sigma);
  if (!(R >= 0.5 * sigma)) throw InputError("sphere radius R", fmt(R), "must be >= sigma/2 = " + fmt(0.5 * sigma) + " (m)");
  return -kPi * kPi * C * rho * rho * R / (6.0 * sigma);  // eq 2.21 at D = sigma
}
double atomic_spheres_contact_energy(double C, double sigma) {
  return 0.5 * sphere_surface_contact_energy(C, sigma, 0.5 * sigma);
}

double effective_surface_energy(double w, double sigma, MolecularSurface kind) {
  count(Model::surface_energy);
  require_positive("pair energy at contact w", w, "J");
  require_positive("molecular diameter sigma", sigma, "m");
  switch (kind) {
    case MolecularSurface::planar: return std::sqrt(3.0) * w / (sigma * sigma);
    case MolecularSurface::isolated_molecule: return 12.0 * w / (2.0 * 4.0 * kPi * 0.25 * sigma * sigma);
    case MolecularSurface::cluster_of_13: return 12.0 * 7.0 * w / (2.0 * 4.0 * kPi * 2.25 * sigma * sigma);
  }
  return kNaN;
}
double surface_energy_molecular(double A, double sigma) {
  count(Model::surface_energy);
  require_nonnegative("Hamaker constant A", A, "J");
  require_positive("molecular diameter sigma", sigma, "m");
  return std::sqrt(3.0) * A / (2.0 * kPi * kPi * sigma * sigma);
}
double lattice_energy(double C, double sigma) {
  require_positive("London coefficient C", C, "J m^6");
  require_positive("interatomic distance sigma", sigma, "m");
  return 7.22 * kAvogadro * C / std::pow(sigma, 6);
}
double work_of_adhesion_at_gap(double A, double D0, double D) {
  count(Model::surface_surface_vdw);
  require_nonnegative("Hamaker constant A", A, "J");
  require_positive("cut-off D0", D0, "m");
  if (!(D >= D0)) throw InputError("separation D", fmt(D), "must be >= D0 = " + fmt(D0) + " (m)");
  return A / (12.0 * kPi) * (1.0 / (D0 * D0) - 1.0 / (D * D));
}

const std::vector<Table22Row>& thesis_table_2_2() {
  // As printed (mJ/m^2 converted to J/m^2); "Coppel" is copper.
  static const std::vector<Table22Row> t = {
      {"aluminium", "metal", 2543, 931, 0.700, 0.800, 1.100},
      {"silver", "metal", 2223, 1233, 1.000, 1.200, 1.500},
      {"copper", "metal", 2603, 1356, 1.300, 1.600, 2.000},
      {"iron", "metal", 2773, 1803, 1.500, 1.800, 2.400},
      {"tungsten", "metal", 5273, 3653, 2.500, 3.600, 4.400},
      {"silicon", "semiconductor", 2623, 1683, 0.750, 1.100, 1.400},
      {"ice", "weak conductor", 373, 273, 0.075, 0.110, 0.071},
  };
  return t;
}
const std::vector<Table23Row>& thesis_table_2_3() {
  static const std::vector<Table23Row> t = {
      {"Al(111)-Al(111)", "similar", 0.715, 0.490, ""},
      {"Zn(001)-Zn(001)", "similar", 0.545, 0.505, ""},
      {"Al(111)-Al(111)", "similar", 0.550, 0.460,
       "printed twice with different values; likely Mg(0001)-Mg(0001), the third similar pair of the dissimilar rows"},
      {"Al(111)-Zn(0001)", "dissimilar", 0.520, kNaN, ""},
      {"Zn(001)-Mg(0001)", "dissimilar", 0.490, kNaN, ""},
      {"Al(111)-Mg(0001)", "dissimilar", 0.505, kNaN, ""},
  };
  return t;
}

}  // namespace nanopush::forces
