// The C++ engine: run a scene and collect the trajectory. (The F77 engine, and the choice
// between the two, is the engines layer: nanopush/engines/engines.hpp.)
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "nanopush/numerics/bulirsch_stoer.hpp"
#include "nanopush/models/rigid_body.hpp"
#include "nanopush/numerics/scalar.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/scenes/scene.hpp"

namespace nanopush {

/// Columns of every trajectory: t, x, y, theta, vx, vy, omega, fx, fy, mf (SI, world axes).
inline const std::vector<std::string>& trajectory_columns() {
  static const std::vector<std::string> c = {"t", "x", "y", "theta", "vx", "vy", "omega", "fx", "fy", "mf"};
  return c;
}
inline const std::vector<std::string>& trajectory_units() {
  static const std::vector<std::string> u = {"s", "m", "m", "rad", "m/s", "m/s", "rad/s", "N", "N", "N m"};
  return u;
}
using TrajectoryRow = std::array<double, 10>;

/// method auto: dop853 for rtol >= this (where dop853 runs), modern below (docs/dop853.md).
inline constexpr double kAutoDop853RtolMin = 1e-11;

struct RunSettings {
  /// Every choice left empty is the scene's (its solver.engine, solver.method, surface.law,
  /// solver.precision); resolve_settings fills them in and validates the combination.
  std::string engine;     ///< cxx | f77; "" = the scene's (run_scene: always cxx)
  /// faithful | modern (C++ BS; f77 is always the thesis algorithm) | dop853 (Dormand-Prince
  /// 8(5,3) with dense output, double; smooth scenes and the thesis law: docs/dop853.md) |
  /// cvode (SUNDIALS CVODE cross-check, rough scenes under the coulomb law only) | auto (by
  /// rtol); "" = the scene's
  std::string method;
  /// Rough scenes: friction law override ("" = the scene's): thesis | printed | coulomb
  std::string law;
  /// Return what was computed when the integrator gives up (status in stats) instead of
  /// throwing; used to show where the thesis law chatters.
  bool allow_partial = false;
  double rtol = 0;                  ///< 0 = the scene's
  double atol = -1;                 ///< < 0 = the scene's (0 = automatic scaling)
  /// Scalar of the integration: double | long (x87 80-bit long double) | quad (__float128);
  /// "" = the scene's solver.precision. long and quad need engine cxx, method faithful or
  /// modern, on a smooth scene (the right-hand side templated on the scalar); each costs
  /// more wall time per RHS call (docs/scenes.md).
  std::string precision;
  /// Called at each output sample with the fraction done (for progress display).
  std::function<void(double)> progress;
};

struct StickEventRecord {
  double t;
  bool stuck;
};

struct Trajectory {
  std::string engine_label;  ///< e.g. "cxx-faithful", "f77", "cxx-faithful-coulomb", "cxx-modern-quad"
  std::string precision = "double";  ///< scalar of the integration: double | long | quad
  std::vector<TrajectoryRow> rows;   ///< always double (extended-precision states rounded)
  /// Extended-precision runs (precision long or quad): the state x, y, theta, vx, vy, omega
  /// at each output in the scalar of the integration, widened exactly to __float128 (rows
  /// holds the same values rounded to double). Empty for double runs.
  std::vector<std::array<num::quad, kStateSize>> extended;
  BsResult stats;
  double rtol = 0;
  std::vector<double> atol;
  /// Rough scenes: work of the push and of friction from t = 0 to each sample [J].
  std::vector<double> work_push, work_fric;
  std::vector<StickEventRecord> events;  ///< coulomb law: instants the body came to rest
  bool complete = true;                  ///< false when allow_partial kept a failed run
};

/// Integrate the scene with the C++ engine. Throws SolverError when the integrator fails
/// (status and time in the message); InputError for bad settings, and for engine "f77"
/// (nanopush::engines runs that one: run_engine).
Trajectory run_scene(const Scene& scene, const RunSettings& settings = {});

/// The end of every engine's run: a failed run is marked incomplete and throws SolverError
/// unless `resolved.allow_partial`.
Trajectory finish_run(const Scene& scene, const RunSettings& resolved, Trajectory tr);

/// One trajectory row from a state y (kX..kOmega) and the friction wrench at it.
TrajectoryRow make_row(double t, const double* y, const WorldWrench& f = {});

/// The rough-surface model of a rough scene (mass, inertia, contact, mu N, push).
RoughBarModel rough_model(const Scene& scene);

/// Settings as resolved against the scene (engine/method/rtol/atol defaults filled in).
RunSettings resolve_settings(const Scene& scene, RunSettings s);

}  // namespace nanopush
