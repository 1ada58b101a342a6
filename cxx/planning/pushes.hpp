// What the planners share (internal to the planning layer): the faces of the bar, the tip's
// start for a push on a face, and one trial push by the quasi-static model.
#pragma once
#include <cmath>
#include <random>
#include <vector>

#include "nanopush/models/tip_push.hpp"
#include "nanopush/planning/plan.hpp"

namespace nanopush::plan::detail {

/// A side of the bar in body axes, with the inward normal the tip pushes along.
struct Face {
  const char* name;
  double nx, ny;
};
inline constexpr Face kFaces[] = {{"-x'", 1, 0}, {"+x'", -1, 0}, {"-y'", 0, 1}, {"+y'", 0, -1}};

/// A push on face `face` at `offset` (fraction of the face's half-length), run by the
/// quasi-static model with travel `travel_max` from pose `from`: its tip path and the outputs
/// (rows after the contact is made are the push's possible stopping points).
struct Trial {
  bool ok = false;
  int face = 0;
  double offset = 0;
  tip::TipPath path;
  std::vector<tip::TipRow> rows;
};
Trial trial_push(const BarGeometry& g, double muN, const tip::TipPath& tip, const Pose& from, int face, double offset,
                 double clearance, double travel_max, int samples, double rtol);

/// The push that stops trial `t` at output row `i`.
PlannedPush push_at(const Trial& t, std::size_t i);

/// Re-run each push of `res` as a scene (push_scene, run_scene) from the pose the previous
/// re-run left; fill each push's verified_deviation, the final pose and errors, the travel and
/// time, `verified` and the status (found when the chain ends within tolerance).
void verify(const Scene& scene, PlanResult& res, const PlanOptions& o);

/// The checks every planner makes of its task (InputError naming the option).
void check_task(const Scene& scene, const Pose& goal, const PlanOptions& o);

/// A standard normal from the generator's raw bits (Box-Muller on 53-bit uniforms): the same
/// numbers for a seed on every platform, unlike std::normal_distribution.
inline double standard_normal(std::mt19937_64& rng) {
  const double u1 = (static_cast<double>(rng() >> 11) + 1.0) * 0x1.0p-53;  // (0, 1]
  const double u2 = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2 * M_PI * u2);
}

/// True once the tip has touched the bar at or before row r.
inline bool pushed(const tip::TipRow& r) { return r.contact != tip::ContactMode::none || r.work_tip != 0; }

}  // namespace nanopush::plan::detail
