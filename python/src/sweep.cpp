// nanopush.sweep: many points at once through the sweep engine (sweeps/sweep.hpp): a plan (a
// cartesian grid or a list of points), a task (run, friction, icor, estimate-mu), evaluated on
// C++ threads with the GIL released; the table comes back as columns.
#include "common.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <thread>

#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::python {

namespace {

/// A plan value as the command line's parse_axis reads it: a number, a flag or text.
SceneValue plan_value(const std::string& key, const py::handle& obj) {
  const py::object v = plain_value(obj, key);  // a NumPy scalar or 0-d array: its value
  if (PyBool_Check(v.ptr())) return SceneValue(v.ptr() == Py_True);
  if (py::isinstance<py::str>(v)) return SceneValue(v.cast<std::string>());
  if (PyNumber_Check(v.ptr())) {
    const double d = arg_double(v, key);
    require_finite(key, d);
    return SceneValue(d);
  }
  throw InputError(key, py::repr(v).cast<std::string>(), "must be a number, a flag or text");
}

/// The values of `key` in the argument `arg` (vary, points): one or more.
std::vector<SceneValue> plan_values(const std::string& arg, const std::string& key, const py::handle& values) {
  std::vector<SceneValue> out;
  if (py::isinstance<py::str>(values)) {  // "FROM:TO:N" or "V1,V2,..." as on the command line
    return sweep::parse_axis(key + "=" + values.cast<std::string>(), false).values;
  }
  if (!py::isinstance<py::iterable>(values))
    throw InputError(key, py::repr(values).cast<std::string>(), "must be a sequence of values or 'FROM:TO:N'");
  for (auto v : values) out.push_back(plan_value(key, v));
  if (out.empty())  // an axis without values is a plan of no points, never what was meant
    throw InputError(arg + "." + key, py::repr(values).cast<std::string>(), "no values: give one or more");
  return out;
}

/// A text cell as csv_quote wrote it, back to its text.
std::string unquote(const std::string& cell) {
  if (cell.size() < 2 || cell.front() != '"' || cell.back() != '"') return cell;
  std::string out;
  for (std::size_t i = 1; i + 1 < cell.size(); ++i) {
    out += cell[i];
    if (cell[i] == '"' && cell[i + 1] == '"') ++i;
  }
  return out;
}

py::dict table(const sweep::Plan& plan, const sweep::Task& task, const std::vector<std::vector<std::string>>& rows) {
  const Columns cols = sweep::table_columns(plan, task);
  py::dict out;
  const auto n = static_cast<py::ssize_t>(rows.size());
  for (std::size_t c = 0; c < cols.size(); ++c) {
    const auto& col = cols[c];
    if (col.type == "string") {
      py::list l;
      for (const auto& r : rows) l.append(unquote(r[c]));
      out[py::str(col.name)] = py::module_::import("numpy").attr("array")(l, py::arg("dtype") = "str");
      continue;
    }
    py::array_t<double> a(n);
    bool whole = col.type == "integer";
    for (py::ssize_t i = 0; i < n; ++i) {
      const std::string& cell = rows[static_cast<std::size_t>(i)][c];
      const double v = sweep::cell_number(cell);
      a.mutable_at(i) = v;
      if (cell.empty()) whole = false;
    }
    if (whole)
      out[py::str(col.name)] = a.attr("astype")("int64");
    else
      out[py::str(col.name)] = a;
  }
  return out;
}

/// The caller's progress callable and Ctrl-C, from the thread that coordinates the workers
/// (the GIL released in between): PyErr_CheckSignals runs the Python signal handlers, so a
/// KeyboardInterrupt (or an exception of the callable) sets `stop` and is kept for the caller.
class Poll {
 public:
  explicit Poll(py::object progress) : progress_(std::move(progress)) {}
  /// With the GIL released; false once the sweep must stop.
  bool operator()(std::size_t done, std::size_t total, bool report) {
    if (stop_.load()) return false;
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (report && !progress_.is_none()) progress_(done, total);
    } catch (py::error_already_set& e) {
      error_ = std::make_unique<py::error_already_set>(std::move(e));
      stop_ = true;
    }
    return !stop_.load();
  }
  [[nodiscard]] const std::atomic<bool>* flag() const { return &stop_; }
  /// Raise what stopped the sweep (with the GIL held), if anything did.
  void rethrow() {
    if (error_) {
      auto e = std::move(error_);
      throw std::move(*e);
    }
  }

 private:
  py::object progress_;
  std::atomic<bool> stop_{false};
  std::unique_ptr<py::error_already_set> error_;
};

/// evaluate_points with a poll every 0.1 s (progress every 0.5 s and at the end): the rows of
/// every point in point order, or the stop raised by the poll.
std::vector<std::vector<std::string>> evaluate_polled(const sweep::Plan& plan, const sweep::Task& task,
                                                      unsigned jobs, Poll& poll) {
  std::vector<std::vector<std::string>> rows(plan.size());
  if (jobs == 0) jobs = std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(std::min<std::size_t>(jobs, std::max<std::size_t>(plan.size(), 1)));
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<unsigned> running{jobs};
  std::mutex mutex;
  std::exception_ptr failure;
  const std::atomic<bool>* stop = poll.flag();
  auto worker = [&] {
    try {
      while (!stop->load()) {
        const std::size_t k = next.fetch_add(1);
        if (k >= rows.size()) break;
        rows[k] = sweep::evaluate_row(plan, task, k);  // each slot written by one thread only
        ++done;
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
      next = rows.size();
    }
    --running;
  };
  {
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < jobs; ++t) threads.emplace_back(worker);
    auto last_poll = std::chrono::steady_clock::now(), last_report = last_poll;
    while (running.load() > 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      const auto now = std::chrono::steady_clock::now();
      if (now - last_poll < std::chrono::milliseconds(100)) continue;
      last_poll = now;
      const bool report = now - last_report >= std::chrono::milliseconds(500);
      if (report) last_report = now;
      poll(done.load(), rows.size(), report);
    }
    for (auto& t : threads) t.join();
  }
  if (failure) std::rethrow_exception(failure);
  if (!stop->load()) poll(done.load(), rows.size(), true);
  return rows;
}

py::tuple run_sweep_named(const std::string& task_name, const py::object& scene_obj, const py::list& axes,
                          const py::object& points, const py::dict& fixed, unsigned jobs, const std::string& engine,
                          const std::string& method, const std::string& law, const py::object& accuracy,
                          const py::object& error_estimate, const py::object& progress, const py::object& out) {
  std::unique_ptr<sweep::Task> task;
  const sweep::TaskKind kind = parse_choice<sweep::TaskKind>("task", task_name);
  if (kind == sweep::TaskKind::run) {
    if (scene_obj.is_none()) throw InputError("task", "run", "a run sweep needs a scene");
    if (!py::isinstance<Scene>(scene_obj))
      throw InputError("scene", py::repr(scene_obj).cast<std::string>(), "must be a nanopush.Scene");
    Scene sc = scene_obj.cast<Scene>();
    RunSettings rs;
    rs.engine = parse_optional_choice<Engine>("engine", engine);
    rs.method = parse_optional_choice<Method>("method", method);
    rs.law = parse_optional_choice<Law>("law", law);
    if (!accuracy.is_none()) {
      rs.accuracy = arg_double(accuracy, "accuracy");
      if (rs.accuracy != 0.0) require_range("accuracy", rs.accuracy, kAccuracyMin, kAccuracyMax);
    }
    if (!error_estimate.is_none()) rs.error_estimate = arg_bool(error_estimate, "error_estimate");
    if (!fixed.empty()) {
      std::vector<SceneSetting> s;
      for (auto item : fixed) {
        const auto key = item.first.cast<std::string>();
        s.emplace_back(key, py::isinstance<py::str>(item.second)
                                ? SceneValue::from_text(key, item.second.cast<std::string>())
                                : plan_value(key, item.second));
      }
      sc.set(s);
    }
    (void)resolve_settings(sc, rs);  // bad engine/method/law before any work
    task = sweep::make_run_task(sc, rs);
  } else {
    if (!engine.empty() || !method.empty() || !law.empty())
      throw InputError("task", task_name, "engine, method and law go with a run sweep (a scene) only");
    std::vector<SceneSetting> s;
    for (auto item : fixed) {
      const auto key = item.first.cast<std::string>();
      s.emplace_back(key, plan_value(key, item.second));
    }
    task = sweep::make_task(kind, s);
  }
  sweep::Plan plan;
  if (!points.is_none()) {
    if (!axes.empty()) throw InputError("points", "(given)", "give either points or vary axes, not both");
    const py::dict d = points.cast<py::dict>();
    std::size_t n = 0;
    bool first = true;
    std::vector<std::vector<SceneValue>> columns;
    for (auto item : d) {
      const auto key = item.first.cast<std::string>();
      plan.keys.push_back(key);
      columns.push_back(plan_values("points", key, item.second));
      if (!first && columns.back().size() != n)
        throw InputError("points." + key, std::to_string(columns.back().size()) + " values",
                         "every key needs the same number of values (" + std::to_string(n) + ")");
      n = columns.back().size();
      first = false;
    }
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<SceneValue> p;
      for (const auto& c : columns) p.push_back(c[i]);
      plan.points.push_back(std::move(p));
    }
  } else {
    std::vector<sweep::Axis> ax;
    for (const auto& item : axes) {
      const auto t = item.cast<py::tuple>();
      const auto key = t[0].cast<std::string>();
      const bool log = t[2].cast<bool>();
      if (log) {
        if (!py::isinstance<py::str>(t[1]))
          throw InputError("vary_log." + key, py::repr(t[1]).cast<std::string>(), "must be 'FROM:TO:N'");
        ax.push_back(sweep::parse_axis(key + "=" + t[1].cast<std::string>(), true));
      } else {
        ax.push_back({key, plan_values("vary", key, t[1])});
      }
    }
    plan = sweep::cartesian(ax);
  }
  // A key is fixed (set) or varied, never both: the fixed value would be overwritten at every
  // point (as `nanopush sweep --set` with --vary or --points).
  for (auto item : fixed) {
    const auto key = item.first.cast<std::string>();
    for (const auto& k : plan.keys)
      if (k == key)
        throw InputError("set", key + "=" + py::str(item.second).cast<std::string>(),
                         "conflicts with " + std::string(points.is_none() ? "vary" : "points") + ", which varies " +
                             key + ": a key is either fixed or varied");
  }
  (void)sweep::table_columns(plan, *task);  // every key and value checked before any work
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw InputError("progress", py::repr(progress).cast<std::string>(), "must be a callable progress(done, total)");
  if (!out.is_none()) {  // streamed to a file by the runner, with its journal (resumable)
    Poll poll(progress);
    sweep::Options o;
    o.jobs = jobs;
    o.out = arg_text(out, "out");
    o.stop = poll.flag();
    o.progress = [&poll](std::size_t done, std::size_t total) { poll(done, total, true); };
    sweep::Result r;
    {
      py::gil_scoped_release release;
      r = sweep::run_local(plan, *task, o);
    }
    poll.rethrow();  // Ctrl-C: KeyboardInterrupt; the journal keeps the finished rows
    py::dict d;
    d["path"] = o.out.string();
    d["points"] = r.points;
    d["done"] = r.done;
    d["resumed"] = r.resumed;
    d["failed"] = r.failed;
    d["complete"] = r.complete;
    return py::make_tuple(py::none(), py::none(), d);
  }
  return sweep_in_memory(plan, *task, jobs, progress);
}

/// nanopush.sweep: the library names some inputs as `nanopush sweep` does (--vary, --vary-log,
/// --set, --engine); here they are nanopush.sweep's arguments.
py::tuple run_sweep(const std::string& task_name, const py::object& scene_obj, const py::list& axes,
                    const py::object& points, const py::dict& fixed, unsigned jobs, const std::string& engine,
                    const std::string& method, const std::string& law, const py::object& accuracy,
                    const py::object& error_estimate, const py::object& progress, const py::object& out) {
  return bindings::with_argument_names(
      {{"--vary-log", "vary_log"}, {"--vary", points.is_none() ? "vary" : "points"}, {"--set", "set"},
       {"--engine", "engine"}},
      [&] {
        return run_sweep_named(task_name, scene_obj, axes, points, fixed, jobs, engine, method, law, accuracy,
                               error_estimate, progress, out);
      });
}

}  // namespace

py::tuple sweep_in_memory(const sweep::Plan& plan, const sweep::Task& task, unsigned jobs, const py::object& progress) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw InputError("progress", py::repr(progress).cast<std::string>(), "must be a callable progress(done, total)");
  Poll poll(progress);
  std::vector<std::vector<std::string>> rows;
  {
    py::gil_scoped_release release;
    rows = evaluate_polled(plan, task, jobs, poll);
  }
  poll.rethrow();  // Ctrl-C: KeyboardInterrupt, or what the progress callable raised
  const Columns cols = sweep::table_columns(plan, task);
  py::list names;
  py::dict units;
  for (const auto& c : cols) {
    names.append(c.name);
    units[py::str(c.name)] = c.unit;
  }
  return py::make_tuple(names, units, table(plan, task, rows));
}

void register_sweep(py::module_& m) {
  m.def("_sweep", &run_sweep, py::arg("task"), py::arg("scene"), py::arg("axes"), py::arg("points"), py::arg("fixed"),
        py::arg("jobs"), py::arg("engine"), py::arg("method"), py::arg("law"), py::arg("accuracy") = py::none(),
        py::arg("error_estimate") = py::none(), py::arg("progress") = py::none(), py::arg("out") = py::none(),
        "The sweep engine in memory (nanopush.sweep is the documented entry point).");
}

}  // namespace nanopush::python
