// nanopush.icor: every iCOR formula of thesis chapters 4-5 (broadcast over NumPy arrays), the
// constrained cubic (5.4) by every solver (C++ Brent and Eigen, F77 Brent and LAPACK), the
// dynamic iCOR and the finite-rectangle iCOR (models/icor.hpp, models/icor_dynamic.hpp).
#include "common.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "nanopush/engines/f77_icor.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/models/icor_dynamic.hpp"

namespace nanopush::python {

namespace {

using icor::CubicSolution;

/// Define `name(arg0, ..., argN-1)` broadcasting a scalar function f(double...) -> double.
template <class F, std::size_t... I>
void def_vec_impl(py::module_& m, const char* name, F f, std::array<const char*, sizeof...(I)> names,
                  const char* doc, std::index_sequence<I...>) {
  m.def(
      name,
      [f, names](decltype((void)I, py::object())... args) {
        const std::array<py::handle, sizeof...(I)> in = {args...};
        auto r = broadcast_apply<sizeof...(I), 1>(in, names, [&f](const double* x, double* y) { y[0] = f(x[I]...); });
        return scalar_or_array(r[0]);
      },
      py::arg(names[I])..., doc);
}
template <std::size_t N, class F>
void def_vec(py::module_& m, const char* name, F f, std::array<const char*, N> names, const char* doc) {
  def_vec_impl(m, name, f, names, doc, std::make_index_sequence<N>{});
}

CubicSolution solve_cubic(double yn, double L, double k2, const std::string& solver) {
  // The push point lies on the rod, as `nanopush icor roots` and the C API require.
  require_positive("L", L, "m");
  require_range("yn", yn, 0.0, 0.5 * L, "m; push point on the rod, at most b = L/2");
  return nanopush::solve_cubic(yn, L, k2, parse_choice<CubicSolver>("solver", solver));
}

void check_solver(const std::string& solver) { (void)parse_choice<CubicSolver>("solver", solver); }

icor::DynamicIntegrator parse_integrator(const std::string& s) { return icor::parse_dynamic_integrator("integrator", s); }

py::object optional_float(const std::optional<double>& v) { return v ? py::object(py::float_(*v)) : py::none(); }

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The rod and the thesis nanorod.
void register_rod(py::module_& m) {
  py::class_<icor::Rod>(m, "Rod", R"doc(A thin rod on a plane (docs/icor.md), SI units. Fields: length L [m], radius [m],
density [kg/m^3], hamaker H [J], z0 (rod-plane separation) [m], gravity g [m/s^2].
Rod() is the thesis nanorod (L = 590 nm, radius 13.5 nm, graphite on graphite).)doc")
      .def(py::init([](double length, double radius, double density, double hamaker, double z0, double gravity) {
             icor::Rod r;
             r.length = length;
             r.radius = radius;
             r.density = density;
             r.hamaker = hamaker;
             r.z0 = z0;
             r.gravity = gravity;
             r.validate();
             return r;
           }),
           py::arg("length") = icor::Rod{}.length, py::arg("radius") = icor::Rod{}.radius,
           py::arg("density") = icor::Rod{}.density, py::arg("hamaker") = icor::Rod{}.hamaker,
           py::arg("z0") = icor::Rod{}.z0, py::arg("gravity") = icor::Rod{}.gravity,
           "A rod; every field finite and > 0 (nanopush.InputError otherwise).")
      .def_readwrite("length", &icor::Rod::length, "L [m]")
      .def_readwrite("radius", &icor::Rod::radius, "[m]")
      .def_readwrite("density", &icor::Rod::density, "[kg/m^3]")
      .def_readwrite("hamaker", &icor::Rod::hamaker, "Hamaker constant H [J]")
      .def_readwrite("z0", &icor::Rod::z0, "rod-plane separation [m]")
      .def_readwrite("gravity", &icor::Rod::gravity, "g [m/s^2]")
      .def("validate", &icor::Rod::validate, "Raise nanopush.InputError unless every field is finite and > 0.")
      .def_property_readonly("half_length", &icor::Rod::half_length, "b = L/2 [m]")
      .def_property_readonly("mass", &icor::Rod::mass, "rho pi r^2 L [kg]")
      .def_property_readonly("inertia", &icor::Rod::inertia, "m L^2/12 about the centre of mass [kg m^2]")
      .def_property_readonly("k2", &icor::Rod::gyration_squared, "k^2 = I/m = L^2/12 [m^2]")
      .def_property_readonly("vdw_force", &icor::Rod::vdw_force, "Parsegian rod-plane attraction F_vdw [N]")
      .def_property_readonly("load", &icor::Rod::load, "W = m g + F_vdw [N]")
      .def("__repr__", [](const icor::Rod& r) {
        return "nanopush.icor.Rod(length=" + fmt(r.length) + ", radius=" + fmt(r.radius) + ", density=" +
               fmt(r.density) + ", hamaker=" + fmt(r.hamaker) + ", z0=" + fmt(r.z0) + ", gravity=" + fmt(r.gravity) +
               ")";
      });
  m.def("nanorod", &icor::nanorod, "The thesis' nanorod: L = 590 nm, radius 13.5 nm, graphite on graphite.");
}

/// Chapter 4 and 5 formulas, broadcast over NumPy arrays.
void register_formulas(py::module_& m) {
  def_vec<2>(m, "experimental_fit", &icor::experimental_fit, {"yn", "L"},
             "Eq 4.1 (experimental fit): iCOR distance R [m] from the centre of mass for a push at yn [m] "
             "(0 <= yn <= L/2) on a rod of length L [m]. Broadcasts.");
  def_vec<2>(m, "falvo", &icor::falvo, {"yn", "L"}, "Eq 4.2 (Falvo et al.): R [m] for a push at yn [m], rod length L [m].");
  def_vec<1>(m, "falvo_normalised", &icor::falvo_normalised, {"x1_hat"},
             "Eq 4.2 in its own coordinates: normalised iCOR x0/L from the normalised push point x1/L (both "
             "from the lower end).");
  def_vec<2>(m, "li", &icor::li, {"yn", "L"}, "Eq 4.3 (Li et al.): R [m] for a push at yn [m], rod length L [m].");
  def_vec<2>(m, "li_position", &icor::li_position, {"l", "L"},
             "Eq 4.3 in its own coordinates: iCOR position S [m] from the left end for a push at l [m] from it.");
  def_vec<2>(m, "unknown_pressure", &icor::unknown_pressure, {"yn", "L"},
             "Eq 4.13 (unknown pressure, minimum force): R = sqrt(b^2 + yn^2) - yn [m], b = L/2.");
  def_vec<4>(m, "minimum_force", &icor::minimum_force, {"mu", "W", "yn", "L"},
             "Eq 4.8: minimum push force that starts motion, mu W (sqrt(yn^2 + b^2) - yn)/b [N]; mu [-], load W [N], "
             "yn, L [m].");
  def_vec<5>(m, "known_pressure", &icor::known_pressure, {"mu", "W", "yn", "F", "L"},
             "Eq 4.7 (known uniform pressure): R [m] for a push force F [N] >= minimum_force (InputError naming the "
             "minimum otherwise).");
  def_vec<4>(m, "force_from_icor", &icor::force_from_icor, {"mu", "W", "R", "L"}, "Eq 4.10: F = mu W R/b [N].");
  def_vec<5>(m, "force_unknown_pressure", &icor::force_unknown_pressure, {"mu", "W", "R", "yn", "L"},
             "Eq 4.11: F = mu W (b^2 + R^2)/(2 b (R + yn)) [N]; needs R + yn > 0.");
  def_vec<2>(m, "impulsive", &icor::impulsive, {"yn", "k2"},
             "Eq 5.5 (with erratum 6): impulsive iCOR R = k^2/yn [m]; +inf at yn = 0 (pure translation). k2 [m^2].");
  def_vec<6>(m, "constrained_force", &icor::constrained_force, {"mu", "W", "R", "yn", "L", "k2"},
             "Eq 5.2 (with erratum 5): push force [N] for an assumed iCOR R [m]; +-inf at the pole yn R = k^2.");

  m.def(
      "constrained_cubic",
      [](double yn, double L, double k2) {
        const auto c = icor::constrained_cubic(yn, L, k2);
        return py::array_t<double>(4, c.data());
      },
      py::arg("yn"), py::arg("L"), py::arg("k2"),
      "Coefficients c0..c3 (ascending) of eq 5.4 divided by m^2 W: 2 yn R^3 - 3 k^2 R^2 + k^2 (b^2 - 2 k^2) [m^4].");
  m.def(
      "constrained_cubic_printed",
      [](double yn, const icor::Rod& rod) {
        const auto c = icor::constrained_cubic_printed(yn, rod);
        return py::array_t<double>(4, c.data());
      },
      py::arg("yn"), py::arg("rod"),
      "Coefficients c0..c3 (ascending) of eq 5.4 exactly as printed, with the rod's m, g, F_vdw, I [kg^3 m^4 s^-2].");
}

/// The constrained cubic (5.4) by every solver.
void register_cubic(py::module_& m) {
  py::class_<CubicSolution>(m, "CubicSolution", "Roots of the constrained cubic (5.4) at one push point, SI.")
      .def_readonly("yn", &CubicSolution::yn, "push point [m]")
      .def_property_readonly(
          "real_roots",
          [](const CubicSolution& s) {
            return py::array_t<double>(static_cast<py::ssize_t>(s.real_roots.size()), s.real_roots.data());
          },
          "finite real roots, ascending [m]")
      .def_readonly("complex_roots", &CubicSolution::complex_roots, "number of non-real roots (0 or 2)")
      .def_readonly("at_infinity", &CubicSolution::at_infinity, "roots lost to the vanishing leading coefficient (yn = 0)")
      .def_property_readonly("negative", [](const CubicSolution& s) { return optional_float(s.negative); },
                             "the negative root closest to 0 (Table 5.1's branch, signed) [m], or None")
      .def_property_readonly("positive", [](const CubicSolution& s) { return optional_float(s.positive); },
                             "the smallest positive root (the other side of the CM) [m], or None")
      .def_readonly("max_residual", &CubicSolution::max_residual, "max |p(R)| / sum |c_i R^i| over the real roots")
      .def("__repr__", [](const CubicSolution& s) {
        std::string r = "<CubicSolution yn=" + fmt(s.yn) + " roots=[";
        for (std::size_t i = 0; i < s.real_roots.size(); ++i) r += (i ? ", " : "") + fmt(s.real_roots[i]);
        return r + "]>";
      });
  py::tuple solvers(NameTable<CubicSolver>::table.size());
  for (std::size_t i = 0; i < solvers.size(); ++i) solvers[i] = std::string(NameTable<CubicSolver>::table[i].second);
  m.attr("cubic_solvers") = solvers;
  m.def("cubic_roots", &solve_cubic, py::arg("yn"), py::arg("L"), py::arg("k2"), py::arg("solver") = "brent",
        "Roots of eq 5.4 for a push at yn >= 0 [m] on a rod of length L [m] with k^2 = I/m [m^2], by one "
        "solver: 'brent' or 'eigen' (C++: Brent's method, companion-matrix eigenvalues), 'brent_f77' or "
        "'lapack_f77' (the FORTRAN 77 code). The numbers of `nanopush icor roots`. Returns a CubicSolution.");
  m.def(
      "cubic_branches",
      [](const py::object& yn, const py::object& L, const py::object& k2, const std::string& solver) {
        check_solver(solver);
        auto r = broadcast_apply<3, 2>({yn, L, k2}, {"yn", "L", "k2"}, [&solver](const double* x, double* y) {
          const auto s = solve_cubic(x[0], x[1], x[2], solver);
          y[0] = s.negative ? *s.negative : kNaN;
          y[1] = s.positive ? *s.positive : kNaN;
        });
        return py::make_tuple(scalar_or_array(r[0]), scalar_or_array(r[1]));
      },
      py::arg("yn"), py::arg("L"), py::arg("k2"), py::arg("solver") = "brent",
      "Both branches of eq 5.4 over arrays (broadcast): (negative, positive) [m], NaN where a branch does not "
      "exist. Solver as for cubic_roots.");
}

/// Velocity iCOR, line contact, finite rectangle, dynamic iCOR.
void register_contact_and_dynamic(py::module_& m) {
  m.def(
      "from_velocity",
      [](const py::object& vx, const py::object& vy, const py::object& omega) {
        auto r = broadcast_apply<3, 3>({vx, vy, omega}, {"vx", "vy", "omega"}, [](const double* x, double* y) {
          require_finite("vx", x[0], "m/s");
          require_finite("vy", x[1], "m/s");
          require_finite("omega", x[2], "rad/s");
          const auto c = icor::icor_from_velocity(x[0], x[1], x[2]);
          y[0] = c.cx;
          y[1] = c.cy;
          y[2] = c.R;
        });
        return py::make_tuple(scalar_or_array(r[0]), scalar_or_array(r[1]), scalar_or_array(r[2]));
      },
      py::arg("vx"), py::arg("vy"), py::arg("omega"),
      "The iCOR read off a rigid velocity (vx, vy [m/s], omega [rad/s]; broadcast): (cx, cy, R), c = (-vy, vx)/omega "
      "relative to the centre of mass [m] in the frame of v, R = |c|; omega = 0 gives c = (0, 0), R = inf.");
  m.def(
      "line_contact_wrench",
      [](const py::object& b, const py::object& R, const py::object& alpha) {
        auto r = broadcast_apply<3, 3>({b, R, alpha}, {"b", "R", "alpha"}, [](const double* x, double* y) {
          require_positive("b", x[0], "m");
          require_nonnegative("R", x[1], "m");
          require_finite("alpha", x[2], "rad");
          const auto w = icor::line_contact_wrench(x[0], x[1], x[2]);
          y[0] = w.fx;
          y[1] = w.fy;
          y[2] = w.mf;
        });
        return py::make_tuple(scalar_or_array(r[0]), scalar_or_array(r[1]), scalar_or_array(r[2]));
      },
      py::arg("b"), py::arg("R"), py::arg("alpha"),
      "Closed-form wrench of a thin rod (line contact, half-length b [m]) rotating counter-clockwise about the iCOR "
      "-R (cos alpha, sin alpha), per unit mu W: (fx, fy [1], mf [m]). Broadcasts.");
  m.def(
      "rod_contact_half_width", [](const icor::Rod& rod) { return icor::rod_contact_half_width(rod); }, py::arg("rod"),
      "Half-width a [m] of the rod's contact strip (Hertz line contact under W/L): 2.78 nm for the nanorod.");

  py::class_<icor::QuasiStaticIcor>(m, "QuasiStaticIcor", "Quasi-static iCOR of a finite rectangle (docs/icor.md).")
      .def_readonly("R", &icor::QuasiStaticIcor::R, "distance CM -> iCOR [m] (inf: pure translation)")
      .def_readonly("alpha", &icor::QuasiStaticIcor::alpha, "direction of the iCOR [rad], c = -R (cos, sin) alpha")
      .def_readonly("force", &icor::QuasiStaticIcor::force, "minimum push |F|/(mu W) [-]")
      .def_readonly("omega_sign", &icor::QuasiStaticIcor::omega_sign, "+1 counter-clockwise, -1 clockwise")
      .def_readonly("iterations", &icor::QuasiStaticIcor::iterations)
      .def_readonly("converged", &icor::QuasiStaticIcor::converged)
      .def_readonly("residual", &icor::QuasiStaticIcor::residual, "max |balance equation| at the answer")
      .def("__repr__", [](const icor::QuasiStaticIcor& q) {
        return "<QuasiStaticIcor R=" + fmt(q.R) + " alpha=" + fmt(q.alpha) + " force=" + fmt(q.force) +
               (q.converged ? " converged>" : " NOT converged>");
      });
  m.def(
      "rectangle",
      [](double a, double b, double yn) {
        py::gil_scoped_release release;
        return icor::rectangle_quasi_static(a, b, yn);
      },
      py::arg("a"), py::arg("b"), py::arg("yn"),
      "Quasi-static iCOR of a 2a x 2b rectangle (uniform pressure, closed-form friction) pushed along body +x' at "
      "(0, yn): a, b [m] (a/b >= 1e-6), yn >= 0 [m]. The numbers of `nanopush icor rectangle`.");

  m.def(
      "dynamic",
      [](double yn, double force, double mu, const icor::Rod& rod, double half_width, std::vector<double> times,
         double rtol, const std::string& integrator) {
        icor::DynamicIcorSetup s;
        s.rod = rod;
        s.mu = mu;
        s.half_width = half_width;
        s.yn = yn;
        s.force = force;
        s.times = std::move(times);
        s.rtol = rtol;
        s.integrator = parse_integrator(integrator);
        icor::DynamicIcorRun r;
        {
          py::gil_scoped_release release;
          r = icor::dynamic_icor(s);
        }
        const auto n = static_cast<py::ssize_t>(r.samples.size());
        py::array_t<double> t(n), R(n), axial(n), offset(n), theta(n), vx(n), vy(n), omega(n);
        py::array_t<bool> moving(n), translation(n);
        for (py::ssize_t i = 0; i < n; ++i) {
          const auto& q = r.samples[static_cast<std::size_t>(i)];
          t.mutable_at(i) = q.t;
          R.mutable_at(i) = q.R;
          axial.mutable_at(i) = q.axial;
          offset.mutable_at(i) = q.offset;
          theta.mutable_at(i) = q.theta;
          vx.mutable_at(i) = q.vx;
          vy.mutable_at(i) = q.vy;
          omega.mutable_at(i) = q.omega;
          moving.mutable_at(i) = q.moving;
          translation.mutable_at(i) = q.translation;
        }
        py::dict d;
        d["t"] = t;
        d["moving"] = moving;
        d["translation"] = translation;
        d["R"] = R;
        d["axial"] = axial;
        d["offset"] = offset;
        d["theta"] = theta;
        d["vx"] = vx;
        d["vy"] = vy;
        d["omega"] = omega;
        d["stuck"] = r.stuck;
        d["load"] = r.load;
        d["half_width"] = r.half_width;
        d["rhs_evaluations"] = r.rhs_evaluations;
        d["integrator"] = icor::to_string(r.integrator);
        d["minimum_force"] = r.minimum_force;
        return d;
      },
      py::arg("yn"), py::arg("force"), py::arg("mu") = 0.1, py::arg("rod") = icor::nanorod(),
      py::arg("half_width") = 0.0, py::arg("times") = std::vector<double>{1e-10}, py::arg("rtol") = 1e-10,
      py::arg("integrator") = "automatic",
      R"doc(The dynamic iCOR (thesis section 5.5, Fig 5.3): the rough-surface rod under the coulomb law,
pushed from rest perpendicular to its axis at yn [m] (0 <= yn <= L/2) with force [N], read at
`times` [s] (ascending, > 0). mu [-]; half_width a [m] of the contact strip (0: Hertz, see
rod_contact_half_width); integrator 'automatic', 'bulirsch-stoer' or 'cvode'. GIL released.

Returns a dict: arrays t, moving, translation, R (distance CM -> iCOR [m]), axial (along the
rod, > 0 on the far side [m]), offset (across [m]), theta [rad], vx, vy [m/s], omega [rad/s];
and stuck, load W [N], half_width [m], rhs_evaluations, integrator, minimum_force [N].)doc");
}

/// Section 5.6.1.1's error analysis and Table 5.1 as printed.
void register_thesis_checks(py::module_& m) {
  m.def(
      "error_analysis",
      [](double L, double k2, const std::string& solver, const Whole& n_arg) {
        const int n = static_cast<int>(arg_integer(n_arg.value, "n", 2, 2147483647));
        const auto e = icor::error_analysis(L, k2, parse_choice<icor::CubicMethod>("solver", solver), n);
        py::dict d;
        d["n"] = e.n;
        d["std_unknown_pressure_nm"] = e.std_unknown_pressure_nm;
        d["std_constrained_nm"] = e.std_constrained_nm;
        d["mean_unknown_pressure_nm"] = e.mean_unknown_pressure_nm;
        d["mean_constrained_nm"] = e.mean_constrained_nm;
        return d;
      },
      py::arg("L"), py::arg("k2"), py::arg("solver") = "brent", py::arg("n") = 296,
      "Section 5.6.1.1: sample standard deviation and mean [nm] of eq 4.13 and of eq 5.4's Table 5.1 branch over "
      "yn = 0, 1, ..., n-1 nm.");
  m.def(
      "thesis_table_5_1",
      [] {
        py::list l;
        for (const auto& r : icor::thesis_table_5_1()) {
          py::dict d;
          d["yn"] = r.yn;
          d["printed"] = r.printed;
          d["digits"] = r.digits();
          d["plus_minus"] = r.plus_minus;
          l.append(d);
        }
        return l;
      },
      "Table 5.1 as printed: yn [m], |R| [m], significant digits, and whether the thesis prints +-.");
}
}  // namespace

void register_icor(py::module_& parent) {
  py::module_ m = parent.def_submodule("icor", "The instantaneous centre of rotation of a pushed nanorod (thesis ch. 4-5).");
  register_rod(m);
  register_formulas(m);
  register_cubic(m);
  register_contact_and_dynamic(m);
  register_thesis_checks(m);
}

}  // namespace nanopush::python
