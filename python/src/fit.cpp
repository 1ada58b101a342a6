// nanopush.fit: scene keys fitted to observed motion (cxx/include/nanopush/fitting/fit.hpp; the
// numbers of `nanopush fit`), and nanopush.synthesize: synthetic observations from the model.
#include "common.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "nanopush/fitting/fit.hpp"
#include "nanopush/outputs/io.hpp"

namespace nanopush::python {

namespace {

fit::SigmaOverrides sigma_of(const py::object& sigma) {
  fit::SigmaOverrides out;
  if (sigma.is_none()) return out;
  if (!py::isinstance<py::dict>(sigma))
    throw InputError("sigma", py::repr(sigma).cast<std::string>(), "must be a dict {column: standard uncertainty}");
  for (const auto& [k, v] : sigma.cast<py::dict>()) {
    const std::string key = arg_text(k, "sigma key");
    out[key] = arg_double(v, "sigma[" + key + "]");
  }
  return out;
}

std::vector<std::string> keys_of(const py::object& free) {
  if (py::isinstance<py::str>(free)) return {free.cast<std::string>()};
  if (!py::isinstance<py::iterable>(free))
    throw InputError("free", py::repr(free).cast<std::string>(), "must be a scene key or a list of scene keys");
  std::vector<std::string> out;
  for (auto k : free) out.push_back(arg_text(k, "free"));
  return out;
}

fit::FitResult fit_scene(const Scene& scene, const py::object& data, const py::object& free, const std::string& law,
                         const py::object& sigma, const std::string& gradients, double rtol, int max_evaluations,
                         double accuracy) {
  fit::FitOptions o;
  o.accuracy = accuracy;
  o.free = keys_of(free);
  o.law = parse_optional_choice<Law>("--law", law);
  o.gradients = gradients;
  o.rtol = rtol;
  o.max_evaluations = max_evaluations;
  const auto overrides = sigma_of(sigma);
  const std::string path = arg_text(data, "data");
  py::gil_scoped_release release;
  const fit::Observations obs = fit::read_observations(path, overrides);
  return fit::fit_trajectory(scene, obs, o);
}

py::array_t<double> matrix(const std::vector<std::array<double, 3>>& rows) {
  py::array_t<double> a({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(3)});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < 3; ++j) m(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = rows[i][j];
  return a;
}

}  // namespace

void register_fit(py::module_& m) {
  py::class_<fit::FitResult>(m, "FitResult", R"doc(A trajectory fit (nanopush.fit; docs/fitting.md).

parameters   dict key -> {'value', 'stderr' (NaN when the data do not determine the key
             separately, or not converged), 'start', 'lower', 'upper', 'at_bound', 'unit'}
correlation  NumPy (k, k) correlation matrix of the estimates (NaN for undetermined keys)
chi2, chi2_dof, dof, converged, status, iterations, n_forward_solves, gradients, law
accuracy     with fit(accuracy=E): dict requested, rtol_used, estimate, reached; else None
identifiable, identifiability_message, determined (list of (name, value, stderr_relative))
t, fitted    observation times [s] and the model's pose (x, y, theta) there, NumPy (n, 3)
residuals    (observed - model) / sigma, NumPy (n, 3), NaN where not observed
json         the JSON summary of `nanopush fit --json`)doc")
      .def_property_readonly("parameters",
                             [](const fit::FitResult& r) {
                               py::dict d;
                               for (const auto& p : r.parameters) {
                                 py::dict e;
                                 e["value"] = p.value;
                                 e["stderr"] = p.stderr_;
                                 e["start"] = p.start;
                                 e["lower"] = p.lower;
                                 e["upper"] = p.upper;
                                 e["at_bound"] = p.at_bound;
                                 e["unit"] = p.unit;
                                 d[py::str(p.key)] = e;
                               }
                               return d;
                             })
      .def_property_readonly("correlation",
                             [](const fit::FitResult& r) {
                               const auto n = static_cast<py::ssize_t>(r.correlation.size());
                               py::array_t<double> a({n, n});
                               auto cells = a.mutable_unchecked<2>();
                               for (py::ssize_t i = 0; i < n; ++i)
                                 for (py::ssize_t j = 0; j < n; ++j)
                                   cells(i, j) = r.correlation[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
                               return a;
                             })
      .def_readonly("chi2", &fit::FitResult::chi2)
      .def_readonly("chi2_dof", &fit::FitResult::chi2_dof)
      .def_readonly("dof", &fit::FitResult::dof)
      .def_readonly("converged", &fit::FitResult::converged)
      .def_readonly("status", &fit::FitResult::status)
      .def_readonly("iterations", &fit::FitResult::iterations)
      .def_readonly("n_forward_solves", &fit::FitResult::n_forward_solves)
      .def_readonly("gradients", &fit::FitResult::gradients)
      .def_readonly("law", &fit::FitResult::law)
      .def_property_readonly("accuracy",
                             [](const fit::FitResult& r) -> py::object {
                               if (r.accuracy.requested <= 0) return py::none();
                               py::dict d;
                               d["requested"] = r.accuracy.requested;
                               d["rtol_used"] = r.accuracy.rtol_used;
                               d["estimate"] = r.accuracy.estimate;
                               d["reached"] = r.accuracy.reached;
                               return d;
                             })
      .def_property_readonly("identifiable", [](const fit::FitResult& r) { return r.identifiability.identifiable; })
      .def_property_readonly("identifiability_message",
                             [](const fit::FitResult& r) { return r.identifiability.message; })
      .def_property_readonly("determined",
                             [](const fit::FitResult& r) {
                               py::list l;
                               for (const auto& c : r.identifiability.determined)
                                 l.append(py::make_tuple(c.name, c.value, c.stderr_relative));
                               return l;
                             })
      .def_property_readonly("t",
                             [](const fit::FitResult& r) {
                               py::array_t<double> a(static_cast<py::ssize_t>(r.t.size()));
                               std::copy(r.t.begin(), r.t.end(), a.mutable_data());
                               return a;
                             })
      .def_property_readonly("fitted", [](const fit::FitResult& r) { return matrix(r.fitted); })
      .def_property_readonly("residuals", [](const fit::FitResult& r) { return matrix(r.residuals); })
      .def_property_readonly("json", [](const fit::FitResult& r) { return fit::fit_json(r); })
      .def("__repr__", [](const fit::FitResult& r) {
        std::string s = "<FitResult";
        for (const auto& p : r.parameters) s += " " + p.key + "=" + fmt(p.value) + " +- " + fmt(p.stderr_);
        return s + ", chi2/dof=" + fmt(r.chi2_dof) + (r.converged ? "" : ", NOT converged") + ">";
      });

  m.def("fit", &fit_scene, py::arg("scene"), py::arg("data"), py::arg("free"), py::kw_only(), py::arg("law") = "",
        py::arg("sigma") = py::none(), py::arg("gradients") = "auto", py::arg("rtol") = 1e-10,
        py::arg("max_evaluations") = 100, py::arg("accuracy") = -1.0,
        R"doc(Fit scene keys to observed motion (`nanopush fit`; docs/fitting.md).

scene        nanopush.Scene: the model and the starting values (not changed)
data         path of a CSV file: t [s] and any of x, y [m], theta [rad] with sigma_x, sigma_y,
             sigma_theta columns
free         a scene key ("surface.mu") or a list of keys
law          rough scenes: 'thesis' or 'coulomb' ('' = the scene's)
sigma        dict column -> standard deviation for columns without a sigma column
gradients    'auto' | 'sensitivities' | 'differences'; rtol of the forward solves;
max_evaluations of Levenberg-Marquardt
accuracy     > 0: the error asked for of the model's poses at the observation times, in
             [1e-14, 0.1] (docs/accuracy.md's norm): the forward solves' rtol is chosen to reach
             it (rtol is then ignored) and checked at the estimate (FitResult.accuracy: dict
             requested, rtol_used, estimate, reached; None when not asked); 0 = none;
             default: the scene's solver.accuracy

Returns a FitResult; a fit that does not converge says so (converged False), it does not
raise. Bad data or keys raise nanopush.InputError naming the row and column or the key.)doc");

  m.def(
      "synthesize",
      [](const Scene& scene, const std::array<double, 3>& sigma, std::uint64_t seed, const std::string& law,
         const py::object& path) {
        std::string text;
        {
          py::gil_scoped_release release;
          text = fit::observations_csv(fit::synthesize(scene, sigma, seed, parse_optional_choice<Law>("law", law)));
        }
        if (!path.is_none()) write_file_atomic(arg_text(path, "path"), text);  // as every output
        return text;
      },
      py::arg("scene"), py::arg("sigma"), py::arg("seed") = 1, py::kw_only(), py::arg("law") = "",
      py::arg("path") = py::none(),
      R"doc(Synthetic observations: the scene's model at its output times plus seeded Gaussian noise
of standard deviation sigma = (sx, sy, stheta) (a component with sigma <= 0 is not observed).
Returns the CSV text that nanopush.fit reads; writes it to `path` too when given.)doc");
}

}  // namespace nanopush::python
