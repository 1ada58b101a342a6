// nanopush_estimate_mu_batch (bindings/nanopush.h) returns exactly the numbers of
// icor::estimate_mu_batch (bit for bit), NaN in yn or R means "not observed", and bad input comes
// back as a status and a message naming the row, with every output untouched.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "../support/capi_check.hpp"
#include "nanopush.h"
#include "nanopush/models/icor.hpp"
#include "nanopush/models/icor_batch.hpp"

namespace {

using nanopush_capi_test::check;
using nanopush_capi_test::message;
using nanopush_capi_test::same;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

int main() {
  namespace icor = nanopush::icor;
  double rod[6];
  nanopush_error err = nanopush_new_error();
  check(nanopush_icor_nanorod(err, rod) == NANOPUSH_OK, "nanorod");
  const int n = 5;
  const double F[n] = {8.5e-7, 6.8e-7, 5.3e-7, 4.3e-7, 6.0e-7};
  const double sF[n] = {1.7e-8, 1.4e-8, 1.1e-8, 0.9e-8, 1.2e-8};
  const double yn[n] = {50e-9, 120e-9, 200e-9, 280e-9, kNaN};
  const double sy[n] = {2e-9, 2e-9, 2e-9, 2e-9, 2e-9};
  const double R[n] = {249e-9, kNaN, 156e-9, 127e-9, 180e-9};
  const double sR[n] = {3e-9, 3e-9, 3e-9, 3e-9, 3e-9};
  const icor::Rod r = icor::nanorod();
  std::vector<icor::Observation> obs;
  for (int i = 0; i < n; ++i) {
    icor::Observation o{{F[i], sF[i]}, std::nullopt, std::nullopt};
    if (!std::isnan(yn[i])) o.yn = icor::Measured{yn[i], sy[i]};
    if (!std::isnan(R[i])) o.R = icor::Measured{R[i], sR[i]};
    obs.push_back(o);
  }

  // Known pressure over all five rows: bit for bit.
  {
    const auto b = icor::estimate_mu_batch(r, obs, icor::Pressure::Known, 5e-9, 2e-20, 0.05);
    double res[NANOPUSH_BATCH_RESULT_SIZE], rows[4 * n];
    int dof = -1, consistent = -1, eq[n];
    check(nanopush_estimate_mu_batch(err, rod, n, F, sF, yn, sy, R, sR, NANOPUSH_PRESSURE_KNOWN, 5e-9, 2e-20, 0.05,
                                     res, &dof, &consistent, rows, eq) == NANOPUSH_OK,
          "known: status");
    const double want[NANOPUSH_BATCH_RESULT_SIZE] = {b.mu,   b.sigma,    b.sigma_stat, b.sigma_syst,
                                                     b.sigma_scaled, b.chi2, b.chi2_dof, b.p_value,
                                                     b.load, b.dmu_dL,   b.dmu_dH};
    for (int k = 0; k < NANOPUSH_BATCH_RESULT_SIZE; ++k) check(same(res[k], want[k]), "known: result " + std::to_string(k));
    check(dof == n - 1, "known: dof");
    check(consistent == (b.consistent ? 1 : 0), "known: consistent");
    for (int i = 0; i < n; ++i) {
      const auto& row = b.rows[static_cast<std::size_t>(i)];
      check(same(rows[i], row.estimate.mu) && same(rows[i + n], row.estimate.sigma) &&
                same(rows[i + 2 * n], row.weight) && same(rows[i + 3 * n], row.pull),
            "known: row " + std::to_string(i + 1));
    }
    check(eq[0] == 10 && eq[1] == 8 && eq[4] == 10, "known: equations 4.10 with R, 4.8 without");
  }
  // Unknown pressure over the rows with yn (the first four): bit for bit, all outputs optional.
  {
    std::vector<icor::Observation> four(obs.begin(), obs.begin() + 4);
    const auto b = icor::estimate_mu_batch(r, four, icor::Pressure::Unknown);
    double res[NANOPUSH_BATCH_RESULT_SIZE];
    int eq[4];
    check(nanopush_estimate_mu_batch(err, rod, 4, F, sF, yn, sy, R, sR, NANOPUSH_PRESSURE_UNKNOWN, 0, 0, 0.01, res,
                                     nullptr, nullptr, nullptr, eq) == NANOPUSH_OK,
          "unknown: status");
    check(same(res[0], b.mu) && same(res[1], b.sigma) && same(res[6], b.chi2_dof), "unknown: mu, sigma, chi2/dof");
    check(eq[0] == 11 && eq[1] == 8, "unknown: equations 4.11 with R, 4.8 without");
    // no R array at all: every row by eq 4.8
    check(nanopush_estimate_mu_batch(err, rod, 4, F, sF, yn, sy, nullptr, nullptr, NANOPUSH_PRESSURE_UNKNOWN, 0, 0,
                                     0.01, res, nullptr, nullptr, nullptr, eq) == NANOPUSH_OK &&
              eq[0] == 8 && eq[3] == 8,
          "unknown: R = NULL");
    // one observation = nanopush_estimate_mu_from_icor
    double mu1 = 0, s1 = 0;
    check(nanopush_estimate_mu_from_icor(err, rod, F[0], sF[0], R[0], sR[0], 0, 0, &mu1, &s1, nullptr, nullptr) ==
              NANOPUSH_OK,
          "single: from_icor");
    check(nanopush_estimate_mu_batch(err, rod, 1, F, sF, nullptr, nullptr, R, sR, NANOPUSH_PRESSURE_KNOWN, 0, 0, 0.01,
                                     res, nullptr, nullptr, nullptr, nullptr) == NANOPUSH_OK &&
              res[0] == mu1 && res[1] == s1 && std::isnan(res[6]),
          "single observation = nanopush_estimate_mu_from_icor, chi2/dof NaN");
  }
  // Bad input: status, message naming the row, outputs untouched.
  {
    double res[NANOPUSH_BATCH_RESULT_SIZE];
    for (double& x : res) x = 42.0;
    nanopush_clear_error(err);
    // unknown pressure: row 5 has no yn
    check(nanopush_estimate_mu_batch(err, rod, n, F, sF, yn, sy, R, sR, NANOPUSH_PRESSURE_UNKNOWN, 0, 0, 0.01, res,
                                     nullptr, nullptr, nullptr, nullptr) == NANOPUSH_BAD_INPUT,
          "unknown without yn: status");
    check(message(err).find("row 5: yn = not given") == 0, "unknown without yn: message " + message(err));
    check(res[0] == 42.0 && res[10] == 42.0, "failed call writes nothing");
    const double bad_sF[n] = {1.7e-8, 1.4e-8, 0.0, 0.9e-8, 1.2e-8};
    const double zero_sy[n] = {0, 0, 0, 0, 0};
    nanopush_clear_error(err);
    check(nanopush_estimate_mu_batch(err, rod, n, F, bad_sF, yn, zero_sy, nullptr, nullptr, NANOPUSH_PRESSURE_KNOWN,
                                     0, 0, 0.01, res, nullptr, nullptr, nullptr, nullptr) == NANOPUSH_BAD_INPUT &&
              message(err).find("row 3: sigma of mu = 0: must be > 0") == 0,
          "zero sigma: " + message(err));
    nanopush_clear_error(err);
    check(nanopush_estimate_mu_batch(err, rod, n, F, sF, yn, nullptr, R, sR, NANOPUSH_PRESSURE_KNOWN, 0, 0, 0.01,
                                     res, nullptr, nullptr, nullptr, nullptr) == NANOPUSH_NULL_HANDLE,
          "yn without sigma_yn: NULL handle");
    check(nanopush_estimate_mu_batch(nullptr, rod, 0, F, sF, yn, sy, R, sR, NANOPUSH_PRESSURE_KNOWN, 0, 0, 0.01, res,
                                     nullptr, nullptr, nullptr, nullptr) == NANOPUSH_BAD_INPUT,
          "n = 0: bad input (NULL error handle allowed)");
    nanopush_clear_error(err);
    check(nanopush_estimate_mu_batch(err, rod, n, F, sF, yn, sy, R, sR, 7, 0, 0, 0.01, res, nullptr, nullptr, nullptr,
                                     nullptr) == NANOPUSH_BAD_INPUT &&
              message(err).find("pressure = 7") == 0,
          "bad pressure: " + message(err));
    check(nanopush_estimate_mu_batch(err, rod, n, F, sF, yn, sy, R, sR, 0, 0, 0, 1.0, res, nullptr, nullptr, nullptr,
                                     nullptr) == NANOPUSH_BAD_INPUT,
          "alpha = 1: bad input");
    check(res[0] == 42.0, "failed calls write nothing");
  }
  nanopush_delete_error(&err);
  return nanopush_capi_test::finish("capi fit-icor: all checks hold");
}
