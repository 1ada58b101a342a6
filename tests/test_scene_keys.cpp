// Scene keys set from code (Scene::set, SceneBuilder): the same validation as the file, and
// exactly the change an edited scene file makes (bit for bit). The key table against the
// parser, and docs/scenes.md against the table.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/scene_keys.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "support/support.hpp"

using namespace nanopush;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string preset(const std::string& name) {
  return std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/thesis/" + name + ".toml";
}

/// Replace the one line starting with `from` (after trimming) by `to`.
std::string edit_line(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find("\n" + from);
  REQUIRE(at != std::string::npos);
  const auto end = text.find('\n', at + 1);
  return text.substr(0, at + 1) + to + text.substr(end);
}

void require_same_scene(const Scene& a, const Scene& b) {
  CHECK(a.name == b.name);
  CHECK(a.mass == b.mass);
  CHECK(a.inertia == b.inertia);
  CHECK(a.geometry.a == b.geometry.a);
  CHECK(a.geometry.b == b.geometry.b);
  CHECK(a.push.force == b.push.force);
  CHECK(a.push.beta == b.push.beta);
  CHECK(a.push.pbx == b.push.pbx);
  CHECK(a.push.pby == b.push.pby);
  CHECK(a.initial == b.initial);
  CHECK(a.surface.kind == b.surface.kind);
  CHECK(a.surface.mu == b.surface.mu);
  CHECK(a.surface.law == b.surface.law);
  CHECK(a.normal_load() == b.normal_load());
  CHECK(a.solver.t_end == b.solver.t_end);
  CHECK(a.solver.samples == b.solver.samples);
  CHECK(a.solver.rtol == b.solver.rtol);
  CHECK(a.solver.method == b.solver.method);
  CHECK(a.solver.max_steps == b.solver.max_steps);
}

void require_same_rows(const Trajectory& a, const Trajectory& b) {
  REQUIRE(a.rows.size() == b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i) REQUIRE(a.rows[i] == b.rows[i]);
  CHECK(a.stats.nfcn == b.stats.nfcn);
}

std::string error_of(const std::function<void()>& f) { return nanopush::test::input_error_of(f, "(no error)"); }

}  // namespace

TEST_CASE("scene set: surface.mu and push.yn change exactly what an edited file changes, bit for bit",
          "[scene][keys][unit]") {
  const std::string path = preset("fig3_18");
  Scene set = load_scene(path);
  set.set({{"surface.mu", 0.1}, {"push.yn", 20e-9}});
  std::string text = read_text(path);
  text = edit_line(text, "mu = 0.06", "mu = 0.1");
  text = edit_line(text, "yn = 45e-9", "yn = 20e-9");
  const Scene edited = parse_scene(text, path);
  require_same_scene(set, edited);
  CHECK(set.surface.mu == 0.1);
  CHECK(set.push.pby == -20e-9);
  CHECK(set.source == std::filesystem::path(path));
  require_same_rows(run_scene(set), run_scene(edited));
}

TEST_CASE("scene set: integer and string keys, from text as the command line gives them", "[scene][keys][unit]") {
  Scene s = load_scene(preset("fig3_6a"));
  s.set({{"solver.samples", SceneValue::from_text("solver.samples", "11")},
         {"solver.method", SceneValue::from_text("solver.method", "modern")},
         {"initial.theta", SceneValue::from_text("initial.theta", "0.25")}});
  CHECK(s.solver.samples == 11);
  CHECK(s.solver.method == Method::modern);
  CHECK(s.initial[2] == 0.25);
  CHECK(s.output_times().size() == 11);
}

TEST_CASE("nearest_scene_key: a typo, a transposition, a bare name; nothing for a far key", "[scene][keys][unit]") {
  CHECK(nearest_scene_key("surface.muu") == "surface.mu");
  CHECK(nearest_scene_key("surfcae.mu") == "surface.mu");
  CHECK(nearest_scene_key("solver.sample") == "solver.samples");
  CHECK(nearest_scene_key("push.forc") == "push.force");
  CHECK(nearest_scene_key("samples") == "solver.samples");
  CHECK(nearest_scene_key("surface.mu") == "surface.mu");
  CHECK(nearest_scene_key("zzzz.qqqq").empty());
  CHECK(nearest_scene_key("").empty());
}

TEST_CASE("scene set: bad keys and values are refused with key, value and range; the scene is unchanged",
          "[scene][keys][errors][unit]") {
  Scene s = load_scene(preset("fig3_18"));
  const double mu0 = s.surface.mu;
  CHECK(error_of([&] { s.set("surface.muu", 0.1); }) ==
        "surface.muu = 0.1: unknown scene key (did you mean surface.mu? `nanopush scene-keys` lists them)");
  CHECK(error_of([&] { s.set("zzzz.qqqq", 0.1); }) ==
        "zzzz.qqqq = 0.1: unknown scene key (`nanopush scene-keys` lists them)");
  CHECK(error_of([&] { s.set("surface.mu", -1.0); }) == "surface.mu = -1: must be in [0, 10]");
  CHECK(error_of([&] { s.set("surface.mu", "high"); }).rfind("surface.mu = \"high\": must be a number", 0) == 0);
  CHECK(error_of([&] { s.set("surface.law", "stick"); }) ==
        "surface.law = \"stick\": must be one of: thesis, printed, coulomb");
  CHECK(error_of([&] { s.set("solver.samples", 10.5); }).rfind("solver.samples = 10.5: must be a whole number", 0) ==
        0);
  CHECK(error_of([&] { s.set("push.yn", 60e-9); }).find("push.yn = 6e-08: the push point must lie on the body") == 0);
  CHECK(error_of([&] { s.set("object.mass", 1e-18); }).find("give either object.mass or object.density") !=
        std::string::npos);
  CHECK(error_of([&] { (void)SceneValue::from_text("surface.mu", "0.1x"); }) ==
        "surface.mu = 0.1x: must be a number (1)");
  CHECK(s.surface.mu == mu0);

  // A key the scene's model does not use is an error, not silently ignored.
  Scene smooth = load_scene(preset("fig3_6a"));
  CHECK(error_of([&] { smooth.set("surface.mu", 0.1); }) ==
        "surface.mu = (present): only meaningful with surface.kind = \"rough\"");
  // ... but set together with the kind it needs, it is accepted.
  smooth.set({{"surface.kind", "rough"}, {"surface.mu", 0.1}});
  CHECK(smooth.rough());
  CHECK(smooth.surface.mu == 0.1);
}

TEST_CASE("scene builder: a scene from nothing equals the preset file, and runs the same", "[scene][keys][unit]") {
  SceneBuilder b;
  b.set("object.shape", "bar")
      .set("object.length", 100e-9)
      .set("object.width", 55e-9)
      .set("object.height", 50e-9)
      .set("object.density", 2267.0)
      .set("push.force", 5e-6)
      .set("push.direction", 0.0)
      .set("push.xn", 27.5e-9)
      .set("push.yn", 45e-9)
      .set("initial.theta", -0.5)
      .set("surface.kind", "smooth")
      .set("solver.t_end", 1.6e-9)
      .set("solver.samples", 401)
      .set("solver.rtol", 1e-12)
      .set("solver.method", "faithful");  // the thesis presets state it (the default is auto)
  const Scene built = b.build("fig3_6a");
  const Scene file = load_scene(preset("fig3_6a"));
  require_same_scene(built, file);
  require_same_rows(run_scene(built), run_scene(file));
  // An incomplete scene is refused at build() with the missing key named.
  SceneBuilder partial;
  partial.set("object.length", 100e-9);
  CHECK(error_of([&] { (void)partial.build(); }) == "object.width = (missing): required number");
}

TEST_CASE("scene key table: every documented key is known to the parser", "[scene][keys][unit]") {
  // A value of the wrong type for each documented key: the parser must complain about that
  // key's value, never call it unknown.
  const std::string rough = read_text(std::string(NANOPUSH_SOURCE_DIR) +
                                      "/drivers/scenes/examples/nanobar_humid_air.toml");
  const Scene base = parse_scene(rough, "humid");
  for (const auto& k : scene_keys()) {
    if (k.type == KeyType::table || k.type == KeyType::array) continue;
    INFO(k.key);
    Scene s = base;
    const std::string msg = error_of([&] {
      if (k.type == KeyType::string) s.set(std::string(k.key), SceneValue(1.5));
      else s.set(std::string(k.key), SceneValue("x"));
    });
    CHECK(msg.find("unknown") == std::string::npos);
    CHECK(msg.rfind(std::string(k.key), 0) == 0);
  }
}

TEST_CASE("scene key table: a file key outside the table is unknown", "[scene][keys][unit]") {
  std::string text = read_text(preset("fig3_6a"));
  text = edit_line(text, "rtol = 1e-12", "rtol = 1e-12\nrtoll = 1e-9");
  CHECK(error_of([&] { (void)parse_scene(text, "x"); }).rfind("solver.rtoll = (present): unknown key", 0) == 0);
  CHECK(error_of([&] { (void)parse_scene(text, "x"); }).find("did you mean solver.rtol? allowed here: ") !=
        std::string::npos);
}

TEST_CASE("docs/scenes.md holds the generated key table", "[scene][keys][docs][unit]") {
  const std::string doc = read_text(std::string(NANOPUSH_SOURCE_DIR) + "/docs/scenes.md");
  CHECK(doc.find(scene_keys_markdown()) != std::string::npos);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
