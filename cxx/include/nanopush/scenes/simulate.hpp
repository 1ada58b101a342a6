// The C++ engine: run a scene and collect the trajectory. (The F77 engine, and the choice
// between the two, is the engines layer: nanopush/engines/engines.hpp.)
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
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
  /// Estimate the global error of the answer (a companion run, docs/accuracy.md); unset =
  /// the scene's solver.error_estimate. run_scene never estimates (the engines layer does).
  std::optional<bool> error_estimate;
  /// The error asked for (docs/accuracy.md): > 0 chooses rtol so that the estimated error of
  /// the final pose is <= accuracy; 0 = none (run at rtol); < 0 = the scene's solver.accuracy.
  double accuracy = -1;
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
  bool error_estimate = false;
  double accuracy = 0;  ///< 0 = none
  bool method_automatic = false;  ///< the method was chosen by auto (run_resolved may hand over)
};

/// How a run ended (docs/errors.md), beside the integrator's own status (stats.status).
enum class Outcome {
  ok,                    ///< an answer
  at_rest,               ///< coulomb law: the push cannot break static friction; the object stays (an answer)
  no_static_friction,    ///< thesis/printed law: the object is (or came) to rest where the sign law chatters
  law_blowup,            ///< printed law: its friction injects energy and the run blows up
  accuracy_not_reached,  ///< --accuracy E could not be met; the best answer and its estimate are kept
  solver_failure,        ///< the integrator gave up (stats.status says how)
};
NANOPUSH_NAMES(Outcome, {Outcome::ok, "ok"}, {Outcome::at_rest, "at_rest"},
               {Outcome::no_static_friction, "no_static_friction"}, {Outcome::law_blowup, "law_blowup"},
               {Outcome::accuracy_not_reached, "accuracy_not_reached"}, {Outcome::solver_failure, "solver_failure"});
/// An outcome that is an answer (ok, at_rest).
inline bool is_answer(Outcome o) { return o == Outcome::ok || o == Outcome::at_rest; }

/// The estimated global error of a run's answer (docs/accuracy.md): the difference from a
/// companion run at a tighter tolerance. NaN where not estimated.
struct ErrorEstimate {
  bool available = false;
  /// The final pose in the accuracy norm: max(|dx|, |dy|) / length_scale and |dtheta| [rad],
  /// whichever is larger.
  double norm = std::numeric_limits<double>::quiet_NaN();
  double x = std::numeric_limits<double>::quiet_NaN();      ///< |dx| at t_end [m]
  double y = std::numeric_limits<double>::quiet_NaN();      ///< |dy| at t_end [m]
  double theta = std::numeric_limits<double>::quiet_NaN();  ///< |dtheta| at t_end [rad]
  double trajectory = std::numeric_limits<double>::quiet_NaN();  ///< the norm's max over the output times
  double t_stick = std::numeric_limits<double>::quiet_NaN();     ///< |d t_stick| [s] (coulomb law; NaN if none)
  double length_scale = 0;   ///< [m] max(object length, distance travelled)
  double companion_rtol = 0;  ///< the tolerance of the companion run
  /// The run compared with: "companion" (a run rtol/100 tighter than the answer) or "looser"
  /// (--accuracy: the answer is the tighter run; the estimate bounds the looser one's error);
  /// "exact" where no run is needed (at_rest: the initial pose, whatever the tolerance).
  std::string basis = "companion";
  std::string companion;      ///< its engine label
  std::int64_t nfcn = 0;      ///< RHS evaluations the estimate cost (companion runs)
  std::string note;           ///< why unavailable, or its limit (a companion at the precision floor)
};

/// What --accuracy did: the error asked for, whether reached, the rtol the answer used.
struct AccuracyRecord {
  double requested = 0;  ///< 0: not asked
  bool reached = false;
  double rtol_used = 0;
  int runs = 0;  ///< runs made (answer and companions)
};

struct StickEventRecord {
  double t;
  bool stuck;
};

/// push.mode = tip: the tip at one output time (world axes, SI).
struct TipSample {
  double x = 0, y = 0;    ///< tip centre [m]
  double fx = 0, fy = 0;  ///< force of the tip on the object [N]
  int contact = 0;        ///< tip::ContactMode: 0 none, 1 stick, 2 slide
};

struct Trajectory {
  std::string engine_label;  ///< e.g. "cxx-faithful", "f77", "cxx-faithful-coulomb", "cxx-modern-quad"
  Precision precision = Precision::double_;  ///< scalar of the integration
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
  std::vector<TipSample> tip;            ///< push.mode = tip: the tip at each row
  std::vector<tip::TipEvent> tip_events; ///< push.mode = tip: contact made, released, tip stops
  bool complete = true;                  ///< false when allow_partial kept a failed run
  Outcome outcome = Outcome::ok;
  std::string outcome_message;  ///< why, for an outcome other than ok
  ErrorEstimate error;          ///< the estimated global error of the answer
  std::int64_t kinks_located = 0;  ///< thesis law, modern and dop853: kinks of the wrench located
  /// Method auto under the coulomb law: modern gave up (a stiff start just outside the limit
  /// surface) and CVODE (BDF) ran the scene instead; what modern said.
  std::string handed_over;
  AccuracyRecord accuracy;
  /// Every RHS evaluation the answer cost: its own run and the estimate's.
  [[nodiscard]] std::int64_t nfcn_total() const { return stats.nfcn + error.nfcn; }
  /// How it ended, for messages: "<outcome>: <why>" ("<status>: <why>" for solver_failure).
  [[nodiscard]] std::string outcome_text() const {
    return (outcome == Outcome::solver_failure ? std::string() : to_string(outcome) + ": ") + outcome_message;
  }
};

/// A push.mode = tip scene: the quasi-static tip push (models/tip_push.hpp, docs/tip.md).
Trajectory run_cxx_tip(const Scene& scene, const ResolvedSettings& resolved);

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

/// A rough scene that starts at rest with its push inside the coulomb limit surface (static
/// friction holds it: the coulomb law's at_rest, the thesis and printed laws' no_static_friction).
bool starts_stuck(const Scene& scene);
/// The message of the outcome no_static_friction: at rest at t (0: from the start) at the pose
/// (x, y, theta) [m, m, rad].
std::string no_static_friction_message(const Scene& scene, Law law, double t, double x, double y, double theta);

/// Settings as resolved against the scene (choices, rtol and atol filled in and validated);
/// InputError naming the field a bad value came from.
ResolvedSettings resolve_settings(const Scene& scene, const RunSettings& settings);

}  // namespace nanopush
