// Tip pushes over the physical space (docs/tip.md): a seeded Latin hypercube of tip scenes,
// every one ending in an answer or in a reason. The quasi-static model answers all of them;
// the dynamic model answers or says why it stopped (its step budget, or a slide too slow for
// double's steps), and points to the quasi-static model where inertia is negligible.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/lhs.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "support/support.hpp"

using namespace nanopush;

namespace NANOPUSH_UNITY_ID {

/// n tip scenes: the example nanorod's scene with the bar, the tip, its path and the surface
/// drawn from a seeded hypercube: length 10 nm - 10 um, width/length 0.01 - 1, height
/// 1 nm - 1 um, tip radius 1 - 50 nm, a gap of 0.1 - 50 nm before contact, the path's offset
/// within 0.7 of the length and its direction within 1.2 rad of the normal, speed
/// 1e-7 - 10 m/s, travel 1 nm - 2 lengths, tip friction 0 (half of them) or 1e-3 - 1,
/// stiffness 0.1 - 100 N/m, mu 1e-3 - 2, f_vdw 1e-12 - 1e-3 N.
std::vector<Scene> tip_lhs_scenes(std::size_t n, std::uint64_t seed, const std::string& model) {
  const Scene base = load_scene(std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/examples/tip_push_nanorod.toml");
  const LhsRange length{10e-9, 10e-6}, aspect{0.01, 1.0}, height{1e-9, 1e-6}, radius{1e-9, 50e-9}, gap{1e-10, 50e-9},
      offset{-0.7, 0.7, false}, direction{-1.2, 1.2, false}, speed{1e-7, 10.0}, travel{1e-9 / 10e-6, 2.0},
      tip_mu{1e-3, 1.0}, stiffness{0.1, 100.0}, mu{1e-3, 2.0}, f_vdw{1e-12, 1e-3};
  std::vector<Scene> out;
  for (const auto& u : latin_hypercube<13>(n, seed)) {
    const double L = length.at(u[0]), W = L * aspect.at(u[1]), R = radius.at(u[3]);
    Scene sc = base;
    sc.set({{"object.length", L},
            {"object.width", W},
            {"object.height", height.at(u[2])},
            {"tip.radius", R},
            {"tip.start_x", -(W / 2 + R + gap.at(u[4]))},
            {"tip.start_y", offset.at(u[5]) * L},
            {"tip.direction", direction.at(u[6])},
            {"tip.speed", speed.at(u[7])},
            {"tip.travel", std::max(1e-9, travel.at(u[8]) * L)},
            {"tip.mu", u[9] < 0.5 ? 0.0 : tip_mu.at(2 * u[9] - 1)},
            {"surface.mu", mu.at(u[11])},
            {"surface.f_vdw", f_vdw.at(u[12])},
            {"solver.samples", 51}});
    if (model != "quasi_static") sc.set("tip.stiffness", stiffness.at(u[10]));
    sc.set("tip.model", model);
    out.push_back(std::move(sc));
  }
  return out;
}

TEST_CASE("Tip scenes of the physical space: the quasi-static model answers every one", "[tip][lhs][numeric]") {
  int answered = 0;
  for (const Scene& sc : tip_lhs_scenes(60, 2026, "quasi_static")) {
    INFO(sc.name << ": length " << sc.length << ", tip at (" << sc.tip.start_x << ", " << sc.tip.start_y << ")");
    const Trajectory tr = run_scene(sc);
    CHECK(tr.complete);
    answered += tr.complete;
  }
  CHECK(answered == 60);
}

TEST_CASE("Tip scenes of the physical space: the dynamic model answers or says why, and auto answers",
          "[tip][lhs][numeric]") {
  // The reasons a dynamic run may stop: its step budget (solver.max_steps), or a slide that
  // starts too slowly for double's steps; where inertia is negligible both point to the
  // quasi-static model. Under auto the quasi-static model runs there, so the stops left are
  // budgets of pushes where inertia counts.
  for (const std::string model : {"dynamic", "auto"}) {
    int answered = 0, reasons = 0;
    for (const Scene& sc : tip_lhs_scenes(30, 7, model)) {
      INFO(model << ": length " << sc.length << ", speed " << sc.tip.speed << ", tip.mu " << sc.tip.mu);
      try {
        const Trajectory tr = run_scene(sc);
        CHECK(tr.complete);
        ++answered;
      } catch (const SolverError& e) {
        const std::string m = e.what();
        INFO(m);
        const bool budget = m.find("solver.max_steps = ") != std::string::npos;
        const bool slow_start = m.find("relaxes in m |V|/(mu N)") != std::string::npos;
        CHECK((budget || slow_start));
        if (model == "auto") CHECK(budget);
        if (slow_start) CHECK(m.find("tip.model = quasi_static or auto") != std::string::npos);
        ++reasons;
      }
    }
    CHECK(answered + reasons == 30);
    CHECK(answered >= (model == "auto" ? 27 : 15));
  }
}

}  // namespace NANOPUSH_UNITY_ID
