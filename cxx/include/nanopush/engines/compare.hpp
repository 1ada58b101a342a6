// The C++ engine against the FORTRAN 77 engine on one scene, judged column by column: the one
// rule behind `nanopush compare`, Python's nanopush.compare and the C API's nanopush_compare.
//
// Two ways to judge (docs/rough.md, "Comparing the engines"):
//  - same steps (method faithful, or a tolerance given): the engines take the same steps, so
//    each column's max |diff| / scale (scale = the column's largest |value| over both runs)
//    must be <= tolerance (default 100 rtol);
//  - convergence (modern, dop853): the step sequences differ, so the engines can agree only to
//    their own integration errors. Each engine is run again at rtol 1e-14 (the tightest rtol at
//    which both run in double); a column agrees when the two tight runs differ by no more than
//    the sum of the engines' errors at rtol (each against its own tight run) plus a rounding
//    floor. Figures are relative to the column's vector scale (x,y | vx,vy | fx,fy share one).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush {

/// The reference rtol of a convergence comparison, and the rounding floor of its verdict.
inline constexpr double kCompareTightRtol = 1e-14;
inline constexpr double kCompareRoundingFloor = 1e-13;

struct CompareSettings {
  Method method = Method::faithful;  ///< the C++ configuration: faithful | modern | dop853
  std::optional<Law> law;            ///< thesis | printed; unset = the scene's (thesis for a coulomb scene)
  double rtol = 0;                  ///< 0 = the scene's
  double atol = -1;                 ///< < 0 = the scene's
  double tolerance = 0;             ///< > 0: judge by same steps against it; 0 = by the method
  /// > 0: the rtol of both engines is the one at which the C++ configuration reaches this
  /// error of the final pose (run_to_accuracy, docs/accuracy.md); rtol is then ignored.
  double accuracy = 0;
};

enum class CompareKind { same_steps, convergence };

/// The verdict on one trajectory column (every column but t).
struct ColumnVerdict {
  std::string name, unit;
  double scale = 0;         ///< same steps: max |value|; convergence: largest norm of the column's vector
  double max_abs_diff = 0;  ///< max |cxx - f77| at rtol [unit]
  double relative = 0;      ///< same steps: max_abs_diff / scale
  double error_cxx = 0, error_f77 = 0;  ///< convergence: each engine at rtol against itself at 1e-14, / scale
  double diff = 0, diff_tight = 0;      ///< convergence: the engines apart at rtol and at 1e-14, / scale
  bool ok = false;
};

struct EngineComparison {
  CompareKind kind = CompareKind::same_steps;
  Law law = Law::thesis;           ///< the law both engines ran
  bool law_from_coulomb = false;   ///< the scene asked for coulomb; compared under thesis instead
  double rtol = 0;                 ///< the resolved rtol of the runs
  AccuracyRecord accuracy;         ///< with CompareSettings::accuracy: how the rtol was chosen
  double tolerance = 0;            ///< same steps: the bound on relative; convergence: 0
  double rtol_tight = 0;           ///< convergence: the reference rtol
  bool tolerance_from_tight = false;  ///< not faithful, but rtol within 10x of the reference: same-steps rule
  Trajectory cxx, f77;             ///< the runs at rtol
  Trajectory cxx_tight, f77_tight;  ///< convergence: the reference runs
  /// False when a run (at rtol or a reference run) did not complete: failed() is that run,
  /// and nothing was judged.
  bool complete = true;
  int failed_run = -1;             ///< 0 cxx, 1 f77, 2 cxx_tight, 3 f77_tight; -1 = none
  [[nodiscard]] const Trajectory* failed() const {
    const Trajectory* runs[] = {&cxx, &f77, &cxx_tight, &f77_tight};
    return failed_run >= 0 ? runs[failed_run] : nullptr;
  }
  /// Non-empty: no verdict could be made, and why (a run or a reference run did not complete,
  /// or a deviation is not finite); agree is then false. Every front end reports it as
  /// "cannot judge" (the CLI exits 3), never as agreement or disagreement.
  std::string cannot_judge;
  bool same_length = true;         ///< both runs returned the same number of samples
  std::vector<ColumnVerdict> columns;
  bool agree = false;
};

/// The law a comparison runs under: `law`, or the scene's (thesis for a coulomb scene).
/// InputError for coulomb (the F77 engine implements thesis and printed only).
Law compare_law(const Scene& scene, std::optional<Law> law, bool* from_coulomb = nullptr);

/// Run both engines (and, for a convergence comparison, both again at kCompareTightRtol) and
/// judge every column. InputError for bad settings; a run that fails is reported through
/// `complete`/failed(), never thrown.
EngineComparison compare_engines(const Scene& scene, const CompareSettings& settings);

}  // namespace nanopush
