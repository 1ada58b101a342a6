// nanopush icor: the instantaneous centre of rotation (thesis chapters 4-5, docs/models.md D).
//   nanopush icor formulas     every principle over a sweep of yn (CSV)
//   nanopush icor roots        the constrained cubic (5.4) from all four solvers (CSV)
//   nanopush icor estimate-mu  friction coefficient from a push force and yn (Fig 4.4)
//                              or from an observed iCOR (Fig 4.5), with uncertainty
//   nanopush icor dynamic      the dynamic iCOR: rough-surface nanorod from rest (CSV)
//   nanopush icor rectangle    quasi-static iCOR of a finite 2a x L rectangle (CSV)
// The reproduce steps of chapters 4-5 are in repro_icor_thesis.cpp and repro_icor_beyond.cpp.
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
#include "cli_checks.hpp"
#include "columns.hpp"
#include "registry.hpp"
#include "icor_common.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

using namespace icor_cli;

// ---- push points, shared by the subcommands --------------------------------------------

/// A sweep of n push points from yn_min to yn_max (yn_max < 0: b), on the rod
/// (0 <= yn_min <= yn_max <= b = L/2); logarithmic with `log`.
std::vector<double> yn_sweep(double yn_min, double yn_max, int n, double b, bool log) {
  if (yn_max < 0.0) yn_max = b;
  require_range("--yn-min", yn_min, 0.0, b, "m");
  require_range("--yn-max", yn_max, yn_min, b, "m");
  return sweep(yn_min, yn_max, n, log);
}

/// The push points of roots and dynamic: the --yn values, then a sweep of --n points (yn_sweep);
/// at least one, each on the rod, as in every front end (Python cubic_roots, the C API).
template <class Options>
std::vector<double> push_points(const Options& o, double b, bool log) {
  std::vector<double> yns = o.yn;
  if (o.n > 0)
    for (double y : yn_sweep(o.yn_min, o.yn_max, o.n, b, log)) yns.push_back(y);
  if (yns.empty()) throw InputError("--yn", "(none)", "give --yn values or a sweep with --n");
  for (double y : yns) require_range("--yn", y, 0.0, b, "m; push point on the rod, at most b = L/2");
  return yns;
}

/// The options of push_points: --yn, --n, --yn-min, --yn-max.
template <class Options>
void add_push_point_options(CLI::App& app, Options& o) {
  app.add_option("--yn", o.yn, "push distances from the CM [m] (one or more)");
  app.add_option("--n", o.n, "also sweep this many push points from --yn-min to --yn-max")->check(count(0, kMaxCount));
  app.add_option("--yn-min", o.yn_min, "sweep start [m]")->capture_default_str();
  app.add_option("--yn-max", o.yn_max, "sweep end [m] (default b = L/2)");
}

// ---- nanopush icor formulas ------------------------------------------------------------

struct FormulasOptions {
  icor::Rod rod;
  double yn_min = 0.0, yn_max = -1.0;  // default: b
  int n = 60;
  double mu = 0.1;
  double force_ratio = 1.0;
  std::string out;
};

int run_formulas(FormulasOptions o) {
  o.rod.validate();
  const double L = o.rod.length, b = o.rod.half_length(), k2 = o.rod.gyration_squared(), W = o.rod.load();
  const std::vector<double> yns = yn_sweep(o.yn_min, o.yn_max, o.n, b, false);
  require_positive("--mu", o.mu);
  require_positive("--force-ratio", o.force_ratio, "F / (mu W)");
  const double F = o.force_ratio * o.mu * W;
  Table t(o.out, columns("icor_formulas"));
  for (double yn : yns) {
    const auto s = icor::solve_constrained_cubic(yn, L, k2, CubicMethod::Brent);
    const double Fmin = icor::minimum_force(o.mu, W, yn, L);
    std::optional<double> r47;
    if (F >= Fmin) r47 = icor::known_pressure(o.mu, W, yn, F, L);
    const double r413 = icor::unknown_pressure(yn, L);
    std::optional<double> f52;
    if (s.negative) f52 = icor::constrained_force(o.mu, W, *s.negative, yn, L, k2);
    t.row({csv_number(yn), csv_number(icor::experimental_fit(yn, L)), csv_number(icor::falvo(yn, L)),
           csv_number(icor::li(yn, L)), csv_number(r413), cell(r47), csv_number(Fmin),
           csv_number(icor::force_from_icor(o.mu, W, r413, L)), cell(s.negative), cell(s.positive), cell(f52),
           csv_number(icor::impulsive(yn, k2))});
  }
  t.write();
  if (!o.out.empty() && o.out != "-") std::cerr << "icor formulas: " << o.n << " rows -> " << o.out << "\n";
  return 0;
}

// ---- nanopush icor roots ---------------------------------------------------------------

struct RootsOptions {
  icor::Rod rod;
  std::vector<double> yn;
  double yn_min = 1e-15, yn_max = -1.0;
  int n = 0;
  bool log = false;
  std::string out;
};

int run_roots(RootsOptions o) {
  o.rod.validate();
  const double L = o.rod.length, k2 = o.rod.gyration_squared();
  const std::vector<double> yns = push_points(o, o.rod.half_length(), o.log);
  Table t(o.out, columns("icor_roots"));
  for (double yn : yns)
    for (const auto& s : all_solvers(L, k2)) {
      const auto sol = s.solve(yn);
      std::vector<std::string> r = {csv_number(yn), s.name.substr(0, s.name.find('_')),
                                    s.name.substr(s.name.find('_') + 1), std::to_string(sol.real_roots.size()),
                                    std::to_string(sol.complex_roots), std::to_string(sol.at_infinity)};
      for (std::size_t i = 0; i < 3; ++i)
        r.push_back(i < sol.real_roots.size() ? csv_number(sol.real_roots[i]) : std::string());
      r.push_back(cell(sol.negative));
      r.push_back(cell(sol.positive));
      r.push_back(csv_number(sol.max_residual));
      t.row(r);
    }
  t.write();
  return 0;
}

// ---- nanopush icor estimate-mu --------------------------------------------------------

struct MuOptions {
  icor::Rod rod;
  double force = -1.0, force_sigma = 0.0;
  std::optional<double> yn, icor_R;
  double yn_sigma = 0.0, icor_sigma = 0.0;
  double length_sigma = 0.0, hamaker_sigma = 0.0;
  std::string out;
};

int run_estimate_mu(const MuOptions& o) {
  o.rod.validate();
  if (!(o.force > 0.0)) throw InputError("--force", fmt(o.force), "the measured push force must be > 0 (N)");
  if (o.yn.has_value() == o.icor_R.has_value())
    throw InputError("--yn/--icor", o.yn ? "both given" : "neither given",
                     "give exactly one: --yn (push point, Fig 4.4) or --icor (observed iCOR distance, Fig 4.5)");
  const auto e = o.yn ? icor::estimate_mu_from_force(o.rod, {o.force, o.force_sigma}, {*o.yn, o.yn_sigma},
                                                     o.length_sigma, o.hamaker_sigma)
                      : icor::estimate_mu_from_icor(o.rod, {o.force, o.force_sigma}, {*o.icor_R, o.icor_sigma},
                                                    o.length_sigma, o.hamaker_sigma);
  std::ostringstream s;
  s << std::setprecision(6);
  s << "friction coefficient from " << (o.yn ? "the minimum push force at yn (eq 4.8, Fig 4.4)"
                                            : "the push force and the observed iCOR (eq 4.10, Fig 4.5)")
    << "\n";
  s << "  load W = m g + F_vdw = " << e.load << " N (m = " << o.rod.mass() << " kg, F_vdw = " << o.rod.vdw_force()
    << " N, H = " << o.rod.hamaker << " J)\n";
  s << "  mu = " << e.mu << " +- " << e.sigma << " (1 sigma, first-order propagation, inputs uncorrelated)\n";
  s << "  contributions (|d mu/d x| * sigma_x):\n";
  for (const auto& c : e.contributions)
    s << "    " << std::setw(3) << c.input << " = " << c.value << " +- " << c.sigma << ": " << std::fabs(c.derivative) * c.sigma
      << "\n";
  std::cout << s.str();
  if (!o.out.empty()) {
    Table t(o.out, columns("icor_estimate_mu"));
    t.row({"mu", csv_number(e.mu), csv_number(e.sigma), "", ""});
    t.row({"W", csv_number(e.load), "", "", ""});
    for (const auto& c : e.contributions)
      t.row({c.input, csv_number(c.value), csv_number(c.sigma), csv_number(c.derivative),
             csv_number(std::fabs(c.derivative) * c.sigma)});
    t.write();
  }
  return 0;
}

// ---- nanopush icor dynamic --------------------------------------------------------------

std::string finite_cell(double v) { return std::isfinite(v) ? csv_number(v) : std::string(); }

struct DynamicOptions {
  icor::Rod rod;
  std::vector<double> yn;
  double yn_min = 5e-9, yn_max = -1.0;  // default: b
  int n = 0;
  std::vector<double> force_ratio = {2.0};
  double t_end = 1e-10;
  int samples = 1;
  double mu = 0.1;
  double half_width = 0.0;
  std::string integrator = "automatic";
  double rtol = 1e-10;
  std::string out;
};

icor::DynamicIntegrator parse_integrator(const std::string& s) { return icor::parse_dynamic_integrator("--integrator", s); }

/// Output times: `samples` log-spaced from t_end/1000 to t_end (t_end alone for 1).
std::vector<double> dynamic_times(double t_end, int samples) {
  require_positive("--t-end", t_end, "s");
  if (samples < 1 || samples > 1000) throw InputError("--samples", std::to_string(samples), "must be in [1, 1000]");
  if (samples == 1) return {t_end};
  return sweep(1e-3 * t_end, t_end, samples, true);
}

int run_dynamic(DynamicOptions o) {
  o.rod.validate();
  const double b = o.rod.half_length(), k2 = o.rod.gyration_squared(), W = o.rod.load();
  require_positive("--mu", o.mu);
  require_nonnegative("--half-width", o.half_width, "m");
  const auto integ = parse_integrator(o.integrator);
  const std::vector<double> yns = push_points(o, b, false);
  if (o.force_ratio.empty()) throw InputError("--force-ratio", "(none)", "give at least one F/(mu W)");
  for (double r : o.force_ratio) require_positive("--force-ratio", r, "F / (mu W)");
  const auto times = dynamic_times(o.t_end, o.samples);
  const double a = o.half_width > 0.0 ? o.half_width : icor::rod_contact_half_width(o.rod);
  Table t(o.out, columns("icor_dynamic"));
  for (double yn : yns) {
    const auto qs = icor::rectangle_quasi_static(a, b, yn);
    for (double ratio : o.force_ratio) {
      icor::DynamicIcorSetup s;
      s.rod = o.rod;
      s.mu = o.mu;
      s.half_width = a;
      s.yn = yn;
      s.force = ratio * o.mu * W;
      s.times = times;
      s.rtol = o.rtol;
      s.integrator = integ;
      const auto r = icor::dynamic_icor(s);
      for (const auto& q : r.samples) {
        const std::string state = !q.moving ? "stuck" : (q.translation ? "translation" : "rotation");
        t.row({csv_number(yn), csv_number(ratio), csv_number(s.force), csv_number(q.t), state,
               q.moving ? finite_cell(q.R) : std::string(), q.moving ? finite_cell(q.axial) : std::string(),
               q.moving && !q.translation ? csv_number(q.offset) : std::string(), csv_number(q.theta),
               finite_cell(icor::impulsive(yn, k2)), finite_cell(qs.R), csv_number(icor::unknown_pressure(yn, o.rod.length)),
               csv_number(qs.force), csv_number(a), icor::to_string(r.integrator)});
      }
    }
  }
  t.write();
  if (!o.out.empty() && o.out != "-") std::cerr << "icor dynamic: -> " << o.out << "\n";
  return 0;
}

// ---- nanopush icor rectangle ------------------------------------------------------------

struct RectangleOptions {
  icor::Rod rod;
  std::vector<double> aspect = {1e-4, 0.1, 0.5, 1.0};
  double yn_min = 0.0, yn_max = -1.0;
  int n = 60;
  std::string out;
};

int run_rectangle(RectangleOptions o) {
  o.rod.validate();
  const double b = o.rod.half_length(), L = o.rod.length;
  const std::vector<double> yns = yn_sweep(o.yn_min, o.yn_max, o.n, b, false);
  if (o.aspect.empty()) throw InputError("--aspect", "(none)", "give at least one a/b");
  for (double ab : o.aspect) require_range("--aspect", ab, 1e-6, 1.0, "a/b");
  Table t(o.out, columns("icor_rectangle"));
  for (double ab : o.aspect)
    for (double yn : yns) {
      const auto q = icor::rectangle_quasi_static(ab * b, b, yn);
      const double r413 = icor::unknown_pressure(yn, L);
      t.row({csv_number(ab), csv_number(ab * b), csv_number(b), csv_number(yn), finite_cell(q.R), csv_number(q.alpha),
             csv_number(q.force), finite_cell(r413), csv_number(icor::minimum_force(1.0, 1.0, yn, L)),
             std::isfinite(q.R) ? csv_number(q.R / r413 - 1.0) : std::string(), q.converged ? "1" : "0",
             csv_number(q.residual)});
      if (!q.converged) std::cerr << "icor rectangle: warning: not converged at a/b = " << ab << ", yn = " << yn << "\n";
    }
  t.write();
  return 0;
}

/// An icor subcommand: its options object (the rod's options first, then `declare`'s), and
/// `run` called with it when the subcommand is the one given (stored in `action`).
template <class Options, class Run, class Declare>
void icor_subcommand(CLI::App& app, const std::shared_ptr<std::function<int()>>& action, const std::string& name,
                     const std::string& description, Run run, Declare declare) {
  CLI::App* sub = app.add_subcommand(name, description);
  auto o = std::make_shared<Options>();
  add_rod_options(*sub, o->rod);
  declare(*sub, *o);
  sub->callback([action, o, run] { *action = [o, run] { return run(*o); }; });
}

RegisterCommand reg{{"icor",
                     "Instantaneous centre of rotation of a pushed nanorod: formulas of ch. 4-5, the constrained "
                     "cubic (5.4) from four solvers, friction coefficient from measurements, the dynamic iCOR "
                     "and the finite rectangle",
                     40, [](CLI::App& app) -> std::function<int()> {
                       auto action = std::make_shared<std::function<int()>>();
                       app.require_subcommand(1);

                       icor_subcommand<FormulasOptions>(
                           app, action, "formulas",
                           "every iCOR principle over a sweep of yn (CSV, SI)",
                           run_formulas, [](CLI::App& f, FormulasOptions& fo) {
                             f.add_option("--yn-min", fo.yn_min, "first push distance from the CM [m]")->capture_default_str();
                             f.add_option("--yn-max", fo.yn_max, "last push distance [m] (default b = L/2)");
                             f.add_option("--n", fo.n, "number of push points")->check(count(1, kMaxCount))->capture_default_str();
                             f.add_option("--mu", fo.mu, "friction coefficient for 4.7, 4.8, 4.10, 5.2 [-]")->capture_default_str();
                             f.add_option("--force-ratio", fo.force_ratio, "push force for eq 4.7 as F/(mu W) [-]")
                                 ->capture_default_str();
                             f.add_option("--out", fo.out, "CSV file, or FILE.nc: netCDF-4 (default: standard output)");
                           });

                       icor_subcommand<RootsOptions>(
                           app, action, "roots",
                           "roots of the constrained cubic (5.4): Brent and "
                           "companion eigenvalues, C++ (Eigen) and FORTRAN 77 (LAPACK)",
                           run_roots, [](CLI::App& r, RootsOptions& ro) {
                             add_push_point_options(r, ro);
                             r.add_flag("--log", ro.log, "logarithmic sweep");
                             r.add_option("--out", ro.out, "CSV file, or FILE.nc: netCDF-4 (default: standard output)");
                           });

                       icor_subcommand<MuOptions>(
                           app, action, "estimate-mu",
                           "friction coefficient from a measured push force and its point yn (Fig 4.4) or from a push "
                           "force and an observed iCOR distance (Fig 4.5), with propagated uncertainty",
                           run_estimate_mu, [](CLI::App& m, MuOptions& mo) {
                             m.add_option("--force", mo.force, "measured push force F [N]")->check(positive())->required();
                             m.add_option("--force-sigma", mo.force_sigma, "standard uncertainty of F [N]")->check(non_negative())->capture_default_str();
                             m.add_option("--yn", mo.yn, "push point: distance from the CM along the rod [m] (Fig 4.4 map)");
                             m.add_option("--yn-sigma", mo.yn_sigma, "standard uncertainty of yn [m]")->check(non_negative())->capture_default_str();
                             m.add_option("--icor", mo.icor_R, "observed iCOR distance from the CM [m] (Fig 4.5 map)");
                             m.add_option("--icor-sigma", mo.icor_sigma, "standard uncertainty of the iCOR distance [m]")
                                 ->check(non_negative())->capture_default_str();
                             m.add_option("--length-sigma", mo.length_sigma, "standard uncertainty of L [m]")->check(non_negative())->capture_default_str();
                             m.add_option("--hamaker-sigma", mo.hamaker_sigma, "standard uncertainty of H [J]")
                                 ->check(non_negative())->capture_default_str();
                             m.add_option("--out", mo.out, "also write the estimate and its budget: CSV file, or FILE.nc: netCDF-4");
                           });

                       icor_subcommand<DynamicOptions>(
                           app, action, "dynamic",
                           "dynamic iCOR: the rough-surface nanorod (coulomb law) pushed from rest perpendicular to "
                           "its axis at yn, iCOR read off the velocities (thesis section 5.5, Fig 5.3)",
                           run_dynamic, [](CLI::App& d, DynamicOptions& dopt) {
                             add_push_point_options(d, dopt);
                             d.add_option("--force-ratio", dopt.force_ratio, "push magnitudes F/(mu W) [-] (one or more)")
                                 ->capture_default_str();
                             d.add_option("--t-end", dopt.t_end, "time of the reading [s] (thesis: 1e-10)")->capture_default_str();
                             d.add_option("--samples", dopt.samples,
                                           "readings per run, log-spaced from t-end/1000 to t-end (1: t-end only)")
                                 ->capture_default_str()
                                 ->check(count(1, 1000));
                             d.add_option("--mu", dopt.mu, "friction coefficient [-] (thesis: 0.1)")->capture_default_str();
                             d.add_option("--half-width", dopt.half_width,
                                           "contact strip half-width a [m]; 0 = Hertz line contact under W/L (2.78 nm)")
                                 ->capture_default_str();
                             d.add_option("--integrator", dopt.integrator,
                                           "automatic | bulirsch-stoer | cvode (automatic: CVODE below 1.09 F_min, else BS)")
                                 ->capture_default_str();
                             d.add_option("--rtol", dopt.rtol, "relative tolerance [-]")->capture_default_str();
                             d.add_option("--out", dopt.out, "CSV file, or FILE.nc: netCDF-4 (default: standard output)");
                           });

                       icor_subcommand<RectangleOptions>(
                           app, action, "rectangle",
                           "quasi-static iCOR and minimum force of a finite 2a x L rectangle "
                           "(closed-form Coulomb friction), beside eq 4.13",
                           run_rectangle, [](CLI::App& q, RectangleOptions& qo) {
                             q.add_option("--aspect", qo.aspect, "half-width over half-length a/b [-] (one or more, 1e-6..1)")
                                 ->capture_default_str();
                             q.add_option("--n", qo.n, "number of push points")->check(count(1, kMaxCount))->capture_default_str();
                             q.add_option("--yn-min", qo.yn_min, "first push distance from the CM [m]")->capture_default_str();
                             q.add_option("--yn-max", qo.yn_max, "last push distance [m] (default b = L/2)");
                             q.add_option("--out", qo.out, "CSV file, or FILE.nc: netCDF-4 (default: standard output)");
                           });

                       return [action] { return (*action) ? (*action)() : 0; };
                     }}};


}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
