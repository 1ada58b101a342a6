// One material, one set of constants (issue 22 item 3): the chapter 2-3 and chapter 4-5 code
// paths read the same graphite; the thesis' Kelvin radius regenerated at the 20 C it states;
// the JKR contact width and the nanobar's F_vdw against the printed values (docs/errata.md,
// "One material, one set of constants").
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "nanopush/models/environment.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/models/materials.hpp"
#include "nanopush/models/surface_forces.hpp"
#include "nanopush/numerics/error.hpp"
#include "support/support.hpp"

using namespace nanopush;
using namespace nanopush::forces;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
using nanopush::test::close_to_ref;
/// Round v / unit to `digits` decimals.
double rounded(double v, double unit, int digits) {
  const double s = std::pow(10.0, digits);
  return std::round(v / unit * s) / s;
}
Body mwcnt(const Material& m) {
  Body b;
  b.shape = Shape::rod;
  b.radius = 13.5e-9;
  b.length = 590e-9;
  b.material = m;
  return b;
}
/// Bisection on E* (log scale) for the JKR line half-width b(E*) = target (b falls with E*).
double modulus_for_half_width(double target, double R, double W, double p) {
  double lo = 1e9, hi = 1e14;
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    (jkr_line_half_width(R, mid, W, p) > target ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}
}  // namespace

TEST_CASE("One material, one set of constants: chapters 2-3 and 4-5 read the same graphite",
          "[forces][constants][unit]") {
  const auto g = find_material("graphite");
  REQUIRE(g);
  const icor::Rod rod = icor::nanorod();
  // Chapter 4-5 code path (iCOR) against the material table (chapters 2-3, scenes).
  CHECK(rod.hamaker == g->hamaker);
  CHECK(rod.density == g->density);
  CHECK(rod.z0 == Environment{}.gap);
  CHECK(g->hamaker == kGraphiteHamaker);
  CHECK(g->density == 2267.0);  // the thesis' one printed graphite constant
  CHECK(g->surface_energy == g->hamaker / kThesisHamakerPerGamma);  // eq 3.9, one gamma
  // The same F_vdw for the thesis' nanorod from both paths: the iCOR's Parsegian force and the
  // scene's normal-load assembly (chapter 3, graphite on graphite in vacuum).
  const LoadReport r = assemble_normal_load(Environment{}, mwcnt(*g));
  CHECK(close_to_ref(r.term("van_der_waals").value, rod.vdw_force(), 4 * test::kEps));
  CHECK(close_to_ref(r.hamaker, rod.hamaker, 4 * test::kEps));
  // Independent oracle: L A d^0.5 / (16 z0^2.5) with the printed inputs.
  CHECK(rounded(rod.vdw_force(), 1e-6, 6) == 5.034273);
  // Every named material: the table entry is what a scene naming it gets, and gamma follows eq
  // 3.9 from the same A unless the entry states its own (gold).
  for (const auto& m : solid_materials()) {
    const auto f = find_material(m.name);
    REQUIRE(f);
    CHECK(f->hamaker == m.hamaker);
    CHECK(f->surface_energy == m.surface_energy);
    if (m.name != "gold") CHECK(close_to_ref(m.surface_energy, m.hamaker / kThesisHamakerPerGamma, 2 * test::kEps));
  }
  // The environment's default condensate is the table's water.
  const auto w = find_liquid("water");
  REQUIRE(w);
  CHECK(Environment{}.liquid.surface_tension == w->surface_tension);
  CHECK(Environment{}.liquid.molar_volume == w->molar_volume);
}

TEST_CASE("Erratum: the two graphite Hamaker constants gave two F_vdw for the same nanotube",
          "[forces][constants][unit]") {
  // The consequence recorded in docs/errata.md: 2.38e-19 J (our former chapter 3 value) and
  // 4.7e-19 J (chapters 4-5) for the same MWCNT, z0 = 0.2 nm.
  CHECK(rounded(rod_plane_vdw_force(2.38e-19, 590e-9, 27e-9, 0.2e-9), 1e-6, 3) == 2.549);
  CHECK(rounded(rod_plane_vdw_force(4.7e-19, 590e-9, 27e-9, 0.2e-9), 1e-6, 3) == 5.034);
}

TEST_CASE("Kelvin radius regenerates the thesis' 0.54 nm at the 20 C it states (eq 2.60)",
          "[forces][constants][unit]") {
  // Oracle: IAPWS 2014 surface tension of ordinary water, tabulated 72.74 mN/m at 20 C,
  // 71.97 at 25 C, 58.91 at 100 C.
  CHECK(rounded(water_surface_tension(293.15), 1e-3, 2) == 72.74);
  CHECK(rounded(water_surface_tension(298.15), 1e-3, 2) == 71.97);
  CHECK(rounded(water_surface_tension(373.15), 1e-3, 2) == 58.91);
  CHECK_THROWS_AS(water_surface_tension(700.0), InputError);
  const auto w = find_liquid("water");
  REQUIRE(w);
  CHECK(w->reference_temperature == 293.15);
  CHECK(w->molar_volume == 18.01528e-3 / 998.21);
  // r_k = gamma V / (R T) at RH = 1/e; the thesis prints 0.54 nm.
  const double rk = std::abs(kelvin_radius(w->surface_tension, w->molar_volume, 293.15, std::exp(-1.0)));
  CHECK(close_to_ref(rk, w->surface_tension * w->molar_volume / (kGasConstant * 293.15), 4 * test::kEps));
  CHECK(rounded(rk, 1e-9, 2) == 0.54);
  CHECK(rounded(rk, 1e-9, 4) == 0.5386);
  // The former table value (0.072 N/m, the 25 C surface tension) does not round to 0.54.
  CHECK(rounded(std::abs(kelvin_radius(0.072, 18.07e-6, 293.15, std::exp(-1.0))), 1e-9, 3) == 0.534);
}

TEST_CASE("JKR contact width of the MWCNT: the thesis' 3 nm needs a modulus it does not print",
          "[forces][constants][unit]") {
  const auto g = *find_material("graphite");
  const double R = 13.5e-9, L = 590e-9;
  const LoadReport r = assemble_normal_load(Environment{}, mwcnt(g));
  REQUIRE(r.contact_model.find("JKR line") != std::string::npos);
  const double W = 2.0 * g.surface_energy;
  const double p = r.sliding_load / L;  // external load per length: m g + F_vdw
  const double Es = effective_modulus(g.youngs_modulus, g.poisson_ratio, g.youngs_modulus, g.poisson_ratio);
  // Oracle: b solves p = pi E* b^2/(4R) - sqrt(2 pi E* W b) (ref [72], per-length form).
  const double b = r.contact_half_width;
  CHECK(std::abs(kPi * Es * b * b / (4 * R) - std::sqrt(2 * kPi * Es * W * b) - p) < 1e-10 * p);
  // With the table's graphite (c-axis E = 36.5 GPa) the width is 9.55 nm, not about 3 nm.
  CHECK(rounded(2 * b, 1e-9, 2) == 9.55);
  // The width is set by E* at the thesis' stated geometry and load: 3 nm needs E* = 387 GPa,
  // i.e. E = 744 GPa for nu = 0.2 (an in-plane/axial modulus, the ~1 TPa quoted for MWCNTs).
  const double Es3 = modulus_for_half_width(1.5e-9, R, W, p);
  CHECK(rounded(Es3, 1e9, 0) == 387);
  CHECK(rounded(2 * (1 - 0.04) * Es3, 1e9, 0) == 744);
  // A scene that sets E = 1 TPa gets "about 3 nm" (2.69 nm).
  Material stiff = g;
  stiff.youngs_modulus = 1e12;
  const LoadReport r1 = assemble_normal_load(Environment{}, mwcnt(stiff));
  CHECK(rounded(2 * r1.contact_half_width, 1e-9, 2) == 2.69);
}

TEST_CASE("Nanobar F_vdw from the chapter 2-3 formulas against the printed 0.400252e-4 N",
          "[forces][constants][unit]") {
  const double A = find_material("graphite")->hamaker;
  const double L = 100e-9, Wd = 55e-9, T = 50e-9, z0 = Environment{}.gap;
  const double printed = 0.400252e-4;
  const double F = bar_plane_vdw_force(A, L, Wd, T, z0);
  // Oracle: eq 2.26 pressure A/(6 pi D^3) times the footprint; the finite thickness changes it
  // by (z0/(z0+T))^3 = 6.3e-8 relative.
  const double flat = A / (6 * kPi * z0 * z0 * z0) * L * Wd;
  CHECK(close_to_ref(F, flat * (1 - std::pow(z0 / (z0 + T), 3)), 8 * test::kEps));
  CHECK(rounded(F, 1e-5, 4) == 1.7142);
  CHECK(rounded(F / printed, 1.0, 3) == 0.428);
  // What the printed value would need: A = 1.097e-18 J at z0 = 0.2 nm (2.3 x any graphite
  // value), or z0 = 0.1508 nm with A = 4.7e-19 J.
  const double A_needed = printed / (F / A);
  CHECK(rounded(A_needed, 1e-18, 3) == 1.097);
  const double z_needed = std::cbrt(A * L * Wd / (6 * kPi * printed));
  CHECK(rounded(z_needed, 1e-9, 4) == 0.1508);
  // The former chapter 3 value does not reproduce it either: 8.681e-6 N.
  CHECK(rounded(bar_plane_vdw_force(2.38e-19, L, Wd, T, z0), 1e-6, 3) == 8.681);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
