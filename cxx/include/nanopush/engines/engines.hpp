// The engines layer: a scene run by either engine, the C++ solver or the FORTRAN 77
// reproduction, side by side. The only C++ of the library that knows the F77 code.
#pragma once
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush {

/// Integrate the scene with the engine `settings.engine` names (cxx | f77; unset = the
/// scene's solver.engine). Same contract as run_scene: SolverError on failure (unless allow_partial),
/// InputError for bad settings.
Trajectory run_engine(const Scene& scene, const RunSettings& settings = {});

/// The engine `resolved.engine` on settings already resolved, the outcome classified
/// (finish_run with allow_partial): never throws for a failed run.
/// Method auto hands a stiff start (a failure before the first output: a push just outside the
/// limit surface) of the coulomb or thesis law over to CVODE's coulomb-law integration
/// (Trajectory::handed_over says so).
Trajectory run_resolved(const Scene& scene, const ResolvedSettings& resolved);

/// The settings a handed-over run used (method cvode, law coulomb): its companions' settings.
void handed_over_settings(ResolvedSettings& s);

/// The F77 engine alone (BSINT with the F77 right-hand sides); `resolved` from resolve_settings.
Trajectory run_f77(const Scene& scene, const ResolvedSettings& resolved);

}  // namespace nanopush
