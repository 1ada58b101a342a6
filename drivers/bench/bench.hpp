// Work-precision benchmark harness (issue 7): one scene, a sweep of tolerances, every engine.
//
// The harness knows nothing about physics. A scene is turned into a `Problem` (initial
// state, output times, per-component scales), a list of `Engine`s (each one a closure that
// solves the problem at a given rtol and a closure that times its bare RHS) and a
// `Reference` (the trajectory at the output times, exact or from extended precision).
// docs/performance.md explains the measurements; bench_engines.hpp builds the engines.
//
// Error measure (column `error` of the CSV): the largest weighted deviation over the output
// times and the state components,
//     error = max_k max_i |y_i(t_k) - yref_i(t_k)| / (scale_i + |yref_i(t_k)|),
// with scale_i the natural scale of component i (Scene::state_scales(): the object's length
// for x and y, 1 rad for theta, length * omega0 for the velocities, omega0 for omega). Every
// engine gets atol_i = rtol * scale_i, so the weight is the one its tolerance uses
// (atol_i + rtol |y_i| = rtol (scale_i + |y_i|)): error and rtol are on the same scale, and
// components that grow far beyond their scale (x, vx under a constant push) are measured
// relative to their size.
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "nanopush/numerics/scalar.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/scenes/choices.hpp"

namespace nanopush::bench {

using num::quad;

/// The initial-value problem every engine sees.
struct Problem {
  std::string name;
  int n = 0;                  ///< state components
  double t0 = 0;              ///< [s]
  std::vector<double> y0;     ///< initial state (SI)
  std::vector<double> tout;   ///< output times [s], non-decreasing, tout[0] >= t0
  std::vector<double> scale;  ///< natural scale per component; atol_i = rtol * scale_i
  [[nodiscard]] std::vector<double> atol(double rtol) const;
  [[nodiscard]] std::size_t nout() const { return tout.size(); }
};

/// One solve: the states at every output time (row k = tout[k]: y[k*n + i]) and the counts.
/// States are stored in quad precision so that extended-precision engines keep their digits.
struct Solve {
  int status = 0;  ///< 0 = success; otherwise the engine's own failure code
  std::string message;
  std::int64_t nfcn = 0;    ///< RHS evaluations (CVODE BDF: including those for the difference-quotient Jacobian)
  std::int64_t naccpt = 0;  ///< accepted steps
  std::int64_t nrejct = 0;  ///< rejected step attempts (error test and convergence failures)
  std::vector<quad> y;      ///< nout * n
  double seconds = 0;       ///< wall time of the solve proper (engine creation to last output) [s]
};

struct Engine {
  std::string name;                  ///< e.g. "cxx-faithful", "cvode-adams"
  Precision precision = Precision::double_;  ///< scalar of the integration
  std::string note;                  ///< how outputs are produced (clipped steps or interpolation), settings
  double rtol_min = 1e-13;           ///< tightest tolerance that is meaningful in this precision
  std::function<Solve(double rtol)> solve;
  /// Wall time [s] of `count` calls of this engine's RHS alone (same scalar, same function),
  /// evaluated at states along the reference trajectory.
  std::function<double(std::int64_t count)> time_rhs;
  /// Diagnostic of the integrator's own time (SweepSettings::replay). replay(rtol, first)
  /// records the RHS values of one solve at rtol and returns a timer: one solve whose RHS
  /// hands the recorded values back in order without evaluating anything (so the integrator
  /// takes the same steps bit for bit), minus the time of copying as many values [s].
  /// Empty (no replay) for extended scalars and RHS the engine calls outside C++; the
  /// returned timer is empty when the replayed solve does not reproduce `first` exactly.
  std::function<std::function<double()>(double rtol, const Solve& first)> replay;
  [[nodiscard]] std::string label() const {
    return precision == Precision::double_ ? name : name + " (" + to_string(precision) + ")";
  }
};

/// The trajectory errors are measured against.
struct Reference {
  std::string kind;     ///< "exact" or "extended"
  std::string how;      ///< one line: how it was obtained
  std::vector<quad> y;  ///< nout * n
  /// Scaled max-abs disagreement between the two independent extended-precision runs
  /// (0 for an exact reference). Errors below 1000 x this are not resolved.
  double disagreement = 0;
};

/// The weighted max-abs deviation (the `error` above) of trajectory a from trajectory b.
double scaled_max_error(const Problem& p, const std::vector<quad>& a, const std::vector<quad>& b);

/// Acceptance of an extended-precision reference: two independent runs a and b must agree
/// to 1e-3 of the smallest error that will be plotted against them.
struct Acceptance {
  bool accepted = false;
  double disagreement = 0;  ///< scaled_max_error(a, b)
  double threshold = 0;     ///< 1e-3 * smallest_error
  std::string explanation;
};
Acceptance accept_reference(const Problem& p, const std::vector<quad>& a, const std::vector<quad>& b,
                            double smallest_error);

/// A reference from two independent extended-precision runs: trajectory of run a, and the
/// scaled disagreement between a and b. Throws SolverError when either run failed.
Reference extended_reference(const Problem& p, const Solve& a, const Solve& b, const std::string& how);

/// Smallest error that goes on the work-precision plot: the minimum over the successful
/// double-precision rows (extended-precision rows are checked against an exact reference only).
struct Row;
double smallest_plotted_error(const std::vector<Row>& rows);

/// The acceptance rule applied to a reference and the rows measured against it (exact
/// references are always accepted).
Acceptance accept_reference(const Reference& ref, const std::vector<Row>& rows);

/// rtol = 10^(-k/2) for k = kmin..kmax (step kstep), keeping rtol >= rtol_min.
std::vector<double> tolerance_sweep(int kmin, int kmax, int kstep, double rtol_min);

/// One line of the benchmark CSV.
struct Row {
  std::string engine;
  Precision precision = Precision::double_;
  double rtol = 0;
  double error = 0;  ///< weighted max-abs error (NaN when the solve failed)
  std::int64_t nfcn = 0, naccpt = 0, nrejct = 0;
  double wall_s = 0;               ///< median wall time of `repeats` solves [s]
  double rhs_s = 0;                ///< median time of nfcn bare RHS calls [s]
  double overhead_ns_per_rhs = 0;  ///< (wall_s - rhs_s) / nfcn [ns]
  int repeats = 0;
  /// (upper quartile - lower quartile) / median of the repeats' wall times: how far a single
  /// timing of this row can be trusted (NaN with fewer than 4 repeats)
  double wall_spread = std::numeric_limits<double>::quiet_NaN();
  int status = 0;  ///< 0 = success; kStatusBelowReference; else the engine's failure code
  /// The integrator alone: median over the repeats of (solve with the RHS values replayed -
  /// copying them) / nfcn [ns] (Engine::replay). NaN when the sweep ran without replay or
  /// the engine has none.
  double own_ns_per_rhs = std::numeric_limits<double>::quiet_NaN();
};

/// Row status of a successful solve whose error the reference cannot resolve: below 1e3 x
/// the disagreement of the two reference runs (the acceptance rule's factor). The row
/// stays in the CSV with its error, but is not plotted, not used in the ratios, and not
/// a failure.
inline constexpr int kStatusBelowReference = -2;

/// Mark the double-precision rows an extended reference cannot resolve (error < 1e3 x
/// its disagreement) with kStatusBelowReference; returns how many. Exact references
/// resolve everything (nothing marked).
int mark_below_reference(const Reference& ref, std::vector<Row>& rows);

/// The loosest rtol R from which an engine's integrator overhead stays within `bound_ns`
/// [ns per RHS]: every successful row of (engine, precision) with rtol <= R has
/// `field` <= bound_ns (overhead_ns_per_rhs, or own_ns_per_rhs for the replay measurement;
/// a NaN counts as above). Empty when the tightest such row is already above the bound,
/// or there is no such row. Throws InputError for a bound that is not finite.
std::optional<double> overhead_within_from(const std::vector<Row>& rows, const std::string& engine,
                                           Precision precision, double bound_ns,
                                           double Row::*field = &Row::overhead_ns_per_rhs);

/// CSV header of the benchmark (docs/performance.md documents every column).
const std::vector<std::string>& csv_columns();
/// The same columns with their units and meanings (the CSV's sidecar, docs/outputs.md).
const Columns& csv_column_specs();

struct SweepSettings {
  int repeats = 9;          ///< timed solves per point (median reported), after one untimed warm-up solve
                            ///< (repeats = 1: no per-point warm-up, one per engine only)
  int repeats_extended = 0; ///< the same for long/quad engines (0 = repeats): their solves take 1-300 ms
  int kmin = 6, kmax = 28;  ///< rtol = 10^(-k/2), each engine stopping at its rtol_min; extended precision continues to its rtol_min
  int kmax_extended = 56;   ///< last k for engines whose rtol_min is below 1e-14 (56: rtol 1e-28)
  int kstep = 1;
  int kstep_extended = 0;   ///< k step for long/quad engines (0 = kstep)
  /// Also time every engine that has one with its RHS values replayed (Engine::replay,
  /// Row::own_ns_per_rhs): `repeats` more solves per point.
  bool replay = false;
  std::function<void(const Row&)> progress;  ///< called after each row (tolerance by tolerance: the engines are interleaved)
};

/// Run every engine over the sweep; errors against `ref`.
std::vector<Row> run_sweep(const Problem& p, const std::vector<Engine>& engines, const Reference& ref,
                           const SweepSettings& s);

/// Write the rows as CSV with its sidecar (atomically, docs/outputs.md); `scene` goes into the sidecar.
void write_csv(const std::vector<Row>& rows, const std::filesystem::path& path, const std::string& scene = {});

/// Work-precision figure: error against RHS evaluations and against wall time, log-log,
/// one line per engine (and precision). Writes `png` and its gnuplot script.
void plot_work_precision(const std::vector<Row>& rows, const std::filesystem::path& csv,
                         const std::filesystem::path& png, const std::string& title);

/// Integrator overhead against rtol, log-log, one line per double-precision engine, with
/// the target as a dashed line: the subtraction measure (overhead_ns_per_rhs) and, when
/// any row has it, the replay measure (own_ns_per_rhs) beside it. Writes `png` and its
/// gnuplot script; `csv` is the file write_csv() wrote the rows to.
void plot_overhead(const std::vector<Row>& rows, const std::filesystem::path& csv, const std::filesystem::path& png,
                   const std::string& title, double target_ns = 10.0);

}  // namespace nanopush::bench
