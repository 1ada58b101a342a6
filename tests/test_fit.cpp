// The trajectory fit (docs/fitting.md): bad data named by row and column, sensitivities
// against central differences of independent forward solves, synthetic fits (truth within 3
// standard errors) on smooth and rough scenes under both laws, the non-identifiable pair, the
// JSON summary.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include "nanopush_toml.hpp"

#include "nanopush/fitting/fit.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "support/support.hpp"

using namespace nanopush;
using namespace nanopush::fit;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
using nanopush::test::input_error_of;
using nanopush::test::preset;

/// A short version of a preset: span t_end, `samples` outputs.
Scene short_scene(const std::string& rel, double t_end, int samples) {
  Scene s = preset(rel);
  s.set({{"solver.t_end", t_end}, {"solver.samples", samples}});
  return s;
}

/// Central differences of forward solves by the C++ engine (an independent integrator:
/// Bulirsch-Stoer), at the scene's output times, with respect to key at relative step h.
std::vector<std::array<double, 3>> engine_difference(const Scene& s, const std::string& key, double h, double rtol,
                                                     const std::string& method, const std::string& law = "") {
  const double v = s.document->at_path(key).value<double>().value();
  const double dv = h * std::abs(v);
  auto run = [&](double x) {
    Scene c = s;
    c.set(key, x);
    RunSettings rs;
    rs.method = parse_optional_choice<Method>("method", method);
    rs.rtol = rtol;
    rs.law = parse_optional_choice<Law>("law", law);
    return run_scene(c, rs).rows;
  };
  const auto a = run(v + dv), b = run(v - dv);
  std::vector<std::array<double, 3>> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < 3; ++j) d[i][j] = (a[i][1 + j] - b[i][1 + j]) / (2 * dv);
  return d;
}

/// max_i |a - b| over max_i |b|, per component present in b.
double relative_difference(const std::vector<std::vector<std::array<double, 3>>>& jac, std::size_t k,
                           const std::vector<std::array<double, 3>>& ref) {
  double worst = 0;
  for (std::size_t j = 0; j < 3; ++j) {
    double scale = 0, err = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      scale = std::max(scale, std::abs(ref[i][j]));
      err = std::max(err, std::abs(jac[i][k][j] - ref[i][j]));
    }
    if (scale > 0) worst = std::max(worst, err / scale);
  }
  return worst;
}

const char* kGood = "t,x,sigma_x,theta\n0,0,1e-9,0\n1e-10,1e-9,1e-9,0.01\n2e-10,2e-9,1e-9,0.02\n";

}  // namespace

TEST_CASE("fit data: a good file reads, --sigma fills a column", "[fit][unit]") {
  const Observations o = parse_observations(kGood, "d.csv", {{"theta", 0.01}});
  REQUIRE(o.t.size() == 3);
  CHECK(o.has[0]);
  CHECK_FALSE(o.has[1]);
  CHECK(o.has[2]);
  CHECK(o.sigma[2][1] == 0.01);
  CHECK(o.value[0][2] == 2e-9);
  CHECK(o.count() == 6);
  // Round trip through observations_csv.
  const Observations back = parse_observations(observations_csv(o), "back.csv");
  CHECK(back.value[2] == o.value[2]);
  CHECK(back.sigma[0] == o.sigma[0]);
}

TEST_CASE("fit data: every bad-data case names its row and column", "[fit][unit]") {
  const SigmaOverrides th{{"theta", 0.01}};
  auto err = [&](const std::string& csv, const SigmaOverrides& s = {}) {
    return input_error_of([&] { (void)parse_observations(csv, "d.csv", s); });
  };
  // Unsorted and duplicate times.
  std::string m = err("t,x,sigma_x\n0,0,1\n2,0,1\n1,0,1\n");
  CHECK_THAT(m, Catch::Contains("d.csv row 3 (line 4), column t") && Catch::Contains("unsorted"));
  m = err("t,x,sigma_x\n0,0,1\n1,0,1\n1,0,1\n");
  CHECK_THAT(m, Catch::Contains("row 3 (line 4), column t") && Catch::Contains("duplicate"));
  // NaN, a word, an empty cell.
  m = err("t,x,sigma_x\n0,0,1\n1,nan,1\n");
  CHECK_THAT(m, Catch::Contains("row 2 (line 3), column x = nan") && Catch::Contains("finite"));
  m = err("t,x,sigma_x\n0,0,1\n1,abc,1\n");
  CHECK_THAT(m, Catch::Contains("row 2 (line 3), column x = abc") && Catch::Contains("not a number"));
  m = err("t,x,sigma_x\n0,,1\n");
  CHECK_THAT(m, Catch::Contains("row 1 (line 2), column x") && Catch::Contains("missing value"));
  // Missing columns: t, every pose column, a sigma.
  CHECK_THAT(err("x,sigma_x\n0,1\n"), Catch::Contains("needs a time column t"));
  CHECK_THAT(err("t\n0\n"), Catch::Contains("at least one of the columns x, y, theta"));
  m = err("t,x,theta,sigma_x\n0,0,0,1\n");
  CHECK_THAT(m, Catch::Contains("column theta") && Catch::Contains("sigma_theta or --sigma theta="));
  CHECK_THAT(err("t,x,sigma_x,z\n0,0,1,0\n"), Catch::Contains("column 4 = \"z\""));
  // sigma <= 0, from the file and from --sigma.
  m = err("t,x,sigma_x\n0,0,1\n1,0,0\n");
  CHECK_THAT(m, Catch::Contains("row 2 (line 3), column sigma_x = 0") && Catch::Contains("> 0"));
  m = err("t,x,sigma_x\n0,0,-1e-9\n");
  CHECK_THAT(m, Catch::Contains("row 1 (line 2), column sigma_x = -1e-09"));
  CHECK_THAT(err("t,x\n0,0\n", {{"x", -1.0}}), Catch::Contains("--sigma x = -1: must be > 0"));
  // A short row.
  CHECK_THAT(err("t,x,sigma_x\n0,0\n"), Catch::Contains("row 1 (line 2) = 2 cells: the header has 3"));
  // Against the scene: outside its time span, too few values for the free parameters.
  const Scene s = short_scene("thesis/fig3_20.toml", 1e-10, 11);
  const Observations late = parse_observations("t,x,sigma_x\n0,0,1e-9\n2e-10,0,1e-9\n", "late.csv");
  CHECK_THAT(input_error_of([&] { check_observations(late, s, 1); }),
             Catch::Contains("late.csv row 2, column t = 2e-10") && Catch::Contains("time span [0, 1e-10]"));
  const Observations one = parse_observations("t,x,sigma_x\n0,0,1e-9\n", "one.csv");
  CHECK_THAT(input_error_of([&] { check_observations(one, s, 1); }), Catch::Contains("too few for 1 free parameter"));
  (void)th;
}

TEST_CASE("fit sensitivities: smooth scene against central differences of BS solves", "[fit][numeric]") {
  const Scene s = short_scene("thesis/fig3_6a.toml", 0.4e-9, 41);
  const std::vector<std::string> free = {"push.force", "initial.theta"};
  const std::vector<double> p = {s.push.force, s.initial[kTheta]};
  const ModelPoses m = model_poses(s, free, p, s.output_times(), std::nullopt, 1e-12, true);
  REQUIRE(m.jac.size() == 41);
  for (std::size_t k = 0; k < free.size(); ++k) {
    const auto fd = engine_difference(s, free[k], 1e-4, 1e-13, "faithful");
    INFO(free[k]);
    CHECK(relative_difference(m.jac, k, fd) < 1e-6);
  }
}

TEST_CASE("fit sensitivities: rough scene, thesis law, against central differences", "[fit][numeric]") {
  const Scene s = short_scene("thesis/fig3_20.toml", 0.4e-9, 41);
  const std::vector<std::string> free = {"surface.mu", "push.force"};
  const std::vector<double> p = {s.surface.mu, s.push.force};
  const ModelPoses m = model_poses(s, free, p, s.output_times(), Law::thesis, 1e-12, true);
  for (std::size_t k = 0; k < free.size(); ++k) {
    const auto fd = engine_difference(s, free[k], 1e-4, 1e-13, "modern", "thesis");
    INFO(free[k]);
    CHECK(relative_difference(m.jac, k, fd) < 1e-6);
  }
}

TEST_CASE("fit gradients: coulomb law by differences of whole solves, across stick events", "[fit][numeric]") {
  // Fig 3.27 parameters (mu = 0.15): the bar slides from rest and sticks at t = 3.81e-10 s,
  // 1e-12 s after a sample. The Jacobian of the fit (central differences, step 1e-4, rtol
  // 1e-12, faithful Bulirsch-Stoer) against differences of the modern method's solves with
  // step 1e-5 at rtol 1e-13: 8e-6 relative (a step of 1e-3 moves the stick across the sample,
  // and the differences there mean nothing: 7e-4).
  const Scene s = short_scene("bench/stick_mu015.toml", 0.8e-9, 41);
  const ModelPoses m = model_poses(s, {"surface.mu"}, {s.surface.mu}, s.output_times(), Law::coulomb, 1e-10, true);
  const auto fd = engine_difference(s, "surface.mu", 1e-5, 1e-13, "modern", "coulomb");
  CHECK(relative_difference(m.jac, 0, fd) < 3e-5);
  CHECK_THAT(input_error_of([&] {
               (void)model_poses(s, {"surface.mu"}, {s.surface.mu}, s.output_times(), Law::coulomb, 1e-10, true,
                                 fit::Gradients::sensitivities);
             }),
             Catch::Contains("rest events"));
}

namespace {

/// Synthetic data at the truth, a start away from it, the fit; truth within 3 stderr.
FitResult fit_synthetic(const Scene& truth, const std::string& key, double start, const std::array<double, 3>& sigma,
                        const std::string& law, std::uint64_t seed) {
  const Observations obs = synthesize(truth, sigma, seed, parse_optional_choice<Law>("law", law));
  Scene s = truth;
  s.set(key, start);
  FitOptions o;
  o.free = {key};
  o.law = parse_optional_choice<Law>("law", law);
  const FitResult r = fit_trajectory(s, obs, o);
  const double t = truth.document->at_path(key).value<double>().value();
  INFO(key << " truth " << t << " estimate " << r.parameters[0].value << " +- " << r.parameters[0].stderr_ << " "
           << r.status << " chi2/dof " << r.chi2_dof);
  CHECK(r.converged);
  CHECK(std::isfinite(r.parameters[0].stderr_));
  CHECK(std::abs(r.parameters[0].value - t) < 3 * r.parameters[0].stderr_);
  CHECK(r.chi2_dof > 0.5);
  CHECK(r.chi2_dof < 1.5);
  CHECK(r.identifiability.identifiable);
  return r;
}

}  // namespace

TEST_CASE("fit synthetic: smooth scene, push.force", "[fit][numeric]") {
  const Scene s = short_scene("thesis/fig3_6a.toml", 0.8e-9, 81);
  const FitResult r = fit_synthetic(s, "push.force", 1.3 * s.push.force, {2e-9, 2e-9, 0.02}, "", 11);
  CHECK(r.gradients == fit::Gradients::sensitivities);
  CHECK(r.fitted.size() == 81);
}

TEST_CASE("fit synthetic: rough scene, thesis law, surface.mu", "[fit][numeric]") {
  const Scene s = short_scene("thesis/fig3_20.toml", 0.8e-9, 81);
  fit_synthetic(s, "surface.mu", 0.1, {1e-9, 1e-9, 0.01}, "thesis", 12);
}

TEST_CASE("fit synthetic: rough scene, coulomb law, surface.mu", "[fit][numeric]") {
  const Scene s = short_scene("bench/stick_mu015.toml", 0.8e-9, 81);
  const FitResult r = fit_synthetic(s, "surface.mu", 0.13, {1e-9, 1e-9, 0.01}, "coulomb", 13);
  CHECK(r.gradients == fit::Gradients::differences);
}

/// The fit found the keys `undetermined` not determined separately, and the data determine
/// their combination `combination` (first in the list).
void check_undetermined(const FitResult& r, const std::vector<std::string>& undetermined,
                        const std::string& combination) {
  const auto& id = r.identifiability;
  INFO(id.message);
  CHECK_FALSE(id.identifiable);
  CHECK(id.undetermined == undetermined);
  REQUIRE_FALSE(id.determined.empty());
  CHECK(id.determined[0].name == combination);
}

TEST_CASE("fit: a model that starts where the thesis law has no static friction says so at once", "[fit][unit]") {
  // Found by a hypercube of fits: a 34 nm bar under 1e-10 N with mu N = 2e-9 N. A run says
  // no_static_friction at once; the fit's forward solve chattered through fig3_18's 20,000
  // steps and reported a bare "too many steps" (and --synthesize with it).
  Scene s = short_scene("thesis/fig3_18.toml", 1.6e-9, 41);
  s.set({{"object.length", 3.418347483686828e-08},
         {"object.width", 2.089977841493339e-08},
         {"object.height", 3.668631917456952e-08},
         {"surface.mu", 0.3346263720527797},
         {"push.force", 1.0245431800604229e-10},
         {"surface.f_vdw", 6.047122636090708e-09},
         {"push.yn", 2.804347036495063e-09},
         {"push.xn", -1.0449889207466695e-08}});
  REQUIRE(s.friction_limit() > s.push.force);
  try {
    (void)synthesize(s, {1e-11, 1e-11, 1e-3}, 1, Law::thesis);
    FAIL("no error");
  } catch (const SolverError& e) {
    CHECK(e.outcome() == "no_static_friction");
    CHECK_THAT(e.what(), Catch::Contains("cannot break static friction") && Catch::Contains("--law coulomb"));
  }
  // Under the coulomb law the same model is an answer: the object stays where it is.
  const Observations obs = synthesize(s, {1e-11, 1e-11, 1e-3}, 1, Law::coulomb);
  CHECK(obs.t.size() == 41);
  // fig3_27 slides, then comes to rest where the push cannot break static friction: the forward
  // model's rest watch stops there, as the run's does, instead of chattering to the budget.
  try {
    (void)synthesize(preset("thesis/fig3_27.toml"), {1e-9, 1e-9, 1e-2}, 1, Law::thesis);
    FAIL("no error");
  } catch (const SolverError& e) {
    CHECK(e.outcome() == "no_static_friction");
    CHECK_THAT(e.what(), Catch::Contains("came to rest at t = "));
  }
  // With sensitivities the solve follows them too and they blow up at rest: it gave up with
  // "step size underflow" before the watch saw the reversal (fig3_20 at mu = 0.2). The same
  // rest is classified as the run classifies it.
  Scene held = preset("thesis/fig3_20.toml");
  held.set("surface.mu", 0.2);
  try {
    (void)model_poses(held, {"surface.mu"}, {0.2}, held.output_times(), Law::thesis, 1e-10, true);
    FAIL("no error");
  } catch (const SolverError& e) {
    CHECK(e.outcome() == "no_static_friction");
    CHECK_THAT(e.what(), Catch::Contains("came to rest at t = "));
  }
}

TEST_CASE("fit identifiability: mu and the adhesion load enter only as mu*N", "[fit][numeric]") {
  const Scene s = short_scene("thesis/fig3_20.toml", 0.8e-9, 41);
  const Observations obs = synthesize(s, {1e-9, 1e-9, 0.01}, 21, Law::thesis);
  Scene start = s;
  start.set("surface.mu", 0.1);
  FitOptions o;
  o.free = {"surface.mu", "surface.f_vdw"};
  const FitResult r = fit_trajectory(start, obs, o);
  check_undetermined(r, {"surface.mu", "surface.f_vdw"}, "mu*N");
  const auto& id = r.identifiability;
  INFO(id.message);
  // mu*N itself is determined: near the truth, within 3 of its standard errors.
  const double truth = s.surface.mu * s.normal_load();
  CHECK(std::abs(std::log(id.determined[0].value / truth)) < 3 * id.determined[0].stderr_relative);
  CHECK(std::isnan(r.parameters[0].stderr_));
  CHECK(std::isnan(r.parameters[1].stderr_));
  CHECK_THAT(id.message, Catch::Contains("not determined separately") && Catch::Contains("mu*N"));
  const std::string json = fit_json(r);
  CHECK_THAT(json, Catch::Contains("\"stderr\": null") && Catch::Contains("\"identifiable\": false"));
}

TEST_CASE("fit JSON: the shape the issue specifies", "[fit][unit]") {
  const Scene s = short_scene("thesis/fig3_6a.toml", 0.4e-9, 21);
  const Observations obs = synthesize(s, {2e-9, 0, 0}, 3);
  Scene start = s;
  start.set("push.force", 4e-6);
  FitOptions o;
  o.free = {"push.force"};
  const FitResult r = fit_trajectory(start, obs, o);
  const auto j = nlohmann::json::parse(fit_json(r));
  const auto& p = j["parameters"]["push.force"];
  CHECK(p["value"] == r.parameters[0].value);  // the shortest decimal reads back to the same double
  CHECK(p["stderr"] == r.parameters[0].stderr_);
  CHECK(p["unit"] == "N");
  CHECK(j["chi2_dof"].is_number());
  CHECK(j["converged"] == true);
  CHECK(j["n_forward_solves"] == r.n_forward_solves);
  CHECK(r.n_forward_solves >= 2);
}

TEST_CASE("fit options: bad keys and settings are named", "[fit][unit]") {
  const Scene s = short_scene("thesis/fig3_6a.toml", 0.4e-9, 21);
  const Observations obs = synthesize(s, {2e-9, 0, 0}, 3);
  FitOptions o;
  CHECK_THAT(input_error_of([&] { (void)fit_trajectory(s, obs, o); }), Catch::Contains("--free = (none)"));
  o.free = {"surface.mu"};  // smooth scene: no friction
  CHECK_FALSE(input_error_of([&] { (void)fit_trajectory(s, obs, o); }).empty());
  o.free = {"solver.t_end"};
  CHECK_THAT(input_error_of([&] { (void)fit_trajectory(s, obs, o); }), Catch::Contains("not model parameters"));
  o.free = {"object.shape"};
  CHECK_THAT(input_error_of([&] { (void)fit_trajectory(s, obs, o); }), Catch::Contains("numeric key"));
  o.free = {"push.force", "push.force"};
  CHECK_THAT(input_error_of([&] { (void)fit_trajectory(s, obs, o); }), Catch::Contains("named twice"));
  // Synthetic data: a negative sigma is refused (it read as "not observed"), and so is data
  // with no column observed (a table of times only).
  CHECK_THAT(input_error_of([&] { (void)synthesize(s, {-1, 0, 0}, 1); }), Catch::StartsWith("sigma_x = -1: must be >= 0"));
  CHECK_THAT(input_error_of([&] { (void)synthesize(s, {0, 0, 0}, 1); }),
             Catch::StartsWith("sigma = 0,0,0: observe at least one column"));
}

TEST_CASE("fit non-convergence: reported with the last state, never silent", "[fit][unit]") {
  const Scene s = short_scene("thesis/fig3_6a.toml", 0.4e-9, 21);
  const Observations obs = synthesize(s, {2e-9, 2e-9, 0}, 4);
  Scene start = s;
  start.set("push.force", 2e-6);
  FitOptions o;
  o.free = {"push.force"};
  o.max_evaluations = 1;
  const FitResult r = fit_trajectory(start, obs, o);
  CHECK_FALSE(r.converged);
  CHECK_THAT(r.status, Catch::Contains("not converged"));
  CHECK(std::isfinite(r.parameters[0].value));
  CHECK_THAT(fit_json(r), Catch::Contains("\"converged\": false"));
}

TEST_CASE("fit identifiability: push force and density enter only as F/m on a smooth scene", "[fit][numeric]") {
  // The bar's inertia scales with its mass (density given): the motion sees F/m only.
  const Scene s = short_scene("thesis/fig3_6a.toml", 0.4e-9, 41);
  const Observations obs = synthesize(s, {2e-9, 2e-9, 0.02}, 8);
  Scene start = s;
  start.set("push.force", 4.8e-6);  // near: the pendulum has other minima further away
  FitOptions o;
  o.free = {"push.force", "object.density", "initial.theta"};
  const FitResult r = fit_trajectory(start, obs, o);
  check_undetermined(r, {"push.force", "object.density"}, "F/m");
  // initial.theta is outside the undetermined direction: it keeps its standard error.
  CHECK(std::isfinite(r.parameters[2].stderr_));
  CHECK(std::abs(r.parameters[2].value - s.initial[kTheta]) < 3 * r.parameters[2].stderr_);
  CHECK(r.chi2_dof < 1.5);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
