// Chapter 2-3 pairwise-summation content (issue 22 item 6): eqs 2.12, 2.18-2.23 (n = 6),
// 2.27-2.30, 2.42-2.44, 3.2-3.5, 3.7, and Tables 2.2-2.3 as data files.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "nanopush/models/surface_forces.hpp"
#include "nanopush/models/surface_forces_pairwise.hpp"
#include "nanopush/numerics/error.hpp"
#include "support/support.hpp"

using namespace nanopush;
using namespace nanopush::forces;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
using nanopush::test::close_to_ref;
/// Gauss-Legendre (composite, 64 panels x 8 points) of eq 2.18's integrand for n = 6:
/// w = -(A/6) int_0^{2R} (2R - z) z / (D + z)^3 dz.
double sphere_energy_quadrature(double A, double R, double D) {
  static const double xg[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static const double wg[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const int panels = 4096;
  double s = 0.0;
  // Substitution z = 2R u^2 clusters the points near z = 0, where the integrand varies on D.
  for (int p = 0; p < panels; ++p) {
    const double a = double(p) / panels, b = double(p + 1) / panels, m = 0.5 * (a + b), h = 0.5 * (b - a);
    for (int k = 0; k < 4; ++k)
      for (int sg : {-1, 1}) {
        const double u = m + sg * h * xg[k], z = 2 * R * u * u, dz = 4 * R * u;
        s += wg[k] * h * (2 * R - z) * z / std::pow(D + z, 3) * dz;
      }
  }
  return -A / 6.0 * s;
}
std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream f(path);
  REQUIRE(f.good());
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(f, line)) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream ls(line);
    while (std::getline(ls, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}
}  // namespace

TEST_CASE("Eq 2.12 and A = pi^2 C rho^2: methane's London coefficient and Hamaker constant",
          "[forces][pairwise][unit]") {
  // Israelachvili's methane: alpha0/(4 pi eps0) = 2.60e-30 m^3, I = 12.6 eV -> C = 102e-79 J m^6.
  const double C = london_coefficient(2.60e-30, 12.6 * kElectronVolt);
  CHECK(std::round(C / 1e-79) == 102.0);
  // Close packing at sigma = 0.4 nm: rho = sqrt(2)/sigma^3; A = pi^2 C rho^2.
  const double rho = close_packed_density(0.4e-9);
  CHECK(close_to_ref(rho, std::sqrt(2.0) / 6.4e-29, 2 * test::kEps));
  CHECK(close_to_ref(hamaker_from_london(C, rho, rho), kPi * kPi * C * rho * rho, 2 * test::kEps));
  CHECK_THROWS_AS(london_coefficient(-1e-30, 1e-18), InputError);
}

TEST_CASE("Eq 2.18 (n = 6): exact sphere-flat energy against quadrature and its limits 2.21-2.23",
          "[forces][pairwise][unit]") {
  const double A = 1e-19, R = 10e-9;
  for (double D : {0.2e-9, 1e-9, 10e-9, 100e-9, 1e-6}) {
    INFO("D = " << D);
    CHECK(close_to_ref(sphere_flat_vdw_energy_exact(A, R, D), sphere_energy_quadrature(A, R, D), 1e-10));
    // Force = -dw/dD by a central difference (relative step 1e-4: error ~1e-8).
    const double h = 1e-4 * D;
    const double fd = (sphere_flat_vdw_energy_exact(A, R, D + h) - sphere_flat_vdw_energy_exact(A, R, D - h)) / (2 * h);
    CHECK(close_to_ref(sphere_flat_vdw_force_exact(A, R, D), fd, 1e-7));
  }
  // D << R: eq 2.21-2.22, relative corrections (1/2 + ln(D/2R)) D/R and 4 D/R (1.7e-6, 4e-7 here);
  // D >> R: eq 2.23 (a molecule count 4 pi R^3 rho/3 times eq 2.16), corrections 3R/D, 4R/D.
  const double Dn = 1e-15;
  CHECK(close_to_ref(sphere_flat_vdw_energy_exact(A, R, Dn), sphere_flat_vdw_energy(A, R, Dn), 2e-6));
  CHECK(close_to_ref(sphere_flat_vdw_force_exact(A, R, Dn), sphere_flat_vdw_force(A, R, Dn), 5e-7));
  const double Df = 1e-3;
  CHECK(close_to_ref(sphere_flat_vdw_energy_exact(A, R, Df), -2.0 / 9.0 * A * std::pow(R / Df, 3), 1e-4));
  CHECK(close_to_ref(sphere_flat_vdw_force_exact(A, R, Df), 2.0 / 3.0 * A * std::pow(R, 3) / std::pow(Df, 4), 1e-4));
  // The series branch (R/D < 1e-2) joins the closed form.
  const double Ds = R / 1e-2;
  CHECK(close_to_ref(sphere_flat_vdw_energy_exact(A, R, Ds * (1 - 1e-12)), sphere_flat_vdw_energy_exact(A, R, Ds * (1 + 1e-12)), 1e-10));
}

TEST_CASE("Eqs 2.27-2.30: contact energies of molecular-scale bodies", "[forces][pairwise][unit]") {
  const double C = 1e-77, s = 0.3e-9, u = C / std::pow(s, 6);
  CHECK(close_to_ref(molecule_surface_contact_energy(C, s), -std::sqrt(2.0) * kPi / 6 * u, 4 * test::kEps));
  CHECK(std::round(-molecule_surface_contact_energy(C, s) / u * 100) == 74.0);  // -0.74 C/sigma^6
  CHECK(std::round(-sphere_surface_contact_energy(C, s, 0.5 * s) / u * 10) == 16.0);  // 2.28: -1.6
  CHECK(std::round(-atomic_spheres_contact_energy(C, s) / u * 10) == 8.0);            // 2.29: -0.8
  // 2.30: linear in R, -1.6 (2R/sigma) C/sigma^6 (1.645 unrounded = pi^2/6).
  for (double R : {0.5 * s, 2 * s, 10 * s})
    CHECK(close_to_ref(sphere_surface_contact_energy(C, s, R), -kPi * kPi / 6 * (2 * R / s) * u, 4 * test::kEps));
  CHECK_THROWS_AS(sphere_surface_contact_energy(C, s, 0.4 * s), InputError);
}

TEST_CASE("Eqs 2.42-2.44, 3.7: effective surface energies; 3.7 equals 2.42 with w of 2.27's pair",
          "[forces][pairwise][unit]") {
  const double w = 1e-20, s = 0.4e-9, u = w / (s * s);
  CHECK(std::round(effective_surface_energy(w, s, MolecularSurface::planar) / u * 100) == 173.0);  // sqrt(3)
  CHECK(std::round(effective_surface_energy(w, s, MolecularSurface::isolated_molecule) / u * 10) == 19.0);
  CHECK(std::round(effective_surface_energy(w, s, MolecularSurface::cluster_of_13) / u * 10) == 15.0);
  // 3.7: gamma = sqrt(3) C rho^2 / (2 sigma^2) with A = pi^2 C rho^2 -- i.e. 2.42 with w = C rho^2/2.
  const double C = 1e-77, rho = close_packed_density(s), A = hamaker_from_london(C, rho, rho);
  CHECK(close_to_ref(surface_energy_molecular(A, s), effective_surface_energy(C * rho * rho / 2, s, MolecularSurface::planar), 8 * test::kEps));
  // The thesis' 3.8-3.9 route: gamma = A/(24 pi (sigma/2.5)^2) is (2.5^2 pi/(12 sqrt(3))) = 0.94 of 3.7.
  CHECK(std::round(surface_energy_from_hamaker(A, s / 2.5) / surface_energy_molecular(A, s) * 100) == 94.0);
}

TEST_CASE("Eqs 3.2-3.5: lattice energy and the work of adhesion at a gap", "[forces][pairwise][unit]") {
  const double C = 1e-77, s = 0.4e-9;
  CHECK(close_to_ref(lattice_energy(C, s), 7.22 * kAvogadro * C / std::pow(s, 6), 4 * test::kEps));
  const double A = 4.7e-19, D0 = 0.165e-9;
  // 3.5: at D -> infinity the work is A/(12 pi D0^2) = 2 gamma (gamma of eq 3.6).
  CHECK(close_to_ref(work_of_adhesion_at_gap(A, D0, 1.0), 2 * surface_energy_from_hamaker(A, D0), 1e-12));
  CHECK(work_of_adhesion_at_gap(A, D0, D0) == 0.0);
  // 3.4: W (1 - D0^2/D^2).
  for (double D : {0.2e-9, 0.5e-9, 2e-9})
    CHECK(close_to_ref(work_of_adhesion_at_gap(A, D0, D), 2 * surface_energy_from_hamaker(A, D0) * (1 - D0 * D0 / (D * D)), 1e-14));
  CHECK_THROWS_AS(work_of_adhesion_at_gap(A, D0, 0.1e-9), InputError);
}

TEST_CASE("Tables 2.2-2.3: the data files scenes use are the tables in code", "[forces][pairwise][unit]") {
  const std::string dir = std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/data/";
  const auto t22 = read_csv(dir + "table2_2.csv");
  REQUIRE(t22.size() == thesis_table_2_2().size() + 1);
  CHECK(t22[0] == std::vector<std::string>{"material", "kind", "boiling_point", "melting_point", "gamma_above_melting",
                                           "gamma_below_melting", "gamma_300K"});
  for (std::size_t i = 0; i < thesis_table_2_2().size(); ++i) {
    const auto& r = thesis_table_2_2()[i];
    const auto& c = t22[i + 1];
    REQUIRE(c.size() == 7);
    CHECK(c[0] == r.material);
    CHECK(c[1] == r.kind);
    CHECK(std::stod(c[2]) == r.boiling_point);
    CHECK(std::stod(c[3]) == r.melting_point);
    CHECK(std::stod(c[4]) == r.gamma_above_melting);
    CHECK(std::stod(c[5]) == r.gamma_below_melting);
    CHECK(std::stod(c[6]) == r.gamma_300K);
  }
  const auto t23 = read_csv(dir + "table2_3.csv");
  REQUIRE(t23.size() == thesis_table_2_3().size() + 1);
  for (std::size_t i = 0; i < thesis_table_2_3().size(); ++i) {
    const auto& r = thesis_table_2_3()[i];
    const auto& c = t23[i + 1];
    REQUIRE(c.size() >= 4);
    CHECK(c[0] == r.interface);
    CHECK(std::stod(c[2]) == r.commensurate);
    if (std::isnan(r.incommensurate)) CHECK(c[3].empty());
    else CHECK(std::stod(c[3]) == r.incommensurate);
  }
  // Table 2.2's silicon at 300 K is the value a scene sets as surface_energy for a measured
  // (not eq 3.9) silicon gamma.
  CHECK(thesis_table_2_2()[5].material == "silicon");
  CHECK(thesis_table_2_2()[5].gamma_300K == 1.4);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
