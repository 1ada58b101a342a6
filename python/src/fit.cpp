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

/// A fit and the observations it was fitted to (FitResult.observed, .sigma, plot()).
struct PyFit {
  fit::FitResult r;
  fit::Observations obs;
};

/// obs columns as an (n, 3) array: x, y, theta, NaN where a column was not observed.
py::array_t<double> obs_matrix(const fit::Observations& o, bool sigma) {
  const auto n = static_cast<py::ssize_t>(o.t.size());
  py::array_t<double> a({n, static_cast<py::ssize_t>(3)});
  auto m = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const auto& v = sigma ? o.sigma[c] : o.value[c];
      m(i, static_cast<py::ssize_t>(c)) = o.has[c] ? v[static_cast<std::size_t>(i)] : std::nan("");
    }
  return a;
}

/// One number of every fitted parameter (its value, stderr_, start, ...), in the order of names.
py::array_t<double> per_parameter(const fit::FitResult& r, double fit::ParameterEstimate::*field) {
  py::array_t<double> a(static_cast<py::ssize_t>(r.parameters.size()));
  for (std::size_t i = 0; i < r.parameters.size(); ++i)
    a.mutable_at(static_cast<py::ssize_t>(i)) = r.parameters[i].*field;
  return a;
}

/// The estimates' covariance: correlation[i][j] stderr[i] stderr[j] (NaN where undetermined).
py::array_t<double> covariance(const fit::FitResult& r) {
  const auto n = static_cast<py::ssize_t>(r.parameters.size());
  py::array_t<double> a({n, n});
  auto m = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t j = 0; j < n; ++j) {
      const auto iu = static_cast<std::size_t>(i), ju = static_cast<std::size_t>(j);
      const double rho = iu < r.correlation.size() && ju < r.correlation[iu].size() ? r.correlation[iu][ju]
                                                                                      : std::nan("");
      m(i, j) = rho * r.parameters[iu].stderr_ * r.parameters[ju].stderr_;
    }
  return a;
}

/// `data` is a path (str or path-like), or CSV text when `text` is true (the Python package
/// writes a dict, a structured array or a DataFrame as CSV, shortest round-trip numbers).
PyFit fit_scene(const Scene& scene, const py::object& data, const py::object& free, const std::string& law,
                const py::object& sigma, const std::string& gradients, double rtol, const Whole& max_evaluations,
                double accuracy, bool text) {
  // The library names some inputs as `nanopush fit` does (--free, --law, --sigma, DATA): here
  // they are nanopush.fit's arguments.
  const std::initializer_list<bindings::ArgumentName> names = {
      {"--free", "free"}, {"--law", "law"}, {"--sigma", "sigma"}, {"DATA", "data"}};
  return bindings::with_argument_names(names, [&] {
    fit::FitOptions o;
    o.accuracy = accuracy;
    o.free = keys_of(free);
    o.law = parse_optional_choice<Law>("law", law);
    o.gradients = parse_choice<fit::Gradients>("gradients", gradients);
    o.rtol = rtol;
    o.max_evaluations = static_cast<int>(arg_integer(max_evaluations.value, "max_evaluations", 1, 100000));
    const auto overrides = sigma_of(sigma);
    const std::string arg = arg_text(data, "data");
    py::gil_scoped_release release;
    PyFit out;
    out.obs = text ? fit::parse_observations(arg, "data", overrides) : fit::read_observations(arg, overrides);
    out.r = fit::fit_trajectory(scene, out.obs, o);
    return out;
  });
}

py::array_t<double> matrix(const std::vector<std::array<double, 3>>& rows) {
  py::array_t<double> a({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(3)});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < 3; ++j) m(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = rows[i][j];
  return a;
}

}  // namespace

namespace {

using FitClass = py::class_<PyFit>;

/// The estimates and the fit's quality: parameters, correlation, chi2, convergence, cost, accuracy.
void add_estimates(FitClass& cls) {
  cls
      .def_property_readonly("parameters",
                             [](const PyFit& f) {
                               py::dict d;
                               for (const auto& p : f.r.parameters) {
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
                             [](const PyFit& f) {
                               const auto n = static_cast<py::ssize_t>(f.r.correlation.size());
                               py::array_t<double> a({n, n});
                               auto cells = a.mutable_unchecked<2>();
                               for (py::ssize_t i = 0; i < n; ++i)
                                 for (py::ssize_t j = 0; j < n; ++j)
                                   cells(i, j) = f.r.correlation[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
                               return a;
                             })
      .def_property_readonly("chi2", [](const PyFit& f) { return f.r.chi2; })
      .def_property_readonly("chi2_dof", [](const PyFit& f) { return f.r.chi2_dof; })
      .def_property_readonly("dof", [](const PyFit& f) { return f.r.dof; })
      .def_property_readonly("converged", [](const PyFit& f) { return f.r.converged; })
      .def_property_readonly("status", [](const PyFit& f) { return f.r.status; })
      .def_property_readonly("iterations", [](const PyFit& f) { return f.r.iterations; })
      .def_property_readonly("n_forward_solves", [](const PyFit& f) { return f.r.n_forward_solves; })
      .def_property_readonly("gradients", [](const PyFit& f) { return to_string(f.r.gradients); })
      .def_property_readonly("law", [](const PyFit& f) { return f.r.law; })
      .def_property_readonly("accuracy",
                             [](const PyFit& f) -> py::object {
                               if (f.r.accuracy.requested <= 0) return py::none();
                               py::dict d;
                               d["requested"] = f.r.accuracy.requested;
                               d["rtol_used"] = f.r.accuracy.rtol_used;
                               d["estimate"] = f.r.accuracy.estimate;
                               d["reached"] = f.r.accuracy.reached;
                               return d;
                             });
}

/// What the data determine: identifiability, and the combinations that are determined.
void add_identifiability(FitClass& cls) {
  cls
      .def_property_readonly("identifiable", [](const PyFit& f) { return f.r.identifiability.identifiable; })
      .def_property_readonly("identifiability_message",
                             [](const PyFit& f) { return f.r.identifiability.message; })
      .def_property_readonly("determined",
                             [](const PyFit& f) {
                               py::list l;
                               for (const auto& c : f.r.identifiability.determined)
                                 l.append(py::make_tuple(c.name, c.value, c.stderr_relative));
                               return l;
                             });
}

/// The data and the model there: t, fitted, residuals, and the JSON summary.
void add_data(FitClass& cls) {
  cls
      .def_property_readonly("t",
                             [](const PyFit& f) {
                               py::array_t<double> a(static_cast<py::ssize_t>(f.r.t.size()));
                               std::copy(f.r.t.begin(), f.r.t.end(), a.mutable_data());
                               return a;
                             })
      .def_property_readonly("fitted", [](const PyFit& f) { return matrix(f.r.fitted); })
      .def_property_readonly("residuals", [](const PyFit& f) { return matrix(f.r.residuals); })
      .def_property_readonly("json", [](const PyFit& f) { return fit::fit_json(f.r); });
}

/// SciPy's and lmfit's names (names, x, stderr, covariance, success, nfev, message, ...).
void add_scipy_names(FitClass& cls) {
  cls
      .def_property_readonly("names",
                             [](const PyFit& f) {
                               std::vector<std::string> v;
                               for (const auto& p : f.r.parameters) v.push_back(p.key);
                               return v;
                             },
                             "The free keys, in the order of x, stderr, covariance and correlation.")
      .def_property_readonly("x",
                             [](const PyFit& f) { return per_parameter(f.r, &fit::ParameterEstimate::value); },
                             "The estimates, in the order of names (SciPy's x).")
      .def_property_readonly("stderr",
                             [](const PyFit& f) { return per_parameter(f.r, &fit::ParameterEstimate::stderr_); },
                             "Standard errors of x (NaN where the data do not determine a key).")
      .def_property_readonly("covariance", [](const PyFit& f) { return covariance(f.r); },
                             "Covariance of x: correlation[i, j] stderr[i] stderr[j] (k x k).")
      .def_property_readonly("success", [](const PyFit& f) { return f.r.converged; },
                             "True when the fit converged (= converged).")
      .def_property_readonly("nfev", [](const PyFit& f) { return f.r.n_forward_solves; },
                             "Forward solves of the model (= n_forward_solves).")
      .def_property_readonly("message", [](const PyFit& f) { return f.r.status; },
                             "The optimiser's words (= status).")
      .def_property_readonly("ndata", [](const PyFit& f) { return f.obs.count(); },
                             "Observed values (data points) fitted.")
      .def_property_readonly("observed", [](const PyFit& f) { return obs_matrix(f.obs, false); },
                             "The observations at t, (n, 3): x, y [m], theta [rad]; NaN where not observed.")
      .def_property_readonly("sigma", [](const PyFit& f) { return obs_matrix(f.obs, true); },
                             "Standard deviations of the observations, (n, 3); NaN where not observed.")
      .def_property_readonly("initial",
                             [](const PyFit& f) { return per_parameter(f.r, &fit::ParameterEstimate::start); },
                             "The starting values, in the order of names.")
      .def("__repr__", [](const PyFit& f) {
        std::string s = "<FitResult";
        for (const auto& p : f.r.parameters) s += " " + p.key + "=" + fmt(p.value) + " +- " + fmt(p.stderr_);
        return s + ", chi2/dof=" + fmt(f.r.chi2_dof) + (f.r.converged ? "" : ", NOT converged") + ">";
      });
}

}  // namespace

void register_fit(py::module_& m) {
  FitClass cls(m, "FitResult", R"doc(A trajectory fit (nanopush.fit; docs/fitting.md).

parameters   dict key -> {'value', 'stderr' (NaN when the data do not determine the key
             separately, or not converged), 'start', 'lower', 'upper', 'at_bound', 'unit'}
correlation  NumPy (k, k) correlation matrix of the estimates (NaN for undetermined keys)
chi2, chi2_dof, dof, converged, status, iterations, n_forward_solves, gradients, law
accuracy     with fit(accuracy=E): dict requested, rtol_used, estimate, reached; else None
identifiable, identifiability_message, determined (list of (name, value, stderr_relative))
t, fitted    observation times [s] and the model's pose (x, y, theta) there, NumPy (n, 3)
residuals    (observed - model) / sigma, NumPy (n, 3), NaN where not observed
json         the JSON summary of `nanopush fit --json`
SciPy/lmfit names: names, x, stderr, covariance, success (= converged), nfev
             (= n_forward_solves), message (= status), ndata, initial; observed and sigma
             (n, 3) the data fitted; report() and plot() (nanopush.fit's docs))doc");
  add_estimates(cls);
  add_identifiability(cls);
  add_data(cls);
  add_scipy_names(cls);

  m.def("_fit", &fit_scene, py::arg("scene"), py::arg("data"), py::arg("free"), py::kw_only(), py::arg("law") = "",
        py::arg("sigma") = py::none(), py::arg("gradients") = "auto", py::arg("rtol") = 1e-10,
        py::arg("max_evaluations") = 100, py::arg("accuracy") = -1.0, py::arg("text") = false,
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
      [](const Scene& scene, const std::array<double, 3>& sigma, const Whole& seed_arg, const std::string& law,
         const py::object& path) {
        // The range of `nanopush fit --synthesize --seed`.
        const auto seed = static_cast<std::uint64_t>(arg_integer(seed_arg.value, "seed", 0, 1LL << 62));
        std::string text;
        {
          py::gil_scoped_release release;
          text = bindings::with_argument_names({{"--law", "law"}}, [&] {
            return fit::observations_csv(fit::synthesize(scene, sigma, seed, parse_optional_choice<Law>("law", law)));
          });
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
