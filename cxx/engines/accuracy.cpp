// The error estimate of a run and the runs that answer to an accuracy (docs/accuracy.md).
#include "nanopush/engines/accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "nanopush/engines/engines.hpp"
#include "nanopush/numerics/bulirsch_stoer.hpp"
#include "nanopush/numerics/dop853.hpp"
#include "nanopush/numerics/error.hpp"

namespace nanopush {

namespace {

/// The tightest rtol a method reaches in a precision (the floors resolve_settings enforces;
/// 100 eps for the methods with clipped steps, where rounding takes over).
double rtol_floor(const ResolvedSettings& s) {
  const double eps = s.precision == Precision::quad    ? static_cast<double>(num::epsilon<num::quad>())
                     : s.precision == Precision::long_ ? static_cast<double>(num::epsilon<long double>())
                                                       : std::numeric_limits<double>::epsilon();
  if (s.engine == Engine::f77) return 100 * std::numeric_limits<double>::epsilon();
  switch (s.method) {
    case Method::dop853: return rtol_in_eps<double>(kDop853RtolEps);
    case Method::modern: return kDenseRtolEps * eps;
    case Method::cvode: return 1e-13;
    default: return 100 * eps;
  }
}

/// Path length of the centre of mass over the samples [m].
double distance(const Trajectory& tr) {
  double d = 0;
  for (std::size_t i = 1; i < tr.rows.size(); ++i)
    d += std::hypot(tr.rows[i][col::x] - tr.rows[i - 1][col::x], tr.rows[i][col::y] - tr.rows[i - 1][col::y]);
  return d;
}

double first_stick(const Trajectory& tr) {
  for (const auto& e : tr.events)
    if (e.stuck && e.t > 0.0) return e.t;
  return std::numeric_limits<double>::quiet_NaN();
}

/// The estimate of an at_rest answer: static friction holds the object from t = 0, found by
/// the rest analysis before any step, so the pose is the initial one whatever the tolerance:
/// exact, and a companion run would only repeat it.
ErrorEstimate exact_at_rest(const Scene& scene) {
  ErrorEstimate e;
  e.available = true;
  e.norm = e.x = e.y = e.theta = e.trajectory = 0;
  e.length_scale = scene.length;
  e.basis = "exact";
  e.note = "at rest from t = 0 (no step taken): the initial pose is exact";
  return e;
}

}  // namespace

double pose_error_norm(const TrajectoryRow& a, const TrajectoryRow& b, double length_scale) {
  return std::max({std::fabs(a[col::x] - b[col::x]) / length_scale, std::fabs(a[col::y] - b[col::y]) / length_scale,
                   std::fabs(a[col::theta] - b[col::theta])});
}

ErrorEstimate estimate_from(const Scene& scene, const Trajectory& answer, const Trajectory& reference) {
  ErrorEstimate e;
  e.companion = reference.engine_label;
  e.companion_rtol = reference.rtol;
  e.nfcn = reference.nfcn_total();
  if (!reference.complete || !is_answer(reference.outcome)) {
    e.note = "the companion run did not finish (" + to_string(reference.outcome) + ": " + reference.outcome_message + ")";
    return e;
  }
  if (reference.rows.size() != answer.rows.size() || answer.rows.empty()) {
    e.note = "the companion run has other output times";
    return e;
  }
  e.available = true;
  e.length_scale = std::max(scene.length, distance(reference));
  const auto& a = answer.rows.back();
  const auto& b = reference.rows.back();
  e.x = std::fabs(a[col::x] - b[col::x]);
  e.y = std::fabs(a[col::y] - b[col::y]);
  e.theta = std::fabs(a[col::theta] - b[col::theta]);
  // The reference is not exact: no estimate claims less than its tolerance (an answer far more
  // accurate than its own rtol can otherwise meet a companion with an error of the same size,
  // and the difference cancels: fig3_6e faithful at rtol 1e-9 is 5e-12 off, modern at 1e-11 too).
  const double floor = reference.rtol;
  e.norm = std::max(pose_error_norm(a, b, e.length_scale), floor);
  e.trajectory = floor;
  for (std::size_t i = 0; i < answer.rows.size(); ++i)
    e.trajectory = std::max(e.trajectory, pose_error_norm(answer.rows[i], reference.rows[i], e.length_scale));
  const double ta = first_stick(answer), tb = first_stick(reference);
  if (std::isnan(ta) != std::isnan(tb))
    e.t_stick = std::numeric_limits<double>::infinity();  // one sticks, the other does not
  else if (!std::isnan(ta))
    e.t_stick = std::fabs(ta - tb);
  return e;
}

ResolvedSettings companion_settings(const Scene& scene, const ResolvedSettings& s, std::string& note) {
  ResolvedSettings c = s;
  c.allow_partial = true;
  c.progress = {};
  c.error_estimate = false;
  c.accuracy = 0;
  c.rtol = s.rtol / kCompanionFactor;
  if (s.atol > 0) c.atol = s.atol / kCompanionFactor;  // 0: scaled from rtol
  // The faithful method (and the F77 engine) clip their steps at the output times: where the
  // output spacing, not the tolerance, sets the step, a tighter rtol repeats the same steps and
  // the difference says nothing. Their companion is the modern method (free steps, dense output).
  if (c.engine == Engine::f77 || c.method == Method::faithful) {
    c.engine = Engine::cxx;
    c.method = Method::modern;
  }
  if (c.method == Method::dop853 && c.rtol < rtol_floor(c)) c.method = Method::modern;
  // At the floor of double, more digits where the right-hand side runs in them (smooth scenes;
  // rough ones under the thesis and coulomb laws with the modern method).
  if (c.rtol < rtol_floor(c) && c.precision != Precision::quad &&
      extended_precision_obstacle(scene.rough(), c.law, c.engine, c.method).empty()) {
    c.precision = c.precision == Precision::double_ ? Precision::long_ : Precision::quad;
    if (c.rtol < rtol_floor(c)) c.precision = Precision::quad;
  }
  if (c.rtol < rtol_floor(c)) {
    c.rtol = rtol_floor(c);
    if (c.rtol > s.rtol / 10)
      note = "the companion run could not be tighter than rtol " + fmt(c.rtol) + " (the floor of " +
             to_string(c.method) + " in " + to_string(c.precision) + "): the estimate is a lower bound";
  }
  return c;
}

Trajectory run_estimated(const Scene& scene, const ResolvedSettings& s) {
  Trajectory tr = run_resolved(scene, s);
  if (!s.error_estimate || !is_answer(tr.outcome)) return tr;
  if (tr.outcome == Outcome::at_rest) {
    tr.error = exact_at_rest(scene);
    return tr;
  }
  std::string note;
  ResolvedSettings used = s;
  if (!tr.handed_over.empty()) handed_over_settings(used);
  const ResolvedSettings c = companion_settings(scene, used, note);
  const Trajectory ref = run_resolved(scene, c);
  tr.error = estimate_from(scene, tr, ref);
  if (!note.empty()) tr.error.note = note;
  return tr;
}

namespace {

/// Three significant digits, for notes.
std::string short_number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

/// Whether a run resolved as `n` may be the answer to one asked as `asked`: the engine is the
/// one asked; the method too, unless auto chose it; the precision may rise only where none was
/// asked for. (The companion of the F77 engine and of faithful is modern: it checks their
/// answers, it cannot replace them.)
bool may_answer(const ResolvedSettings& n, const ResolvedSettings& asked, const RunSettings& settings) {
  return n.engine == asked.engine && (asked.method_automatic || n.method == asked.method) &&
         (!settings.precision || n.precision == asked.precision);
}

/// The asked configuration `s` at the next rtol, kCompanionFactor tighter, in more digits where
/// none were asked for and the model runs in them; nullopt below the floor of what may answer.
std::optional<ResolvedSettings> tighter_in_kind(const Scene& scene, const ResolvedSettings& s, const RunSettings& settings) {
  ResolvedSettings t = s;
  t.rtol = s.rtol / kCompanionFactor;
  if (s.atol > 0) t.atol = s.atol / kCompanionFactor;
  if (t.rtol < rtol_floor(t) && !settings.precision && t.precision != Precision::quad && t.engine == Engine::cxx &&
      extended_precision_obstacle(scene.rough(), t.law, t.engine, t.method).empty()) {
    t.precision = t.precision == Precision::double_ ? Precision::long_ : Precision::quad;
    if (t.rtol < rtol_floor(t)) t.precision = Precision::quad;
  }
  if (t.rtol < rtol_floor(t)) return std::nullopt;
  return t;
}

}  // namespace

Trajectory run_to_accuracy(const Scene& scene, const RunSettings& settings) {
  RunSettings at = settings;
  at.accuracy = 0;
  at.error_estimate = false;
  at.allow_partial = true;
  at.rtol = resolve_settings(scene, settings).accuracy;
  const ResolvedSettings first = resolve_settings(scene, at);
  const double wanted = resolve_settings(scene, settings).accuracy;
  ResolvedSettings cur_s = first;
  Trajectory best = run_resolved(scene, first);
  if (!best.handed_over.empty()) handed_over_settings(cur_s);
  std::int64_t spent = best.stats.nfcn;
  int runs = 1;
  ErrorEstimate best_error;
  bool reached = false;
  if (best.outcome == Outcome::at_rest) {
    best_error = exact_at_rest(scene);
    reached = true;
  }
  // Each pair 100 times tighter should estimate an error some 10-100 times smaller. Where it
  // does not fall by half near double's rounding (the estimate at most 1e-12), the error is
  // bounded by what stays in double whatever the state's precision (event instants, output
  // times, the rest direction): tightening on, into long and quad, would cost minutes and
  // reach nothing. (Larger estimates can stall for several pairs and then fall: chaotic
  // scenes of bench-accuracy at E = 1e-4 do; they are left to tighten.)
  double lowest = std::numeric_limits<double>::infinity();
  const auto stalled = [&](const ErrorEstimate& e, const std::string& rtol_text) {
    const bool stall = e.norm > 0.5 * lowest && e.norm <= 1e-12;
    if (stall)
      best_error.note = "the estimate stopped falling with rtol (" + short_number(lowest) + ", then " +
                        short_number(e.norm) + " at rtol " + rtol_text +
                        "): near double's rounding the error is bounded by what stays in double (event instants, "
                        "output times)";
    lowest = std::min(lowest, e.norm);
    return stall;
  };
  while (is_answer(best.outcome) && !reached) {
    std::string note;
    const ResolvedSettings next_s = companion_settings(scene, cur_s, note);
    if (!(next_s.rtol < cur_s.rtol) && next_s.precision == cur_s.precision) {
      best_error.note = "rtol cannot go below " + fmt(cur_s.rtol) + " (the floor of " + to_string(cur_s.method) +
                        " in " + to_string(cur_s.precision) + ")";
      break;
    }
    Trajectory next = run_resolved(scene, next_s);
    spent += next.stats.nfcn;
    ++runs;
    ErrorEstimate e = estimate_from(scene, best, next);
    if (!e.available) {  // keep the estimate of the last pair that finished
      if (best_error.available)
        best_error.note = e.note;
      else
        best_error = e;
      break;
    }
    if (!may_answer(next_s, first, settings)) {
      // The companion is another configuration (the F77 engine's and faithful's is modern; an
      // asked dop853 or precision is kept): it checks `best`, the answer stays `best`, with the
      // companion's estimate, and the next try is the asked configuration, tighter.
      if (!note.empty()) e.note = note;
      best_error = e;
      if (e.norm <= wanted) {
        reached = true;
        break;
      }
      if (stalled(e, short_number(cur_s.rtol))) break;
      const std::optional<ResolvedSettings> t = tighter_in_kind(scene, cur_s, settings);
      if (!t) {
        best_error.note = "rtol cannot go below " + fmt(cur_s.rtol) + " in the configuration asked (" +
                          (first.engine == Engine::f77 ? std::string("the F77 engine") : to_string(cur_s.method)) +
                          " in " + to_string(cur_s.precision) + ")";
        break;
      }
      Trajectory again = run_resolved(scene, *t);
      spent += again.stats.nfcn;
      ++runs;
      best = std::move(again);
      cur_s = *t;
      if (!best.handed_over.empty()) handed_over_settings(cur_s);
      continue;
    }
    e.basis = "looser";  // the answer will be `next`: the run it is compared with is `best`
    e.companion = best.engine_label;
    e.companion_rtol = best.rtol;
    best = std::move(next);
    best_error = e;
    cur_s = next_s;
    if (e.norm <= wanted) {
      reached = true;
      break;
    }
    if (stalled(e, short_number(e.companion_rtol))) break;
  }
  best_error.nfcn = spent - best.stats.nfcn;
  best.error = best_error;
  best.accuracy = {wanted, reached, best.rtol, runs};
  if (!reached && is_answer(best.outcome)) {
    best.outcome = Outcome::accuracy_not_reached;
    best.outcome_message = "the estimated error " +
                           (best_error.available ? fmt(best_error.norm) : std::string("(none)")) +
                           " of the final pose is above the accuracy asked, " + fmt(wanted) +
                           (best_error.note.empty() ? "" : ": " + best_error.note);
  }
  return best;
}

}  // namespace nanopush
