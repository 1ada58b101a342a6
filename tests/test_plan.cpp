// Push planning (planning/plan.hpp): a seeded task planned and verified by independent forward
// runs of the scene, the goal norm, and the clear ends of bad or unreachable tasks.
#include <catch2/catch.hpp>
#include <cmath>

#include "nanopush/numerics/error.hpp"
#include "nanopush/planning/check.hpp"
#include "nanopush/planning/plan.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "support/support.hpp"

using namespace nanopush;

namespace NANOPUSH_UNITY_ID {

const std::string kRodScene = test::kTipSceneText;

TEST_CASE("Planning: angle errors wrap, modulo a half turn for a symmetric bar", "[plan][unit]") {
  CHECK(plan::angle_error(3.0, -3.0, false) == Approx(6.0 - 2 * M_PI));
  CHECK(plan::angle_error(M_PI + 0.1, 0.0, true) == Approx(0.1));
  CHECK(plan::angle_error(0.5 * M_PI, 0.0, true) == Approx(0.5 * M_PI));  // (-pi/2, pi/2]
  CHECK(plan::angle_error(-0.5 * M_PI, 0.0, true) == Approx(0.5 * M_PI));
}

TEST_CASE("Planning: a seeded task is planned and each push replays to the planned pose", "[plan][numeric]") {
  const Scene sc = parse_scene(kRodScene, "rod.toml");
  plan::PlanOptions o;
  o.tolerance_distance = 2e-9;
  o.tolerance_angle = 0.02;
  const plan::Pose goal{40e-9, 25e-9, 0.4};
  const auto r = plan::plan_pushes(sc, goal, o);
  INFO(r.message);
  REQUIRE(r.found());
  CHECK(r.verified);
  REQUIRE(!r.pushes.empty());
  CHECK(static_cast<int>(r.pushes.size()) <= o.max_pushes);
  // Independent check: replay the plan push by push from the scene's own pose with run_scene,
  // each run a scene with the push's tip keys.
  plan::Pose at{0, 0, 0};
  for (const auto& p : r.pushes) {
    Scene s = sc;
    s.set({{"initial.x", at.x}, {"initial.y", at.y}, {"initial.theta", at.theta}, {"tip.start_x", p.start_x},
           {"tip.start_y", p.start_y}, {"tip.direction", p.direction}, {"tip.speed", p.speed}, {"tip.travel", p.travel}});
    const Trajectory tr = run_scene(s);
    const auto& last = tr.rows.back();
    at = {last[col::x], last[col::y], last[col::theta]};
    CHECK(std::hypot(at.x - p.end.x, at.y - p.end.y) < 0.1 * o.tolerance_distance);
  }
  CHECK(std::hypot(at.x - goal.x, at.y - goal.y) <= o.tolerance_distance);
  CHECK(std::fabs(plan::angle_error(at.theta, goal.theta, true)) <= o.tolerance_angle);
  CHECK(r.tip_travel > 0);
  CHECK(r.time == Approx(r.tip_travel / 1e-6));
}

/// Where `r`'s pushes, made open loop (the tip paths fixed in world axes) by run_scene from
/// `start` with the tip friction `tip_mu`, leave the bar (NaN: a push the model cannot follow
/// there).
plan::Pose replay(const Scene& sc, const plan::PlanResult& r, double tip_mu, plan::Pose start) {
  Scene world = sc;
  world.set("tip.mu", tip_mu);
  for (const auto& p : r.pushes) {
    try {
      const Trajectory tr = run_scene(plan::push_scene(world, start, p));
      start = {tr.rows.back()[col::x], tr.rows.back()[col::y], tr.rows.back()[col::theta]};
    } catch (const SolverError&) {
      return {std::nan(""), std::nan(""), std::nan("")};
    }
  }
  return start;
}

TEST_CASE("Planning: a robust plan reaches the goal across the tip friction range and start shifts", "[plan][numeric]") {
  const Scene sc = parse_scene(kRodScene, "rod.toml");  // tip.mu = 0
  plan::PlanOptions o;
  o.tolerance_distance = 2e-9;
  o.tolerance_angle = 0.02;
  const plan::Pose goal{40e-9, 25e-9, 0.4};
  plan::PlanOptions ro = o;
  ro.robust_tip_mu_lo = 0.0;
  ro.robust_tip_mu_hi = 0.3;
  ro.robust_start_x = ro.robust_start_y = 0.5e-9;
  ro.robust_start_theta = 0.004;
  const auto r = plan::plan_pushes(sc, goal, ro);
  INFO(r.message);
  REQUIRE(r.found());
  CHECK(r.verified);
  REQUIRE(r.worlds.size() == 8);  // the model's (tip.mu 0), tip.mu 0.3, six start shifts
  CHECK(r.worlds[1].tip_mu == 0.3);
  for (const auto& w : r.worlds) CHECK(w.reached);
  // Independent check: replayed by run_scene in worlds the planner did not see (tip friction
  // inside the range), the robust plan reaches the goal; the model's plan, chosen for tip.mu = 0
  // alone, misses it in some of them.
  const auto nominal = plan::plan_pushes(sc, goal, o);
  REQUIRE(nominal.found());
  CHECK(nominal.worlds.empty());
  int nominal_misses = 0;
  for (double mu : {0.05, 0.1, 0.15, 0.2, 0.25, 0.3}) {
    INFO("tip.mu = " << mu);
    const plan::Pose at = replay(sc, r, mu, r.start);
    CHECK(std::hypot(at.x - goal.x, at.y - goal.y) <= o.tolerance_distance);
    CHECK(std::fabs(plan::angle_error(at.theta, goal.theta, true)) <= o.tolerance_angle);
    const plan::Pose n = replay(sc, nominal, mu, nominal.start);
    nominal_misses += !(std::hypot(n.x - goal.x, n.y - goal.y) <= o.tolerance_distance &&
                        std::fabs(plan::angle_error(n.theta, goal.theta, true)) <= o.tolerance_angle);
  }
  CHECK(nominal_misses > 0);
  // A tip friction range on a force-push scene, or reversed, is bad input.
  plan::PlanOptions bad = o;
  bad.robust_tip_mu_lo = 0.3;
  bad.robust_tip_mu_hi = 0.1;
  CHECK_THROWS_AS(plan::plan_pushes(sc, goal, bad), InputError);
  // A negative end or a NaN shift is refused, not read as "no robust worlds" (a plan for the
  // model alone would come back as if robust).
  bad.robust_tip_mu_lo = -0.1;
  bad.robust_tip_mu_hi = 0.1;
  CHECK_THROWS_WITH(plan::plan_pushes(sc, goal, bad),
                    Catch::Matchers::StartsWith("--tip-mu-range = -0.1:0.1: must be LO:HI with 0 <= LO <= HI <= 10"));
  // The same rule for the worlds of a plan's check (Python's and C's tip_mu_range): one
  // function, check_tip_mu_range, for both.
  plan::CheckWorlds w;
  w.tip_mu_lo = -0.1;
  w.tip_mu_hi = 0.1;
  CHECK_THROWS_WITH(plan::check_worlds(sc, w),
                    Catch::Matchers::StartsWith("--tip-mu-range = -0.1:0.1: must be LO:HI with 0 <= LO <= HI <= 10"));
  bad = o;
  bad.robust_start_x = -1e-9;
  CHECK_THROWS_WITH(plan::plan_pushes(sc, goal, bad), Catch::Matchers::StartsWith("--noise = -1e-09: a robust plan's start shifts"));
  bad.robust_start_x = std::nan("");
  CHECK_THROWS_WITH(plan::plan_pushes(sc, goal, bad), Catch::Matchers::StartsWith("--noise = nan: a robust plan's start shifts"));
}

TEST_CASE("Planning: an unreachable goal ends in not_found with the best plan; bad input names the option",
          "[plan][unit]") {
  const Scene sc = parse_scene(kRodScene, "rod.toml");
  plan::PlanOptions o;
  o.max_pushes = 1;
  const auto r = plan::plan_pushes(sc, {300e-9, 200e-9, 1.0}, o);
  CHECK(r.status == plan::PlanStatus::not_found);
  CHECK(r.pushes.size() == 1);
  CHECK(r.message.find("1 pushes") != std::string::npos);
  o.tolerance_distance = 1e-18;
  CHECK_THROWS_WITH(plan::plan_pushes(sc, {1e-8, 0, 0}, o), Catch::Contains("--tolerance"));
  CHECK_THROWS_WITH(plan::plan_pushes(sc, {1e-8, 0, 1e308}, plan::PlanOptions{}),
                    Catch::Contains("THETA must be within [-1e6, 1e6] rad"));
  o.tolerance_distance = std::nan("");  // not "below what the model resolves": not a number
  CHECK_THROWS_WITH(plan::plan_pushes(sc, {1e-8, 0, 0}, o), Catch::StartsWith("--tolerance = nan: must be a finite number"));
  o = {};
  o.max_pushes = 0;
  CHECK_THROWS_WITH(plan::plan_pushes(sc, {1e-8, 0, 0}, o), Catch::Contains("--max-pushes"));
  CHECK_THROWS_WITH(plan::parse_objective("speed"), Catch::Contains("--objective"));
  // A goal beyond kGoalReach bar lengths is refused naming --goal, not the push it would give
  // ("tip.travel / tip.speed = inf"); one within reach is a task.
  o = {};
  const double L = 2 * std::max(sc.geometry.a, sc.geometry.b);
  CHECK_THROWS_WITH(plan::plan_pushes(sc, {1e308, 0, 0}, o),
                    Catch::StartsWith("--goal = 1e+308,0,0: must be within 1e6 bar lengths of the bar's start"));
  CHECK_THROWS_WITH(plan::check_plan_task(sc, {0, -1.01 * plan::kGoalReach * L, 0}, o), Catch::StartsWith("--goal = 0,"));
  CHECK_NOTHROW(plan::check_plan_task(sc, {0, 0.99 * plan::kGoalReach * L, 0}, o));
}

}  // namespace NANOPUSH_UNITY_ID

namespace NANOPUSH_UNITY_ID {

TEST_CASE("Planning: the closed loop reaches the goal when the truth's tip friction differs and images are noisy",
          "[plan][numeric]") {
  const Scene model = parse_scene(kRodScene, "rod.toml");
  Scene truth = model;
  truth.set("tip.mu", 0.3);  // the model assumes a frictionless tip
  plan::PlanOptions o;
  o.tolerance_distance = 2e-9;
  o.tolerance_angle = 0.02;
  o.max_pushes = 15;
  const plan::Noise noise{0.3e-9, 0.3e-9, 0.003};
  const plan::Pose goal{40e-9, 25e-9, 0.4};
  const auto r = plan::closed_loop(model, truth, goal, o, noise, 7);
  INFO(r.message);
  REQUIRE(r.reached());
  CHECK(r.final_distance <= o.tolerance_distance);
  CHECK(r.final_angle <= o.tolerance_angle);
  CHECK(!r.steps.empty());
  // The same seed gives the same loop (portable noise).
  const auto again = plan::closed_loop(model, truth, goal, o, noise, 7);
  REQUIRE(again.steps.size() == r.steps.size());
  CHECK(again.steps.back().observed.x == r.steps.back().observed.x);
  CHECK_THROWS_WITH(plan::closed_loop(model, truth, goal, o, plan::Noise{-1, 0, 0}, 7), Catch::Contains("--noise"));
}

TEST_CASE("Planning: the tip friction is re-fitted from what the pushes did", "[plan][numeric]") {
  const Scene model = parse_scene(kRodScene, "rod.toml");  // a frictionless tip
  Scene truth = model;
  truth.set("tip.mu", 0.3);
  plan::PlanOptions o;
  o.tolerance_distance = 2e-9;
  o.tolerance_angle = 0.02;
  const auto r = plan::plan_pushes(model, {40e-9, 25e-9, 0.4}, o);
  REQUIRE(r.found());
  // Noiseless images of the truth making the model's pushes: the fit must find a tip friction
  // whose model predicts each image from the one before (the truth's own 0.3 does, exactly).
  std::vector<plan::SeenPush> seen;
  plan::Pose at = r.start;
  for (const auto& p : r.pushes) {
    const Trajectory tr = run_scene(plan::push_scene(truth, at, p));
    const plan::Pose after{tr.rows.back()[col::x], tr.rows.back()[col::y], tr.rows.back()[col::theta]};
    seen.push_back({at, after, p});
    at = after;
  }
  const double mu = plan::fit_tip_mu(model, seen, {}, o, 0.0, 1.0);
  Scene fitted = model;
  fitted.set("tip.mu", mu);
  for (const auto& s : seen) {
    const Trajectory tr = run_scene(plan::push_scene(fitted, s.before, s.push));
    CHECK(std::hypot(tr.rows.back()[col::x] - s.after.x, tr.rows.back()[col::y] - s.after.y) <=
          1e-3 * o.tolerance_distance);
    CHECK(std::fabs(tr.rows.back()[col::theta] - s.after.theta) <= 1e-3 * o.tolerance_angle);
  }
  // The frictionless model does not predict them (the pushes slide the tip differently).
  double worst = 0;
  for (const auto& s : seen) {
    const Trajectory tr = run_scene(plan::push_scene(model, s.before, s.push));
    worst = std::max(worst, std::fabs(tr.rows.back()[col::theta] - s.after.theta));
  }
  CHECK(worst > 1e-2 * o.tolerance_angle);
  // Nothing seen, or not a tip scene: the current value stays.
  CHECK(plan::fit_tip_mu(model, {}, {}, o, 0.25, 1.0) == 0.25);
  // In the closed loop the model learns the truth's tip friction.
  o.max_pushes = 15;
  const auto loop = plan::closed_loop(model, truth, {40e-9, 25e-9, 0.4}, o, {0.3e-9, 0.3e-9, 0.003}, 7);
  INFO(loop.message);
  REQUIRE(loop.reached());
  REQUIRE(loop.tip_mu >= 0);
  CHECK(loop.steps.front().tip_mu == 0.0);  // the first push is planned with the model's own
  const auto kept = plan::closed_loop(model, truth, {40e-9, 25e-9, 0.4}, o, {0.3e-9, 0.3e-9, 0.003}, 7,
                                      plan::Refit{false, 1.0, 6});
  CHECK(kept.tip_mu == 0.0);
}

TEST_CASE("Planning: a push the model cannot follow on the true bar is not made, and the loop goes on",
          "[plan][numeric]") {
  // bench-plan's closed-loop task 36 (seed 20121): the nanorod, whose loop once ended in the
  // quasi-static solver's failure at a corner contact, thrown out of closed_loop.
  const Scene model = parse_scene(
      "[object]\nlength = 590e-9\nwidth = 27e-9\nheight = 27e-9\ndensity = 2267.0\n[push]\nmode = \"tip\"\n[tip]\n"
      "start_x = -1e-6\nstart_y = 0.0\ntravel = 1e-9\nradius = 10e-9\nspeed = 1e-6\n[surface]\nkind = \"rough\"\n"
      "mu = 0.1\nf_vdw = 1e-8\n[solver]\nsamples = 2\n",
      "nanorod");
  Scene truth = model;
  truth.set("surface.mu", 0.10713957744135703);
  plan::PlanOptions o;
  o.tolerance_distance = 3e-9;
  o.tolerance_angle = 0.03;
  o.max_pushes = 20;
  const plan::Pose goal{8.522163350442059e-07, 8.945098803854814e-07, 0.7341822300212641};
  plan::ClosedLoopResult r;
  REQUIRE_NOTHROW(r = plan::closed_loop(model, truth, goal, o, plan::Noise{1e-9, 1e-9, 0.01}, 20121 + 35));
  INFO(r.message);
  CHECK(r.unsimulated >= 1);  // the push it could not follow was counted, not thrown
  CHECK(r.steps.size() <= 20);
}

}  // namespace NANOPUSH_UNITY_ID

namespace NANOPUSH_UNITY_ID {

TEST_CASE("Planning: --check gives the success probability over start-pose noise and mu", "[plan][numeric]") {
  const Scene sc = parse_scene(kRodScene, "rod.toml");
  plan::PlanOptions o;
  o.tolerance_distance = 2e-9;
  o.tolerance_angle = 0.02;
  const auto r = plan::plan_pushes(sc, {40e-9, 25e-9, 0.4}, o);
  REQUIRE(r.found());
  // No noise: every world is the plan's own, whatever mu (the quasi-static path ignores it).
  const auto exact = plan::check_plan(sc, r, o, {}, 5, 0.05, 0.5, 1);
  CHECK(exact.successes == 5);
  CHECK(exact.high == 1.0);
  // Start-pose noise far beyond the tolerance: open loop fails most worlds.
  const auto noisy = plan::check_plan(sc, r, o, {20e-9, 20e-9, 0.2}, 20, 0, 0, 2);
  CHECK(noisy.successes < 10);
  CHECK(noisy.low <= noisy.probability);
  CHECK(noisy.probability <= noisy.high);
  CHECK_THROWS_WITH(plan::check_plan(sc, r, o, {}, 5, 0.5, 0.1, 1), Catch::Contains("--mu-range"));
  CHECK_THROWS_WITH(plan::check_plan(sc, r, o, {}, 0, 0, 0, 1), Catch::Contains("--check"));
  // The trials run through the sweep engine, each from its own stream (seed, trial): the same
  // worlds and end poses, bit for bit, on one thread or two.
  const auto one = plan::check_plan(sc, r, o, {5e-9, 5e-9, 0.05}, 6, 0, 0, 7, 1);
  const auto two = plan::check_plan(sc, r, o, {5e-9, 5e-9, 0.05}, 6, 0, 0, 7, 2);
  CHECK(one.successes == two.successes);
  CHECK(one.final_distance == two.final_distance);
  CHECK(one.final_angle == two.final_angle);
}

TEST_CASE("Planning: the check's 95 % Wilson interval", "[plan][unit]") {
  // Closed forms: 0 of n -> [0, z^2 / (n + z^2)]; n of n -> [n / (n + z^2), 1].
  const double z2 = 1.959963984540054 * 1.959963984540054;
  plan::PlanCheck none;
  none.trials = 20;
  plan::wilson_interval(none);
  CHECK(none.probability == 0);
  CHECK(none.low == 0);
  CHECK(none.high == Approx(z2 / (20 + z2)).epsilon(1e-14));
  plan::PlanCheck all;
  all.trials = all.successes = 20;
  plan::wilson_interval(all);
  CHECK(all.low == Approx(20 / (20 + z2)).epsilon(1e-14));
  CHECK(all.high == 1.0);
}

}  // namespace NANOPUSH_UNITY_ID
