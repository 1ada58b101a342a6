// C API: scenes, runs and the engine comparison (bindings/nanopush.h) over nanopush::load_scene /
// parse_scene / run_engine / compare_engines.
#include <algorithm>
#include <limits>
#include <memory>

#include "capi_internal.hpp"
#include "nanopush/engines/compare.hpp"

using namespace nanopush::capi;

namespace {
// A trajectory's row count against the caller's buffer (rows it can hold).
void require_capacity(int capacity, std::size_t rows) {
  if (capacity < 0 || static_cast<std::size_t>(capacity) < rows)
    throw StatusError(NANOPUSH_BUFFER_TOO_SMALL, "capacity = " + std::to_string(capacity) + ": the trajectory has " +
                                                     std::to_string(rows) + " rows (query nanopush_trajectory_get_size)");
}
// A string of the trajectory into buffer[size]: its full length, or -1 on failure.
/// A text of the trajectory (`text` of it) into the caller's buffer: the length, or -1.
template <class Text>
int trajectory_string(nanopush_error error, nanopush_trajectory trajectory, Text text, char* buffer, int size) {
  int n = -1;
  guarded(error, [&] {
    require_handle(trajectory, "trajectory");
    n = copy_string(text(trajectory->trajectory), buffer, size);
    return NANOPUSH_OK;
  });
  return n;
}
}  // namespace

extern "C" {

nanopush_scene nanopush_load_scene(nanopush_error error, const char* path) {
  nanopush_scene out = nullptr;
  guarded(error, [&] {
    require_handle(path, "path");
    auto s = std::make_unique<nanopush_scene_s>();
    // The library names the file SCENE (the command line's argument): here it is path.
    s->scene = nanopush::bindings::with_argument_names({{"SCENE", "path"}}, [&] { return nanopush::load_scene(path); });
    out = s.release();
    return NANOPUSH_OK;
  });
  return out;
}

nanopush_scene nanopush_parse_scene(nanopush_error error, const char* toml_text, const char* source_name) {
  nanopush_scene out = nullptr;
  guarded(error, [&] {
    require_handle(toml_text, "toml_text");
    auto s = std::make_unique<nanopush_scene_s>();
    s->scene = nanopush::parse_scene(toml_text, source_name ? source_name : "<string>");
    out = s.release();
    return NANOPUSH_OK;
  });
  return out;
}

void nanopush_delete_scene(nanopush_scene* scene) { delete_handle(scene); }

int nanopush_scene_get_name(nanopush_error error, nanopush_scene scene, char* buffer, int size) {
  int n = -1;
  guarded(error, [&] {
    require_handle(scene, "scene");
    n = copy_string(scene->scene.name, buffer, size);
    return NANOPUSH_OK;
  });
  return n;
}

int nanopush_scene_set_real(nanopush_error error, nanopush_scene scene, const char* key, double value) {
  return guarded(error, [&] {
    require_handle(scene, "scene");
    require_handle(key, "key");
    scene->scene.set(key, nanopush::SceneValue(value));
    return NANOPUSH_OK;
  });
}

int nanopush_scene_set_string(nanopush_error error, nanopush_scene scene, const char* key, const char* value) {
  return guarded(error, [&] {
    require_handle(scene, "scene");
    require_handle(key, "key");
    require_handle(value, "value");
    scene->scene.set(key, nanopush::SceneValue::from_text(key, value));
    return NANOPUSH_OK;
  });
}

int nanopush_scene_get_info(nanopush_error error, nanopush_scene scene, double* t_end, int* samples,
                            double* mass, double* inertia, double* initial) {
  return guarded(error, [&] {
    require_handle(scene, "scene");
    const nanopush::Scene& sc = scene->scene;
    if (t_end) *t_end = sc.solver.t_end;
    if (samples) *samples = sc.solver.samples;
    if (mass) *mass = sc.mass;
    if (inertia) *inertia = sc.inertia;
    if (initial) std::copy(sc.initial.begin(), sc.initial.end(), initial);
    return NANOPUSH_OK;
  });
}

int nanopush_scene_get_push(nanopush_error error, nanopush_scene scene, double* push) {
  return guarded(error, [&] {
    require_handle(scene, "scene");
    require_handle(push, "push");
    const nanopush::Push& p = scene->scene.push;
    push[0] = p.force;
    push[1] = p.beta;
    push[2] = p.pbx;
    push[3] = p.pby;
    return NANOPUSH_OK;
  });
}

nanopush_trajectory nanopush_run_scene(nanopush_error error, nanopush_scene scene, const char* engine,
                                       const char* method, double rtol, double atol) {
  return nanopush_run_scene_ex(error, scene, engine, method, nullptr, rtol, atol);
}

nanopush_trajectory nanopush_run_scene_ex(nanopush_error error, nanopush_scene scene, const char* engine,
                                          const char* method, const char* law, double rtol, double atol) {
  return nanopush_run_scene_precision(error, scene, engine, method, law, nullptr, rtol, atol);
}

nanopush_trajectory nanopush_run_scene_precision(nanopush_error error, nanopush_scene scene, const char* engine,
                                                 const char* method, const char* law, const char* precision,
                                                 double rtol, double atol) {
  return nanopush_run_scene_accuracy(error, scene, engine, method, law, precision, rtol, atol, -1.0, -1);
}

nanopush_trajectory nanopush_run_scene_accuracy(nanopush_error error, nanopush_scene scene, const char* engine,
                                                const char* method, const char* law, const char* precision,
                                                double rtol, double atol, double accuracy, int error_estimate) {
  nanopush_trajectory out = nullptr;
  guarded(error, [&] {
    require_handle(scene, "scene");
    nanopush::RunSettings rs;
    rs.engine = nanopush::parse_optional_choice<nanopush::Engine>("engine", opt_string(engine));  // "" = the scene's
    rs.method = nanopush::parse_optional_choice<nanopush::Method>("method", opt_string(method));
    rs.law = nanopush::parse_optional_choice<nanopush::Law>("law", opt_string(law));
    rs.precision = nanopush::parse_optional_choice<nanopush::Precision>("precision", opt_string(precision));
    nanopush::require_finite("rtol", rtol);
    nanopush::require_finite("atol", atol);
    rs.rtol = rtol;
    rs.atol = atol;
    nanopush::require_finite("accuracy", accuracy);
    if (accuracy > 0) nanopush::require_range("accuracy", accuracy, nanopush::kAccuracyMin, nanopush::kAccuracyMax);
    rs.accuracy = accuracy < 0 ? -1.0 : accuracy;
    if (error_estimate > 1)
      throw nanopush::InputError("error_estimate", std::to_string(error_estimate),
                                 "must be 1 (estimate the error), 0 (do not) or < 0 (the scene's "
                                 "solver.error_estimate)");
    if (error_estimate >= 0) rs.error_estimate = error_estimate == 1;
    auto t = std::make_unique<nanopush_trajectory_s>();
    t->trajectory = nanopush::run_engine(scene->scene, rs);
    out = t.release();
    return NANOPUSH_OK;
  });
  return out;
}

int nanopush_compare(nanopush_error error, nanopush_scene scene, const char* method, const char* law, double rtol,
                     double atol, double tolerance, int* agree, int* kind, double* figures) {
  return guarded(error, [&] {
    require_handle(scene, "scene");
    require_handle(agree, "agree");
    nanopush::CompareSettings cs;
    if (!opt_string(method).empty()) cs.method = nanopush::parse_choice<nanopush::Method>("method", opt_string(method));
    cs.law = nanopush::parse_optional_choice<nanopush::Law>("law", opt_string(law));
    nanopush::require_finite("rtol", rtol);
    nanopush::require_finite("atol", atol);
    nanopush::require_finite("tolerance", tolerance);
    cs.rtol = rtol;
    cs.atol = atol;
    cs.tolerance = tolerance;
    const nanopush::EngineComparison r = nanopush::compare_engines(scene->scene, cs);
    if (const nanopush::Trajectory* t = r.failed())
      throw nanopush::SolverError(scene->scene.name + " (" + t->engine_label +
                                  (r.failed_run >= 2 ? ", reference run" : "") + "): " + t->outcome_text() +
                                      "; cannot judge: " + r.cannot_judge,
                                  to_string(t->outcome));
    if (!r.cannot_judge.empty())
      throw nanopush::SolverError(scene->scene.name + ": cannot judge: " + r.cannot_judge);
    *agree = r.agree ? 1 : 0;
    const bool same = r.kind == nanopush::CompareKind::same_steps;
    if (kind) *kind = same ? 0 : 1;
    if (figures)
      for (std::size_t c = 0; c < 9; ++c)
        figures[c] = c < r.columns.size() ? (same ? r.columns[c].relative : r.columns[c].diff_tight)
                                          : std::numeric_limits<double>::quiet_NaN();
    return NANOPUSH_OK;
  });
}

void nanopush_delete_trajectory(nanopush_trajectory* trajectory) { delete_handle(trajectory); }

int nanopush_trajectory_get_size(nanopush_error error, nanopush_trajectory trajectory, int* rows) {
  return guarded(error, [&] {
    require_handle(trajectory, "trajectory");
    require_handle(rows, "rows");
    *rows = static_cast<int>(trajectory->trajectory.rows.size());
    return NANOPUSH_OK;
  });
}

int nanopush_trajectory_get_data(nanopush_error error, nanopush_trajectory trajectory, int capacity,
                                 double* data) {
  return guarded(error, [&] {
    require_handle(trajectory, "trajectory");
    const auto& rows = trajectory->trajectory.rows;
    require_capacity(capacity, rows.size());
    if (!rows.empty()) require_handle(data, "data");
    static_assert(std::tuple_size_v<nanopush::TrajectoryRow> == NANOPUSH_TRAJECTORY_COLUMNS);
    for (std::size_t i = 0; i < rows.size(); ++i)
      std::copy(rows[i].begin(), rows[i].end(), data + NANOPUSH_TRAJECTORY_COLUMNS * i);
    return NANOPUSH_OK;
  });
}

int nanopush_trajectory_get_counts(nanopush_error error, nanopush_trajectory trajectory, int64_t* counts) {
  return guarded(error, [&] {
    require_handle(trajectory, "trajectory");
    require_handle(counts, "counts");
    const auto& st = trajectory->trajectory.stats;
    counts[0] = st.nfcn;
    counts[1] = st.naccpt;
    counts[2] = st.nrejct;
    return NANOPUSH_OK;
  });
}

int nanopush_trajectory_get_engine(nanopush_error error, nanopush_trajectory trajectory, char* buffer,
                                   int size) {
  return trajectory_string(
      error, trajectory, [](const nanopush::Trajectory& t) { return t.engine_label; }, buffer, size);
}

int nanopush_trajectory_get_error(nanopush_error error, nanopush_trajectory trajectory, double* estimate) {
  return guarded(error, [&] {
    require_handle(trajectory, "trajectory");
    require_handle(estimate, "estimate");
    const nanopush::Trajectory& tr = trajectory->trajectory;
    const nanopush::ErrorEstimate& e = tr.error;
    const double v[NANOPUSH_ERROR_SIZE] = {e.norm, e.x, e.y, e.theta, e.trajectory, tr.rtol,
                                           static_cast<double>(tr.nfcn_total())};
    std::copy(v, v + NANOPUSH_ERROR_SIZE, estimate);
    return NANOPUSH_OK;
  });
}

int nanopush_trajectory_get_outcome(nanopush_error error, nanopush_trajectory trajectory, char* buffer, int size) {
  int n = -1;
  guarded(error, [&] {
    require_handle(trajectory, "trajectory");
    n = copy_string(nanopush::to_string(trajectory->trajectory.outcome), buffer, size);
    return NANOPUSH_OK;
  });
  return n;
}

int nanopush_trajectory_get_precision(nanopush_error error, nanopush_trajectory trajectory, char* buffer,
                                      int size) {
  return trajectory_string(
      error, trajectory, [](const nanopush::Trajectory& t) { return nanopush::to_string(t.precision); }, buffer, size);
}

int nanopush_trajectory_get_state_extended(nanopush_error error, nanopush_trajectory trajectory, int capacity,
                                           double* hi, double* lo) {
  return guarded(error, [&] {
    require_handle(trajectory, "trajectory");
    const nanopush::Trajectory& tr = trajectory->trajectory;
    const std::size_t rows = tr.rows.size();
    require_capacity(capacity, rows);
    if (rows == 0) return NANOPUSH_OK;
    require_handle(hi, "hi");
    require_handle(lo, "lo");
    constexpr int ns = NANOPUSH_STATE_SIZE;
    static_assert(ns == nanopush::kStateSize);
    for (std::size_t k = 0; k < rows; ++k)
      for (int i = 0; i < ns; ++i) {
        const std::size_t at = static_cast<std::size_t>(ns) * k + static_cast<std::size_t>(i);
        if (tr.extended.empty()) {  // a double run: the state itself, exactly
          hi[at] = tr.rows[k][static_cast<std::size_t>(i) + 1];
          lo[at] = 0;
        } else {  // hi = the value rounded to double, lo = the remainder rounded to double
          const nanopush::num::quad v = tr.extended[k][static_cast<std::size_t>(i)];
          hi[at] = static_cast<double>(v);
          lo[at] = static_cast<double>(v - static_cast<nanopush::num::quad>(hi[at]));
        }
      }
    return NANOPUSH_OK;
  });
}

}  // extern "C"
