// plan --check through the sweep engine (docs/planning.md, "Checking a plan"): the Monte Carlo
// over worlds that are not the model's is a sweep whose points are trials, so it runs on
// threads, across MPI ranks, resumes from its journal and writes its table like any sweep.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>

#include "nanopush/planning/plan.hpp"
#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::plan {

/// What the worlds of a check draw from: trial k's start pose is the plan's start plus
/// Gaussian noise, its surface mu uniform in [mu_lo, mu_hi] (both 0: the scene's) and its tip
/// friction uniform in [tip_mu_lo, tip_mu_hi] (lo < 0: the scene's), in that order, from the
/// trial's own random stream (seed, k), so a trial is the same on whichever thread or rank
/// computes it.
struct CheckWorlds {
  Noise noise;
  double mu_lo = 0, mu_hi = 0;
  std::uint64_t seed = 0;
  double tip_mu_lo = -1, tip_mu_hi = -1;  ///< the tip's friction uniform in [lo, hi] (lo < 0: the scene's)
};

/// The worlds `w` checked against `scene` (the noise finite and >= 0, the friction ranges, a
/// tip range on a tip scene): InputError naming --noise, --mu-range or --tip-mu-range. The
/// task below checks them too; a command checks them before it plans.
void check_worlds(const Scene& scene, const CheckWorlds& w);

/// The points of a check: one axis `trial` = 1 .. trials (a grid: nothing stored per trial).
/// InputError (naming --check) outside [1, 1000000].
sweep::Plan check_points(int trials);

/// The task of a check: at trial k, the plan's pushes made open loop in world k (the tip paths
/// fixed in world axes). Outputs: the world (start pose, mu), the pushes made, the true end
/// pose, its distance and angle from the goal and `success` (1 within the tolerance). A push
/// that cannot be made there (the tip would start inside the bar, or the model cannot follow
/// it) ends the trial unsuccessful, its message says which push and why (status ok: the plan
/// failing in a world is an answer). InputError for bad noise or mu range.
std::unique_ptr<sweep::Task> make_check_task(const Scene& scene, const PlanResult& plan, const PlanOptions& options,
                                             const CheckWorlds& worlds);

/// The success count and its 95 % Wilson interval from a check's table (a sweep table with the
/// columns `success`, `final_distance`, `final_angle`); InputError naming the file if it is not
/// one.
PlanCheck read_check_table(const std::filesystem::path& table);

/// check_plan over the worlds `w` (surface and tip friction ranges, start noise, seed).
PlanCheck check_plan(const Scene& scene, const PlanResult& plan, const PlanOptions& options, const CheckWorlds& w,
                     int trials, unsigned jobs = 0);

/// Fill probability, low and high of `c` from its trials and successes (95 % Wilson interval).
void wilson_interval(PlanCheck& c);

}  // namespace nanopush::plan
