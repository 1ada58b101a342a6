// The F77 engine (BSINT through the bind(C) bridge) and the choice between engines.
#include "nanopush/engines/engines.hpp"

#include "nanopush/engines/accuracy.hpp"

#include <algorithm>
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
    tr.outcome_message = no_static_friction_outcome(sc, s.law, 0.0);
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
                                    printed ? 1 : 0, nstat);
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

Trajectory run_resolved(const Scene& scene, const ResolvedSettings& s) {
  ResolvedSettings keep = s;
  keep.allow_partial = true;
  Trajectory tr = finish_run(scene, keep, s.engine == Engine::f77 ? run_f77(scene, s) : run_cxx(scene, s));
  // Method auto under the coulomb law: a push just outside the limit surface starts so slowly
  // that the velocity's direction relaxes at mu N / (m |V|), stiff while |V| is tiny, and the
  // explicit Bulirsch-Stoer spends its step budget in the first picoseconds. CVODE's BDF copes:
  // hand the scene over to it (its cost includes the attempt). Only a failure before the first
  // output after t = 0 is such a start; a later one (a bar spinning thousands of turns) would
  // cost CVODE far more than the budget the scene gave modern.
  if (tr.outcome == Outcome::solver_failure && s.method_automatic && s.method == Method::modern &&
      s.engine == Engine::cxx && scene.rough() && s.law == Law::coulomb && tr.rows.size() <= 1) {
    ResolvedSettings c = keep;
    c.method = Method::cvode;
    Trajectory tc = finish_run(scene, c, run_cxx(scene, c));
    if (is_answer(tc.outcome)) {
      tc.stats.nfcn += tr.stats.nfcn;
      tc.handed_over = tr.outcome_message;
      return tc;
    }
  }
  return tr;
}

Trajectory run_engine(const Scene& scene, const RunSettings& settings) {
  const ResolvedSettings s = resolve_settings(scene, settings);
  Trajectory tr = s.accuracy > 0 ? run_to_accuracy(scene, settings) : run_estimated(scene, s);
  return finish_run(scene, s, std::move(tr));
}

}  // namespace nanopush
