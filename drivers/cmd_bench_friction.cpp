// nanopush bench-friction: nanoseconds per friction wrench of the production closed form and
// far-field forms (friction.hpp: closed_form, far_field) against the F77 routine's forms, which
// the faithful method keeps (the *_reference functions), in one binary, interleaved; and a rough scene integrated with
// each. A benchmark, never a timed test: the two must agree (the bounds of
// tests/test_friction_fast.cpp, else exit 4); the 0.5x target is reported, not asserted.
// docs/performance.md ("Friction resultant") and docs/friction.md document the results.
#include <algorithm>
#include <array>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <thread>

#include "nanopush/models/friction.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/numerics/bulirsch_stoer.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "cli_checks.hpp"
#include "bench_report.hpp"
#include "columns.hpp"
#include "registry.hpp"
#include "scene_args.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

using Clock = std::chrono::steady_clock;

constexpr double kTarget = 0.5;  // issue 24: new ns per wrench <= 0.5 x the former
constexpr double kEps = DBL_EPSILON;
constexpr double kA = 27.5e-9, kB = 50e-9, kL = 50e-9;  // the thesis nanobar's contact

struct BenchFrictionOptions {
  std::string out = "bench_friction";
  std::string scene = "fig3_17";
  std::vector<std::string> sets;
  int repeats = 9;
  double seconds = 0.6;  // per workload, both implementations together
  bool no_plot = false, quiet = false;
};

std::string fixed(double v, int digits) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::string sci(double v) {
  std::ostringstream s;
  s << std::setprecision(2) << v;
  return s.str();
}

/// One input of a wrench workload: (R, alpha, sense) for the (R, alpha) entry point, or the
/// body velocity (vx, vy, omega) for the velocity entry point.
struct Input {
  double p, q, r;
};

struct Workload {
  std::string name, description;
  int form = -1;            ///< rectangle_friction_form of every input; -1: mixed
  bool velocity = false;    ///< rectangle_friction_from_velocity instead of rectangle_friction_wrench
  double a = kA, b = kB;    ///< contact half-width and half-length [m]
  std::vector<Input> inputs;
  std::string calls_old, calls_new;  ///< log/sqrt/division count per wrench, from the code
  // results
  std::vector<double> ns_old, ns_new, ratios;
  double max_dforce = 0, max_dmoment = 0;
  bool agree = true;
};

FrictionWrench eval(const Workload& w, const Input& in, bool reference) {
  if (w.velocity)
    return reference ? friction_detail::rectangle_friction_from_velocity_reference(w.a, w.b, 1.0, in.p, in.q, in.r)
                     : rectangle_friction_from_velocity(w.a, w.b, 1.0, in.p, in.q, in.r);
  const int sense = in.r < 0 ? -1 : 1;
  return reference ? friction_detail::rectangle_friction_wrench_reference(w.a, w.b, 1.0, in.p, in.q, sense)
                   : rectangle_friction_wrench(w.a, w.b, 1.0, in.p, in.q, sense);
}

/// Time `passes` sweeps over the inputs: ns per wrench. The sum of the results goes to a
/// volatile so that nothing is optimised away.
double time_pass(const Workload& w, bool reference, int passes) {
  volatile double sink = 0;
  double s = 0;
  const auto t0 = Clock::now();
  for (int k = 0; k < passes; ++k)
    for (const Input& in : w.inputs) {
      const FrictionWrench f = eval(w, in, reference);
      s += f.fx + f.fy + f.mf;
    }
  const double dt = std::chrono::duration<double>(Clock::now() - t0).count();
  sink = s;
  (void)sink;
  return 1e9 * dt / (static_cast<double>(passes) * static_cast<double>(w.inputs.size()));
}

/// Agreement with the bounds of tests/test_friction_fast.cpp: the closed form within 1e-14
/// (units of muN and muN max(a, b)), the far field within 8 eps (force) and 16 eps (moment,
/// relative), the asymptotic form identical.
int form_of(const Workload& w, const Input& in) {
  if (!w.velocity) return rectangle_friction_form(w.a, w.b, in.p);
  return in.r == 0.0 ? 5 : rectangle_friction_form(w.a, w.b, std::hypot(in.p, in.q) / std::fabs(in.r));
}

void check_agreement(Workload& w) {
  const double L = std::max(w.a, w.b);
  for (const Input& in : w.inputs) {
    const FrictionWrench n = eval(w, in, false), o = eval(w, in, true);
    const int form = form_of(w, in);
    const double df = std::hypot(n.fx - o.fx, n.fy - o.fy);
    const double dm = std::fabs(n.mf - o.mf) / (form == 0 ? L : std::fabs(o.mf) > 0 ? std::fabs(o.mf) : 1.0);
    w.max_dforce = std::max(w.max_dforce, df);
    w.max_dmoment = std::max(w.max_dmoment, dm);
    const bool ok = form == 0 ? (df <= 1e-14 && dm <= 1e-14) : (df <= 8 * kEps && dm <= 16 * kEps);
    if (!ok) w.agree = false;
  }
}

/// The production right-hand side, recording the body velocity of every evaluation.
struct RecordingRhs {
  RoughBarThesisRhs rhs;
  std::vector<Input>* seen;
  int operator()(double t, const double* y, double* d) const noexcept {
    const double c = std::cos(y[kTheta]), s = std::sin(y[kTheta]);
    const bool at_rest = y[kVx] == 0.0 && y[kVy] == 0.0 && y[kOmega] == 0.0;
    if (!at_rest) seen->push_back({c * y[kVx] + s * y[kVy], -s * y[kVx] + c * y[kVy], y[kOmega]});
    return rhs(t, y, d);
  }
};

struct RunResult {
  BsResult stats;
  std::vector<std::array<double, kRoughStateSize>> states;
  double wall = 0;
};

template <class Rhs>
RunResult integrate(const Scene& sc, const ResolvedSettings& rs, const Rhs& rhs) {
  const auto atol = sc.atol_vector(rs.rtol, rs.atol, kRoughStateSize);
  auto opt = rs.method == Method::modern ? BsOptions<double>::modern(rs.rtol, atol) : BsOptions<double>::faithful(rs.rtol, atol);
  opt.h0 = sc.solver.h0;
  opt.hmax = sc.solver.hmax;
  opt.maxstp = sc.solver.max_steps;
  const auto tout = sc.output_times();
  std::array<double, kRoughStateSize> y{};
  std::copy(sc.initial.begin(), sc.initial.end(), y.begin());
  RunResult r;
  r.states.reserve(tout.size());
  BulirschStoer<double, kRoughStateSize> bs(opt);
  const auto t0 = Clock::now();
  r.stats = bs.integrate(rhs, 0.0, y.data(), std::span<const double>(tout), [&](std::size_t, double, const double* yy) {
    std::array<double, kRoughStateSize> row{};
    std::copy(yy, yy + kRoughStateSize, row.begin());
    r.states.push_back(row);
  });
  r.wall = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

int bench_friction(const BenchFrictionOptions& o) {
  if (o.repeats < 1) throw InputError("--repeats", std::to_string(o.repeats), "must be >= 1");
  const auto load_start = load_average();
  const fs::path out_dir = o.out;
  fs::create_directories(out_dir);

  // ---- the rough scene: its settings as `nanopush run` resolves them (thesis law, C++ engine)
  Scene sc = load_scene_arg(o.scene, o.sets);
  if (!sc.rough()) throw InputError("--scene", o.scene, "must be a rough scene (surface.kind = \"rough\")");
  set_provenance_scene(o.scene);
  const ResolvedSettings rs = resolve_settings(sc, RunSettings{});
  if (rs.law != Law::thesis)
    throw InputError("surface.law", to_string(rs.law), "bench-friction integrates the thesis law (the RHS is the friction)");
  const RoughBarModel model = rough_model(sc);

  // ---- workloads
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  constexpr int kInputs = 4096;
  std::vector<Workload> work;
  auto band = [&](const std::string& name, const std::string& what, double lo, double hi, int form,
                  const std::string& old_calls, const std::string& new_calls) {
    Workload w;
    w.name = name;
    w.description = what;
    w.form = form;
    w.calls_old = old_calls;
    w.calls_new = new_calls;
    for (int i = 0; i < kInputs; ++i) {
      const double rho = lo == 0.0 ? hi * u(rng) : lo * std::pow(hi / lo, u(rng));
      w.inputs.push_back({rho * kL, 2 * 3.14159265358979323846 * u(rng), u(rng) < 0.5 ? -1.0 : 1.0});
    }
    work.push_back(std::move(w));
  };
  // Counts per wrench in the form itself (the (R, alpha) entry point adds cos, sin and three
  // divisions to both): closed form before, 2 x (2 sqrt + 4 asinh of 1 log + 1 sqrt) = 20;
  // far field before, 3 sqrt + 3 divisions per node pair (n^2/2 pairs for the n x n rule).
  band("closed_form", "R/max(a,b) < 3: corner terms", 0.0, kFrictionFarField, 0, "8 log + 12 sqrt",
       "4 log + 4 sqrt (2 two-lane)");
  band("far_gl12", "3 <= R/max(a,b) < 8: 12 x 12 Gauss-Legendre", kFrictionFarField, kFrictionGl8From, 1,
       "216 sqrt + 216 div", "144 sqrt + 72 div (two-lane: 72 + 36)");
  band("far_gl8", "8 <= R/max(a,b) < 24: 8 x 8 Gauss-Legendre", kFrictionGl8From, kFrictionGl6From, 2,
       "96 sqrt + 96 div", "64 sqrt + 32 div (two-lane: 32 + 16)");
  band("far_gl6", "24 <= R/max(a,b) < 512: 6 x 6 Gauss-Legendre", kFrictionGl6From, kFrictionGl4From, 3,
       "54 sqrt + 54 div", "36 sqrt + 18 div (two-lane: 18 + 9)");
  band("far_gl4", "512 <= R/max(a,b) < 1e9: 4 x 4 Gauss-Legendre", kFrictionGl4From, kFrictionAsymptotic, 4,
       "24 sqrt + 24 div", "16 sqrt + 8 div (two-lane: 8 + 4)");
  // The rough scene's own mix: the body velocity of every RHS evaluation of one run.
  Workload mix;
  mix.name = "run_" + o.scene;
  mix.description = "velocity form at the " + o.scene + " run's own RHS evaluations";
  mix.velocity = true;
  mix.a = model.geometry.a;
  mix.b = model.geometry.b;
  mix.calls_old = "by form, as above";
  mix.calls_new = "by form, as above";
  {
    const RecordingRhs rec{RoughBarThesisRhs{model}, &mix.inputs};
    (void)integrate(sc, rs, rec);
  }
  std::array<std::size_t, 6> mix_forms{};
  for (const Input& in : mix.inputs) ++mix_forms[static_cast<std::size_t>(form_of(mix, in))];
  work.push_back(std::move(mix));

  for (Workload& w : work) check_agreement(w);

  if (!o.quiet)
    std::cerr << "bench-friction: " << work.size() << " workloads, " << o.repeats << " repeats, "
              << fixed(o.seconds, 2) << " s each; load average " << fixed(load_start[0], 2) << "\n";

  // ---- wrench timings: per workload, old and new alternate (which goes first alternates too),
  // each timing ~ seconds / (2 repeats); the ratio of each pair is kept (a change of the host's
  // load between pairs cancels).
  for (Workload& w : work) {
    (void)time_pass(w, true, 1);  // warm-up
    (void)time_pass(w, false, 1);
    const double per_timing = o.seconds / (2.0 * o.repeats);
    const double ns_guess = time_pass(w, true, 1);
    const int passes = std::max(1, static_cast<int>(per_timing * 1e9 / (ns_guess * static_cast<double>(w.inputs.size()))));
    for (int r = 0; r < o.repeats; ++r) {
      double t_old, t_new;
      if (r % 2 == 0) {
        t_old = time_pass(w, true, passes);
        t_new = time_pass(w, false, passes);
      } else {
        t_new = time_pass(w, false, passes);
        t_old = time_pass(w, true, passes);
      }
      w.ns_old.push_back(t_old);
      w.ns_new.push_back(t_new);
      w.ratios.push_back(t_new / t_old);
    }
    if (!o.quiet)
      std::cerr << "bench-friction: " << std::left << std::setw(16) << w.name << std::right << " old "
                << fixed(median(w.ns_old), 1) << " ns, new " << fixed(median(w.ns_new), 1) << " ns, ratio "
                << fixed(median(w.ratios), 3) << "\n";
  }

  // ---- the rough scene integrated with each right-hand side, interleaved
  RoughBarModel f77_model = model;
  f77_model.f77_forms = true;
  const RoughBarThesisRhs old_rhs{f77_model};
  const RoughBarThesisRhs new_rhs{model};
  RunResult ro = integrate(sc, rs, old_rhs), rn = integrate(sc, rs, new_rhs);  // warm-up and the check
  std::vector<double> run_old, run_new, run_ratio;
  for (int r = 0; r < o.repeats; ++r) {
    double a, b;
    if (r % 2 == 0) {
      a = integrate(sc, rs, old_rhs).wall;
      b = integrate(sc, rs, new_rhs).wall;
    } else {
      b = integrate(sc, rs, new_rhs).wall;
      a = integrate(sc, rs, old_rhs).wall;
    }
    run_old.push_back(a);
    run_new.push_back(b);
    run_ratio.push_back(b / a);
  }
  // Trajectories: the largest difference of theta [rad], and of every state relative to its
  // scale (Scene::state_scales) plus its size, over the outputs.
  const auto scales = sc.state_scales();
  double dtheta = 0, dstate = 0;
  const std::size_t nrows = std::min(ro.states.size(), rn.states.size());
  for (std::size_t i = 0; i < nrows; ++i)
    for (int c = 0; c < kRoughStateSize; ++c) {
      const double d = std::fabs(ro.states[i][static_cast<std::size_t>(c)] - rn.states[i][static_cast<std::size_t>(c)]);
      if (c == kTheta) dtheta = std::max(dtheta, d);
      dstate = std::max(dstate, d / (scales[static_cast<std::size_t>(c)] + std::fabs(ro.states[i][static_cast<std::size_t>(c)])));
    }
  const bool run_same_length = ro.states.size() == rn.states.size();
  if (!o.quiet)
    std::cerr << "bench-friction: " << o.scene << " run: old " << fixed(1e3 * median(run_old), 3) << " ms, new "
              << fixed(1e3 * median(run_new), 3) << " ms, ratio " << fixed(median(run_ratio), 3) << "; RHS "
              << ro.stats.nfcn << " / " << rn.stats.nfcn << ", max |dtheta| " << sci(dtheta) << " rad\n";
  const auto load_end = load_average();

  // ---- CSV
  const Columns cols = columns("bench_friction");
  std::vector<std::vector<std::string>> rows;
  auto add_row = [&](const std::string& name, std::size_t inputs, const std::vector<double>& a,
                     const std::vector<double>& b, const std::vector<double>& ratio, double df, double dm, double unit) {
    rows.push_back({csv_quote(name), std::to_string(inputs), std::to_string(ratio.size()), csv_number(unit * median(a)),
                    csv_number(unit * median(b)), csv_number(median(ratio)),
                    csv_number(*std::min_element(ratio.begin(), ratio.end())),
                    csv_number(*std::max_element(ratio.begin(), ratio.end())), csv_number(df), csv_number(dm)});
  };
  for (const Workload& w : work)
    add_row(w.name, w.inputs.size(), w.ns_old, w.ns_new, w.ratios, w.max_dforce, w.max_dmoment, 1.0);
  add_row("integrate_" + o.scene, static_cast<std::size_t>(rn.stats.nfcn), run_old, run_new, run_ratio, dtheta, dstate,
          1e9);
  const fs::path csv = out_dir / "friction_bench.csv";
  RunInfo info = {{"load_start", load_start[0]}, {"load_end", load_end[0]},
                  {"cores", std::max(1u, std::thread::hardware_concurrency())}};
  write_csv_atomic(csv, cols, rows, o.scene, info);

  // ---- plot: ns per wrench, old and new, per workload (log scale)
  const fs::path png = out_dir / "friction_bench.png";
  const std::string plot_note = plot_skipped(o.no_plot);
  if (plot_note.empty()) {
    std::ostringstream b;
    b << "set title 'friction wrench: ns per call, F77 forms and production forms (median of " << o.repeats
      << " interleaved pairs)' noenhanced\n"
      << "set datafile separator ','\nset style data histograms\nset style histogram clustered gap 1\n"
      << "set style fill solid 0.8 border -1\nset boxwidth 0.9\nset logscale y\nset ylabel 'ns per wrench'\n"
      << "set grid ytics\nset key outside right top\nset xtics rotate by -25 noenhanced\n"
      << "plot '" << csv.string() << "' every ::0::" << work.size() - 1
      << " skip 1 using 4:xtic(1) title 'F77 forms (faithful)' lc rgb '#999999', '' every ::0::"
      << work.size() - 1 << " skip 1 using 5 title 'production forms' lc rgb '#1f77b4'\n";
    plot::render_script(b.str(), png, 900, 550);
  }

  // ---- report
  bool all_agree = run_same_length && ro.stats.nfcn > 0;
  for (const Workload& w : work) all_agree = all_agree && w.agree;
  const auto met = [](bool ok) { return ok ? std::string("met") : std::string("**NOT met**"); };
  std::ostringstream md;
  md << "# Friction wrench benchmark\n\n"
     << "`nanopush bench-friction`: ns per friction wrench, the production forms (`friction.hpp`: `closed_form`, "
        "`far_field`; \"after\") against the F77 routine's forms, which the faithful method keeps "
        "(`closed_form_reference`, `far_field_reference`; \"before\"), in one binary. "
        "Contact a = 27.5 nm, b = 50 nm (the thesis nanobar); 4096 inputs per workload; per workload "
     << o.repeats << " timed pairs (old, new) back to back, alternating which goes first, about "
     << fixed(1e3 * o.seconds / (2.0 * o.repeats), 0)
     << " ms each; the ratio is the median of the pairs' ratios. Host: "
     << std::max(1u, std::thread::hardware_concurrency()) << " cores, load average (1 min) " << fixed(load_start[0], 2)
     << " at the start, " << fixed(load_end[0], 2) << " at the end.\n\n"
     << "| workload | log/sqrt/div per wrench before | after | ns before | ns after | ratio (min–max) | "
        "max \\|Δf\\|/μN | max Δmf |\n|---|---|---|---|---|---|---|---|\n";
  for (const Workload& w : work)
    md << "| " << w.name << ": " << w.description << " | " << w.calls_old << " | " << w.calls_new << " | "
       << fixed(median(w.ns_old), 1) << " | " << fixed(median(w.ns_new), 1) << " | **" << fixed(median(w.ratios), 3)
       << "** (" << fixed(*std::min_element(w.ratios.begin(), w.ratios.end()), 3) << "–"
       << fixed(*std::max_element(w.ratios.begin(), w.ratios.end()), 3) << ") | " << sci(w.max_dforce) << " | "
       << sci(w.max_dmoment) << " |\n";
  const Workload& m = work.back();
  md << "\nThe (R, α) entry point adds cos α, sin α and three divisions to every row (~20–25 ns, the same "
        "before and after); the velocity entry point (`run_` row, what the rough right-hand side calls) a "
        "square root and five divisions. Δmf is relative to μN max(a, b) in the closed form and to |mf| "
        "elsewhere. The `"
     << m.name << "` row times the " << m.inputs.size() << " body velocities of one run's RHS evaluations; by form: ";
  const char* form_names[6] = {"closed form", "12 × 12", "8 × 8", "6 × 6", "4 × 4", "asymptotic"};
  for (int f = 0; f < 6; ++f)
    md << form_names[f] << " " << fixed(100.0 * static_cast<double>(mix_forms[static_cast<std::size_t>(f)]) /
                                            static_cast<double>(std::max<std::size_t>(1, m.inputs.size())),
                                        0)
       << " %" << (f < 5 ? ", " : ".\n\n");
  md << "| the whole run: " << o.scene << " (" << to_string(rs.method) << ", rtol " << rs.rtol << ", " << to_string(rs.law)
     << " law), integrated by the C++ engine | before | after | ratio (min–max) |\n|---|---|---|---|\n"
     << "| wall time [ms], median of " << o.repeats << " | " << fixed(1e3 * median(run_old), 3) << " | "
     << fixed(1e3 * median(run_new), 3) << " | **" << fixed(median(run_ratio), 3) << "** ("
     << fixed(*std::min_element(run_ratio.begin(), run_ratio.end()), 3) << "–"
     << fixed(*std::max_element(run_ratio.begin(), run_ratio.end()), 3) << ") |\n"
     << "| RHS evaluations, accepted / rejected steps | " << ro.stats.nfcn << ", " << ro.stats.naccpt << " / "
     << ro.stats.nrejct << " | " << rn.stats.nfcn << ", " << rn.stats.naccpt << " / " << rn.stats.nrejct << " | |\n"
     << "| trajectory: max \\|Δθ\\| [rad]; max state difference / (scale + \\|value\\|) | " << sci(dtheta) << "; "
     << sci(dstate) << " | | |\n\n";
  md << "| target | measured | |\n|---|---|---|\n";
  for (const Workload& w : work)
    md << "| " << w.name << ": ns per wrench <= " << kTarget << " × before | " << fixed(median(w.ratios), 3) << " | "
       << met(median(w.ratios) <= kTarget) << " |\n";
  md << "| new and old agree (closed form 1e-14, far field 8 eps force and 16 eps moment, the bounds of "
        "tests/test_friction_fast.cpp) | "
     << (all_agree ? "yes" : "**no**") << " | " << met(all_agree) << " |\n";
  md << "\nFiles: `" << csv.filename().string() << "` (sidecar `" << schema_path(csv).filename().string() << "`)";
  if (plot_note.empty())
    md << ", `" << png.filename().string() << "`:\n\n![ns per wrench, before and after](" << png.filename().string()
       << ")\n";
  else
    md << "; " << plot_note << ".\n";
  write_and_print_report(out_dir / "report.md", md.str());
  return bench_status(all_agree, "bench-friction: the new and the old forms disagree beyond the tests' bounds (report.md)");
}

RegisterCommand reg{
    {"bench-friction",
     "Benchmark of the friction wrench: ns per call of the production forms against the F77 routine's forms (same "
     "binary, interleaved), by evaluation form and at a rough scene's own RHS evaluations, and the scene's run "
     "with each; CSV, PNG and report.md (docs/performance.md)",
     92, options_then<BenchFrictionOptions>(bench_friction, [](CLI::App& app, BenchFrictionOptions& o) {
       app.add_option("--out", o.out, "output directory: friction_bench.csv (+ .schema.json), friction_bench.png "
                                       "(+ .gp), report.md")
           ->capture_default_str();
       app.add_option("--scene", o.scene, "rough scene (file or preset) whose run is timed with each form")
           ->capture_default_str();
       add_set_option(app, o.sets);
       app.add_option("--repeats", o.repeats, "timed pairs (old, new) per workload and of the run")
           ->check(count(1, 1000))
           ->capture_default_str();
       app.add_option("--seconds", o.seconds, "time per wrench workload, both forms together (s)")
           ->check(CLI::Range(1e-4, 600.0))
           ->capture_default_str();
       app.add_flag("--no-plot", o.no_plot, "no PNG (the CSV and report only)");
       app.add_flag("--quiet", o.quiet, "no progress on standard error");
     })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
