// Quasi-static friction estimates in batch (issue 21 item 3; models/icor_batch.hpp): against
// the one-observation estimates bit for bit, sqrt(N) shrinking, finite differences of the new
// eq 4.11 inverse, synthetic data from the forward iCOR model with seeded noise, a Monte Carlo
// check of the first-order sigma, and the chi-square tail against tabulated quantiles.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "nanopush/models/icor.hpp"
#include "nanopush/models/icor_batch.hpp"
#include "nanopush/numerics/error.hpp"

using namespace nanopush;
using icor::Measured;
using icor::Observation;
using icor::Pressure;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

double sample_std(const std::vector<double>& v) { return icor::sample_std(v); }

double derivative_of(const icor::MuEstimate& e, const std::string& input) {
  for (const auto& c : e.contributions)
    if (c.input == input) return c.derivative;
  FAIL("no contribution " << input);
  return 0.0;
}

}  // namespace

TEST_CASE("icor_batch.single_observation_is_the_existing_estimate", "[icor_batch][unit]") {
  const icor::Rod rod = icor::nanorod();
  const Measured F{1e-6, 3e-8}, yn{200e-9, 5e-9}, R{150e-9, 4e-9};
  // known, R: eq 4.10 == estimate_mu_from_icor
  {
    const auto b = icor::estimate_mu_batch(rod, {{F, std::nullopt, R}}, Pressure::Known);
    const auto e = icor::estimate_mu_from_icor(rod, F, R);
    CHECK(b.mu == e.mu);
    CHECK(b.sigma == e.sigma);
    CHECK(b.sigma_stat == e.sigma);
    CHECK(b.rows.at(0).equation == "4.10");
    CHECK(b.dof == 0);
    CHECK(std::isnan(b.chi2_dof));
    CHECK(b.consistent);
  }
  // known and unknown, yn only: eq 4.8 == estimate_mu_from_force
  for (Pressure p : {Pressure::Known, Pressure::Unknown}) {
    const auto b = icor::estimate_mu_batch(rod, {{F, yn, std::nullopt}}, p);
    const auto e = icor::estimate_mu_from_force(rod, F, yn);
    CHECK(b.mu == e.mu);
    CHECK(b.sigma == e.sigma);
  }
  // with the rod's systematic sigmas: the total is the existing estimate's (to rounding)
  {
    const double sL = 10e-9, sH = 3e-20;
    const auto b = icor::estimate_mu_batch(rod, {{F, yn, std::nullopt}}, Pressure::Known, sL, sH);
    const auto e = icor::estimate_mu_from_force(rod, F, yn, sL, sH);
    CHECK(b.mu == e.mu);
    CHECK(b.sigma == Approx(e.sigma).epsilon(1e-14));
    CHECK(b.dmu_dL == derivative_of(e, "L"));
    CHECK(b.dmu_dH == derivative_of(e, "H"));
  }
}

TEST_CASE("icor_batch.identical_observations_shrink_sigma_by_sqrt_n", "[icor_batch][unit]") {
  const icor::Rod rod = icor::nanorod();
  const Observation o{{1e-6, 3e-8}, Measured{100e-9, 5e-9}, Measured{180e-9, 6e-9}};
  for (Pressure p : {Pressure::Known, Pressure::Unknown}) {
    const auto one = icor::estimate_mu_batch(rod, {o}, p);
    for (int n : {2, 9, 100}) {
      const auto b = icor::estimate_mu_batch(rod, std::vector<Observation>(n, o), p, 5e-9, 1e-20);
      CHECK(b.mu == one.mu);
      CHECK(b.sigma_stat == Approx(one.sigma / std::sqrt(n)).epsilon(1e-14));
      CHECK(b.chi2 == 0.0);
      CHECK(b.p_value == 1.0);
      CHECK(b.consistent);
      // the systematic part does not shrink
      const auto b1 = icor::estimate_mu_batch(rod, {o}, p, 5e-9, 1e-20);
      CHECK(b.sigma_syst == Approx(b1.sigma_syst).epsilon(1e-14));
    }
  }
}

TEST_CASE("icor_batch.unknown_pressure_inverse_and_its_derivatives", "[icor_batch][numeric]") {
  icor::Rod rod = icor::nanorod();
  const double b = rod.half_length();
  // At the iCOR of eq 4.13, eq 4.11 inverted is eq 4.8 inverted (same mu), for every yn.
  for (double yn : {0.0, 1e-9, 50e-9, 200e-9, b}) {
    const double R = icor::unknown_pressure(yn, rod.length);
    const auto u = icor::estimate_mu_unknown_pressure(rod, {1e-6, 0}, {R, 0}, {yn, 0});
    const auto f = icor::estimate_mu_from_force(rod, {1e-6, 0}, {yn, 0});
    CHECK(u.mu == Approx(f.mu).epsilon(1e-14));
    // and the forward eq 4.11 at that mu gives back the force
    CHECK(icor::force_unknown_pressure(u.mu, rod.load(), R, yn, rod.length) == Approx(1e-6).epsilon(1e-14));
  }
  // Derivatives against central finite differences (F, R, yn, L, H).
  const double F = 7e-7, R = 140e-9, yn = 90e-9;
  const auto e = icor::estimate_mu_unknown_pressure(rod, {F, 0}, {R, 0}, {yn, 0});
  auto mu = [&](double f, double r, double y, double L, double H) {
    icor::Rod x = rod;
    x.length = L;
    x.hamaker = H;
    return icor::estimate_mu_unknown_pressure(x, {f, 0}, {r, 0}, {y, 0}).mu;
  };
  const double h = 1e-5;
  const double L = rod.length, H = rod.hamaker;
  CHECK(derivative_of(e, "F") ==
        Approx((mu(F * (1 + h), R, yn, L, H) - mu(F * (1 - h), R, yn, L, H)) / (2 * h * F)).epsilon(1e-8));
  CHECK(derivative_of(e, "R") ==
        Approx((mu(F, R * (1 + h), yn, L, H) - mu(F, R * (1 - h), yn, L, H)) / (2 * h * R)).epsilon(1e-8));
  CHECK(derivative_of(e, "yn") ==
        Approx((mu(F, R, yn * (1 + h), L, H) - mu(F, R, yn * (1 - h), L, H)) / (2 * h * yn)).epsilon(1e-8));
  CHECK(derivative_of(e, "L") ==
        Approx((mu(F, R, yn, L * (1 + h), H) - mu(F, R, yn, L * (1 - h), H)) / (2 * h * L)).epsilon(1e-7));
  CHECK(derivative_of(e, "H") ==
        Approx((mu(F, R, yn, L, H * (1 + h)) - mu(F, R, yn, L, H * (1 - h))) / (2 * h * H)).epsilon(1e-7));
}

TEST_CASE("icor_batch.synthetic_data_within_three_sigma", "[icor_batch][numeric]") {
  // Forward model: the line-contact quasi-static push (iCOR of eq 4.13, minimum force of
  // eq 4.8 = 4.10 = 4.11 there), seeded Gaussian noise on F (2 %), yn (3 nm), R (3 nm).
  const icor::Rod rod = icor::nanorod();
  const double b = rod.half_length(), W = rod.load();
  for (double mu_true : {0.05, 0.3}) {
    for (unsigned seed : {1u, 2u, 3u}) {
      std::mt19937_64 gen(seed);
      std::uniform_real_distribution<double> where(0.1 * b, 0.95 * b);
      std::normal_distribution<double> z(0.0, 1.0);
      std::vector<Observation> obs;
      for (int i = 0; i < 25; ++i) {
        const double yn = where(gen), R = icor::unknown_pressure(yn, rod.length);
        const double F = icor::minimum_force(mu_true, W, yn, rod.length);
        const double sF = 0.02 * F, sy = 3e-9, sR = 3e-9;
        obs.push_back({{F + sF * z(gen), sF}, Measured{yn + sy * z(gen), sy}, Measured{R + sR * z(gen), sR}});
      }
      for (Pressure p : {Pressure::Known, Pressure::Unknown}) {
        const auto est = icor::estimate_mu_batch(rod, obs, p);
        INFO("mu_true " << mu_true << " seed " << seed << " " << icor::to_string(p) << ": mu = " << est.mu
                        << " +- " << est.sigma << ", chi2/dof " << est.chi2_dof);
        CHECK(std::fabs(est.mu - mu_true) < 3.0 * est.sigma);
        CHECK(est.p_value > 1e-3);
        CHECK(est.sigma < 0.05 * mu_true);
      }
    }
  }
}

TEST_CASE("icor_batch.first_order_sigma_against_monte_carlo", "[icor_batch][numeric]") {
  const icor::Rod rod = icor::nanorod();
  const double F = 8e-7, R = 120e-9, yn = 150e-9;
  const Measured mF{F, 0.02 * F}, mR{R, 3e-9}, my{yn, 3e-9};
  std::mt19937_64 gen(42);
  std::normal_distribution<double> z(0.0, 1.0);
  // One observation, each distribution: the spread of mu over noisy inputs.
  for (Pressure p : {Pressure::Known, Pressure::Unknown}) {
    const auto first = icor::estimate_row(rod, {mF, my, mR}, p).estimate;
    std::vector<double> mus;
    for (int k = 0; k < 4000; ++k) {
      const Observation o{{F + mF.sigma * z(gen), mF.sigma}, Measured{yn + my.sigma * z(gen), my.sigma},
                          Measured{R + mR.sigma * z(gen), mR.sigma}};
      mus.push_back(icor::estimate_row(rod, o, p).estimate.mu);
    }
    // sampling error of a standard deviation from 4000 draws: about 1.1 %
    CHECK(sample_std(mus) == Approx(first.sigma).epsilon(0.05));
  }
  // The combination of 10 observations: the spread of the combined mu over 400 batches.
  std::vector<double> combined;
  double sigma_stat = 0.0;
  for (int k = 0; k < 400; ++k) {
    std::vector<Observation> obs;
    for (int i = 0; i < 10; ++i)
      obs.push_back({{F + mF.sigma * z(gen), mF.sigma}, Measured{yn + my.sigma * z(gen), my.sigma},
                     Measured{R + mR.sigma * z(gen), mR.sigma}});
    const auto b = icor::estimate_mu_batch(rod, obs, Pressure::Unknown);
    combined.push_back(b.mu);
    sigma_stat += b.sigma_stat / 400.0;
  }
  // sampling error from 400 batches: about 3.5 %
  CHECK(sample_std(combined) == Approx(sigma_stat).epsilon(0.12));
}

TEST_CASE("icor_batch.inconsistent_observations_are_flagged", "[icor_batch][unit]") {
  const icor::Rod rod = icor::nanorod();
  const Measured R{150e-9, 2e-9};
  std::vector<Observation> obs = {{{1e-6, 1e-8}, std::nullopt, R}, {{1.3e-6, 1e-8}, std::nullopt, R}};
  const auto b = icor::estimate_mu_batch(rod, obs, Pressure::Known);
  CHECK_FALSE(b.consistent);
  CHECK(b.p_value < 1e-6);
  CHECK(b.sigma_scaled > 3.0 * b.sigma_stat);
  CHECK(b.rows[0].pull < 0.0);
  CHECK(b.rows[1].pull > 0.0);
  CHECK(b.rows[0].weight + b.rows[1].weight == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("icor_batch.bad_observations_name_the_row", "[icor_batch][unit]") {
  const icor::Rod rod = icor::nanorod();
  const Observation good{{1e-6, 1e-8}, Measured{1e-7, 1e-9}, std::nullopt};
  const Observation no_sigma{{1e-6, 0.0}, Measured{1e-7, 0.0}, std::nullopt};
  CHECK_THROWS_WITH(icor::estimate_mu_batch(rod, {good, no_sigma}, Pressure::Known),
                    Catch::Contains("row 2: sigma of mu = 0: must be > 0"));
  const Observation only_R{{1e-6, 1e-8}, std::nullopt, Measured{1e-7, 1e-9}};
  CHECK_THROWS_WITH(icor::estimate_mu_batch(rod, {only_R}, Pressure::Unknown),
                    Catch::Contains("row 1: yn = not given"));
  const Observation beyond{{1e-6, 1e-8}, Measured{400e-9, 1e-9}, std::nullopt};
  CHECK_THROWS_WITH(icor::estimate_mu_batch(rod, {good, good, beyond}, Pressure::Known),
                    Catch::Contains("row 3: yn = 4e-07: must be in [0, 2.95e-07]"));
  CHECK_THROWS_AS(icor::estimate_mu_batch(rod, {}, Pressure::Known), InputError);
  CHECK_THROWS_AS(icor::parse_pressure("both"), InputError);
}

TEST_CASE("icor_batch.chi2_survival_against_tables", "[icor_batch][numeric]") {
  // 5 % upper quantiles (NIST/SEMATECH table) for 1, 2, 3, 10 and 25 degrees of freedom
  CHECK(icor::chi2_survival(3.841458820694124, 1) == Approx(0.05).epsilon(1e-9));
  CHECK(icor::chi2_survival(5.991464547107979, 2) == Approx(0.05).epsilon(1e-9));
  CHECK(icor::chi2_survival(7.814727903251178, 3) == Approx(0.05).epsilon(1e-9));
  CHECK(icor::chi2_survival(18.307038053275146, 10) == Approx(0.05).epsilon(1e-9));
  CHECK(icor::chi2_survival(37.65248413348277, 25) == Approx(0.05).epsilon(1e-9));
  // k = 2: exactly exp(-x/2)
  for (double x : {0.1, 1.0, 10.0, 100.0}) CHECK(icor::chi2_survival(x, 2) == Approx(std::exp(-x / 2)).epsilon(1e-14));
  CHECK(icor::chi2_survival(0.0, 4) == 1.0);
  CHECK(icor::chi2_survival(1e4, 7) == 0.0);
  CHECK(icor::chi2_survival(2000.0, 2000) == Approx(0.4958).margin(1e-3));
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
