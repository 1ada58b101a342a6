// Scene files: bad input is rejected with the field, the value and the allowed range.
#include <catch2/catch.hpp>

#include <string>

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"
#include "support/support.hpp"

using namespace nanopush;
using Catch::Matchers::Contains;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
const std::string kGood = nanopush::test::kBaseSceneText + "[solver]\nt_end = 1.6e-9\n";

std::string with(const std::string& from, const std::string& to) { return nanopush::test::replaced(kGood, from, to); }
}  // namespace

TEST_CASE("A minimal scene parses with defaults", "[scene][unit]") {
  const Scene sc = parse_scene(kGood, "good.toml");
  CHECK(sc.name == "good");
  CHECK(sc.model == "smooth");
  CHECK(sc.solver.samples == 401);
  CHECK(sc.solver.engine == nanopush::Engine::cxx);
  CHECK(sc.initial[kTheta] == 0.0);
}

TEST_CASE("Bad scenes are rejected with field, value and range", "[scene][unit]") {
  CHECK_THROWS_WITH(parse_scene(with("length = 100e-9", "length = -1"), "s"),
                    Contains("object.length = -1") && Contains("must be > 0") && Contains("(m)"));
  CHECK_THROWS_WITH(parse_scene(with("force = 5e-6", "force = 0"), "s"), Contains("push.force = 0"));
  CHECK_THROWS_WITH(parse_scene(with("length = 100e-9", "lenght = 100e-9"), "s"),
                    Contains("object.lenght") && Contains("unknown key"));
  CHECK_THROWS_WITH(parse_scene(with("yn = 45e-9", "yn = 80e-9"), "s"),
                    Contains("push.yn = 8") && Contains("on the body"));
  CHECK_THROWS_WITH(parse_scene(with("t_end = 1.6e-9", "t_end = 1.6e-9\nrtol = 2.0"), "s"),
                    Contains("solver.rtol = 2") && Contains("[1e-30, 0.1]"));
  CHECK_THROWS_WITH(parse_scene(with("t_end = 1.6e-9", "t_end = 1.6e-9\nengine = \"rust\""), "s"),
                    Contains("solver.engine = \"rust\"") && Contains("cxx, f77"));
  CHECK_THROWS_WITH(parse_scene(with("density = 2267.0", "density = \"heavy\""), "s"),
                    Contains("object.density") && Contains("must be a number"));
  CHECK_THROWS_WITH(parse_scene(with("density = 2267.0", ""), "s"), Contains("object.mass = (missing)"));
  CHECK_THROWS_WITH(parse_scene(with("[solver]", "[solver\n"), "s"), Contains("TOML syntax"));
  CHECK_THROWS_WITH(parse_scene(with("t_end = 1.6e-9", "t_end = 1.6e-9\nsamples = 1"), "s"),
                    Contains("solver.samples = 1"));
  CHECK_THROWS_WITH(parse_scene(with("[solver]", "[surface]\nkind = \"icy\"\n[solver]"), "s"),
                    Contains("surface.kind = \"icy\""));
  CHECK_THROWS_WITH(parse_scene(with("t_end = 1.6e-9", "t_end = nan"), "s"), Contains("solver.t_end = nan"));
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
