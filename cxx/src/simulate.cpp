#include "nanopush/simulate.hpp"

#include "f77_bsint.h"
#include "nanopush/error.hpp"
#include "nanopush/io.hpp"
#include "nanopush/rigid_body.hpp"

namespace nanopush {

RunSettings resolve_settings(const Scene& scene, RunSettings s) {
  if (s.engine.empty()) s.engine = scene.solver.engine;
  if (s.engine != "cxx" && s.engine != "f77") throw InputError("engine", s.engine, "must be cxx or f77");
  if (s.method.empty()) s.method = scene.solver.method;
  if (s.method != "faithful" && s.method != "modern") throw InputError("method", s.method, "must be faithful or modern");
  if (s.rtol == 0) s.rtol = scene.solver.rtol;
  require_range("rtol", s.rtol, 1e-30, 0.1);
  if (s.atol < 0) s.atol = scene.solver.atol;
  return s;
}

namespace {

TrajectoryRow make_row(double t, const double* y) {
  return {t, y[kX], y[kY], y[kTheta], y[kVx], y[kVy], y[kOmega], 0.0, 0.0, 0.0};
}

Trajectory run_cxx(const Scene& sc, const RunSettings& s) {
  Trajectory tr;
  tr.engine_label = "cxx-" + s.method;
  tr.rtol = s.rtol;
  tr.atol = sc.atol_vector(s.rtol, s.atol);
  auto opt = s.method == "modern" ? BsOptions<double>::modern(s.rtol, tr.atol)
                                  : BsOptions<double>::faithful(s.rtol, tr.atol);
  opt.h0 = sc.solver.h0;
  opt.hmax = sc.solver.hmax;
  BulirschStoer<double, kStateSize> bs(opt);
  const SmoothBarRhs rhs{sc.mass, sc.inertia, sc.push};
  const auto tout = sc.output_times();
  std::array<double, kStateSize> y = sc.initial;
  tr.rows.reserve(tout.size());
  const double n = static_cast<double>(tout.size());
  tr.stats = bs.integrate(rhs, 0.0, y.data(), std::span<const double>(tout), [&](std::size_t i, double t, const double* yy) {
    tr.rows.push_back(make_row(t, yy));
    if (s.progress) s.progress(static_cast<double>(i + 1) / n);
  });
  return tr;
}

Trajectory run_f77(const Scene& sc, const RunSettings& s) {
  Trajectory tr;
  tr.engine_label = "f77";
  tr.rtol = s.rtol;
  tr.atol = sc.atol_vector(s.rtol, s.atol);
  const auto tout = sc.output_times();
  std::vector<double> yout(tout.size() * kStateSize);
  std::array<double, kStateSize> y = sc.initial;
  const double params[6] = {sc.mass, sc.inertia, sc.push.force, sc.push.beta, sc.push.pbx, sc.push.pby};
  int nstat[3] = {0, 0, 0};
  const int st = np_f77_bsint_smooth_bar(kStateSize, 0.0, y.data(), static_cast<int>(tout.size()), tout.data(),
                                         yout.data(), s.rtol, tr.atol.data(), sc.solver.h0, sc.solver.hmax, 8, 1,
                                         100000, params, nstat);
  tr.stats.status = static_cast<BsStatus>(st);
  tr.stats.nfcn = nstat[0];
  tr.stats.naccpt = nstat[1];
  tr.stats.nrejct = nstat[2];
  if (st == 0) {
    for (std::size_t i = 0; i < tout.size(); ++i) tr.rows.push_back(make_row(tout[i], &yout[i * kStateSize]));
    tr.stats.t_reached = tout.back();
  } else {
    tr.stats.message = std::string("F77 BSINT returned status ") + std::to_string(st) + " (" +
                       to_string(static_cast<BsStatus>(st)) + ")";
  }
  if (s.progress) s.progress(1.0);
  return tr;
}

}  // namespace

Trajectory run_scene(const Scene& scene, const RunSettings& settings) {
  const RunSettings s = resolve_settings(scene, settings);
  Trajectory tr = s.engine == "f77" ? run_f77(scene, s) : run_cxx(scene, s);
  if (!tr.stats.ok())
    throw SolverError(scene.name + " (" + tr.engine_label + "): " + to_string(tr.stats.status) +
                      (tr.stats.message.empty() ? "" : ": " + tr.stats.message));
  return tr;
}

void write_trajectory_csv(const Trajectory& tr, const std::filesystem::path& path) {
  CsvWriter w(path, trajectory_columns());
  for (const auto& r : tr.rows) w.row(std::vector<double>(r.begin(), r.end()));
  w.commit();
}

}  // namespace nanopush
