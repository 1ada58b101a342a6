// The target-oriented baseline planner (plan.hpp: plan_baseline; docs/planning.md).
#include <chrono>
#include <cmath>
#include <limits>

#include "nanopush/planning/plan.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "pushes.hpp"

namespace nanopush::plan {

PlanResult plan_baseline(const Scene& scene, const Pose& goal, const PlanOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  detail::check_task(scene, goal, o);
  const BarGeometry& g = scene.geometry;
  const double L = 2 * std::max(g.a, g.b);
  const tip::TipPath base = scene.push_mode == PushMode::tip ? scene.tip : tip::TipPath{};
  const double muN = scene.friction_limit(), rtol = std::max(scene.solver.rtol, 1e-10);
  const bool long_y = g.b >= g.a;
  // The long faces push along body x' (long_y) or y'; a turn pushes one of them off-centre.
  const int face_lo = long_y ? 0 : 2;
  const double aim_tol = std::max(o.tolerance_angle, 0.02);
  PlanResult res;
  res.start = {scene.initial[kX], scene.initial[kY], scene.initial[kTheta]};
  res.goal = goal;
  res.options = o;
  Pose pose = res.start;
  auto within = [&](const Pose& p) {
    return std::hypot(p.x - goal.x, p.y - goal.y) <= o.tolerance_distance &&
           std::fabs(angle_error(p.theta, goal.theta, o.half_turn_symmetric)) <= o.tolerance_angle;
  };
  // Direction the long face's inward normal points at orientation theta (face -x' or -y').
  auto normal_angle = [&](double theta) { return theta + (long_y ? 0.0 : M_PI / 2); };
  // A push chosen by `aim` (smaller is better) over a trial's stopping points.
  auto best_stop = [&](const detail::Trial& t, auto&& aim) {
    std::size_t best = t.rows.size();
    double v = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      if (!detail::pushed(t.rows[i])) continue;
      const double a = aim(Pose{t.rows[i].x, t.rows[i].y, t.rows[i].theta});
      if (a < v) {
        v = a;
        best = i;
      }
    }
    return best;
  };
  // Take a push: its end pose is the scene's forward run of it, as in plan_pushes.
  auto take = [&](PlannedPush p) -> bool {
    try {
      const Trajectory tr = run_scene(push_scene(scene, pose, p));
      const auto& r = tr.rows.back();
      p.end = {r[col::x], r[col::y], r[col::theta]};
    } catch (const std::exception&) {
      return false;
    }
    res.pushes.push_back(p);
    pose = p.end;
    return true;
  };
  // Turn towards orientation `target` (modulo pi: either long face) by a push at 0.7 of the
  // half-length on the side that turns the right way.
  auto turn = [&](double target) -> bool {
    const double err = angle_error(target, pose.theta, true);  // > 0: turn counter-clockwise
    // On face -x' (inward normal +x'), a push at y' = s b has torque -s b F: s < 0 turns CCW.
    const double s = err > 0 ? -0.7 : 0.7;
    const double travel = o.clearance + 1.5 * std::fabs(err) * L;
    const detail::Trial t = detail::trial_push(g, muN, base, pose, face_lo, long_y ? s : -s, o.clearance, travel, 241, rtol);
    ++res.forward_runs;
    if (!t.ok) return false;
    const std::size_t i = best_stop(t, [&](const Pose& p) { return std::fabs(angle_error(target, p.theta, true)); });
    if (i >= t.rows.size()) return false;
    return take(detail::push_at(t, i));
  };
  while (static_cast<int>(res.pushes.size()) < o.max_pushes && !within(pose)) {
    const double dx = goal.x - pose.x, dy = goal.y - pose.y, dist = std::hypot(dx, dy);
    bool ok;
    if (dist > o.tolerance_distance) {
      const double aim = std::atan2(dy, dx);
      const double off = angle_error(aim, normal_angle(pose.theta), true);
      if (std::fabs(off) > aim_tol) {
        ok = turn(pose.theta + off);  // point a long face's normal at the goal
      } else {  // push through the centre, from the face whose normal points at the goal
        const bool forward = std::cos(aim - normal_angle(pose.theta)) > 0;
        const int face = face_lo + (forward ? 0 : 1);
        const detail::Trial t = detail::trial_push(g, muN, base, pose, face, 0.0, o.clearance, o.clearance + 1.2 * dist,
                                                   241, rtol);
        ++res.forward_runs;
        ok = t.ok;
        if (ok) {
          const std::size_t i = best_stop(t, [&](const Pose& p) { return std::hypot(p.x - goal.x, p.y - goal.y); });
          ok = i < t.rows.size();
          if (ok) ok = take(detail::push_at(t, i));
        }
      }
    } else {
      ok = turn(goal.theta);
    }
    if (!ok) break;
  }
  detail::verify(scene, res, o);
  res.planning_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace nanopush::plan
