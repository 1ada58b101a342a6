// The closed loop (plan.hpp: closed_loop; docs/planning.md): image, re-plan, push, repeat.
#include <chrono>
#include <cmath>
#include <random>

#include <boost/math/tools/minima.hpp>

#include "nanopush/numerics/error.hpp"
#include "nanopush/planning/plan.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "pushes.hpp"

namespace nanopush::plan {

using detail::standard_normal;

double fit_tip_mu(const Scene& model, const std::vector<SeenPush>& seen, const Noise& noise, const PlanOptions& o,
                  double current, double mu_max) {
  if (seen.empty() || model.push_mode != PushMode::tip) return current;
  const double sx = noise.x > 0 ? noise.x : 1e-3 * o.tolerance_distance,
               sy = noise.y > 0 ? noise.y : 1e-3 * o.tolerance_distance,
               st = noise.theta > 0 ? noise.theta : 1e-3 * o.tolerance_angle;
  constexpr double kCannot = 1e12;  // a push the model cannot make at this mu
  auto cost = [&](double mu) {
    Scene m = model;
    m.set("tip.mu", mu);
    double s = 0;
    for (const SeenPush& p : seen) {
      try {
        const Trajectory tr = run_scene(push_scene(m, p.before, p.push));
        const auto& r = tr.rows.back();
        const double dx = (r[col::x] - p.after.x) / sx, dy = (r[col::y] - p.after.y) / sy,
                     dt = angle_error(r[col::theta], p.after.theta, false) / st;
        s += dx * dx + dy * dy + dt * dt;
      } catch (const InputError&) {
        s += kCannot;
      } catch (const SolverError&) {
        s += kCannot;
      }
    }
    return s;
  };
  constexpr int kScan = 9;
  std::vector<double> mu(kScan), c(kScan);
  for (int i = 0; i < kScan; ++i) {
    mu[static_cast<std::size_t>(i)] = mu_max * i / (kScan - 1);
    c[static_cast<std::size_t>(i)] = cost(mu[static_cast<std::size_t>(i)]);
  }
  const auto best = static_cast<std::size_t>(std::min_element(c.begin(), c.end()) - c.begin());
  const double lo = mu[best > 0 ? best - 1 : 0], hi = mu[std::min<std::size_t>(best + 1, kScan - 1)];
  std::uintmax_t iterations = 20;
  const auto r = boost::math::tools::brent_find_minima(cost, lo, hi, 20, iterations);
  return r.second <= c[best] ? r.first : mu[best];
}

ClosedLoopResult closed_loop(const Scene& model_in, const Scene& truth, const Pose& goal, const PlanOptions& o,
                             const Noise& noise, std::uint64_t seed, const Refit& refit) {
  Scene model = model_in;  // its tip.mu is re-fitted along the loop
  const bool tip_scene = model.push_mode == PushMode::tip;
  std::vector<SeenPush> seen_pushes;
  const auto t0 = std::chrono::steady_clock::now();
  detail::check_task(model, goal, o);
  for (double s : {noise.x, noise.y, noise.theta})
    if (!(s >= 0 && std::isfinite(s))) throw InputError("--noise", std::to_string(s), "standard deviations must be >= 0");
  std::mt19937_64 rng(seed);
  auto image = [&](const Pose& p) {
    return Pose{p.x + noise.x * standard_normal(rng), p.y + noise.y * standard_normal(rng),
                p.theta + noise.theta * standard_normal(rng)};
  };
  auto within = [&](const Pose& p) {
    return std::hypot(p.x - goal.x, p.y - goal.y) <= o.tolerance_distance &&
           std::fabs(angle_error(p.theta, goal.theta, o.half_turn_symmetric)) <= o.tolerance_angle;
  };
  // What the images can vouch for: the loop aims, and stops, two sigmas of its mean image
  // inside the tolerance (when that leaves at least half of it), so a stop is a true arrival.
  constexpr int kConfirmImages = 3;
  const double sd = std::hypot(noise.x, noise.y) / std::sqrt(double(kConfirmImages)),
               sa = noise.theta / std::sqrt(double(kConfirmImages));
  PlanOptions aim = o;
  aim.tolerance_distance = std::max(0.5 * o.tolerance_distance, o.tolerance_distance - 2 * sd);
  aim.tolerance_angle = std::max(0.5 * o.tolerance_angle, o.tolerance_angle - 2 * sa);
  auto within_aim = [&](const Pose& p) {
    return std::hypot(p.x - goal.x, p.y - goal.y) <= aim.tolerance_distance &&
           std::fabs(angle_error(p.theta, goal.theta, o.half_turn_symmetric)) <= aim.tolerance_angle;
  };
  // Stop only when the mean of kConfirmImages images is within the aim: one image within the
  // tolerance leaves the truth outside too often (its error is the noise's sigma; the mean's is
  // sigma / sqrt(n)). A lab takes the extra images only when one already says "there".
  auto confirmed = [&](const Pose& truth_pose, Pose& seen_pose) {
    if (!within_aim(seen_pose)) return false;
    Pose mean = seen_pose;
    for (int k = 1; k < kConfirmImages; ++k) {
      const Pose p = image(truth_pose);
      mean.x += p.x;
      mean.y += p.y;
      mean.theta += seen_pose.theta + angle_error(p.theta, seen_pose.theta, false);
    }
    mean = {mean.x / kConfirmImages, mean.y / kConfirmImages, mean.theta / kConfirmImages};
    seen_pose = mean;
    return within_aim(mean);
  };
  ClosedLoopResult res;
  Pose true_pose{truth.initial[kX], truth.initial[kY], truth.initial[kTheta]};
  Pose seen = image(true_pose);
  while (static_cast<int>(res.steps.size()) < o.max_pushes && !confirmed(true_pose, seen)) {
    // Plan from the image with the model (its initial pose replaced by what was seen).
    Scene from = model;
    from.set({{"initial.x", seen.x}, {"initial.y", seen.y}, {"initial.theta", seen.theta}});
    PlanOptions po = aim;
    po.max_pushes = o.max_pushes - static_cast<int>(res.steps.size());
    const PlanResult plan = plan_pushes(from, goal, po);
    if (plan.pushes.empty()) {
      res.message = "no push brings the imaged bar closer to the goal";
      break;
    }
    LoopStep step;
    step.observed = seen;
    step.truth = true_pose;
    step.push = plan.pushes.front();
    step.plan_pushes = static_cast<int>(plan.pushes.size());
    step.tip_mu = tip_scene ? model.tip.mu : -1;
    bool made = false;
    // The tip follows the planned path in world axes; the bar is where it truly is.
    try {
      const Trajectory tr = run_scene(push_scene(truth, true_pose, step.push));
      const auto& r = tr.rows.back();
      true_pose = {r[col::x], r[col::y], r[col::theta]};
      made = true;
    } catch (const InputError&) {
      // The planned tip start lies inside the true bar (the image was off by more than the
      // clearance): the AFM would touch down on the bar; the push is not made, image again.
      ++res.unsimulated;
    } catch (const SolverError&) {
      // The model cannot follow this push on the true bar (the quasi-static solve fails where
      // the tip meets a corner): it is not made, and the bar is imaged again. Counted, so a
      // benchmark says how often the loop had to step around its own model.
      ++res.unsimulated;
    }
    res.tip_travel += step.push.travel;
    res.time += step.push.travel / step.push.speed;
    res.steps.push_back(step);
    const Pose before = seen;
    seen = image(true_pose);
    if (made && refit.enabled && tip_scene) {
      seen_pushes.push_back({before, seen, step.push});
      if (static_cast<int>(seen_pushes.size()) > refit.window) seen_pushes.erase(seen_pushes.begin());
      model.set("tip.mu", fit_tip_mu(model, seen_pushes, noise, o, model.tip.mu, refit.mu_max));
    }
  }
  res.tip_mu = tip_scene ? model.tip.mu : -1;
  res.final_truth = true_pose;
  res.final_observed = seen;
  res.final_distance = std::hypot(true_pose.x - goal.x, true_pose.y - goal.y);
  res.final_angle = std::fabs(angle_error(true_pose.theta, goal.theta, o.half_turn_symmetric));
  res.status = within(true_pose) ? LoopStatus::reached : LoopStatus::not_reached;
  if (!res.reached() && res.message.empty())
    res.message = "after " + std::to_string(res.steps.size()) + " pushes the bar is " + std::to_string(res.final_distance) +
                  " m and " + std::to_string(res.final_angle) + " rad from the goal (the image " +
                  (within(seen) ? "says it is there: the noise hides the rest)" : "says it is not)");
  res.planning_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace nanopush::plan
