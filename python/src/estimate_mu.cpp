// nanopush.estimate_mu: the friction coefficient from a measured push force and its point yn
// (Fig 4.4, eq 4.8) or from a push force and an observed iCOR (Fig 4.5, eq 4.10), with the
// first-order uncertainty and its budget (models/icor.hpp).
#include "common.hpp"

#include <cmath>

#include "nanopush/models/icor.hpp"

namespace nanopush::python {

namespace {

struct Estimate {
  icor::MuEstimate e;
  std::string basis;  ///< force (yn given) | icor (R given)
};

Estimate estimate(double force, double sigma_force, const py::object& yn, double sigma_yn, const py::object& R,
                  double sigma_R, double sigma_L, double sigma_H, const py::object& rod_obj) {
  if (!rod_obj.is_none() && !py::isinstance<icor::Rod>(rod_obj))
    throw InputError("rod", py::repr(rod_obj).cast<std::string>(), "must be a nanopush.Rod (or None: the thesis' nanorod)");
  const icor::Rod rod = rod_obj.is_none() ? icor::nanorod() : rod_obj.cast<icor::Rod>();
  if (yn.is_none() == R.is_none())
    throw InputError("yn/R", yn.is_none() ? "neither given" : "both given",
                     "give exactly one: yn (push point, Fig 4.4) or R (observed iCOR distance, Fig 4.5)");
  Estimate out;
  if (!yn.is_none()) {
    out.basis = "force";
    out.e = icor::estimate_mu_from_force(rod, {force, sigma_force}, {arg_double(yn, "yn"), sigma_yn}, sigma_L, sigma_H);
  } else {
    out.basis = "icor";
    out.e = icor::estimate_mu_from_icor(rod, {force, sigma_force}, {arg_double(R, "R"), sigma_R}, sigma_L, sigma_H);
  }
  return out;
}

}  // namespace

void register_estimate_mu(py::module_& m) {
  py::class_<Estimate>(m, "MuEstimate", R"doc(A friction coefficient with its first-order uncertainty (inputs uncorrelated).

mu [-], sigma [-] (one standard uncertainty), load W [N] used, basis ('force': from F and
yn, eq 4.8; 'icor': from F and R, eq 4.10), and the budget `contributions`: one dict per
input (F, yn or R, L, H) with value, sigma (SI), derivative d mu/d input and contribution
|d mu/d input| sigma.)doc")
      .def_property_readonly("mu", [](const Estimate& e) { return e.e.mu; })
      .def_property_readonly("sigma", [](const Estimate& e) { return e.e.sigma; })
      .def_property_readonly("load", [](const Estimate& e) { return e.e.load; })
      .def_readonly("basis", &Estimate::basis)
      .def_property_readonly(
          "contributions",
          [](const Estimate& e) {
            py::list l;
            for (const auto& c : e.e.contributions) {
              py::dict d;
              d["input"] = c.input;
              d["value"] = c.value;
              d["sigma"] = c.sigma;
              d["derivative"] = c.derivative;
              d["contribution"] = std::fabs(c.derivative) * c.sigma;
              l.append(d);
            }
            return l;
          })
      .def_property_readonly(
          "derivatives",
          [](const Estimate& e) {
            py::dict d;
            for (const auto& c : e.e.contributions) d[py::str(c.input)] = c.derivative;
            return d;
          },
          "d mu / d input for each input, SI (dict).")
      .def("__repr__", [](const Estimate& e) {
        return "<MuEstimate mu=" + fmt(e.e.mu) + " +- " + fmt(e.e.sigma) + " (" + e.basis + ")>";
      });

  m.def("estimate_mu", &estimate, py::arg("force"), py::arg("sigma_force") = 0.0, py::kw_only(),
        py::arg("yn") = py::none(), py::arg("sigma_yn") = 0.0, py::arg("R") = py::none(), py::arg("sigma_R") = 0.0,
        py::arg("sigma_L") = 0.0, py::arg("sigma_H") = 0.0, py::arg("rod") = py::none(),
        R"doc(Friction coefficient from measurements, with its uncertainty (Figs 4.4, 4.5).

force        measured push force F [N] (> 0); sigma_force its standard uncertainty [N]
yn           push point, distance from the centre of mass along the rod [m] (0..L/2):
             mu from the minimum force, eq 4.8 (Fig 4.4); sigma_yn [m]
R            observed iCOR distance from the centre of mass [m] (> 0): mu from eq 4.10
             (Fig 4.5); sigma_R [m]. Give exactly one of yn and R.
sigma_L      uncertainty of the rod length [m]; sigma_H of the Hamaker constant [J]
rod          nanopush.icor.Rod (default: the thesis nanorod)

Returns a MuEstimate (mu, sigma, load, contributions, derivatives): the numbers of
`nanopush icor estimate-mu`.)doc");
}

}  // namespace nanopush::python
