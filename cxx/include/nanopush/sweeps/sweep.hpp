// Many scenes at once: a plan of points (a cartesian grid of axes, or a list), a task
// evaluated at each point (a run's summary, a friction wrench, the iCOR formulas, a mu
// estimate), and the tidy table of the results: one row per point, ordered by point index,
// so the table never depends on how many threads, shards or MPI ranks computed it.
// docs/sweeps.md documents the axes syntax, the columns and how to run on a cluster.
#pragma once
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "nanopush/outputs/io.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush::sweep {

/// One axis: a key and the values it takes.
struct Axis {
  std::string key;
  std::vector<SceneValue> values;
};

/// "KEY=FROM:TO:N": N values from FROM to TO, both included (linear; geometric with `log`);
/// "KEY=V1,V2,...": the listed values (numbers, or text for text keys). N in [1, 1000000].
Axis parse_axis(const std::string& spec, bool log = false);

/// The points of a sweep: the keys that vary (the table's input columns) and, per point, one
/// value per key.
struct Plan {
  std::vector<std::string> keys;
  std::vector<std::vector<SceneValue>> points;
  [[nodiscard]] std::size_t size() const { return points.size(); }
  /// The settings of point i.
  [[nodiscard]] std::vector<SceneSetting> settings(std::size_t i) const;
};

/// The most points a plan may have (a grid, a --points table): 1e8; larger is a typo.
inline constexpr std::size_t kMaxPlanPoints = 100000000;

/// The cartesian product of the axes, the last axis varying fastest.
Plan cartesian(const std::vector<Axis>& axes);
/// A list of points from a CSV file: the header names the keys, each row is a point.
Plan points_from_csv(const std::filesystem::path& path);

/// What is evaluated at each point.
class Task {
 public:
  virtual ~Task() = default;
  /// run | friction | icor | estimate-mu
  [[nodiscard]] virtual std::string name() const = 0;
  /// The summary columns a point gives (after the point index and the inputs).
  [[nodiscard]] virtual Columns outputs() const = 0;
  /// The column a varied key gets (unit and meaning); throws InputError for a key the task
  /// does not take.
  [[nodiscard]] virtual Column input_column(const std::string& key) const = 0;
  /// Throws InputError for a value of a varied key the task cannot take at all (a word for a
  /// number, a choice not allowed), so such a plan fails before any work.
  virtual void check_input(const std::string& key, const SceneValue& value) const {
    (void)key;
    (void)value;
  }
  /// The output cells at a point (csv_number, "" for missing). Throws InputError (bad input)
  /// or SolverError (the integrator gave up) for a point that fails.
  [[nodiscard]] virtual std::vector<std::string> evaluate(const std::vector<SceneSetting>& point,
                                                        std::size_t index) const = 0;
  /// The same with the point's status: a task whose points can end in an outcome other than
  /// ok or a failure (a run: at_rest, accuracy_not_reached with its best answer; docs/errors.md)
  /// overrides it. status "ok" by default.
  struct PointResult {
    std::vector<std::string> cells;
    std::string status = "ok";
    std::string message;
  };
  [[nodiscard]] virtual PointResult evaluate_point(const std::vector<SceneSetting>& point, std::size_t index) const {
    PointResult r;
    r.cells = evaluate(point, index);
    return r;
  }
  /// Everything that determines the results, as text (the journal's identity).
  [[nodiscard]] virtual std::string identity() const = 0;
  /// The scene's name (for the sidecar), "" when the task has none.
  [[nodiscard]] virtual std::string scene_name() const { return {}; }
};

/// A run of `base` with the varied keys set (Scene::set); the run's engine, method and law
/// from `settings` (empty: the scene's). Outputs: final pose, distance and rotation
/// travelled, final iCOR, time to stick, peak friction force, work of friction, counts. With
/// `trajectories`, each point's trajectory is kept there as point_<index>.csv.
std::unique_ptr<Task> make_run_task(const Scene& base, RunSettings settings,
                                    std::filesystem::path trajectories = {});
/// The friction wrench of the rectangular contact at an iCOR (keys a, b, muN, R, alpha, sense).
std::unique_ptr<Task> make_friction_task(const std::vector<SceneSetting>& fixed);
/// Every iCOR formula of chapters 4-5 at a push offset (keys yn, mu, force, rod.*).
std::unique_ptr<Task> make_icor_task(const std::vector<SceneSetting>& fixed);
/// mu and its uncertainty from a push force and yn, or from a force and an observed iCOR R.
std::unique_ptr<Task> make_estimate_mu_task(const std::vector<SceneSetting>& fixed);
/// The task named (run needs a scene: use make_run_task).
std::unique_ptr<Task> make_task(const std::string& name, const std::vector<SceneSetting>& fixed);

/// The table's columns: point, the varied keys, the task's outputs, status, message. Checks
/// every varied key and value with the task (InputError before any work).
Columns table_columns(const Plan& plan, const Task& task);
/// The row of point i: its inputs, outputs and status (ok | bad_input | solver_failure |
/// error) with the message; never throws for a failing point.
std::vector<std::string> evaluate_row(const Plan& plan, const Task& task, std::size_t i);
/// True when a row's status is not an answer (ok or at_rest).
bool row_failed(const std::vector<std::string>& row);
/// A row as one CSV line (cells as formatted, joined by commas), and back (quotes kept).
std::string join_cells(const std::vector<std::string>& row);
std::vector<std::string> split_cells(const std::string& line);

/// Points of shard `index` of `count` (index, index + count, ...): every point in exactly one.
std::vector<std::size_t> shard_points(std::size_t n, std::size_t index, std::size_t count);

/// An append-only record of finished rows, so a killed sweep resumes where it stopped. One
/// line per row: index, checksum, cells; a record that is incomplete or does not match its
/// checksum is ignored. The first line names the sweep (a hash of plan, task and shard): a
/// journal of another sweep is an error, never silently mixed in.
class Journal {
 public:
  /// Open (create or resume) `path` for the sweep whose identity is `identity`.
  Journal(std::filesystem::path path, const std::string& identity);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;
  /// Rows finished before (resumed), by point index.
  [[nodiscard]] const std::map<std::size_t, std::vector<std::string>>& resumed() const { return resumed_; }
  /// Append a finished row (thread-safe; one write per record).
  void append(std::size_t index, const std::vector<std::string>& row);
  /// Remove the journal (the table is complete).
  void remove();
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::mutex mutex_;
  std::map<std::size_t, std::vector<std::string>> resumed_;
};

/// The journal of a sweep whose table is `out`: OUT.journal beside it; for a table written
/// through (a device such as /dev/null, /dev/stdout) NAME.journal in the working directory,
/// never beside the device. OutputError (exit 5) if `out` is a directory or a FIFO.
std::filesystem::path journal_path(const std::filesystem::path& out);

/// The identity of a sweep: task, plan and shard, as text (hashed into the journal's header).
std::string sweep_identity(const Plan& plan, const Task& task, std::size_t shard_index, std::size_t shard_count);

struct Options {
  unsigned jobs = 0;                  ///< threads; 0 = every core
  std::size_t shard_index = 0, shard_count = 1;
  std::filesystem::path out;          ///< the table (CSV; its sidecar beside it)
  /// Called with (done, total) from the coordinating thread about twice a second.
  std::function<void(std::size_t, std::size_t)> progress;
  /// Set to stop taking new points (a signal handler); points in flight finish.
  const std::atomic<bool>* stop = nullptr;
};

struct Result {
  std::size_t points = 0;   ///< points of this shard
  std::size_t done = 0;     ///< rows in the table (or journal, when stopped)
  std::size_t resumed = 0;  ///< rows taken from the journal
  std::size_t failed = 0;   ///< rows whose status is not ok
  bool complete = false;    ///< the table was written
};

/// Run the points of one shard on `jobs` threads with a journal beside the table; when every
/// point is done, write the table (ordered by point index) and its sidecar, and remove the
/// journal.
Result run_local(const Plan& plan, const Task& task, const Options& options);

/// In memory: the rows of every point (evaluate_row), in point order, computed on `jobs`
/// threads (0 = every core); no journal, no file. A failing point's row keeps its status and
/// message (see row_failed). The rows are the same whatever `jobs` is.
std::vector<std::vector<std::string>> evaluate_points(const Plan& plan, const Task& task, unsigned jobs = 0);

/// The position of a column (an input key's or an output's name, as in table_columns) in the
/// rows of plan and task; throws InputError when there is none.
std::size_t column_index(const Plan& plan, const Task& task, const std::string& name);

/// A number cell read back as the double it was written from (cells are shortest round-trip
/// text): "" (missing) is NaN; text that is not a whole number throws InputError.
double cell_number(const std::string& cell);

/// Write the table of `rows` (point index -> row), ordered, with its sidecar. The sidecar's
/// "run" object records the plan's size, the shard, the rows and failed rows, then `timings`
/// (the caller's: wall time, threads, ranks, rows resumed).
void write_table(const std::filesystem::path& out, const Plan& plan, const Task& task,
                 const std::map<std::size_t, std::vector<std::string>>& rows, std::size_t shard_index,
                 std::size_t shard_count, const RunInfo& timings = {});

/// The sidecar's timings of a sweep: `wall_s` [s] from the start of this invocation to the
/// table, the threads per process, the MPI ranks, the rows taken from the journal.
RunInfo sweep_timings(double wall_s, unsigned threads, int ranks, std::size_t resumed);

/// The identity of a plan and task, whatever the shard (a hash of sweep_identity): recorded as
/// "plan" in a table's sidecar, so merge joins only shards of one sweep.
std::string plan_identity(const Plan& plan, const Task& task);

/// Join shard tables into the table of the whole plan (the same bytes as one run). Each table
/// needs its sidecar: every shard's plan identity and size the same, each shard i/n once and
/// all n present, every row of its shard with the header's number of cells and a known status,
/// as many rows as the sidecar says, every point 0 .. plan_points - 1 once; InputError
/// otherwise. Returns the failed-row count.
std::size_t merge_tables(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out);

}  // namespace nanopush::sweep
