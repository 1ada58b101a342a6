// nanopush bench-accuracy: how honest the error estimate is and what --accuracy costs, on a
// seeded Latin hypercube of rough scenes over the physical space (docs/accuracy.md).
//  1. Honesty: each scene run as a user runs it (method auto, the scene's rtol drawn from
//     1e-12..1e-4), its error estimate against the true error (a run 100x tighter than the
//     answer and at most 1e-13, modern Bulirsch-Stoer; in long double below double's floor),
//     under the coulomb and thesis laws; the outcome of every scene.
//  2. Cost: --accuracy E for E = 1e-4 .. 1e-12 (coulomb law): the fraction of judged scenes
//     whose true error is <= E, and the RHS evaluations (estimate included) over those of a
//     plain run at rtol = E.
// Writes accuracy_honesty.csv, accuracy_cost.csv (+ sidecars), accuracy.png and accuracy.md;
// also a reproduce step (fewer scenes) with its section in out/report.md.
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

#include "nanopush/engines/accuracy.hpp"
#include "nanopush/engines/engines.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "nanopush/scenes/lhs.hpp"
#include "bench_options.hpp"
#include "cli_checks.hpp"
#include "bench_report.hpp"
#include "columns.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct BenchAccuracyOptions : BenchDirectoryOptions {
  int scenes = 200;
  std::uint64_t seed = 2026;
  double tightest = 1e-12;  ///< the smallest E of the cost table (reproduce: 1e-6, for its time)
};

constexpr double kReferenceRtol = 1e-13, kLongReferenceRtolMin = 1e-18;

/// The true error of `tr` (accuracy norm), against a modern run 100x tighter than tr's rtol and
/// at most 1e-13, in long double where that is below double's floor (not below 1e-18); NaN
/// when the reference does not complete.
double true_error(const Scene& sc, Law law, const Trajectory& tr) {
  RunSettings r;
  r.method = Method::modern;
  r.law = law;
  r.rtol = std::min(kReferenceRtol, tr.rtol / 100);
  r.error_estimate = false;
  r.allow_partial = true;
  if (r.rtol < 10 * rtol_in_eps<double>(kDenseRtolEps)) {
    r.precision = Precision::long_;
    r.rtol = std::max(r.rtol, kLongReferenceRtolMin);
  }
  if (!tr.error.available) return std::nan("");
  const Trajectory ref = run_engine(sc, r);
  if (!ref.complete || ref.rows.size() != tr.rows.size()) return std::nan("");
  return pose_error_norm(tr.rows.back(), ref.rows.back(), tr.error.length_scale);
}

/// What the cheapest answers to --accuracy E cost on one scene, as RHS evaluations over a plain
/// run at rtol = E: `pair`, the cheapest pair of runs at r and r / kCompanionFactor whose answers
/// differ by <= E (the least any answer checked by a second solve pays), and `single`, the
/// cheapest single run whose true error is <= E (what a scheme that knew the answer's error
/// without checking it would pay). r runs over E 10^(-k/2), k = 0, 1, ... down to the floor of
/// double, method auto as --accuracy runs it; NaN where no r on that grid qualifies. The pairs
/// through grid index `through` are all tried, so the bound covers --accuracy's own last pair.
/// Grid points (half decades) between a run and its companion.
std::size_t pair_step() { return static_cast<std::size_t>(std::lround(2 * std::log10(kCompanionFactor))); }

struct CostBound {
  double pair = std::nan(""), single = std::nan("");
};

CostBound cheapest_answers(const Scene& sc, double e, const Trajectory& plain, std::size_t through) {
  RunSettings r;
  r.law = Law::coulomb;
  r.allow_partial = true;
  r.error_estimate = false;
  std::deque<Trajectory> runs{plain};  // at() appends: a deque keeps the references it gave
  const auto at = [&](std::size_t k) -> const Trajectory& {
    while (runs.size() <= k) {
      r.rtol = e * std::pow(10.0, -0.5 * static_cast<double>(runs.size()));
      runs.push_back(run_engine(sc, r));
    }
    return runs[k];
  };
  const auto usable = [](const Trajectory& t) { return t.complete && is_answer(t.outcome) && !t.rows.empty(); };
  CostBound b;
  if (plain.outcome == Outcome::at_rest) {  // exact after one run (docs/accuracy.md)
    b.pair = b.single = 1;
    return b;
  }
  const double floor = rtol_in_eps<double>(kDenseRtolEps);
  const std::size_t step = pair_step();
  double pair = std::numeric_limits<double>::infinity();
  std::size_t first = 0;
  bool found = false;
  // The cost is nearly monotone in 1/r: two grid points past the first pair that agrees suffice
  // (and the pairs through `through`, where --accuracy stopped).
  for (std::size_t k = 0; e * std::pow(10.0, -0.5 * static_cast<double>(k + step)) >= floor; ++k) {
    if (found && k > first + 2 && k > through) break;
    const Trajectory& a = at(k);
    const Trajectory& c = at(k + step);
    if (!usable(a) || !usable(c) || estimate_from(sc, a, c).norm > e) continue;
    pair = std::min(pair, static_cast<double>(a.stats.nfcn + c.stats.nfcn));
    if (!found) first = k;
    found = true;
  }
  const double base = static_cast<double>(std::max<std::int64_t>(1, plain.stats.nfcn));
  if (found) b.pair = pair / base;
  RunSettings ref;
  ref.method = Method::modern;
  ref.law = Law::coulomb;
  ref.precision = Precision::long_;
  ref.rtol = kLongReferenceRtolMin;
  ref.error_estimate = false;
  ref.allow_partial = true;
  const Trajectory truth = run_engine(sc, ref);
  if (!usable(truth)) return b;
  for (const Trajectory& t : runs)
    if (usable(t) && t.rows.size() == truth.rows.size() && estimate_from(sc, t, truth).norm <= e)
      b.single = std::min(std::isnan(b.single) ? std::numeric_limits<double>::infinity() : b.single,
                          static_cast<double>(t.stats.nfcn) / base);
  return b;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

/// A bound's cell: "-" where the quantile falls among scenes with no qualifying run in double.
std::string bound_cell(double v) {
  if (std::isinf(v)) return "-";
  std::ostringstream s;
  s << std::setprecision(3) << v;
  return s.str();
}

struct Summary {
  std::map<std::string, int> outcomes;
  int judged = 0, dishonest = 0;
};

/// Both parts; the Markdown summary into `md`. Returns false if a check failed.
bool bench_accuracy(const BenchAccuracyOptions& o, const fs::path& dir, std::ostream& md, std::ostream& log,
                    ReproduceContext* ctx) {
  const Scene base = load_scene(resolve_scene("fig3_18"));
  const auto scenes = rough_lhs_scenes(base, static_cast<std::size_t>(o.scenes), o.seed);
  bool ok = true;
  // ---- 1. honesty ------------------------------------------------------------------------
  CsvWriter hon(dir / "accuracy_honesty.csv",
                columns("bench_accuracy_honesty"));
  std::map<std::string, Summary> by_law;
  std::vector<double> cost_ratio;
  for (const Law law : {Law::coulomb, Law::thesis}) {
    Summary& s = by_law[to_string(law)];
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      RunSettings rs;
      rs.law = law;
      rs.allow_partial = true;
      const Trajectory tr = run_engine(scenes[i], rs);
      ++s.outcomes[to_string(tr.outcome)];
      double truth = std::nan("");
      if (is_answer(tr.outcome)) truth = true_error(scenes[i], law, tr);
      if (!std::isnan(truth)) {
        ++s.judged;
        if (truth > 10 * tr.error.norm + 1e-11) ++s.dishonest;
        cost_ratio.push_back(static_cast<double>(tr.nfcn_total()) / static_cast<double>(std::max<std::int64_t>(1, tr.stats.nfcn)));
      }
      hon.cells({to_string(law), std::to_string(i), csv_number(tr.rtol), to_string(tr.outcome), csv_number(tr.error.norm),
                 csv_number(truth), csv_number(truth / tr.error.norm), std::to_string(tr.stats.nfcn),
                 std::to_string(tr.nfcn_total())});
    }
    log << "bench-accuracy: " << to_string(law) << ": " << s.judged << " judged, " << s.dishonest << " dishonest\n";
    if (s.dishonest * 100 > s.judged) ok = false;
  }
  hon.commit();
  md << "**Honesty of the estimate.** " << o.scenes << " rough scenes of a Latin hypercube over the physical space "
     << "(seed " << o.seed << "; length 10 nm-10 um, width/length 0.01-1, height 1 nm-1 um, density 1e3-2e4 kg/m^3, "
     << "push 1e-12-1e-3 N anywhere on the body, mu 1e-3-2, f_vdw 1e-12-1e-3 N, rtol 1e-12-1e-4; fig3_18 "
     << "otherwise), each run with method auto and its estimate, judged against a modern run 100x tighter (at most "
     << "1e-13; in long double below 1e-14). Target: true error > 10x the estimate at <= 1 % of the judged scenes.\n\n"
     << "| law | ok | at_rest | no_static_friction | law_blowup | solver_failure | judged | true > 10x estimate |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (auto& [law, s] : by_law)
    md << "| " << law << " | " << s.outcomes["ok"] << " | " << s.outcomes["at_rest"] << " | "
       << s.outcomes["no_static_friction"] << " | " << s.outcomes["law_blowup"] << " | " << s.outcomes["solver_failure"]
       << " | " << s.judged << " | " << s.dishonest << " |\n";
  md << "\nThe estimate's cost (all RHS evaluations over the answer's): median " << std::setprecision(3)
     << quantile(cost_ratio, 0.5) << ", 90th percentile " << quantile(cost_ratio, 0.9) << ".\n\n";
  // ---- 2. cost of --accuracy ---------------------------------------------------------------
  CsvWriter cost(dir / "accuracy_cost.csv",
                 columns("bench_accuracy_cost"));
  md << "**Cost of `--accuracy`** (coulomb law, the first " << scenes.size() / 2
     << " scenes): the fraction of judged scenes whose true error is <= E, and all RHS evaluations of the answer "
        "over those of a plain run at rtol = E. Target: >= 99 % met, cost <= 4x. The runs each answer took "
        "(the first at rtol = E, each next 100 times tighter) say where the cost goes: a verified answer needs "
        "two, a scene whose first pair disagrees three or more. The last two columns bound what any scheme "
        "could pay (90th percentiles, rtol on a half-decade grid from E down to the floor of double, method "
        "auto; \"-\" where the percentile falls among scenes that need more digits than double holds): "
        "`checked pair`, "
        "the cheapest pair of runs at r and r/100 whose answers differ by <= E, chosen knowing in advance "
        "which r agrees (the least an answer checked by a second solve pays); `single run`, the cheapest "
        "run whose true error is <= E, chosen knowing that error (no check at all).\n\n"
     << "| E | answered | not reached | judged | met | median cost | 90th pct cost | 1 run | 2 runs | 3 runs | "
        ">= 4 runs | bound: checked pair | bound: single run |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const double e : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    if (e < 0.5 * o.tightest) break;
    int answered = 0, not_reached = 0, judged = 0, met = 0;
    std::array<int, 4> by_runs{};  // answers that took 1, 2, 3, >= 4 runs
    std::vector<double> ratios, bound_pair, bound_single;
    for (std::size_t i = 0; i < scenes.size() / 2; ++i) {
      RunSettings rs;
      rs.law = Law::coulomb;
      rs.allow_partial = true;
      rs.accuracy = e;
      const Trajectory tr = run_engine(scenes[i], rs);
      RunSettings plain;
      plain.law = Law::coulomb;
      plain.allow_partial = true;
      plain.rtol = e;
      plain.error_estimate = false;
      const Trajectory pl = run_engine(scenes[i], plain);
      if (tr.outcome == Outcome::accuracy_not_reached) ++not_reached;
      double truth = std::nan("");
      if (is_answer(tr.outcome)) {
        ++answered;
        ++by_runs[static_cast<std::size_t>(std::clamp(tr.accuracy.runs, 1, 4) - 1)];
        truth = true_error(scenes[i], Law::coulomb, tr);
        if (!std::isnan(truth)) {
          ++judged;
          met += truth <= e ? 1 : 0;
        }
      }
      const double ratio = pl.complete ? static_cast<double>(tr.nfcn_total()) / static_cast<double>(std::max<std::int64_t>(1, pl.stats.nfcn))
                                       : std::nan("");
      CostBound bound;
      if (is_answer(tr.outcome) && !std::isnan(ratio)) {
        ratios.push_back(ratio);
        // --accuracy's own pairs lie on that grid: where they stay in double, the bound is no dearer.
        const bool in_double = tr.rtol >= rtol_in_eps<double>(kDenseRtolEps) && tr.accuracy.runs >= 2;
        const auto last_pair = in_double ? static_cast<std::size_t>(std::lround(2 * std::log10(e / tr.rtol))) - pair_step() : 0;
        bound = cheapest_answers(scenes[i], e, pl, last_pair);  // none on the grid: as costly as it gets
        if (in_double && bound.pair > ratio * (1 + 1e-12)) {
          log << "bench-accuracy: E = " << e << ", scene " << i << ": the cheapest checked pair (" << bound.pair
              << ") costs more than --accuracy's answer (" << ratio << ")\n";
          ok = false;
        }
        bound_pair.push_back(std::isnan(bound.pair) ? std::numeric_limits<double>::infinity() : bound.pair);
        bound_single.push_back(std::isnan(bound.single) ? std::numeric_limits<double>::infinity() : bound.single);
      }
      cost.cells({csv_number(e), std::to_string(i), to_string(tr.outcome), csv_number(tr.rtol), csv_number(tr.error.norm),
                  csv_number(truth), std::to_string(tr.nfcn_total()), std::to_string(pl.stats.nfcn), csv_number(ratio),
                  std::to_string(tr.accuracy.runs), csv_number(bound.pair), csv_number(bound.single)});
    }
    md << "| " << e << " | " << answered << " | " << not_reached << " | " << judged << " | " << met << " | "
       << quantile(ratios, 0.5) << " | " << quantile(ratios, 0.9) << " | " << by_runs[0] << " | " << by_runs[1] << " | "
       << by_runs[2] << " | " << by_runs[3] << " | " << bound_cell(quantile(bound_pair, 0.9)) << " | "
       << bound_cell(quantile(bound_single, 0.9)) << " |\n";
    log << "bench-accuracy: E = " << e << ": " << met << "/" << judged << " met\n";
  }
  cost.commit();
  if (plot::available()) {
    plot::Figure f;
    f.title = "error estimate against the true error; cost of --accuracy";
    f.cols = 2;
    f.width = 1300;
    f.height = 600;
    plot::Panel a;
    a.title = "honesty (above the dashed line: true > 10x estimate)";
    a.xlabel = "estimate";
    a.ylabel = "true error";
    a.logx = a.logy = true;
    const fs::path h = dir / "accuracy_honesty.csv";
    a.series.push_back({h, "5", "(strcol(1) eq 'coulomb' ? $6 : 1/0)", "coulomb", "points pt 7 ps 0.6"});
    a.series.push_back({h, "5", "(strcol(1) eq 'thesis' ? $6 : 1/0)", "thesis", "points pt 6 ps 0.6"});
    a.series.push_back({h, "5", "($5*10)", "true = 10 x estimate", "lines dt 2 lc rgb 'black'"});
    plot::Panel b;
    b.title = "--accuracy E: RHS evaluations over a plain run at rtol = E";
    b.xlabel = "accuracy asked E";
    b.ylabel = "cost ratio";
    b.logx = true;
    b.series.push_back({dir / "accuracy_cost.csv", "1", "9", "scenes", "points pt 7 ps 0.6"});
    f.panels = {a, b};
    const fs::path fig = plot::render(f, dir / "accuracy.png");
    md << "![accuracy](" << (ctx ? "accuracy/" : "") << fig.filename().string() << ")\n";
    if (ctx) ctx->produced(fig);
  }
  if (ctx) {
    ctx->produced(dir / "accuracy_honesty.csv");
    ctx->produced(dir / "accuracy_cost.csv");
  }
  return ok;
}

int run_bench_accuracy(const BenchAccuracyOptions& o) {
  const fs::path dir = o.out;
  fs::create_directories(dir);
  std::ostringstream md;
  md << "# Accuracy benchmark\n\n";
  const bool ok = bench_accuracy(o, dir, md, std::cerr, nullptr);
  write_file_atomic(dir / "accuracy.md", md.str());
  std::cerr << "bench-accuracy: " << (dir / "accuracy.md").string() << ", accuracy_honesty.csv, accuracy_cost.csv\n";
  return bench_status(ok, "bench: the true error exceeds 10x the estimate at more than 1 % of the scenes, or a cost "
                          "bound above the cost it bounds (accuracy.md)");
}

RegisterCommand reg{{"bench-accuracy",
                     "Benchmark of the error estimate (honesty) and of --accuracy (met, cost) on a Latin hypercube of "
                     "rough scenes (docs/accuracy.md)",
                     94, options_then<BenchAccuracyOptions>(run_bench_accuracy, [](CLI::App& app, BenchAccuracyOptions& o) {
                       add_bench_directory_option(app, o);
                       app.add_option("--scenes", o.scenes, "scenes of the Latin hypercube")
                           ->check(count(2, 100000))
                           ->capture_default_str();
                       app.add_option("--seed", o.seed, "its seed")
                           ->check(count(0, 1000000000000))
                           ->capture_default_str();
                     })}};

RegisterReproduce step{{"accuracy",
                        "error estimate against the true error, and the cost of --accuracy, on a Latin hypercube of "
                        "rough scenes",
                        80, [](ReproduceContext& c) {
                          BenchAccuracyOptions o;
                          o.scenes = c.quick ? 10 : 40;
                          o.tightest = 1e-6;
                          const fs::path dir = c.out / "accuracy";
                          fs::create_directories(dir);
                          c.report << "\n## Accuracy: the error estimate and --accuracy (docs/accuracy.md)\n\n";
                          std::ostringstream log;
                          if (!bench_accuracy(o, dir, c.report, log, &c))
                            c.failures.push_back("accuracy: the true error exceeds 10x the estimate at more than 1 % "
                                                 "of the judged scenes");
                        },
                        6.0}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
