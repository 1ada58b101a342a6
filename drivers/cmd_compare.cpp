// nanopush compare: run a scene with the C++ and the FORTRAN 77 engine and judge the deviation.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

#include "nanopush/engines/engines.hpp"
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
};

/// Column groups judged together: a vector's components share its scale (the frame is
/// arbitrary), so a component that stays near zero is not judged against its own tiny range.
const std::vector<std::vector<std::size_t>>& column_groups() {
  static const std::vector<std::vector<std::size_t>> g = {{1, 2}, {3}, {4, 5}, {6}, {7, 8}, {9}};
  return g;
}

/// Largest vector norm of a group over both runs (the scale of its columns).
double group_scale(const std::vector<std::size_t>& g, const Trajectory& a, const Trajectory& b) {
  double s = 0;
  for (const Trajectory* t : {&a, &b})
    for (const auto& r : t->rows) {
      double n2 = 0;
      for (std::size_t c : g) n2 += r[c] * r[c];
      s = std::max(s, std::sqrt(n2));
    }
  return s;
}

double max_diff(const Trajectory& a, const Trajectory& b, std::size_t c) {
  double m = 0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) m = std::max(m, std::fabs(a.rows[i][c] - b.rows[i][c]));
  return m;
}

/// Faithful configuration: the two engines take the same steps, so they agree far below the
/// integration tolerance; the deviation is judged per column against `tol`.
bool judge_same_steps(const Trajectory& ta, const Trajectory& tb, double tol) {
  const auto& cols = trajectory_columns();
  const auto& units = trajectory_units();
  std::cout << "  " << std::left << std::setw(8) << "column" << std::setw(16) << "max |diff|" << std::setw(10)
            << "unit" << std::setw(18) << "max |diff|/scale"
            << "scale = max |value|\n";
  bool ok = true;
  for (std::size_t c = 1; c < cols.size(); ++c) {
    double scale = 0;
    for (const Trajectory* t : {&ta, &tb})
      for (const auto& r : t->rows) scale = std::max(scale, std::fabs(r[c]));
    const double maxabs = max_diff(ta, tb, c);
    const double rel = scale > 0 ? maxabs / scale : maxabs;
    const bool col_ok = rel <= tol;
    ok = ok && col_ok;
    std::cout << "  " << std::left << std::setw(8) << cols[c] << std::setw(16) << std::setprecision(4) << maxabs
              << std::setw(10) << units[c] << std::setw(18) << rel << scale << (col_ok ? "" : "   <-- exceeds") << "\n";
  }
  std::cout << "  tolerance on max |diff|/scale: " << tol << (ok ? "  -> engines agree\n" : "  -> ENGINES DISAGREE\n");
  return ok;
}

/// Different step sequences (modern, dop853): the engines can agree only to their own
/// integration errors. Each engine's error at rtol is measured against the same engine at the
/// tightest rtol; the engines agree when their tight runs differ by no more than the sum of
/// those errors (they converge to the same solution). docs/rough.md, "Comparing the engines".
bool judge_convergence(const Trajectory& ta, const Trajectory& tb, const Trajectory& ta2, const Trajectory& tb2,
                       double rtol2) {
  const auto& cols = trajectory_columns();
  std::cout << "  each engine's error at rtol estimated against itself at rtol " << rtol2
            << "; all figures relative to the column's scale (largest norm of its vector: x,y | vx,vy | fx,fy)\n";
  std::cout << "  " << std::left << std::setw(8) << "column" << std::setw(14) << "error cxx" << std::setw(14)
            << "error f77" << std::setw(16) << "|cxx - f77|" << std::setw(18) << "|cxx - f77| tight"
            << "scale\n";
  // Rounding floor: the engines' tightest runs cannot agree better than this.
  const double floor = 1e-13;
  bool ok = true;
  for (const auto& g : column_groups()) {
    const double scale = group_scale(g, tb, tb2);
    for (std::size_t c : g) {
      const double s = scale > 0 ? scale : 1.0;
      const double ea = max_diff(ta, ta2, c) / s, eb = max_diff(tb, tb2, c) / s;
      const double d = max_diff(ta, tb, c) / s, d2 = max_diff(ta2, tb2, c) / s;
      const bool col_ok = d2 <= ea + eb + floor;
      ok = ok && col_ok;
      std::cout << "  " << std::left << std::setw(8) << cols[c] << std::setprecision(3) << std::setw(14) << ea
                << std::setw(14) << eb << std::setw(16) << d << std::setw(18) << d2 << scale
                << (col_ok ? "" : "   <-- tight runs differ by more than the errors") << "\n";
    }
  }
  std::cout << (ok ? "  -> engines agree: they converge to the same solution, each within its own integration error\n"
                   : "  -> ENGINES DISAGREE: their tight runs differ by more than their errors at rtol\n");
  return ok;
}

int compare_cmd(const CompareOptions& o) {
  const Scene sc = load_scene_arg(o.scene, o.sets);
  RunSettings a, b;
  a.engine = "cxx";
  a.method = o.method.empty() ? "faithful" : o.method;
  b.engine = "f77";
  // The F77 engine implements the thesis and printed laws; a scene asking for the coulomb law
  // is compared under the thesis law unless --law coulomb is given, which has no F77 peer.
  std::string law = o.law;
  if (law.empty()) {
    law = sc.surface.law == "coulomb" ? "thesis" : sc.surface.law;
    if (sc.rough() && sc.surface.law == "coulomb")
      std::cout << "note: " << sc.name
                << " asks for the coulomb law; the engines are compared under the thesis law, which both implement\n";
  }
  if (law == "coulomb")
    throw InputError("--law", law,
                     "thesis or printed: the F77 engine implements only those. The coulomb law's independent "
                     "check is its CVODE cross-check: nanopush run " +
                         o.scene + " --law coulomb --method cvode (docs/rough.md)");
  a.law = b.law = law;
  a.rtol = b.rtol = o.rtol;
  a.atol = b.atol = o.atol;
  a.allow_partial = b.allow_partial = true;
  const Trajectory ta = run_engine(sc, a), tb = run_engine(sc, b);
  for (const Trajectory* t : {&ta, &tb})
    if (!t->complete) {
      std::cerr << "nanopush: solver failure: " << sc.name << " (" << t->engine_label << "): "
                << to_string(t->stats.status) << ": " << t->stats.message << "\n";
      print_rest_diagnosis(sc, law, *t, std::cerr);
      std::cerr << "  nothing to compare\n";
      return 3;
    }
  const double rtol = resolve_settings(sc, a).rtol;
  std::cout << "compare " << sc.name << ": " << ta.engine_label << " vs " << tb.engine_label << " (rtol " << rtol
            << ")\n";
  std::cout << "  RHS evaluations " << ta.stats.nfcn << " vs " << tb.stats.nfcn << ", accepted " << ta.stats.naccpt
            << " vs " << tb.stats.naccpt << ", rejected " << ta.stats.nrejct << " vs " << tb.stats.nrejct << "\n";
  if (ta.rows.size() != tb.rows.size()) {
    std::cout << "  the engines returned " << ta.rows.size() << " and " << tb.rows.size()
              << " samples  -> ENGINES DISAGREE\n";
    return 1;
  }
  // The reference runs: the tightest rtol at which both engines still run in double. Not
  // rtol/100: the F77 engine's error is not monotone in rtol where it starts from rest (its
  // first step sees friction jump from 0 to mu N), e.g. fig3_16 is further off at 1e-12 than
  // at 1e-10; at 1e-14 both engines are within ~1e-12 of dop853 at 1e-13.
  constexpr double kTightest = 1e-14;
  const double rtol2 = kTightest;
  if (a.method == "faithful" || o.tolerance > 0 || rtol < 10 * rtol2) {
    if (a.method != "faithful" && o.tolerance <= 0)
      std::cout << "  note: rtol " << rtol << " is within 10x of the tightest reference (" << kTightest
                << "), so the different step sequences are judged against 100 rtol\n";
    return judge_same_steps(ta, tb, o.tolerance > 0 ? o.tolerance : 100 * rtol) ? 0 : 1;
  }
  RunSettings a2 = a, b2 = b;
  a2.rtol = b2.rtol = rtol2;
  if (o.atol > 0) a2.atol = b2.atol = o.atol * (rtol2 / rtol);
  const Trajectory ta2 = run_engine(sc, a2), tb2 = run_engine(sc, b2);
  return judge_convergence(ta, tb, ta2, tb2, rtol2) ? 0 : 1;
}

RegisterCommand reg_compare{{"compare",
                             "Run a scene with both engines (C++ and FORTRAN 77) and report the deviation per column",
                             20, [](CLI::App& app) -> std::function<int()> {
                               auto o = std::make_shared<CompareOptions>();
                               app.add_option("SCENE", o->scene, "scene file, or a preset name such as fig3_6a (`nanopush presets`)")->required();
                               add_set_option(app, o->sets);
                               app.add_option("--rtol", o->rtol, "relative tolerance (default: the scene's solver.rtol)")
                                   ->check(positive());
                               app.add_option("--atol", o->atol,
                                              "absolute tolerance, one value for every state component (default: the "
                                              "scene's; 0 = rtol times each component's natural scale)")
                                   ->check(non_negative());
                               app.add_option("--method", o->method,
                                              "C++ configuration compared with F77: faithful (default; the same "
                                              "steps), modern or dop853 (judged by convergence: docs/rough.md)")
                                   ->check(CLI::IsMember({"faithful", "modern", "dop853"}));
                               app.add_option("--law", o->law,
                                              "rough scenes: thesis or printed (both engines implement them); "
                                              "default: the scene's (thesis for a coulomb scene)")
                                   ->check(CLI::IsMember({"thesis", "printed", "coulomb"}));
                               app.add_option("--tolerance", o->tolerance,
                                              "largest allowed max|diff|/max|value| per column; default 100 rtol for "
                                              "faithful (same steps); other methods get a convergence test instead: each "
                                              "engine re-run at rtol 1e-14 (docs/rough.md)")
                                   ->check(positive());
                               return [o] { return compare_cmd(*o); };
                             }}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
