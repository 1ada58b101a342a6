// nanopush bench: work-precision benchmark of every engine on one scene (issue 7), and the
// reproduce step `bench_smooth` (work-precision plots of the smooth nanobar).
// docs/performance.md documents the CSV, the measurements and the results.
#include <algorithm>
#include <functional>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <thread>

#include "bench/bench_scene.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "cli_checks.hpp"
#include "registry.hpp"
#include "scene_args.hpp"
#include "sweep_output.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

using bench::Row;

struct BenchOptions {
  std::string scene = "fig3_6a";
  std::vector<std::string> sets;  ///< --set KEY=VALUE
  std::string out;  // CSV; default bench_<scene>.csv
  std::string plot;  // PNG; default beside the CSV
  std::vector<std::string> engines;
  std::vector<Precision> precisions;
  std::vector<std::string> precision_names;  ///< --precision, read into precisions by bench_cmd
  bench::SweepSettings sweep;  ///< --kmin .. --repeats-extended, --replay (its progress set by run_bench)
  int samples = 0;
  std::int64_t rhs_budget = 0;  // stick-slip: RHS evaluations per solve for engines without event location
  bool quick = false, no_plot = false, quiet = false;
  /// Options the user gave (the others take the scene's budgets: stick_slip_budgets).
  bool given_kmax = false, given_kstep = false, given_repeats = false, given_rhs_budget = false;
};

/// A scene whose friction law is coulomb (stick-slip)? Its engines without event location
/// chatter through every rest (minutes per solve without a limit).
bool stick_slip(const Scene& scene) { return scene.rough() && scene.surface.law == Law::coulomb; }

/// The budgets `reproduce` gives a stick-slip scene, and the defaults of `nanopush bench` on
/// one (options the user gave are kept): each solve of an engine without event location may
/// spend 2e5 RHS evaluations (100 x what event location needs); the sweep stops at rtol 1e-9,
/// where the two double-precision reference runs (agreeing to ~1e-12) still resolve the
/// smallest error by the acceptance rule; every third tolerance, one timed solve per point
/// (the criterion is on RHS counts).
void stick_slip_budgets(BenchOptions& o) {
  if (!o.given_kmax) o.sweep.kmax = 18;
  if (!o.given_kstep) o.sweep.kstep = 3;
  if (!o.given_repeats) o.sweep.repeats = 1;
  if (!o.given_rhs_budget) o.rhs_budget = 200000;
}

// ------------------------------------------------------------------ the issue's ratios
/// Cheapest run of (engine, precision) whose error is <= target: {nfcn, wall_s}; NaN if none.
std::pair<double, double> cheapest_at(const std::vector<Row>& rows, const std::string& eng, double target,
                                      Precision prec = Precision::double_) {
  double nf = std::numeric_limits<double>::quiet_NaN(), wall = nf;
  for (const auto& r : rows) {
    if (r.engine != eng || r.precision != prec || r.status != 0 || !(r.error <= target)) continue;
    if (!(static_cast<double>(r.nfcn) >= nf)) nf = static_cast<double>(r.nfcn);
    if (!(r.wall_s >= wall)) wall = r.wall_s;
  }
  return {nf, wall};
}

bool has_engine(const std::vector<Row>& rows, const std::string& eng, Precision prec = Precision::double_) {
  return std::any_of(rows.begin(), rows.end(), [&](const Row& r) { return r.engine == eng && r.precision == prec; });
}

std::string num3(double v) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s << std::setprecision(3) << v;
  return s.str();
}

/// A ratio judged against a bound: three decimals, so that the printed value never rounds
/// across the bound it is compared with (1.2549 is "1.255 (NOT met)", not "1.25 (NOT met)").
std::string ratio3(double v) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s << std::fixed << std::setprecision(3) << v;
  return s.str();
}

/// Bare-RHS time spread (max / min over a sweep) beyond which the report says that the
/// host's load changed during the run.
constexpr double kHostSpread = 1.2;
constexpr std::int64_t kHostMinCalls = 2000;

struct Ratios {
  std::string markdown;
  std::vector<std::string> failures;  ///< correctness checks only (never timings)
};

/// The "Done when" ratios of issue 7 that the rows can measure.
Ratios measure_ratios(const std::vector<Row>& rows) {
  Ratios out;
  std::ostringstream md;
  // 0. The host's speed during the sweep: the bare RHS time of the C++ BS rows (the same RHS
  //    at every tolerance). On a shared machine it moves with the neighbours' load, and a
  //    change in the middle of a sweep skews the timing ratios of the tolerances it spans.
  //    Only rows of at least kHostMinCalls calls: a row's timing cycles through the sample
  //    states nfcn times, and a rough RHS costs more at some states than at others, so a
  //    short row measures a different mix.
  {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const auto& r : rows)
      if ((r.engine == "cxx-faithful" || r.engine == "cxx-modern") && r.precision == Precision::double_ && r.status == 0 &&
          r.nfcn >= kHostMinCalls && r.rhs_s > 0) {
        const double ns = r.rhs_s / static_cast<double>(r.nfcn) * 1e9;
        lo = std::min(lo, ns);
        hi = std::max(hi, ns);
      }
    if (hi > 0)
      md << "\n**Host speed during the sweep**: one bare RHS call took " << num3(lo) << " to " << num3(hi)
         << " ns over the C++ BS rows (double, rows of >= " << kHostMinCalls << " calls), "
         << (hi <= kHostSpread * lo
                 ? "stable within " + std::to_string(static_cast<int>(std::lround((kHostSpread - 1) * 100))) + " %.\n"
                 : "a spread of " + ratio3(hi / lo) +
                       " x: the machine's load changed during the run (or, with few repeats, single timings were "
                       "disturbed), and the timing ratios below at the tolerances concerned may be skewed (counts "
                       "and errors are not).\n");
  }
  // 1. C++ BS against Boost.Odeint bulirsch_stoer, at equal achieved error.
  for (const std::string peer : {"odeint-bs", "odeint-bs-dense"}) {
    if (!has_engine(rows, peer)) continue;
    for (const std::string cxx : {"cxx-faithful", "cxx-modern"}) {
      if (!has_engine(rows, cxx)) continue;
      // The issue's targets are for the C++ BS at its best (modern) against Odeint's
      // bulirsch_stoer. Faithful is bound to the F77 engine's clipped steps by design, and
      // Odeint's dense-output stepper is a further peer: both are shown without a verdict.
      const bool judged = cxx == "cxx-modern" && peer == "odeint-bs";
      md << "\n**" << cxx << " vs " << peer << "** (cheapest run of each with error <= target; "
         << (judged                   ? "target wall <= 0.8, RHS <= 1.0):\n\n"
             : cxx == "cxx-faithful" ? "no target: faithful takes the F77 engine's steps, clipped at every output; "
                                       "the targets are cxx-modern's):\n\n"
                                     : "no target: the targets are against odeint-bs, Odeint's bulirsch_stoer):\n\n")
         << "| error <= | RHS " << cxx << " | RHS " << peer << " | RHS ratio | wall " << cxx << " [ms] | wall " << peer
         << " [ms] | wall ratio |\n|---|---|---|---|---|---|---|\n";
      double worst_rhs = 0, worst_wall = 0;
      int compared = 0, missed = 0;  // levels both reach; levels only the peer reaches
      for (int e = 6; e <= 12; ++e) {
        const double target = std::pow(10.0, -e);
        const auto [nc, wc] = cheapest_at(rows, cxx, target);
        const auto [no, wo] = cheapest_at(rows, peer, target);
        const double rr = nc / no, rw = wc / wo;
        if (std::isfinite(rr)) worst_rhs = std::max(worst_rhs, rr);
        if (std::isfinite(rw)) worst_wall = std::max(worst_wall, rw);
        if (std::isfinite(nc) && std::isfinite(no)) ++compared;
        if (!std::isfinite(nc) && std::isfinite(no)) ++missed;
        md << "| 1e-" << e << " | " << num3(nc) << " | " << num3(no) << " | " << num3(rr) << " | " << num3(wc * 1e3)
           << " | " << num3(wo * 1e3) << " | " << num3(rw) << " |\n";
      }
      if (compared == 0 && missed == 0) {
        md << "\nNo error level in 1e-6..1e-12 is reached by both engines: not measured here.\n";
      } else {
        const bool rhs_met = worst_rhs <= 1.0 && missed == 0, wall_met = worst_wall <= 0.8 && missed == 0;
        const auto verdict = [judged](bool met) { return judged ? (met ? " (met)" : " (NOT met)") : ""; };
        md << "\nWorst over 1e-6..1e-12: RHS ratio " << ratio3(worst_rhs) << verdict(rhs_met) << ", wall ratio "
           << ratio3(worst_wall) << verdict(wall_met) << ".";
        if (missed > 0) md << " " << cxx << " does not reach " << missed << " level(s) that " << peer << " reaches.";
        md << "\n";
      }
    }
  }
  // 1b. The interpolant's acceptance (docs/bulirsch_stoer.md): ours against ODEX's, when both ran.
  if (has_engine(rows, "cxx-modern") && has_engine(rows, "cxx-modern-odex")) {
    md << "\n**cxx-modern (dense_accept 1) vs cxx-modern-odex (ODEX's 10)** (cheapest run of each with error <= "
          "target; no target, the measurement behind docs/bulirsch_stoer.md):\n\n"
       << "| error <= | RHS cxx-modern | RHS cxx-modern-odex | RHS ratio | wall cxx-modern [ms] | wall "
          "cxx-modern-odex [ms] | wall ratio |\n|---|---|---|---|---|---|---|\n";
    for (int e = 4; e <= 13; ++e) {
      const double target = std::pow(10.0, -e);
      const auto [nc, wc] = cheapest_at(rows, "cxx-modern", target);
      const auto [no, wo] = cheapest_at(rows, "cxx-modern-odex", target);
      md << "| 1e-" << e << " | " << num3(nc) << " | " << num3(no) << " | " << num3(nc / no) << " | " << num3(wc * 1e3)
         << " | " << num3(wo * 1e3) << " | " << num3(wc / wo) << " |\n";
    }
  }
  // 2. F77 against the C++ faithful engine: identical counts, wall-time ratio in [0.8, 1.25].
  for (const std::string f77 : {"f77-callback", "f77-native"}) {
    if (!has_engine(rows, f77) || !has_engine(rows, "cxx-faithful")) continue;
    md << "\n**" << f77 << " vs cxx-faithful** (same rtol; target: identical counts, wall ratio in [0.8, 1.25]):\n\n"
       << "| rtol | RHS f77 / C++ | accepted | rejected | wall ratio f77/C++ |\n|---|---|---|---|---|\n";
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    int mismatches = 0;
    for (const auto& a : rows) {
      if (a.engine != f77 || a.precision != Precision::double_) continue;
      for (const auto& c : rows) {
        if (c.engine != "cxx-faithful" || c.precision != Precision::double_ || c.rtol != a.rtol) continue;
        const bool same = a.nfcn == c.nfcn && a.naccpt == c.naccpt && a.nrejct == c.nrejct;
        if (!same) {
          ++mismatches;
          out.failures.push_back(f77 + " vs cxx-faithful at rtol " + fmt(a.rtol) + ": counts differ (" +
                                 std::to_string(a.nfcn) + " vs " + std::to_string(c.nfcn) + " RHS)");
        }
        const double r = a.wall_s / c.wall_s;
        lo = std::min(lo, r);
        hi = std::max(hi, r);
        md << "| " << num3(a.rtol) << " | " << a.nfcn << " / " << c.nfcn << (same ? "" : " **differ**") << " | "
           << a.naccpt << " / " << c.naccpt << " | " << a.nrejct << " / " << c.nrejct << " | " << ratio3(r) << " |\n";
      }
    }
    md << "\nCounts " << (mismatches ? "DIFFER" : "identical at every rtol") << "; wall ratio from " << ratio3(lo)
       << " to " << ratio3(hi) << (lo >= 0.8 && hi <= 1.25 ? " (met)" : " (NOT met)") << ".\n";
  }
  // 3. Integrator overhead per RHS evaluation.
  const bool alone = std::any_of(rows.begin(), rows.end(), [](const Row& r) { return std::isfinite(r.own_ns_per_rhs); });
  md << "\n**Integrator overhead** (wall time minus the time of as many bare RHS calls, per RHS call; target <= 10 ns "
        "for the C++ BS; the column \"<= 10 ns at\": the tolerances at which it holds, i.e. the loosest rtol from "
        "which every tighter row of the sweep is within it"
     << (alone ? "; \"alone\": the integrator alone, timed with the RHS values of the same solve replayed instead of "
                 "evaluated (the same steps bit for bit) minus the time of copying them, and where that is within "
                 "10 ns (docs/performance.md, \"The integrator alone\")"
               : "")
     << "):\n\n| engine | precision | ns per RHS (min / median / max over the sweep) | RHS cost [ns] (median) | "
        "wall-time spread of the repeats (median over the sweep) | <= 10 ns at |"
     << (alone ? " alone: ns per RHS (min / median / max) | alone <= 10 ns at |\n|---|---|---|---|---|---|---|---|\n"
               : "\n|---|---|---|---|---|---|\n");
  // "rtol <= R", "every rtol of the sweep" or "no rtol of the sweep" for one column.
  const auto within = [&rows](const std::string& eng, Precision prec, double Row::*field) {
    const auto from = bench::overhead_within_from(rows, eng, prec, 10.0, field);
    double loosest = 0;
    for (const auto& r : rows)
      if (r.engine == eng && r.precision == prec && r.status == 0 && r.nfcn > 0) loosest = std::max(loosest, r.rtol);
    return !from ? std::string("no rtol of the sweep") : *from >= loosest ? std::string("every rtol of the sweep")
                                                                          : "rtol <= " + num3(*from);
  };
  std::vector<std::pair<std::string, Precision>> seen;
  for (const auto& r : rows)
    if (std::find(seen.begin(), seen.end(), std::make_pair(r.engine, r.precision)) == seen.end())
      seen.emplace_back(r.engine, r.precision);
  for (const auto& [eng, prec] : seen) {
    std::vector<double> ov, rc, sp, own;
    for (const auto& r : rows)
      if (r.engine == eng && r.precision == prec && r.status == 0 && r.nfcn > 0) {
        ov.push_back(r.overhead_ns_per_rhs);
        if (std::isfinite(r.own_ns_per_rhs)) own.push_back(r.own_ns_per_rhs);
        rc.push_back(r.rhs_s / static_cast<double>(r.nfcn) * 1e9);
        if (std::isfinite(r.wall_spread)) sp.push_back(r.wall_spread);
      }
    if (ov.empty()) continue;
    std::sort(ov.begin(), ov.end());
    std::sort(rc.begin(), rc.end());
    std::sort(sp.begin(), sp.end());
    std::sort(own.begin(), own.end());
    md << "| " << eng << " | " << to_string(prec) << " | " << num3(ov.front()) << " / " << num3(ov[ov.size() / 2]) << " / "
       << num3(ov.back()) << " | " << num3(rc[rc.size() / 2]) << " | "
       << (sp.empty() ? std::string("n/a (< 4 repeats)") : num3(100 * sp[sp.size() / 2]) + " %") << " | "
       << within(eng, prec, &Row::overhead_ns_per_rhs) << " |";
    if (alone) {
      if (own.empty())
        md << " n/a (no replay) | n/a |";
      else
        md << " " << num3(own.front()) << " / " << num3(own[own.size() / 2]) << " / " << num3(own.back()) << " | "
           << (own.size() == ov.size() ? within(eng, prec, &Row::own_ns_per_rhs) : std::string("n/a (rows without replay)"))
           << " |";
    }
    md << "\n";
  }
  // 4. Extended precision.
  md << "\n**Precision** (smallest error reached; target 1e-25 in extended precision):\n\n"
        "| engine | precision | smallest error | at rtol | RHS | wall [ms] |\n|---|---|---|---|---|---|\n";
  for (const auto& [eng, prec] : seen) {
    if (eng.rfind("cxx-", 0) != 0) continue;
    const Row* best = nullptr;
    for (const auto& r : rows)
      if (r.engine == eng && r.precision == prec && r.status == 0 && (!best || r.error < best->error)) best = &r;
    if (best)
      md << "| " << eng << " | " << to_string(prec) << " | " << num3(best->error) << " | " << num3(best->rtol) << " | "
         << best->nfcn << " | " << num3(best->wall_s * 1e3) << " |\n";
  }
  // 4. Event location (stick-slip scene): RHS of the event-locating engine against the best
  //    engine without it, at errors <= 1e-8 (target <= 0.5).
  const bool stick = has_engine(rows, "cxx-events");
  if (stick) {
    auto is_event = [](const std::string& e) { return e == "cxx-events" || e == "cvode-events"; };
    md << "\n**Event location** (stick-slip; cheapest run with error <= target; target: cxx-events <= 0.5 x the "
          "best engine without event location at 1e-8):\n\n| error <= | RHS cxx-events | RHS best without events "
          "(engine) | ratio |\n|---|---|---|---|\n";
    for (int e = 4; e <= 10; e += 2) {
      const double target = std::pow(10.0, -e);
      const auto [ne, we] = cheapest_at(rows, "cxx-events", target);
      (void)we;
      double best = std::numeric_limits<double>::infinity();
      std::string who = "none reaches it";
      for (const auto& r : rows)
        if (!is_event(r.engine) && r.status == 0 && r.error <= target && static_cast<double>(r.nfcn) < best) {
          best = static_cast<double>(r.nfcn);
          who = r.engine;
        }
      // The target applies at errors <= 1e-8; a level only one side reaches has no ratio.
      const bool judged = e >= 8;
      std::string ratio;
      if (std::isfinite(ne) && std::isfinite(best))
        ratio = ratio3(ne / best) + (judged ? (ne / best <= 0.5 ? " (met)" : " (NOT met)") : "");
      else if (std::isfinite(ne))
        ratio = std::string("n/a: only cxx-events reaches it") + (judged ? " (met)" : "");
      else if (std::isfinite(best))
        ratio = std::string("n/a: cxx-events does not reach it") + (judged ? " (NOT met)" : "");
      else
        ratio = "n/a: neither reaches it (not measured)";
      md << "| 1e-" << e << " | " << num3(ne) << " | " << (std::isfinite(best) ? num3(best) : std::string("-")) << " ("
         << who << ") | " << ratio << " |\n";
    }
    md << "\nEngines without event location integrate the thesis-law ODE: at rest the friction flips every step; "
          "their failures (step budget) are results here, not errors.\n";
  }
  for (const auto& r : rows)
    if (r.status != 0 && r.status != bench::kStatusBelowReference) {
      if (stick && r.engine != "cxx-events" && r.engine != "cvode-events") continue;
      out.failures.push_back(r.engine + " (" + to_string(r.precision) + ") failed at rtol " + fmt(r.rtol) + " with status " +
                             std::to_string(r.status));
    }
  out.markdown = md.str();
  return out;
}

// ------------------------------------------------------------------ running
struct BenchOutcome {
  std::vector<Row> rows;
  bench::Reference reference;
  bench::Acceptance acceptance;       ///< of the reference used
  int below_reference = 0;            ///< rows the reference cannot resolve (not plotted)
  bench::Acceptance extended_check;   ///< exact references: a quad C++ BS run vs the exact solution
  double extended_check_rtol = 0;
  Ratios ratios;
  std::vector<std::string> engine_notes;
  double seconds = 0;
  bool has_precision_plot = false;
};

BenchOutcome run_bench(const Scene& scene, const BenchOptions& o, std::ostream* log) {
  const auto t_start = std::chrono::steady_clock::now();
  bench::EngineConfig cfg;
  cfg.only = o.engines;
  cfg.rhs_budget = o.rhs_budget;
  if (!o.precisions.empty()) cfg.precisions = o.precisions;
  const auto names = bench::engine_names(scene);
  for (const auto& e : cfg.only)
    if (std::find(names.begin(), names.end(), e) == names.end()) {
      std::string all;
      for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
      throw InputError("--engines", e, "must be one of: " + all);
    }
  bench::Bench b = bench::make_bench(scene, cfg);
  if (b.engines.empty()) throw InputError("--engines", "(selection)", "selects no engine");
  bench::SweepSettings s = o.sweep;
  if (log)
    s.progress = [log](const Row& r) {
      *log << "  " << std::left << std::setw(16) << r.engine << std::setw(7) << to_string(r.precision) << " rtol "
           << std::setw(9) << std::setprecision(3) << r.rtol << " error " << std::setw(10) << r.error << " RHS "
           << std::setw(8) << r.nfcn << " wall " << std::setw(9) << r.wall_s * 1e3 << " ms  overhead " << std::setw(7)
           << r.overhead_ns_per_rhs << " ns/RHS"
           << (std::isfinite(r.own_ns_per_rhs) ? "  alone " + num3(r.own_ns_per_rhs) + " ns/RHS" : std::string())
           << (r.status ? "  FAILED" : "") << "\n"
           << std::flush;
    };
  BenchOutcome out;
  out.reference = b.reference;
  out.rows = bench::run_sweep(b.problem, b.engines, b.reference, s);
  out.below_reference = bench::mark_below_reference(b.reference, out.rows);
  out.acceptance = bench::accept_reference(b.reference, out.rows);
  if (b.reference.kind == "exact") {
    // The acceptance rule of extended references, exercised on the smooth scene: an
    // independent quad run against the exact solution.
    out.extended_check_rtol = 1e-28;
    const bench::Solve q = bench::extended_run(scene, b.problem, out.extended_check_rtol, true);
    out.extended_check = bench::accept_reference(b.problem, b.reference.y, q.y, bench::smallest_plotted_error(out.rows));
  }
  out.ratios = measure_ratios(out.rows);
  if (!out.acceptance.accepted) out.ratios.failures.push_back("reference rejected: " + out.acceptance.explanation);
  if (b.reference.kind == "exact" && !out.extended_check.accepted)
    out.ratios.failures.push_back("quad C++ BS vs exact: " + out.extended_check.explanation);
  for (const auto& e : b.engines)
    if (e.precision == Precision::double_ || e.name == "cxx-faithful") out.engine_notes.push_back(e.label() + ": " + e.note);
  out.has_precision_plot = std::any_of(out.rows.begin(), out.rows.end(), [](const Row& x) { return x.precision != Precision::double_; });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return out;
}

std::string machine() {
  std::string model = "unknown CPU";
  if (FILE* f = popen("lscpu 2>/dev/null | sed -n 's/^Model name: *//p'", "r")) {
    char buf[256];
    if (fgets(buf, sizeof buf, f)) {
      model = buf;
      while (!model.empty() && (model.back() == '\n' || model.back() == ' ')) model.pop_back();
    }
    pclose(f);
  }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " logical CPUs";
}

/// The two figures: every engine in double precision; the C++ BS in every precision run.
/// Returns the PNGs written.
std::vector<std::filesystem::path> plot_all(const std::vector<Row>& rows, const std::filesystem::path& csv,
                                            const std::filesystem::path& png, const std::string& scene) {
  std::vector<Row> dbl, prec;
  for (const auto& r : rows) {
    if (r.precision == Precision::double_) dbl.push_back(r);
    if (r.engine.rfind("cxx-", 0) == 0) prec.push_back(r);
  }
  std::vector<std::filesystem::path> out;
  bench::plot_work_precision(dbl, csv, png, "Work-precision in double precision, scene " + scene);
  out.push_back(png);
  if (prec.size() != dbl.size() || std::any_of(prec.begin(), prec.end(), [](const Row& r) { return r.precision != Precision::double_; })) {
    std::filesystem::path p2 = png;
    p2.replace_extension();
    p2 += "_precision.png";
    bench::plot_work_precision(prec, csv, p2, "C++ Bulirsch-Stoer in double, long double and __float128, scene " + scene);
    out.push_back(p2);
  }
  if (!dbl.empty()) {
    std::filesystem::path p3 = png;
    p3.replace_extension();
    p3 += "_overhead.png";
    bench::plot_overhead(dbl, csv, p3, "Integrator overhead per RHS evaluation (double), scene " + scene);
    out.push_back(p3);
  }
  return out;
}

std::string report_section(const Scene& scene, const BenchOptions& o, const BenchOutcome& r,
                           const std::string& png_rel, const std::string& csv_rel) {
  std::ostringstream md;
  md << "Scene `" << scene.name << "` (" << scene.description << "): " << scene.solver.samples
     << " output times over [0, " << scene.solver.t_end << "] s; rtol = 10^(-k/2), k = " << o.sweep.kmin << ".."
     << o.sweep.kmax
     << " step " << o.sweep.kstep << " (long/quad: to k = " << o.sweep.kmax_extended << " step "
     << (o.sweep.kstep_extended > 0 ? o.sweep.kstep_extended : o.sweep.kstep) << "), atol_i = rtol * scale_i; "
     << o.sweep.repeats << " timed solve(s) per point (median)"
     << (o.sweep.repeats_extended > 0 && o.sweep.repeats_extended != o.sweep.repeats
             ? ", " + std::to_string(o.sweep.repeats_extended) + " in long/quad precision"
             : std::string())
     << (o.sweep.repeats > 1 ? ", after an untimed warm-up solve per engine and per point"
                       : ", after one untimed warm-up solve per engine")
     << ". Machine: " << machine() << ". Whole sweep: "
     << num3(r.seconds) << " s.\n\n"
     << "Error: max over output times and components of |y_i - y_ref,i| / (scale_i + |y_ref,i|). Reference: " << r.reference.kind
     << " (" << r.reference.how << "); " << r.acceptance.explanation << ".\n";
  if (r.below_reference > 0)
    md << r.below_reference << " row(s) reached errors below 1e3 x the references' disagreement ("
       << num3(1e3 * r.reference.disagreement) << "): the reference cannot resolve them, so they are in the CSV with status "
       << bench::kStatusBelowReference << " and are neither plotted nor used in the ratios.\n";
  if (r.extended_check_rtol > 0)
    md << "Extended-precision check of the acceptance rule: C++ BS modern in __float128 at rtol "
       << num3(r.extended_check_rtol) << " against the exact solution: " << r.extended_check.explanation << ".\n";
  if (png_rel.empty()) {
    md << "\nPlots: not written (--no-plot).\n";
  } else {
    md << "\n![work-precision](" << png_rel << ")\n";
  }
  if (!png_rel.empty() && r.has_precision_plot) {
    std::string p2 = png_rel.substr(0, png_rel.size() - 4) + "_precision.png";
    md << "\n![precision](" << p2 << ")\n";
  }
  if (!png_rel.empty() && std::any_of(r.rows.begin(), r.rows.end(), [](const Row& x) { return x.precision == Precision::double_; }))
    md << "\n![integrator overhead per RHS evaluation against rtol](" << png_rel.substr(0, png_rel.size() - 4)
       << "_overhead.png)\n";
  md << "\nData: `" << csv_rel << "`. Engines:\n\n";
  for (const auto& n : r.engine_notes) md << "- " << n << "\n";
  md << r.ratios.markdown << "\n";
  return md.str();
}

int bench_cmd(BenchOptions o) {
  for (const auto& p : o.precision_names) o.precisions.push_back(parse_choice<Precision>("--precision", p));
  Scene scene = load_scene_arg(o.scene, o.sets);
  set_provenance_scene(o.scene);
  if (o.samples != 0) {
    require_range("--samples", o.samples, 2, 1e7);
    scene.solver.samples = o.samples;
  }
  if (stick_slip(scene)) stick_slip_budgets(o);
  if (o.quick) {
    o.sweep.kstep = 6;
    o.sweep.repeats = 1;
  }
  require_range("--repeats", o.sweep.repeats, 1, 1000);
  require_range("--repeats-extended", o.sweep.repeats_extended, 0, 1000);
  require_range("--kstep", o.sweep.kstep, 1, 100);
  require_range("--kstep-extended", o.sweep.kstep_extended, 0, 100);
  require_range("--kmin", o.sweep.kmin, 0, 60);
  require_range("--kmax", o.sweep.kmax, o.sweep.kmin, 60);
  require_range("--kmax-extended", o.sweep.kmax_extended, o.sweep.kmin, 60);
  namespace fs = std::filesystem;
  // The table: FILE.csv, or FILE.nc (netCDF-4, docs/data.md), refused before the run otherwise.
  const TableOutput table(o.out.empty() ? fs::path("bench_" + scene.name + ".csv") : fs::path(o.out), "--out", false);
  if (table.netcdf()) {
    // The figure and its script read the CSV, which a .nc output does not keep.
    if (!o.plot.empty())
      throw InputError("--plot", o.plot, "the figure is drawn from the CSV: with --out FILE.nc there is none "
                                         "(write FILE.csv, or convert it afterwards: nanopush convert)");
    o.no_plot = true;
  }
  const fs::path csv = table.table();
  fs::path png = o.plot.empty() ? fs::path(csv).replace_extension(".png") : fs::path(o.plot);
  if (csv.has_parent_path()) fs::create_directories(csv.parent_path());
  const BenchOutcome r = run_bench(scene, o, o.quiet ? nullptr : &std::cerr);
  bench::write_csv(r.rows, csv);
  const std::string written = table.finish();
  std::string png_rel = png.filename().string();
  if (!o.no_plot) plot_all(r.rows, csv, png, scene.name);
  std::cout << "# nanopush bench " << scene.name << "\n\n"
            << report_section(scene, o, r, o.no_plot ? std::string() : png_rel, written);
  std::cerr << "bench: " << r.rows.size() << " rows in " << written << (o.no_plot ? "" : ", plot " + png.string())
            << " (" << num3(r.seconds) << " s)\n";
  if (!r.ratios.failures.empty()) {
    for (const auto& f : r.ratios.failures) std::cerr << "bench: check failed: " << f << "\n";
    return 4;
  }
  return 0;
}

/// One work-precision reproduce step: `preset` (a scene under drivers/scenes) into
/// <out>/bench/<file>.{csv,png}, a report section titled `heading`. The rough scenes of
/// issue 4 register their steps with this too (see the end of this file).
void reproduce_bench_scene(ReproduceContext& ctx, const std::string& step, const std::string& preset,
                           const std::string& file, const std::string& heading, const std::string& label,
                           const std::function<void(BenchOptions&)>& adjust = {}) {
  namespace fs = std::filesystem;
  const fs::path dir = ctx.out / "bench";
  fs::create_directories(dir);
  BenchOptions o;
  o.scene = preset;
  o.precisions = {Precision::double_, Precision::long_, Precision::quad};
  if (ctx.quick) {
    o.sweep.kstep = 6;
    o.sweep.repeats = 1;
    o.precisions = {Precision::double_, Precision::quad};
  } else {
    // Medians of 5: up to two load spikes on a shared machine do not move them. A long/quad
    // solve takes 10-400 ms, long against any spike: one timing, every other tolerance (a
    // median of 3 cost 13 s of reproduce's 33, issue 24's 20 s budget).
    o.sweep.repeats = 5;
    o.sweep.repeats_extended = 1;
    o.sweep.kstep_extended = 2;
  }
  if (adjust) adjust(o);
  const Scene scene = load_scene(resolve_scene(preset));
  const BenchOutcome r = run_bench(scene, o, nullptr);
  const fs::path csv = dir / (file + ".csv"), png = dir / (file + ".png");
  bench::write_csv(r.rows, csv, preset);
  ctx.produced(csv);
  for (const auto& f : plot_all(r.rows, csv, png, label)) {
    ctx.produced(f);
    fs::path gp = f;
    ctx.produced(gp.replace_extension(".gp"));
  }
  ctx.report << "## " << heading << "\n\n"
             << report_section(scene, o, r, "bench/" + file + ".png", "bench/" + file + ".csv")
             << "\nTimings are measurements on this machine, not checks; only correctness (identical F77/C++ counts, "
                "successful solves, reference acceptance) can fail this step.\n\n";
  for (const auto& f : r.ratios.failures) ctx.failures.push_back(step + ": " + f);
}

void reproduce_bench_smooth(ReproduceContext& ctx) {
  // The smooth scene is the issue's 6-state system: its overhead is also measured with the
  // RHS values replayed (the integrator alone).
  reproduce_bench_scene(ctx, "bench_smooth", "thesis/fig3_6a", "smooth_fig3_6a",
                        "Work-precision: the smooth nanobar against the exact solution (issue 7)",
                        "fig3_6a (smooth nanobar)", [](BenchOptions& o) { o.sweep.replay = true; });
}

RegisterCommand reg{
    {"bench", "Work-precision benchmark: every engine over a sweep of tolerances on one scene (CSV + plot)", 60,
     [](CLI::App& app) -> std::function<int()> {
       auto o = std::make_shared<BenchOptions>();
       app.add_option("SCENE", o->scene, "scene file or preset name (smooth, or rough under the thesis law)")->capture_default_str();
       add_set_option(app, o->sets);
       app.add_option("--out", o->out,
                      "the table: FILE.csv (default bench_<scene>.csv; columns in docs/performance.md) or FILE.nc "
                      "(netCDF-4, no figure; docs/data.md)");
       app.add_option("--plot", o->plot, "work-precision PNG (default: the CSV's name with .png)");
       app.add_flag("--no-plot", o->no_plot, "write the CSV only");
       app.add_option("--engines", o->engines,
                      "engines to run (default all but cxx-modern-odex, which runs only when named): cxx-faithful, cxx-modern, "
                      "cxx-modern-odex, cxx-dop853, f77-callback, f77-native, cvode-adams, "
                      "cvode-bdf, arkode-erk8, odeint-bs, odeint-bs-dense");
       app.add_option("--precision", o->precision_names,
                      "scalar of the C++ BS, repeatable: double (53-bit), long (x87 64-bit), quad (__float128, "
                      "113-bit); default double")
           ->check(is_choice<Precision>());
       app.add_option("--kmin", o->sweep.kmin, "first k of rtol = 10^(-k/2)")
           ->check(count(0, 64))
           ->capture_default_str();
       auto* kmax = app.add_option("--kmax", o->sweep.kmax,
                                   "last k in double precision (28: rtol 1e-14, stick-slip scenes 18: rtol 1e-9; each "
                                   "engine stops at its tightest meaningful rtol: C++ BS 1e-14, others 1e-13)")
                        ->check(count(0, 64))
                        ->capture_default_str();
       app.add_option("--kmax-extended", o->sweep.kmax_extended, "last k in long/quad precision (56: rtol 1e-28)")
           ->check(count(0, 64))
           ->capture_default_str();
       auto* kstep = app.add_option("--kstep", o->sweep.kstep, "step in k (stick-slip scenes: 3)")
                         ->check(count(1, 64))
                         ->capture_default_str();
       app.add_option("--kstep-extended", o->sweep.kstep_extended, "step in k for long/quad engines (0 = --kstep)")
           ->check(count(0, 64))
           ->capture_default_str();
       auto* repeats = app.add_option("--repeats", o->sweep.repeats,
                                      "timed solves per point; the median is reported (stick-slip scenes: 1)")
                           ->check(count(1, 1000))
                           ->capture_default_str();
       app.add_option("--repeats-extended", o->sweep.repeats_extended,
                      "timed solves per point for long/quad engines (0 = --repeats)")
           ->check(count(0, 1000))
           ->capture_default_str();
       app.add_option("--samples", o->samples, "override the scene's number of output times (0: the scene's)")
           ->check(count(0, 10000000));
       app.add_flag("--quick", o->quick, "k step 6 and one repeat (seconds)");
       app.add_flag("--quiet", o->quiet, "no per-row progress on standard error");
       app.add_flag("--replay", o->sweep.replay,
                    "also time every double engine with the RHS values of the same solve replayed instead of "
                    "evaluated: the integrator alone, without the RHS (CSV column own_ns_per_rhs; --repeats more "
                    "solves per point)");
       auto* budget = app.add_option("--rhs-budget", o->rhs_budget,
                                     "stick-slip scenes: RHS evaluations allowed per solve to the engines without "
                                     "event location (default there 200000; 0 = only their step budgets)")
                          ->check(count(0, 1000000000000))
                          ->capture_default_str();
       return [o, kmax, kstep, repeats, budget] {
         o->given_kmax = kmax->count() > 0;
         o->given_kstep = kstep->count() > 0;
         o->given_repeats = repeats->count() > 0;
         o->given_rhs_budget = budget->count() > 0;
         return bench_cmd(*o);
       };
     }}};

RegisterReproduce step{{"bench_smooth",
                        "work-precision of every engine on the smooth nanobar (fig3_6a) against the exact solution",
                        70, reproduce_bench_smooth, 9.0}};

RegisterReproduce step_rough{
    {"bench_rough",
     "work-precision of every engine on the rough nanobar without stick (fig3_17, mu = 0.05, thesis law) against the "
     "extended-precision F77 program",
     71, [](ReproduceContext& c) {
       reproduce_bench_scene(c, "bench_rough", "fig3_17", "rough_mu005", "Work-precision: rough surface, mu = 0.05",
                             "mu = 0.05");
     },
     7.0}};
// The stick-slip scene (mu = 0.15, coulomb law): the event-locating integrators against every
// engine without event location, with the budgets of stick_slip_budgets.
RegisterReproduce step_stick{
    {"bench_stick",
     "work-precision on the rough nanobar with stick-slip (mu = 0.15, coulomb law): event location against engines "
     "without it",
     72, [](ReproduceContext& c) {
       reproduce_bench_scene(c, "bench_stick", "stick_mu015", "stick_mu015",
                             "Work-precision: stick-slip, mu = 0.15, coulomb law (event location)", "mu = 0.15 stick-slip",
                             [&c](BenchOptions& o) {
                               o.precisions = {Precision::double_};
                               stick_slip_budgets(o);
                               if (c.quick) o.sweep.kstep = 6;
                             });
     },
     7.0}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
