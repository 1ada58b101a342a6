// Push planning (plan.hpp, docs/planning.md): a greedy search over iCOR-informed candidate
// pushes, each candidate one quasi-static run whose best stopping point along the way sets
// the push's travel; then every push re-run as a scene, and the whole chain end to end.
#include "nanopush/planning/plan.hpp"

#include "nanopush_toml.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include "nanopush/models/tip_push.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/numerics/names.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "pushes.hpp"

namespace nanopush::plan {

using detail::kFaces;

namespace {

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

constexpr std::pair<Objective, std::string_view> kObjectives[] = {
    {Objective::pushes, "pushes"}, {Objective::travel, "travel"}, {Objective::time, "time"}, {Objective::force, "force"}};

struct Candidate {
  int face = 0;
  double offset = 0;
};

bool within(const Pose& p, const Pose& goal, const PlanOptions& o) {
  return std::hypot(p.x - goal.x, p.y - goal.y) <= o.tolerance_distance &&
         std::fabs(angle_error(p.theta, goal.theta, o.half_turn_symmetric)) <= o.tolerance_angle;
}

/// A world a robust plan must reach the goal in: the scene with its tip friction, and the
/// bar's pose in it as the plan's pushes so far leave it.
struct World {
  double tip_mu = 0;
  Scene scene;
  Pose start, pose;
};

/// The model's world, then (PlanOptions::robust) the tip friction at both ends of the range and
/// the start shifted by each component's +-shift, one at a time.
std::vector<World> make_worlds(const Scene& scene, const Pose& start, const PlanOptions& o) {
  const double mu0 = scene.push_mode == PushMode::tip ? scene.tip.mu : 0.0;
  std::vector<World> ws{{mu0, scene, start, start}};
  if (!o.robust()) return ws;
  if (o.robust_tip_mu_lo >= 0) {  // a valid range (check_task)
    if (scene.push_mode != PushMode::tip)
      throw InputError("--tip-mu-range", scene.name, "plans over tip friction need a tip scene (push.mode = \"tip\")");
    for (double mu : {o.robust_tip_mu_lo, o.robust_tip_mu_hi}) {
      if (std::any_of(ws.begin(), ws.end(), [&](const World& w) { return w.tip_mu == mu && w.start.x == start.x &&
                                                                          w.start.y == start.y && w.start.theta == start.theta; }))
        continue;
      World w{mu, scene, start, start};
      w.scene.set("tip.mu", mu);
      ws.push_back(std::move(w));
    }
  }
  const double shifts[3] = {o.robust_start_x, o.robust_start_y, o.robust_start_theta};
  for (int k = 0; k < 3; ++k) {  // finite and >= 0 (check_task)
    if (shifts[k] == 0) continue;
    for (double sign : {-1.0, 1.0}) {
      Pose p = start;
      (k == 0 ? p.x : k == 1 ? p.y : p.theta) += sign * shifts[k];
      World w{mu0, scene, p, p};
      w.scene.set({{"initial.x", p.x}, {"initial.y", p.y}, {"initial.theta", p.theta}});
      ws.push_back(std::move(w));
    }
  }
  return ws;
}

/// Each robust world's replay of the whole plan from its start; the plan is found only when it
/// reaches the goal in every world, verified only when every replay ends within tolerance.
void verify_worlds(const std::vector<World>& worlds, PlanResult& res, const PlanOptions& o) {
  bool all = true;
  std::size_t k = 0, first_miss = 0;
  for (const World& w : worlds) {
    PlanResult::World out{w.tip_mu, w.start, w.start, 0, 0, false};
    bool ran = true;
    for (const PlannedPush& p : res.pushes) {
      try {
        const Trajectory tr = run_scene(push_scene(w.scene, out.final_pose, p));
        const auto& r = tr.rows.back();
        out.final_pose = {r[col::x], r[col::y], r[col::theta]};
      } catch (const std::exception&) {
        ran = false;
        break;
      }
    }
    out.final_distance = std::hypot(out.final_pose.x - res.goal.x, out.final_pose.y - res.goal.y);
    out.final_angle = std::fabs(angle_error(out.final_pose.theta, res.goal.theta, o.half_turn_symmetric));
    out.reached = ran && within(out.final_pose, res.goal, o);
    if (!out.reached && all) first_miss = k;
    all = all && out.reached;
    res.worlds.push_back(out);
    ++k;
  }
  res.verified = res.verified && all;
  if (all || !res.found()) return;
  const PlanResult::World& m = res.worlds[first_miss];
  res.status = PlanStatus::not_found;
  res.message = "no plan within " + std::to_string(o.max_pushes) + " pushes reaches the goal in every world: with tip.mu = " +
                fmt(m.tip_mu) + " from (" + fmt(m.start.x) + ", " + fmt(m.start.y) + ", " + fmt(m.start.theta) +
                ") the best leaves the bar " + fmt(m.final_distance) + " m and " + fmt(m.final_angle) + " rad from the goal";
}

}  // namespace

namespace detail {

Trial trial_push(const BarGeometry& g, double muN, const tip::TipPath& tip, const Pose& p, int face, double offset,
                 double clearance, double travel_max, int samples, double rtol) {
  Trial t;
  t.face = face;
  t.offset = offset;
  const Face& f = kFaces[face];
  // Contact point on the face (body axes), then the tip's centre one radius + clearance outside.
  const double bx = f.nx != 0 ? -f.nx * g.a : offset * g.a;
  const double by = f.ny != 0 ? -f.ny * g.b : offset * g.b;
  const double cs = std::cos(p.theta), sn = std::sin(p.theta);
  const double wx = p.x + cs * bx - sn * by, wy = p.y + sn * bx + cs * by;
  const double dx = cs * f.nx - sn * f.ny, dy = sn * f.nx + cs * f.ny;
  const double back = tip.radius + clearance;
  t.path = tip;
  t.path.start_x = wx - back * dx;
  t.path.start_y = wy - back * dy;
  t.path.direction = std::atan2(dy, dx);
  t.path.travel = travel_max;
  try {
    t.rows = tip::run_quasi_static(g, muN, t.path, p.x, p.y, p.theta, 0.0, samples, rtol).rows;
    t.ok = true;
  } catch (const SolverError&) {
    t.ok = false;  // no quasi-static answer along this push: not one to plan with
  }
  return t;
}

void check_task(const Scene& scene, const Pose& goal, const PlanOptions& o) {
  if (!scene.rough())
    throw InputError("surface.kind", "\"" + scene.model + "\"", "pushes are planned against friction: use \"rough\"");
  if (!(scene.friction_limit() > 0)) throw InputError("surface.mu", fmt(scene.surface.mu), "must be > 0 to plan pushes");
  for (double v : {goal.x, goal.y, goal.theta})
    if (!std::isfinite(v)) throw InputError("--goal", fmt(goal.x) + "," + fmt(goal.y) + "," + fmt(goal.theta), "must be three finite numbers X,Y,THETA (m, m, rad)");
  const double L = 2 * std::max(scene.geometry.a, scene.geometry.b);
  // Within reach: a push's travel and duration follow from the distance to the goal, and a goal
  // beyond a million bar lengths (far past any AFM's scan range) is no task for the bar, whose
  // pushes would overflow there.
  {
    const double x0 = scene.initial[kX], y0 = scene.initial[kY], reach = kGoalReach * L;
    if (!(std::hypot(goal.x - x0, goal.y - y0) <= reach)) {
      std::ostringstream r;
      r << std::setprecision(3) << reach;
      throw InputError("--goal", fmt(goal.x) + "," + fmt(goal.y) + "," + fmt(goal.theta),
                       "must be within 1e6 bar lengths of the bar's start: |(X, Y) - (" + fmt(x0) + ", " + fmt(y0) +
                           ")| <= " + r.str() + " m (the bar is " + fmt(L) + " m long)");
    }
    // An angle is compared modulo 2 pi (pi for a symmetric bar): beyond 1e6 rad its remainder
    // keeps fewer digits than the angle tolerance can judge (eps 1e6 = 2e-10 rad).
    if (!(std::fabs(goal.theta) <= 1e6))
      throw InputError("--goal", fmt(goal.x) + "," + fmt(goal.y) + "," + fmt(goal.theta),
                       "THETA must be within [-1e6, 1e6] rad (it is taken modulo 2 pi: give it reduced)");
  }
  require_finite("--tolerance", o.tolerance_distance, "m");
  require_finite("--tolerance", o.tolerance_angle, "rad");
  // The model resolves poses to ~rtol of the bar's size; a tolerance below 1e-6 of it is noise.
  if (!(o.tolerance_distance >= 1e-6 * L))
    throw InputError("--tolerance", fmt(o.tolerance_distance) + " m",
                     "below what the model resolves: must be >= " + fmt(1e-6 * L) + " m (1e-6 of the bar's length)");
  if (!(o.tolerance_angle >= 1e-6)) throw InputError("--tolerance", fmt(o.tolerance_angle) + " rad", "must be >= 1e-6 rad");
  if (o.max_pushes < 1 || o.max_pushes > 1000) throw InputError("--max-pushes", std::to_string(o.max_pushes), "must be in [1, 1000]");
  if (!(o.clearance > 0)) throw InputError("clearance", fmt(o.clearance), "must be > 0 (m)");
  // Robust worlds (-1, -1: the model's tip friction only). A range that is not one, or a
  // negative or NaN shift, would otherwise read as "not robust" and give a plan for the
  // model alone.
  check_tip_mu_range(o.robust_tip_mu_lo, o.robust_tip_mu_hi);
  for (double v : {o.robust_start_x, o.robust_start_y, o.robust_start_theta})
    if (!(v >= 0 && std::isfinite(v)))
      throw InputError("--noise", fmt(v), "a robust plan's start shifts must be finite and >= 0");

}

void verify(const Scene& scene, PlanResult& res, const PlanOptions& o) {
  const Pose& goal = res.goal;
  const bool sym = o.half_turn_symmetric;
  // The end pose of push p replayed as a scene from pose `from` (nullopt: it cannot start there).
  auto replay = [&](const Pose& from, const PlannedPush& p, std::string& why) -> std::optional<Pose> {
    try {
      const Trajectory tr = run_scene(push_scene(scene, from, p));
      const auto& r = tr.rows.back();
      return Pose{r[col::x], r[col::y], r[col::theta]};
    } catch (const std::exception& e) {
      why = e.what();
      return std::nullopt;
    }
  };
  // 1. Each push, run as a scene from the pose the plan says it starts at.
  Pose from = res.start;
  bool each_ok = true;
  std::size_t k = 0;
  for (PlannedPush& p : res.pushes) {
    ++k;
    std::string why;
    const auto end = replay(from, p, why);
    if (!end) {
      each_ok = false;
      res.message = "push " + std::to_string(k) + " does not replay: " + why;
      break;
    }
    p.verified_deviation = std::max(std::hypot(end->x - p.end.x, end->y - p.end.y) / o.tolerance_distance,
                                    std::fabs(angle_error(end->theta, p.end.theta, false)) / o.tolerance_angle);
    each_ok = each_ok && p.verified_deviation <= 0.1;
    from = p.end;
    res.tip_travel += p.travel;
    res.time += p.travel / p.speed;
  }
  const bool planned_reach = within(res.pushes.empty() ? res.start : res.pushes.back().end, goal, o);
  // 2. The whole sequence end to end from the start: each push from where the last one left.
  Pose at = res.start;
  bool chain_ok = true;
  k = 0;
  for (const PlannedPush& p : res.pushes) {
    ++k;
    std::string why;
    const auto end = replay(at, p, why);
    if (!end) {
      chain_ok = false;
      if (res.message.empty())
        res.message = "end to end, push " + std::to_string(k) + " cannot start where the pushes before it left the bar (" +
                      why + "): the plan's small deviations grew";
      break;
    }
    at = *end;
  }
  res.final_pose = at;
  res.final_distance = std::hypot(at.x - goal.x, at.y - goal.y);
  res.final_angle = std::fabs(angle_error(at.theta, goal.theta, sym));
  chain_ok = chain_ok && within(at, goal, o);
  res.verified = each_ok && chain_ok;
  res.status = planned_reach ? PlanStatus::found : PlanStatus::not_found;
  if (!planned_reach && res.message.empty())
    res.message = "no plan within " + std::to_string(o.max_pushes) + " pushes: the best leaves the bar " +
                  fmt(res.final_distance) + " m and " + fmt(res.final_angle) + " rad from the goal";
  else if (planned_reach && !chain_ok && res.message.empty())
    res.message = "each push replays as planned, but end to end from the start the bar ends " + fmt(res.final_distance) +
                  " m and " + fmt(res.final_angle) +
                  " rad from the goal: deviations of the order of the tolerance of the integration grow along the "
                  "sequence (pushes near the centre with a frictionless tip are unstable); plan in closed loop";
}

PlannedPush push_at(const Trial& t, std::size_t i) {
  double max_force = 0;
  for (std::size_t k = 0; k <= i; ++k) max_force = std::max(max_force, std::hypot(t.rows[k].tip_fx, t.rows[k].tip_fy));
  const tip::TipRow& r = t.rows[i];
  return {t.path.start_x, t.path.start_y, t.path.direction, t.path.speed, t.path.speed * r.t,
          Pose{r.x, r.y, r.theta}, kFaces[t.face].name, t.offset, max_force};
}

}  // namespace detail

Objective parse_objective(const std::string& text) {
  for (const auto& [o, n] : kObjectives)
    if (text == n) return o;
  throw InputError("--objective", text, "must be one of: pushes, travel, time, force");
}

std::string to_string(Objective o) {
  for (const auto& [v, n] : kObjectives)
    if (v == o) return std::string(n);
  return "?";
}

double angle_error(double theta, double goal, bool sym) {
  const double period = sym ? M_PI : 2 * M_PI;
  double d = std::remainder(theta - goal, period);
  if (d <= -0.5 * period) d += period;
  return d;
}

double pose_cost(const Pose& p, const Pose& goal, double half_length, bool sym) {
  return std::hypot(p.x - goal.x, p.y - goal.y) + half_length * std::fabs(angle_error(p.theta, goal.theta, sym));
}

Scene push_scene(const Scene& scene, const Pose& from, const PlannedPush& p) {
  if (!scene.document) throw InputError("scene", scene.name, "has no document to replay pushes from");
  toml::table doc = *scene.document;
  toml::table push;
  push.insert_or_assign("mode", "tip");
  doc.insert_or_assign("push", push);
  toml::table t;
  t.insert_or_assign("start_x", p.start_x);
  t.insert_or_assign("start_y", p.start_y);
  t.insert_or_assign("direction", p.direction);
  t.insert_or_assign("speed", p.speed);
  t.insert_or_assign("travel", p.travel);
  t.insert_or_assign("radius", scene.push_mode == PushMode::tip ? scene.tip.radius : tip::TipPath{}.radius);
  t.insert_or_assign("mu", scene.push_mode == PushMode::tip ? scene.tip.mu : 0.0);
  doc.insert_or_assign("tip", t);
  toml::table init;
  init.insert_or_assign("x", from.x);
  init.insert_or_assign("y", from.y);
  init.insert_or_assign("theta", from.theta);
  doc.insert_or_assign("initial", init);
  if (toml::table* s = doc["solver"].as_table()) {
    for (const char* k : {"t_end", "method", "engine", "precision", "h0", "hmax"}) s->erase(k);
  }
  doc.erase("sweep");
  return scene_from_document(doc, scene.name);
}

void check_tip_mu_range(double lo, double hi) {
  if (!(lo == -1 && hi == -1) && !(lo >= 0 && lo <= hi && hi <= 10))
    throw InputError("--tip-mu-range", fmt(lo) + ":" + fmt(hi), "must be LO:HI with 0 <= LO <= HI <= 10");
}

void check_plan_task(const Scene& scene, const Pose& goal, const PlanOptions& o) { detail::check_task(scene, goal, o); }

PlanResult plan_pushes(const Scene& scene, const Pose& goal, const PlanOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  detail::check_task(scene, goal, o);
  const BarGeometry& g = scene.geometry;
  const double L = 2 * std::max(g.a, g.b);
  tip::TipPath base = scene.push_mode == PushMode::tip ? scene.tip : tip::TipPath{};
  const double muN = scene.friction_limit();
  const double rtol = std::max(scene.solver.rtol, 1e-10);
  const bool sym = o.half_turn_symmetric;
  const double half = 0.5 * L;

  PlanResult res;
  res.start = {scene.initial[kX], scene.initial[kY], scene.initial[kTheta]};
  res.goal = goal;
  res.options = o;

  // Candidates: the long faces at offsets across their length (off-centre pushes turn the bar
  // about the iCOR of chapters 4-5, central ones translate it), the short faces at three.
  std::vector<Candidate> cands;
  const bool long_y = g.b >= g.a;  // the faces x' = +-a are the long ones
  for (int f = 0; f < 4; ++f) {
    const bool long_face = (f < 2) == long_y;
    const std::vector<double> offs = long_face ? std::vector<double>{-0.9, -0.7, -0.5, -0.3, -0.15, 0.0, 0.15, 0.3, 0.5, 0.7, 0.9}
                                               : std::vector<double>{-0.5, 0.0, 0.5};
    for (double s : offs) cands.push_back({f, s});
  }

  // The worlds the plan must reach the goal in: the model's first, then (robust planning) the
  // others. Every candidate push is the model world's (its tip path in world axes), run in each.
  std::vector<World> worlds = make_worlds(scene, res.start, o);
  auto worst_cost = [&](const std::vector<World>& ws) {
    double c = 0;
    for (const World& w : ws) c = std::max(c, pose_cost(w.pose, goal, half, sym));
    return c;
  };
  auto all_within = [&](const std::vector<World>& ws) {
    return std::all_of(ws.begin(), ws.end(), [&](const World& w) { return within(w.pose, goal, o); });
  };
  double cost = worst_cost(worlds);
  const int samples = 241;
  std::vector<std::vector<tip::TipRow>> other(worlds.size());  // the other worlds' runs of a candidate
  while (static_cast<int>(res.pushes.size()) < o.max_pushes && !all_within(worlds)) {
    const Pose& pose = worlds.front().pose;
    const double dist = std::hypot(pose.x - goal.x, pose.y - goal.y);
    // The tip starts clear of the bar in every world: back by how far the worlds' bars stand
    // from the model's (0 with one world).
    double spread = 0;
    for (const World& w : worlds)
      spread = std::max(spread, std::hypot(w.pose.x - pose.x, w.pose.y - pose.y) +
                                    half * std::fabs(angle_error(w.pose.theta, pose.theta, false)));
    const double clearance = o.clearance + spread;
    const double travel_max = clearance + dist + half * std::fabs(angle_error(pose.theta, goal.theta, sym)) + 0.5 * L;
    struct Best {
      double score = std::numeric_limits<double>::infinity();
      double cost = 0;
      PlannedPush push;
    } best;
    for (const Candidate& c : cands) {
      tip::TipPath path = base;
      path.mu = worlds.front().tip_mu;
      const detail::Trial tr = detail::trial_push(g, muN, path, pose, c.face, c.offset, clearance, travel_max, samples, rtol);
      if (!tr.ok) continue;
      ++res.forward_runs;
      bool all_ran = true;
      for (std::size_t w = 1; w < worlds.size() && all_ran; ++w) {
        tip::TipPath pw = tr.path;
        pw.mu = worlds[w].tip_mu;
        const Pose& q = worlds[w].pose;
        try {
          other[w] = tip::run_quasi_static(g, muN, pw, q.x, q.y, q.theta, 0.0, samples, rtol).rows;
          all_ran = other[w].size() == tr.rows.size();
        } catch (const std::runtime_error&) {  // InputError: the tip would start inside the bar there; SolverError: no answer
          all_ran = false;
        }
        ++res.forward_runs;
      }
      if (!all_ran) continue;  // a push that cannot be made in every world is not robust
      double max_force = 0;
      for (std::size_t i = 0; i < tr.rows.size(); ++i) {
        const tip::TipRow& r = tr.rows[i];
        max_force = std::max(max_force, std::hypot(r.tip_fx, r.tip_fy));
        if (!detail::pushed(r)) continue;
        const Pose q{r.x, r.y, r.theta};
        double cq = pose_cost(q, goal, half, sym);
        bool reached = within(q, goal, o);
        for (std::size_t w = 1; w < worlds.size(); ++w) {
          const tip::TipRow& rw = other[w][i];
          const Pose qw{rw.x, rw.y, rw.theta};
          cq = std::max(cq, pose_cost(qw, goal, half, sym));
          reached = reached && within(qw, goal, o);
          max_force = std::max(max_force, std::hypot(rw.tip_fx, rw.tip_fy));
        }
        const double travel = tr.path.speed * r.t;
        double score = cq;
        const double gain = cost - cq;
        if (o.objective == Objective::travel || o.objective == Objective::time)
          score = gain > 0 ? -gain / travel : std::numeric_limits<double>::infinity();
        else if (o.objective == Objective::force)
          score = gain > 0 ? -gain / std::max(max_force, 1e-300) : std::numeric_limits<double>::infinity();
        if (reached) score = -std::numeric_limits<double>::infinity();  // reaches the goal: take it (shortest)
        const bool better = score < best.score || (score == best.score && travel < best.push.travel);
        if (better && cq < cost) {
          best.score = score;
          best.cost = cq;
          best.push = detail::push_at(tr, i);
        }
      }
    }
    if (!std::isfinite(best.cost) || best.push.travel <= 0 || best.cost > cost * (1 - 1e-6)) break;  // no push helps
    // The pose the push leaves is the scene's own forward run of it (what verification and a
    // user replaying plan.csv compute), not the trial's sample: the next push is planned from
    // there, so the plan and its replay are one computation. (The two agree to ~rtol, but a
    // push near the centre of a face with a frictionless tip amplifies such differences.)
    bool made = true;
    for (World& w : worlds) {
      try {
        const Trajectory tr = run_scene(push_scene(w.scene, w.pose, best.push));
        const auto& r = tr.rows.back();
        w.pose = {r[col::x], r[col::y], r[col::theta]};
      } catch (const std::exception&) {
        made = false;  // cannot happen for a push the trials ran; stop with the plan so far
        break;
      }
      ++res.forward_runs;
    }
    if (!made) break;
    best.push.end = worlds.front().pose;
    res.pushes.push_back(best.push);
    cost = worst_cost(worlds);
  }

  detail::verify(scene, res, o);
  if (o.robust()) verify_worlds(worlds, res, o);
  res.planning_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace nanopush::plan
