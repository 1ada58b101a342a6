// Every scene of the physical space ends in an answer or in a reason: seeded Latin hypercubes
// of tip pushes (docs/tip.md), of pushes on a smooth surface (every method, both engines) and
// of pushes in an environment (docs/forces.md, both laws). Where a run stops, its message
// says why and what to change. (The rough force pushes' hypercube is test_accuracy.cpp's.)
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "nanopush/engines/engines.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/lhs.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "support/support.hpp"

using namespace nanopush;

namespace NANOPUSH_UNITY_ID {

/// The physical ranges the rough hypercube draws from (scenes/lhs.hpp): the bar's size, the
/// push, mu, f_vdw and rtol are drawn from the same ranges here.
const RoughLhsRanges kSpace;

struct BarSize {
  double length, width, height;
};
/// The bar's size at a hypercube point's first three coordinates.
template <std::size_t D>
BarSize bar_size(const std::array<double, D>& u) {
  const double length = kSpace.length.at(u[0]);
  return {length, length * kSpace.aspect.at(u[1]), kSpace.height.at(u[2])};
}

/// n tip scenes: the example nanorod's scene with the bar, the tip, its path and the surface
/// drawn from a seeded hypercube: length 10 nm - 10 um, width/length 0.01 - 1, height
/// 1 nm - 1 um, tip radius 1 - 50 nm, a gap of 0.1 - 50 nm before contact, the path's offset
/// within 0.7 of the length and its direction within 1.2 rad of the normal, speed
/// 1e-7 - 10 m/s, travel 1 nm - 2 lengths, tip friction 0 (half of them) or 1e-3 - 1,
/// stiffness 0.1 - 100 N/m, mu 1e-3 - 2, f_vdw 1e-12 - 1e-3 N.
std::vector<Scene> tip_lhs_scenes(std::size_t n, std::uint64_t seed, const std::string& model) {
  const Scene base = load_scene(std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/examples/tip_push_nanorod.toml");
  const LhsRange radius{1e-9, 50e-9}, gap{1e-10, 50e-9}, offset{-0.7, 0.7, false}, direction{-1.2, 1.2, false},
      speed{1e-7, 10.0}, travel{1e-9 / 10e-6, 2.0}, tip_mu{1e-3, 1.0}, stiffness{0.1, 100.0};
  std::vector<Scene> out;
  for (const auto& u : latin_hypercube<13>(n, seed)) {
    const auto [L, W, H] = bar_size(u);
    const double R = radius.at(u[3]);
    Scene sc = base;
    sc.set({{"object.length", L},
            {"object.width", W},
            {"object.height", H},
            {"tip.radius", R},
            {"tip.start_x", -(W / 2 + R + gap.at(u[4]))},
            {"tip.start_y", offset.at(u[5]) * L},
            {"tip.direction", direction.at(u[6])},
            {"tip.speed", speed.at(u[7])},
            {"tip.travel", std::max(1e-9, travel.at(u[8]) * L)},
            {"tip.mu", u[9] < 0.5 ? 0.0 : tip_mu.at(2 * u[9] - 1)},
            {"surface.mu", kSpace.mu.at(u[11])},
            {"surface.f_vdw", kSpace.f_vdw.at(u[12])},
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

/// The thesis' smooth scene fig3_6a with the bar, the push and the run drawn from a seeded
/// hypercube: length 10 nm - 10 um, width/length 0.01 - 1, height 1 nm - 1 um, density
/// 1e3 - 2e4 kg/m^3, push 1e-12 - 1e-3 N anywhere on the body in any direction, t_end
/// 1 ps - 1 us, rtol 1e-13 - 1e-4; the engine and method cycle through F77 and the C++ methods.
std::vector<Scene> smooth_lhs_scenes(std::size_t n, std::uint64_t seed) {
  const Scene base = load_scene(std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/thesis/fig3_6a.toml");
  const LhsRange half{-0.5, 0.5, false}, direction{-3.0, 3.0, false}, t_end{1e-12, 1e-6}, rtol{1e-13, 1e-4};
  const char* methods[] = {"auto", "faithful", "modern", "dop853"};
  std::vector<Scene> out;
  std::size_t i = 0;
  for (const auto& u : latin_hypercube<10>(n, seed)) {
    const auto [L, W, H] = bar_size(u);
    Scene sc = base;
    sc.set({{"object.length", L},
            {"object.width", W},
            {"object.height", H},
            {"object.density", kSpace.density.at(u[3])},
            {"push.force", kSpace.force.at(u[4])},
            {"push.xn", half.at(u[5]) * W},
            {"push.yn", half.at(u[6]) * L},
            {"push.direction", direction.at(u[7])},
            {"solver.t_end", t_end.at(u[8])},
            {"solver.rtol", rtol.at(u[9])},
            {"solver.samples", 51}});
    if (i % 5 == 4)
      sc.set("solver.engine", "f77");
    else
      sc.set("solver.method", methods[i % 5]);
    out.push_back(std::move(sc));
    ++i;
  }
  return out;
}

TEST_CASE("Smooth scenes of the physical space: every method answers, or says how fast the bar turned",
          "[smooth][lhs][numeric]") {
  // The only stop: the step budget of a tiny bar pushed hard, which turns (or swings about the
  // push's line) thousands of times over t_end, tens of steps each.
  int answered = 0, turning = 0;
  for (const Scene& sc : smooth_lhs_scenes(200, 2026)) {
    INFO("length " << sc.length << ", F " << sc.push.force << ", t_end " << sc.solver.t_end << ", rtol "
                   << sc.solver.rtol << ", " << to_string(sc.solver.engine) << " " << to_string(sc.solver.method));
    try {
      const Trajectory tr = run_engine(sc, RunSettings{});  // the scene's engine: F77 too
      CHECK(tr.complete);
      ++answered;
    } catch (const SolverError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find("the object turns at up to") != std::string::npos);
      ++turning;
    }
  }
  CHECK(answered + turning == 200);
  CHECK(answered >= 180);
}

/// The example nanobar in an environment (graphite on graphite) with the bar, the push, the
/// medium (vacuum, humid air at any humidity, water or ethanol), the temperature, the gap and
/// the law drawn from a seeded hypercube.
std::vector<Scene> environment_lhs_scenes(std::size_t n, std::uint64_t seed) {
  // The example without its humidity (a key of humid air only), in vacuum until the medium is drawn.
  std::ifstream in(std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/examples/nanobar_humid_air.toml");
  std::string text, line;
  while (std::getline(in, line))
    if (line.rfind("humidity", 0) != 0) text += (line == "medium = \"humid_air\"" ? "medium = \"vacuum\"" : line) + "\n";
  const Scene base = parse_scene(text, "nanobar_humid_air.toml");
  const LhsRange half{-0.5, 0.5, false}, temperature{200, 400}, gap{1e-11, 1e-8};
  std::vector<Scene> out;
  for (const auto& u : latin_hypercube<12>(n, seed)) {
    const auto [L, W, H] = bar_size(u);
    Scene sc = base;
    sc.set({{"object.length", L},
            {"object.width", W},
            {"object.height", H},
            {"body.length", L},
            {"body.width", W},
            {"body.height", H},
            {"push.force", kSpace.force.at(u[3])},
            {"push.xn", half.at(u[4]) * W},
            {"push.yn", half.at(u[5]) * L},
            {"surface.mu", kSpace.mu.at(u[6])},
            {"environment.temperature", temperature.at(u[7])},
            {"environment.gap", gap.at(u[8])},
            {"solver.rtol", kSpace.rtol.at(u[9])},
            {"solver.samples", 51}});
    sc.set("surface.law", u[10] < 0.5 ? "coulomb" : "thesis");
    if (u[11] < 0.25) {
      sc.set({{"environment.medium", std::string("liquid")},
              {"environment.liquid", std::string(u[11] < 0.125 ? "ethanol" : "water")}});
    } else if (u[11] >= 0.5) {
      sc.set({{"environment.medium", std::string("humid_air")}, {"environment.humidity", (u[11] - 0.5) * 2}});
    }
    out.push_back(std::move(sc));
  }
  return out;
}

TEST_CASE("Pushes in an environment over the physical space: answers, or the thesis law's classified stop",
          "[forces][lhs][numeric]") {
  int answered = 0, classified = 0;
  for (const Scene& sc : environment_lhs_scenes(100, 2026)) {
    INFO("length " << sc.length << ", F " << sc.push.force << ", law " << to_string(sc.surface.law));
    RunSettings s;
    s.allow_partial = true;
    const Trajectory tr = run_engine(sc, s);
    if (is_answer(tr.outcome)) {
      ++answered;
    } else {
      INFO(tr.outcome_message);
      CHECK(tr.outcome == Outcome::no_static_friction);
      CHECK(sc.surface.law == Law::thesis);
      ++classified;
    }
  }
  CHECK(answered + classified == 100);
  CHECK(answered >= 50);
}

}  // namespace NANOPUSH_UNITY_ID
