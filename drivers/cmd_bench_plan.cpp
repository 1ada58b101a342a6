// nanopush bench-plan: the push planner against a lab's target-oriented baseline on seeded
// tasks (docs/planning.md, "Benchmark"): success rate, pushes, tip travel, time, planning time.
// Writes plan_benchmark.csv (+ schema), plan_benchmark.md and plan_benchmark.png.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>

#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "nanopush/planning/check.hpp"
#include "nanopush/planning/plan.hpp"
#include "bench_report.hpp"
#include "bench_options.hpp"
#include "cli_checks.hpp"
#include "columns.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

namespace fs = std::filesystem;

struct BenchPlanOptions : BenchDirectoryOptions {
  int tasks = 200;
  int max_pushes = 20;
  std::uint64_t seed = 20121;
  double tolerance_distance = 1e-9, tolerance_angle = 0.01;
  /// The closed loop: the first N tasks again, mu of the truth unknown within +-30 %, imaging
  /// noise sigma 1 nm (x, y) and 0.01 rad, tolerance three of those sigmas.
  int closed_loop = 40;
  double noise_distance = 1e-9, noise_angle = 0.01;
  /// Robust plans: the first N tasks planned for the model alone and for a tip friction in
  /// 0-0.3 and start noise, each checked open loop in `robust_trials` worlds.
  int robust = 10, robust_trials = 50;
};

/// The two bars of the thesis: the nanobar of chapter 3 and the nanorod of chapters 4-5.
Scene bar_scene(bool rod) {
  std::ostringstream s;
  s << "[object]\nlength = " << (rod ? "590e-9" : "100e-9") << "\nwidth = " << (rod ? "27e-9" : "55e-9")
    << "\nheight = " << (rod ? "27e-9" : "50e-9")
    << "\ndensity = 2267.0\n[push]\nmode = \"tip\"\n[tip]\nstart_x = -1e-6\nstart_y = 0.0\ntravel = 1e-9\n"
       "radius = 10e-9\nspeed = 1e-6\n[surface]\nkind = \"rough\"\nmu = 0.1\nf_vdw = 1e-8\n[solver]\nsamples = 2\n";
  return parse_scene(s.str(), rod ? "nanorod" : "nanobar");
}

/// A uniform double in [0, 1) from the generator's raw bits (the same on every platform,
/// unlike std::uniform_real_distribution).
double uniform(std::mt19937_64& r) { return static_cast<double>(r() >> 11) * 0x1.0p-53; }

/// The closed loop a lab runs (plan::closed_loop) on the first o.closed_loop tasks: the truth's
/// surface mu uniform within +-30 % of the model's and its tip friction uniform in 0-0.3 (the
/// model assumes a frictionless tip), imaging noise o.noise_*, a tolerance of three noise sigmas
/// (a true pose cannot be judged finer than the images show it). Each task runs twice: re-fitting
/// the tip friction after every push (the loop's default) and keeping the model's. Writes
/// plan_closed_loop.csv; returns the Markdown paragraph.
std::string closed_loop_bench(const BenchPlanOptions& o, const Scene (&bars)[2], const std::vector<plan::Pose>& goals) {
  const int n = std::min<int>(o.closed_loop, static_cast<int>(goals.size()));
  if (n <= 0) return {};
  plan::PlanOptions po;
  po.tolerance_distance = 3 * o.noise_distance;
  po.tolerance_angle = 3 * o.noise_angle;
  po.max_pushes = o.max_pushes;
  const plan::Noise noise{o.noise_distance, o.noise_distance, o.noise_angle};
  std::mt19937_64 rng(o.seed + 1);
  CsvWriter w(fs::path(o.out) / "plan_closed_loop.csv",
              columns("bench_plan_closed_loop"),
              "bench-plan");
  int reached = 0, reached_kept = 0, unsimulated = 0;
  std::vector<double> pushes, pushes_kept, planning, fit_error;
  for (int k = 0; k < n; ++k) {
    const bool rod = k % 2 == 1;
    Scene truth = bars[rod];
    const double mu = 0.1 * (0.7 + 0.6 * uniform(rng));
    const double tip_mu = 0.3 * uniform(rng);
    truth.set({{"surface.mu", mu}, {"tip.mu", tip_mu}});
    const auto& goal = goals[static_cast<std::size_t>(k)];
    const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(k);
    const plan::ClosedLoopResult r = plan::closed_loop(bars[rod], truth, goal, po, noise, seed);
    const plan::ClosedLoopResult kept = plan::closed_loop(bars[rod], truth, goal, po, noise, seed, plan::Refit{false});
    reached_kept += kept.reached() ? 1 : 0;
    pushes_kept.push_back(static_cast<double>(kept.steps.size()));
    fit_error.push_back(std::fabs(r.tip_mu - tip_mu));
    reached += r.reached() ? 1 : 0;
    unsimulated += r.unsimulated;
    pushes.push_back(static_cast<double>(r.steps.size()));
    planning.push_back(r.planning_seconds);
    w.cells({csv_number(k + 1), rod ? "nanorod" : "nanobar", csv_number(mu), csv_number(tip_mu), csv_number(r.tip_mu),
             r.reached() ? "1" : "0", csv_number(static_cast<double>(r.steps.size())), kept.reached() ? "1" : "0",
             csv_number(static_cast<double>(kept.steps.size())), csv_number(r.tip_travel), csv_number(r.planning_seconds),
             csv_number(r.final_distance), csv_number(r.final_angle)});
    std::cerr << "\rbench-plan: closed loop " << k + 1 << "/" << n << std::flush;
  }
  std::cerr << "\n";
  w.commit();
  std::ostringstream md;
  md << std::setprecision(3) << "\n**Closed loop** (the first " << n << " tasks; the true surface mu uniform in 0.07-0.13, "
     << "the model's 0.1; the true tip friction uniform in 0-0.3, the model's 0; imaging noise " << o.noise_distance * 1e9
     << " nm and " << o.noise_angle << " rad; tolerance " << po.tolerance_distance * 1e9 << " nm and " << po.tolerance_angle
     << " rad): re-fitting the tip friction after each push, reached " << reached << "/" << n << " ("
     << 100.0 * reached / n << " %), median pushes " << median(pushes) << ", median planning " << median(planning)
     << " s, median |tip mu fitted - true| " << median(fit_error) << "; keeping the model's tip friction, reached "
     << reached_kept << "/" << n << ", median pushes " << median(pushes_kept) << "; " << unsimulated << " planned pushes could not be made on the true bar (the tip would "
     << "start inside it, or the model could not follow the push there) and the bar was imaged again. "
     << "plan_closed_loop.csv has each task.\n";
  return md.str();
}

/// Robust plans (plan --robust) on the first o.robust tasks: each planned for the model alone
/// (tip mu 0) and robustly (tip mu at 0 and 0.3, the start shifted by 2 sigma of a 0.3 nm /
/// 0.002 rad noise), tolerance 2 nm and 0.02 rad; both checked open loop in o.robust_trials
/// worlds with the tip mu uniform in 0-0.3 and that start noise. Writes plan_robust.csv;
/// returns the Markdown paragraph.
std::string robust_bench(const BenchPlanOptions& o, const Scene (&bars)[2], const std::vector<plan::Pose>& goals) {
  const int n = std::min<int>(o.robust, static_cast<int>(goals.size()));
  if (n <= 0) return {};
  plan::PlanOptions po;
  po.tolerance_distance = 2e-9;
  po.tolerance_angle = 0.02;
  po.max_pushes = o.max_pushes;
  const plan::Noise noise{0.3e-9, 0.3e-9, 0.002};
  plan::PlanOptions ro = po;
  ro.robust_tip_mu_lo = 0;
  ro.robust_tip_mu_hi = 0.3;
  ro.robust_start_x = 2 * noise.x;
  ro.robust_start_y = 2 * noise.y;
  ro.robust_start_theta = 2 * noise.theta;
  plan::CheckWorlds worlds{noise, 0, 0, o.seed + 2, 0.0, 0.3};
  CsvWriter w(fs::path(o.out) / "plan_robust.csv", columns("bench_plan_robust"), "bench-plan");
  int found[2] = {0, 0};
  std::vector<double> success[2], pushes[2], planning[2];
  for (int k = 0; k < n; ++k) {
    const bool rod = k % 2 == 1;
    const auto& goal = goals[static_cast<std::size_t>(k)];
    std::vector<std::string> cells{csv_number(k + 1), rod ? "nanorod" : "nanobar"};
    double seconds[2] = {0, 0};
    for (int which = 0; which < 2; ++which) {
      const plan::PlanResult r = plan::plan_pushes(bars[rod], goal, which == 0 ? po : ro);
      const bool ok = r.found() && r.verified;
      const double p = ok ? plan::check_plan(bars[rod], r, po, worlds, o.robust_trials).probability : 0.0;
      found[which] += ok ? 1 : 0;
      success[which].push_back(p);
      pushes[which].push_back(static_cast<double>(r.pushes.size()));
      planning[which].push_back(r.planning_seconds);
      seconds[which] = r.planning_seconds;
      for (const std::string& c : {std::string(ok ? "1" : "0"), csv_number(static_cast<double>(r.pushes.size())), csv_number(p)})
        cells.push_back(c);
    }
    cells.push_back(csv_number(seconds[0]));
    cells.push_back(csv_number(seconds[1]));
    w.cells(cells);
    std::cerr << "\rbench-plan: robust " << k + 1 << "/" << n << std::flush;
  }
  std::cerr << "\n";
  w.commit();
  auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / static_cast<double>(v.size());
  };
  std::ostringstream md;
  md << std::setprecision(3) << "\n**Robust plans** (the first " << n << " tasks; tolerance 2 nm and 0.02 rad; each "
     << "plan checked open loop in " << o.robust_trials << " worlds with the tip friction uniform in 0-0.3 and start "
     << "noise 0.3 nm and 0.002 rad): the model's plan (tip mu 0) found " << found[0] << "/" << n
     << ", success in the worlds " << 100 * mean(success[0]) << " % on average (median pushes " << median(pushes[0])
     << ", median planning " << median(planning[0]) << " s); the robust plan (`--robust`: tip mu 0 and 0.3, the start "
     << "shifted by 2 sigma) found " << found[1] << "/" << n << ", success " << 100 * mean(success[1])
     << " % on average (median pushes " << median(pushes[1]) << ", median planning " << median(planning[1])
     << " s). A plan not found counts as 0 %. plan_robust.csv has each task.\n";
  return md.str();
}

int run_bench_plan(const BenchPlanOptions& o) {
  fs::create_directories(o.out);
  const Scene bars[2] = {bar_scene(false), bar_scene(true)};
  std::mt19937_64 rng(o.seed);
  plan::PlanOptions po;
  po.tolerance_distance = o.tolerance_distance;
  po.tolerance_angle = o.tolerance_angle;
  po.max_pushes = o.max_pushes;
  const Columns cols = columns("bench_plan");
  const fs::path csv = fs::path(o.out) / "plan_benchmark.csv";
  CsvWriter w(csv, cols, "bench-plan");
  struct Stats {
    int found = 0, n = 0;
    std::vector<double> pushes, travel, time, planning;
  } st[2];
  std::vector<double> ratio;  // planner pushes / baseline pushes, tasks both solve
  std::vector<plan::Pose> goals;
  for (int k = 0; k < o.tasks; ++k) {
    const bool rod = k % 2 == 1;
    const Scene& sc = bars[rod];
    const double L = sc.length, r = 5 * L * std::sqrt(uniform(rng)), phi = 2 * M_PI * uniform(rng);
    const plan::Pose goal{r * std::cos(phi), r * std::sin(phi), M_PI * (2 * uniform(rng) - 1)};
    goals.push_back(goal);
    int pushes[2] = {0, 0};
    bool found[2] = {false, false};
    for (int which = 0; which < 2; ++which) {
      const plan::PlanResult res = which == 0 ? plan::plan_pushes(sc, goal, po) : plan::plan_baseline(sc, goal, po);
      Stats& s = st[which];
      ++s.n;
      found[which] = res.found() && res.verified;
      pushes[which] = static_cast<int>(res.pushes.size());
      if (found[which]) {
        ++s.found;
        s.pushes.push_back(pushes[which]);
        s.travel.push_back(res.tip_travel);
        s.time.push_back(res.time);
      }
      s.planning.push_back(res.planning_seconds);
      w.cells({csv_number(k + 1), which == 0 ? "plan" : "baseline", rod ? "nanorod" : "nanobar", csv_number(goal.x),
               csv_number(goal.y), csv_number(goal.theta), found[which] ? "1" : "0", csv_number(pushes[which]),
               csv_number(res.tip_travel), csv_number(res.time), csv_number(res.planning_seconds),
               csv_number(res.final_distance), csv_number(res.final_angle)});
    }
    if (found[0] && found[1]) ratio.push_back(double(pushes[0]) / pushes[1]);
    std::cerr << "\rbench-plan: " << k + 1 << "/" << o.tasks << " tasks" << std::flush;
  }
  std::cerr << "\n";
  w.commit();
  const std::string loop_md = closed_loop_bench(o, bars, goals) + robust_bench(o, bars, goals);
  std::ostringstream md;
  md << std::setprecision(3) << "| planner | success | median pushes | median tip travel (nm) | median time (s) | median planning (s) |\n"
     << "|---|---|---|---|---|---|\n";
  for (int which = 0; which < 2; ++which) {
    const Stats& s = st[which];
    md << "| " << (which == 0 ? "plan" : "baseline") << " | " << s.found << "/" << s.n << " ("
       << 100.0 * s.found / std::max(1, s.n) << " %) | " << median(s.pushes) << " | " << median(s.travel) * 1e9 << " | "
       << median(s.time) << " | " << median(s.planning) << " |\n";
  }
  md << "\nTasks both solve: " << ratio.size() << "; median ratio of pushes (plan / baseline): " << median(ratio)
     << ". Seed " << o.seed << ", " << o.tasks << " tasks (nanobar and nanorod alternately), goals uniform within five "
     << "body lengths, any orientation, tolerance " << o.tolerance_distance << " m and " << o.tolerance_angle
     << " rad, at most " << o.max_pushes << " pushes.\n" << loop_md;
  write_file_atomic(fs::path(o.out) / "plan_benchmark.md", md.str());
  plot::Figure fig;
  fig.title = "bench-plan: pushes per task";
  fig.cols = 2;
  plot::Panel p1{"pushes (0: not found)", "task", "pushes", false, false, "set key top left", {}};
  p1.series.push_back({csv, "1", "(strcol(2) eq 'plan' ? $8 * $7 : NaN)", "plan", "points pt 7 ps 0.6"});
  p1.series.push_back({csv, "1", "(strcol(2) eq 'baseline' ? $8 * $7 : NaN)", "baseline", "points pt 6 ps 0.8"});
  plot::Panel p2{"planning time", "task", "s", false, true, "set key top left", {}};
  p2.series.push_back({csv, "1", "(strcol(2) eq 'plan' ? $11 : NaN)", "plan", "points pt 7 ps 0.6"});
  p2.series.push_back({csv, "1", "(strcol(2) eq 'baseline' ? $11 : NaN)", "baseline", "points pt 6 ps 0.8"});
  fig.panels = {p1, p2};
  plot::render(fig, fs::path(o.out) / "plan_benchmark.png");
  std::cout << md.str();
  return 0;
}

RegisterCommand reg{{"bench-plan",
                     "Benchmark of the push planner against target-oriented pushing on seeded tasks (docs/planning.md)",
                     94, options_then<BenchPlanOptions>(run_bench_plan, [](CLI::App& app, BenchPlanOptions& o) {
                       add_bench_directory_option(app, o);
                       app.add_option("--tasks", o.tasks, "number of seeded tasks")->check(count(1, 100000))->capture_default_str();
                       app.add_option("--max-pushes", o.max_pushes, "pushes allowed per task")
                           ->check(count(1, 1000))
                           ->capture_default_str();
                       app.add_option("--seed", o.seed, "seed of the tasks")->check(count(0, 1000000000000LL))->capture_default_str();
                       app.add_option("--closed-loop", o.closed_loop,
                                      "closed-loop tasks (the first N tasks again, mu unknown within +-30 %, imaging noise; 0: none)")
                           ->check(count(0, 100000))
                           ->capture_default_str();
                       app.add_option("--robust", o.robust,
                                      "robust-plan tasks (the first N tasks planned for the model and for a tip mu in "
                                      "0-0.3 and start noise, each checked open loop; 0: none)")
                           ->check(count(0, 100000))
                           ->capture_default_str();
                       app.add_option("--robust-trials", o.robust_trials, "worlds each robust-plan task is checked in")
                           ->check(count(1, 1000000))
                           ->capture_default_str();
                     })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
