// nanopush bench-fit: the trajectory fit measured (docs/fitting.md, "Benchmark").
//  1. Cost: a 401-sample one-parameter fit (surface.mu) on a rough scene (Fig 3.20, 1.6 ns)
//     under both laws: forward solves and wall time of Levenberg-Marquardt (with
//     sensitivities, and with differences) against Brent's derivative-free minimisation of
//     chi2 (Boost.Math brent_find_minima), each run until its estimate is as close to the
//     converged optimum as Levenberg-Marquardt's.
//  2. Coverage: over N synthetic data sets per configuration (small scenes, short spans), the
//     fraction of 95 % intervals (estimate +- 1.96 stderr) that contain the truth.
// Writes fit_benchmark.csv, fit_coverage.csv (+ schemas), fit_coverage.png and fit_benchmark.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/tools/minima.hpp>
#include "nanopush_toml.hpp"

#include "nanopush/fitting/fit.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "bench_options.hpp"
#include "cli_checks.hpp"
#include "bench_report.hpp"
#include "columns.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct BenchFitOptions : BenchDirectoryOptions {
  int coverage = 200;
  bool quick = false;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double chi2_of(const fit::Observations& obs, const fit::ModelPoses& m) {
  double c = 0;
  for (std::size_t i = 0; i < obs.t.size(); ++i)
    for (std::size_t j = 0; j < 3; ++j)
      if (obs.has[j]) {
        const double r = (obs.value[j][i] - m.pose[i][j]) / obs.sigma[j][i];
        c += r * r;
      }
  return c;
}

struct CostRow {
  std::string law, method;
  double estimate = 0, error = 0;  // |estimate - converged optimum|
  long solves = 0;
  double wall = 0;
};

/// Cost of one configuration: LM (sensitivities where the law allows, and differences),
/// Brent at the same accuracy.
std::vector<CostRow> cost(const std::string& preset, Law law, double truth, double start, std::ostream& log) {
  Scene s = load_scene(resolve_scene(preset));
  s.set("surface.mu", truth);
  const fit::Observations obs = fit::synthesize(s, {1e-9, 1e-9, 0.01}, 1, law);
  s.set("surface.mu", start);
  fit::FitOptions fo;
  fo.free = {"surface.mu"};
  fo.law = law;
  // The converged optimum: Levenberg-Marquardt at tolerances at rounding.
  fit::FitOptions tight = fo;
  tight.xtol = 1e-14;
  tight.ftol = 1e-15;
  const double best = fit::fit_trajectory(s, obs, tight).parameters[0].value;
  std::vector<CostRow> rows;
  // The accuracy both must reach: 1e-3 of the standard error (far below what the data tell).
  const double accuracy = 1e-3 * fit::fit_trajectory(s, obs, tight).parameters[0].stderr_;
  for (const fit::Gradients g : {fit::Gradients::sensitivities, fit::Gradients::differences}) {
    if (law == Law::coulomb && g == fit::Gradients::sensitivities) continue;
    fo.gradients = g;
    // Levenberg-Marquardt's tolerances tightened tenfold until it is that close.
    for (const double tol : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}) {
      fo.xtol = tol;
      fo.ftol = tol;
      const auto t0 = std::chrono::steady_clock::now();
      const fit::FitResult r = fit::fit_trajectory(s, obs, fo);
      const double err = std::abs(r.parameters[0].value - best);
      if (err <= accuracy || tol <= 1e-12) {
        CostRow row{to_string(law), "levenberg-marquardt (" + to_string(g) + ", tol " + fmt(tol) + ")", r.parameters[0].value, err,
                    static_cast<long>(r.n_forward_solves), seconds_since(t0)};
        rows.push_back(row);
        log << "  " << to_string(law) << ", " << row.method << ": mu = " << std::setprecision(12) << row.estimate << ", "
            << row.solves << " solves, " << std::setprecision(3) << row.wall << " s\n";
        break;
      }
    }
  }
  // Brent on chi2(mu) in [start/2, 2 start], bits raised until it is as accurate.
  for (int bits = 8; bits <= 52; bits += 2) {
    long evals = 0;
    const auto t0 = std::chrono::steady_clock::now();
    auto f = [&](double mu) {
      ++evals;
      try {
        return chi2_of(obs, fit::model_poses(s, {"surface.mu"}, {mu}, obs.t, law, fo.rtol, false));
      } catch (const SolverError&) {  // the thesis law chatters where friction holds the push
        return 1e300;
      }
    };
    std::uintmax_t iters = 200;
    const auto r = boost::math::tools::brent_find_minima(f, 0.5 * start, 1.2 * start, bits, iters);
    const double wall = seconds_since(t0);
    if (std::abs(r.first - best) <= accuracy || bits >= 52) {
      rows.push_back({to_string(law), "brent (" + std::to_string(bits) + " bits)", r.first, std::abs(r.first - best), evals, wall});
      log << "  " << to_string(law) << ", brent: mu = " << std::setprecision(12) << r.first << ", " << evals << " solves, "
          << std::setprecision(3) << wall << " s\n";
      break;
    }
  }
  return rows;
}

struct CoverageConfig {
  std::string name, preset, key, law;
  double t_end;
  int samples;
  double start_factor;
};

int run_bench_fit(const BenchFitOptions& o) {
  const fs::path dir = o.out;
  fs::create_directories(dir);
  std::ostringstream md;
  bool ok = true;

  // 1. Cost.
  std::cerr << "bench-fit: cost of a 401-sample one-parameter fit (Fig 3.20 and 3.27 scenes, 1.6 ns)\n";
  std::vector<CostRow> rows = cost("thesis/fig3_20", Law::thesis, 0.08, 0.1, std::cerr);
  for (auto& r : cost("bench/stick_mu015", Law::coulomb, 0.15, 0.13, std::cerr)) rows.push_back(r);
  CsvWriter cw(dir / "fit_benchmark.csv",
               columns("bench_fit"));
  for (const auto& r : rows)
    cw.cells({csv_quote(r.law), csv_quote(r.method), csv_number(r.estimate), csv_number(r.error), std::to_string(r.solves),
              csv_number(r.wall)});
  cw.commit();
  md << "# Trajectory fit: benchmark\n\nGenerated by `nanopush bench-fit` (drivers/cmd_bench_fit.cpp); see "
        "[fitting.md](../fitting.md).\n\n## Cost of a one-parameter fit\n\n"
     << "surface.mu from 401 samples of x, y (sigma 1 nm) and theta (sigma 0.01 rad) over 1.6 ns, synthetic data "
        "(seed 1), rtol 1e-10. Thesis law: Fig 3.20's scene (truth 0.08, start 0.1); coulomb law: Fig 3.27's "
        "(truth 0.15, start 0.13, stick-slip). Brent (Boost.Math `brent_find_minima` on chi2 over [start/2, 1.2 start], below the thesis law's chatter at mu > F/N = 0.125) "
        "with more bits, and Levenberg-Marquardt with tolerances (xtol = ftol) ten times tighter, until each estimate lies "
        "within 1e-3 standard errors of the converged optimum.\n\n"
     << "| law | method | estimate | distance from optimum | forward solves | wall [s] |\n|---|---|---|---|---|---|\n";
  for (const auto& r : rows)
    md << "| " << r.law << " | " << r.method << " | " << std::setprecision(10) << r.estimate << " | "
       << std::setprecision(2) << r.error << " | " << r.solves << " | " << std::setprecision(3) << r.wall << " |\n";
  md << "\n";
  for (const std::string law : {"thesis", "coulomb"}) {
    const CostRow* brent = nullptr;
    for (const auto& r : rows)
      if (r.law == law && r.method.rfind("brent", 0) == 0) brent = &r;
    for (const auto& r : rows)
      if (r.law == law && brent && &r != brent)
        md << "- " << law << " law, " << r.method << ": " << std::setprecision(2)
           << static_cast<double>(r.solves) / static_cast<double>(brent->solves) << " x Brent's forward solves, "
           << r.wall / brent->wall << " x its wall time.\n";
  }

  // 2. Coverage.
  const int n = o.quick ? 20 : o.coverage;
  const std::vector<CoverageConfig> configs = {
      {"smooth push.force", "thesis/fig3_6a", "push.force", "", 0.4e-9, 41, 1.2},
      {"rough thesis surface.mu", "thesis/fig3_20", "surface.mu", "thesis", 0.4e-9, 41, 1.2},
      {"rough coulomb surface.mu", "bench/stick_mu015", "surface.mu", "coulomb", 0.6e-9, 31, 0.9},
  };
  CsvWriter cov(dir / "fit_coverage.csv",
                columns("bench_fit_coverage"));
  md << "\n## Coverage of the 95 % intervals\n\n" << n
     << " synthetic data sets per configuration (x, y: sigma 1 nm, theta: 0.01 rad; seeds 1.." << n
     << "), the fit started " << "20 % (coulomb: -10 %) away from the truth. Expected: 95 %, acceptable 90-99 %.\n\n"
     << "| configuration | samples | data sets | covered | fraction | not converged | wall [s] |\n|---|---|---|---|---|---|---|\n";
  std::cerr << "bench-fit: coverage, " << n << " data sets per configuration\n";
  const boost::math::normal normal;
  for (const auto& c : configs) {
    Scene truth = load_scene(resolve_scene(c.preset));
    truth.set({{"solver.t_end", c.t_end}, {"solver.samples", c.samples}});
    const double tv = truth.document->at_path(c.key).value<double>().value();
    Scene start = truth;
    start.set(c.key, tv * c.start_factor);
    std::vector<std::pair<double, std::vector<std::string>>> zs;
    int covered = 0, failed = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 1; i <= n; ++i) {
      const fit::Observations obs = fit::synthesize(truth, {1e-9, 1e-9, 0.01}, static_cast<std::uint64_t>(i), parse_optional_choice<Law>("law", c.law));
      fit::FitOptions fo;
      fo.free = {c.key};
      fo.law = parse_optional_choice<Law>("law", c.law);  // "": the smooth scene has no law
      const fit::FitResult r = fit::fit_trajectory(start, obs, fo);
      if (!r.converged) ++failed;
      const auto& p = r.parameters[0];
      const double z = (p.value - tv) / p.stderr_;
      const bool in = std::abs(z) <= 1.96;
      covered += in ? 1 : 0;
      zs.push_back({z, {csv_quote(c.name), std::to_string(i), csv_number(tv), csv_number(p.value), csv_number(p.stderr_),
                        csv_number(z), "", in ? "1" : "0"}});
    }
    const double wall = seconds_since(t0);
    std::sort(zs.begin(), zs.end(), [](auto& a, auto& b) { return a.first < b.first; });
    for (std::size_t k = 0; k < zs.size(); ++k) {
      zs[k].second[6] = csv_number(quantile(normal, (static_cast<double>(k) + 0.5) / static_cast<double>(zs.size())));
      cov.cells(zs[k].second);
    }
    const double frac = static_cast<double>(covered) / n;
    md << "| " << c.name << " | " << c.samples << " | " << n << " | " << covered << " | " << std::setprecision(3) << frac
       << " | " << failed << " | " << std::setprecision(3) << wall << " |\n";
    std::cerr << "  " << c.name << ": " << covered << "/" << n << " covered, " << failed << " not converged, " << wall
              << " s\n";
    if (!o.quick && (frac < 0.90 || frac > 0.99 || failed > 0)) ok = false;
  }
  cov.commit();
  if (plot::available()) {
    plot::Figure f;
    f.title = "fit coverage: (estimate - truth) / stderr against normal quantiles";
    plot::Panel p;
    p.xlabel = "standard normal quantile";
    p.ylabel = "z";
    const fs::path csv = dir / "fit_coverage.csv";
    for (const auto& c : configs)  // one config's rows: the others undefined (1/0)
      p.series.push_back({csv, "7", "(strcol(1) eq '" + c.name + "' ? $6 : 1/0)", c.name, "points pt 7 ps 0.6"});
    p.series.push_back({csv, "7", "7", "y = x", "lines lw 1 lc rgb 'black'"});
    f.panels.push_back(p);
    f.width = 800;
    f.height = 700;
    plot::render(f, dir / "fit_coverage.png");
    md << "\n![coverage](fit_coverage.png)\n";
  }
  write_file_atomic(dir / "fit_benchmark.md", md.str());
  std::cerr << "bench-fit: " << (dir / "fit_benchmark.md").string() << ", fit_benchmark.csv, fit_coverage.csv, fit_coverage.png\n";
  return bench_status(ok, "bench: coverage outside 90-99 % or a fit that did not converge (fit_benchmark.md)");
}

RegisterCommand reg{{"bench-fit",
                     "Benchmark of the trajectory fit: forward solves and wall time against Brent, coverage of the 95 % "
                     "intervals over synthetic data sets (docs/fitting.md)",
                     93, options_then<BenchFitOptions>(run_bench_fit, [](CLI::App& app, BenchFitOptions& o) {
                       add_bench_directory_option(app, o);
                       app.add_option("--coverage", o.coverage, "synthetic data sets per configuration")
                           ->check(count(10, 100000))
                           ->capture_default_str();
                       app.add_flag("--quick", o.quick, "20 data sets, no coverage check (for tests)");
                     })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
