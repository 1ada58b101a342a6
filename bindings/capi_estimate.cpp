// C API: the friction coefficient from measurements (bindings/nanopush.h) over
// nanopush::icor::estimate_mu_from_force / estimate_mu_from_icor (cxx/include/nanopush/models/icor.hpp,
// the numbers of `nanopush icor estimate-mu`). Everything is computed before anything is stored, so a
// failed call leaves every output untouched.
#include <algorithm>
#include <string>

#include "capi_internal.hpp"
#include "nanopush/models/icor.hpp"

using namespace nanopush::capi;
namespace icor = nanopush::icor;

namespace {


/// d mu / d input of the contribution named `input` (the library names them "F", "yn", "R", "L",
/// "H"); mapped by name so the C order never depends on the order of the C++ vector.
double derivative(const icor::MuEstimate& e, const char* input) {
  const auto it = std::find_if(e.contributions.begin(), e.contributions.end(),
                               [&](const icor::Contribution& c) { return c.input == input; });
  if (it == e.contributions.end())
    throw StatusError(NANOPUSH_INTERNAL, std::string("mu estimate: no contribution named ") + input);
  return it->derivative;
}

/// The estimator `library` (icor::estimate_mu_from_force or _from_icor) on the measured push force
/// and the second input (yn or R, named `second`), computed in full before anything is stored:
/// mu, sigma, load and derivatives[4] = d mu / d (F, second input, L, H). Any output may be NULL.
int estimate(nanopush_error error, icor::MuEstimate (*library)(const icor::Rod&, icor::Measured, icor::Measured,
                                                               double, double),
             const char* second, const double* rod, icor::Measured force, icor::Measured x, double sigma_L,
             double sigma_H, double* mu, double* sigma, double* load, double* derivatives) {
  return guarded(error, [&] {
    const icor::MuEstimate e = library(rod_from(rod), force, x, sigma_L, sigma_H);
    const double d[4] = {derivative(e, "F"), derivative(e, second), derivative(e, "L"), derivative(e, "H")};
    if (mu) *mu = e.mu;
    if (sigma) *sigma = e.sigma;
    if (load) *load = e.load;
    if (derivatives) std::copy(d, d + 4, derivatives);
    return NANOPUSH_OK;
  });
}

}  // namespace

extern "C" {

int nanopush_estimate_mu_from_force(nanopush_error error, const double* rod, double force, double sigma_force,
                                    double yn, double sigma_yn, double sigma_L, double sigma_H, double* mu,
                                    double* sigma, double* load, double* derivatives) {
  return estimate(error, icor::estimate_mu_from_force, "yn", rod, {force, sigma_force}, {yn, sigma_yn}, sigma_L,
                  sigma_H, mu, sigma, load, derivatives);
}

int nanopush_estimate_mu_from_icor(nanopush_error error, const double* rod, double force, double sigma_force,
                                   double R, double sigma_R, double sigma_L, double sigma_H, double* mu,
                                   double* sigma, double* load, double* derivatives) {
  return estimate(error, icor::estimate_mu_from_icor, "R", rod, {force, sigma_force}, {R, sigma_R}, sigma_L, sigma_H,
                  mu, sigma, load, derivatives);
}

}  // extern "C"
