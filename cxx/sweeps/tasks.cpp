// What a sweep evaluates at a point: a run of a scene (summary of its trajectory), or one of
// the closed-form evaluations (friction wrench, iCOR formulas, mu estimate).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "nanopush/scenes/engine_method.hpp"
#include "nanopush/engines/engines.hpp"
#include "nanopush/models/friction.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene_keys.hpp"
#include "nanopush/numerics/names.hpp"
#include "nanopush/numerics/tsv.hpp"
#include "hash.hpp"
#include "nanopush/outputs/trajectory_csv.hpp"
#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::sweep {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A number varied for a scene key against the key's own range as the key table states it
/// ("> 0", ">= 0", "[a, b]", "0 or [a, b]"); a range that depends on other keys (abs(yn) <=
/// length/2) is left to the point, where the other keys are known. InputError (exit 2 before
/// any point) naming the key, the value and the range.
void check_static_range(const std::string& key, double v) {
  const SceneKey* k = find_scene_key(key);
  if (!k) return;
  std::string_view r = k->range;
  const std::string range(r);
  auto refuse = [&] { throw InputError("--vary " + key, fmt(v), "out of range: must be " + range); };
  if (!std::isfinite(v)) refuse();
  if (r.substr(0, 5) == "0 or ") {
    if (v == 0) return;
    r.remove_prefix(5);
  }
  auto number = [](std::string_view t, double& out) {
    while (!t.empty() && t.front() == ' ') t.remove_prefix(1);
    while (!t.empty() && t.back() == ' ') t.remove_suffix(1);
    if (t == "pi/2") {
      out = 1.5707963267948966;
      return true;
    }
    const auto res = std::from_chars(t.data(), t.data() + t.size(), out);
    return res.ec == std::errc() && res.ptr == t.data() + t.size();
  };
  double lo = 0, hi = 0;
  if (r.substr(0, 4) == "> 0;" || r == "> 0") {
    if (!(v > 0)) refuse();
  } else if (r == ">= 0") {
    if (!(v >= 0)) refuse();
  } else if (r.size() > 4 && (r.front() == '[' || r.front() == '(') && (r.back() == ']' || r.back() == ')')) {
    const auto comma = r.find(',');
    if (comma == std::string_view::npos || !number(r.substr(1, comma - 1), lo) ||
        !number(r.substr(comma + 1, r.size() - comma - 2), hi))
      return;  // a bound named by another key
    const bool lo_ok = r.front() == '[' ? v >= lo : v > lo, hi_ok = r.back() == ']' ? v <= hi : v < hi;
    if (!lo_ok || !hi_ok) refuse();
  }
}

std::string cell(double v) { return csv_number(v); }  // NaN -> "" (missing)

// The tasks' output columns and the closed-form tasks' parameters are data: task_columns.tsv
// and task_parameters.tsv, compiled in (cxx/sweeps/CMakeLists.txt).
#include "task_columns.tsv.inc"
#include "task_parameters.tsv.inc"

}  // namespace

Columns task_columns(std::string_view task) {
  static const auto catalogue = [] {
    std::map<std::string, Columns, std::less<>> c;
    tsv::for_each_row(kTaskColumnsTsv, [&c](std::string_view row) {
      const auto f = tsv::fields<5>(row);
      c[std::string(f[0])].push_back({std::string(f[1]), std::string(f[3]), std::string(f[4]), std::string(f[2])});
    });
    return c;
  }();
  const auto it = catalogue.find(task);
  if (it == catalogue.end()) throw std::logic_error("cxx/sweeps/task_columns.tsv lists no columns of task " + std::string(task));
  return it->second;
}

namespace {

// ---- run: a scene's trajectory, summarised ---------------------------------------------------

class RunTask final : public Task {
 public:
  RunTask(const Scene& base, RunSettings s, std::filesystem::path trajectories)
      : base_(base), settings_(std::move(s)), trajectories_(std::move(trajectories)) {
    check_engine_method(base_, settings_);
  }
  [[nodiscard]] std::string name() const override { return "run"; }
  [[nodiscard]] std::string scene_name() const override { return base_.name; }


  [[nodiscard]] Column input_column(const std::string& key) const override {
    const SceneKey* k = find_scene_key(key);
    if (!k) throw InputError(key, "(varied)", "unknown scene key (`nanopush scene-keys` lists them)");
    std::string name = key;  // a plain identifier: surface.mu -> surface_mu
    for (char& ch : name)
      if (ch == '.') ch = '_';
    Column c{name, std::string(k->unit), "scene key " + key + ": " + std::string(k->description)};
    if (k->type == KeyType::string || k->type == KeyType::boolean) c.type = "string";
    if (k->type == KeyType::integer) c.type = "integer";
    return c;
  }

  /// A text or flag value (a choice such as surface.law, solver.method) is checked on the scene
  /// before any point runs, each distinct value once: `--vary surface.law=thesis,coulmb` is bad
  /// input (exit 2), not a sweep whose rows all fail. Numbers are checked where they run (their
  /// ranges can depend on other keys of the point).
  void check_input(const std::string& key, const SceneValue& value) const override {
    if (value.kind() == KeyType::number) {
      check_static_range(key, value.number());
      return;
    }
    if (!checked_.insert(key + "=" + value.to_string()).second) return;
    Scene sc = base_;
    sc.set(key, value);
    if (settings_.engine == Engine::f77 && !settings_.method && key == "solver.method" &&
        sc.solver.method != Method::faithful && sc.solver.method != Method::automatic)
      throw InputError("--vary solver.method", value.to_string(),
                       "conflicts with --engine f77: the f77 engine has one method (its Bulirsch-Stoer); vary "
                       "solver.method with --engine cxx");
  }

  [[nodiscard]] std::vector<std::string> evaluate(const std::vector<SceneSetting>& point,
                                                  std::size_t index) const override {
    PointResult r = evaluate_point(point, index);
    if (r.status != "ok" && r.status != to_string(Outcome::at_rest)) throw SolverError(r.message, r.status);
    return r.cells;
  }

  [[nodiscard]] PointResult evaluate_point(const std::vector<SceneSetting>& point, std::size_t index) const override {
    Scene sc = base_;
    if (!point.empty()) sc.set(point);
    RunSettings s = settings_;
    s.allow_partial = true;  // an outcome other than ok is the row's status
    const Trajectory tr = run_engine(sc, s);
    if (!is_answer(tr.outcome) && tr.outcome != Outcome::accuracy_not_reached)
      return {{}, to_string(tr.outcome), sc.name + " (" + tr.engine_label + "): " + tr.outcome_message};
    if (!trajectories_.empty())
      write_trajectory_csv(tr, trajectories_ / ("point_" + std::to_string(index) + ".csv"));
    const auto& rows = tr.rows;
    const auto& last = rows.back();
    double dist = 0, rot = 0, fpeak = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      fpeak = std::max(fpeak, std::hypot(rows[i][col::fx], rows[i][col::fy]));
      if (i == 0) continue;
      dist += std::hypot(rows[i][col::x] - rows[i - 1][col::x], rows[i][col::y] - rows[i - 1][col::y]);
      rot += std::fabs(rows[i][col::theta] - rows[i - 1][col::theta]);
    }
    double ix = kNaN, iy = kNaN;
    if (last[col::omega] != 0.0) {  // v = omega x r: the point at rest is CM + (-vy, vx) / omega
      ix = -last[col::vy] / last[col::omega];
      iy = last[col::vx] / last[col::omega];
    }
    double t_stick = kNaN;
    for (const auto& e : tr.events)
      if (e.stuck && e.t > 0.0) {
        t_stick = e.t;
        break;
      }
    const double wf = tr.work_fric.empty() ? 0.0 : tr.work_fric.back();
    const ErrorEstimate& e = tr.error;
    PointResult r;
    r.cells = {cell(last[col::x]), cell(last[col::y]), cell(last[col::theta]), cell(dist), cell(rot), cell(ix), cell(iy),
               cell(t_stick), cell(fpeak), cell(wf), cell(e.norm), cell(e.x), cell(e.y), cell(e.theta),
               cell(e.trajectory), cell(tr.rtol), std::to_string(tr.nfcn_total()), std::to_string(tr.stats.naccpt),
               std::to_string(tr.stats.nrejct)};
    r.status = to_string(tr.outcome);
    if (tr.outcome != Outcome::ok) r.message = tr.outcome_message;
    return r;
  }

  [[nodiscard]] std::vector<std::pair<std::string, std::string>> describe() const override {
    // The choices as asked ("" where the scene's are taken: its hash covers them).
    const std::string engine = name_or_empty(settings_.engine), method = name_or_empty(settings_.method),
                      law = name_or_empty(settings_.law);
    return {{"task", "run"},
            {"scene", base_.name},
            {"scene_hash", hex(fnv1a(base_.to_toml()))},
            {"engine", engine.empty() ? std::string(name_of(base_.solver.engine)) : engine},
            {"method", method.empty() ? std::string(name_of(base_.solver.method)) : method},
            {"law", law.empty() ? (base_.rough() ? std::string(name_of(base_.surface.law)) : "") : law},
            {"settings", "rtol=" + fmt(settings_.rtol) + " atol=" + fmt(settings_.atol) +
                             " precision=" + name_or_empty(settings_.precision) + " accuracy=" + fmt(settings_.accuracy) +
                             " estimate=" + (settings_.error_estimate ? (*settings_.error_estimate ? "1" : "0") : "")}};
  }

  [[nodiscard]] std::string identity() const override {
    // The journal's identity of the task: the settings as given ("" = the scene's).
    return "run\n" + base_.to_toml() + "\nengine=" + name_or_empty(settings_.engine) +
           " method=" + name_or_empty(settings_.method) + " law=" + name_or_empty(settings_.law) +
           " rtol=" + fmt(settings_.rtol) + " atol=" + fmt(settings_.atol) +
           " precision=" + name_or_empty(settings_.precision) + " accuracy=" + fmt(settings_.accuracy) +
           " estimate=" + (settings_.error_estimate ? (*settings_.error_estimate ? "1" : "0") : "");
  }

 private:
  Scene base_;
  RunSettings settings_;
  std::filesystem::path trajectories_;
  mutable std::set<std::string> checked_;  ///< text values already checked (table_columns, one thread)
};

// ---- closed-form evaluations over named parameters ---------------------------------------

struct Param {
  std::string key, unit, description;
  double dflt;  ///< NaN: required (or optional, see the task); for a choice, the index of the default
  std::vector<std::string> choices = {};  ///< a text parameter: its allowed values (stored as their index)
};

/// The parameters of a task as task_parameters.tsv lists them, in its order.
std::vector<Param> task_parameters(std::string_view task) {
  std::vector<Param> out;
  tsv::for_each_row(kTaskParametersTsv, [&](std::string_view row) {
    const auto f = tsv::fields<6>(row);
    if (f[0] != task) return;
    Param p{std::string(f[1]), std::string(f[2]), std::string(f[5]), kNaN};
    for (std::string_view rest = f[4]; !rest.empty();) {
      const std::size_t comma = std::min(rest.find(", "), rest.size());
      p.choices.emplace_back(rest.substr(0, comma));
      rest.remove_prefix(std::min(comma + 2, rest.size()));
    }
    if (!p.choices.empty()) {
      const auto it = std::find(p.choices.begin(), p.choices.end(), f[3]);
      if (it == p.choices.end()) throw std::logic_error("task_parameters.tsv: " + p.key + "'s default is not a choice");
      p.dflt = static_cast<double>(it - p.choices.begin());
    } else if (f[3] != "none") {
      const auto r = std::from_chars(f[3].data(), f[3].data() + f[3].size(), p.dflt);
      if (r.ec != std::errc() || r.ptr != f[3].data() + f[3].size())
        throw std::logic_error("task_parameters.tsv: " + p.key + "'s default is not a number");
    }
    out.push_back(std::move(p));
  });
  if (out.empty()) throw std::logic_error("task_parameters.tsv lists no parameters of task " + std::string(task));
  return out;
}

/// A closed-form task: its parameters (task_parameters.tsv, then `more`), each fixed by --set
/// or varied, and compute() on their values.
class ParamTask : public Task {
 public:
  ParamTask(std::string name, const std::vector<SceneSetting>& fixed, const std::vector<Param>& more = {})
      : name_(std::move(name)), params_(task_parameters(name_)) {
    params_.insert(params_.end(), more.begin(), more.end());
    for (const auto& p : params_) values_[p.key] = p.dflt;
    for (const auto& [k, v] : fixed) values_[k] = value(k, v);
  }
  [[nodiscard]] std::string name() const override { return name_; }
  [[nodiscard]] Column input_column(const std::string& key) const override {
    for (const auto& p : params_)
      if (p.key == key) {
        std::string name = key;
        for (char& ch : name)
          if (ch == '.') ch = '_';
        if (!p.choices.empty()) return text_column(name, key + ": " + p.description);
        return {name, p.unit, key + ": " + p.description};
      }
    throw InputError(key, "(varied)", "not a parameter of --task " + name() + " (" + keys() + ")");
  }
  [[nodiscard]] std::vector<std::string> evaluate(const std::vector<SceneSetting>& point,
                                                  std::size_t /*index*/) const override {
    auto v = values_;
    for (const auto& [k, x] : point) v[k] = value(k, x);
    return compute(v);
  }
  void check_input(const std::string& key, const SceneValue& v) const override { (void)value(key, v); }
  [[nodiscard]] std::vector<std::pair<std::string, std::string>> describe() const override {
    std::string fixed;
    for (const auto& [k, x] : values_) fixed += (fixed.empty() ? "" : " ") + k + "=" + fmt(x);
    return {{"task", name()}, {"values", fixed}};
  }
  [[nodiscard]] std::string identity() const override {
    std::ostringstream s;
    s << name();
    for (const auto& [k, x] : values_) s << " " << k << "=" << fmt(x);  // a choice by its index
    return s.str();
  }

 protected:
  using Values = std::map<std::string, double>;
  [[nodiscard]] virtual std::vector<std::string> compute(const Values& v) const = 0;
  static double need(const Values& v, const std::string& key) {
    const double x = v.at(key);
    if (std::isnan(x)) throw InputError(key, "(missing)", "required: give it with --set or vary it");
    return x;
  }

 private:
  /// The value of parameter `key` (a choice: the index of its text), or InputError.
  [[nodiscard]] double value(const std::string& key, const SceneValue& v) const {
    for (const auto& p : params_) {
      if (p.key != key) continue;
      if (p.choices.empty()) {
        if (v.kind() != KeyType::number) throw InputError(key, v.to_string(), "must be a number");
        return v.number();
      }
      std::string allowed;
      for (std::size_t i = 0; i < p.choices.size(); ++i) {
        if (v.kind() == KeyType::string && v.to_string() == p.choices[i]) return static_cast<double>(i);
        allowed += (i ? ", " : "") + p.choices[i];
      }
      throw InputError(key, v.to_string(), "must be one of: " + allowed);
    }
    throw InputError(key, v.to_string(), "not a parameter of --task " + name() + " (" + keys() + ")");
  }
  [[nodiscard]] std::string keys() const {
    std::string s;
    for (const auto& p : params_) s += (s.empty() ? "" : ", ") + p.key;
    return s;
  }
  std::string name_;
  std::vector<Param> params_;
  Values values_;
};

/// A task on a rod (icor, estimate-mu): its parameters and the rod's (rod.*, the defaults of
/// icor::Rod); compute_on gets the rod built from them and validated.
class RodTask : public ParamTask {
 public:
  RodTask(std::string name, const std::vector<SceneSetting>& fixed) : ParamTask(std::move(name), fixed, rod_params()) {}

 protected:
  [[nodiscard]] virtual std::vector<std::string> compute_on(const Values& v, const icor::Rod& rod) const = 0;
  [[nodiscard]] std::vector<std::string> compute(const Values& v) const final { return compute_on(v, rod_of(v)); }

 private:
  static icor::Rod rod_of(const Values& v) {
    icor::Rod r;
    r.length = v.at("rod.length");
    r.radius = v.at("rod.radius");
    r.density = v.at("rod.density");
    r.hamaker = v.at("rod.hamaker");
    r.z0 = v.at("rod.z0");
    r.gravity = v.at("rod.gravity");
    r.validate();
    return r;
  }
  static std::vector<Param> rod_params() {
    const icor::Rod r;
    return {{"rod.length", "m", "rod length L", r.length},
            {"rod.radius", "m", "rod radius", r.radius},
            {"rod.density", "kg/m^3", "rod density", r.density},
            {"rod.hamaker", "J", "Hamaker constant H (assumed literature-order value by default)", r.hamaker},
            {"rod.z0", "m", "rod-plane separation z0", r.z0},
            {"rod.gravity", "m/s^2", "gravity", r.gravity}};
  }
};

class FrictionTask final : public ParamTask {
 public:
  explicit FrictionTask(const std::vector<SceneSetting>& fixed) : ParamTask("friction", fixed) {}

 protected:
  [[nodiscard]] std::vector<std::string> compute(const Values& v) const override {
    const double s = need(v, "sense");
    if (s != 1.0 && s != -1.0) throw InputError("sense", fmt(s), "must be 1 or -1");
    const auto w = rectangle_friction_wrench_checked(need(v, "a"), need(v, "b"), need(v, "muN"), need(v, "R"),
                                                     need(v, "alpha"), static_cast<int>(s));
    return {cell(w.fx), cell(w.fy), cell(w.mf)};
  }
};

class IcorTask final : public RodTask {
 public:
  explicit IcorTask(const std::vector<SceneSetting>& fixed) : RodTask("icor", fixed) {}

 protected:
  [[nodiscard]] std::vector<std::string> compute_on(const Values& v, const icor::Rod& rod) const override {
    const double L = rod.length, yn = need(v, "yn"), mu = need(v, "mu"), W = rod.load();
    const auto method = v.at("cubic") == 0.0 ? icor::CubicMethod::Brent : icor::CubicMethod::Eigen;
    const auto sol = icor::solve_constrained_cubic(yn, L, rod.gyration_squared(), method);
    const double F = v.at("force"), R = icor::unknown_pressure(yn, L);
    return {cell(icor::experimental_fit(yn, L)),
            cell(icor::falvo(yn, L)),
            cell(icor::li(yn, L)),
            cell(R),
            cell(sol.negative ? *sol.negative : kNaN),
            cell(sol.positive ? *sol.positive : kNaN),
            cell(icor::impulsive(yn, rod.gyration_squared())),
            cell(icor::minimum_force(mu, W, yn, L)),
            cell(std::isnan(F) ? kNaN : icor::known_pressure(mu, W, yn, F, L)),
            cell(W),
            cell(icor::force_from_icor(mu, W, R, L))};
  }
};

class EstimateMuTask final : public RodTask {
 public:
  explicit EstimateMuTask(const std::vector<SceneSetting>& fixed) : RodTask("estimate-mu", fixed) {}

 protected:
  [[nodiscard]] std::vector<std::string> compute_on(const Values& v, const icor::Rod& rod) const override {
    const bool has_yn = !std::isnan(v.at("yn")), has_R = !std::isnan(v.at("R"));
    if (has_yn == has_R)
      throw InputError("yn/R", has_yn ? "both given" : "neither given", "give exactly one: yn (basis force) or R (basis icor)");
    const icor::Measured F{need(v, "force"), v.at("sigma_force")};
    const auto e = has_yn ? icor::estimate_mu_from_force(rod, F, {v.at("yn"), v.at("sigma_yn")}, v.at("sigma_L"),
                                                         v.at("sigma_H"))
                          : icor::estimate_mu_from_icor(rod, F, {v.at("R"), v.at("sigma_R")}, v.at("sigma_L"),
                                                        v.at("sigma_H"));
    return {has_yn ? "force" : "icor", cell(e.mu), cell(e.sigma), cell(e.load)};
  }
};

}  // namespace

std::unique_ptr<Task> make_run_task(const Scene& base, RunSettings settings, std::filesystem::path trajectories) {
  return std::make_unique<RunTask>(base, std::move(settings), std::move(trajectories));
}
std::unique_ptr<Task> make_friction_task(const std::vector<SceneSetting>& fixed) {
  return std::make_unique<FrictionTask>(fixed);
}
std::unique_ptr<Task> make_icor_task(const std::vector<SceneSetting>& fixed) { return std::make_unique<IcorTask>(fixed); }
std::unique_ptr<Task> make_estimate_mu_task(const std::vector<SceneSetting>& fixed) {
  return std::make_unique<EstimateMuTask>(fixed);
}
std::unique_ptr<Task> make_task(TaskKind kind, const std::vector<SceneSetting>& fixed) {
  switch (kind) {
    case TaskKind::friction: return make_friction_task(fixed);
    case TaskKind::icor: return make_icor_task(fixed);
    case TaskKind::estimate_mu: return make_estimate_mu_task(fixed);
    case TaskKind::run: break;
  }
  throw std::logic_error("make_task: a run sweep needs a scene (make_run_task)");
}

// ---- rows --------------------------------------------------------------------------------

Columns table_columns(const Plan& plan, const Task& task, bool check) {
  Columns c{count_column("point", "index of the point in the plan (0-based; the table's order)")};
  for (const auto& k : plan.keys) c.push_back(task.input_column(k));
  if (check) plan.for_each_value([&](const std::string& key, const SceneValue& v) { task.check_input(key, v); });
  for (auto& o : task.outputs()) c.push_back(o);
  c.push_back(text_column("status",
                          "ok or at_rest (an answer); no_static_friction, law_blowup, accuracy_not_reached (its best "
                          "answer kept), solver_failure, bad_input (a value the model refuses) or error (docs/errors.md)"));
  c.push_back(text_column("message", "why the point failed; empty when ok"));
  return c;
}

std::vector<std::string> evaluate_row(const Plan& plan, const Task& task, std::size_t i) {
  std::vector<std::string> row{std::to_string(i)};
  const auto pt = plan.point(i);
  std::vector<SceneSetting> settings;
  settings.reserve(pt.size());
  for (std::size_t k = 0; k < pt.size(); ++k) {
    const auto& v = pt[k];
    row.push_back(v.kind() == KeyType::number ? csv_number(v.number()) : csv_quote(v.to_string()));
    if (k < plan.keys.size()) settings.emplace_back(plan.keys[k], v);
  }
  const std::size_t n_out = task.outputs().size();
  std::string status = "ok", message;
  try {
    auto out = task.evaluate_point(settings, i);
    for (auto& c : out.cells) row.push_back(std::move(c));
    status = std::move(out.status);
    message = std::move(out.message);
  } catch (const InputError& e) {
    status = "bad_input";
    message = e.what();
  } catch (const SolverError& e) {
    status = e.outcome();
    message = e.what();
  } catch (const std::exception& e) {
    status = "error";
    message = e.what();
  }
  row.resize(1 + plan.keys.size() + n_out);  // a failed point's outputs are empty (or its best answer's)
  for (char& ch : message)
    if (ch == '\n' || ch == '\r' || ch == '\t') ch = ' ';
  row.push_back(status);
  row.push_back(csv_quote(message));
  return row;
}

bool row_failed(const std::vector<std::string>& row) {
  return row.size() < 2 || (row[row.size() - 2] != "ok" && row[row.size() - 2] != "at_rest");
}

}  // namespace nanopush::sweep
