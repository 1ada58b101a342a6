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

/// estimate_mu over arrays: mu, sigma, load and the four derivatives (F, yn or R, L, H) at
/// every element of the inputs broadcast together (Python: MuEstimates).
struct Estimates {
  std::string basis;
  py::object mu, sigma, load;
  py::dict derivatives, contributions;
};

py::object estimate(const py::object& force, const py::object& sigma_force, const py::object& yn,
                    const py::object& sigma_yn, const py::object& R, const py::object& sigma_R,
                    const py::object& sigma_L, const py::object& sigma_H, const py::object& rod_obj) {
  if (!rod_obj.is_none() && !py::isinstance<icor::Rod>(rod_obj))
    throw InputError("rod", py::repr(rod_obj).cast<std::string>(), "must be a nanopush.Rod (or None: the thesis' nanorod)");
  const icor::Rod rod = rod_obj.is_none() ? icor::nanorod() : rod_obj.cast<icor::Rod>();
  if (yn.is_none() == R.is_none())
    throw InputError("yn/R", yn.is_none() ? "neither given" : "both given",
                     "give exactly one: yn (push point, Fig 4.4) or R (observed iCOR distance, Fig 4.5)");
  const bool by_force = !yn.is_none();
  const char* pos = by_force ? "yn" : "R";
  const py::object& p = by_force ? yn : R;
  const py::object& sp = by_force ? sigma_yn : sigma_R;
  const std::string sp_name = by_force ? "sigma_yn" : "sigma_R";
  auto one = [&](const double* x) {
    return by_force ? icor::estimate_mu_from_force(rod, {x[0], x[1]}, {x[2], x[3]}, x[4], x[5])
                    : icor::estimate_mu_from_icor(rod, {x[0], x[1]}, {x[2], x[3]}, x[4], x[5]);
  };
  auto r = broadcast_apply<6, 7>({force, sigma_force, p, sp, sigma_L, sigma_H},
                                 {"force", "sigma_force", pos, sp_name.c_str(), "sigma_L", "sigma_H"},
                                 [&](const double* x, double* y) {
                                   const icor::MuEstimate e = one(x);
                                   y[0] = e.mu;
                                   y[1] = e.sigma;
                                   y[2] = e.load;
                                   for (std::size_t k = 0; k < 4; ++k) y[3 + k] = e.contributions[k].derivative;
                                 });
  if (r[0].ndim() == 0) {  // every input one number: the MuEstimate with its budget
    Estimate out;
    out.basis = by_force ? "force" : "icor";
    const double x[6] = {arg_double(force, "force"), arg_double(sigma_force, "sigma_force"), arg_double(p, pos),
                         arg_double(sp, sp_name), arg_double(sigma_L, "sigma_L"), arg_double(sigma_H, "sigma_H")};
    out.e = one(x);
    return py::cast(std::move(out));
  }
  Estimates out;
  out.basis = by_force ? "force" : "icor";
  out.mu = r[0];
  out.sigma = r[1];
  out.load = r[2];
  const char* inputs[4] = {"F", pos, "L", "H"};
  const py::object sig[4] = {sigma_force, sp, sigma_L, sigma_H};
  const py::module_ np = py::module_::import("numpy");
  for (std::size_t k = 0; k < 4; ++k) {
    out.derivatives[inputs[k]] = r[3 + k];
    out.contributions[inputs[k]] = np.attr("abs")(r[3 + k]) * np.attr("asarray")(sig[k], py::arg("dtype") = "float64");
  }
  return py::cast(std::move(out));
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

  py::class_<Estimates>(m, "MuEstimates", R"doc(Friction coefficients from arrays of measurements (estimate_mu with array input):
mu, sigma, load: float arrays of the inputs' broadcast shape; basis ('force' or 'icor');
derivatives and contributions: dicts input (F, yn or R, L, H) -> array of d mu/d input and of
|d mu/d input| sigma. Element i is estimate_mu at element i of the inputs.)doc")
      .def_readonly("basis", &Estimates::basis)
      .def_readonly("mu", &Estimates::mu)
      .def_readonly("sigma", &Estimates::sigma)
      .def_readonly("load", &Estimates::load)
      .def_readonly("derivatives", &Estimates::derivatives)
      .def_readonly("contributions", &Estimates::contributions)
      .def("__len__", [](const Estimates& e) { return py::len(e.mu); })
      .def("__repr__", [](const Estimates& e) {
        return "<MuEstimates " + py::str(e.mu.attr("shape")).cast<std::string>() + " (" + e.basis + ")>";
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
`nanopush icor estimate-mu`. Arrays (any of force, the sigmas, yn or R) broadcast as NumPy
does, like the icor functions: then a MuEstimates of arrays (mu, sigma, load, derivatives,
contributions); InputError.index names the element at fault.)doc");
}

}  // namespace nanopush::python
