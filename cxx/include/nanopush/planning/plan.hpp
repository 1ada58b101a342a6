// Push planning (docs/planning.md): a sequence of straight tip pushes that brings a bar from a
// scene's initial pose to a goal pose, planned through the quasi-static tip model
// (models/tip_push.hpp) and verified push by push, and end to end, by forward runs of the
// scene (run_scene with push.mode = tip).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "nanopush/scenes/scene.hpp"

namespace nanopush::plan {

/// A goal pose (world axes): CM position [m] and orientation [rad].
struct Pose {
  double x = 0, y = 0, theta = 0;
};

/// What the plan minimises besides reaching the goal: the number of pushes, the tip's travel,
/// the time (travel / speed: the same ranking as travel at one speed) or the largest tip force.
enum class Objective { pushes, travel, time, force };
Objective parse_objective(const std::string& text);  ///< InputError naming --objective
std::string to_string(Objective o);

struct PlanOptions {
  double tolerance_distance = 1e-9;  ///< [m] |CM - goal|
  double tolerance_angle = 0.01;     ///< [rad] |theta - goal|
  Objective objective = Objective::pushes;
  int max_pushes = 10;
  /// The bar is symmetric under a half turn: theta and theta + pi are the same placement
  /// (false: the ends are told apart).
  bool half_turn_symmetric = true;
  double clearance = 2e-9;  ///< gap between tip and bar where each push starts [m]
  /// Robust planning (docs/planning.md, "Robust plans"): the plan is chosen so that it reaches
  /// the goal in every world of a set, not only in the model's: the tip friction at both ends
  /// of [robust_tip_mu_lo, robust_tip_mu_hi] (lo < 0: the model's only) and the start pose
  /// shifted by +-robust_start.x, +-y, +-theta, one component at a time (0: not shifted).
  double robust_tip_mu_lo = -1, robust_tip_mu_hi = -1;
  double robust_start_x = 0, robust_start_y = 0, robust_start_theta = 0;
  [[nodiscard]] bool robust() const {
    return robust_tip_mu_lo >= 0 || robust_start_x > 0 || robust_start_y > 0 || robust_start_theta > 0;
  }
};

/// One planned push: the tip keys of the scene (tip.start_x, tip.start_y, tip.direction,
/// tip.speed, tip.travel) and the pose it leaves.
struct PlannedPush {
  double start_x = 0, start_y = 0, direction = 0, speed = 0, travel = 0;
  Pose end;
  std::string face;       ///< which side of the bar was pushed ("-x'", "+x'", "-y'", "+y'")
  double offset = 0;      ///< contact offset along the face, as a fraction of its half-length
  double max_force = 0;   ///< largest tip force during the push [N]
  double verified_deviation = -1;  ///< forward run's end pose vs the plan, in the goal norm (< 0: not run)
};

/// A plan's outcome: found (the plan reaches the goal within the tolerance), or not_found
/// (the best plan found is kept).
enum class PlanStatus { found, not_found };
/// A closed loop's outcome: reached (the true pose within tolerance), or not_reached.
enum class LoopStatus { reached, not_reached };

struct PlanResult {
  PlanStatus status = PlanStatus::not_found;
  std::string message;
  Pose start, goal;
  std::vector<PlannedPush> pushes;
  Pose final_pose;          ///< end to end, by forward runs from the start
  double final_distance = 0;  ///< |CM - goal| [m]
  double final_angle = 0;     ///< |theta - goal| [rad] (modulo pi if half-turn symmetric)
  bool verified = false;      ///< every push re-run matches, and the chain ends within tolerance
  double tip_travel = 0;      ///< summed over pushes [m]
  double time = 0;            ///< summed push durations [s]
  long forward_runs = 0;      ///< model runs the search took
  /// Robust planning: each world the plan was chosen for (the model's first) and where the
  /// plan, replayed end to end in it, leaves the bar. Empty unless options.robust().
  struct World {
    double tip_mu = 0;
    Pose start, final_pose;
    double final_distance = 0, final_angle = 0;
    bool reached = false;
  };
  std::vector<World> worlds;
  PlanOptions options;        ///< what the plan was asked for (tolerance, symmetry, ...)
  double planning_seconds = 0;
  [[nodiscard]] bool found() const { return status == PlanStatus::found; }
};

/// The angle error theta - goal wrapped to (-pi, pi], or to (-pi/2, pi/2] when half-turn symmetric.
double angle_error(double theta, double goal, bool half_turn_symmetric);

/// The distance a bar is from a pose, as the planner measures it: |dr| + (L/2) |dtheta| [m]
/// (how far the bar's ends are from where they should be).
double pose_cost(const Pose& p, const Pose& goal, double half_length, bool half_turn_symmetric);

/// Plan pushes for the bar of `scene` (a rough surface; its tip keys, when push.mode = tip,
/// give the tip's radius, speed and friction, else 10 nm, 1 um/s, 0) from the scene's initial
/// pose to `goal`. Throws InputError for bad input (a smooth surface, a tolerance below what
/// the model resolves, max_pushes < 1).
PlanResult plan_pushes(const Scene& scene, const Pose& goal, const PlanOptions& options);

/// How far a goal may lie from the bar's start, in bar lengths (InputError naming --goal beyond).
inline constexpr double kGoalReach = 1e6;

/// A range of tip friction coefficients, [lo, hi] with 0 <= lo <= hi <= 10, or -1:-1 for none
/// (the sentinel of PlanOptions and CheckWorlds): anything else, a negative end included, is
/// InputError naming --tip-mu-range, never read as "none".
void check_tip_mu_range(double lo, double hi);

/// The checks of the task that plan_pushes makes first (the scene, the goal within reach, the
/// tolerance, the robust worlds): InputError naming the option. For a front end that checks
/// every option before any work.
void check_plan_task(const Scene& scene, const Pose& goal, const PlanOptions& options);

/// The baseline a lab uses (target-oriented pushing, docs/planning.md): turn the bar by
/// off-centre pushes until a long face's normal points at the goal, push through the centre
/// towards it, then turn to the goal orientation by off-centre pushes; repeat. Each push's
/// travel is where the model says the push's aim is best met. Same task checks, outputs and
/// verification as plan_pushes.
PlanResult plan_baseline(const Scene& scene, const Pose& goal, const PlanOptions& options);

/// Pose noise of the imaging in the closed loop: standard deviations (m, m, rad).
struct Noise {
  double x = 0, y = 0, theta = 0;
};

/// One step of the closed loop: what was seen, the push made, where the bar truly went.
struct LoopStep {
  Pose observed;        ///< the image: the true pose plus noise
  Pose truth;           ///< the true pose when the image was taken
  PlannedPush push;     ///< the push made (its `end` is what the model predicted)
  int plan_pushes = 0;  ///< pushes the re-plan needed from this image
  double tip_mu = -1;   ///< the model's tip friction this push was planned with (< 0: not a tip scene)
};

struct ClosedLoopResult {
  LoopStatus status = LoopStatus::not_reached;
  std::string message;
  std::vector<LoopStep> steps;
  Pose final_truth, final_observed;
  double final_distance = 0, final_angle = 0;  ///< of the true pose from the goal
  double tip_travel = 0, time = 0, planning_seconds = 0;
  /// Planned pushes not made: the tip would start inside the true bar, or the model could not
  /// follow the push on it (a solver failure); the bar was imaged again instead.
  int unsimulated = 0;
  double tip_mu = -1;  ///< the model's tip friction at the end (the last fit; < 0: not a tip scene)
  [[nodiscard]] bool reached() const { return status == LoopStatus::reached; }
};

/// How the closed loop learns what the model does not know. The quasi-static path depends on the
/// tip's friction and not on the surface's mu (which scales every force), so what is re-fitted
/// is tip.mu: after each push, the value in [0, mu_max] whose model predicts best the images
/// seen after the pushes made so far (the last `window`), each from the image before it
/// (fit_tip_mu).
struct Refit {
  bool enabled = true;
  double mu_max = 1.0;
  int window = 6;
};

/// One push seen by the loop: the image before it, the push made, the image after it.
struct SeenPush {
  Pose before, after;
  PlannedPush push;
};

/// The tip friction in [0, mu_max] that minimises the sum over `seen` of the squared
/// differences between the model's end pose of each push (from the image before it, the
/// model's tip.mu replaced) and the image after it, each component over its noise (or, without
/// noise, over a thousandth of the tolerance): a coarse scan of 9 values then Brent's method
/// (Boost.Math) in the best bracket. A push the model cannot make at some mu costs that mu a
/// large penalty. Returns `current` when `seen` is empty or the model is not a tip scene.
double fit_tip_mu(const Scene& model, const std::vector<SeenPush>& seen, const Noise& noise, const PlanOptions& options,
                  double current, double mu_max);

/// The AFM loop a lab runs: image the bar (the truth's pose plus seeded Gaussian noise), plan
/// from the image with the model scene, make the plan's first push on the truth scene (the tip
/// path in world axes, as an AFM would), image again; until the image is within tolerance and
/// stays so, or max_pushes pushes were made. `truth` is the model scene with what the model
/// does not know changed (tip friction, the bar's size, ...).
/// With `refit` enabled and a tip scene, the model's tip.mu is re-fitted after every push
/// (fit_tip_mu) and the next plan made with it.
ClosedLoopResult closed_loop(const Scene& model, const Scene& truth, const Pose& goal, const PlanOptions& options,
                             const Noise& noise, std::uint64_t seed, const Refit& refit = {});

/// How often an open-loop plan succeeds when the world is not the model's (plan --check).
struct PlanCheck {
  int trials = 0, successes = 0;
  double probability = 0;            ///< successes / trials
  double low = 0, high = 0;          ///< 95 % Wilson interval of the probability
  std::vector<double> final_distance, final_angle;  ///< per trial, of the true end pose from the goal
};

/// Monte Carlo over `trials` worlds: the bar starts at the plan's start plus seeded noise, the
/// surface's mu is uniform in [mu_lo, mu_hi] (mu_lo = mu_hi = 0: the scene's), and the plan's
/// pushes are made open loop (the tip paths fixed in world axes). A trial succeeds when the bar
/// ends within the tolerance. A push that cannot start (the tip would touch down on the bar), or
/// that the model cannot follow, fails its trial. The trials run through the sweep engine on
/// `jobs` threads (0: every core; planning/check.hpp), each from its own random stream, so the
/// result does not depend on `jobs`.
PlanCheck check_plan(const Scene& scene, const PlanResult& plan, const PlanOptions& options, const Noise& noise,
                     int trials, double mu_lo, double mu_hi, std::uint64_t seed, unsigned jobs = 0);

/// The scene that replays push `p` from pose `from` (push.mode = tip and the push's tip keys).
Scene push_scene(const Scene& scene, const Pose& from, const PlannedPush& p);

}  // namespace nanopush::plan

namespace nanopush {
NANOPUSH_NAMES(plan::PlanStatus, {plan::PlanStatus::found, "found"}, {plan::PlanStatus::not_found, "not_found"});
NANOPUSH_NAMES(plan::LoopStatus, {plan::LoopStatus::reached, "reached"}, {plan::LoopStatus::not_reached, "not_reached"});
}  // namespace nanopush
