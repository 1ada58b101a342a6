// nanopush run: integrate a scene with either engine (compare: cmd_compare.cpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <unistd.h>

#include "nanopush/scenes/engine_method.hpp"
#include "nanopush/outputs/trajectory_csv.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/engines/engines.hpp"
#include "cli_checks.hpp"
#include "registry.hpp"
#include "scene_args.hpp"
#include "sweep_output.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct RunOptions {
  std::string scene, engine, method, out, law, precision;
  std::vector<std::string> sets;  ///< --set KEY=VALUE
  double rtol = 0, atol = -1;
  double accuracy = -1;  ///< < 0: the scene's solver.accuracy
  bool no_estimate = false;
  bool quiet = false;
  bool keep_partial = false;
};

/// Progress on stderr for runs longer than a second, only on a terminal.
std::function<void(double)> progress_printer(const std::string& label) {
  if (!::isatty(2)) return {};
  auto start = std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
  auto last = std::make_shared<double>(0.0);
  return [start, last, label](double frac) {
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - *start).count();
    if (el > 1.0 && (el - *last > 0.5 || frac >= 1.0)) {
      *last = el;
      std::fprintf(stderr, "\r%s: %5.1f%% (%.1f s)%s", label.c_str(), 100 * frac, el, frac >= 1.0 ? "\n" : "");
    }
  };
}

void add_common(CLI::App& app, RunOptions& o) {
  app.add_option("SCENE", o.scene, "scene file, or a preset name such as fig3_6a (`nanopush presets`)")->required();
  add_set_option(app, o.sets);
  app.add_option("--rtol", o.rtol, "relative tolerance (default: the scene's solver.rtol)")->check(positive());
  app.add_option("--atol", o.atol,
                 "absolute tolerance, one value for every state component (default: the scene's; 0 = rtol times "
                 "each component's natural scale)")
      ->check(non_negative());
  add_accuracy_options(app, o.accuracy, o.no_estimate);
}

void print_summary(const Scene& sc, const Trajectory& tr, double seconds, std::ostream& os) {
  const auto& last = tr.rows.back();
  os << std::setprecision(10) << sc.name << " [" << tr.engine_label << "] rtol = " << tr.rtol << ", precision "
     << to_string(tr.precision) << (tr.precision == Precision::double_ ? "" : " (CSV values rounded to double)") << "\n"
     << "  t_end = " << last[col::t] << " s: x = " << last[col::x] << " m, y = " << last[col::y] << " m, theta = " << last[col::theta]
     << " rad, omega = " << last[col::omega] << " rad/s\n"
     << "  RHS evaluations " << tr.stats.nfcn << ", accepted steps " << tr.stats.naccpt << ", rejected steps "
     << tr.stats.nrejct << (tr.kinks_located > 0 ? ", kinks located " + std::to_string(tr.kinks_located) : std::string())
     << ", wall time " << std::setprecision(3)
     << (seconds < 1 ? seconds * 1e3 : seconds) << (seconds < 1 ? " ms\n" : " s\n");
  print_error_estimate(tr, os);
}

int run_cmd(const RunOptions& o) {
  const Scene sc = load_scene_arg(o.scene, o.sets);
  set_provenance_scene(o.scene);  // recorded in the CSV's sidecar
  if (!o.quiet && !sc.load_report.empty()) std::cerr << sc.name << ": " << sc.load_report;
  RunSettings rs;
  rs.engine = parse_optional_choice<Engine>("engine", o.engine);  // "" = the scene's
  rs.method = parse_optional_choice<Method>("method", o.method);
  rs.rtol = o.rtol;
  rs.atol = o.atol;
  rs.law = parse_optional_choice<Law>("law", o.law);
  rs.precision = parse_optional_choice<Precision>("precision", o.precision);
  rs.allow_partial = true;  // a failure is reported below (and its samples kept with --keep-partial)
  rs.progress = progress_printer(sc.name);
  rs.accuracy = o.accuracy;
  if (o.no_estimate) rs.error_estimate = false;
  check_engine_method(sc, rs);
  // An output name of unknown extension is refused before the run (docs/data.md).
  (void)TableOutput::kind_of(o.out);
  // And where it goes (a directory, a FIFO, a path ending in '/'): refused before the run. (The
  // default name holds the engine's label, known after the run; it goes to the working directory.)
  if (!o.out.empty() && o.out != "-") {
    if (std::filesystem::path(o.out).extension() == ".nc") check_outputs({o.out, o.out + ".csv"});
    else check_outputs(csv_with_sidecar(o.out));
  }
  const auto t0 = std::chrono::steady_clock::now();
  const Trajectory tr = run_engine(sc, rs);
  const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::string out = o.out.empty() ? sc.name + "." + tr.engine_label + ".csv" : o.out;
  if (!tr.complete) {
    // Never presented as a result: a distinct name, a message, a non-zero exit.
    std::cerr << "nanopush: " << (tr.outcome == Outcome::solver_failure ? "solver failure" : to_string(tr.outcome))
              << ": " << sc.name << " (" << tr.engine_label << "): " << tr.outcome_message << "\n";
    if (tr.outcome == Outcome::accuracy_not_reached) print_error_estimate(tr, std::cerr);
    if (tr.outcome == Outcome::solver_failure) print_rest_diagnosis(sc, rs.law.value_or(sc.surface.law), tr, std::cerr);
    if (o.keep_partial) {
      if (out == "-") out = sc.name + "." + tr.engine_label + ".csv";
      const std::string partial = out + ".partial.csv";
      write_trajectory_csv(tr, partial);
      std::cerr << "  the " << tr.rows.size() << " samples computed before the failure are in " << partial
                << " (incomplete)\n";
    } else {
      std::cerr << "  nothing written (--keep-partial keeps the " << tr.rows.size() << " samples computed)\n";
    }
    return 3;
  }
  if (out == "-") {
    // Standard output: the same CSV as the file, without a sidecar (docs/outputs.md).
    std::vector<std::vector<std::string>> rows;
    for (auto& r : tr.rows) {
      std::vector<std::string> cells;
      for (double v : r) cells.push_back(csv_number(v));
      rows.push_back(std::move(cells));
    }
    std::cout << csv_document(trajectory_column_specs(), rows);
  } else if (std::filesystem::path(out).extension() == ".nc") {
    // netCDF-4 (docs/data.md): the trajectory over its times, `t` the coordinate.
    const TableOutput nc(out);
    write_trajectory_csv(tr, nc.table());
    (void)nc.finish({{"t", tr.rows.size()}});
  } else {
    write_trajectory_csv(tr, out);
  }
  if (!o.quiet) {
    print_summary(sc, tr, dt, std::cerr);
    if (tr.outcome == Outcome::at_rest) std::cerr << "  at_rest: " << tr.outcome_message << "\n";
    if (!tr.handed_over.empty())
      std::cerr << "  method auto handed over to cvode: modern gave up (" << tr.handed_over
                << "), a stiff start just outside the limit surface (docs/accuracy.md)\n";
    for (const auto& e : tr.events) {
      if (e.t == 0.0)
        std::cerr << "  at rest at t = 0: " << (e.stuck ? "stays stuck (applied wrench inside the limit surface)" : "the push starts it sliding") << "\n";
      else
        std::cerr << "  came to rest at t = " << e.t << " s: " << (e.stuck ? "stuck (applied wrench inside the limit surface)" : "slid off again") << "\n";
    }
    for (const auto& e : tr.tip_events) std::cerr << "  tip: " << e.what << " at t = " << e.t << " s\n";
    if (out != "-") std::cerr << "  trajectory (SI, world axes): " << out << "\n";
  }
  return 0;
}

RegisterCommand reg_run{{"run", "Integrate a scene and write its trajectory as CSV (t,x,y,theta,vx,vy,omega,fx,fy,mf; SI)",
                         10, options_then<RunOptions>(run_cmd, [](CLI::App& app, RunOptions& o) {
                           add_common(app, o);
                           app.add_option("--engine", o.engine, "cxx (modern C++) or f77 (FORTRAN 77); default: the scene's")
                               ->check(is_choice<Engine>());
                           app.add_option("--method", o.method,
                                          "C++ integrator: faithful (steps identical to F77), modern (Bulirsch-Stoer with dense "
                                          "output), dop853 (Dormand-Prince 8(5,3), double; smooth scenes and the thesis law: "
                                          "docs/dop853.md), cvode (SUNDIALS cross-check of the coulomb law), or auto (dop853 for "
                                          "rtol >= 1e-11 where it runs, else modern); default: the scene's")
                               ->check(is_choice<Method>());
                           app.add_option("--law", o.law,
                                          "rough scenes: friction law, thesis (sign law of eq 3.40), printed (the same with "
                                          "eqs 3.45-3.48 exactly as printed, docs/rough.md) or coulomb (event-located "
                                          "stick-slip); default: the scene's")
                               ->check(is_choice<Law>());
                           app.add_option("--precision", o.precision,
                                          "scalar of the integration: double, long (x87 80-bit) or quad (__float128); "
                                          "long and quad need --engine cxx, --method faithful or modern, a smooth scene. "
                                          "Cost (fig3_6a, release build): at the same rtol long takes ~6x the wall time of "
                                          "double, quad ~40x; double stops near 1e-14 in theta, long reaches ~1e-17 (rtol "
                                          "1e-17, ~7x), quad ~3e-24 (--method modern --rtol 1e-24, ~80-100x). The CSV holds "
                                          "the values rounded to double. Default: the scene's solver.precision (double)")
                               ->check(is_choice<Precision>());
                           app.add_option("--out", o.out, "output CSV ('-' for standard output; FILE.nc: netCDF-4, docs/data.md; default <scene>.<engine>.csv)");
                           app.add_flag("--quiet", o.quiet, "no summary on standard error");
                           app.add_flag("--keep-partial", o.keep_partial,
                                        "when the integrator gives up, keep the samples computed so far in "
                                        "OUT.partial.csv (exit status stays non-zero)");
                         })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
