// The C++ engine: run a scene and collect the trajectory. (The F77 engine, and the choice
// between the two, is the engines layer: nanopush/engines/engines.hpp.)
#pragma once
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "nanopush/numerics/bulirsch_stoer.hpp"
#include "nanopush/models/rigid_body.hpp"
#include "nanopush/numerics/scalar.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/scenes/choices.hpp"
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
/// The columns of a TrajectoryRow by name: row[col::fx] (the order of trajectory_columns()).
namespace col {
inline constexpr std::size_t t = 0, x = 1, y = 2, theta = 3, vx = 4, vy = 5, omega = 6, fx = 7, fy = 8, mf = 9;
}

/// method auto: dop853 for rtol >= this (where dop853 runs), modern below (docs/dop853.md).
inline constexpr double kAutoDop853RtolMin = 1e-11;

/// What a run asks for. Every choice left unset is the scene's (its solver.engine,
/// solver.method, surface.law, solver.precision); resolve_settings fills them in and validates
/// the combination. Front ends read names with parse_optional_choice (choices.hpp).
struct RunSettings {
  std::optional<Engine> engine;  ///< cxx | f77 (run_scene: always cxx)
  /// faithful (C++ BS, the F77 engine's steps; f77 is always the thesis algorithm) | modern |
  /// dop853 (Dormand-Prince 8(5,3) with dense output, double; smooth scenes and the thesis
  /// law: docs/dop853.md) | cvode (SUNDIALS CVODE cross-check, rough scenes under the
  /// coulomb law only) | automatic (by rtol)
  std::optional<Method> method;
  std::optional<Law> law;  ///< rough scenes: thesis | printed | coulomb
  /// Return what was computed when the integrator gives up (status in stats) instead of
  /// throwing; used to show where the thesis law chatters.
  bool allow_partial = false;
  double rtol = 0;                  ///< 0 = the scene's
  double atol = -1;                 ///< < 0 = the scene's (0 = automatic scaling)
  /// Scalar of the integration: double | long (x87 80-bit long double) | quad (__float128).
  /// long and quad need engine cxx, method faithful or modern, on a smooth scene (the
  /// right-hand side templated on the scalar); each costs more wall time per RHS call
  /// (docs/scenes.md).
  std::optional<Precision> precision;
  /// Called at each output sample with the fraction done (for progress display).
  std::function<void(double)> progress;
};

/// RunSettings resolved against a scene: every choice made (method automatic replaced by the
/// method it picks), rtol and atol filled in, the combination validated.
struct ResolvedSettings {
  Engine engine = Engine::cxx;
  Method method = Method::faithful;
  Law law = Law::thesis;
  Precision precision = Precision::double_;
  bool allow_partial = false;
  double rtol = 0, atol = 0;
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

/// The C++ engine on settings already resolved (no finish_run: a failed run is returned as is).
Trajectory run_cxx(const Scene& scene, const ResolvedSettings& resolved);

/// The end of every engine's run: a failed run is marked incomplete and throws SolverError
/// unless `resolved.allow_partial`.
Trajectory finish_run(const Scene& scene, const ResolvedSettings& resolved, Trajectory tr);

/// One trajectory row from a state y (kX..kOmega) and the friction wrench at it.
TrajectoryRow make_row(double t, const double* y, const WorldWrench& f = {});

/// The rough-surface model of a rough scene (mass, inertia, contact, mu N, push).
RoughBarModel rough_model(const Scene& scene);

/// Settings as resolved against the scene (choices, rtol and atol filled in and validated);
/// InputError naming the field a bad value came from.
ResolvedSettings resolve_settings(const Scene& scene, const RunSettings& settings);

}  // namespace nanopush
