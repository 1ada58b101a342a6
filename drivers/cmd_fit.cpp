// nanopush fit: scene keys estimated from observed motion (docs/fitting.md).
//   nanopush fit SCENE DATA.csv --free KEY [--free KEY ...] [--sigma x=2e-9 ...] [--law ...]
//                [--set KEY=VALUE ...] [--json FILE] [--out DIR]
//   nanopush fit SCENE --synthesize DATA.csv --sigma x=1e-9 [--seed N]   (synthetic data)
// And the reproduce step `fit_synthetic`: one synthetic fit, truth against estimate.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "nanopush/fitting/fit.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "cli_checks.hpp"
#include "columns.hpp"
#include "registry.hpp"
#include "scene_args.hpp"
#include "sweep_output.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct FitCliOptions {
  std::string scene, data, law, json, out = ".", synthesize, gradients = "auto", format = "png";
  std::vector<std::string> sets, free, sigma;
  double rtol = 1e-10, accuracy = -1;  // -1: the scene's solver.accuracy
  int max_evaluations = 100;
  std::uint64_t seed = 1;
  bool no_plot = false, quiet = false;
};

fit::SigmaOverrides parse_sigma(const std::vector<std::string>& texts) {
  fit::SigmaOverrides m;
  for (const auto& t : texts) {
    const auto eq = t.find('=');
    if (eq == std::string::npos) throw InputError("--sigma", t, "must read COLUMN=VALUE, e.g. x=2e-9 (x, y in m; theta in rad)");
    const std::string col = t.substr(0, eq), val = t.substr(eq + 1);
    if (col != "x" && col != "y" && col != "theta") throw InputError("--sigma", t, "the column must be x, y or theta");
    double v = 0;
    std::istringstream s(val);
    if (!(s >> v) || !s.eof()) throw InputError("--sigma " + col, val, "must be a number > 0");
    require_positive("--sigma " + col, v, col == "theta" ? "rad" : "m");
    if (m.count(col)) throw InputError("--sigma", col, "given twice");
    m[col] = v;
  }
  return m;
}

/// The fitted trajectory over the data: CSV (+ schema) with observed values, sigmas and
/// normalised residuals, and a PNG per observed column.
/// "key = value +- stderr" with `digits` and `sigma_digits` significant digits, or `undetermined`
/// in place of the uncertainty when the fit could not give one.
void put_estimate(std::ostream& s, const fit::ParameterEstimate& p, int digits, int sigma_digits,
                  const char* undetermined) {
  s << p.key << " = " << std::setprecision(digits) << p.value;
  if (std::isfinite(p.stderr_))
    s << " +- " << std::setprecision(sigma_digits) << p.stderr_;
  else
    s << undetermined;
}

void write_outputs(const fit::FitResult& r, const fit::Observations& obs, const fs::path& dir, const std::string& base,
                   bool plot_it, std::vector<fs::path>& produced) {
  fs::create_directories(dir);
  Columns cols = columns("fit");
  const char* units[3] = {"m", "m", "rad"};
  for (std::size_t c = 0; c < 3; ++c) {
    if (!obs.has[c]) continue;
    const std::string n = fit::kPoseColumns[c];
    cols.push_back({n, units[c], "observed " + n});
    cols.push_back({"sigma_" + n, units[c], "standard deviation of the observed " + n});
    cols.push_back({"residual_" + n, "1", "(observed - fitted) / sigma, " + n});
  }
  const fs::path csv = dir / (base + ".fit.csv");
  CsvWriter w(csv, cols);
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    std::vector<double> row = {r.t[i], r.fitted[i][0], r.fitted[i][1], r.fitted[i][2]};
    for (std::size_t c = 0; c < 3; ++c)
      if (obs.has[c]) {
        row.push_back(obs.value[c][i]);
        row.push_back(obs.sigma[c][i]);
        row.push_back(r.residuals[i][c]);
      }
    w.row(row);
  }
  RunInfo info = {{"converged", r.converged}, {"chi2_dof", r.chi2_dof},
                  {"n_forward_solves", r.n_forward_solves}, {"wall_seconds", r.wall_seconds}};
  for (const auto& p : r.parameters) {
    info.emplace_back(p.key, p.value);
    if (std::isfinite(p.stderr_)) info.emplace_back(p.key + ".stderr", p.stderr_);
  }
  w.run_info(info);
  w.commit();
  produced.push_back(csv);
  if (!plot_it || !plot::available()) return;
  plot::Figure f;
  std::ostringstream title;
  title << "fit of " << base << ":";
  for (const auto& p : r.parameters) {
    title << " ";
    put_estimate(title, p, 5, 2, " (undetermined)");
  }
  title << ", chi2/dof = " << std::setprecision(3) << r.chi2_dof;
  f.title = title.str();
  int col = 5;
  const char* scale[3] = {"*1e9", "*1e9", ""};
  const char* label[3] = {"x [nm]", "y [nm]", "theta [rad]"};
  for (std::size_t c = 0; c < 3; ++c) {
    if (!obs.has[c]) continue;
    plot::Panel p;
    p.xlabel = "t [ns]";
    p.ylabel = label[c];
    p.title = fit::kPoseColumns[c];
    p.series.push_back({csv, "($1*1e9)", "($" + std::to_string(col) + scale[c] + ")", "observed", "points pt 7 ps 0.4 lc rgb '#7f7f7f'"});
    p.series.push_back({csv, "($1*1e9)", "($" + std::to_string(2 + c) + scale[c] + ")", "fitted", "lines lw 2 lc rgb '#d62728'"});
    f.panels.push_back(p);
    col += 3;
  }
  f.cols = static_cast<int>(f.panels.size());
  f.width = 500 * f.cols;
  f.height = 450;
  produced.push_back(plot::render(f, dir / (base + ".fit.png")));
}

std::string summary_text(const fit::FitResult& r, const fit::Observations& obs, const std::string& name) {
  std::ostringstream s;
  s << "fit of " << name << " to " << obs.source << ": " << obs.t.size() << " times, " << obs.count()
    << " values; gradients: " << to_string(r.gradients) << (r.law.empty() ? "" : ", law " + r.law) << "\n";
  for (const auto& p : r.parameters) {
    s << "  ";
    put_estimate(s, p, 8, 3, " (not determined separately)");
    s << (p.unit == "1" ? "" : " " + p.unit) << " (start " << std::setprecision(6) << p.start << ")" << (p.at_bound ? " AT BOUND" : "") << "\n";
  }
  if (r.parameters.size() > 1) {
    s << "  correlation:";
    for (const auto& row : r.correlation) {
      s << "\n   ";
      for (double c : row) s << " " << std::setw(7) << (std::isfinite(c) ? fmt(std::round(c * 1000) / 1000) : "-");
    }
    s << "\n";
  }
  s << "  chi2/dof = " << std::setprecision(4) << r.chi2_dof << " (chi2 " << r.chi2 << ", dof " << r.dof << ")\n"
    << "  " << r.status << " after " << r.iterations << " iterations, " << r.n_forward_solves << " forward solves ("
    << r.n_sensitivity_solves << " with sensitivities), " << std::setprecision(3) << r.wall_seconds << " s\n";
  if (!r.identifiability.identifiable) s << "  identifiability: " << r.identifiability.message << "\n";
  if (r.accuracy.requested > 0)
    s << "  accuracy asked " << std::setprecision(3) << r.accuracy.requested << " of the model's poses: "
      << (r.accuracy.reached ? "reached" : "NOT reached") << " with rtol " << r.accuracy.rtol_used << " (estimate "
      << r.accuracy.estimate << " at the estimate)\n";
  return s.str();
}

int run_fit(const FitCliOptions& o) {
  plot::set_format(plot::parse_format(o.format));
  const Scene sc = load_scene_arg(o.scene, o.sets);
  set_provenance_scene(o.scene);
  const auto sigma = parse_sigma(o.sigma);
  if (!o.synthesize.empty()) {
    if (!o.data.empty()) throw InputError("DATA", o.data, "--synthesize writes data; give no DATA file with it");
    if (!o.free.empty()) throw InputError("--free", o.free[0], "--synthesize fits nothing; drop --free");
    if (sigma.empty()) throw InputError("--sigma", "(none)", "--synthesize needs the noise of each column to write, e.g. --sigma x=1e-9");
    const TableOutput table(o.synthesize, "--synthesize", false);  // FILE.csv or FILE.nc, checked before the runs
    std::vector<fs::path> targets = csv_with_sidecar(table.table());  // and the .nc it becomes
    if (table.netcdf()) targets.emplace_back(o.synthesize);
    check_outputs(targets);
    std::array<double, 3> s{0, 0, 0};
    for (std::size_t c = 0; c < 3; ++c)
      if (auto it = sigma.find(fit::kPoseColumns[c]); it != sigma.end()) s[c] = it->second;
    const fit::Observations obs = fit::synthesize(sc, s, o.seed, parse_optional_choice<Law>("--law", o.law), {}, o.rtol);
    Columns cols = {{"t", "s", "observation time"}};
    const char* units[3] = {"m", "m", "rad"};
    for (std::size_t c = 0; c < 3; ++c)
      if (obs.has[c]) {
        cols.push_back({fit::kPoseColumns[c], units[c], std::string("model ") + fit::kPoseColumns[c] + " plus Gaussian noise"});
        cols.push_back({std::string("sigma_") + fit::kPoseColumns[c], units[c], "standard deviation of the noise"});
      }
    CsvWriter w(table.table(), cols);
    for (std::size_t i = 0; i < obs.t.size(); ++i) {
      std::vector<double> row = {obs.t[i]};
      for (std::size_t c = 0; c < 3; ++c)
        if (obs.has[c]) {
          row.push_back(obs.value[c][i]);
          row.push_back(obs.sigma[c][i]);
        }
      w.row(row);
    }
    w.run_info({{"seed", o.seed}});
    w.commit();
    (void)table.finish();
    if (!o.quiet) std::cerr << "synthetic data of " << sc.name << " (seed " << o.seed << "): " << o.synthesize << "\n";
    return 0;
  }
  if (o.data.empty()) throw InputError("DATA", "(none)", "give the observations (CSV: t and any of x, y, theta with sigmas), or --synthesize FILE");
  const fit::Observations obs = fit::read_observations(o.data, sigma);
  fit::FitOptions fo;
  fo.free = o.free;
  fo.law = parse_optional_choice<Law>("--law", o.law);
  fo.rtol = o.rtol;
  fo.accuracy = o.accuracy;
  fo.gradients = parse_choice<fit::Gradients>("--gradients", o.gradients);
  fo.max_evaluations = o.max_evaluations;
  // Every output checked where it goes before the fit (docs/errors.md, "Outputs"): a target
  // that cannot be written costs no fit and leaves none of the others.
  check_output_directory(o.out);
  std::vector<fs::path> targets = csv_with_sidecar(fs::path(o.out) / (sc.name + ".fit.csv"));
  if (!o.no_plot && plot::available()) {
    const fs::path figure = plot::figure_path(fs::path(o.out) / (sc.name + ".fit.png"));
    targets.push_back(figure);
    targets.push_back(fs::path(figure).replace_extension(".gp"));
  }
  if (!o.json.empty() && o.json != "-") targets.emplace_back(o.json);
  check_outputs(targets);
  const fit::FitResult r = fit::fit_trajectory(sc, obs, fo);
  std::vector<fs::path> produced;
  write_outputs(r, obs, o.out, sc.name, !o.no_plot, produced);
  if (!o.json.empty()) {
    if (o.json == "-")
      std::cout << fit::fit_json(r);
    else
      write_file_atomic(o.json, fit::fit_json(r));
  }
  if (o.json != "-") std::cout << summary_text(r, obs, sc.name);
  if (!o.quiet)
    for (const auto& p : produced) std::cerr << "  " << p.string() << "\n";
  if (!r.converged) {
    std::cerr << "nanopush: solver failure: the fit did not converge (" << r.status
              << "); the outputs hold its last state, marked converged = false\n";
    return 3;
  }
  if (r.accuracy.requested > 0 && !r.accuracy.reached) {
    std::cerr << "nanopush: accuracy_not_reached: the model's error at the estimate is " << r.accuracy.estimate
              << " at rtol " << r.accuracy.rtol_used << " (asked " << r.accuracy.requested
              << "); the outputs hold the fit at that rtol\n";
    return 3;
  }
  return 0;
}

RegisterCommand reg_fit{{"fit", "Fit scene keys (e.g. surface.mu) to an observed trajectory: estimates, standard errors, identifiability",
                         62, [](CLI::App& app) -> std::function<int()> {
                           auto o = std::make_shared<FitCliOptions>();
                           app.add_option("SCENE", o->scene, "scene file or preset name: the model and the start values")->required();
                           app.add_option("DATA", o->data, "observations CSV: t and any of x, y, theta; sigma_x, ... or --sigma");
                           app.add_option("--free", o->free, "scene key to fit (repeat for several), e.g. surface.mu");
                           app.add_option("--sigma", o->sigma, "standard deviation of a column: x=2e-9, y=2e-9 (m), theta=0.01 (rad)");
                           add_set_option(app, o->sets);
                           app.add_option("--law", o->law, "rough scenes: friction law (default: the scene's)")
                               ->check(is_choice<Law>({Law::thesis, Law::coulomb}));
                           app.add_option("--rtol", o->rtol, "relative tolerance of the forward solves (default 1e-10)")
                               ->check(real_in(1e-14, 1e-3));
                           app.add_option("--accuracy", o->accuracy,
                                          "the error asked for of the model's poses at the observation times "
                                          "(docs/accuracy.md's norm), in [1e-14, 0.1]: the forward solves' rtol is "
                                          "chosen to reach it (instead of --rtol) and checked at the estimate")
                               ->check(CLI::Range(kAccuracyMin, kAccuracyMax));
                           app.add_option("--gradients", o->gradients,
                                          "auto (sensitivities where the right-hand side is smooth, differences under the "
                                          "coulomb law) | sensitivities | differences")
                               ->check(is_choice<fit::Gradients>());
                           app.add_option("--max-evaluations", o->max_evaluations, "Levenberg-Marquardt evaluations (default 100)")
                               ->check(count(1, 100000));
                           app.add_option("--json", o->json, "write the JSON summary to FILE (- = standard output)");
                           app.add_option("--out", o->out, "directory of SCENE.fit.csv (+ schema) and SCENE.fit.png (default .)");
                           app.add_option("--synthesize", o->synthesize,
                                          "write synthetic data instead of fitting: the scene's model at its output times "
                                          "plus Gaussian noise of --sigma (seeded), as FILE.csv (and its sidecar) or "
                                          "FILE.nc (netCDF-4, docs/data.md)");
                           app.add_option("--seed", o->seed, "seed of --synthesize (default 1)")->check(count(0, 1LL << 62));
                           app.add_option("--format", o->format, "figure format: png, svg or pdf (default png)");
                           app.add_flag("--no-plot", o->no_plot, "no figure");
                           app.add_flag("--quiet", o->quiet, "no file list on stderr");
                           return [o] { return run_fit(*o); };
                         }}};

// ---- reproduce: one synthetic fit -----------------------------------------------------

void reproduce_fit(ReproduceContext& ctx) {
  const fs::path dir = ctx.out / "fit";
  fs::create_directories(dir);
  Scene truth = load_scene(resolve_scene("thesis/fig3_20"));
  truth.set({{"solver.t_end", 0.8e-9}, {"solver.samples", ctx.quick ? 81 : 161}});
  const std::array<double, 3> sigma{1e-9, 1e-9, 0.01};
  const fit::Observations obs = fit::synthesize(truth, sigma, 2026, Law::thesis);
  Scene start = truth;
  start.set("surface.mu", 0.12);
  fit::FitOptions fo;
  fo.free = {"surface.mu"};
  const fit::FitResult r = fit::fit_trajectory(start, obs, fo);
  std::vector<fs::path> produced;
  write_outputs(r, obs, dir, "fig3_20_synthetic", true, produced);
  write_file_atomic(dir / "fig3_20_synthetic.fit.json", fit::fit_json(r));
  produced.push_back(dir / "fig3_20_synthetic.fit.json");
  for (const auto& p : produced) ctx.produced(p);
  const auto& p = r.parameters[0];
  const double lo = p.value - 1.96 * p.stderr_, hi = p.value + 1.96 * p.stderr_;
  ctx.report << "## Synthetic fit (docs/fitting.md)\n\n"
             << "Fig 3.20's scene (rough surface, thesis law) over 0.8 ns, " << obs.t.size()
             << " samples of x, y (sigma 1 nm) and theta (sigma 0.01 rad), Gaussian noise with seed 2026; surface.mu "
                "fitted from 0.12.\n\n"
             << "| truth | estimate | standard error | 95 % interval | chi2/dof | forward solves |\n|---|---|---|---|---|---|\n"
             << "| " << truth.surface.mu << " | " << std::setprecision(6) << p.value << " | " << std::setprecision(3)
             << p.stderr_ << " | [" << std::setprecision(6) << lo << ", " << hi << "] | " << std::setprecision(4)
             << r.chi2_dof << " | " << r.n_forward_solves << " |\n\n"
             << "![fit](fit/fig3_20_synthetic.fit.png)\n\n";
  if (!r.converged) ctx.failures.push_back("fit_synthetic: the fit did not converge: " + r.status);
  if (!(std::abs(p.value - truth.surface.mu) < 3 * p.stderr_))
    ctx.failures.push_back("fit_synthetic: the estimate " + fmt(p.value) + " is more than 3 standard errors from the truth");
}

RegisterReproduce step_fit{{"fit_synthetic", "a synthetic trajectory fit: truth, estimate, interval, plot", 70, reproduce_fit}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
