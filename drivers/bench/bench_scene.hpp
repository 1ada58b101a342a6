// The benchmark of one scene (issue 7): problem, reference and engines from a Scene.
//
// Adding a surface model (rough scenes, issue 4) means one more branch in make_bench()
// (drivers/bench/bench_scene.cpp): build its RHS (templated on the scalar, as SmoothBarRhs),
// take the extended-precision reference (run_extended_reference<6>) and the generic
// engines (generic_engines<6>); optionally scene-specific engines (an F77 RHS, an
// event-locating integrator). The harness, CSV and plots need no change.
#pragma once
#include <string>
#include <vector>

#include "bench/bench.hpp"
#include "bench/bench_engines.hpp"
#include "nanopush/scenes/scene.hpp"

namespace nanopush::bench {

/// The scene as an initial-value problem: state (x, y, theta, vx, vy, omega) in SI, the
/// scene's output times, scales = Scene::state_scales().
Problem problem_from_scene(const Scene& sc);

/// True when the scene has a closed-form solution the harness knows (smooth surface, no
/// initial rotation rate: the pendulum of docs/models.md §A).
bool has_exact_solution(const Scene& sc);

/// The exact trajectory of a smooth-surface scene at the output times, in __float128:
/// constant acceleration in x, y and the pendulum (Jacobi sn by the AGM) in theta, omega,
/// with theta* and the torque amplitude computed in quad from the push point.
std::vector<quad> smooth_exact(const Scene& sc, const Problem& p);

/// The C++ BS on the scene's RHS in __float128 (modern or faithful) at rtol: an
/// independent extended-precision run, used to check a reference.
Solve extended_run(const Scene& sc, const Problem& p, double rtol, bool modern);

struct Bench {
  Problem problem;
  Reference reference;
  std::vector<Engine> engines;
};

/// Every engine `cfg` selects for this scene. The smooth scene adds `f77-native`
/// (np_f77_bsint_smooth_bar: the F77 RHS called from F77).
Bench make_bench(const Scene& sc, const EngineConfig& cfg);

/// Names of every engine make_bench can build for a scene of this model (CSV order).
std::vector<std::string> engine_names(const Scene& sc);

}  // namespace nanopush::bench
