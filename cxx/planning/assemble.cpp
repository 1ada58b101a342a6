// Assembly (assemble.hpp; docs/planning.md): assignment, order and clearance around plan_pushes.
#include "nanopush/planning/assemble.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "nanopush/models/tip_push.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush::plan {

namespace {

// The tip's columns of a tip push's trajectory (docs/tip.md): t, x, y, theta, vx, vy, omega,
// fx, fy, mf, tip_x, tip_y, tip_fx, tip_fy, contact.
constexpr std::size_t kTipX = 10, kTipY = 11;
constexpr std::size_t kMaxBars = 20, kExactAssignment = 8;

std::string text(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::string pose_text(const Pose& p) { return "(" + text(p.x) + ", " + text(p.y) + ", " + text(p.theta) + ")"; }

double total_cost(const std::vector<Pose>& objects, const std::vector<Pose>& slots, const std::vector<int>& slot_of,
                  double half_length, bool sym) {
  double c = 0;
  for (std::size_t i = 0; i < objects.size(); ++i)
    c += pose_cost(objects[i], slots[static_cast<std::size_t>(slot_of[i])], half_length, sym);
  return c;
}

/// Why bar `i`'s replayed pushes are not clear of the others ("" when they are).
std::string clearance_problem(const Scene& dense, const PlanResult& r, std::size_t i, const std::vector<Pose>& poses,
                              double a, double b, double tip_radius, double gap) {
  Pose from = r.start;
  int k = 1;
  for (const PlannedPush& p : r.pushes) {
    const Trajectory tr = run_scene(push_scene(dense, from, p));
    for (const auto& row : tr.rows) {
      const Pose at{row[col::x], row[col::y], row[col::theta]};
      for (std::size_t j = 0; j < poses.size(); ++j) {
        if (j == i) continue;
        if (bars_overlap(at, poses[j], a, b, gap))
          return "push " + std::to_string(k) + " brings it within " + text(gap) + " m of bar " + std::to_string(j + 1);
        if (row.size() > kTipY && disc_touches_bar(row[kTipX], row[kTipY], tip_radius, poses[j], a, b, gap))
          return "the tip of push " + std::to_string(k) + " passes within " + text(gap) + " m of bar " +
                 std::to_string(j + 1);
      }
    }
    from = p.end;
    ++k;
  }
  return {};
}

void check_poses(const std::vector<Pose>& poses, const std::string& what, double a, double b, double gap) {
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Pose& p = poses[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.theta))
      throw InputError(what + " " + std::to_string(i + 1), pose_text(p), "must be three finite numbers x, y, theta");
    for (std::size_t j = 0; j < i; ++j)
      if (bars_overlap(p, poses[j], a, b, gap))
        throw InputError(what + " " + std::to_string(i + 1), pose_text(p),
                         "overlaps " + what + " " + std::to_string(j + 1) + " " + pose_text(poses[j]) +
                             " (bars must be at least " + text(gap) + " m apart)");
  }
}

}  // namespace

std::vector<int> assign_slots(const std::vector<Pose>& objects, const std::vector<Pose>& slots, double half_length,
                              bool sym) {
  const std::size_t n = objects.size();
  std::vector<int> best(n);
  std::iota(best.begin(), best.end(), 0);
  if (n <= kExactAssignment) {
    std::vector<int> perm = best;
    double least = total_cost(objects, slots, best, half_length, sym);
    while (std::next_permutation(perm.begin(), perm.end())) {
      const double c = total_cost(objects, slots, perm, half_length, sym);
      if (c < least) {
        least = c;
        best = perm;
      }
    }
    return best;
  }
  // Greedy: the cheapest remaining (object, slot) pair first.
  std::vector<bool> object_done(n), slot_done(n);
  for (std::size_t k = 0; k < n; ++k) {
    double least = std::numeric_limits<double>::infinity();
    std::size_t bi = 0, bs = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t s = 0; s < n; ++s)
        if (!object_done[i] && !slot_done[s]) {
          const double c = pose_cost(objects[i], slots[s], half_length, sym);
          if (c < least) least = c, bi = i, bs = s;
        }
    best[bi] = static_cast<int>(bs);
    object_done[bi] = slot_done[bs] = true;
  }
  // Pairwise exchanges while one lowers the sum.
  for (bool improved = true; improved;) {
    improved = false;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        auto cost = [&](std::size_t o, int s) { return pose_cost(objects[o], slots[static_cast<std::size_t>(s)], half_length, sym); };
        if (cost(i, best[j]) + cost(j, best[i]) < cost(i, best[i]) + cost(j, best[j]) - 1e-15) {
          std::swap(best[i], best[j]);
          improved = true;
        }
      }
  }
  return best;
}

bool bars_overlap(const Pose& p, const Pose& q, double a, double b, double gap) {
  const double ha = a + 0.5 * gap, hb = b + 0.5 * gap;
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double cp = std::cos(p.theta), sp = std::sin(p.theta), cq = std::cos(q.theta), sq = std::sin(q.theta);
  // Each rectangle's body axes x' = (c, s) and y' = (-s, c).
  const double axes[4][2] = {{cp, sp}, {-sp, cp}, {cq, sq}, {-sq, cq}};
  for (const auto& u : axes) {
    const double d = std::fabs(dx * u[0] + dy * u[1]);
    const double rp = ha * std::fabs(cp * u[0] + sp * u[1]) + hb * std::fabs(-sp * u[0] + cp * u[1]);
    const double rq = ha * std::fabs(cq * u[0] + sq * u[1]) + hb * std::fabs(-sq * u[0] + cq * u[1]);
    if (d >= rp + rq) return false;  // a separating axis
  }
  return true;
}

bool disc_touches_bar(double cx, double cy, double r, const Pose& p, double a, double b, double gap) {
  const double c = std::cos(p.theta), s = std::sin(p.theta), dx = cx - p.x, dy = cy - p.y;
  const double lx = c * dx + s * dy, ly = -s * dx + c * dy;  // in the bar's body axes
  const double ex = std::max(std::fabs(lx) - a, 0.0), ey = std::max(std::fabs(ly) - b, 0.0);
  return std::hypot(ex, ey) < r + gap;
}

AssemblyResult assemble(const Scene& scene, const std::vector<Pose>& objects, const std::vector<Pose>& slots,
                        const AssemblyOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (objects.empty()) throw InputError("objects", "(none)", "at least one bar to place");
  if (objects.size() > kMaxBars)
    throw InputError("objects", std::to_string(objects.size()) + " bars", "at most " + std::to_string(kMaxBars));
  if (slots.size() != objects.size())
    throw InputError("pattern", std::to_string(slots.size()) + " slots",
                     "must have one slot per bar (" + std::to_string(objects.size()) + ")");
  if (!(o.gap >= 0 && std::isfinite(o.gap))) throw InputError("--gap", text(o.gap), "must be >= 0 (m)");
  if (o.samples < 2 || o.samples > 100000) throw InputError("samples", std::to_string(o.samples), "must be in [2, 100000]");
  const double a = scene.geometry.a, b = scene.geometry.b, half_length = std::max(a, b);
  check_poses(objects, "bar", a, b, 0.0);
  check_poses(slots, "slot", a, b, o.gap);
  const bool sym = o.plan.half_turn_symmetric;
  const double tip_radius = scene.push_mode == PushMode::tip ? scene.tip.radius : tip::TipPath{}.radius;

  AssemblyResult res;
  res.slot_of = assign_slots(objects, slots, half_length, sym);
  res.assignment_cost = total_cost(objects, slots, res.slot_of, half_length, sym);
  std::vector<Pose> poses = objects;
  std::vector<bool> placed(objects.size(), false);
  Scene dense = scene;  // the replays that check clearance: samples along each push
  dense.set("solver.samples", o.samples);
  for (std::size_t round = 0; round < objects.size(); ++round) {
    // The unplaced bars, nearest to their slots first.
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < objects.size(); ++i)
      if (!placed[i]) order.push_back(i);
    auto cost_of = [&](std::size_t i) {
      return pose_cost(poses[i], slots[static_cast<std::size_t>(res.slot_of[i])], half_length, sym);
    };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return cost_of(i) < cost_of(j); });
    std::string why;
    bool moved = false;
    for (std::size_t i : order) {
      const Pose& slot = slots[static_cast<std::size_t>(res.slot_of[i])];
      Scene from = scene;
      from.set({{"initial.x", poses[i].x}, {"initial.y", poses[i].y}, {"initial.theta", poses[i].theta}});
      PlanResult r = plan_pushes(from, slot, o.plan);
      if (!r.found()) {
        why += "\n  bar " + std::to_string(i + 1) + ": no plan to slot " + std::to_string(res.slot_of[i] + 1) + ": " +
               r.message;
        continue;
      }
      const std::string problem = clearance_problem(dense, r, i, poses, a, b, tip_radius, o.gap);
      if (!problem.empty()) {
        why += "\n  bar " + std::to_string(i + 1) + ": " + problem;
        continue;
      }
      poses[i] = r.final_pose;
      placed[i] = true;
      res.moves.push_back({static_cast<int>(i), res.slot_of[i], std::move(r)});
      moved = true;
      break;
    }
    if (!moved) {
      res.message = "no remaining bar can be moved to its slot clear of the others:" + why;
      break;
    }
  }
  res.final_poses = poses;
  res.status = std::all_of(placed.begin(), placed.end(), [](bool p) { return p; }) ? AssemblyStatus::assembled : AssemblyStatus::not_found;
  res.planning_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace nanopush::plan
