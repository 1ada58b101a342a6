// Quasi-static friction estimates in batch (models/icor_batch.hpp; docs/fitting.md).
#include "nanopush/models/icor_batch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/special_functions/gamma.hpp>

#include "nanopush/numerics/error.hpp"

namespace nanopush::icor {

std::string to_string(Pressure p) { return std::string(name_of(p)); }

Pressure parse_pressure(const std::string& text, const std::string& field) {
  if (const auto p = choice_from_name<Pressure>(text)) return *p;
  throw InputError(field, text.empty() ? "\"\"" : text, "must be " + choice_names<Pressure>());
}

MuEstimate estimate_mu_unknown_pressure(const Rod& rod, Measured F, Measured R, Measured yn, double sigma_L,
                                        double sigma_H) {
  rod.validate();
  require_positive("F", F.value, "N");
  require_nonnegative("F uncertainty", F.sigma, "N");
  require_positive("R", R.value, "m");
  require_nonnegative("R uncertainty", R.sigma, "m");
  require_range("yn", yn.value, 0.0, rod.half_length(), "m; push point on the rod, at most b = L/2");
  require_nonnegative("yn uncertainty", yn.sigma, "m");
  require_nonnegative("L uncertainty", sigma_L, "m");
  require_nonnegative("H uncertainty", sigma_H, "J");
  const double b = rod.half_length(), W = rod.load(), r = R.value, q = b * b + r * r;
  MuEstimate e;
  e.load = W;
  e.mu = 2.0 * b * F.value * (r + yn.value) / (W * q);
  // d ln mu = dF/F + dR (1/(R+yn) - 2R/q) + dyn/(R+yn) - (b/q) dL - (F_vdw/(H W)) dH  (W proportional to L).
  e.contributions = {
      {"F", F.value, F.sigma, e.mu / F.value},
      {"R", r, R.sigma, e.mu * (1.0 / (r + yn.value) - 2.0 * r / q)},
      {"yn", yn.value, yn.sigma, e.mu / (r + yn.value)},
      {"L", rod.length, sigma_L, -e.mu * b / q},
      {"H", rod.hamaker, sigma_H, -e.mu * rod.vdw_force() / (rod.hamaker * W)},
  };
  return propagate_uncertainty(e);
}

RowEstimate estimate_row(const Rod& rod, const Observation& obs, Pressure pressure) {
  RowEstimate row;
  if (!obs.yn && !obs.R)
    throw InputError("yn/R", "neither given", "each observation needs yn (push offset) or R (iCOR distance)");
  if (pressure == Pressure::Known) {
    if (obs.R) {
      row.estimate = estimate_mu_from_icor(rod, obs.force, *obs.R);
      row.equation = "4.10";
    } else {
      row.estimate = estimate_mu_from_force(rod, obs.force, *obs.yn);
      row.equation = "4.8";
    }
  } else {
    if (!obs.yn)
      throw InputError("yn", "not given",
                       "the unknown pressure distribution (eq 4.11) needs the push offset yn of every observation");
    if (obs.R) {
      row.estimate = estimate_mu_unknown_pressure(rod, obs.force, *obs.R, *obs.yn);
      row.equation = "4.11";
    } else {
      row.estimate = estimate_mu_from_force(rod, obs.force, *obs.yn);  // eq 4.11 at eq 4.13 == eq 4.8
      row.equation = "4.8";
    }
  }
  return row;
}

namespace {
double derivative(const MuEstimate& e, const std::string& input) {
  for (const auto& c : e.contributions)
    if (c.input == input) return c.derivative;
  return 0.0;
}
}  // namespace

BatchEstimate estimate_mu_batch(const Rod& rod, const std::vector<Observation>& observations, Pressure pressure,
                                double sigma_L, double sigma_H, double alpha) {
  rod.validate();
  require_nonnegative("L uncertainty", sigma_L, "m");
  require_nonnegative("H uncertainty", sigma_H, "J");
  if (!(alpha > 0.0 && alpha < 1.0)) throw InputError("alpha", fmt(alpha), "must be in (0, 1)");
  if (observations.empty()) throw InputError("observations", "0", "need at least 1 observation");
  BatchEstimate b;
  b.pressure = pressure;
  b.load = rod.load();
  b.rows.reserve(observations.size());
  for (std::size_t i = 0; i < observations.size(); ++i) {
    const std::string where = "row " + std::to_string(i + 1) + ": ";
    try {
      b.rows.push_back(estimate_row(rod, observations[i], pressure));
    } catch (const InputError& e) {
      throw InputError(where + e.what());
    }
    const MuEstimate& e = b.rows.back().estimate;  // finite: estimate_mu_from_* refuse overflow
    if (!(e.sigma > 0.0))
      throw InputError(where + "sigma of mu = " + fmt(e.sigma) +
                       ": must be > 0 (give F, yn or R a standard uncertainty > 0)");
  }
  // Inverse-variance weights relative to the first row (a_i = sigma_1 / sigma_i), so that one
  // observation returns its own mu and sigma bit for bit and N equal ones sigma_1 / sqrt(N).
  const double ref = b.rows.front().estimate.sigma, mu0 = b.rows.front().estimate.mu;
  double S = 0.0;
  for (const auto& r : b.rows) {
    const double a = ref / r.estimate.sigma;
    S += a * a;
  }
  double shift = 0.0;
  for (auto& r : b.rows) {
    const double a = ref / r.estimate.sigma;
    r.weight = a * a / S;
    shift += r.weight * (r.estimate.mu - mu0);
    b.dmu_dL += r.weight * derivative(r.estimate, "L");
    b.dmu_dH += r.weight * derivative(r.estimate, "H");
  }
  b.mu = mu0 + shift;
  b.sigma_stat = ref / std::sqrt(S);
  for (auto& r : b.rows) {
    r.pull = (r.estimate.mu - b.mu) / r.estimate.sigma;
    b.chi2 += r.pull * r.pull;
  }
  b.dof = static_cast<int>(b.rows.size()) - 1;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  b.chi2_dof = b.dof > 0 ? b.chi2 / b.dof : nan;
  b.p_value = b.dof > 0 ? chi2_survival(b.chi2, b.dof) : nan;
  b.consistent = b.dof == 0 || b.p_value >= alpha;
  const double eL = b.dmu_dL * sigma_L, eH = b.dmu_dH * sigma_H;
  b.sigma_syst = std::sqrt(eL * eL + eH * eH);
  b.sigma = b.sigma_syst > 0.0 ? std::hypot(b.sigma_stat, b.sigma_syst) : b.sigma_stat;
  const double scaled = b.sigma_stat * std::sqrt(b.dof > 0 ? std::max(1.0, b.chi2_dof) : 1.0);
  b.sigma_scaled = b.sigma_syst > 0.0 ? std::hypot(scaled, b.sigma_syst) : scaled;
  return b;
}

double chi2_survival(double x, int k) {
  if (k < 1) throw InputError("chi2 degrees of freedom", std::to_string(k), "must be >= 1");
  if (!(x > 0.0)) return 1.0;
  if (std::isinf(x)) return 0.0;
  // Q(k/2, x/2), the regularised upper incomplete gamma function (Boost.Math; 0 on underflow).
  return boost::math::gamma_q(0.5 * k, 0.5 * x);
}

}  // namespace nanopush::icor
