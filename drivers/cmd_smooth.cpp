// Reproduce step for thesis Fig 3.6: the smooth-surface nanobar, eight cases, both engines,
// against the exact pendulum solution.
#include <charconv>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "nanopush/outputs/trajectory_csv.hpp"
#include "nanopush/numerics/elliptic.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "nanopush/engines/engines.hpp"
#include "columns.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

void reproduce_fig3_6(ReproduceContext& ctx) {
  namespace fs = std::filesystem;
  const fs::path dir = ctx.out / "fig3_6";
  fs::create_directories(dir);
  const std::vector<std::string> cases = {"a", "b", "c", "d", "e", "f", "g", "h"};
  CsvWriter summary(dir / "summary.csv",
                    columns("smooth_summary"));
  plot::Figure fig;
  fig.title = "Fig 3.6: nanobar pushed on a smooth surface (theta against t; C++ and F77 engines)";
  fig.rows = 4;
  fig.cols = 2;
  fig.width = 1200;
  fig.height = 1400;
  plot::Figure errfig;
  errfig.title = "Fig 3.6: errors against the exact pendulum, and C++ against F77 (rtol 1e-12)";
  plot::Panel errpanel;
  errpanel.xlabel = "t [ns]";
  errpanel.ylabel = "|theta - theta_exact| [rad]";
  errpanel.logy = true;
  errpanel.extra = "set key outside right";
  // The C++ and F77 curves of Fig 3.6 coincide: their difference gets a panel of its own.
  plot::Panel devpanel = errpanel;
  devpanel.title = "|theta_C++ - theta_F77| (exact zeros drawn at 1e-18)";
  devpanel.ylabel = "|theta_C++ - theta_F77| [rad]";
  errfig.rows = 2;
  errfig.height = 1100;
  std::ostringstream table;
  table << "| case | theta0 [rad] | max err C++ [rad] | max err F77 [rad] | max C++-F77 [rad] | RHS evals C++ / F77 | "
           "accepted / rejected |\n|---|---|---|---|---|---|---|\n";
  for (const auto& c : cases) {
    const Scene sc = load_scene(scenes_dir() / "thesis" / ("fig3_6" + c + ".toml"));
    RunSettings cx, fo;
    cx.engine = Engine::cxx;
    cx.method = Method::faithful;
    fo.engine = Engine::f77;
    cx.error_estimate = fo.error_estimate = false;  // judged against the exact solution
    const Trajectory tc = run_engine(sc, cx);
    const Trajectory tf = run_engine(sc, fo);
    const std::string scene_id = "thesis/fig3_6" + c;
    write_trajectory_csv(tc, dir / (sc.name + "_cxx.csv"), scene_id);
    write_trajectory_csv(tf, dir / (sc.name + "_f77.csv"), scene_id);
    ctx.produced(dir / (sc.name + "_cxx.csv"));
    ctx.produced(dir / (sc.name + "_f77.csv"));
    const Pendulum<double> ex(sc.push.theta_equilibrium(), sc.initial[kTheta], sc.push.force * sc.push.lever(),
                              sc.inertia);
    const double Fd = sc.push.force * sc.push.lever();
    auto energy = [&](const TrajectoryRow& r) {
      return 0.5 * sc.inertia * r[col::omega] * r[col::omega] - Fd * std::cos(r[col::theta] - sc.push.theta_equilibrium());
    };
    CsvWriter err(dir / (sc.name + "_error.csv"),
                  columns("smooth_error"),
                  scene_id);
    double ec = 0, ef = 0, dev = 0, drift = 0;
    for (std::size_t i = 0; i < tc.rows.size(); ++i) {
      const double t = tc.rows[i][col::t], th = ex.theta(t);
      const double a = std::fabs(tc.rows[i][col::theta] - th), b = std::fabs(tf.rows[i][col::theta] - th);
      ec = std::max(ec, a);
      ef = std::max(ef, b);
      dev = std::max(dev, std::fabs(tc.rows[i][col::theta] - tf.rows[i][col::theta]));
      drift = std::max(drift, std::fabs(energy(tc.rows[i]) - energy(tc.rows[0])) / Fd);
      err.row({t, th, a, b, std::fabs(tc.rows[i][col::theta] - tf.rows[i][col::theta])});
    }
    err.commit();
    ctx.produced(dir / (sc.name + "_error.csv"));
    summary.row(sc.name, {sc.initial[kTheta], sc.push.theta_equilibrium(), ex.k == 0 ? 0.0 : ex.period(), ec, ef, dev,
                          drift, double(tc.stats.nfcn), double(tf.stats.nfcn), double(tc.stats.naccpt),
                          double(tf.stats.naccpt), double(tc.stats.nrejct), double(tf.stats.nrejct)});
    // theta0 with all its digits (shortest round-trip form), not through `table`, whose
    // precision the error columns set to 2 (that leak printed 1.25 as "1.2").
    char th0[32];
    const auto th0_end = std::to_chars(th0, th0 + sizeof th0, sc.initial[kTheta]).ptr;
    table << "| " << c << " | " << std::string(th0, th0_end) << " | " << std::scientific << std::setprecision(2) << ec << " | "
          << ef << " | " << dev << " | " << std::defaultfloat << tc.stats.nfcn << " / " << tf.stats.nfcn << " | "
          << tc.stats.naccpt << " / " << tc.stats.nrejct << " |\n";
    if (ec > 1e-10) ctx.failures.push_back("fig3_6" + c + ": C++ theta error " + fmt(ec) + " > 1e-10 rad");
    if (ef > 1e-10) ctx.failures.push_back("fig3_6" + c + ": F77 theta error " + fmt(ef) + " > 1e-10 rad");
    if (tc.stats.nfcn != tf.stats.nfcn)
      ctx.failures.push_back("fig3_6" + c + ": RHS counts differ, C++ faithful " + std::to_string(tc.stats.nfcn) +
                             " vs F77 " + std::to_string(tf.stats.nfcn));
    if (dev > 1e-12) ctx.failures.push_back("fig3_6" + c + ": C++ and F77 differ by " + fmt(dev) + " rad in theta");
    if (drift > 1e-10) ctx.failures.push_back("fig3_6" + c + ": energy drift " + fmt(drift) + " > 1e-10");

    plot::Panel p;
    p.title = "(" + c + ") theta0 = " + fmt(sc.initial[kTheta]) + " rad" + (c == "h" ? ", yn = 0" : "");
    p.xlabel = "t [ns]";
    p.ylabel = "theta [rad]";
    if (c == "g") p.extra = "set format y '%.7f'";
    p.series.push_back({dir / (sc.name + "_cxx.csv"), "($1*1e9)", "4", "C++", "lines lw 2 lc rgb '#1f77b4'"});
    p.series.push_back({dir / (sc.name + "_f77.csv"), "($1*1e9)", "4", "F77", "lines lw 1 dt 2 lc rgb '#d62728'"});
    fig.panels.push_back(p);
    // Zero errors cannot go on a log axis: plot max(err, 1e-18).
    errpanel.series.push_back({dir / (sc.name + "_error.csv"), "($1*1e9)", "($3 > 1e-18 ? $3 : 1e-18)", "(" + c + ")",
                               "lines lw 1.5"});
    devpanel.series.push_back({dir / (sc.name + "_error.csv"), "($1*1e9)", "($5 > 1e-18 ? $5 : 1e-18)", "(" + c + ")",
                               "lines lw 1.5"});
  }
  summary.commit();
  ctx.produced(dir / "summary.csv");
  const auto fig_path = plot::render(fig, dir / "fig3_6.png");
  ctx.produced(fig_path);
  errpanel.title = "|theta - theta_exact|, C++ faithful engine";
  errfig.panels.push_back(errpanel);
  errfig.panels.push_back(devpanel);
  const auto err_path = plot::render(errfig, dir / "fig3_6_error.png");
  ctx.produced(err_path);

  ctx.report << "## Fig 3.6: nanobar on a smooth surface (docs/models.md §A)\n\n"
             << "Eight cases, push F = 5e-6 N along +X at the thesis point (xn, yn) = (27.5, 45) nm, i.e. body point\n"
             << "(27.5, -45) nm; m = 0.623425e-18 kg; rtol = 1e-12 with tolerances scaled per state component.\n"
             << "The exact solution is a pendulum about theta* = pi/2 - atan(xn/yn) = "
             << std::setprecision(10) << Push::from_thesis(5e-6, 0, 27.5e-9, 45e-9).theta_equilibrium()
             << " rad (the thesis prints 1.022246, truncated),\nwith Jacobi sn computed by the AGM. Errors are the "
                "maximum over the 401 samples in [0, 1.6 ns].\n\n"
             << table.str() << "\n![Fig 3.6](fig3_6/" << fig_path.filename().string() << ")\n\n![errors](fig3_6/"
             << err_path.filename().string() << ")\n\n"
             << "Case (g) starts at the printed theta0 = 1.022246 rad, 9.2e-7 rad below theta*, so it swings with that\n"
             << "amplitude instead of translating exactly; (h) is an exact translation (theta = 0 to the last bit).\n\n";
}

RegisterReproduce step{{"fig3_6", "smooth-surface nanobar, eight cases, both engines vs the exact pendulum", 10,
                        reproduce_fig3_6}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
