// Reproduce steps of thesis chapters 4-5 (docs/models.md D): Table 5.1 from every solver, the
// section 5.6.1.1 error analysis, Figs 4.2-4.5 and 5.2, each beside the printed values.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "nanopush/engines/f77_icor.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/models/icor_dynamic.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "nanopush/sweeps/sweep.hpp"
#include "columns.hpp"
#include "registry.hpp"
#include "icor_common.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

using namespace icor_cli;

void step_table5_1(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double L = rod.length, k2 = rod.gyration_squared();
  const auto solvers = all_solvers(L, k2);
  Columns header = columns("table5_1");
  for (const auto& s : solvers) {
    header.push_back({s.name + "_negative", "m", "negative root of the constrained cubic (eq 5.4), " + s.name});
    header.push_back({s.name + "_positive", "m", "positive root (the other branch), " + s.name + "; empty if none"});
  }
  for (const auto& s : solvers)
    header.push_back({"deviation_" + s.name, "1", "(|R_negative| - printed) / printed, " + s.name});
  header.push_back(count_column("printed_digits_match",
                                "1 if |R_negative| rounded to the printed digits equals the printed value for all solvers"));
  header.push_back({"max_relative_spread", "1", "largest relative difference between the four solvers' roots"});
  const auto path = ctx.out / "table5_1.csv";
  Table t(path, header);
  ctx.report << "\n## Table 5.1: iCOR from the constrained cubic (5.4), nanorod L = 590 nm\n\n"
             << "Signed roots of 2 yn R^3 - 3 k^2 R^2 + k^2 (b^2 - 2 k^2) = 0 (k^2 = I/m = L^2/12) from four solvers:\n"
             << "Brent and Eigen companion eigenvalues in C++, Brent and LAPACK DGEEV companion eigenvalues in\n"
             << "FORTRAN 77. The thesis prints |R| of the negative root (docs/models.md: the far side of the CM); `deviation` is\n"
             << "(|R_negative| - printed)/printed; `match` says |R_negative| rounded to the printed number of\n"
             << "significant digits equals the printed value for all four solvers. The positive branch (the other\n"
             << "branch) exists for yn < b/sqrt(3) = 170.3 nm; where the thesis prints +- (yn <= 2 nm)\n"
             << "both branches are shown exactly (erratum 9).\n\n"
             << "| yn [nm] | thesis [m] | R negative (Brent C++) [m] | deviation | match | R positive [m] | max spread of 4 solvers |\n"
             << "|---:|---:|---:|---:|:---:|---:|---:|\n";
  double worst_spread = 0.0;
  int matches = 0;
  for (const auto& row : icor::thesis_table_5_1()) {
    std::vector<CubicSolution> sol;
    for (const auto& s : solvers) sol.push_back(s.solve(row.yn));
    std::vector<std::string> cells = {csv_number(row.yn), csv_number(row.printed)};
    for (const auto& x : sol) {
      cells.push_back(cell(x.negative));
      cells.push_back(cell(x.positive));
    }
    bool all_match = true;
    double spread = 0.0;
    for (const auto& x : sol) {
      if (!x.negative) {
        cells.push_back("");
        all_match = false;
        continue;
      }
      cells.push_back(csv_number((-*x.negative - row.printed) / row.printed));
      const double shown = icor::round_significant(-*x.negative, row.digits());
      all_match = all_match && std::fabs(shown - row.printed) <= 1e-12 * row.printed;
      spread = std::max(spread, std::fabs(*x.negative - *sol[0].negative) / std::fabs(*sol[0].negative));
      if (x.positive && sol[0].positive)
        spread = std::max(spread, std::fabs(*x.positive - *sol[0].positive) / *sol[0].positive);
    }
    cells.push_back(all_match ? "1" : "0");
    cells.push_back(csv_number(spread));
    t.row(cells);
    worst_spread = std::max(worst_spread, spread);
    matches += all_match ? 1 : 0;
    check(ctx, all_match, "table5_1: yn = " + fmt(row.yn) + " m does not round to the printed " + row.mantissa + "e-8");
    std::ostringstream line;
    line << std::setprecision(7);
    line << "| " << row.yn * 1e9 << " | " << (row.plus_minus ? "±" : "") << row.mantissa << "e-8 | "
         << *sol[0].negative << " | " << std::setprecision(2) << (-*sol[0].negative - row.printed) / row.printed
         << " | " << (all_match ? "yes" : "**no**") << " | " << std::setprecision(7);
    if (sol[0].positive) line << *sol[0].positive;
    else line << "—";
    line << " | "
         << std::setprecision(2) << spread << " |\n";
    ctx.report << line.str();
  }
  check(ctx, worst_spread <= 1e-12, "table5_1: the four solvers differ by " + fmt(worst_spread) + " > 1e-12 relative");
  t.write();
  ctx.produced(path);
  ctx.report << "\n" << matches << " of " << icor::thesis_table_5_1().size()
             << " rows match the printed digits from every solver; the largest relative spread between the four "
                "solvers is "
             << std::setprecision(3) << worst_spread << ".\n";
}

void step_error_analysis(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double L = rod.length, k2 = rod.gyration_squared();
  const auto path = ctx.out / "icor_error_analysis.csv";
  ctx.report << "\n## Section 5.6.1.1: error analysis (sample standard deviation of R)\n\n"
             << "Sampling that reproduces the printed values: yn = 0, 1, 2, ..., 295 nm (n = 296, the push point from\n"
             << "the CM to the rod end, 1 nm apart), R in nanometres, sample standard deviation (n - 1 in the\n"
             << "denominator); for (5.4) the branch of Table 5.1 (|R| of the negative root). The thesis' four\n"
             << "decimals are the truncation of our values (5.395080 prints as 5.3950, not 5.3951: see errata).\n\n"
             << "| equation | solver | sample std [nm] | population std [nm] | thesis [nm] | truncated to 4 dp |\n"
             << "|---|---|---:|---:|---:|---:|\n";
  // Collect the samples.
  std::vector<double> r413;
  for (int i = 0; i < 296; ++i) r413.push_back(icor::unknown_pressure(i * 1e-9, L) / 1e-9);
  struct Line {
    std::string eq, solver;
    std::vector<double> R;
    double thesis;
  };
  std::vector<Line> lines = {{"4.13", "closed form", r413, icor::kThesisStdUnknownPressure}};
  for (const auto& s : all_solvers(L, k2)) {
    std::vector<double> R;
    for (int i = 0; i < 296; ++i) {
      const auto sol = s.solve(i * 1e-9);
      if (!sol.negative) throw SolverError("no negative root of (5.4) at yn = " + std::to_string(i) + " nm");
      R.push_back(-*sol.negative / 1e-9);
    }
    lines.push_back({"5.4", s.name, R, icor::kThesisStdConstrained});
  }
  Table t(path, columns("icor_error_analysis"));
  for (const auto& l : lines) {
    const double n = static_cast<double>(l.R.size());
    double mean = 0.0;
    for (double v : l.R) mean += v / n;
    const double sd = icor::sample_std(l.R), pop = sd * std::sqrt((n - 1.0) / n);
    const double tr = std::trunc(sd * 1e4) / 1e4, ro = std::round(sd * 1e4) / 1e4;
    t.row({l.eq, l.solver, std::to_string(l.R.size()), "0", csv_number(295e-9), csv_number(1e-9), csv_number(mean),
           csv_number(sd), csv_number(pop), csv_number(l.thesis), csv_number(tr), csv_number(ro),
           csv_number(sd - l.thesis)});
    std::ostringstream line;
    line << std::fixed << std::setprecision(6) << "| " << l.eq << " | " << l.solver << " | " << sd << " | " << pop
         << " | " << std::setprecision(4) << l.thesis << " | " << tr << " |\n";
    ctx.report << line.str();
    check(ctx, std::fabs(tr - l.thesis) < 1e-9,
          "icor_error_analysis: " + l.eq + " (" + l.solver + ") std " + fmt(sd) + " does not give the printed " + fmt(l.thesis));
  }
  t.write();
  ctx.produced(path);
}

/// The icor task's outputs `names` over the grid yn x mu (mu fastest; no mu: the task's
/// default) for the thesis nanorod, through the sweep engine on every core: per point (in
/// plan order), the values of `names`.
std::vector<std::vector<double>> icor_by_sweep(const std::vector<double>& yns, const std::vector<double>& mus,
                                               const std::vector<std::string>& names,
                                               std::optional<double> force = std::nullopt,
                                               const std::string& cubic = "brent") {
  const auto rod = icor::nanorod();
  std::vector<SceneSetting> fixed = {{"rod.length", rod.length}, {"rod.radius", rod.radius},
                                     {"rod.density", rod.density}, {"rod.hamaker", rod.hamaker},
                                     {"rod.z0", rod.z0},         {"rod.gravity", rod.gravity}};
  if (force) fixed.emplace_back("force", *force);
  fixed.emplace_back("cubic", cubic);
  const auto task = sweep::make_icor_task(fixed);
  std::vector<sweep::Axis> axes = {{"yn", {}}};
  for (double y : yns) axes[0].values.emplace_back(y);
  if (!mus.empty()) {
    axes.push_back({"mu", {}});
    for (double m : mus) axes[1].values.emplace_back(m);
  }
  const sweep::Plan plan = sweep::cartesian(axes);
  const auto rows = sweep::evaluate_points(plan, *task, 0);
  std::vector<std::size_t> cols;
  for (const auto& nm : names) cols.push_back(sweep::column_index(plan, *task, nm));
  std::vector<std::vector<double>> out;
  out.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (sweep::row_failed(rows[i]))
      throw SolverError("icor sweep, point " + std::to_string(i) + ": " + rows[i].back());
    std::vector<double> v;
    for (std::size_t c : cols) v.push_back(sweep::cell_number(rows[i][c]));
    out.push_back(std::move(v));
  }
  return out;
}

void step_fig4_2(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double b = rod.half_length();
  const int n = ctx.quick ? 30 : 296;
  const auto csv = ctx.out / "fig4_2.csv";
  CsvWriter w(csv, columns("fig4_2"));
  double worst = 0.0;
  const auto yns = sweep(0.0, b, n, false);
  const auto v = icor_by_sweep(yns, {}, {"R_experimental_fit", "R_falvo", "R_li", "R_unknown_pressure"});
  for (std::size_t i = 0; i < yns.size(); ++i) {
    const double yn = yns[i], fit = v[i][0], falvo = v[i][1], li = v[i][2], r = v[i][3];
    worst = std::max({worst, std::fabs(falvo - r) / r, std::fabs(li - r) / r});
    w.row({yn, fit, falvo, li, r});
  }
  w.commit();
  ctx.produced(csv);
  check(ctx, worst <= 1e-14, "fig4_2: eqs 4.2/4.3 differ from 4.13 by " + fmt(worst));
  plot::Panel p{"", "push point yn [nm]", "iCOR distance from the CM, R [nm]", false, false, "", {}};
  p.series = {{csv, "($1*1e9)", "($2*1e9)", "eq 4.1 experimental fit", "lines lw 2"},
              {csv, "($1*1e9)", "($3*1e9)", "eq 4.2 Falvo et al.", "lines lw 4"},
              {csv, "($1*1e9)", "($4*1e9)", "eq 4.3 Li et al.", "lines lw 2 dt 2"},
              {csv, "($1*1e9)", "($5*1e9)", "eq 4.13 unknown pressure", "points pt 6 ps 0.6"}};
  render_if_possible(ctx, "Fig 4.2: quasi-static iCOR, nanorod L = 590 nm", p, ctx.out / "fig4_2.png");
  ctx.report << "\n## Fig 4.2: the unconstrained quasi-static iCOR\n\n"
             << "Eqs 4.2 (Falvo) and 4.3 (Li) mapped to R (x1 = b + yn, R = b - L x0; l = b - yn, R = S - b) equal\n"
             << "eq 4.13 to " << std::setprecision(2) << worst << " relative over " << n << " points. Eq 4.1 "
             << "(R = b - rho, rho = 0.5 L sqrt(yn/L)) lies below them: the thesis' scale factor.\n";
}

const std::vector<double> kMuFamily43 = {0.01, 0.05, 0.10, 0.15};
const std::vector<double> kMuFamily44 = {0.01, 0.1, 0.25, 0.5, 0.75, 1.0};

std::string mu_name(double mu) {
  std::ostringstream s;
  s << "mu=" << mu;
  return s.str();
}

/// A figure of a mu family (Figs 4.3-4.5) over the nanorod's push points yn in [0, b]: the CSV
/// holds yn, the `shared` columns (outputs that do not depend on mu, read at the family's first
/// mu), then one `per_mu(mu)` column a mu (the last of `outputs`); the figure draws the family's
/// columns, x = `x` (a gnuplot using-expression), y = column scaled by `yscale` ("" or "*1e9").
struct MuFamily {
  std::string stem;                 ///< fig4_3: the CSV's and the PNG's name
  const std::vector<double>& mus;   ///< the family
  Columns shared;                   ///< columns between yn and the family's
  std::function<Column(double)> per_mu;
  std::vector<std::string> outputs;  ///< the shared columns' icor outputs, then the family's
  std::optional<double> force;       ///< the push force, for the outputs that need one
  std::string title, xlabel, ylabel, x, yscale;
};

void mu_family_figure(ReproduceContext& ctx, const MuFamily& f) {
  const double b = icor::nanorod().half_length();
  const int n = ctx.quick ? 30 : 296;
  const auto csv = ctx.out / (f.stem + ".csv");
  Columns h = {{"yn", "m", "push point: distance from the CM along the rod"}};
  h.insert(h.end(), f.shared.begin(), f.shared.end());
  for (double mu : f.mus) h.push_back(f.per_mu(mu));
  CsvWriter w(csv, h);
  const auto yns = sweep(0.0, b, n, false);
  const auto v = icor_by_sweep(yns, f.mus, f.outputs, f.force);
  const std::size_t m = f.mus.size(), last = f.outputs.size() - 1;
  for (std::size_t i = 0; i < yns.size(); ++i) {
    std::vector<double> r = {yns[i]};
    for (std::size_t j = 0; j < last; ++j) r.push_back(v[i * m][j]);
    for (std::size_t k = 0; k < m; ++k) r.push_back(v[i * m + k][last]);
    w.row(r);
  }
  w.commit();
  ctx.produced(csv);
  plot::Panel p{"", f.xlabel, f.ylabel, false, true, "", {}};
  const std::size_t first = 2 + f.shared.size();  // the family's first column, from 1
  for (std::size_t i = 0; i < m; ++i)
    p.series.push_back({csv, f.x, "($" + std::to_string(i + first) + f.yscale + ")", mu_name(f.mus[i]), "lines lw 2"});
  render_if_possible(ctx, f.title, p, ctx.out / (f.stem + ".png"));
}

void step_fig4_3(ReproduceContext& ctx) {
  const double W = icor::nanorod().load();
  mu_family_figure(ctx, {"fig4_3", kMuFamily43, {},
                         [](double mu) {
                           return Column{"R_known_pressure_mu_" + value_name(mu), "m",
                                         "iCOR distance, known uniform pressure (eq 4.7), F = 0.15 W, " + mu_name(mu),
                                         "number", {{"mu", mu}}};
                         },
                         {"R_known_pressure"},
                         0.15 * W,  // one push force for the whole family: F >= mu W >= F_min for mu <= 0.15
                         "Fig 4.3: iCOR for known pressure (eq 4.7), F = 0.15 W", "push point yn [nm]", "R [nm]",
                         "($1*1e9)", "*1e9"});
  ctx.report << "\n## Fig 4.3: iCOR for a known (uniform) pressure, eq 4.7\n\n"
             << "The thesis does not print the push force used; we hold F = 0.15 W fixed (W = m g + F_vdw = "
             << std::setprecision(4) << W << " N), which starts motion for every mu <= 0.15. With F = mu W (the\n"
             << "thesis' 'F ~ mu (m g + F_vdw)') eq 4.7 gives R = b + sqrt(2 b yn) for every mu: one curve.\n";
}

void step_fig4_4(ReproduceContext& ctx) {
  mu_family_figure(ctx, {"fig4_4", kMuFamily44, {},
                         [](double mu) {
                           return Column{"F_min_mu_" + value_name(mu), "N", "minimum push force (eq 4.8), " + mu_name(mu),
                                         "number", {{"mu", mu}}};
                         },
                         {"F_min"}, std::nullopt, "Fig 4.4: minimum push force (eq 4.8) vs push point",
                         "push point yn [nm]", "F_min [N]", "($1*1e9)", ""});
  ctx.report << "\n## Fig 4.4: minimum push force, eq 4.8 (the map behind `nanopush icor estimate-mu --yn`)\n\n"
             << "F_min / (mu W) falls from 1 at yn = 0 to sqrt(2) - 1 at the rod end. Absolute forces scale with the\n"
             << "assumed Hamaker constant H = " << icor::nanorod().hamaker << " J (the thesis prints none for graphite).\n";
}

void step_fig4_5(ReproduceContext& ctx) {
  const double b = icor::nanorod().half_length();
  mu_family_figure(ctx, {"fig4_5", kMuFamily44, {{"R_unknown_pressure", "m", "iCOR distance, unknown pressure (eq 4.13)"}},
                         [](double mu) {
                           return Column{"F_from_icor_mu_" + value_name(mu), "N",
                                         "push force from the iCOR (eq 4.10), " + mu_name(mu), "number", {{"mu", mu}}};
                         },
                         {"R_unknown_pressure", "F_from_icor"}, std::nullopt,
                         "Fig 4.5: push force (eq 4.10) vs quasi-static iCOR", "iCOR distance R [nm]", "F [N]", "($2*1e9)",
                         ""});
  ctx.report << "\n## Fig 4.5: push force against the iCOR, eq 4.10 (the map behind `estimate-mu --icor`)\n\n"
             << "R runs from (sqrt(2) - 1) b = " << std::setprecision(4) << (std::sqrt(2.0) - 1.0) * b * 1e9
             << " nm (push at the rod end; the thesis reads ~118 nm) to b = " << b * 1e9 << " nm (push at the CM).\n";
}

void step_fig5_2(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double b = rod.half_length(), k2 = rod.gyration_squared();
  const int n = ctx.quick ? 30 : 296;
  const auto csv = ctx.out / "fig5_2.csv";
  Table t(csv, columns("fig5_2"));
  const auto yns = sweep(0.0, b, n, false);
  const auto v = icor_by_sweep(yns, {}, {"R_unknown_pressure", "R_constrained_negative", "R_constrained_positive"},
                               std::nullopt, "eigen");
  for (std::size_t i = 0; i < yns.size(); ++i) {  // a missing root is NaN: an empty cell, and so is its negation
    const double neg = v[i][1], pos = v[i][2];
    t.row({csv_number(yns[i]), csv_number(v[i][0]), csv_number(neg), csv_number(pos), csv_number(-neg),
           csv_number(-pos)});
  }
  t.write();
  ctx.produced(csv);
  // Bifurcation points at yn = 0.
  const auto pts = ctx.out / "fig5_2_bifurcation.csv";
  {
    const double r0 = std::sqrt((b * b - 2.0 * k2) / 3.0);
    CsvWriter w(pts, columns("fig5_2_bifurcation"));
    w.row({0.0, r0});
    w.row({0.0, -r0});
    w.commit();
    ctx.produced(pts);
  }
  plot::Panel p{"", "push point yn [nm]", "iCOR distance from the CM [nm] (> 0: far side from the push)", false, false,
                "set yrange [-300:320]", {}};
  p.series = {{csv, "($1*1e9)", "($5*1e9)", "eq 5.4, Table 5.1 branch", "lines lw 2"},
              {csv, "($1*1e9)", "($6*1e9)", "eq 5.4, other branch (yn < b/sqrt 3)", "lines lw 2 dt 3"},
              {csv, "($1*1e9)", "($2*1e9)", "eq 4.13", "lines lw 2 dt 2"},
              {pts, "($1*1e9)", "($2*1e9)", "bifurcation (yn = 0)", "points pt 4 ps 2"}};
  render_if_possible(ctx, "Fig 5.2: quasi-static iCOR with (5.4) and without (4.13) the tangential constraint",
                     p, ctx.out / "fig5_2.png");
  ctx.report << "\n## Fig 5.2: constrained (5.4) against unconstrained (4.13) quasi-static iCOR\n\n"
             << "Plotted with R > 0 on the far side of the CM from the push (the sign of chapter 4): the Table 5.1\n"
             << "branch of (5.4) is |R_negative|, its other branch -R_positive. At yn = 0 the two branches meet the\n"
             << "axis at +-b/3 = +-" << std::setprecision(5) << b / 3.0 * 1e9 << " nm (the bifurcation squares).\n"
             << "(Side of the CM as docs/models.md section D reads the cubic's signs; see docs/errata.md, iCOR item 5.)\n"
             << "Fig 5.3 (dynamic iCOR) is the step fig5_3.\n";
}



RegisterReproduce r1{{"table5_1", "Table 5.1: the constrained cubic from Brent/Eigen (C++) and Brent/LAPACK (F77)", 50, step_table5_1}};
RegisterReproduce r2{{"icor_error_analysis", "Section 5.6.1.1: sample std of R for eqs 4.13 and 5.4", 51, step_error_analysis}};
RegisterReproduce r3{{"fig4_2", "Fig 4.2: iCOR from eqs 4.1, 4.2, 4.3, 4.13", 52, step_fig4_2}};
RegisterReproduce r4{{"fig4_3", "Fig 4.3: iCOR for known pressure (eq 4.7)", 53, step_fig4_3}};
RegisterReproduce r5{{"fig4_4", "Fig 4.4: minimum push force (eq 4.8)", 54, step_fig4_4}};
RegisterReproduce r6{{"fig4_5", "Fig 4.5: push force vs iCOR (eq 4.10)", 55, step_fig4_5}};
RegisterReproduce r7{{"fig5_2", "Fig 5.2: iCOR with (5.4) and without (4.13) constraints", 56, step_fig5_2}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
