// The F77 engine (BSINT through the bind(C) bridge) and the choice between engines.
#include "nanopush/engines/engines.hpp"

#include "nanopush/engines/accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "f77_bsint.h"
#include "f77_rough.h"
#include "nanopush/models/rigid_body.hpp"
#include "nanopush/models/rough_bar.hpp"

namespace nanopush {

Trajectory run_f77(const Scene& sc, const ResolvedSettings& s) {
  Trajectory tr;
  const bool printed = sc.rough() && s.law == Law::printed;
  tr.engine_label = sc.rough() ? (printed ? "f77-printed" : "f77-thesis") : "f77";
  const int n = sc.rough() ? kRoughStateSize : kStateSize;
  tr.rtol = s.rtol;
  tr.atol = sc.atol_vector(s.rtol, s.atol, n);
  const auto tout = sc.output_times();
  if (sc.rough() && starts_stuck(sc)) {  // the sign law cannot hold it: no 100,000 steps of chatter
    tr.rows.push_back(make_row(0.0, sc.initial.data()));
    tr.work_push.push_back(0.0);
    tr.work_fric.push_back(0.0);
    tr.outcome = Outcome::no_static_friction;
    tr.outcome_message =
        no_static_friction_message(sc, s.law, 0.0, sc.initial[kX], sc.initial[kY], sc.initial[kTheta]);
    return tr;
  }
  std::vector<double> yout(tout.size() * static_cast<std::size_t>(n));
  std::vector<double> y(static_cast<std::size_t>(n), 0.0);
  std::copy(sc.initial.begin(), sc.initial.end(), y.begin());
  int nstat[3] = {0, 0, 0};
  int st;
  const int maxstp = static_cast<int>(std::min<long>(sc.solver.max_steps, 2000000000L));
  if (sc.rough()) {
    const double params[12] = {sc.mass,       sc.inertia,    sc.push.force, sc.push.beta,
                               sc.push.pbx,   sc.push.pby,   sc.geometry.a, sc.geometry.b,
                               sc.friction_limit(), 0.0, 0.0, 0.0};
    st = np_f77_bsint_rough_bar_law(n, 0.0, y.data(), static_cast<int>(tout.size()), tout.data(), yout.data(),
                                    s.rtol, tr.atol.data(), sc.solver.h0, sc.solver.hmax, 8, 1, maxstp, params,
                                    printed ? 1 + printed_reading_index(sc.surface.printed) : 0, nstat);
  } else {
    const double params[6] = {sc.mass, sc.inertia, sc.push.force, sc.push.beta, sc.push.pbx, sc.push.pby};
    st = np_f77_bsint_smooth_bar(n, 0.0, y.data(), static_cast<int>(tout.size()), tout.data(), yout.data(), s.rtol,
                                 tr.atol.data(), sc.solver.h0, sc.solver.hmax, 8, 1, maxstp, params, nstat);
  }
  tr.stats.status = static_cast<BsStatus>(st);
  tr.stats.nfcn = nstat[0];
  tr.stats.naccpt = nstat[1];
  tr.stats.nrejct = nstat[2];
  RoughBarModel model = rough_model(sc);
  model.printed = printed;
  model.f77_forms = true;  // the friction columns as the F77 routine evaluates them
  // Outputs reached: on failure BSINT leaves later columns untouched; y holds the state at the
  // last output reached, so count the columns by comparing times reached.
  std::size_t reached = tout.size();
  if (st != 0) {
    tr.stats.message = std::string("F77 BSINT returned status ") + std::to_string(st) + " (" +
                       to_string(static_cast<BsStatus>(st)) + ")";
    reached = 0;
    for (std::size_t i = 0; i < tout.size(); ++i) {
      bool same = true;
      for (int c = 0; c < n; ++c) same = same && yout[i * static_cast<std::size_t>(n) + static_cast<std::size_t>(c)] == y[static_cast<std::size_t>(c)];
      if (same) reached = i + 1;
    }
  }
  for (std::size_t i = 0; i < reached; ++i) {
    const double* yy = &yout[i * static_cast<std::size_t>(n)];
    if (sc.rough()) {
      tr.rows.push_back(make_row(tout[i], yy, model.friction(yy[kTheta], yy[kVx], yy[kVy], yy[kOmega])));
      tr.work_push.push_back(yy[kWorkPush]);
      tr.work_fric.push_back(yy[kWorkFric]);
    } else {
      tr.rows.push_back(make_row(tout[i], yy));
    }
  }
  if (!tr.rows.empty()) tr.stats.t_reached = tr.rows.back()[col::t];
  if (s.progress) s.progress(1.0);
  return tr;
}

namespace {

/// A failure at a stiff start or a stiff run down to rest: before the first output, or with the
/// speed |v| + |omega| L/2 falling over the last outputs at a rate that reaches zero within
/// kRunDownOutputs more of them.
constexpr double kRunDownOutputs = 10;
bool stiff_failure(const Scene& scene, const Trajectory& tr) {
  const std::size_t n = tr.rows.size();
  if (n <= 1) return true;
  auto speed = [&](const TrajectoryRow& r) {
    return std::hypot(r[col::vx], r[col::vy]) + std::fabs(r[col::omega]) * 0.5 * scene.length;
  };
  const double s1 = speed(tr.rows[n - 1]), s0 = speed(tr.rows[n - 2]);
  return s1 < s0 && s1 <= kRunDownOutputs * (s0 - s1);
}

}  // namespace

Trajectory run_resolved(const Scene& scene, const ResolvedSettings& s) {
  ResolvedSettings keep = s;
  keep.allow_partial = true;
  Trajectory tr = finish_run(scene, keep, s.engine == Engine::f77 ? run_f77(scene, s) : run_cxx(scene, s));
  // Method auto under the coulomb law: a push just outside the limit surface starts so slowly
  // that the velocity's direction relaxes at mu N / (m |V|), stiff while |V| is tiny, and the
  // explicit Bulirsch-Stoer spends its step budget in the first picoseconds. CVODE's BDF copes:
  // hand the scene over to it (its cost includes the attempt). The same stiffness returns where
  // a slide runs down to rest. Only a failure before the first output after t = 0, or one where
  // the body was slowing to rest within a few outputs, is such a case; another (a bar spinning
  // thousands of turns) would cost CVODE far more than the budget the scene gave modern.
  // The thesis law slides as the coulomb law does (the same wrench while V != 0): its stiff
  // start goes to CVODE's coulomb-law integration too, kept where that run never comes to rest
  // after t = 0 (so it is the thesis law's trajectory).
  const bool thesis = s.law == Law::thesis && (s.method == Method::modern || s.method == Method::dop853);
  if (tr.outcome == Outcome::solver_failure && s.method_automatic && s.engine == Engine::cxx && scene.rough() &&
      ((s.law == Law::coulomb && s.method == Method::modern) || thesis) && stiff_failure(scene, tr)) {
    ResolvedSettings c = keep;
    handed_over_settings(c);
    Trajectory tc = finish_run(scene, c, run_cxx(scene, c));
    // Under the thesis law: the first rest after t = 0 ends the trajectory it shares with the
    // coulomb law. Stuck there, the thesis law has no static friction to hold it (classified);
    // sliding off, the two laws part (the failure stands).
    const auto rest = std::find_if(tc.events.begin(), tc.events.end(), [](const StickEventRecord& e) { return e.t > 0.0; });
    if (is_answer(tc.outcome) && (s.law == Law::coulomb || rest == tc.events.end() || rest->stuck)) {
      tc.stats.nfcn += tr.stats.nfcn;
      tc.handed_over = tr.outcome_message;
      if (thesis) {
        tc.engine_label = "cxx-cvode-thesis";
        if (rest != tc.events.end()) {
          while (tc.rows.size() > 1 && tc.rows.back()[col::t] > rest->t) tc.rows.pop_back();
          tc.work_push.resize(std::min(tc.work_push.size(), tc.rows.size()));
          tc.work_fric.resize(std::min(tc.work_fric.size(), tc.rows.size()));
          const auto& r = tc.rows.back();
          tc.outcome = Outcome::no_static_friction;
          tc.outcome_message = no_static_friction_message(scene, s.law, rest->t, r[col::x], r[col::y], r[col::theta]);
          tc.complete = false;
          tc.events.erase(rest, tc.events.end());
        }
      }
      return tc;
    }
  }
  return tr;
}

void handed_over_settings(ResolvedSettings& s) {
  s.method = Method::cvode;
  s.law = Law::coulomb;
}

Trajectory run_engine(const Scene& scene, const RunSettings& settings) {
  const ResolvedSettings s = resolve_settings(scene, settings);
  Trajectory tr = s.accuracy > 0 ? run_to_accuracy(scene, settings) : run_estimated(scene, s);
  return finish_run(scene, s, std::move(tr));
}

}  // namespace nanopush
