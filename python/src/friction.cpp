// nanopush.friction_wrench / friction_from_velocity: the closed-form Coulomb friction over a
// 2a x 2b rectangle (models/friction.hpp), broadcast over NumPy arrays, GIL released.
#include "common.hpp"

#include <limits>
#include <type_traits>

#include "f77_friction.h"
#include "nanopush/models/friction.hpp"

namespace nanopush::python {

namespace {

int sense_of(double s) {
  if (s == 1.0) return 1;
  if (s == -1.0) return -1;
  throw InputError("sense", fmt(s), "must be +1 (counter-clockwise) or -1 (clockwise)");
}

PyObject* g_wrench = nullptr;  // the namedtuple nanopush.Wrench, owned for the life of the process

py::object wrench_tuple(const std::array<py::array_t<double>, 3>& w) {
  return py::handle(g_wrench)(scalar_or_array(w[0]), scalar_or_array(w[1]), scalar_or_array(w[2]));
}

py::object friction_wrench(const py::object& a, const py::object& b, const py::object& R, const py::object& alpha,
                           const py::object& sense, const py::object& mu_n, const std::string& engine) {
  const bool f77 = parse_choice<Engine>("engine", engine) == Engine::f77;
  const std::array<py::handle, 6> in = {a, b, R, alpha, sense, mu_n};
  const std::array<const char*, 6> names = {"a", "b", "R", "alpha", "sense", "muN"};
  if (f77) {
    return wrench_tuple(broadcast_apply<6, 3>(in, names, [](const double* x, double* w) {
      const int s = sense_of(x[4]);
      (void)rectangle_friction_wrench_checked(x[0], x[1], x[5], x[2], x[3], s);  // the library's checks
      const int st = np_f77_rectangle_friction(x[0], x[1], x[5], x[2], x[3], s, w);
      if (st != 0) {
        char msg[160];
        np_f77_friction_message(st, msg, sizeof msg);
        throw InputError(std::string("F77 engine: ") + msg);
      }
    }));
  }
  // The common case: one contact (a, b, sense, muN scalars) at many iCORs. Its parameters are
  // checked once; per iCOR only R and alpha (the library's message when one is bad), then the
  // unchecked hot path, as a C++ loop would call it.
  const DArray pa = as_double_array(a, "a"), pb = as_double_array(b, "b"), ps = as_double_array(sense, "sense"),
               pm = as_double_array(mu_n, "muN");
  if (pa.size() == 1 && pb.size() == 1 && ps.size() == 1 && pm.size() == 1 && pa.ndim() == 0 && pb.ndim() == 0 &&
      ps.ndim() == 0 && pm.ndim() == 0) {
    const double ca = *pa.data(), cb = *pb.data(), cm = *pm.data();
    const int cs = sense_of(*ps.data());
    (void)rectangle_friction_wrench_checked(ca, cb, cm, 0.0, 0.0, cs);
    const auto kernel = [=](auto sense_c) {
      return [=](const double* x, double* w) {
        if (!(x[0] >= 0.0 && x[0] <= std::numeric_limits<double>::max() && x[1] - x[1] == 0.0))
          (void)rectangle_friction_wrench_checked(ca, cb, cm, x[0], x[1], cs);  // throws the library's message
        const auto f = rectangle_friction_wrench(ca, cb, cm, x[0], x[1], decltype(sense_c)::value);
        w[0] = f.fx;
        w[1] = f.fy;
        w[2] = f.mf;
      };
    };
    // The rotation sense as a compile-time constant (one branch less per iCOR).
    if (cs > 0)
      return wrench_tuple(broadcast_apply<2, 3>({R, alpha}, {"R", "alpha"}, kernel(std::integral_constant<int, 1>{})));
    return wrench_tuple(broadcast_apply<2, 3>({R, alpha}, {"R", "alpha"}, kernel(std::integral_constant<int, -1>{})));
  }
  return wrench_tuple(broadcast_apply<6, 3>(in, names, [](const double* x, double* w) {
    const auto f = rectangle_friction_wrench_checked(x[0], x[1], x[5], x[2], x[3], sense_of(x[4]));
    w[0] = f.fx;
    w[1] = f.fy;
    w[2] = f.mf;
  }));
}

py::object friction_from_velocity(const py::object& a, const py::object& b, const py::object& vx,
                                  const py::object& vy, const py::object& omega, const py::object& mu_n) {
  const std::array<py::handle, 6> in = {a, b, vx, vy, omega, mu_n};
  const std::array<const char*, 6> names = {"a", "b", "vx", "vy", "omega", "muN"};
  return wrench_tuple(broadcast_apply<6, 3>(in, names, [](const double* x, double* w) {
    const auto f = rectangle_friction_from_velocity_checked(x[0], x[1], x[5], x[2], x[3], x[4]);
    w[0] = f.fx;
    w[1] = f.fy;
    w[2] = f.mf;
  }));
}

}  // namespace

void register_friction(py::module_& m) {
  py::object wrench = py::module_::import("collections").attr("namedtuple")("Wrench", py::make_tuple("fx", "fy", "mf"));
  wrench.attr("__module__") = "nanopush";
  wrench.attr("__doc__") =
      "Friction wrench in body axes: fx, fy [N] (force) and mf [N m] (moment about the centre of mass).";
  g_wrench = wrench.release().ptr();
  m.attr("Wrench") = py::handle(g_wrench);
  m.def("friction_wrench", &friction_wrench, py::arg("a"), py::arg("b"), py::arg("R"), py::arg("alpha"),
        py::arg("sense") = 1, py::arg("mu_n") = 1.0, py::arg("engine") = "cxx",
        R"doc(Coulomb friction over a 2a x 2b rectangle with uniform pressure, in closed form
(thesis eqs 3.27-3.50, docs/friction.md), at iCORs given as NumPy arrays of any shape.

a      half-width along body x' [m] (> 0)
b      half-length along body y' [m] (> 0; min(a, b)/max(a, b) >= 1e-12)
R      distance from the iCOR to the centre of mass [m] (>= 0); the iCOR is at
       -R (cos alpha, sin alpha) in body axes
alpha  direction of the iCOR [rad]
sense  +1 counter-clockwise rotation (omega > 0), -1 clockwise
mu_n   mu N, the friction coefficient times the normal load [N] (>= 0; default 1:
       the numbers of `nanopush friction`)
engine 'cxx' (the C++ closed form) or 'f77' (the FORTRAN 77 RECTFR)

Every argument broadcasts (NumPy rules). Returns Wrench(fx, fy, mf): force [N] and moment
about the centre of mass [N m] in body axes, arrays of the broadcast shape (floats for scalar
input). Computed in C++ with the GIL released. A bad element raises nanopush.InputError
(a ValueError) with the library's message; its .index is the element.)doc");
  m.def("friction_from_velocity", &friction_from_velocity, py::arg("a"), py::arg("b"), py::arg("vx"), py::arg("vy"),
        py::arg("omega"), py::arg("mu_n") = 1.0,
        R"doc(Friction wrench from the body-axis rigid velocity: centre-of-mass velocity (vx, vy) [m/s]
and angular rate omega [rad/s] (arrays of any shape, broadcast). The iCOR is
(-vy, vx)/omega; omega = 0 is pure translation (moment 0), all zero is rest (zero wrench).
a, b [m] and mu_n [N] as for friction_wrench. Returns Wrench(fx, fy, mf) [N, N, N m],
body axes; GIL released.)doc");
}

}  // namespace nanopush::python
