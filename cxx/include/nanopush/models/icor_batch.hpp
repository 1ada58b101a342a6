// Quasi-static friction estimates in batch (thesis chapter 4, docs/models.md section D,
// docs/fitting.md "Quasi-static estimates in batch"): N observations of a pushed rod, each a
// push force F with the push offset yn and/or the observed iCOR distance R (all with standard
// uncertainties), give one mu per observation for each of the thesis' two pressure
// distributions; the per-observation values are combined by inverse-variance weighting (the
// weighted least-squares estimate of a common mu) with a chi^2 consistency check.
//
// Which equation each observation uses (b = L/2, W = m g + F_vdw, s = sqrt(b^2 + yn^2)):
//   known pressure   (thesis 4.2.3.1)  R observed: eq 4.10 inverted, mu = F b / (W R)
//                                      (the balance of forces; yn not needed, not used);
//                                      yn only:    eq 4.8 inverted, mu = F (s + yn) / (W b)
//                                      (F is the minimum force at yn).
//   unknown pressure (thesis 4.2.3.2)  R and yn:   eq 4.11 inverted,
//                                      mu = 2 b F (R + yn) / (W (b^2 + R^2)) (balance of moments);
//                                      yn only:    eq 4.11 at the iCOR of eq 4.13, which is
//                                      algebraically eq 4.8 (computed as eq 4.8);
//                                      R only:     InputError (eq 4.11 needs yn).
// With data on the line-contact model (R on eq 4.13, F the minimum force) all of them agree.
//
// Uncertainty: each observation's sigma is first-order propagation of the sigmas of F, yn and
// R (uncorrelated). The rod's length and Hamaker constant are common to every observation, so
// their sigmas are systematic: they are propagated through the combined value (weights held
// fixed) and added in quadrature after the combination, never divided by sqrt(N).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "nanopush/models/icor.hpp"

namespace nanopush::icor {

enum class Pressure {
  Known,    ///< thesis section 4.2.3.1: eqs 4.8 / 4.10
  Unknown,  ///< thesis section 4.2.3.2: eqs 4.11 / 4.13
};
}  // namespace nanopush::icor
namespace nanopush {
NANOPUSH_NAMES(icor::Pressure, {icor::Pressure::Known, "known"}, {icor::Pressure::Unknown, "unknown"});
}  // namespace nanopush
namespace nanopush::icor {
std::string to_string(Pressure p);
/// "known" | "unknown"; anything else throws InputError naming `field`.
Pressure parse_pressure(const std::string& text, const std::string& field = "pressure");

/// One observation: the push force and at least one of yn (push offset from the CM along the
/// rod, 0..b) and R (observed distance from the CM to the iCOR, > 0). SI.
struct Observation {
  Measured force;
  std::optional<Measured> yn;
  std::optional<Measured> R;
};

/// mu from one observation by eq 4.11 inverted (unknown pressure, balance of moments):
/// mu = 2 b F (R + yn) / (W (b^2 + R^2)); contributions F, R, yn, L, H (in that order).
MuEstimate estimate_mu_unknown_pressure(const Rod& rod, Measured F, Measured R, Measured yn, double sigma_L = 0.0,
                                        double sigma_H = 0.0);

/// One observation's estimate: the MuEstimate of its equation with the rod's L and H taken
/// as exact (their sigmas are applied to the combination), and which equation it was.
struct RowEstimate {
  MuEstimate estimate;
  std::string equation;  ///< "4.8", "4.10" or "4.11"
  double weight = 0.0;   ///< normalised inverse-variance weight, sum over rows = 1
  double pull = 0.0;     ///< (mu_i - combined mu) / sigma_i
};

/// mu of one observation for one distribution (the table above); InputError for a missing
/// quantity or an observation outside the equation's range, naming the quantity.
RowEstimate estimate_row(const Rod& rod, const Observation& obs, Pressure pressure);

struct BatchEstimate {
  Pressure pressure = Pressure::Known;
  std::vector<RowEstimate> rows;
  double mu = 0.0;           ///< inverse-variance weighted mean of the rows' mu
  double sigma_stat = 0.0;   ///< 1 / sqrt(sum 1/sigma_i^2): from the observations' sigmas alone
  double dmu_dL = 0.0;       ///< d mu / d L of the combination (weights fixed) [1/m]
  double dmu_dH = 0.0;       ///< d mu / d H [1/J]
  double sigma_syst = 0.0;   ///< sqrt((dmu_dL sigma_L)^2 + (dmu_dH sigma_H)^2)
  double sigma = 0.0;        ///< sqrt(sigma_stat^2 + sigma_syst^2): the standard uncertainty
  double chi2 = 0.0;         ///< sum ((mu_i - mu) / sigma_i)^2
  int dof = 0;               ///< N - 1
  double chi2_dof = 0.0;     ///< chi2 / dof (NaN for N = 1)
  double p_value = 0.0;      ///< P(chi^2_dof >= chi2) if the sigmas are right (NaN for N = 1)
  bool consistent = true;    ///< p_value >= alpha (true for N = 1: nothing to check)
  double sigma_scaled = 0.0; ///< sigma_stat sqrt(max(1, chi2_dof)) (+ syst.): Birge-scaled, for inconsistent data
  double load = 0.0;         ///< W [N]
};

/// Combine N >= 1 observations for one pressure distribution. Each observation's sigma must
/// come out > 0 (else InputError naming the row); alpha in (0, 1) is the significance level
/// of the consistency check. Rows are numbered from 1 in messages ("row 3: ...").
BatchEstimate estimate_mu_batch(const Rod& rod, const std::vector<Observation>& observations, Pressure pressure,
                                double sigma_L = 0.0, double sigma_H = 0.0, double alpha = 0.01);

/// Upper tail of the chi-square distribution with k >= 1 degrees of freedom, P(X >= x): the
/// regularised upper incomplete gamma function Q(k/2, x/2) (Boost.Math gamma_q); 1 for x <= 0.
double chi2_survival(double x, int k);

}  // namespace nanopush::icor
