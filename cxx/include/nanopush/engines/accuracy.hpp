// The error of an answer, and answers to the accuracy asked for (docs/accuracy.md).
//
// The estimate: the same scene run again at a tolerance RHO times tighter (the companion),
// by the same engine and method where the method reaches that tolerance (dop853 hands over to
// the modern Bulirsch-Stoer below its floor; a smooth scene at the floor of double goes to
// long or quad precision). The difference of the two answers estimates the error of the looser
// one; it is honest while the companion's own error is well below it, which a factor RHO buys
// on every scene we measured (tests/test_accuracy.cpp, bench accuracy).
#pragma once
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush {

/// How much tighter the companion run is than the run it checks.
inline constexpr double kCompanionFactor = 100.0;

/// The accuracy norm (docs/accuracy.md) of the pose difference between two rows, positions
/// over `length_scale` [m], angle in rad: max(|dx|, |dy|) / length_scale, |dtheta|.
double pose_error_norm(const TrajectoryRow& a, const TrajectoryRow& b, double length_scale);

/// The error estimate of `answer` from a `reference` run of the same scene at a tighter
/// tolerance (same output times). Not available (note says why) when the reference is
/// incomplete or sampled differently.
ErrorEstimate estimate_from(const Scene& scene, const Trajectory& answer, const Trajectory& reference);

/// The settings of the companion of a run resolved as `s` (rtol / kCompanionFactor, method or
/// precision changed where the floor of the method is reached). `note` tells what changed and
/// whether the companion could not be tighter than the run (then the estimate is a lower bound).
ResolvedSettings companion_settings(const Scene& scene, const ResolvedSettings& s, std::string& note);

/// A run resolved as `s` with its error estimated when s.error_estimate (the companion's cost
/// in error.nfcn). Never throws for a failed run (finish_run does).
Trajectory run_estimated(const Scene& scene, const ResolvedSettings& s);

/// Runs at tighter and tighter rtol (from the accuracy E asked for, by kCompanionFactor each)
/// until two successive answers differ by <= E in the accuracy norm; the answer is the tighter
/// of the two, its estimate their difference. Outcome accuracy_not_reached (with the best
/// answer and estimate) when the floor of the method or a failure stops it first.
Trajectory run_to_accuracy(const Scene& scene, const RunSettings& settings);

}  // namespace nanopush
