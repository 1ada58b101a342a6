// nanopush compare: run a scene with the C++ and the FORTRAN 77 engine and judge the deviation.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

#include "nanopush/engines/compare.hpp"
#include "nanopush/numerics/error.hpp"
#include "cli_checks.hpp"
#include "registry.hpp"
#include "scene_args.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct CompareOptions {
  std::string scene, method, law;
  std::vector<std::string> sets;  ///< --set KEY=VALUE
  double rtol = 0, atol = -1;
  double tolerance = 0;
  double accuracy = 0;
};

/// The same-steps table: per column max |diff|, unit, max |diff|/scale and scale.
void print_same_steps(const EngineComparison& r) {
  std::cout << "  " << std::left << std::setw(8) << "column" << std::setw(16) << "max |diff|" << std::setw(10)
            << "unit" << std::setw(18) << "max |diff|/scale"
            << "scale = max |value|\n";
  for (const ColumnVerdict& v : r.columns)
    std::cout << "  " << std::left << std::setw(8) << v.name << std::setw(16) << std::setprecision(4)
              << v.max_abs_diff << std::setw(10) << v.unit << std::setw(18) << v.relative << v.scale
              << (v.ok ? "" : "   <-- exceeds") << "\n";
  std::cout << "  tolerance on max |diff|/scale: " << r.tolerance
            << (r.agree ? "  -> engines agree\n" : "  -> ENGINES DISAGREE\n");
}

/// The convergence table: each engine's own error and the engines apart at rtol and tight.
void print_convergence(const EngineComparison& r) {
  std::cout << "  each engine's error at rtol estimated against itself at rtol " << r.rtol_tight
            << "; all figures relative to the column's scale (largest norm of its vector: x,y | vx,vy | fx,fy)\n";
  std::cout << "  " << std::left << std::setw(8) << "column" << std::setw(14) << "error cxx" << std::setw(14)
            << "error f77" << std::setw(16) << "|cxx - f77|" << std::setw(18) << "|cxx - f77| tight"
            << "scale\n";
  for (const ColumnVerdict& v : r.columns)
    std::cout << "  " << std::left << std::setw(8) << v.name << std::setprecision(3) << std::setw(14) << v.error_cxx
              << std::setw(14) << v.error_f77 << std::setw(16) << v.diff << std::setw(18) << v.diff_tight << v.scale
              << (v.ok ? "" : "   <-- tight runs differ by more than the errors") << "\n";
  std::cout << (r.agree ? "  -> engines agree: they converge to the same solution, each within its own integration error\n"
                        : "  -> ENGINES DISAGREE: their tight runs differ by more than their errors at rtol\n");
}

int compare_cmd(const CompareOptions& o) {
  const Scene sc = load_scene_arg(o.scene, o.sets);
  CompareSettings cs;
  cs.method = o.method.empty() ? Method::faithful : parse_choice<Method>("method", o.method);
  cs.law = parse_optional_choice<Law>("law", o.law);
  cs.rtol = o.rtol;
  cs.atol = o.atol;
  cs.tolerance = o.tolerance;
  cs.accuracy = o.accuracy;
  if (o.accuracy > 0 && o.rtol > 0)
    throw InputError("--rtol", fmt(o.rtol), "--accuracy chooses the rtol: give one of --rtol and --accuracy");
  const EngineComparison r = compare_engines(sc, cs);
  if (r.law_from_coulomb)
    std::cout << "note: " << sc.name
              << " asks for the coulomb law; the engines are compared under the thesis law, which both implement\n";
  if (const Trajectory* t = r.failed()) {
    const bool reference = r.failed_run >= 2;
    std::cerr << "nanopush: " << (t->outcome == Outcome::solver_failure ? "solver failure" : to_string(t->outcome))
              << ": " << sc.name << " (" << t->engine_label
              << (reference ? ", the reference run at rtol " + fmt(r.rtol_tight) : std::string()) << "): "
              << t->outcome_message << "\n";
    if (t->outcome == Outcome::solver_failure) print_rest_diagnosis(sc, r.law, *t, std::cerr);
    std::cerr << "nanopush: cannot judge: " << r.cannot_judge
              << (reference ? " (no reference to judge the engines against)\n" : "\n");
    return 3;
  }
  std::cout << "compare " << sc.name << ": " << r.cxx.engine_label << " vs " << r.f77.engine_label << " (rtol "
            << r.rtol << ")\n";
  if (r.accuracy.requested > 0)
    std::cout << "  accuracy asked " << r.accuracy.requested << ": " << r.cxx.engine_label << " reaches it at rtol "
              << r.accuracy.rtol_used << " (" << r.accuracy.runs << " runs); both engines run there\n";
  std::cout << "  RHS evaluations " << r.cxx.stats.nfcn << " vs " << r.f77.stats.nfcn << ", accepted "
            << r.cxx.stats.naccpt << " vs " << r.f77.stats.naccpt << ", rejected " << r.cxx.stats.nrejct << " vs "
            << r.f77.stats.nrejct << "\n";
  if (!r.same_length) {
    std::cout << "  the engines returned " << r.cxx.rows.size() << " and " << r.f77.rows.size()
              << " samples  -> ENGINES DISAGREE\n";
    return 1;
  }
  if (r.kind == CompareKind::same_steps) {
    if (r.tolerance_from_tight)
      std::cout << "  note: rtol " << r.rtol << " is within 10x of the tightest reference (" << kCompareTightRtol
                << "), so the different step sequences are judged against 100 rtol\n";
    print_same_steps(r);
  } else {
    print_convergence(r);
  }
  if (!r.cannot_judge.empty()) {
    std::cerr << "nanopush: cannot judge: " << sc.name << ": " << r.cannot_judge << "\n";
    return 3;
  }
  return r.agree ? 0 : 1;
}

RegisterCommand reg_compare{{"compare",
                             "Run a scene with both engines (C++ and FORTRAN 77) and report the deviation per column",
                             20, options_then<CompareOptions>(compare_cmd, [](CLI::App& app, CompareOptions& o) {
                               app.add_option("SCENE", o.scene, "scene file, or a preset name such as fig3_6a (`nanopush presets`)")->required();
                               add_set_option(app, o.sets);
                               app.add_option("--rtol", o.rtol, "relative tolerance (default: the scene's solver.rtol)")
                                   ->check(positive());
                               app.add_option("--atol", o.atol,
                                              "absolute tolerance, one value for every state component (default: the "
                                              "scene's; 0 = rtol times each component's natural scale)")
                                   ->check(non_negative());
                               app.add_option("--method", o.method,
                                              "C++ configuration compared with F77: faithful (default; the same "
                                              "steps), modern or dop853 (judged by convergence: docs/rough.md)")
                                   ->check(is_choice<Method>({Method::faithful, Method::modern, Method::dop853}));
                               app.add_option("--law", o.law,
                                              "rough scenes: thesis or printed (both engines implement them); "
                                              "default: the scene's (thesis for a coulomb scene)")
                                   ->check(is_choice<Law>());
                               app.add_option("--tolerance", o.tolerance,
                                              "largest allowed max|diff|/max|value| per column; default 100 rtol for "
                                              "faithful (same steps); other methods get a convergence test instead: each "
                                              "engine re-run at rtol 1e-14 (docs/rough.md)")
                                   ->check(positive());
                               app.add_option("--accuracy", o.accuracy,
                                              "run both engines at the rtol at which the C++ configuration reaches "
                                              "this error of the final pose, in [1e-14, 0.1] (docs/accuracy.md); "
                                              "instead of --rtol")
                                   ->check(CLI::Range(kAccuracyMin, kAccuracyMax));
                             })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
