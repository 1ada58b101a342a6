// nanopush.estimate_mu_batch: the friction coefficient from N quasi-static observations (push
// force with the push offset yn and/or the observed iCOR distance R), for one of the thesis'
// pressure distributions, combined by inverse-variance weighting with a chi^2 consistency check
// (models/icor_batch.hpp; the numbers of `nanopush fit-icor`).
#include "common.hpp"

#include <cmath>

#include "nanopush/models/icor.hpp"
#include "nanopush/models/icor_batch.hpp"

namespace nanopush::python {

namespace {

/// A 1-d float64 copy of `obj`, broadcast from a scalar to n; InputError naming `name` otherwise.
std::vector<double> vector_of(const py::handle& obj, const char* name, py::ssize_t n) {
  const DArray a = as_double_array(obj, name);
  std::vector<double> v(static_cast<std::size_t>(n));
  if (a.ndim() == 0) {
    std::fill(v.begin(), v.end(), *a.data());
  } else if (a.ndim() == 1 && a.shape(0) == n) {
    for (py::ssize_t i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = a.at(i);
  } else {
    throw InputError(name, "shape of " + std::to_string(a.ndim()) + "-d array",
                     "must be a number or a 1-d array of len(force) = " + std::to_string(n));
  }
  return v;
}

py::array_t<double> array_of(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

struct Batch {
  icor::BatchEstimate b;
};

Batch estimate_batch(const py::object& force, const py::object& sigma_force, const py::object& yn,
                     const py::object& sigma_yn, const py::object& R, const py::object& sigma_R,
                     const std::string& pressure, double sigma_L, double sigma_H, double alpha,
                     const py::object& rod_obj) {
  if (!rod_obj.is_none() && !py::isinstance<icor::Rod>(rod_obj))
    throw InputError("rod", py::repr(rod_obj).cast<std::string>(), "must be a nanopush.Rod (or None: the thesis' nanorod)");
  const icor::Rod rod = rod_obj.is_none() ? icor::nanorod() : rod_obj.cast<icor::Rod>();
  const icor::Pressure p = icor::parse_pressure(pressure);
  const DArray f = as_double_array(force, "force");
  if (f.ndim() != 1 || f.shape(0) < 1)
    throw InputError("force", "array of " + std::to_string(f.ndim()) + " dimensions",
                     "must be a 1-d array of at least one push force (N)");
  const py::ssize_t n = f.shape(0);
  const auto F = vector_of(force, "force", n), sF = vector_of(sigma_force, "sigma_force", n);
  auto optional_pair = [&](const py::object& v, const py::object& s, const char* vn, const char* sn) {
    std::pair<std::vector<double>, std::vector<double>> out;
    if (v.is_none()) {
      if (!s.is_none()) throw InputError(sn, "given", std::string("needs ") + vn);
      return out;
    }
    if (s.is_none()) throw InputError(sn, "None", std::string("must be given with ") + vn + " (standard uncertainty)");
    out.first = vector_of(v, vn, n);
    out.second = vector_of(s, sn, n);
    return out;
  };
  const auto [y, sy] = optional_pair(yn, sigma_yn, "yn", "sigma_yn");
  const auto [r, sr] = optional_pair(R, sigma_R, "R", "sigma_R");
  std::vector<icor::Observation> obs(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < obs.size(); ++i) {
    obs[i].force = {F[i], sF[i]};
    if (!y.empty() && !std::isnan(y[i])) obs[i].yn = icor::Measured{y[i], sy[i]};
    if (!r.empty() && !std::isnan(r[i])) obs[i].R = icor::Measured{r[i], sr[i]};
  }
  Batch out;
  {
    py::gil_scoped_release release;
    out.b = icor::estimate_mu_batch(rod, obs, p, sigma_L, sigma_H, alpha);
  }
  return out;
}

}  // namespace

void register_fit_icor(py::module_& m) {
  py::class_<Batch>(m, "MuBatch", R"doc(Friction coefficient combined from N observations (nanopush.estimate_mu_batch).

mu [-] and sigma = sqrt(sigma_stat^2 + sigma_syst^2); sigma_stat from the observations'
sigmas (1 / sqrt(sum 1/sigma_i^2)); sigma_syst from the rod's length and Hamaker constant
(common to every row, not divided by sqrt(N)); chi2, dof = N - 1, chi2_dof, p_value (NaN
for N = 1), consistent (p_value >= alpha), sigma_scaled (Birge: sigma_stat sqrt(max(1,
chi2_dof)), with the systematic part); load W [N], dmu_dL [1/m], dmu_dH [1/J]; per row
(NumPy arrays) row_mu, row_sigma, row_weight, row_pull and equations ('4.8', '4.10', '4.11').)doc")
      .def_property_readonly("pressure", [](const Batch& x) { return icor::to_string(x.b.pressure); })
      .def_property_readonly("mu", [](const Batch& x) { return x.b.mu; })
      .def_property_readonly("sigma", [](const Batch& x) { return x.b.sigma; })
      .def_property_readonly("sigma_stat", [](const Batch& x) { return x.b.sigma_stat; })
      .def_property_readonly("sigma_syst", [](const Batch& x) { return x.b.sigma_syst; })
      .def_property_readonly("sigma_scaled", [](const Batch& x) { return x.b.sigma_scaled; })
      .def_property_readonly("chi2", [](const Batch& x) { return x.b.chi2; })
      .def_property_readonly("dof", [](const Batch& x) { return x.b.dof; })
      .def_property_readonly("chi2_dof", [](const Batch& x) { return x.b.chi2_dof; })
      .def_property_readonly("p_value", [](const Batch& x) { return x.b.p_value; })
      .def_property_readonly("consistent", [](const Batch& x) { return x.b.consistent; })
      .def_property_readonly("load", [](const Batch& x) { return x.b.load; })
      .def_property_readonly("dmu_dL", [](const Batch& x) { return x.b.dmu_dL; })
      .def_property_readonly("dmu_dH", [](const Batch& x) { return x.b.dmu_dH; })
      .def_property_readonly("row_mu",
                             [](const Batch& x) {
                               std::vector<double> v;
                               for (const auto& r : x.b.rows) v.push_back(r.estimate.mu);
                               return array_of(v);
                             })
      .def_property_readonly("row_sigma",
                             [](const Batch& x) {
                               std::vector<double> v;
                               for (const auto& r : x.b.rows) v.push_back(r.estimate.sigma);
                               return array_of(v);
                             })
      .def_property_readonly("row_weight",
                             [](const Batch& x) {
                               std::vector<double> v;
                               for (const auto& r : x.b.rows) v.push_back(r.weight);
                               return array_of(v);
                             })
      .def_property_readonly("row_pull",
                             [](const Batch& x) {
                               std::vector<double> v;
                               for (const auto& r : x.b.rows) v.push_back(r.pull);
                               return array_of(v);
                             })
      .def_property_readonly("equations",
                             [](const Batch& x) {
                               py::list l;
                               for (const auto& r : x.b.rows) l.append(r.equation);
                               return l;
                             })
      .def("__repr__", [](const Batch& x) {
        return "<MuBatch " + icor::to_string(x.b.pressure) + " pressure: mu=" + fmt(x.b.mu) + " +- " +
               fmt(x.b.sigma) + ", chi2/dof=" + fmt(x.b.chi2_dof) + ", n=" + std::to_string(x.b.rows.size()) + ">";
      });

  m.def("estimate_mu_batch", &estimate_batch, py::arg("force"), py::arg("sigma_force"), py::kw_only(),
        py::arg("yn") = py::none(), py::arg("sigma_yn") = py::none(), py::arg("R") = py::none(),
        py::arg("sigma_R") = py::none(), py::arg("pressure") = "known", py::arg("sigma_L") = 0.0,
        py::arg("sigma_H") = 0.0, py::arg("alpha") = 0.01, py::arg("rod") = py::none(),
        R"doc(Friction coefficient from N quasi-static observations, combined (`nanopush fit-icor`).

force, sigma_force   push forces [N] (1-d array, > 0) and their standard uncertainties (array or
                     one number for all)
yn, sigma_yn         push offsets from the centre of mass [m] (0..L/2), NaN: not observed
R, sigma_R           observed iCOR distances from the centre of mass [m] (> 0), NaN: not observed
pressure             'known' (eq 4.10 where R is observed, else eq 4.8) or 'unknown' (eq 4.11,
                     needs yn; eq 4.8 where R is not observed)
sigma_L, sigma_H     rod length [m] and Hamaker constant [J] uncertainties (systematic)
alpha                significance level of the chi^2 consistency check
rod                  nanopush.icor.Rod (default: the thesis nanorod)

Returns a MuBatch. Bad input raises nanopush.InputError naming the row ("row 3: ...").)doc");
}

}  // namespace nanopush::python
