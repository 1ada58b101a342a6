#include "nanopush/engines/compare.hpp"

#include <algorithm>
#include <cmath>

#include "nanopush/engines/accuracy.hpp"
#include "nanopush/engines/engines.hpp"
#include "nanopush/numerics/error.hpp"

namespace nanopush {

namespace {

/// Column groups judged together in a convergence comparison: a vector's components share its
/// scale (the frame is arbitrary), so a component that stays near zero is not judged against
/// its own tiny range.
const std::vector<std::vector<std::size_t>>& column_groups() {
  static const std::vector<std::vector<std::size_t>> g = {{1, 2}, {3}, {4, 5}, {6}, {7, 8}, {9}};
  return g;
}

/// Largest vector norm of a group over both runs (the scale of its columns).
double group_scale(const std::vector<std::size_t>& g, const Trajectory& a, const Trajectory& b) {
  double s = 0;
  for (const Trajectory* t : {&a, &b})
    for (const auto& r : t->rows) {
      double n2 = 0;
      for (std::size_t c : g) n2 += r[c] * r[c];
      s = std::max(s, std::sqrt(n2));
    }
  return s;
}

/// max |a - b| over the samples of column c; NaN if any difference is NaN (never swallowed).
double max_diff(const Trajectory& a, const Trajectory& b, std::size_t c) {
  double m = 0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    const double d = std::fabs(a.rows[i][c] - b.rows[i][c]);
    if (std::isnan(d)) return d;
    m = std::max(m, d);
  }
  return m;
}

/// A verdict needs finite figures: the first column whose deviation, scale or error is not
/// finite makes the comparison unjudgeable (cannot_judge says which), never "agree".
void check_finite(EngineComparison& r) {
  for (const ColumnVerdict& v : r.columns) {
    for (double x : {v.scale, v.max_abs_diff, v.relative, v.error_cxx, v.error_f77, v.diff, v.diff_tight}) {
      if (!std::isfinite(x)) {
        r.agree = false;
        r.cannot_judge = "the deviation of column " + v.name + " is not finite (max |cxx - f77| = " +
                         fmt(v.max_abs_diff) + ", scale " + fmt(v.scale) +
                         "): a run left the finite numbers";
        return;
      }
    }
  }
}

void judge_same_steps(EngineComparison& r) {
  const auto& cols = trajectory_columns();
  const auto& units = trajectory_units();
  r.agree = true;
  for (std::size_t c = 1; c < cols.size(); ++c) {
    ColumnVerdict v;
    v.name = cols[c];
    v.unit = units[c];
    for (const Trajectory* t : {&r.cxx, &r.f77})
      for (const auto& row : t->rows) v.scale = std::max(v.scale, std::fabs(row[c]));
    v.max_abs_diff = max_diff(r.cxx, r.f77, c);
    v.relative = v.scale > 0 ? v.max_abs_diff / v.scale : v.max_abs_diff;
    v.ok = v.relative <= r.tolerance;
    r.agree = r.agree && v.ok;
    r.columns.push_back(std::move(v));
  }
}

void judge_convergence(EngineComparison& r) {
  const auto& cols = trajectory_columns();
  const auto& units = trajectory_units();
  r.agree = true;
  for (const auto& g : column_groups()) {
    const double scale = group_scale(g, r.f77, r.f77_tight);
    const double s = scale > 0 ? scale : 1.0;
    for (std::size_t c : g) {
      ColumnVerdict v;
      v.name = cols[c];
      v.unit = units[c];
      v.scale = scale;
      v.max_abs_diff = max_diff(r.cxx, r.f77, c);
      v.error_cxx = max_diff(r.cxx, r.cxx_tight, c) / s;
      v.error_f77 = max_diff(r.f77, r.f77_tight, c) / s;
      v.diff = v.max_abs_diff / s;
      v.diff_tight = max_diff(r.cxx_tight, r.f77_tight, c) / s;
      v.ok = v.diff_tight <= v.error_cxx + v.error_f77 + kCompareRoundingFloor;
      r.agree = r.agree && v.ok;
      r.columns.push_back(std::move(v));
    }
  }
}

/// Marks the comparison incomplete at the first run of `runs` that did not complete.
bool all_complete(EngineComparison& r, std::initializer_list<int> runs) {
  for (int i : runs) {
    r.failed_run = i;
    if (const Trajectory* t = r.failed(); !t->complete) {
      r.complete = false;
      r.cannot_judge = "the " + t->engine_label + " run" +
                       (i >= 2 ? " (the reference at rtol " + fmt(kCompareTightRtol) + ")" : std::string()) +
                       " did not complete: " + t->outcome_text();
      return false;
    }
  }
  r.failed_run = -1;
  return true;
}

}  // namespace

Law compare_law(const Scene& scene, std::optional<Law> law, bool* from_coulomb) {
  // The F77 engine implements the thesis and printed laws; a scene asking for the coulomb law
  // is compared under the thesis law unless the coulomb law is asked for, which has no F77 peer.
  if (from_coulomb) *from_coulomb = !law && scene.rough() && scene.surface.law == Law::coulomb;
  const Law l = law ? *law : (scene.surface.law == Law::coulomb ? Law::thesis : scene.surface.law);
  if (l == Law::coulomb)
    throw InputError("law", "coulomb",
                     "thesis or printed: the F77 engine implements only those. The coulomb law's independent "
                     "check is its CVODE cross-check: nanopush run " +
                         scene.name + " --law coulomb --method cvode, or nanopush.run(scene, law='coulomb', "
                         "method='cvode') (docs/rough.md)");
  return l;
}

EngineComparison compare_engines(const Scene& scene, const CompareSettings& cs) {
  if (scene.push_mode == PushMode::tip)
    throw InputError("scene", scene.name,
                     "a tip push: the F77 engine is the thesis' model and has no tip, so there is nothing to compare "
                     "with; its checks are the energy balance and the closed forms (docs/tip.md)");
  if (cs.method != Method::faithful && cs.method != Method::modern && cs.method != Method::dop853)
    throw InputError("method", to_string(cs.method),
                     "must be faithful, modern or dop853 (the C++ configuration compared)");
  // 0 is "judge by the method"; anything else must be a bound (a negative or NaN one read as
  // 0, an infinite one made every comparison agree).
  if (!(cs.tolerance >= 0 && std::isfinite(cs.tolerance)))
    throw InputError("tolerance", fmt(cs.tolerance),
                     "must be a finite number > 0 (largest max|diff|/max|value| per column), or 0 for the method's "
                     "default");
  EngineComparison r;
  r.law = compare_law(scene, cs.law, &r.law_from_coulomb);
  RunSettings a, b;
  a.engine = Engine::cxx;
  a.method = cs.method;
  b.engine = Engine::f77;
  a.law = b.law = r.law;
  a.precision = b.precision = Precision::double_;  // the F77 engine is REAL*8: compared in double
  a.rtol = b.rtol = cs.rtol;
  a.atol = b.atol = cs.atol;
  a.allow_partial = b.allow_partial = true;
  // The verdict has its own references (below): no companion runs for error estimates.
  a.error_estimate = b.error_estimate = false;
  a.accuracy = b.accuracy = 0;
  if (cs.accuracy > 0) {
    // The rtol at which the C++ configuration reaches the accuracy asked for; both engines run there.
    RunSettings want = a;
    want.accuracy = cs.accuracy;
    const Trajectory chosen = run_to_accuracy(scene, want);
    r.accuracy = chosen.accuracy;
    if (!chosen.accuracy.reached || !is_answer(chosen.outcome)) {
      r.cxx = chosen;
      r.complete = false;
      r.failed_run = 0;
      r.cannot_judge = "the accuracy asked for was not reached: " + chosen.outcome_text();
      return r;
    }
    a.rtol = b.rtol = chosen.accuracy.rtol_used;
  }
  r.rtol = resolve_settings(scene, a).rtol;
  r.cxx = run_engine(scene, a);
  r.f77 = run_engine(scene, b);
  if (!all_complete(r, {0, 1})) return r;
  if (r.cxx.rows.size() != r.f77.rows.size()) {
    r.same_length = false;
    r.agree = false;
    return r;
  }
  // The reference runs: the tightest rtol at which both engines still run in double. Not
  // rtol/100: the F77 engine's error is not monotone in rtol where it starts from rest (its
  // first step sees friction jump from 0 to mu N), e.g. fig3_16 is further off at 1e-12 than
  // at 1e-10; at 1e-14 both engines are within ~1e-12 of dop853 at 1e-13.
  if (cs.method == Method::faithful || cs.tolerance > 0 || r.rtol < 10 * kCompareTightRtol) {
    r.kind = CompareKind::same_steps;
    r.tolerance_from_tight = cs.method != Method::faithful && cs.tolerance <= 0;
    r.tolerance = cs.tolerance > 0 ? cs.tolerance : 100 * r.rtol;
    judge_same_steps(r);
    check_finite(r);
    return r;
  }
  r.kind = CompareKind::convergence;
  r.rtol_tight = kCompareTightRtol;
  RunSettings a2 = a, b2 = b;
  a2.rtol = b2.rtol = r.rtol_tight;
  if (cs.atol > 0) a2.atol = b2.atol = cs.atol * (r.rtol_tight / r.rtol);
  r.cxx_tight = run_engine(scene, a2);
  r.f77_tight = run_engine(scene, b2);
  if (!all_complete(r, {2, 3})) return r;
  judge_convergence(r);
  check_finite(r);
  return r;
}

}  // namespace nanopush
