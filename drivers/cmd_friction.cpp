// nanopush friction: the friction wrench of a rectangular contact at any iCOR (docs/models.md §B),
// row by row from standard input; a microbenchmark (--bench); and the reproduce steps for the
// thesis' Figs 3.9-3.11.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "f77_friction.h"
#include "nanopush/numerics/error.hpp"
#include "nanopush/models/friction.hpp"
#include "nanopush/models/friction_cubature.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "nanopush/sweeps/sweep.hpp"
#include "nanopush/outputs/csv_reader.hpp"
#include "cli_checks.hpp"
#include "columns.hpp"
#include "registry.hpp"
#include "sweep_output.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

constexpr double kPi = 3.14159265358979323846;
// The thesis nanobar (docs/models.md §A): width 55 nm, length 100 nm -> a = 27.5 nm, b = 50 nm.
constexpr double kBarA = 27.5e-9, kBarB = 50e-9;

struct Options {
  double a = kBarA, b = kBarB;
  int sense = 1;
  std::string engine = "cxx";
  bool bench = false;
  double bench_seconds = 0.3;
  std::string bench_csv;
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

/// Parse a whole field as a double; throws InputError naming line, field and value.
double parse_field(const std::string& text, std::size_t line, const std::string& field,
                   const std::string& requirement) {
  const std::string t = trim(text);
  const std::string where = "stdin line " + std::to_string(line) + ", field " + field;
  if (t.empty()) throw InputError(where, "(empty)", requirement);
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end == t.c_str() || *end != '\0') throw InputError(where, t, "not a number; " + requirement);
  if (!std::isfinite(v)) throw InputError(where, t, requirement);
  return v;
}

FrictionWrench evaluate(const Options& o, double R, double alpha) {
  if (parse_choice<Engine>("--engine", o.engine) == Engine::f77) {
    double w[3];
    const int st = np_f77_rectangle_friction(o.a, o.b, 1.0, R, alpha, o.sense, w);
    if (st != 0) {
      char msg[160];
      np_f77_friction_message(st, msg, sizeof msg);
      throw InputError(std::string("F77 engine: ") + msg);
    }
    return {w[0], w[1], w[2]};
  }
  return rectangle_friction_wrench(o.a, o.b, 1.0, R, alpha, o.sense);
}

int run_rows(const Options& o) {
  (void)rectangle_friction_wrench_checked(o.a, o.b, 1.0, 0.0, 0.0, o.sense);  // validates a, b, sense
  std::ostringstream out;
  out << "R,alpha,fx,fy,mf\n";
  // Records from stdin (RFC 4180, csv_reader.hpp); '#' comments and blank lines skipped; an
  // optional header R,alpha.
  csv::ReadOptions ro;
  ro.comments = true;
  csv::Reader reader(std::cin, "stdin", ro);
  csv::Record rec;
  bool first = true;
  while (reader.next(rec)) {
    const std::size_t n = rec.line;
    const auto& f = rec.fields;
    if (first && f.size() == 2 && f[0] == "R" && f[1] == "alpha") {
      first = false;
      continue;
    }
    first = false;
    if (f.size() < 2)
      throw InputError("stdin line " + std::to_string(n), csv::join(f), "expected two fields 'R,alpha' separated by a comma");
    if (f.size() > 2)
      throw InputError("stdin line " + std::to_string(n), csv::join(f), "expected exactly two fields 'R,alpha'");
    const double R = parse_field(f[0], n, "R", "must be a finite number >= 0 (m)");
    if (!(R >= 0.0))
      throw InputError("stdin line " + std::to_string(n) + ", field R", f[0], "must be a finite number >= 0 (m)");
    const double alpha = parse_field(f[1], n, "alpha", "must be a finite number (rad)");
    const auto w = evaluate(o, R, alpha);
    out << csv_number(R) << ',' << csv_number(alpha) << ',' << csv_number(w.fx) << ',' << csv_number(w.fy) << ','
        << csv_number(w.mf) << '\n';
  }
  std::cout << out.str();  // all rows valid: no partial output on error
  return 0;
}

// ---------------------------------------------------------------------------------------------
// Microbenchmark (a driver, never a test).

std::string machine_description() {
  std::string cpu = "unknown CPU";
  std::ifstream f("/proc/cpuinfo");
  std::string l;
  int cores = 0;
  while (std::getline(f, l)) {
    if (l.rfind("model name", 0) == 0 && cpu == "unknown CPU") cpu = trim(l.substr(l.find(':') + 1));
    if (l.rfind("processor", 0) == 0) ++cores;
  }
  std::ostringstream s;
  s << cpu << ", " << cores << " logical CPUs; compiler " << __VERSION__;
#ifdef NDEBUG
  s << ", NDEBUG";
#else
  s << ", assertions on";
#endif
#ifdef __OPTIMIZE__
  s << ", optimised";
#endif
  return s.str();
}

struct BenchRow {
  std::string what;
  double evals_per_s;
  long evals;
  double seconds;
};

template <class F>
BenchRow time_it(const std::string& what, double seconds, F&& f) {
  using clk = std::chrono::steady_clock;
  long n = 0;
  double sink = 0.0;
  const auto t0 = clk::now();
  double dt = 0.0;
  do {
    for (int k = 0; k < 64; ++k) sink += f(n++);
    dt = std::chrono::duration<double>(clk::now() - t0).count();
  } while (dt < seconds);
  if (sink == 12345.678) std::cerr << "";  // keep the results alive
  return {what, static_cast<double>(n) / dt, n, dt};
}

int run_bench(const Options& o) {
  (void)rectangle_friction_wrench_checked(o.a, o.b, 1.0, 0.0, 0.0, 1);
  if (!(o.bench_seconds > 0.0 && o.bench_seconds <= 20.0))
    throw InputError("--bench-seconds", fmt(o.bench_seconds), "must be in (0, 20] (s)");
  if (!o.bench_csv.empty()) (void)TableOutput::kind_of(o.bench_csv, "--bench-csv", false);  // before the timing
  const double a = o.a, b = o.b, L = std::max(a, b);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t N = 4096, M = N - 1;
  std::vector<double> rn(N), rf(N), ra(N), al(N), vx(N), vy(N), om(N);  // rf: far field, log-uniform
  for (std::size_t i = 0; i < N; ++i) {
    rn[i] = L * kFrictionFarField * u(rng);
    rf[i] = L * kFrictionFarField * std::pow(10.0, 8.0 * u(rng));
    ra[i] = L * kFrictionAsymptotic * std::pow(10.0, 6.0 * u(rng));
    al[i] = 2 * kPi * u(rng);
    vx[i] = u(rng) - 0.5;
    vy[i] = u(rng) - 0.5;
    om[i] = (u(rng) - 0.5) / L * std::pow(10.0, -4.0 * u(rng));
  }
  std::vector<BenchRow> rows;
  const double s = o.bench_seconds;
  rows.push_back(time_it("closed form, R < 3 max(a,b) (corner terms)", s, [&](long i) {
    const auto w = rectangle_friction_wrench(a, b, 1.0, rn[static_cast<std::size_t>(i) & M], al[static_cast<std::size_t>(i) & M], 1);
    return w.fx + w.mf;
  }));
  struct Band {
    const char* what;
    double lo, hi;
  };
  for (const Band& band : {Band{"far field, 3 <= R/max(a,b) < 8 (12x12 GL)", kFrictionFarField, kFrictionGl8From},
                           Band{"far field, 8 <= R/max(a,b) < 24 (8x8 GL)", kFrictionGl8From, kFrictionGl6From},
                           Band{"far field, 24 <= R/max(a,b) < 512 (6x6 GL)", kFrictionGl6From, kFrictionGl4From},
                           Band{"far field, 512 <= R/max(a,b) < 1e9 (4x4 GL)", kFrictionGl4From, kFrictionAsymptotic}}) {
    std::vector<double> rb(N);
    for (auto& x : rb) x = L * band.lo * std::pow(band.hi / band.lo, u(rng));
    rows.push_back(time_it(band.what, s, [&](long i) {
      const auto w = rectangle_friction_wrench(a, b, 1.0, rb[static_cast<std::size_t>(i) & M], al[static_cast<std::size_t>(i) & M], 1);
      return w.fx + w.mf;
    }));
  }
  rows.push_back(time_it("asymptotic, R >= 1e9 max(a,b)", s, [&](long i) {
    const auto w = rectangle_friction_wrench(a, b, 1.0, ra[static_cast<std::size_t>(i) & M], al[static_cast<std::size_t>(i) & M], 1);
    return w.fx + w.mf;
  }));
  rows.push_back(time_it("from velocity (mixed iCORs)", s, [&](long i) {
    const std::size_t k = static_cast<std::size_t>(i) & M;
    const auto w = rectangle_friction_from_velocity(a, b, 1.0, vx[k], vy[k], om[k]);
    return w.fx + w.mf;
  }));
  rows.push_back(time_it("F77 RECTFR through the bridge, R < 3 max(a,b)", s, [&](long i) {
    double w[3];
    np_f77_rectangle_friction(a, b, 1.0, rn[static_cast<std::size_t>(i) & M], al[static_cast<std::size_t>(i) & M], 1, w);
    return w[0] + w[2];
  }));
  rows.push_back(time_it("cubature, uniform pressure, tol 1e-12, R < 3 max(a,b)", s, [&](long i) {
    const auto q = cubature_friction_wrench_uniform(a, b, 1.0, rn[static_cast<std::size_t>(i) & M], al[static_cast<std::size_t>(i) & M], 1, 1e-12);
    return q.wrench.fx;
  }));
  rows.push_back(time_it("cubature, uniform pressure, tol 1e-12, far field", s, [&](long i) {
    const auto q = cubature_friction_wrench_uniform(a, b, 1.0, rf[static_cast<std::size_t>(i) & M], al[static_cast<std::size_t>(i) & M], 1, 1e-12);
    return q.wrench.fx;
  }));
  rows.push_back(time_it("cubature, arbitrary pressure (fully 2-D), tol 1e-12, R < 3 max(a,b)", s, [&](long i) {
    const auto q = cubature_friction_wrench(a, b, 1.0, rn[static_cast<std::size_t>(i) & M], al[static_cast<std::size_t>(i) & M], 1,
                                            [](double, double) { return 1.0; }, 1e-12);
    return q.wrench.fx;
  }));
  std::cout << "machine: " << machine_description() << "\n";
  std::cout << "rectangle a = " << a << " m, b = " << b << " m; " << s << " s per row\n\n";
  std::cout << "| evaluation | evaluations/s | evaluations | time [s] |\n|---|---:|---:|---:|\n";
  for (const auto& r : rows)
    std::cout << "| " << r.what << " | " << std::setprecision(4) << r.evals_per_s << " | " << r.evals << " | "
              << std::setprecision(3) << r.seconds << " |\n";
  if (!o.bench_csv.empty()) {
    const TableOutput table(o.bench_csv, "--bench-csv", false);  // FILE.csv or FILE.nc
    CsvWriter f(table.table(), columns("friction_bench"));
    for (const auto& r : rows)
      f.cells({csv_quote(r.what), csv_number(r.evals_per_s), std::to_string(r.evals), csv_number(r.seconds)});
    f.commit();
    (void)table.finish();
  }
  return 0;
}

RegisterCommand reg{{"friction",
                     "Friction wrench of a rectangular contact: reads 'R,alpha' rows on stdin, writes "
                     "'R,alpha,fx,fy,mf' (muN = 1, body axes); --bench times the evaluation forms",
                     30, [](CLI::App& app) -> std::function<int()> {
                       auto o = std::make_shared<Options>();
                       app.add_option("--a", o->a, "half-width of the contact along body x' (m; default: the thesis nanobar, 55 nm wide)")
                           ->capture_default_str();
                       app.add_option("--b", o->b, "half-length of the contact along body y' (m; default: the thesis nanobar, 100 nm long)")
                           ->capture_default_str();
                       app.add_option("--sense", o->sense,
                                      "+1 counter-clockwise rotation (omega > 0), -1 clockwise")
                           ->check(count(-1, 1))
                           ->check(CLI::Validator([](std::string& s) { return s == "0" ? std::string("0: must be 1 or -1") : std::string(); }, ""))
                           ->capture_default_str();
                       app.add_option("--engine", o->engine, "cxx (C++) or f77 (FORTRAN 77 RECTFR)")
                           ->check(is_choice<Engine>())
                           ->capture_default_str();
                       app.add_flag("--bench", o->bench,
                                    "microbenchmark: evaluations per second of each form vs the cubature");
                       app.add_option("--bench-seconds", o->bench_seconds, "time per benchmark row (s)")
                           ->capture_default_str();
                       app.add_option("--bench-csv", o->bench_csv, "also write the benchmark table to FILE.csv (and its sidecar) or FILE.nc (netCDF-4, docs/data.md)");
                       app.footer(
                           "Input rows: R [m] >= 0 (distance from the iCOR to the centre of mass), alpha [rad];\n"
                           "the iCOR is at -R (cos alpha, sin alpha) in body axes (x' across the width, y' along\n"
                           "the length). Output: fx, fy [N] and mf [N m] for mu N = 1 N. Blank lines and lines\n"
                           "starting with # are ignored; an optional first line 'R,alpha' is a header.");
                       return [o] { return o->bench ? run_bench(*o) : run_rows(*o); };
                     }}};

// ---------------------------------------------------------------------------------------------
// Reproduce: Fig 3.9 (normalised force and moment vs R) and Figs 3.10-3.11 (maps over iCORs).

double mean_distance_rect(double a, double b) {
  const double d = std::hypot(a, b);
  return d / 3 + a * a / (6 * b) * std::log((b + d) / a) + b * b / (6 * a) * std::log((a + d) / b);
}

/// The friction wrench (mu N = 1, counter-clockwise) of the a x b contact at every point of
/// `plan` (keys R, alpha) through the sweep engine's friction task, on every core; in point order.
std::vector<FrictionWrench> wrenches_by_sweep(double a, double b, const sweep::Plan& plan) {
  const auto task = sweep::make_friction_task({{"a", a}, {"b", b}, {"muN", 1.0}, {"sense", 1.0}});
  const auto rows = sweep::evaluate_points(plan, *task, 0);
  const std::size_t ifx = sweep::column_index(plan, *task, "fx"), ify = sweep::column_index(plan, *task, "fy"),
                    imf = sweep::column_index(plan, *task, "mf");
  std::vector<FrictionWrench> out;
  out.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    if (sweep::row_failed(r))
      throw SolverError("friction sweep, point " + std::to_string(i) + ": " + r.back());
    out.push_back({sweep::cell_number(r[ifx]), sweep::cell_number(r[ify]), sweep::cell_number(r[imf])});
  }
  return out;
}

void fig3_9(ReproduceContext& ctx) {
  const double a = kBarA, b = kBarB, L = std::max(a, b);
  const std::vector<double> alphas = {0.0, kPi / 6, kPi / 4, kPi / 3, kPi / 2};
  const std::vector<std::string> names = {"0", "pi/6", "pi/4", "pi/3", "pi/2"};
  const int n = ctx.quick ? 61 : 601;
  Columns header = columns("fig3_9");
  for (std::size_t k = 0; k < alphas.size(); ++k) {
    header.push_back({"Ffn_alpha" + std::to_string(k), "1",
                      "normalised friction force |f|/(mu N) at iCOR direction alpha = " + names[k], "number",
                      {{"alpha", alphas[k]}}});
    header.push_back({"Mfn_alpha" + std::to_string(k), "1",
                      "normalised friction moment |m_f|/(mu N max(a, b)) at iCOR direction alpha = " + names[k],
                      "number", {{"alpha", alphas[k]}}});
  }
  const auto csv = ctx.out / "fig3_9_friction_vs_R.csv";
  CsvWriter w(csv, header);
  double worst_engine = 0.0, worst_cub_f = 0.0, worst_cub_m = 0.0;
  bool monotone = true;
  std::vector<double> prevF(alphas.size(), -1.0), prevM(alphas.size(), 1e300);
  std::vector<double> lastF(alphas.size()), lastM(alphas.size());
  // The grid R x alpha (alpha fastest) through the sweep engine; the F77 check beside it.
  std::vector<double> rhos;
  sweep::Axis axR{"R", {}}, axA{"alpha", {}};
  for (int i = 0; i < n; ++i) {
    rhos.push_back(std::pow(10.0, -3.0 + 6.0 * i / (n - 1)));
    axR.values.emplace_back(rhos.back() * L);
  }
  for (double al : alphas) axA.values.emplace_back(al);
  const auto wrench = wrenches_by_sweep(a, b, sweep::cartesian({axR, axA}));
  for (int i = 0; i < n; ++i) {
    const double rho = rhos[static_cast<std::size_t>(i)];
    const double R = rho * L;
    std::vector<double> row = {R, rho};
    for (std::size_t k = 0; k < alphas.size(); ++k) {
      const auto& c = wrench[static_cast<std::size_t>(i) * alphas.size() + k];
      double f[3];
      if (np_f77_rectangle_friction(a, b, 1.0, R, alphas[k], 1, f) != 0) throw SolverError("F77 RECTFR failed");
      const double Ffn = std::hypot(c.fx, c.fy), Mfn = std::fabs(c.mf) / L;
      worst_engine = std::max({worst_engine, std::fabs(std::hypot(f[0], f[1]) - Ffn),
                               std::fabs(std::fabs(f[2]) / L - Mfn) / std::max(Mfn, 1e-300)});
      if (alphas[k] == 0.0 && (Ffn < prevF[k] - 1e-15 || Mfn > prevM[k] + 1e-15)) monotone = false;
      prevF[k] = Ffn;
      prevM[k] = Mfn;
      lastF[k] = Ffn;
      lastM[k] = Mfn;
      if (i % (n / 10) == 0) {
        const auto q = cubature_friction_wrench_uniform(a, b, 1.0, R, alphas[k], 1, 1e-13);
        worst_cub_f = std::max(worst_cub_f, std::hypot(q.wrench.fx - c.fx, q.wrench.fy - c.fy));
        worst_cub_m = std::max(worst_cub_m, std::fabs(q.wrench.mf - c.mf) / L);
      }
      row.push_back(Ffn);
      row.push_back(Mfn);
    }
    w.row(row);
  }
  w.commit();
  ctx.produced(csv);
  const auto r0 = rectangle_friction_wrench(a, b, 1.0, 0.0, 0.0, 1);
  const double mfn0 = std::fabs(r0.mf) / L, mfn0_exact = mean_distance_rect(a, b) / L;
  if (plot::available()) {
    // A raw script (plot::render emits 'set key best', which gnuplot 5.4 rejects).
    std::ostringstream g;
    g << "set multiplot layout 1,2 title 'Fig 3.9: normalised friction force and moment vs iCOR distance "
         "(100 x 55 nm bar, uniform pressure)'\n";
    for (int panel = 0; panel < 2; ++panel) {
      g << "set grid\nset logscale x\nset format x '10^{%L}'\nset xlabel 'R / max(a,b)'\n"
        << (panel == 0 ? "set title 'F_{fn} = |f|/({/Symbol m}N)'\nset ylabel 'F_{fn}'\nset key bottom right\n"
                       : "set title 'M_{fn} = |m_f|/({/Symbol m}N max(a,b))'\nset ylabel 'M_{fn}'\nset key top right\n")
        << "plot ";
      for (std::size_t k = 0; k < alphas.size(); ++k)
        g << (k ? ", \\\n     " : "") << "'" << csv.string() << "' skip 1 using 2:" << (3 + 2 * k + panel)
          << " with lines lw 2 title '{/Symbol a} = " << names[k] << "'";
      g << "\n";
    }
    g << "unset multiplot\n";
    const auto png = ctx.out / "fig3_9_friction_vs_R.png";
    plot::render_script(g.str(), png, 1400, 600);
    ctx.produced(png);
  }
  auto& r = ctx.report;
  r << "\n## Fig 3.9: normalised friction force and moment vs R (docs/models.md §B)\n\n"
    << "Bar 100 x 55 nm (a = 27.5 nm, b = 50 nm), uniform pressure, R/max(a,b) from 1e-3 to 1e3 (log), "
    << "alpha = 0, pi/6, pi/4, pi/3, pi/2. The thesis prints the curves only (alpha = 0), no values; "
    << "we check its qualitative statements and the exact oracles.\n\n"
    << "| check | thesis | nanopush | holds |\n|---|---|---|---|\n"
    << "| R = 0: Ffn | 0 | " << std::hypot(r0.fx, r0.fy) << " | " << (std::hypot(r0.fx, r0.fy) == 0.0 ? "yes" : "NO")
    << " |\n"
    << "| R = 0: Mfn = <r>/max(a,b) | maximum | " << std::setprecision(15) << mfn0 << " (exact " << mfn0_exact
    << ") | " << (std::fabs(mfn0 - mfn0_exact) <= 1e-14 ? "yes" : "NO") << " |\n"
    << "| R = 1e3 max(a,b): Ffn (alpha = 0) | -> 1 | " << lastF[0] << " | " << (lastF[0] > 1 - 1e-6 ? "yes" : "NO")
    << " |\n"
    << "| R = 1e3 max(a,b): Mfn (alpha = 0) | -> 0 | " << lastM[0] << " | " << (lastM[0] < 1e-3 ? "yes" : "NO")
    << " |\n"
    << "| alpha = 0: Ffn increases, Mfn decreases with R | yes | " << (monotone ? "yes" : "no") << " | "
    << (monotone ? "yes" : "NO") << " |\n"
    << "| C++ vs F77 engine, max deviation (Ffn abs, Mfn rel) | - | " << worst_engine << " | "
    << (worst_engine <= 1e-13 ? "yes" : "NO") << " |\n"
    << "| closed form vs cubature (tol 1e-13): max abs df/muN, max abs dmf/(muN L) | - | " << worst_cub_f << ", "
    << worst_cub_m << " | " << (std::max(worst_cub_f, worst_cub_m) <= 1e-12 ? "yes" : "NO") << " |\n"
    << std::setprecision(6) << "\nOther alpha give curves of the same shape, as the thesis says; the moment's far "
    << "field tends to (a^2 sin^2 alpha + b^2 cos^2 alpha)/(3 R max(a,b)), so it depends on alpha.\n";
  if (std::hypot(r0.fx, r0.fy) != 0.0) ctx.failures.push_back("fig3_9: R = 0 force not zero");
  if (!(std::fabs(mfn0 - mfn0_exact) <= 1e-14)) ctx.failures.push_back("fig3_9: R = 0 moment != mean distance");
  if (!(lastF[0] > 1 - 1e-6) || !(lastM[0] < 1e-3)) ctx.failures.push_back("fig3_9: no translation limit");
  if (!monotone) ctx.failures.push_back("fig3_9: Ffn/Mfn not monotone at alpha = 0");
  if (!(worst_engine <= 1e-13)) ctx.failures.push_back("fig3_9: C++ and F77 differ by " + fmt(worst_engine));
  if (!(std::max(worst_cub_f, worst_cub_m) <= 1e-12)) ctx.failures.push_back("fig3_9: closed form vs cubature");
}

void fig3_10_11(ReproduceContext& ctx) {
  const double a = kBarA, b = kBarB, L = std::max(a, b);
  const int n = ctx.quick ? 41 : 201;
  const double xmax = 4 * a, ymax = 2 * b;  // iCOR window: on and around the contact
  const auto csv = ctx.out / "fig3_10_11_friction_maps.csv";
  double fmin = 1e300, fmax = -1e300, mmax = -1e300, worst_engine = 0.0;
  double mmax_cx = 0, mmax_cy = 0;
  {
    CsvWriter f(csv, columns("fig3_10_11"));
    // The iCOR grid as a list of points (R, alpha), evaluated by the sweep engine.
    sweep::Plan plan;
    plan.keys = {"R", "alpha"};
    for (int i = 0; i < n; ++i) {
      const double cx = xmax * (2 * i - (n - 1)) / (n - 1);
      for (int j = 0; j < n; ++j) {
        const double cy = ymax * (2 * j - (n - 1)) / (n - 1);
        plan.points.push_back({std::hypot(cx, cy), std::atan2(-cy, -cx)});
      }
    }
    const auto wrench = wrenches_by_sweep(a, b, plan);
    for (int i = 0; i < n; ++i) {
      const double cx = xmax * (2 * i - (n - 1)) / (n - 1);  // exactly 0 at the centre
      for (int j = 0; j < n; ++j) {
        const double cy = ymax * (2 * j - (n - 1)) / (n - 1);
        // iCOR at body point (cx, cy) = -R (cos alpha, sin alpha).
        const double R = std::hypot(cx, cy), alpha = std::atan2(-cy, -cx);
        const auto& c = wrench[static_cast<std::size_t>(i) * static_cast<std::size_t>(n) + static_cast<std::size_t>(j)];
        double w[3];
        if (np_f77_rectangle_friction(a, b, 1.0, R, alpha, 1, w) != 0) throw SolverError("F77 RECTFR failed");
        const double Ffn = std::hypot(c.fx, c.fy), Mfn = std::fabs(c.mf) / L;
        worst_engine = std::max({worst_engine, std::fabs(std::hypot(w[0], w[1]) - Ffn), std::fabs(std::fabs(w[2]) / L - Mfn)});
        fmin = std::min(fmin, Ffn);
        fmax = std::max(fmax, Ffn);
        if (Mfn > mmax) {
          mmax = Mfn;
          mmax_cx = cx;
          mmax_cy = cy;
        }
        f.row({cx * 1e9, cy * 1e9, R, alpha, Ffn, Mfn});
      }
      f.blank_line();  // gnuplot scan separator
    }
    f.commit();
  }
  ctx.produced(csv);
  if (plot::available()) {
    for (int k = 0; k < 2; ++k) {
      std::ostringstream g;
      const std::string col = k == 0 ? "5" : "6";
      g << "set title '" << (k == 0 ? "Fig 3.10: normalised friction force F_{fn} = |f|/({/Symbol m}N)"
                                    : "Fig 3.11: normalised friction moment M_{fn} = |m_f|/({/Symbol m}N max(a,b))")
        << " vs iCOR position (100 x 55 nm bar)'\n"
        << "set xlabel 'iCOR x'' (nm, across the width)'\nset ylabel 'iCOR y'' (nm, along the length)'\n"
        // viridis (perceptually uniform, readable in grey), not a rainbow that invents edges
        << "set size ratio -1\nset palette defined (0 '#440154', 1 '#482878', 2 '#3e4a89', 3 '#31688e', "
           "4 '#26828e', 5 '#1f9e89', 6 '#35b779', 7 '#6dcd59', 8 '#fde725')\nset cblabel '" << (k == 0 ? "F_{fn}" : "M_{fn}")
        << "'\n"
        << "set xrange [" << -xmax * 1e9 << ":" << xmax * 1e9 << "]\nset yrange [" << -ymax * 1e9 << ":"
        << ymax * 1e9 << "]\n"
        << "set object 1 rect from " << -a * 1e9 << "," << -b * 1e9 << " to " << a * 1e9 << "," << b * 1e9
        << " front fillstyle empty border lc rgb 'white' lw 2\n"
        << "set contour base\nset cntrparam levels 10\n"
        << "plot '" << csv.string() << "' skip 1 using 1:2:" << col << " with image notitle\n";
      const auto png = ctx.out / (k == 0 ? "fig3_10_force_map.png" : "fig3_11_moment_map.png");
      plot::render_script(g.str(), png, 800, 800);
      ctx.produced(png);
    }
  }
  const double mfn0 = mean_distance_rect(a, b) / L;
  auto& r = ctx.report;
  r << "\n## Figs 3.10-3.11: normalised force and moment over iCOR positions (docs/models.md §B)\n\n"
    << "iCOR on a " << n << " x " << n << " grid over x' in [-4a, 4a], y' in [-2b, 2b] (the contact is the white "
    << "rectangle). The thesis shows 3-D surfaces without values; its statements: the force is smallest with the "
    << "iCOR at the centre of pressure and grows towards the edges and beyond; the moment is largest at the centre "
    << "and decreases as the iCOR moves away.\n\n"
    << "| check | thesis | nanopush | holds |\n|---|---|---|---|\n"
    << std::setprecision(12) << "| min Ffn over the grid (at the centre) | minimum 0 | " << fmin << " | "
    << (fmin <= 1e-15 ? "yes" : "NO") << " |\n"
    << "| max Ffn over the grid (<= 1) | grows away from centre | " << fmax << " | " << (fmax <= 1.0 ? "yes" : "NO")
    << " |\n"
    << "| max Mfn over the grid, at the centre = <r>/max(a,b) = " << mfn0 << " | maximum at centre | " << mmax
    << " at (" << mmax_cx * 1e9 << ", " << mmax_cy * 1e9 << ") nm | "
    << (std::fabs(mmax - mfn0) <= 1e-14 && mmax_cx == 0.0 && mmax_cy == 0.0 ? "yes" : "NO") << " |\n"
    << "| C++ vs F77 engine, max deviation | - | " << worst_engine << " | " << (worst_engine <= 1e-13 ? "yes" : "NO")
    << " |\n"
    << std::setprecision(6);
  if (!(fmin <= 1e-15) || !(fmax <= 1.0)) ctx.failures.push_back("fig3_10: force map out of [0, 1] or min not 0");
  if (!(std::fabs(mmax - mfn0) <= 1e-14)) ctx.failures.push_back("fig3_11: moment maximum is not <r> at the centre");
  if (!(worst_engine <= 1e-13)) ctx.failures.push_back("fig3_10_11: C++ and F77 differ by " + fmt(worst_engine));
}

RegisterReproduce rep9{{"fig3_9_friction", "Fig 3.9: normalised friction force and moment vs R (nanobar)", 31, fig3_9}};
RegisterReproduce rep10{{"fig3_10_11_friction", "Figs 3.10-3.11: friction force and moment maps over iCOR positions",
                         32, fig3_10_11}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
