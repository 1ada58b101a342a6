// Integration across the kinks of a right-hand side (private to the scenes layer): where an
// event function g_k(y) changes sign the RHS is continuous but not smooth (the thesis law's
// friction wrench as the iCOR crosses the lines of the contact's edges), an extrapolation or
// Runge-Kutta step across it loses its order, and the error stops falling with rtol. Each such
// crossing is located (Illinois regula falsi on sub-integrations from the step's start) and the
// integration restarted there, so no step straddles a kink (docs/accuracy.md).
#pragma once
#include <cstdint>
#include <functional>
#include <span>

#include "nanopush/numerics/integration.hpp"

namespace nanopush::detail {

/// The state in scalar S (double; long double and quad for the extended-precision runs); times
/// in double.
template <typename S>
using KinkObserverT = std::function<void(double t, const S* y)>;
template <typename S>
using KinkHookT = std::function<int(double t0, const S* y0, double t1, const S* y1)>;
/// One integration from (t0, y) over the output times `tout` with an observer and a step hook,
/// by a fresh integrator (the method's own options, its first step h0 when h0 > 0, at most
/// max_steps steps); y is left at the last time reached.
template <typename S>
using KinkIntegrateT = std::function<IntegrationResult(double t0, S* y, std::span<const double> tout,
                                                       const KinkObserverT<S>& observer, const KinkHookT<S>& hook,
                                                       double h0, std::int64_t max_steps)>;
/// The event functions at a state: g[0..nk).
template <typename S>
using KinkFunctionsT = std::function<void(const S* y, S* g)>;
using KinkObserver = KinkObserverT<double>;
using KinkHook = KinkHookT<double>;
using KinkIntegrate = KinkIntegrateT<double>;
using KinkFunctions = KinkFunctionsT<double>;

struct KinkResult {
  IntegrationResult stats;   ///< counts summed over every integration, the status of the last
  std::int64_t located = 0;  ///< kinks located
  bool stopped_by_hook = false;  ///< `hook` stopped the run (kHookStopAfter)
};

/// Integrate the state y (n components) from 0 over `tout` as `run` does, locating the sign
/// changes of the `nk` functions `kinks` and restarting at each. `hook` (optional) sees every
/// committed step and may stop the run after it. `max_steps` bounds the steps of the whole run,
/// the restarts and the location's sub-integrations included (status too_many_steps beyond):
/// where a kink function hovers at zero (the iCOR riding an edge line as the body slows) the
/// kinks come every few steps, and a budget per integration let the run go on for millions.
/// Instantiated for double, long double and quad.
template <typename S>
KinkResult integrate_across_kinks(const KinkIntegrateT<S>& run, const KinkFunctionsT<S>& kinks, int nk, S* y, int n,
                                  std::span<const double> tout, const KinkObserverT<S>& observer,
                                  const KinkHookT<S>& hook, std::int64_t max_steps);

}  // namespace nanopush::detail
