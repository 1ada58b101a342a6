// push.mode = tip in the C++ engine: the quasi-static tip push (models/tip_push.hpp) or the
// dynamic one (models/tip_dynamic.hpp), as tip.model chooses (docs/tip.md), as a Trajectory
// with the tip's columns and contact events.
#include <cmath>

#include "nanopush/models/tip_dynamic.hpp"
#include "nanopush/models/tip_push.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush {

namespace {

void add_rows(Trajectory& tr, const tip::TipRunResult& run) {
  tr.rows.reserve(run.rows.size());
  tr.tip.reserve(run.rows.size());
  for (const tip::TipRow& r : run.rows) {
    tr.rows.push_back({r.t, r.x, r.y, r.theta, r.vx, r.vy, r.omega, r.fx, r.fy, r.mf});
    tr.tip.push_back({r.tip_x, r.tip_y, r.tip_fx, r.tip_fy, static_cast<int>(r.contact)});
    tr.work_push.push_back(r.work_tip);
    tr.work_fric.push_back(r.work_fric);
  }
  tr.tip_events = run.events;
  tr.stats.nfcn = run.nfcn;
  tr.stats.naccpt = run.steps;
}

}  // namespace

Trajectory run_cxx_tip(const Scene& sc, const ResolvedSettings& s) {
  if (sc.tip_model_run() == TipModel::dynamic) {
    Trajectory tr;
    tr.engine_label = "cxx-tip-dynamic";
    tr.rtol = s.rtol;
    const auto& in = sc.initial;
    const tip::DynamicRunResult run =
        tip::run_dynamic(sc.geometry, sc.friction_limit(), {sc.mass, sc.inertia, sc.tip_stiffness}, sc.tip, in[kX],
                         in[kY], in[kTheta], sc.solver.t_end, sc.solver.samples, s.rtol, sc.solver.max_steps);
    add_rows(tr, run.run);
    tr.stats.t_reached = sc.solver.t_end;
    return tr;
  }
  Trajectory tr;
  tr.engine_label = "cxx-quasi-static";
  tr.rtol = s.rtol;
  const auto& in = sc.initial;
  const tip::TipRunResult run = tip::run_quasi_static(sc.geometry, sc.friction_limit(), sc.tip, in[kX], in[kY],
                                                      in[kTheta], sc.solver.t_end, sc.solver.samples, s.rtol);
  add_rows(tr, run);
  tr.stats.t_reached = sc.solver.t_end;
  return tr;
}

}  // namespace nanopush
