// C API: the trajectory fit (bindings/nanopush.h) over nanopush::fit::fit_trajectory
// (cxx/include/nanopush/fitting/fit.hpp, the numbers of `nanopush fit`). Everything is computed
// before anything is stored, so a failed call leaves every output untouched.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "capi_internal.hpp"
#include "nanopush/fitting/fit.hpp"

using namespace nanopush::capi;
namespace fit = nanopush::fit;

namespace {

/// "a,b , c" -> {"a", "b", "c"} (blanks around items dropped, empty items refused).
std::vector<std::string> split_list(const std::string& text, const char* field) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string item = text.substr(start, comma - start);
    const auto a = item.find_first_not_of(" \t"), b = item.find_last_not_of(" \t");
    item = a == std::string::npos ? std::string() : item.substr(a, b - a + 1);
    if (item.empty()) throw nanopush::InputError(field, "\"" + text + "\"", "must be a comma-separated list of names");
    out.push_back(item);
    start = comma + 1;
  }
  return out;
}

/// "x=2e-9,theta=0.01" -> {x: 2e-9, theta: 0.01}.
fit::SigmaOverrides sigma_overrides(const char* text) {
  fit::SigmaOverrides out;
  if (!text || !*text) return out;
  for (const auto& item : split_list(text, "sigma")) {
    const auto eq = item.find('=');
    char* end = nullptr;
    const double v = eq == std::string::npos ? 0.0 : std::strtod(item.c_str() + eq + 1, &end);
    if (eq == std::string::npos || eq == 0 || end == item.c_str() + eq + 1 || *end != '\0' || !std::isfinite(v))
      throw nanopush::InputError("sigma", item, "must be COLUMN=VALUE (x, y or theta; standard deviation, SI)");
    out[item.substr(0, eq)] = v;
  }
  return out;
}

}  // namespace

extern "C" {

int nanopush_fit_trajectory(nanopush_error error, nanopush_scene scene, const char* data_path, const char* free_keys,
                            const char* law, const char* sigma, int nfree, double* values, double* stderrs,
                            double* summary, int* converged, char* json, int json_size, int* json_length) {
  // The library names some inputs as `nanopush fit` does (--free, --law, --sigma, DATA): here
  // they are this function's arguments.
  return guarded(error, [&] {
    return nanopush::bindings::with_argument_names(
        {{"--free", "free_keys"}, {"--law", "law"}, {"--sigma", "sigma"}, {"DATA", "data_path"}}, [&] {
      require_handle(scene, "scene");
      require_handle(data_path, "data_path");
      require_handle(free_keys, "free_keys");
      if (json_size < 0) throw nanopush::InputError("json_size", std::to_string(json_size), "must be >= 0");
      if (json_size > 0) require_handle(json, "json");
      fit::FitOptions o;
      o.free = split_list(free_keys, "free_keys");
      o.law = nanopush::parse_optional_choice<nanopush::Law>("law", opt_string(law));
      if (nfree < static_cast<int>(o.free.size()))
        throw StatusError(NANOPUSH_BUFFER_TOO_SMALL, "nfree = " + std::to_string(nfree) + ": values and stderrs hold " +
                                                         "fewer than the " + std::to_string(o.free.size()) + " free keys");
      const fit::Observations obs = fit::read_observations(data_path, sigma_overrides(sigma));
      const fit::FitResult r = fit::fit_trajectory(scene->scene, obs, o);
      const std::string text = fit::fit_json(r);
      // everything computed: store
      for (std::size_t k = 0; k < r.parameters.size(); ++k) {
        if (values) values[k] = r.parameters[k].value;
        if (stderrs) stderrs[k] = r.parameters[k].stderr_;
      }
      if (summary) {
        const double s[NANOPUSH_FIT_SUMMARY_SIZE] = {r.chi2,
                                                     r.chi2_dof,
                                                     static_cast<double>(r.dof),
                                                     static_cast<double>(r.iterations),
                                                     static_cast<double>(r.n_forward_solves),
                                                     r.identifiability.identifiable ? 1.0 : 0.0};
        std::copy(s, s + NANOPUSH_FIT_SUMMARY_SIZE, summary);
      }
      if (converged) *converged = r.converged ? 1 : 0;
      const int len = copy_string(text, json, json_size);
      if (json_length) *json_length = len;
      return NANOPUSH_OK;
    });
  });
}

}  // extern "C"
