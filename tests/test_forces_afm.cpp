// AFM probe relations (thesis eqs 2.1-2.11): spring-constant identities and motion modes.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "nanopush/models/afm_probe.hpp"
#include "nanopush/numerics/error.hpp"
#include "support/support.hpp"

using namespace nanopush;
using namespace nanopush::afm;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
using nanopush::test::rel_close;
Cantilever silicon() { return {169e9, 1.0 / 3.0, 125e-6, 30e-6, 4e-6, 15e-6}; }
}  // namespace

TEST_CASE("Cantilever spring constants: eqs 2.4-2.7 and their stated identities", "[afm][unit]") {
  const auto k = spring_constants(silicon());
  CHECK(rel_close(k.kz, 169e9 * 30e-6 * 64e-18 / (4 * std::pow(125e-6, 3)), 4 * test::kEps));
  CHECK(rel_close(k.kby, std::pow(30.0 / 4.0, 2) * k.kz, 8 * test::kEps));   // (w/t)^2 kz, eq 2.7
  CHECK(rel_close(k.kxz, 2.0 / 3.0 * (125.0 / 15.0) * k.kz, 8 * test::kEps));  // eq 2.5
  // eq 2.6: k_theta = G w t^3/(3 l H^2) ~ (Ls^2/2) kz, exact for nu = 1/3 (E = 2(1+nu)G).
  CHECK(rel_close(k.ktheta, k.Ls * k.Ls / 2 * k.kz, 16 * test::kEps));
  auto c = silicon();
  c.nu = 0.2;
  CHECK_FALSE(rel_close(spring_constants(c).ktheta, k.Ls * k.Ls / 2 * k.kz, 1e-3));
}

TEST_CASE("Deflection: eq 2.1 reduces to eq 2.2 without lateral force; numerators rotate the force",
          "[afm][unit][errata]") {
  const auto k = spring_constants(silicon());
  for (double alpha : {0.0, 0.1, 0.3}) {
    CHECK(rel_close(deflection_1d(k, 2e-9, 0.0, alpha), deflection_2d_normal(k, 2e-9, alpha), 4 * test::kEps));
    // The numerators are the components of (Fx, Fz) in the beam frame tilted by alpha:
    // their squares sum to Fx^2 + Fz^2 (the printed "Fz sin a + Fx sin a" does not).
    const double Fz = 2e-9, Fx = 5e-9, c = std::cos(alpha), s = std::sin(alpha);
    const double n1 = Fz * c - Fx * s, n2 = Fz * s + Fx * c;
    CHECK(rel_close(n1 * n1 + n2 * n2, Fx * Fx + Fz * Fz, 8 * test::kEps));
    CHECK(rel_close(deflection_1d(k, Fz, Fx, alpha), n1 / k.kz - n2 / k.kxz, 4 * test::kEps));
  }
  CHECK(rel_close(twist_2d(k, 1e-9, 2.0), 2.0 * 1e-9 / k.ktheta, 4 * test::kEps));
}

TEST_CASE("Nanosphere motion modes: stick, slide, roll, spin (text after eq 2.10, eq 2.11)", "[afm][unit]") {
  SphereContact c;
  c.R = 50e-9;
  c.a = 5e-9;
  c.a2 = 3e-9;
  c.tau_s = 1e8;      // tau_s A = 7.85 nN
  c.tau_s2 = 1e8;     // tau_s2 A2 = 2.83 nN
  c.tau_psi = 1.0;    // tau_psi A = 7.85e-17 N m
  c.tau_theta = 1.0;
  c.Fz = 1e-9;
  c.f1 = 5e-9;
  c.f2 = 1e-9;
  CHECK(sphere_modes(c).text() == "stick");
  c.f1 = 10e-9;
  CHECK(sphere_modes(c).text() == "slide");
  c.f2 = 3e-9;  // tip slips: (f1 - f2) R = 3.5e-16 >= 7.85e-17
  CHECK(sphere_modes(c).text() == "roll");
  c.x0 = 1e-7;  // Fz x0 = 1e-16 >= tau_theta A = 7.85e-17
  CHECK(sphere_modes(c).text() == "roll+spin");
  CHECK_THROWS_AS(sphere_modes(SphereContact{}), InputError);  // R = 0
  auto bad = silicon();
  bad.thickness = 0.0;
  CHECK_THROWS_AS(spring_constants(bad), InputError);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
