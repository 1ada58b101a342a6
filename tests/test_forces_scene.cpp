// Scenes: environment/body parsing (errors name the TOML field), assembly of only the
// models a scene needs (evaluation counters), and dropping of negligible terms.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "nanopush_toml.hpp"

#include "nanopush/scenes/environment_toml.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/models/surface_forces.hpp"
#include "support/support.hpp"

using namespace nanopush;
namespace nf = nanopush::forces;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
toml::table parse(std::string_view text) { return toml::parse(text); }
Environment env_of(std::string_view text) { return parse_environment(parse(text)); }
Body body_of(std::string_view text) { return parse_body(parse(text)); }
const char* kTube = R"(shape = "rod"
material = "graphite"
radius = 13.5e-9
length = 590e-9)";
std::string message_of(const std::function<void()>& f) { return nanopush::test::input_error_of(f, "(no error)"); }
}  // namespace

TEST_CASE("Environment and body tables parse; errors name the TOML field", "[forces][scene][validation][unit]") {
  const Environment e = env_of(R"(medium = "humid_air"
humidity = 0.4
temperature = 300.0)");
  CHECK(e.medium == Medium::humid_air);
  CHECK(e.humidity == 0.4);
  CHECK(e.liquid.name == "water");
  const Body b = body_of(kTube);
  CHECK(b.shape == Shape::rod);
  CHECK(b.mass() == Approx(2267.0 * nf::kPi * 13.5e-9 * 13.5e-9 * 590e-9).epsilon(1e-14));

  CHECK(message_of([] { env_of("medium = \"humid_air\"\nhumidity = 1.5"); }) ==
        "environment.humidity = 1.5: must be in [0, 1]");
  CHECK(message_of([] { env_of("medium = \"humid_air\"\nhumidity = -0.1"); }) ==
        "environment.humidity = -0.1: must be in [0, 1]");
  CHECK(message_of([] { env_of("medium = \"humid_air\""); }).rfind("environment.humidity = (missing)", 0) == 0);
  CHECK(message_of([] { env_of("medium = \"vacuum\"\nhumidity = 0.5"); }).find("only allowed with medium") !=
        std::string::npos);
  CHECK(message_of([] { env_of("medium = \"plasma\""); }) ==
        "environment.medium = \"plasma\": must be one of: vacuum, humid_air, liquid");
  CHECK(message_of([] { env_of("humidty = 0.5"); }).rfind("environment.humidty = 0.5: unknown key", 0) == 0);
  CHECK(message_of([] { env_of("gap = 0.0"); }) == "environment.gap = 0: must be > 0 (m)");
  CHECK(message_of([] { env_of("gap = \"small\""); }) == "environment.gap = \"small\": must be a number");
  CHECK(message_of([] { env_of("medium = \"liquid\""); }).rfind("environment.liquid = (missing)", 0) == 0);
  CHECK(message_of([] { env_of("medium = \"liquid\"\nliquid = \"mercury\""); }).rfind("environment.liquid = \"mercury\": unknown liquid", 0) == 0);
  CHECK(message_of([] { body_of("shape = \"rod\"\nmaterial = \"graphite\"\nradius = 1e-9\nlength = 1e-7\nhamaker = -1e-20"); }) ==
        "body.hamaker = -1e-20: must be >= 0 (J)");
  CHECK(message_of([] { body_of("shape = \"rod\"\nmaterial = \"graphite\"\nradius = -1e-9\nlength = 1e-7"); }) ==
        "body.radius = -1e-09: must be > 0 (m)");
  CHECK(message_of([] { body_of("shape = \"cone\""); }) == "body.shape = \"cone\": must be one of: bar, rod, tube, sphere");
  CHECK(message_of([] { body_of("material = \"graphite\""); }).rfind("body.shape = (missing)", 0) == 0);
  CHECK(message_of([] { body_of("shape = \"sphere\"\nradius = 1e-8\nmaterial = \"unobtainium\""); }).rfind("body.material = \"unobtainium\": unknown material", 0) == 0);
  CHECK(message_of([] { body_of("shape = \"sphere\"\nradius = 1e-8\nlength = 1e-8\nmaterial = \"gold\""); }).rfind("body.length = 1e-08: not used by shape", 0) == 0);
  CHECK(message_of([] { body_of("shape = \"sphere\"\nradius = 1e-8\ndensity = 1000.0"); }).rfind("body.hamaker = (missing)", 0) == 0);
  CHECK(message_of([] { body_of("shape = \"tube\"\nradius = 1e-8\ninner_radius = 2e-8\nlength = 1e-7\nmaterial = \"graphite\""); }).rfind("body.inner_radius = 2e-08: must be < radius", 0) == 0);
  // Explicit constants instead of a named material.
  const Body c = body_of("shape = \"sphere\"\nradius = 1e-8\ndensity = 1000.0\nhamaker = 1e-19\nyoungs_modulus = 1e11\npoisson_ratio = 0.3");
  CHECK(c.material.name == "custom");
  CHECK(std::isnan(c.material.surface_energy));
}

TEST_CASE("A scene without adhesion evaluates no adhesion model", "[forces][scene][unit]") {
  const Body b = body_of(kTube);
  for (const char* env_text : {"adhesion = false", "medium = \"humid_air\"\nhumidity = 0.7\nadhesion = false"}) {
    INFO(env_text);
    const Environment e = env_of(env_text);
    nf::model_counters().reset();
    const LoadReport r = assemble_normal_load(e, b);
    CHECK(nf::model_counters().adhesion_total() == 0);
    CHECK(nf::model_counters()[nf::Model::hertz] > 0);  // the contact model still ran
    for (const char* t : {"van_der_waals", "capillary", "contact_adhesion"}) {
      CHECK(r.term(t).status == TermStatus::not_needed);
      CHECK(std::isnan(r.term(t).value));
    }
    CHECK(r.term("gravity").status == TermStatus::evaluated);
    CHECK(r.normal_load == r.term("gravity").value);
    CHECK(r.contact_model == "Hertz line contact");
    // Hertz line half-width under the weight alone.
    const double Es = nf::effective_modulus(36.5e9, 0.2, 36.5e9, 0.2);
    CHECK(r.contact_half_width == Approx(std::sqrt(4 * (r.normal_load / b.length) * b.radius / (nf::kPi * Es))).epsilon(1e-14));
  }
}

TEST_CASE("Only the models a scene needs: vacuum runs no capillary model, humid air does", "[forces][scene][unit]") {
  const Body b = body_of(kTube);
  nf::model_counters().reset();
  const LoadReport vac = assemble_normal_load(env_of("medium = \"vacuum\""), b);
  CHECK(nf::model_counters()[nf::Model::capillary] == 0);
  CHECK(nf::model_counters()[nf::Model::kelvin] == 0);
  CHECK(nf::model_counters()[nf::Model::rod_plane_vdw] == 1);
  CHECK(nf::model_counters()[nf::Model::sphere_surface_vdw] == 0);
  CHECK(vac.term("capillary").status == TermStatus::not_needed);
  CHECK(vac.term("buoyancy").status == TermStatus::not_needed);
  CHECK(vac.term("contact_adhesion").status == TermStatus::evaluated);
  // Parsegian force of the thesis' rod (graphite A from the material table, z0 = 0.2 nm).
  CHECK(vac.term("van_der_waals").value == Approx(590e-9 * nf::kGraphiteHamaker * std::sqrt(27e-9) / (16 * std::pow(0.2e-9, 2.5))).epsilon(1e-14));
  // The JKR half-width satisfies the line relation under the external load.
  const double Es = nf::effective_modulus(36.5e9, 0.2, 36.5e9, 0.2);
  CHECK(nf::jkr_line_load_per_length(b.radius, Es, vac.work_of_adhesion, vac.contact_half_width) ==
        Approx(vac.sliding_load / b.length).epsilon(1e-10));

  nf::model_counters().reset();
  const LoadReport hum = assemble_normal_load(env_of("medium = \"humid_air\"\nhumidity = 0.5"), b);
  CHECK(nf::model_counters()[nf::Model::capillary] == 1);
  CHECK(nf::model_counters()[nf::Model::kelvin] == 1);
  CHECK(hum.term("capillary").status == TermStatus::evaluated);
  CHECK(hum.term("capillary").value > 0.0);
  CHECK(hum.normal_load > vac.normal_load);

  // humidity = 0: no meniscus model runs.
  nf::model_counters().reset();
  const LoadReport dry = assemble_normal_load(env_of("medium = \"humid_air\"\nhumidity = 0.0"), b);
  CHECK(nf::model_counters()[nf::Model::kelvin] == 0);
  CHECK(dry.term("capillary").status == TermStatus::not_needed);

  // Liquid: buoyancy, and water screens the van der Waals attraction (A132 < A12).
  LoadOptions keep;
  keep.drop_negligible = false;  // buoyancy (~4e-13 of N) would be dropped otherwise
  const LoadReport liq = assemble_normal_load(env_of("medium = \"liquid\"\nliquid = \"water\""), b, keep);
  CHECK(liq.term("buoyancy").status == TermStatus::evaluated);
  CHECK(liq.term("buoyancy").value == Approx(-nf::find_liquid("water")->density * b.volume() * 9.81).epsilon(1e-14));
  CHECK(liq.hamaker < vac.hamaker);
  CHECK(liq.hamaker == Approx(std::pow(std::sqrt(nf::kGraphiteHamaker) - std::sqrt(3.7e-20), 2)).epsilon(1e-14));
}

TEST_CASE("Shares add up to one and the sphere scene uses the sphere models", "[forces][scene][unit]") {
  const Body s = body_of("shape = \"sphere\"\nradius = 10e-9\nmaterial = \"silica\"");
  nf::model_counters().reset();
  const LoadReport r = assemble_normal_load(env_of("medium = \"humid_air\"\nhumidity = 0.5"), s);
  CHECK(nf::model_counters()[nf::Model::sphere_surface_vdw] == 1);
  CHECK(nf::model_counters()[nf::Model::jkr] >= 1);
  CHECK(nf::model_counters()[nf::Model::rod_plane_vdw] == 0);
  double share = 0.0;
  for (const auto& t : r.terms)
    if (t.status == TermStatus::evaluated) share += t.share;
  CHECK(share == Approx(1.0).epsilon(1e-14));
  // JKR: the adhesion term is the Hertz-equivalent load minus the external load.
  const double Es = nf::effective_modulus(73e9, 0.17, 73e9, 0.17);
  CHECK(4.0 / 3.0 * Es * std::pow(r.contact_half_width, 3) / 10e-9 == Approx(r.normal_load).epsilon(1e-12));
  CHECK(r.to_text().find("contact_adhesion") != std::string::npos);
}

TEST_CASE("Dropping a negligible term changes N and the trajectory by less than the tolerance",
          "[forces][scene][numeric]") {
  const Body b = body_of(kTube);
  const Environment e = env_of("medium = \"vacuum\"");
  LoadOptions keep;
  keep.drop_negligible = false;
  LoadOptions drop;  // rtol 1e-10, drop_fraction 0.1
  const LoadReport all = assemble_normal_load(e, b, keep);
  const LoadReport red = assemble_normal_load(e, b, drop);
  // Gravity is ~9e-13 of N here (docs/models.md: "gravity is ~1e-13 of F_vdw"): dropped.
  CHECK(all.term("gravity").status == TermStatus::evaluated);
  REQUIRE(red.term("gravity").status == TermStatus::dropped);
  CHECK(std::abs(red.term("gravity").value) < red.drop_threshold);
  CHECK(red.drop_threshold == Approx(drop.drop_fraction * drop.rtol * all.normal_load).epsilon(1e-12));
  const double relN = std::abs(all.normal_load - red.normal_load) / all.normal_load;
  CHECK(relN < drop.drop_fraction * drop.rtol);
  CHECK(relN > 0.0);
  // Trajectory of the sliding tube, eqs 3.19-3.21: x(t) = (F - mu N) t^2 / (2 m), push F = 2 mu N.
  const double mu = 0.1, t = 1e-9, m = b.mass();
  const double F = 2 * mu * all.sliding_load;
  const double x_all = (F - mu * all.sliding_load) * t * t / (2 * m);
  const double x_red = (F - mu * red.sliding_load) * t * t / (2 * m);
  CHECK(std::abs(x_all - x_red) / std::abs(x_all) < drop.rtol);
  // Gravity below the threshold but amplified by the JKR line contact (dN/dp ~ 1.21 here)
  // above it: kept, with the reason in the report.
  LoadOptions edge;
  // Threshold 10 % above gravity: the term is below it, its effect on N (x 1.2) above it.
  edge.drop_fraction = 1.1 * all.term("gravity").value / (edge.rtol * all.normal_load);
  const LoadReport kept = assemble_normal_load(e, b, edge);
  CHECK(std::abs(kept.term("gravity").value) < kept.drop_threshold);
  CHECK(kept.term("gravity").status == TermStatus::evaluated);
  CHECK(kept.term("gravity").note.find("amplifies") != std::string::npos);
  CHECK(kept.normal_load == all.normal_load);
  // A term above the threshold is kept: tighten drop_fraction so nothing is dropped.
  LoadOptions tight;
  tight.drop_fraction = 1e-4;
  CHECK(assemble_normal_load(e, b, tight).term("gravity").status == TermStatus::evaluated);
}

TEST_CASE("A bar evaluates no contact-adhesion model; a rigid sphere uses Derjaguin", "[forces][scene][unit]") {
  nf::model_counters().reset();
  const LoadReport bar = assemble_normal_load(env_of("medium = \"vacuum\""),
                                              body_of("shape = \"bar\"\nmaterial = \"graphite\"\nlength = 100e-9\nwidth = 55e-9\nheight = 50e-9"));
  CHECK(nf::model_counters()[nf::Model::surface_surface_vdw] == 1);
  CHECK(nf::model_counters()[nf::Model::dupre] == 0);
  CHECK(nf::model_counters()[nf::Model::surface_energy] == 0);
  CHECK(bar.term("contact_adhesion").status == TermStatus::not_needed);
  CHECK(bar.contact_half_width == 27.5e-9);
  // Rigid sphere (Young's modulus 0): Derjaguin 2 pi R W, W = 2 gamma.
  const Body s = body_of("shape = \"sphere\"\nradius = 10e-9\ndensity = 1000.0\nhamaker = 1e-19\nsurface_energy = 0.05");
  nf::model_counters().reset();
  const LoadReport r = assemble_normal_load(env_of("medium = \"vacuum\""), s);
  CHECK(nf::model_counters()[nf::Model::derjaguin] == 1);
  CHECK(nf::model_counters()[nf::Model::jkr] == 0);
  CHECK(r.term("contact_adhesion").value == Approx(2 * nf::kPi * 10e-9 * 0.1).epsilon(1e-15));
  CHECK(r.contact_half_width == 0.0);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
