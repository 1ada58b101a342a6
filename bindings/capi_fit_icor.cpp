// C API: the friction coefficient from N quasi-static observations in batch (bindings/nanopush.h)
// over nanopush::icor::estimate_mu_batch (cxx/include/nanopush/models/icor_batch.hpp, the numbers
// of `nanopush fit-icor`). Everything is computed before anything is stored, so a failed call
// leaves every output untouched.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "capi_internal.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/models/icor_batch.hpp"

using namespace nanopush::capi;
namespace icor = nanopush::icor;

namespace {


/// value[i] (NaN: not observed) with sigma[i]; a NULL value array observes nothing.
std::optional<icor::Measured> measured(const double* value, const double* sigma, int i) {
  if (!value || std::isnan(value[i])) return std::nullopt;
  return icor::Measured{value[i], sigma[i]};
}

}  // namespace

extern "C" {

int nanopush_estimate_mu_batch(nanopush_error error, const double* rod, int n, const double* force,
                               const double* sigma_force, const double* yn, const double* sigma_yn, const double* R,
                               const double* sigma_R, int pressure, double sigma_L, double sigma_H, double alpha,
                               double* result, int* dof, int* consistent, double* rows, int* equations) {
  return guarded(error, [&] {
    const icor::Rod r = rod_from(rod);
    if (n < 1) throw nanopush::InputError("n", std::to_string(n), "must be >= 1 (observations)");
    require_handle(force, "force");
    require_handle(sigma_force, "sigma_force");
    if (yn) require_handle(sigma_yn, "sigma_yn");
    if (R) require_handle(sigma_R, "sigma_R");
    if (pressure != NANOPUSH_PRESSURE_KNOWN && pressure != NANOPUSH_PRESSURE_UNKNOWN)
      throw nanopush::InputError("pressure", std::to_string(pressure),
                                 "must be NANOPUSH_PRESSURE_KNOWN (0) or NANOPUSH_PRESSURE_UNKNOWN (1)");
    std::vector<icor::Observation> obs(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      obs[static_cast<std::size_t>(i)] = {{force[i], sigma_force[i]}, measured(yn, sigma_yn, i),
                                          measured(R, sigma_R, i)};
    }
    const auto b = icor::estimate_mu_batch(
        r, obs, pressure == NANOPUSH_PRESSURE_KNOWN ? icor::Pressure::Known : icor::Pressure::Unknown, sigma_L,
        sigma_H, alpha);
    const double res[NANOPUSH_BATCH_RESULT_SIZE] = {b.mu,     b.sigma,   b.sigma_stat, b.sigma_syst,
                                                    b.sigma_scaled, b.chi2, b.chi2_dof, b.p_value,
                                                    b.load,   b.dmu_dL,  b.dmu_dH};
    if (result) std::copy(res, res + NANOPUSH_BATCH_RESULT_SIZE, result);
    if (dof) *dof = b.dof;
    if (consistent) *consistent = b.consistent ? 1 : 0;
    for (int i = 0; i < n; ++i) {
      const auto& row = b.rows[static_cast<std::size_t>(i)];
      if (rows) {
        rows[i] = row.estimate.mu;
        rows[i + n] = row.estimate.sigma;
        rows[i + 2 * n] = row.weight;
        rows[i + 3 * n] = row.pull;
      }
      if (equations) equations[i] = row.equation == "4.8" ? 8 : row.equation == "4.10" ? 10 : 11;
    }
    return NANOPUSH_OK;
  });
}

}  // extern "C"
