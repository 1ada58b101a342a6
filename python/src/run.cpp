// nanopush.run: a scene integrated by the C++ or the F77 engine (run_engine), the trajectory
// as NumPy arrays; nanopush.Result; and the two engines compared (compare_engines).
#include "common.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>

#include <pybind11/stl/filesystem.h>

#include "nanopush/engines/compare.hpp"
#include "nanopush/engines/engines.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/trajectory_csv.hpp"
#include "nanopush/scenes/engine_method.hpp"

namespace nanopush::python {

namespace {

/// What nanopush.run returns: the trajectory, the scene's name and the integration's wall time.
struct RunResult {
  Trajectory tr;
  std::string scene;
  double wall_s = 0.0;
};

/// A read-only view of column k (k < 0: the whole n x 10 table) of the result `self`.
py::array column_view(const py::object& self, int k) {
  const auto& r = self.cast<const RunResult&>();
  const auto n = static_cast<py::ssize_t>(r.tr.rows.size());
  const double* data = n > 0 ? r.tr.rows.front().data() : nullptr;
  static const double empty[10] = {};
  if (!data) data = empty;
  constexpr auto row = static_cast<py::ssize_t>(sizeof(TrajectoryRow));
  py::array a = k < 0 ? py::array_t<double>({n, py::ssize_t{10}}, {row, py::ssize_t{sizeof(double)}}, data, self)
                      : py::array_t<double>({n}, {row}, data + k, self);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

py::array_t<double> copy_vector(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

/// rtol (> 0; None = the scene's, 0) and atol (>= 0; None = the scene's, -1) from Python.
void read_tolerances(const py::object& rtol, const py::object& atol, double& r, double& a) {
  r = 0.0;
  a = -1.0;
  if (!rtol.is_none()) {
    r = arg_double(rtol, "rtol");
    require_positive("rtol", r);
  }
  if (!atol.is_none()) {
    a = arg_double(atol, "atol");
    require_nonnegative("atol", a);
  }
}

/// accuracy (None = the scene's; 0 = none; else in [kAccuracyMin, kAccuracyMax]) and
/// error_estimate (None = the scene's) into the run settings.
void read_accuracy(const py::object& accuracy, const py::object& error_estimate, RunSettings& rs) {
  if (!accuracy.is_none()) {
    rs.accuracy = arg_double(accuracy, "accuracy");
    if (rs.accuracy != 0.0) require_range("accuracy", rs.accuracy, kAccuracyMin, kAccuracyMax);
  }
  if (!error_estimate.is_none()) rs.error_estimate = arg_bool(error_estimate, "error_estimate");
}

py::object number_or_none(double v) { return std::isnan(v) ? py::object(py::none()) : py::object(py::float_(v)); }

/// The error estimate as a dict (docs/accuracy.md).
py::dict error_dict(const ErrorEstimate& e) {
  py::dict d;
  d["available"] = e.available;
  d["estimate"] = number_or_none(e.norm);
  d["x"] = number_or_none(e.x);
  d["y"] = number_or_none(e.y);
  d["theta"] = number_or_none(e.theta);
  d["trajectory"] = number_or_none(e.trajectory);
  d["t_stick"] = number_or_none(e.t_stick);
  d["length_scale"] = e.length_scale;
  d["basis"] = e.basis;
  d["companion"] = e.companion;
  d["companion_rtol"] = e.companion_rtol;
  d["nfcn"] = e.nfcn;
  d["note"] = e.note;
  return d;
}

/// t_eval (solve_ivp's): the output times, strictly increasing, within [0, solver.t_end].
/// Sets `scene.times`, with 0 first (the integration starts there); returns whether that 0 was
/// added (its row is then dropped from the answer).
bool set_output_times(Scene& scene, const py::object& t_eval) {
  const DArray a = as_double_array(t_eval, "t_eval");
  if (a.ndim() != 1 || a.size() == 0)
    throw InputError("t_eval", "an array of shape " + py::str(py::tuple(py::cast(std::vector<py::ssize_t>(
                                                          a.shape(), a.shape() + a.ndim())))).cast<std::string>(),
                     "must be a 1-d sequence of one or more times [s]");
  const double tend = scene.solver.t_end;
  std::vector<double> t;
  t.reserve(static_cast<std::size_t>(a.size()) + 1);
  for (py::ssize_t i = 0; i < a.size(); ++i) {
    const double v = a.at(i);
    const std::string field = "t_eval[" + std::to_string(i) + "]";
    require_finite(field, v);
    require_range(field, v, 0.0, tend, "s; within [0, solver.t_end]");
    if (i > 0 && !(v > t.back())) throw InputError(field, fmt(v), "must be greater than the time before it (" + fmt(t.back()) + " s): t_eval strictly increasing");
    t.push_back(v);
  }
  const bool added = t.front() != 0.0;
  if (added) t.insert(t.begin(), 0.0);
  if (t.size() < 2) t.push_back(tend);  // t_eval = [0]: the engines need an interval
  scene.times = std::move(t);
  return added;
}

/// Drop the first sample (the t = 0 added for t_eval) from a trajectory.
void drop_first_sample(Trajectory& tr) {
  if (tr.rows.empty()) return;
  tr.rows.erase(tr.rows.begin());
  if (!tr.work_push.empty()) tr.work_push.erase(tr.work_push.begin());
  if (!tr.work_fric.empty()) tr.work_fric.erase(tr.work_fric.begin());
  if (!tr.extended.empty()) tr.extended.erase(tr.extended.begin());
}

RunResult run(const Scene& scene, const std::string& engine, const std::string& method, const std::string& law,
              const py::object& rtol, const py::object& atol, const std::string& precision,
              const py::object& accuracy, const py::object& error_estimate, const py::object& t_eval) {
  RunSettings rs;
  read_accuracy(accuracy, error_estimate, rs);
  rs.engine = parse_optional_choice<Engine>("engine", engine);  // "" = the scene's (run_engine)
  rs.method = parse_optional_choice<Method>("method", method);
  rs.law = parse_optional_choice<Law>("law", law);
  rs.precision = parse_optional_choice<Precision>("precision", precision);
  read_tolerances(rtol, atol, rs.rtol, rs.atol);
  rs.allow_partial = true;  // a failure becomes nanopush.SolverError carrying the partial result
  // engine="f77" with the scene's own method: as `nanopush run`, the argument named engine
  bindings::with_argument_names({{"--engine", "engine"}}, [&] { check_engine_method(scene, rs); });
  RunResult r;
  r.scene = scene.name;
  Scene own = scene;  // another Python thread may set() the caller's scene meanwhile
  bool only_zero = false, drop_zero = false;
  if (!t_eval.is_none()) {
    drop_zero = set_output_times(own, t_eval);
    only_zero = !drop_zero && own.times.size() == 2 && as_double_array(t_eval, "t_eval").size() == 1;
  }
  {
    py::gil_scoped_release release;
    const auto t0 = std::chrono::steady_clock::now();
    r.tr = run_engine(own, rs);
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  if (drop_zero) drop_first_sample(r.tr);
  if (only_zero && r.tr.rows.size() > 1) {  // t_eval = [0]: the initial state alone
    r.tr.rows.resize(1);
    if (r.tr.work_push.size() > 1) r.tr.work_push.resize(1);
    if (r.tr.work_fric.size() > 1) r.tr.work_fric.resize(1);
    if (r.tr.extended.size() > 1) r.tr.extended.resize(1);
  }
  if (!r.tr.complete)
    throw RunFailure(scene.name + " (" + r.tr.engine_label + "): " + r.tr.outcome_text(), r.tr);
  return r;
}

/// nanopush.compare's work: compare_engines, its verdicts as a dict (Comparison wraps it).
py::dict compare(const Scene& scene, const std::string& method, const std::string& law, const py::object& rtol,
                 const py::object& atol, const py::object& tolerance, const py::object& accuracy) {
  CompareSettings cs;
  cs.method = method.empty() ? Method::faithful : parse_choice<Method>("method", method);
  cs.law = parse_optional_choice<Law>("law", law);
  read_tolerances(rtol, atol, cs.rtol, cs.atol);
  if (!tolerance.is_none()) cs.tolerance = arg_double(tolerance, "tolerance");
  if (!accuracy.is_none()) {
    cs.accuracy = arg_double(accuracy, "accuracy");
    if (!(cs.accuracy >= kAccuracyMin && cs.accuracy <= kAccuracyMax))
      throw InputError("accuracy", fmt(cs.accuracy), "must be in [" + fmt(kAccuracyMin) + ", " + fmt(kAccuracyMax) + "]");
    if (!rtol.is_none()) throw InputError("rtol", fmt(cs.rtol), "accuracy chooses the rtol: give one of them");
  }
  EngineComparison r;
  const Scene own = scene;
  {
    py::gil_scoped_release release;
    r = compare_engines(own, cs);
  }
  if (const Trajectory* t = r.failed()) {
    throw RunFailure(scene.name + " (" + t->engine_label + (r.failed_run >= 2 ? ", reference run" : "") +
                         "): " + t->outcome_text() + "; cannot judge: " + r.cannot_judge,
                     *t);
  }
  if (!r.cannot_judge.empty()) throw RunFailure(scene.name + ": cannot judge: " + r.cannot_judge, r.cxx);
  auto result = [&](Trajectory& tr) {
    RunResult rr;
    rr.tr = std::move(tr);
    rr.scene = scene.name;
    return py::cast(std::move(rr));
  };
  const bool same = r.kind == CompareKind::same_steps;
  py::dict d;
  d["kind"] = same ? "same-steps" : "convergence";
  d["tolerance"] = same ? py::object(py::float_(r.tolerance)) : py::object(py::none());
  d["agree"] = r.agree;
  d["law"] = to_string(r.law);
  if (r.accuracy.requested > 0) {
    py::dict a;
    a["requested"] = r.accuracy.requested;
    a["reached"] = r.accuracy.reached;
    a["rtol_used"] = r.accuracy.rtol_used;
    a["runs"] = r.accuracy.runs;
    d["accuracy"] = a;
  } else {
    d["accuracy"] = py::none();
  }
  d["cxx"] = result(r.cxx);
  d["f77"] = result(r.f77);
  py::dict cols;
  for (const ColumnVerdict& v : r.columns) {
    py::dict c;
    if (same) {
      c["max_abs_diff"] = v.max_abs_diff;
      c["relative"] = v.relative;
    } else {
      c["error_cxx"] = v.error_cxx;
      c["error_f77"] = v.error_f77;
      c["diff"] = v.diff;
      c["diff_tight"] = v.diff_tight;
    }
    c["unit"] = v.unit;
    c["scale"] = v.scale;
    c["ok"] = v.ok;
    cols[py::str(v.name)] = c;
  }
  d["columns"] = cols;
  return d;
}

}  // namespace

py::object make_result(const Trajectory& tr) {
  RunResult r;
  r.tr = tr;
  return py::cast(std::move(r));
}

namespace {

using ResultClass = py::class_<RunResult>;

/// The table: one read-only view per column, the whole array, names and units, to_dict, to_csv.
void add_table(ResultClass& cls) {
  const auto& cols = trajectory_columns();
  const auto& units = trajectory_units();
  for (std::size_t k = 0; k < cols.size(); ++k) {
    const int kk = static_cast<int>(k);
    cls.def_property_readonly(
        cols[k].c_str(), [kk](const py::object& self) { return column_view(self, kk); },
        (cols[k] + " [" + units[k] + "] at each output time (read-only view)").c_str());
  }
  cls.def_property_readonly(
         "array", [](const py::object& self) { return column_view(self, -1); },
         "The trajectory as an n x 10 read-only array, columns t, x, y, theta, vx, vy, omega, fx, fy, mf.")
      .def_property_readonly_static("columns", [](const py::object&) { return trajectory_columns(); },
                                    "Column names, in order.")
      .def_property_readonly_static(
          "units",
          [](const py::object&) {
            py::dict d;
            for (std::size_t k = 0; k < trajectory_columns().size(); ++k)
              d[py::str(trajectory_columns()[k])] = trajectory_units()[k];
            return d;
          },
          "Unit of each column.")
      .def(
          "to_dict",
          [](const py::object& self) {
            py::dict d;
            const auto& r = self.cast<const RunResult&>();
            for (std::size_t k = 0; k < trajectory_columns().size(); ++k) {
              py::array_t<double> a(static_cast<py::ssize_t>(r.tr.rows.size()));
              double* p = a.mutable_data();
              for (std::size_t i = 0; i < r.tr.rows.size(); ++i) p[i] = r.tr.rows[i][k];
              d[py::str(trajectory_columns()[k])] = a;
            }
            return d;
          },
          "The columns as a dict of independent (writable, contiguous) arrays: pandas.DataFrame(r.to_dict()).")
      .def(
          "to_csv",
          [](const RunResult& r, const std::filesystem::path& path) {
            py::gil_scoped_release release;
            write_trajectory_csv(r.tr, path, r.scene);
          },
          py::arg("path"),
          "Write the CSV of `nanopush run --out PATH` (shortest round-trip numbers) with its sidecar "
          "PATH.schema.json; atomic (a temporary name renamed when complete).");
}

/// How the run went: counts, engine, precision, tolerances, completeness.
void add_counts(ResultClass& cls) {
  cls
      .def_property_readonly("nfcn", [](const RunResult& r) { return r.tr.stats.nfcn; }, "Right-hand-side evaluations.")
      .def_property_readonly("steps", [](const RunResult& r) { return r.tr.stats.naccpt; }, "Accepted steps.")
      .def_property_readonly("rejected", [](const RunResult& r) { return r.tr.stats.nrejct; }, "Rejected steps.")
      .def_property_readonly("engine", [](const RunResult& r) { return r.tr.engine_label; },
                             "The engine and configuration that ran, e.g. 'cxx-faithful', 'f77', "
                             "'cxx-faithful-coulomb'.")
      .def_property_readonly("precision", [](const RunResult& r) { return to_string(r.tr.precision); },
                             "Scalar of the integration: double, long or quad (columns always hold doubles).")
      .def_property_readonly("rtol", [](const RunResult& r) { return r.tr.rtol; }, "Relative tolerance used.")
      .def_property_readonly("atol", [](const RunResult& r) { return copy_vector(r.tr.atol); },
                             "Absolute tolerance of each state component (SI).")
      .def_property_readonly("complete", [](const RunResult& r) { return r.tr.complete; },
                             "False only for the partial result a SolverError carries.");
}

/// scipy.integrate.solve_ivp's names: success, status, message, nfev, states (its `y`).
void add_solve_ivp(ResultClass& cls) {
  cls
      .def_property_readonly("integrator_status", [](const RunResult& r) { return status_name(r.tr.stats.status); },
                             "The integrator's status as a word: success, or why it stopped (too_many_steps, "
                             "step_underflow, rhs_failed, not_finite).")
      .def_property_readonly("success", [](const RunResult& r) { return r.tr.complete && is_answer(r.tr.outcome); },
                             "True when the run gave an answer (outcome ok or at_rest), as solve_ivp's success; "
                             "False only on a SolverError's partial result.")
      .def_property_readonly(
          "status", [](const RunResult& r) { return r.tr.complete && is_answer(r.tr.outcome) ? 0 : -1; },
          "solve_ivp's status: 0 the run reached its last output time, -1 it failed (a SolverError's partial "
          "result); `integrator_status` and `outcome` say more.")
      .def_property_readonly(
          "message",
          [](const RunResult& r) -> std::string {
            if (!r.tr.outcome_message.empty()) return r.tr.outcome_message;
            if (r.tr.complete && is_answer(r.tr.outcome)) return "reached the last output time";
            return r.tr.outcome_text();
          },
          "Why the run ended, in words (solve_ivp's message).")
      .def_property_readonly("nfev", [](const RunResult& r) { return r.tr.stats.nfcn; },
                             "Right-hand-side evaluations of the integration (solve_ivp's nfev; = nfcn).")
      .def_property_readonly(
          "states",
          [](const py::object& self) {
            // Columns x .. omega of the row-major table, transposed: shape (6, n), no copy.
            const auto& r = self.cast<const RunResult&>();
            const auto n = static_cast<py::ssize_t>(r.tr.rows.size());
            static const double empty[10] = {};
            const double* data = n > 0 ? r.tr.rows.front().data() : empty;
            constexpr auto row = static_cast<py::ssize_t>(sizeof(TrajectoryRow));
            py::array a = py::array_t<double>({py::ssize_t{6}, n}, {py::ssize_t{sizeof(double)}, row}, data + col::x, self);
            static_assert(col::omega == col::x + 5, "states: x, y, theta, vx, vy, omega contiguous");
            a.attr("setflags")(py::arg("write") = false);
            return a;
          },
          "The state matrix, shape (6, n), rows x, y [m], theta [rad], vx, vy [m/s], omega [rad/s]: what "
          "solve_ivp calls `y` (here `y` is the y coordinate). A read-only view.")
      .def_property_readonly_static(
          "state_names", [](const py::object&) { return std::vector<std::string>{"x", "y", "theta", "vx", "vy", "omega"}; },
          "The rows of `states`, in order.");
}

/// What the answer is worth: its outcome, error estimate, accuracy, cost, works and events.
/// push.mode = tip: the tip at each row and its events, as the CLI's table and summary give
/// them (tip_x, tip_y, tip_fx, tip_fy, contact; "tip: contact at t = ...").
void add_tip(ResultClass& cls) {
  cls.def_property_readonly(
         "tip",
         [](const RunResult& r) -> py::object {
           if (r.tr.tip.empty()) return py::none();
           const std::size_t n = r.tr.tip.size();
           std::vector<double> x(n), y(n), fx(n), fy(n);
           py::array_t<int> contact(static_cast<py::ssize_t>(n));
           auto c = contact.mutable_unchecked<1>();
           for (std::size_t i = 0; i < n; ++i) {
             const TipSample& s = r.tr.tip[i];
             x[i] = s.x;
             y[i] = s.y;
             fx[i] = s.fx;
             fy[i] = s.fy;
             c(static_cast<py::ssize_t>(i)) = s.contact;
           }
           py::dict d;
           d["x"] = copy_vector(x);
           d["y"] = copy_vector(y);
           d["fx"] = copy_vector(fx);
           d["fy"] = copy_vector(fy);
           d["contact"] = contact;
           for (auto item : d) item.second.attr("setflags")(py::arg("write") = false);
           return d;
         },
         "push.mode = tip: a dict of arrays at the output times, as the CLI table's tip columns: x, y "
         "(the tip's centre, m), fx, fy (its force on the object, N), contact (0 none, 1 stick, 2 slide); "
         "None for other scenes.")
      .def_property_readonly(
          "tip_events",
          [](const RunResult& r) {
            py::list l;
            for (const auto& e : r.tr.tip_events) l.append(py::make_tuple(e.t, e.what));
            return l;
          },
          "push.mode = tip: (t [s], what) for each contact made, release and the tip's stop.");
}

void add_outcome(ResultClass& cls) {
  cls
      .def_property_readonly("outcome", [](const RunResult& r) { return to_string(r.tr.outcome); },
                             "How the run ended (docs/errors.md): ok or at_rest for an answer; no_static_friction, "
                             "law_blowup, accuracy_not_reached, solver_failure on a SolverError's partial result.")
      .def_property_readonly("outcome_message", [](const RunResult& r) { return r.tr.outcome_message; },
                             "Why, for an outcome other than ok.")
      .def_property_readonly("error", [](const RunResult& r) { return error_dict(r.tr.error); },
                             "The estimated global error of the answer (docs/accuracy.md): estimate (the final "
                             "pose in the accuracy norm), x, y [m], theta [rad] (final pose), trajectory (the norm's "
                             "max over the output times), t_stick [s], length_scale [m], basis, companion, "
                             "companion_rtol, nfcn (its cost), note; None where not estimated.")
      .def_property_readonly("error_estimate", [](const RunResult& r) { return number_or_none(r.tr.error.norm); },
                             "error['estimate']: the estimated error of the final pose (None if not estimated).")
      .def_property_readonly(
          "accuracy",
          [](const RunResult& r) {
            py::dict d;
            d["requested"] = r.tr.accuracy.requested;
            d["reached"] = r.tr.accuracy.reached;
            d["rtol_used"] = r.tr.accuracy.rtol_used;
            d["runs"] = r.tr.accuracy.runs;
            return d;
          },
          "What accuracy= did: requested (0: not asked), reached, rtol_used, runs.")
      .def_property_readonly("nfcn_total", [](const RunResult& r) { return r.tr.nfcn_total(); },
                             "Every RHS evaluation the answer cost, the error estimate's included.")
      .def_property_readonly("scene", [](const RunResult& r) { return r.scene; }, "The scene's name.")
      .def_property_readonly("wall_time", [](const RunResult& r) { return r.wall_s; },
                             "Wall time of the integration [s] (as `nanopush run` reports it).")
      .def_property_readonly("work_push", [](const RunResult& r) { return copy_vector(r.tr.work_push); },
                             "Rough scenes: work of the push from t = 0 to each sample [J] (empty otherwise).")
      .def_property_readonly("work_friction", [](const RunResult& r) { return copy_vector(r.tr.work_fric); },
                             "Rough scenes: work of friction from t = 0 to each sample [J] (empty otherwise).")
      .def_property_readonly(
          "events",
          [](const RunResult& r) {
            py::list l;
            for (const auto& e : r.tr.events) l.append(py::make_tuple(e.t, e.stuck));
            return l;
          },
          "Coulomb law: (t [s], stuck) at each instant the body came to rest.")
      .def("__len__", [](const RunResult& r) { return r.tr.rows.size(); })
      .def("__repr__", [](const RunResult& r) {
        return "<nanopush.Result " + r.scene + " [" + r.tr.engine_label + "]: " + std::to_string(r.tr.rows.size()) +
               " samples, " + std::to_string(r.tr.stats.nfcn) + " RHS evaluations>";
      });
}

}  // namespace

void register_run(py::module_& m) {
  auto cls = py::class_<RunResult>(m, "Result", R"doc(A trajectory: one row per output time, SI, world axes, centre of mass.

Columns (read-only NumPy arrays): t [s], x, y [m], theta [rad], vx, vy [m/s], omega [rad/s],
fx, fy [N] (friction force), mf [N m] (friction moment); `array` is the n x 10 table.
A tip push adds `tip` (the tip at each row: x, y, fx, fy, contact) and `tip_events`.
Counts: nfcn (right-hand-side evaluations), steps (accepted), rejected. to_dict() gives a
dict of arrays (pandas.DataFrame(result.to_dict())); to_csv(path) writes the CSV of
`nanopush run --out` (and its Table Schema sidecar).)doc");
  add_table(cls);
  add_counts(cls);
  add_solve_ivp(cls);
  add_outcome(cls);
  add_tip(cls);

  m.def("_run", &run, py::arg("scene"), py::arg("engine") = "", py::arg("method") = "", py::arg("law") = "",
        py::arg("rtol") = py::none(), py::arg("atol") = py::none(), py::arg("precision") = "",
        py::arg("accuracy") = py::none(), py::arg("error_estimate") = py::none(), py::arg("t_eval") = py::none(),
        "Integrate a scene (nanopush.run is the documented entry point).");
  m.def("_compare", &compare, py::arg("scene"), py::arg("method") = "faithful", py::arg("law") = "",
        py::arg("rtol") = py::none(), py::arg("atol") = py::none(), py::arg("tolerance") = py::none(),
        py::arg("accuracy") = py::none(), "Both engines judged column by column (nanopush.compare is the documented entry point).");
}

}  // namespace nanopush::python
