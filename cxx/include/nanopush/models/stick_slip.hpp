// The `coulomb` friction law: event-located stick–slip for the rough-surface nanobar
// (docs/models.md §C). docs/stick_slip.md gives the mechanics; in short:
//
//  * Sliding: the friction wrench depends only on the direction of the rigid velocity
//    V = (vx, vy, omega) and is continuous (C^1) in it while V != 0 (also through omega = 0
//    with v != 0: the iCOR passes through infinity, no switch there); smooth except where
//    the iCOR crosses an edge of the contact (log-singular second derivatives there,
//    docs/rough.md). The only discontinuity is V = 0. During a sliding phase the right-hand side is extended past
//    rest by computing friction from +V or -V, whichever lies on the side of the current
//    sliding direction ("mode"), so the integrand stays smooth through the rest instant,
//    and the event g = V·mode (a transversal zero) is located to full precision.
//  * At rest: the body stays stuck while the applied wrench lies inside the limit surface
//    (the set of friction wrenches over all iCORs, translation included). Otherwise it
//    starts sliding with the acceleration A that minimises the convex function
//    ½ AᵀMA − W·A + D(A) (Gauss' principle with maximal dissipation, D the dissipation
//    rate): the limit surface and the inertia together pick the direction.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "nanopush/numerics/bulirsch_stoer.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/models/rough_bar.hpp"

namespace nanopush {

/// Result of the at-rest analysis.
struct RestAnalysis {
  bool stuck = true;
  /// Best power margin max over unit directions of (W·ξ − D(ξ)) in the mass-scaled metric
  /// [N/sqrt(kg)]: <= 0 when stuck (the applied wrench is inside the limit surface).
  double margin = 0;
  /// When sliding starts: the initial acceleration (ax, ay, alpha) [m/s², m/s², rad/s²].
  std::array<double, 3> accel{};
  /// Friction evaluations the analysis took (counted as RHS evaluations by the integrators:
  /// each costs what the right-hand side costs).
  std::int64_t evaluations = 0;
};

/// Decide stick or slip for a body at rest at orientation theta (world axes).
RestAnalysis analyse_rest(const RoughBarModel& model, double theta);

/// An event where the body came to rest.
struct StickEvent {
  double t = 0;      ///< [s]
  bool stuck = false;  ///< stayed stuck after it (else slid off again)
};

/// A coulomb-law integration that gave up, with the status that says why (too many steps,
/// step size underflow, ... as the integrator reports them; too_many_steps for too many rest
/// events; step_underflow for a slide that stalls in its first step).
class CoulombError : public SolverError {
 public:
  CoulombError(BsStatus status, const std::string& message) : SolverError(message), status_(status) {}
  [[nodiscard]] BsStatus status() const noexcept { return status_; }

 private:
  BsStatus status_;
};

struct StickSlipResult {
  BsResult stats;               ///< summed over all sliding phases, root finding included
  std::vector<StickEvent> events;
  std::int64_t root_fcn = 0;    ///< RHS evaluations spent locating events (part of stats.nfcn)
  bool stuck_at_end = false;
};

/// Per-output callback: time, 8-state, and the friction wrench acting at that instant
/// (static friction when stuck).
/// The state in the run's scalar S (double, or long double / quad for extended precision).
template <typename S>
using StickSlipObserverT = std::function<void(double t, const S* y, const WorldWrench& friction)>;
using StickSlipObserver = StickSlipObserverT<double>;

/// Integrate the rough-surface nanobar under the `coulomb` law with the C++ Bulirsch–Stoer
/// engine (options as for any run). y0: 8-state. Throws SolverError on integrator failure.
StickSlipResult integrate_coulomb(const RoughBarModel& model, const BsOptions<double>& options, const double* y0,
                                  const std::vector<double>& tout, const StickSlipObserver& observer);

/// The same in long double or quad (S): the state, the right-hand side and the friction wrench
/// (friction_extended.hpp) in S; times, the rest analysis and the direction of a slide that
/// starts from rest in double. Instantiated for long double and num::quad.
template <typename S>
StickSlipResult integrate_coulomb_extended(const RoughBarModel& model, const BsOptions<S>& options, const S* y0,
                                           const std::vector<double>& tout, const StickSlipObserverT<S>& observer);

/// The same with SUNDIALS CVODE (BDF, Newton, dense Jacobian) and CVODE's root finding,
/// as an independent cross-check. Available when built with SUNDIALS.
StickSlipResult integrate_coulomb_cvode(const RoughBarModel& model, double rtol, const std::vector<double>& atol,
                                        const double* y0, const std::vector<double>& tout,
                                        const StickSlipObserver& observer);

/// The friction wrench the coulomb law applies at state y with sliding mode `mode`
/// (unit direction in the scaled velocity space (vx, vy, omega L)): from +V or -V,
/// whichever is on the mode's side; from the mode itself when V = 0.
WorldWrench coulomb_friction(const RoughBarModel& model, const double* y, const std::array<double, 3>& mode);

/// The coulomb-law right-hand side (8 states) with sliding mode `mode`.
void coulomb_rhs(const RoughBarModel& model, const double* y, const std::array<double, 3>& mode, double* dydt);

}  // namespace nanopush
