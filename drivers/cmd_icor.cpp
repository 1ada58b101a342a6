// nanopush icor: the instantaneous centre of rotation (thesis chapters 4-5, models.md D).
//   nanopush icor formulas     every principle over a sweep of yn (CSV)
//   nanopush icor roots        the constrained cubic (5.4) from all four solvers (CSV)
//   nanopush icor estimate-mu  friction coefficient from a push force and yn (Fig 4.4)
//                              or from an observed iCOR (Fig 4.5), with uncertainty
//   nanopush icor dynamic      the dynamic iCOR: rough-surface nanorod from rest (CSV)
//   nanopush icor rectangle    quasi-static iCOR of a finite 2a x L rectangle (CSV)
// and the reproduce steps table5_1, icor_error_analysis, fig4_2 ... fig4_5, fig5_2, fig5_3,
// icor_rectangle.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "f77_icor.hpp"
#include "nanopush/error.hpp"
#include "nanopush/icor.hpp"
#include "nanopush/icor_dynamic.hpp"
#include "nanopush/io.hpp"
#include "nanopush/plot.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {

using icor::CubicMethod;
using icor::CubicSolution;

// ---- shared pieces -------------------------------------------------------------------

void add_rod_options(CLI::App& app, icor::Rod& rod) {
  app.add_option("--length", rod.length, "rod length L [m]")->capture_default_str();
  app.add_option("--radius", rod.radius, "rod radius [m]")->capture_default_str();
  app.add_option("--density", rod.density, "rod density [kg/m^3] (graphite 2267)")->capture_default_str();
  app.add_option("--hamaker", rod.hamaker,
                 "Hamaker constant H [J]; the thesis prints none for graphite, the default is an assumed "
                 "literature-order value (only absolute forces depend on it)")
      ->capture_default_str();
  app.add_option("--z0", rod.z0, "rod-plane separation z0 [m] (thesis: 0.2 nm)")->capture_default_str();
  app.add_option("--gravity", rod.gravity, "g [m/s^2]")->capture_default_str();
}

/// The four solvers of the cubic: {column name, solve(yn)}.
struct NamedSolver {
  std::string name;
  std::function<CubicSolution(double)> solve;
};
std::vector<NamedSolver> all_solvers(double L, double k2) {
  return {
      {"brent_cxx", [=](double yn) { return icor::solve_constrained_cubic(yn, L, k2, CubicMethod::Brent); }},
      {"eigen_cxx", [=](double yn) { return icor::solve_constrained_cubic(yn, L, k2, CubicMethod::Eigen); }},
      {"brent_f77", [=](double yn) { return f77::icor_cubic(yn, L, k2, f77::IcorCubicMethod::Brent); }},
      {"lapack_f77", [=](double yn) { return f77::icor_cubic(yn, L, k2, f77::IcorCubicMethod::Lapack); }},
  };
}

std::string cell(const std::optional<double>& v) { return v ? csv_number(*v) : std::string(); }

/// A CSV whose cells may be empty (a branch that does not exist): written atomically.
class Table {
 public:
  Table(const std::filesystem::path& path, std::vector<std::string> header) : path_(path), header_(std::move(header)) {}
  void row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  std::string text() const {
    std::ostringstream o;
    for (std::size_t i = 0; i < header_.size(); ++i) o << (i ? "," : "") << header_[i];
    o << "\n";
    for (const auto& r : rows_) {
      for (std::size_t i = 0; i < r.size(); ++i) o << (i ? "," : "") << r[i];
      o << "\n";
    }
    return o.str();
  }
  /// Write to the file (atomically), or to stdout when the path is empty or "-".
  void write() const {
    if (path_.empty() || path_ == "-") std::cout << text();
    else write_file_atomic(path_, text());
  }

 private:
  std::filesystem::path path_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

std::vector<double> sweep(double lo, double hi, int n, bool log) {
  if (n < 1) throw InputError("--n", std::to_string(n), "must be >= 1");
  if (log && !(lo > 0.0)) throw InputError("--yn-min", fmt(lo), "must be > 0 with --log");
  std::vector<double> v;
  for (int i = 0; i < n; ++i) {
    const double t = n == 1 ? 0.0 : static_cast<double>(i) / (n - 1);
    v.push_back(log ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t);
  }
  if (n > 1) v.back() = hi;
  return v;
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
  if (o.yn_max < 0.0) o.yn_max = b;
  require_range("--yn-min", o.yn_min, 0.0, b, "m");
  require_range("--yn-max", o.yn_max, o.yn_min, b, "m");
  require_positive("--mu", o.mu);
  require_positive("--force-ratio", o.force_ratio, "F / (mu W)");
  const double F = o.force_ratio * o.mu * W;
  Table t(o.out, {"yn", "R_4_1", "R_4_2", "R_4_3", "R_4_13", "R_4_7", "F_min_4_8", "F_4_10", "R_5_4_negative",
                  "R_5_4_positive", "F_5_2_negative", "R_5_5"});
  for (double yn : sweep(o.yn_min, o.yn_max, o.n, false)) {
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
  std::vector<double> yns = o.yn;
  if (o.n > 0) {
    if (o.yn_max < 0.0) o.yn_max = o.rod.half_length();
    require_nonnegative("--yn-min", o.yn_min, "m");
    require_range("--yn-max", o.yn_max, o.yn_min, 1e300, "m");
    for (double y : sweep(o.yn_min, o.yn_max, o.n, o.log)) yns.push_back(y);
  }
  if (yns.empty()) throw InputError("--yn", "(none)", "give --yn values or a sweep with --n");
  for (double y : yns) require_nonnegative("--yn", y, "m");
  Table t(o.out, {"yn", "solver", "language", "n_real", "n_complex", "n_infinite", "root_1", "root_2", "root_3",
                  "negative_branch", "positive_branch", "max_relative_residual"});
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
  if (o.force < 0.0) throw InputError("--force", "(missing)", "the measured push force is required (N)");
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
    Table t(o.out, {"input", "value", "sigma", "dmu_dinput", "contribution"});
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

icor::DynamicIntegrator parse_integrator(const std::string& s) {
  if (s == "automatic") return icor::DynamicIntegrator::automatic;
  if (s == "bulirsch-stoer") return icor::DynamicIntegrator::bulirsch_stoer;
  if (s == "cvode") return icor::DynamicIntegrator::cvode;
  throw InputError("--integrator", s, "must be automatic, bulirsch-stoer or cvode");
}

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
  std::vector<double> yns = o.yn;
  if (o.n > 0) {
    if (o.yn_max < 0.0) o.yn_max = b;
    require_range("--yn-min", o.yn_min, 0.0, b, "m");
    require_range("--yn-max", o.yn_max, o.yn_min, b, "m");
    for (double y : sweep(o.yn_min, o.yn_max, o.n, false)) yns.push_back(y);
  }
  if (yns.empty()) throw InputError("--yn", "(none)", "give --yn values or a sweep with --n");
  for (double y : yns) require_range("--yn", y, 0.0, b, "m; push point on the rod, at most b = L/2");
  if (o.force_ratio.empty()) throw InputError("--force-ratio", "(none)", "give at least one F/(mu W)");
  for (double r : o.force_ratio) require_positive("--force-ratio", r, "F / (mu W)");
  const auto times = dynamic_times(o.t_end, o.samples);
  const double a = o.half_width > 0.0 ? o.half_width : icor::rod_contact_half_width(o.rod);
  Table t(o.out, {"yn", "force_ratio", "force", "t", "state", "R", "R_axial", "offset", "theta", "R_impulsive_5_5",
                  "R_quasi_static_rectangle", "R_4_13", "F_min_rectangle_ratio", "half_width", "integrator"});
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
  if (o.yn_max < 0.0) o.yn_max = b;
  require_range("--yn-min", o.yn_min, 0.0, b, "m");
  require_range("--yn-max", o.yn_max, o.yn_min, b, "m");
  if (o.aspect.empty()) throw InputError("--aspect", "(none)", "give at least one a/b");
  for (double ab : o.aspect) require_range("--aspect", ab, 1e-6, 1.0, "a/b");
  Table t(o.out, {"aspect", "a", "b", "yn", "R", "alpha", "F_min_ratio", "R_4_13", "F_min_4_8_ratio",
                  "relative_deviation_R", "converged", "residual"});
  for (double ab : o.aspect)
    for (double yn : sweep(o.yn_min, o.yn_max, o.n, false)) {
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

RegisterCommand reg{{"icor",
                     "Instantaneous centre of rotation of a pushed nanorod: formulas of ch. 4-5, the constrained "
                     "cubic (5.4) from four solvers, friction coefficient from measurements, the dynamic iCOR "
                     "and the finite rectangle",
                     40, [](CLI::App& app) -> std::function<int()> {
                       auto action = std::make_shared<std::function<int()>>();
                       app.require_subcommand(1);

                       auto* f = app.add_subcommand("formulas", "every iCOR principle over a sweep of yn (CSV, SI)");
                       auto fo = std::make_shared<FormulasOptions>();
                       add_rod_options(*f, fo->rod);
                       f->add_option("--yn-min", fo->yn_min, "first push distance from the CM [m]")->capture_default_str();
                       f->add_option("--yn-max", fo->yn_max, "last push distance [m] (default b = L/2)");
                       f->add_option("--n", fo->n, "number of push points")->capture_default_str();
                       f->add_option("--mu", fo->mu, "friction coefficient for 4.7, 4.8, 4.10, 5.2 [-]")->capture_default_str();
                       f->add_option("--force-ratio", fo->force_ratio, "push force for eq 4.7 as F/(mu W) [-]")
                           ->capture_default_str();
                       f->add_option("--out", fo->out, "CSV file (default: standard output)");
                       f->callback([action, fo] { *action = [fo] { return run_formulas(*fo); }; });

                       auto* r = app.add_subcommand("roots", "roots of the constrained cubic (5.4): Brent and "
                                                             "companion eigenvalues, C++ (Eigen) and FORTRAN 77 (LAPACK)");
                       auto ro = std::make_shared<RootsOptions>();
                       add_rod_options(*r, ro->rod);
                       r->add_option("--yn", ro->yn, "push distances from the CM [m] (one or more)");
                       r->add_option("--n", ro->n, "also sweep this many push points from --yn-min to --yn-max");
                       r->add_option("--yn-min", ro->yn_min, "sweep start [m]")->capture_default_str();
                       r->add_option("--yn-max", ro->yn_max, "sweep end [m] (default b = L/2)");
                       r->add_flag("--log", ro->log, "logarithmic sweep");
                       r->add_option("--out", ro->out, "CSV file (default: standard output)");
                       r->callback([action, ro] { *action = [ro] { return run_roots(*ro); }; });

                       auto* m = app.add_subcommand(
                           "estimate-mu",
                           "friction coefficient from a measured push force and its point yn (Fig 4.4) or from a push "
                           "force and an observed iCOR distance (Fig 4.5), with propagated uncertainty");
                       auto mo = std::make_shared<MuOptions>();
                       add_rod_options(*m, mo->rod);
                       m->add_option("--force", mo->force, "measured push force F [N]")->required();
                       m->add_option("--force-sigma", mo->force_sigma, "standard uncertainty of F [N]")->capture_default_str();
                       m->add_option("--yn", mo->yn, "push point: distance from the CM along the rod [m] (Fig 4.4 map)");
                       m->add_option("--yn-sigma", mo->yn_sigma, "standard uncertainty of yn [m]")->capture_default_str();
                       m->add_option("--icor", mo->icor_R, "observed iCOR distance from the CM [m] (Fig 4.5 map)");
                       m->add_option("--icor-sigma", mo->icor_sigma, "standard uncertainty of the iCOR distance [m]")
                           ->capture_default_str();
                       m->add_option("--length-sigma", mo->length_sigma, "standard uncertainty of L [m]")->capture_default_str();
                       m->add_option("--hamaker-sigma", mo->hamaker_sigma, "standard uncertainty of H [J]")
                           ->capture_default_str();
                       m->add_option("--out", mo->out, "also write the estimate and its budget as CSV");
                       m->callback([action, mo] { *action = [mo] { return run_estimate_mu(*mo); }; });

                       auto* d = app.add_subcommand(
                           "dynamic",
                           "dynamic iCOR: the rough-surface nanorod (coulomb law) pushed from rest perpendicular to "
                           "its axis at yn, iCOR read off the velocities (thesis section 5.5, Fig 5.3)");
                       auto dopt = std::make_shared<DynamicOptions>();
                       add_rod_options(*d, dopt->rod);
                       d->add_option("--yn", dopt->yn, "push distances from the CM [m] (one or more)");
                       d->add_option("--n", dopt->n, "also sweep this many push points from --yn-min to --yn-max");
                       d->add_option("--yn-min", dopt->yn_min, "sweep start [m]")->capture_default_str();
                       d->add_option("--yn-max", dopt->yn_max, "sweep end [m] (default b = L/2)");
                       d->add_option("--force-ratio", dopt->force_ratio, "push magnitudes F/(mu W) [-] (one or more)")
                           ->capture_default_str();
                       d->add_option("--t-end", dopt->t_end, "time of the reading [s] (thesis: 1e-10)")->capture_default_str();
                       d->add_option("--samples", dopt->samples,
                                     "readings per run, log-spaced from t-end/1000 to t-end (1: t-end only)")
                           ->capture_default_str();
                       d->add_option("--mu", dopt->mu, "friction coefficient [-] (thesis: 0.1)")->capture_default_str();
                       d->add_option("--half-width", dopt->half_width,
                                     "contact strip half-width a [m]; 0 = Hertz line contact under W/L (2.78 nm)")
                           ->capture_default_str();
                       d->add_option("--integrator", dopt->integrator,
                                     "automatic | bulirsch-stoer | cvode (automatic: CVODE below 1.09 F_min, else BS)")
                           ->capture_default_str();
                       d->add_option("--rtol", dopt->rtol, "relative tolerance [-]")->capture_default_str();
                       d->add_option("--out", dopt->out, "CSV file (default: standard output)");
                       d->callback([action, dopt] { *action = [dopt] { return run_dynamic(*dopt); }; });

                       auto* q = app.add_subcommand("rectangle",
                                                    "quasi-static iCOR and minimum force of a finite 2a x L rectangle "
                                                    "(closed-form Coulomb friction), beside eq 4.13");
                       auto qo = std::make_shared<RectangleOptions>();
                       add_rod_options(*q, qo->rod);
                       q->add_option("--aspect", qo->aspect, "half-width over half-length a/b [-] (one or more, 1e-6..1)")
                           ->capture_default_str();
                       q->add_option("--n", qo->n, "number of push points")->capture_default_str();
                       q->add_option("--yn-min", qo->yn_min, "first push distance from the CM [m]")->capture_default_str();
                       q->add_option("--yn-max", qo->yn_max, "last push distance [m] (default b = L/2)");
                       q->add_option("--out", qo->out, "CSV file (default: standard output)");
                       q->callback([action, qo] { *action = [qo] { return run_rectangle(*qo); }; });

                       return [action] { return (*action) ? (*action)() : 0; };
                     }}};

// ---- reproduce steps -------------------------------------------------------------------

void check(ReproduceContext& ctx, bool ok, const std::string& what) {
  if (!ok) ctx.failures.push_back(what);
}

/// Draw a one-panel figure. (plot::render emits "set key best", which Debian's gnuplot
/// rejects; until the shared plot.cpp is fixed we write the script body ourselves and use
/// plot::render_script, which keeps the same atomic-output guarantees.)
std::string gp_quote(const std::string& s) {
  std::string r = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    r += c;
  }
  return r + "\"";
}

void render_if_possible(ReproduceContext& ctx, const plot::Figure& fig, const std::filesystem::path& png) {
  if (!plot::available()) {
    ctx.report << "\n(gnuplot not found: " << png.filename().string() << " not drawn)\n";
    return;
  }
  std::ostringstream b;
  for (const auto& p : fig.panels) {
    b << "set grid\nset key outside right top box\n";
    if (p.logy) b << "set format y \"10^{%L}\"\n";
    b << "set title " << gp_quote(p.title.empty() ? fig.title : p.title) << "\n";
    b << "set xlabel " << gp_quote(p.xlabel) << "\nset ylabel " << gp_quote(p.ylabel) << "\n";
    if (p.logx) b << "set logscale x\n";
    if (p.logy) b << "set logscale y\n";
    if (!p.extra.empty()) b << p.extra << "\n";
    b << "plot ";
    for (std::size_t i = 0; i < p.series.size(); ++i) {
      const auto& s = p.series[i];
      b << (i ? ", \\\n     " : "") << gp_quote(s.csv.string()) << " every ::1 using " << s.x << ":" << s.y
        << " with " << s.style << " title " << gp_quote(s.title);
    }
    b << "\n";
  }
  plot::render_script(b.str(), png, fig.width, fig.height);
  ctx.produced(png);
  ctx.produced(std::filesystem::path(png).replace_extension(".gp"));
}

void step_table5_1(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double L = rod.length, k2 = rod.gyration_squared();
  const auto solvers = all_solvers(L, k2);
  std::vector<std::string> header = {"yn", "thesis"};
  for (const auto& s : solvers) {
    header.push_back(s.name + "_negative");
    header.push_back(s.name + "_positive");
  }
  for (const auto& s : solvers) header.push_back("deviation_" + s.name);
  header.push_back("printed_digits_match");
  header.push_back("max_relative_spread");
  const auto path = ctx.out / "table5_1.csv";
  Table t(path, header);
  ctx.report << "\n## Table 5.1: iCOR from the constrained cubic (5.4), nanorod L = 590 nm\n\n"
             << "Signed roots of 2 yn R^3 - 3 k^2 R^2 + k^2 (b^2 - 2 k^2) = 0 (k^2 = I/m = L^2/12) from four solvers:\n"
             << "Brent and Eigen companion eigenvalues in C++, Brent and LAPACK DGEEV companion eigenvalues in\n"
             << "FORTRAN 77. The thesis prints |R| of the negative root (models.md: the far side of the CM); `deviation` is\n"
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
  Table t(path, {"equation", "solver", "n", "yn_first", "yn_last", "yn_step", "mean_R_nm", "sample_std_nm",
                 "population_std_nm", "thesis_std_nm", "truncated_4dp", "rounded_4dp", "deviation_nm"});
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

void step_fig4_2(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double L = rod.length, b = rod.half_length();
  const int n = ctx.quick ? 30 : 296;
  const auto csv = ctx.out / "fig4_2.csv";
  CsvWriter w(csv, {"yn", "R_4_1_experimental_fit", "R_4_2_falvo", "R_4_3_li", "R_4_13_unknown_pressure"});
  double worst = 0.0;
  for (double yn : sweep(0.0, b, n, false)) {
    const double r = icor::unknown_pressure(yn, L);
    worst = std::max({worst, std::fabs(icor::falvo(yn, L) - r) / r, std::fabs(icor::li(yn, L) - r) / r});
    w.row({yn, icor::experimental_fit(yn, L), icor::falvo(yn, L), icor::li(yn, L), r});
  }
  w.commit();
  ctx.produced(csv);
  check(ctx, worst <= 1e-14, "fig4_2: eqs 4.2/4.3 differ from 4.13 by " + fmt(worst));
  plot::Figure fig;
  fig.title = "Fig 4.2: quasi-static iCOR, nanorod L = 590 nm";
  plot::Panel p{"", "push point yn [nm]", "iCOR distance from the CM, R [nm]", false, false, "", {}};
  p.series = {{csv, "($1*1e9)", "($2*1e9)", "eq 4.1 experimental fit", "lines lw 2"},
              {csv, "($1*1e9)", "($3*1e9)", "eq 4.2 Falvo et al.", "lines lw 4"},
              {csv, "($1*1e9)", "($4*1e9)", "eq 4.3 Li et al.", "lines lw 2 dt 2"},
              {csv, "($1*1e9)", "($5*1e9)", "eq 4.13 unknown pressure", "points pt 6 ps 0.6"}};
  fig.panels.push_back(p);
  render_if_possible(ctx, fig, ctx.out / "fig4_2.png");
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

void step_fig4_3(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double L = rod.length, b = rod.half_length(), W = rod.load();
  const int n = ctx.quick ? 30 : 296;
  const double F = 0.15 * W;  // one push force for the whole family: F >= mu W >= F_min for mu <= 0.15
  const auto csv = ctx.out / "fig4_3.csv";
  std::vector<std::string> h = {"yn"};
  for (double mu : kMuFamily43) h.push_back("R_4_7_" + mu_name(mu));
  CsvWriter w(csv, h);
  for (double yn : sweep(0.0, b, n, false)) {
    std::vector<double> r = {yn};
    for (double mu : kMuFamily43) r.push_back(icor::known_pressure(mu, W, yn, F, L));
    w.row(r);
  }
  w.commit();
  ctx.produced(csv);
  plot::Figure fig;
  fig.title = "Fig 4.3: iCOR for known pressure (eq 4.7), F = 0.15 W";
  plot::Panel p{"", "push point yn [nm]", "R [nm]", false, true, "", {}};
  for (std::size_t i = 0; i < kMuFamily43.size(); ++i)
    p.series.push_back({csv, "($1*1e9)", "($" + std::to_string(i + 2) + "*1e9)", mu_name(kMuFamily43[i]), "lines lw 2"});
  fig.panels.push_back(p);
  render_if_possible(ctx, fig, ctx.out / "fig4_3.png");
  ctx.report << "\n## Fig 4.3: iCOR for a known (uniform) pressure, eq 4.7\n\n"
             << "The thesis does not print the push force used; we hold F = 0.15 W fixed (W = m g + F_vdw = "
             << std::setprecision(4) << W << " N), which starts motion for every mu <= 0.15. With F = mu W (the\n"
             << "thesis' 'F ~ mu (m g + F_vdw)') eq 4.7 gives R = b + sqrt(2 b yn) for every mu: one curve.\n";
}

void step_fig4_4(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double L = rod.length, b = rod.half_length(), W = rod.load();
  const int n = ctx.quick ? 30 : 296;
  const auto csv = ctx.out / "fig4_4.csv";
  std::vector<std::string> h = {"yn"};
  for (double mu : kMuFamily44) h.push_back("F_min_4_8_" + mu_name(mu));
  CsvWriter w(csv, h);
  for (double yn : sweep(0.0, b, n, false)) {
    std::vector<double> r = {yn};
    for (double mu : kMuFamily44) r.push_back(icor::minimum_force(mu, W, yn, L));
    w.row(r);
  }
  w.commit();
  ctx.produced(csv);
  plot::Figure fig;
  fig.title = "Fig 4.4: minimum push force (eq 4.8) vs push point";
  plot::Panel p{"", "push point yn [nm]", "F_min [N]", false, true, "", {}};
  for (std::size_t i = 0; i < kMuFamily44.size(); ++i)
    p.series.push_back({csv, "($1*1e9)", "($" + std::to_string(i + 2) + ")", mu_name(kMuFamily44[i]), "lines lw 2"});
  fig.panels.push_back(p);
  render_if_possible(ctx, fig, ctx.out / "fig4_4.png");
  ctx.report << "\n## Fig 4.4: minimum push force, eq 4.8 (the map behind `nanopush icor estimate-mu --yn`)\n\n"
             << "F_min / (mu W) falls from 1 at yn = 0 to sqrt(2) - 1 at the rod end. Absolute forces scale with the\n"
             << "assumed Hamaker constant H = " << rod.hamaker << " J (the thesis prints none for graphite).\n";
}

void step_fig4_5(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double L = rod.length, b = rod.half_length(), W = rod.load();
  const int n = ctx.quick ? 30 : 296;
  const auto csv = ctx.out / "fig4_5.csv";
  std::vector<std::string> h = {"yn", "R_4_13"};
  for (double mu : kMuFamily44) h.push_back("F_4_10_" + mu_name(mu));
  CsvWriter w(csv, h);
  for (double yn : sweep(0.0, b, n, false)) {
    const double R = icor::unknown_pressure(yn, L);
    std::vector<double> r = {yn, R};
    for (double mu : kMuFamily44) r.push_back(icor::force_from_icor(mu, W, R, L));
    w.row(r);
  }
  w.commit();
  ctx.produced(csv);
  plot::Figure fig;
  fig.title = "Fig 4.5: push force (eq 4.10) vs quasi-static iCOR";
  plot::Panel p{"", "iCOR distance R [nm]", "F [N]", false, true, "", {}};
  for (std::size_t i = 0; i < kMuFamily44.size(); ++i)
    p.series.push_back({csv, "($2*1e9)", "($" + std::to_string(i + 3) + ")", mu_name(kMuFamily44[i]), "lines lw 2"});
  fig.panels.push_back(p);
  render_if_possible(ctx, fig, ctx.out / "fig4_5.png");
  ctx.report << "\n## Fig 4.5: push force against the iCOR, eq 4.10 (the map behind `estimate-mu --icor`)\n\n"
             << "R runs from (sqrt(2) - 1) b = " << std::setprecision(4) << (std::sqrt(2.0) - 1.0) * b * 1e9
             << " nm (push at the rod end; the thesis reads ~118 nm) to b = " << b * 1e9 << " nm (push at the CM).\n";
}

void step_fig5_2(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double L = rod.length, b = rod.half_length(), k2 = rod.gyration_squared();
  const int n = ctx.quick ? 30 : 296;
  const auto csv = ctx.out / "fig5_2.csv";
  Table t(csv, {"yn", "R_4_13", "R_5_4_negative", "R_5_4_positive", "far_side_5_4", "near_side_5_4"});
  for (double yn : sweep(0.0, b, n, false)) {
    const auto s = icor::solve_constrained_cubic(yn, L, k2, CubicMethod::Eigen);
    std::optional<double> far, near;
    if (s.negative) far = -*s.negative;
    if (s.positive) near = -*s.positive;
    t.row({csv_number(yn), csv_number(icor::unknown_pressure(yn, L)), cell(s.negative), cell(s.positive), cell(far),
           cell(near)});
  }
  t.write();
  ctx.produced(csv);
  // Bifurcation points at yn = 0.
  const auto pts = ctx.out / "fig5_2_bifurcation.csv";
  {
    const double r0 = std::sqrt((b * b - 2.0 * k2) / 3.0);
    CsvWriter w(pts, {"yn", "R"});
    w.row({0.0, r0});
    w.row({0.0, -r0});
    w.commit();
    ctx.produced(pts);
  }
  plot::Figure fig;
  fig.title = "Fig 5.2: quasi-static iCOR with (5.4) and without (4.13) the tangential constraint";
  plot::Panel p{"", "push point yn [nm]", "iCOR distance from the CM [nm] (> 0: far side from the push)", false, false,
                "set yrange [-300:320]", {}};
  p.series = {{csv, "($1*1e9)", "($5*1e9)", "eq 5.4, Table 5.1 branch", "lines lw 2"},
              {csv, "($1*1e9)", "($6*1e9)", "eq 5.4, other branch (yn < b/sqrt 3)", "lines lw 2 dt 3"},
              {csv, "($1*1e9)", "($2*1e9)", "eq 4.13", "lines lw 2 dt 2"},
              {pts, "($1*1e9)", "($2*1e9)", "bifurcation (yn = 0)", "points pt 4 ps 2"}};
  fig.panels.push_back(p);
  render_if_possible(ctx, fig, ctx.out / "fig5_2.png");
  ctx.report << "\n## Fig 5.2: constrained (5.4) against unconstrained (4.13) quasi-static iCOR\n\n"
             << "Plotted with R > 0 on the far side of the CM from the push (the sign of chapter 4): the Table 5.1\n"
             << "branch of (5.4) is |R_negative|, its other branch -R_positive. At yn = 0 the two branches meet the\n"
             << "axis at +-b/3 = +-" << std::setprecision(5) << b / 3.0 * 1e9 << " nm (the bifurcation squares).\n"
             << "(Side of the CM as models.md section D reads the cubic's signs; see docs/errata.md, iCOR item 5.)\n"
             << "Fig 5.3 (dynamic iCOR) is the step fig5_3.\n";
}


// ---- Fig 5.3: quasi-static, dynamic and impulsive iCOR --------------------------------

const std::vector<double> kDynamicRatios = {1.1, 2.0, 5.0, 20.0};

std::string ratio_name(double r) {
  std::ostringstream s;
  s << r;
  return s.str();
}

void step_fig5_3(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double L = rod.length, b = rod.half_length(), k2 = rod.gyration_squared(), W = rod.load(), mu = 0.1;
  const double muW = mu * W, a = icor::rod_contact_half_width(rod);
  auto dyn = [&](double yn, double force, std::vector<double> times) {
    icor::DynamicIcorSetup s;
    s.rod = rod;
    s.mu = mu;
    s.half_width = a;
    s.yn = yn;
    s.force = force;
    s.times = std::move(times);
    return icor::dynamic_icor(s);
  };
  const int n = ctx.quick ? 8 : 59;
  const auto csv = ctx.out / "fig5_3.csv";
  std::vector<std::string> h = {"yn", "R_impulsive_5_5", "R_4_13", "R_5_4_table_branch", "R_quasi_static_rectangle"};
  for (double r : kDynamicRatios) h.push_back("R_dynamic_F=" + ratio_name(r) + "muW");
  for (double r : kDynamicRatios) h.push_back("theta_F=" + ratio_name(r) + "muW");
  Table t(csv, h);
  int between_fail = 0, between_total = 0;
  std::vector<double> yns = sweep(5e-9, b, n, false);
  for (double yn : yns) {
    const double imp = icor::impulsive(yn, k2), qs = icor::rectangle_quasi_static(a, b, yn).R;
    const auto c = icor::solve_constrained_cubic(yn, L, k2, CubicMethod::Eigen);
    std::vector<std::string> row = {csv_number(yn), csv_number(imp), csv_number(icor::unknown_pressure(yn, L)),
                                    c.negative ? csv_number(-*c.negative) : std::string(), csv_number(qs)};
    std::vector<std::string> thetas;
    double prev = qs;
    for (double r : kDynamicRatios) {
      const auto run = dyn(yn, r * muW, {1e-10});
      const auto& q = run.samples.at(0);
      row.push_back(q.moving && !q.translation ? csv_number(q.axial) : std::string());
      thetas.push_back(csv_number(q.theta));
      // Small rotation by 1e-10 s: between quasi-static and impulsive, monotone in F -- away from
      // their crossing (yn = b/sqrt 3), where the rod's rotation (second order in theta) is larger
      // than the interval itself.
      if (r <= 5.0 && std::fabs(imp - qs) >= 0.05 * qs) {
        ++between_total;
        const bool ok = q.moving && (q.axial - prev) * (imp - qs) > 0.0 && (imp - q.axial) * (imp - qs) > 0.0;
        if (!ok) ++between_fail;
        prev = q.axial;
      }
    }
    row.insert(row.end(), thetas.begin(), thetas.end());
    t.row(row);
  }
  t.write();
  ctx.produced(csv);
  check(ctx, between_fail == 0,
        "fig5_3: the dynamic iCOR (F/(mu W) = 1.1, 2, 5) left the interval quasi-static..impulsive at " +
            std::to_string(between_fail) + " points");

  // The two limits, read along the way.
  const auto lim = ctx.out / "fig5_3_limits.csv";
  Table tl(lim, {"limit", "yn", "parameter", "t", "R", "reference", "relative_distance", "integrator"});
  struct LimitRow {
    double yn, p, R, ref, d;
  };
  std::vector<LimitRow> imp_rows, qs_rows;
  bool imp_ok = true, qs_ok = true, stuck_ok = true;
  for (double yn : {50e-9, 150e-9, 250e-9}) {
    const double imp = icor::impulsive(yn, k2);
    double prev = 1e300;
    for (double r : {2.0, 5.0, 20.0, 100.0, 1000.0}) {
      const double tt = 2e-10 / r;  // fixed impulse F t = 2 mu W x 1e-10 s
      const auto run = dyn(yn, r * muW, {tt});
      const double R = run.samples.at(0).axial, d = std::fabs(R / imp - 1.0);
      imp_ok = imp_ok && d < prev && d <= 1.5 / r;
      prev = d;
      imp_rows.push_back({yn, r, R, imp, d});
      tl.row({"impulsive (fixed impulse)", csv_number(yn), csv_number(r), csv_number(tt), csv_number(R), csv_number(imp),
              csv_number(d), icor::to_string(run.integrator)});
    }
    const auto qs = icor::rectangle_quasi_static(a, b, yn);
    prev = 1e300;
    for (double e : {1e-1, 1e-2, 1e-3, 1e-4}) {
      const auto run = dyn(yn, (1.0 + e) * qs.force * muW, {1e-10});
      const double R = run.samples.at(0).axial, d = std::fabs(R / qs.R - 1.0);
      qs_ok = qs_ok && run.samples.at(0).moving && d < prev && d <= 0.5 * e;
      prev = d;
      qs_rows.push_back({yn, e, R, qs.R, d});
      tl.row({"quasi-static (F -> F_min)", csv_number(yn), csv_number(e), csv_number(1e-10), csv_number(R),
              csv_number(qs.R), csv_number(d), icor::to_string(run.integrator)});
    }
    const auto below = dyn(yn, 0.999 * qs.force * muW, {1e-10});
    stuck_ok = stuck_ok && below.stuck && !below.samples.at(0).moving;
    tl.row({"no motion (F = 0.999 F_min)", csv_number(yn), csv_number(-1e-3), csv_number(1e-10), "", csv_number(qs.R), "",
            icor::to_string(below.integrator)});
  }
  tl.write();
  ctx.produced(lim);
  check(ctx, imp_ok, "fig5_3: the dynamic iCOR does not approach the impulsive one monotonically (<= 1.5 mu W/F)");
  check(ctx, qs_ok, "fig5_3: the dynamic iCOR does not approach the quasi-static one monotonically (<= 0.5 (F/F_min - 1))");
  check(ctx, stuck_ok, "fig5_3: a push at 0.999 F_min moved the rod");

  plot::Figure fig;
  fig.title = "Fig 5.3: quasi-static, dynamic (t = 1e-10 s, mu = 0.1) and impulsive iCOR, nanorod L = 590 nm";
  plot::Panel p{"", "push point yn [nm]", "iCOR distance from the CM, far side [nm]", false, true,
                "set yrange [50:5000]", {}};
  p.series = {{csv, "($1*1e9)", "($2*1e9)", "impulsive (5.5) k^2/yn", "lines lw 3 dt 2"},
              {csv, "($1*1e9)", "($3*1e9)", "quasi-static (4.13)", "lines lw 3 dt 3"},
              {csv, "($1*1e9)", "($4*1e9)", "quasi-static, constrained (5.4)", "lines lw 2 dt 4"}};
  for (std::size_t i = 0; i < kDynamicRatios.size(); ++i)
    p.series.push_back({csv, "($1*1e9)", "($" + std::to_string(i + 6) + "*1e9)",
                        "dynamic, F = " + ratio_name(kDynamicRatios[i]) + " mu W", "linespoints lw 2 pt 7 ps 0.6"});
  fig.panels.push_back(p);
  render_if_possible(ctx, fig, ctx.out / "fig5_3.png");

  std::ostringstream r;
  r << "\n## Fig 5.3: quasi-static, dynamic and impulsive iCOR\n\n"
    << "Dynamic: the rough-surface model (models.md C) for the nanorod, mu = 0.1, under the coulomb law\n"
    << "(event-located stick-slip), pushed from rest along +X, perpendicular to the rod, at yn from the CM; the\n"
    << "iCOR is read off the velocities at t = 1e-10 s (thesis section 5.5). Contact: a strip 2a x L with\n"
    << "a = " << std::setprecision(4) << a * 1e9 << " nm (Hertz line contact of graphite under W/L; the thesis gives no width),\n"
    << "W = m g + F_vdw = " << W << " N. Distances are on the far side of the CM from the push.\n"
    << "The thesis prints no push force for Fig 5.3: we draw F/(mu W) = 1.1, 2, 5, 20.\n\n"
    << "| yn [nm] | impulsive [nm] | 4.13 [nm] | rectangle [nm] |";
  for (double q : kDynamicRatios) r << " F = " << q << " mu W [nm] |";
  r << " theta(1e-10 s), F = 20 mu W [rad] |\n|---:|---:|---:|---:|";
  for (std::size_t i = 0; i < kDynamicRatios.size(); ++i) r << "---:|";
  r << "---:|\n";
  for (double yn : {10e-9, 50e-9, 100e-9, b / std::sqrt(3.0), 200e-9, 250e-9, b}) {
    r << std::fixed << std::setprecision(1) << "| " << yn * 1e9 << " | " << icor::impulsive(yn, k2) * 1e9 << " | "
      << icor::unknown_pressure(yn, L) * 1e9 << " | " << icor::rectangle_quasi_static(a, b, yn).R * 1e9 << " |";
    double th = 0.0;
    for (double q : kDynamicRatios) {
      const auto run = dyn(yn, q * muW, {1e-10});
      r << " " << run.samples.at(0).axial * 1e9 << " |";
      th = run.samples.at(0).theta;
    }
    r << std::setprecision(3) << " " << th << " |\n";
  }
  r << std::defaultfloat << std::setprecision(3)
    << "\nFor F/(mu W) = 1.1, 2, 5 (rotation < 0.2 rad by 1e-10 s) the dynamic iCOR lies between the quasi-static\n"
    << "and the impulsive one (" << between_total - between_fail << " of " << between_total
    << " readings at push points where the two differ by >= 5 %), moving toward the impulsive one as F grows.\n"
    << "Within a few nm of their crossing the rod's rotation (second order in theta) exceeds the interval itself\n"
    << "(F = 5 mu W at 170 nm: 0.2 % below it). All three meet where eq 4.13 equals k^2/yn:\n"
    << "yn = b/sqrt(3) = " << std::setprecision(4) << b / std::sqrt(3.0) * 1e9
    << " nm (the thesis reads the 'consistent point' at ~177 nm). Beyond it the impulsive\n"
    << "iCOR is the closer one to the CM, so there the dynamic iCOR is *larger* than the impulsive one for these\n"
    << "forces; it falls below it (the thesis' reading) only for a push strong enough to turn the rod appreciably\n"
    << "within 1e-10 s (F = 20 mu W: 0.3-0.6 rad), when the world-fixed push is no longer perpendicular (docs/errata.md).\n\n"
    << "Limits (`fig5_3_limits.csv`). Impulsive: the impulse F t held at 2 mu W x 1e-10 s while F grows (impulsive\n"
    << "motion is a large force over a short time; at a fixed 1e-10 s a large force spins the rod instead).\n"
    << "Quasi-static: F = (1 + e) F_min of the rectangle, read at 1e-10 s; F = 0.999 F_min leaves the rod stuck\n"
    << "(no motion) at every yn tested.\n\n"
    << "| limit | yn [nm] | F/(mu W) or e | R [nm] | reference [nm] | relative distance |\n|---|---:|---:|---:|---:|---:|\n";
  for (const auto& x : imp_rows)
    r << "| impulsive | " << std::setprecision(4) << x.yn * 1e9 << " | " << x.p << " | " << std::setprecision(7)
      << x.R * 1e9 << " | " << x.ref * 1e9 << " | " << std::setprecision(3) << x.d << " |\n";
  for (const auto& x : qs_rows)
    r << "| quasi-static | " << std::setprecision(4) << x.yn * 1e9 << " | " << x.p << " | " << std::setprecision(7)
      << x.R * 1e9 << " | " << x.ref * 1e9 << " | " << std::setprecision(3) << x.d << " |\n";
  r << "\nMeasured: the distance to the impulsive iCOR is ~ mu W/F (friction's share of the wrench), to the\n"
    << "quasi-static one ~0.18 (F/F_min - 1).\n";
  ctx.report << r.str();
}

// ---- The finite rectangle (beyond the thesis) ------------------------------------------

const std::vector<double> kAspects = {1e-4, 0.1, 0.5, 1.0};

void step_icor_rectangle(ReproduceContext& ctx) {
  const auto rod = icor::nanorod();
  const double L = rod.length, b = rod.half_length();
  const int n = ctx.quick ? 12 : 60;
  const auto csv = ctx.out / "icor_rectangle.csv";
  std::vector<std::string> h = {"yn", "R_4_13", "F_min_4_8_ratio"};
  for (double ab : kAspects) h.push_back("R_a/b=" + ratio_name(ab));
  for (double ab : kAspects) h.push_back("F_min_ratio_a/b=" + ratio_name(ab));
  Table t(csv, h);
  std::vector<double> worst(kAspects.size(), 0.0);
  bool all_converged = true;
  for (double yn : sweep(b / n, b, n, false)) {
    const double r413 = icor::unknown_pressure(yn, L);
    std::vector<std::string> row = {csv_number(yn), csv_number(r413), csv_number(icor::minimum_force(1.0, 1.0, yn, L))};
    std::vector<std::string> forces;
    for (std::size_t i = 0; i < kAspects.size(); ++i) {
      const auto q = icor::rectangle_quasi_static(kAspects[i] * b, b, yn);
      all_converged = all_converged && q.converged;
      worst[i] = std::max(worst[i], std::fabs(q.R / r413 - 1.0));
      row.push_back(csv_number(q.R));
      forces.push_back(csv_number(q.force));
    }
    row.insert(row.end(), forces.begin(), forces.end());
    t.row(row);
  }
  t.write();
  ctx.produced(csv);
  check(ctx, all_converged, "icor_rectangle: the quasi-static solve did not converge everywhere");
  check(ctx, worst[0] <= 1e-6, "icor_rectangle: a/b = 1e-4 deviates from eq 4.13 by " + fmt(worst[0]) + " > 1e-6");
  plot::Figure fig;
  fig.title = "Quasi-static iCOR of a finite rectangle 2a x L (uniform pressure) beside eq 4.13";
  plot::Panel p{"", "push point yn [nm]", "iCOR distance from the CM, far side [nm]", false, true, "", {}};
  p.series = {{csv, "($1*1e9)", "($2*1e9)", "eq 4.13 (line contact)", "lines lw 4 dt 2"}};
  for (std::size_t i = 0; i < kAspects.size(); ++i)
    p.series.push_back({csv, "($1*1e9)", "($" + std::to_string(i + 4) + "*1e9)", "a/b = " + ratio_name(kAspects[i]),
                        "linespoints lw 2 pt 7 ps 0.5"});
  fig.panels.push_back(p);
  render_if_possible(ctx, fig, ctx.out / "icor_rectangle.png");
  std::ostringstream r;
  r << "\n## Beyond the thesis: the quasi-static iCOR of a finite rectangle\n\n"
    << "Closed-form Coulomb friction over a 2a x 2b rectangle with uniform pressure (models.md B), push along body x'\n"
    << "at (0, yn): R, alpha and F_min solve the force and moment balance (quasi_static_icor, both senses). The iCOR\n"
    << "stays on the rod axis (alpha = pi/2) and moves away from the CM as the contact widens; F_min grows.\n"
    << "Tests: within 1e-6 of eq 4.13 at a/b = 1e-4, and within 1e-9 of an independent cubature + bisection solve\n"
    << "for a/b = 0.01 ... 1 (tests/test_icor_dynamic.cpp).\n\n"
    << "| a/b | max relative deviation from 4.13 over yn | F_min/(mu W) at yn = b (4.8: 0.4142) |\n|---:|---:|---:|\n";
  for (std::size_t i = 0; i < kAspects.size(); ++i)
    r << "| " << kAspects[i] << " | " << std::setprecision(3) << worst[i] << " | " << std::setprecision(6)
      << icor::rectangle_quasi_static(kAspects[i] * b, b, b).force << " |\n";
  ctx.report << r.str();
}

RegisterReproduce r1{{"table5_1", "Table 5.1: the constrained cubic from Brent/Eigen (C++) and Brent/LAPACK (F77)", 50, step_table5_1}};
RegisterReproduce r2{{"icor_error_analysis", "Section 5.6.1.1: sample std of R for eqs 4.13 and 5.4", 51, step_error_analysis}};
RegisterReproduce r3{{"fig4_2", "Fig 4.2: iCOR from eqs 4.1, 4.2, 4.3, 4.13", 52, step_fig4_2}};
RegisterReproduce r4{{"fig4_3", "Fig 4.3: iCOR for known pressure (eq 4.7)", 53, step_fig4_3}};
RegisterReproduce r5{{"fig4_4", "Fig 4.4: minimum push force (eq 4.8)", 54, step_fig4_4}};
RegisterReproduce r6{{"fig4_5", "Fig 4.5: push force vs iCOR (eq 4.10)", 55, step_fig4_5}};
RegisterReproduce r7{{"fig5_2", "Fig 5.2: iCOR with (5.4) and without (4.13) constraints", 56, step_fig5_2}};
RegisterReproduce r8{{"fig5_3", "Fig 5.3: quasi-static, dynamic (rough-surface nanorod) and impulsive iCOR", 57, step_fig5_3}};
RegisterReproduce r9{{"icor_rectangle", "Quasi-static iCOR of a finite rectangle beside eq 4.13", 58, step_icor_rectangle}};

}  // namespace
}  // namespace nanopush::cli
