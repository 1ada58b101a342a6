// Surface and adhesion forces (docs/models.md F): independent closed-form oracles of issue 6,
// internal consistency of the contact models, Table 3.1 against the printed digits, and
// input validation.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "nanopush/numerics/error.hpp"
#include "nanopush/models/surface_forces.hpp"
#include "support/support.hpp"

using namespace nanopush;
using namespace nanopush::forces;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
using nanopush::test::rel_close;
/// |value/unit - printed| <= half a unit in the last printed digit: "to all given digits".
bool to_printed_digits(double value, double unit, double printed, int decimals) {
  return std::abs(value / unit - printed) <= 0.5 * std::pow(10.0, -decimals);
}
}  // namespace

TEST_CASE("Issue 6 oracles for A = 1e-19 J, R = 10 nm, to all given digits", "[forces][unit]") {
  const double A = 1e-19, R = 10e-9;
  SECTION("sphere-flat van der Waals A R/(6 D^2) = 1.041666667 nN at D = 0.4 nm (eq 2.22)") {
    const double F = sphere_flat_vdw_force(A, R, 0.4e-9);
    CHECK(to_printed_digits(F, 1e-9, 1.041666667, 9));
    CHECK(rel_close(F, 1e-27 / 9.6e-19, 4 * test::kEps));
  }
  SECTION("JKR pull-off 1.5 pi R W = 4.71238898 nN at W = 0.1 J/m^2 (eq 2.52)") {
    CHECK(to_printed_digits(jkr_pull_off_force(R, 0.1), 1e-9, 4.71238898, 8));
  }
  SECTION("DMT / Derjaguin 2 pi R W = 6.283185307 nN (eq 2.45)") {
    CHECK(to_printed_digits(dmt_pull_off_force(R, 0.1), 1e-9, 6.283185307, 9));
  }
  SECTION("capillary 4 pi R gamma cos(theta) = 9.047786842 nN, gamma = 0.072 N/m, theta = 0 (eq 2.70)") {
    CHECK(to_printed_digits(capillary_force_max(R, 0.072, 0.0), 1e-9, 9.047786842, 9));
    // eq 2.69 at D = 0 is the maximum, and eq 2.71 with gamma_SL = 0 too.
    CHECK(capillary_force_sphere(R, 0.072, 0.0, 0.5e-9, 0.0) == capillary_force_max(R, 0.072, 0.0));
    CHECK(capillary_force_with_solid_contact(R, 0.072, 0.0, 0.0) == capillary_force_max(R, 0.072, 0.0));
  }
  SECTION("Hertz radius (3 F R/(4 E*))^(1/3) = 0.4217163327 nm at F = 1 nN, E* = 100 GPa (eq 2.57)") {
    CHECK(to_printed_digits(hertz_contact_radius(R, 100e9, 1e-9), 1e-9, 0.4217163327, 10));
  }
}

TEST_CASE("gamma versus W = 2 gamma: Derjaguin sphere-flat equals 4 pi R gamma (eq 2.48)", "[forces][unit]") {
  const double R = 7e-9, gamma = 0.05;
  CHECK(rel_close(derjaguin_adhesion_force(R, work_of_cohesion(gamma)), 4 * kPi * R * gamma, 4 * test::kEps));
  CHECK(rel_close(jkr_pull_off_force(R, 2 * gamma), 3 * kPi * R * gamma, 4 * test::kEps));  // eq 2.52
  CHECK(work_of_adhesion_dispersion(gamma, gamma) == 2 * gamma);                     // eq 2.35, like materials
  CHECK(interfacial_energy(gamma, gamma, 2 * gamma) == 0.0);                          // eq 2.32
  // eq 2.36 in terms of Dupre: W132 = gamma13 + gamma23 - gamma12
  CHECK(work_of_adhesion_in_medium(0.03, 0.02, 0.01) == Approx(0.04).epsilon(1e-15));
}

TEST_CASE("van der Waals forms are minus the derivatives of their energies", "[forces][unit]") {
  const double A = 3e-20, R = 20e-9, D = 0.7e-9, h = 1e-6 * D;
  auto deriv = [h](auto f, double x) { return (f(x + h) - f(x - h)) / (2 * h); };
  CHECK(rel_close(sphere_flat_vdw_force(A, R, D), deriv([&](double x) { return sphere_flat_vdw_energy(A, R, x); }, D), 1e-8));
  CHECK(rel_close(flat_flat_vdw_pressure(A, D), deriv([&](double x) { return flat_flat_vdw_energy_per_area(A, x); }, D), 1e-8));
  const double C = 1e-77, rho = 3e28;
  CHECK(rel_close(molecule_surface_force(C, rho, D), deriv([&](double x) { return molecule_surface_energy(C, rho, x); }, D), 1e-8));
  // Two equal spheres: half the sphere-flat force (text after eq 2.23).
  CHECK(rel_close(sphere_sphere_vdw_force(A, R, R, D), 0.5 * sphere_flat_vdw_force(A, R, D), 4 * test::kEps));
}

TEST_CASE("Parsegian rod-plane force is the Derjaguin integral of the flat-flat pressure", "[forces][numeric]") {
  // Per unit length, cylinder of radius R at gap z0: F/L = int P(z0 + x^2/(2R)) dx over x in R,
  // P = A/(6 pi z^3). Closed form: A sqrt(2R)/(16 z0^2.5) = A sqrt(d)/(16 z0^2.5). Midpoint rule
  // in u = atan(x / sqrt(2 R z0)) (the integrand becomes cos^4 u).
  const double A = 1e-19, R = 13.5e-9, z0 = 0.2e-9, L = 590e-9;
  const double s = std::sqrt(2 * R * z0);
  const int n = 20000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = -kPi / 2 + (i + 0.5) * kPi / n;
    const double x = s * std::tan(u);
    const double z = z0 + x * x / (2 * R);
    sum += A / (6 * kPi * z * z * z) * s / (std::cos(u) * std::cos(u));
  }
  const double per_length = sum * kPi / n;
  CHECK(rel_close(rod_plane_vdw_force(A, L, 2 * R, z0), per_length * L, 1e-10));
}

TEST_CASE("JKR sphere: round trip, Hertz limit, a0 and separation radius (eqs 2.50-2.58)", "[forces][unit]") {
  const double R = 10e-9, E = 50e9, W = 0.1;
  const double a0 = jkr_zero_load_radius(R, E, W);
  CHECK(rel_close(jkr_contact_radius(R, E, W, 0.0), a0, 8 * test::kEps));
  for (double F : {-1e-9, 0.0, 1e-9, 1e-7}) {
    const double a = jkr_contact_radius(R, E, W, F);
    CHECK(std::abs(jkr_load_for_radius(R, E, W, a) - F) <= 1e-12 * (std::abs(F) + jkr_pull_off_force(R, W)));
  }
  // At the pull-off load the radius is a0 / 4^(1/3) = 0.63 a0 (eq 2.53).
  CHECK(rel_close(jkr_contact_radius(R, E, W, -jkr_pull_off_force(R, W)), jkr_separation_radius(R, E, W), 1e-12));
  CHECK(jkr_separation_radius(R, E, W) / a0 == Approx(0.63).margin(0.005));
  // W = 0: Hertz (eq 2.56-2.58).
  CHECK(rel_close(jkr_contact_radius(R, E, 0.0, 2e-9), hertz_contact_radius(R, E, 2e-9), 8 * test::kEps));
  CHECK(rel_close(jkr_central_displacement(R, E, 0.0, hertz_contact_radius(R, E, 2e-9)), hertz_displacement(R, E, 2e-9), 8 * test::kEps));
  // Hertz centre pressure is 1.5 times the mean (text after eq 2.59).
  const double a = hertz_contact_radius(R, E, 2e-9);
  CHECK(rel_close(hertz_pressure(R, E, 2e-9, 0.0), 1.5 * 2e-9 / (kPi * a * a), 8 * test::kEps));
  // JKR pressure integrates to the load: int_0^a P 2 pi r dr (x = sin t substitution).
  const double F = 3e-9, aj = jkr_contact_radius(R, E, W, F);
  const int n = 4000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) * (kPi / 2) / n, x = std::sin(t);
    sum += jkr_pressure(R, E, W, aj, x) * 2 * kPi * aj * aj * x * std::cos(t);
  }
  CHECK(rel_close(sum * (kPi / 2) / n, F, 1e-6));
  CHECK_THROWS_AS(jkr_contact_radius(R, E, W, -2 * jkr_pull_off_force(R, W)), InputError);
}

TEST_CASE("JKR line contact: round trip, Hertz limit, thesis' form of ref [72]", "[forces][unit]") {
  const double R = 13.5e-9, E = 19e9, W = 0.25, L = 590e-9;
  for (double p : {0.0, 0.1, 4.3, 100.0}) {
    const double b = jkr_line_half_width(R, E, W, p);
    CHECK(std::abs(jkr_line_load_per_length(R, E, W, b) - p) <= 1e-12 * (p + 1.0));
    // The thesis writes W(b) with the total load P = 2 l p and K = 4E*/3.
    CHECK(rel_close(jkr_line_thesis_work_of_adhesion(R, E, b, L / 2, p * L), W, 1e-10));
  }
  CHECK(rel_close(jkr_line_half_width(R, E, 0.0, 4.3), hertz_line_half_width(R, E, 4.3), 1e-14));
  CHECK_THROWS_AS(jkr_line_half_width(R, E, W, -1e3), InputError);
}

TEST_CASE("Layered surfaces: limits 2.40-2.41 and the general form 2.38", "[forces][unit]") {
  // Combining relations A_ijk = (s_i - s_j)(s_k - s_j) with s = sqrt(A).
  const double s1 = std::sqrt(2e-19), s2 = std::sqrt(0.3e-19), s3 = std::sqrt(0.5e-19);
  auto Aijk = [](double si, double sj, double sk) { return (si - sj) * (sk - sj); };
  const double A232 = Aijk(s2, s3, s2), A123 = Aijk(s1, s2, s3), A121 = Aijk(s1, s2, s1), A131 = Aijk(s1, s3, s1);
  const double T = 1e-9;
  const double small = 1e-13, large = 1e-5;
  CHECK(rel_close(layered_vdw_pressure_symmetric(A232, A123, A121, T, small), flat_flat_vdw_pressure(A232, small), 1e-3));
  CHECK(rel_close(layered_vdw_pressure_symmetric(A232, A123, A121, T, large), flat_flat_vdw_pressure(A131, large), 1e-3));
  // General form with 1 = 1', 2 = 2', T = T' reduces to the symmetric one when
  // sqrt(A121 A323) = A123 (true here: (s1-s2)(s3-s2) > 0, the layer is the softest).
  const double A323 = Aijk(s3, s2, s3);
  REQUIRE(A123 > 0);
  for (double D : {0.3e-9, 2e-9, 20e-9})
    CHECK(rel_close(layered_vdw_pressure(A232, A121, A323, A121, A323, T, T, D),
                    layered_vdw_pressure_symmetric(A232, A123, A121, T, D), 1e-12));
}

TEST_CASE("Metallic adhesion (eq 2.37): minimum -2 gamma at D0 (erratum: sign of the bracket)",
          "[forces][unit][errata]") {
  const double gamma = 1.1, D0 = 0.2e-9, lam = 0.05e-9, h = 1e-6 * lam;
  CHECK(metallic_adhesion_energy_per_area(gamma, D0, D0, lam) == -2 * gamma);
  // Our form: zero slope at D0 (one-sided derivative, since D >= D0).
  const double slope = (metallic_adhesion_energy_per_area(gamma, D0 + h, D0, lam) + 2 * gamma) / h;
  CHECK(std::abs(slope) < 1e-5 * 2 * gamma / lam);
  CHECK(metallic_adhesion_pressure(gamma, D0, D0, lam) == 0.0);
  // Maximum attraction 2 gamma/(e lambda) at D = D0 + lambda.
  CHECK(rel_close(metallic_adhesion_pressure(gamma, D0 + lam, D0, lam), 2 * gamma / (std::exp(1.0) * lam), 4 * test::kEps));
  // The printed form -2 gamma [1 - x] e^-x has slope 4 gamma/lambda at D0: no minimum there.
  auto printed = [&](double D) { const double x = (D - D0) / lam; return -2 * gamma * (1 - x) * std::exp(-x); };
  CHECK(rel_close((printed(D0 + h) - printed(D0)) / h, 4 * gamma / lam, 1e-5));
}

TEST_CASE("Kelvin radius of water: 0.54 nm / ln(RH) at 20 C (eq 2.60)", "[forces][unit]") {
  // Water's 20 C constants from the material table (gamma 0.07274 N/m, V = 18.048 cm^3/mol):
  // 0.5386 nm, the thesis' 0.54 nm (docs/errata.md C2; more in tests/test_forces_constants.cpp).
  const auto w = *find_liquid("water");
  const double rk = kelvin_radius(w.surface_tension, w.molar_volume, 293.15, std::exp(-1.0));
  CHECK(rk < 0.0);
  CHECK(std::round(-rk * 1e11) == 54.0);
  CHECK(rel_close(rk, -w.surface_tension * w.molar_volume / (kGasConstant * 293.15), 4 * test::kEps));
  CHECK(kelvin_radius(0.072, 18.07e-6, 293.15, 0.0) == 0.0);
  // Laplace (2.63): r2 >> r1 gives gamma/r1.
  CHECK(laplace_pressure(0.072, 1e-9, std::numeric_limits<double>::infinity()) == 0.072 / 1e-9);
}

TEST_CASE("Capillary cylinder and plate extensions vanish without a meniscus", "[forces][unit]") {
  CHECK(capillary_force_cylinder(13.5e-9, 590e-9, 0.072, 0.0, 0.1e-9, 0.2e-9) == 0.0);  // d = 0.2 nm <= D
  const double r1 = 1e-9, R = 13.5e-9, L = 1e-6;
  CHECK(rel_close(capillary_force_cylinder(R, L, 0.072, 0.0, r1, 0.0), 4 * L * 0.072 * std::sqrt(R / r1), 8 * test::kEps));
  CHECK(capillary_force_plate(1e-14, 0.072, 0.0, 0.05e-9, 0.2e-9) == 0.0);
}

TEST_CASE("Hamaker combining relation", "[forces][unit]") {
  CHECK(rel_close(hamaker_combined(4e-20, 9e-20), 6e-20, 4 * test::kEps));
  CHECK(hamaker_combined(4e-20, 4e-20, 4e-20) == 0.0);
  CHECK(hamaker_combined(9e-20, 1e-20, 4e-20) < 0.0);  // repulsion across a medium in between
}

TEST_CASE("Table 3.1: corrected values to the printed digits; old values where rounding allows",
          "[forces][table3_1][regression]") {
  const auto& t = thesis_table_3_1();
  REQUIRE(t.size() == 18);
  for (const auto& row : t) {
    INFO(row.material);
    const auto c = check_table_3_1_row(row);
    if (row.material == "n-Octane") {
      // Printed 23.3313, computed 23.3136 with either factor: a slip in the printed digits.
      CHECK_FALSE(c.corrected_exact);
      CHECK_FALSE(c.corrected_unrounded);
      CHECK(to_printed_digits(c.gamma_corrected, 1e-3, 23.3136, 4));
    } else if (row.material == "Polystyrene" || row.material == "Polyvinyl chloride" || row.material == "Glycol" ||
               row.material == "Formamide") {
      // These four were computed with the unrounded factor 24 pi (0.16 nm)^2.
      CHECK_FALSE(c.corrected_exact);
      CHECK(c.corrected_unrounded);
    } else {
      CHECK(c.corrected_exact);
    }
    if (row.material == "Glycol") {
      CHECK_FALSE(c.old_within_A_rounding);  // 27.28 computed, 28 printed
    } else if (row.material == "Polystyrene") {
      CHECK_FALSE(c.old_exact);
      CHECK(c.old_within_A_rounding);  // 32.15 computed, 32.1 printed: A = 6.58e-20 gives it
    } else {
      CHECK(c.old_exact);
    }
  }
  // The docs/models.md example: water 18.0 (old) and 19.1690 (corrected).
  CHECK(to_printed_digits(surface_energy_from_hamaker(3.7e-20), 1e-3, 18.0, 0));
  CHECK(to_printed_digits(surface_energy_corrected(3.7e-20), 1e-3, 19.1690, 4));
  // eq 3.8: 24 pi (0.4 nm / 2.5)^2 rounds to the printed 1.9302e-18.
  CHECK(std::round(24 * kPi * std::pow(0.4e-9 / 2.5, 2) / 1e-22) == 19302.0);
}

TEST_CASE("Bad input is rejected with the field, the value and the allowed range", "[forces][validation][unit]") {
  CHECK_THROWS_AS(sphere_flat_vdw_force(-1e-19, 1e-8, 1e-9), InputError);
  CHECK_THROWS_WITH(sphere_flat_vdw_force(-1e-19, 1e-8, 1e-9), Catch::Contains("Hamaker constant A = -") && Catch::Contains("must be >= 0 (J)"));
  CHECK_THROWS_WITH(sphere_flat_vdw_force(1e-19, 1e-8, 0.0), Catch::Contains("separation D = 0: must be > 0"));
  CHECK_THROWS_AS(sphere_flat_vdw_force(1e-19, 1e-8, -1e-9), InputError);
  CHECK_THROWS_AS(flat_flat_vdw_pressure(1e-19, 0.0), InputError);
  CHECK_THROWS_AS(rod_plane_vdw_force(1e-19, 1e-6, 2e-8, -0.2e-9), InputError);
  CHECK_THROWS_AS(surface_energy_from_hamaker(-1e-20), InputError);
  CHECK_THROWS_WITH(kelvin_radius(0.072, 18e-6, 293.0, 1.5), Catch::Contains("relative humidity = 1.5: must be in [0, 1]"));
  CHECK_THROWS_AS(kelvin_radius(0.072, 18e-6, 293.0, -0.1), InputError);
  CHECK_THROWS_AS(hertz_contact_radius(1e-8, 1e11, -1e-9), InputError);
  CHECK_THROWS_AS(capillary_force_max(1e-8, 0.072, 2.0), InputError);  // theta > pi/2
  CHECK_THROWS_AS(sphere_flat_vdw_force(1e-19, std::numeric_limits<double>::quiet_NaN(), 1e-9), InputError);
  CHECK_THROWS_AS(metallic_adhesion_pressure(1.0, 0.1e-9, 0.2e-9, 0.05e-9), InputError);  // D < D0
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
