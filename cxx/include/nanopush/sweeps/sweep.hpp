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
#include <string_view>
#include <vector>

#include "nanopush/outputs/io.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush::sweep {

/// One axis: a key and the values it takes.
struct Axis {
  std::string key;
  std::vector<SceneValue> values;
  std::string spec = {};  ///< as written ("surface.mu=0.02:0.2:10"; --vary-log: "log:" first), "" in code
};

/// "KEY=FROM:TO:N": N values from FROM to TO, both included, as numpy.linspace(FROM, TO, N)
/// computes them (FROM + i * ((TO - FROM) / (N - 1)), the last exactly TO); with `log`, as
/// numpy.geomspace (10^(log10 FROM + i * step), the ends exactly as written).
/// "KEY=V1,V2,...": the listed values (numbers, or text for text keys). N in [1, 1000000].
Axis parse_axis(const std::string& spec, bool log = false);

/// The i-th of n values from `from` to `to` as numpy.linspace / numpy.geomspace give them.
double linspace_value(double from, double to, std::size_t n, std::size_t i);
double geomspace_value(double from, double to, std::size_t n, std::size_t i);

class PointTable;  ///< a --points file read by index (points_table.cpp)

/// The points of a sweep: the keys that vary (the table's input columns) and the value of each
/// key at point i. Nothing of the plan's size is stored: a grid is its axes (point i computed
/// from i), a --points file is read by index (a checkpoint every 1024 rows, the rows near the
/// last one read cached). A list built in code (`points`) is held in memory.
struct Plan {
  std::vector<std::string> keys;
  /// A list built in code: one value per key per point (empty for a grid or a file).
  std::vector<std::vector<SceneValue>> points;
  /// A grid (cartesian): its axes, the last varying fastest.
  std::vector<Axis> axes;
  bool grid = false;
  /// A --points file (points_from_csv), read by index; `source` is its name as given.
  std::shared_ptr<PointTable> table;
  std::string source;

  [[nodiscard]] std::size_t size() const;
  /// The values of point i (one per key).
  [[nodiscard]] std::vector<SceneValue> point(std::size_t i) const;
  /// The settings of point i.
  [[nodiscard]] std::vector<SceneSetting> settings(std::size_t i) const;
  /// Every distinct (key, value) of the plan is passed to `f` at least once (a grid: each
  /// axis's values; a list or file: every point's), for checks before any work.
  void for_each_value(const std::function<void(const std::string&, const SceneValue&)>& f) const;
  /// The plan as text for identities: the axes and their values, or the points' hash.
  [[nodiscard]] std::string identity_text() const;
  /// What the plan is, for the sidecar and the journal (field, value as written): "grid" or
  /// "points", each axis as written, the --points file and its hash, the size.
  [[nodiscard]] std::vector<std::pair<std::string, std::string>> describe() const;
};

/// The most points a plan may have (a grid, a --points table): 1e8; larger is a typo.
inline constexpr std::size_t kMaxPlanPoints = 100000000;

/// The cartesian product of the axes, the last axis varying fastest (nothing stored per point).
Plan cartesian(const std::vector<Axis>& axes);
/// A list of points from a CSV file: the header names the keys, each row is a point. The file
/// is read once through (every row checked, counted and hashed), then by index.
Plan points_from_csv(const std::filesystem::path& path);

/// The output columns of the task named `task` as task_columns.tsv lists them (the table is
/// compiled in and read on the first call); std::logic_error if it lists none.
Columns task_columns(std::string_view task);

/// What is evaluated at each point.
class Task {
 public:
  virtual ~Task() = default;
  /// run | friction | icor | estimate-mu | plan-check
  [[nodiscard]] virtual std::string name() const = 0;
  /// The summary columns a point gives (after the point index and the inputs): by default the
  /// task's rows of task_columns.tsv.
  [[nodiscard]] virtual Columns outputs() const { return task_columns(name()); }
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
  /// What fixes the task's results beside the plan, as (field, value) for the sidecar's plan
  /// record and the journal (scene hash, engine, method, law, fixed values...).
  [[nodiscard]] virtual std::vector<std::pair<std::string, std::string>> describe() const {
    return {{"task", name()}};
  }
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
/// The kinds of sweep task: runs of a scene, or one of the closed-form tasks.
enum class TaskKind { run, friction, icor, estimate_mu };
/// The closed-form task of that kind (run needs a scene: use make_run_task).
std::unique_ptr<Task> make_task(TaskKind kind, const std::vector<SceneSetting>& fixed);

/// The table's columns: point, the varied keys, the task's outputs, status, message. With
/// `check`, checks every varied key and every distinct value with the task (InputError before
/// any work; a --points file is read through once more).
Columns table_columns(const Plan& plan, const Task& task, bool check = true);
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

/// What a sweep is, field by field (the plan's and the task's describe(), the fixed values,
/// the shard, the version): recorded in the journal and the table's sidecar, so a journal or
/// shard of another sweep is refused naming the field that differs.
using PlanRecord = std::vector<std::pair<std::string, std::string>>;
PlanRecord plan_record(const Plan& plan, const Task& task, const std::vector<std::string>& fixed = {});
/// The first fields where `theirs` (a journal's, a shard's) and `ours` differ, as a message
/// ("law: coulomb there, thesis here"); "" when none differs.
std::string plan_difference(const PlanRecord& theirs, const PlanRecord& ours);

/// An append-only record of finished rows, so a killed sweep resumes where it stopped. One
/// line per row: index, checksum, cells; a record that is incomplete or does not match its
/// checksum is ignored. The first line names the sweep (a hash of plan, task and shard), the
/// second records its plan field by field: a journal of another sweep is an error naming the
/// difference, never silently mixed in. Read one line at a time.
class Journal {
 public:
  /// Open (create or resume) `path` for the sweep whose identity is `identity`. Each record
  /// read back goes to `on_row` (index, CSV line) as it is read, when given (nothing kept:
  /// resume in bounded memory); else it is kept in resumed().
  using RowCallback = std::function<void(std::size_t, std::string)>;
  Journal(std::filesystem::path path, const std::string& identity, const PlanRecord& record = {},
          const RowCallback& on_row = {});
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;
  /// Rows finished before (resumed), by point index: each row's CSV line.
  [[nodiscard]] const std::map<std::size_t, std::string>& resumed() const { return resumed_; }
  /// Hand the resumed rows over (the journal keeps none).
  std::map<std::size_t, std::string> take_resumed() { return std::move(resumed_); }
  /// Append a finished row (thread-safe; one write per record).
  void append(std::size_t index, const std::vector<std::string>& row);
  void append_line(std::size_t index, const std::string& line);
  /// Remove the journal (the table is complete).
  void remove();
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::mutex mutex_;
  std::map<std::size_t, std::string> resumed_;
};

/// The table of a shard written as its rows come, in point order: a row that comes before its
/// turn waits, and a point may start only within `window` positions of the next row to write
/// (may_start), so at most `window` rows wait whatever the plan's size. The CSV goes through
/// the atomic output (a temporary renamed at commit); rows also go to `sink` in point order.
class OrderedTable {
 public:
  using Sink = std::function<void(std::size_t index, const std::string& line)>;
  OrderedTable(const std::filesystem::path& out, const Plan& plan, const Task& task, std::size_t shard_index,
               std::size_t shard_count, Sink sink = {}, std::size_t window = 4096);
  ~OrderedTable();
  OrderedTable(const OrderedTable&) = delete;
  OrderedTable& operator=(const OrderedTable&) = delete;
  /// The point at shard position p is i = shard_index + p * shard_count.
  [[nodiscard]] std::size_t index_of(std::size_t position) const { return index_ + position * count_; }
  [[nodiscard]] std::size_t positions() const { return positions_; }
  /// Add the row of point `index` (its CSV line); rows in turn are written at once.
  void add(std::size_t index, std::string line, bool failed);
  /// May the point at shard position p start (within the window of the next row to write)?
  [[nodiscard]] bool may_start(std::size_t position) const { return position < written_ + window_; }
  /// Is the row of shard position p in (written, or waiting for its turn)?
  [[nodiscard]] bool has(std::size_t position) const { return position < written_ || waiting_.count(position) > 0; }
  [[nodiscard]] std::size_t written() const { return written_; }
  [[nodiscard]] std::size_t done() const { return written_ + waiting_.size(); }
  [[nodiscard]] std::size_t failed() const { return failed_; }
  [[nodiscard]] bool complete() const { return written_ == positions_; }
  /// Every row written: the sidecar (plan record, rows, failed rows, `timings`), then rename.
  void commit(const RunInfo& timings, const PlanRecord& record);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::size_t index_, count_, positions_, window_, written_ = 0, failed_ = 0;
  std::map<std::size_t, std::pair<std::string, bool>> waiting_;  ///< by position
  Sink sink_;
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
  /// Each row as it is written, in point order (index, its CSV line), e.g. to stream a table
  /// elsewhere; called from the thread that writes the table. With `out` empty no file and no
  /// journal is written: the rows go to the sink only.
  std::function<void(std::size_t, const std::string&)> row_sink;
  /// The fixed values as given (--set KEY=VALUE), recorded in the sidecar's plan record.
  std::vector<std::string> fixed;
  /// Rows that may wait for a slower point before them (the bound of the memory held).
  std::size_t window = 4096;
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

/// The sidecar's timings of a sweep: `wall_s` [s] from the start of this invocation to the
/// table, `cpu_s` [s] the CPU time of every thread (and rank) of this invocation, the threads
/// per process, the MPI ranks, the rows taken from the journal.
RunInfo sweep_timings(double wall_s, unsigned threads, int ranks, std::size_t resumed, double cpu_s = -1);
/// CPU time (user + system) of this process so far [s].
double process_cpu_seconds();

/// The identity of a plan and task, whatever the shard (a hash of sweep_identity): recorded as
/// "plan" in a table's sidecar, so merge joins only shards of one sweep.
std::string plan_identity(const Plan& plan, const Task& task);

/// Join shard tables into the table of the whole plan (the same bytes as one run), reading
/// each shard one row at a time. Each table needs its sidecar: every shard's plan identity
/// and size the same (a difference named field by field), each shard i/n once and
/// all n present, every row of its shard with the header's number of cells and a known status,
/// as many rows as the sidecar says, every point 0 .. plan_points - 1 once; InputError
/// otherwise. Returns the failed-row count.
std::size_t merge_tables(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out);

}  // namespace nanopush::sweep

namespace nanopush {
NANOPUSH_NAMES(sweep::TaskKind, {sweep::TaskKind::run, "run"}, {sweep::TaskKind::friction, "friction"},
               {sweep::TaskKind::icor, "icor"}, {sweep::TaskKind::estimate_mu, "estimate-mu"});
}  // namespace nanopush

