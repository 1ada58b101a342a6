// What every integrator of nanopush shares: the dynamic dimension, the step hook, the status
// and the result, and the written contract an integrator follows (BulirschStoer,
// bulirsch_stoer.hpp; Dop853, dop853.hpp; a third method follows the same).
//
// The contract. An integrator is a class template Integrator<Scalar, N> (N = Dynamic for a
// size chosen at run time), constructed from its options (and n when N is Dynamic), with
//   - size() -> int, options() -> its options (both from IntegratorBase below);
//   - integrate(rhs, t0, y, tout, observer [, hook]) -> a result that is, or derives from,
//     IntegrationResult (an integrator writes the hooked one and takes the others from
//     IntegratorBase below):
//       rhs(t, y, dydt) -> int writes dydt[0..n) and returns 0, or non-zero to abort (that
//         value is reported in rhs_status, status rhs_failed; never retried);
//       y holds the state at t0 on entry and the state at the last output time reached on
//         return;
//       tout is non-decreasing and >= t0; observer(i, tout[i], y_i) is called once per output
//         time, in order, each time hit exactly (clipped steps) or interpolated (dense output);
//       hook (optional: HookedOdeIntegrator) hook(t_old, y_old, t_new, y_new) ->
//         StepHookAction after each accepted step, before it is committed (event location:
//         stick_slip.cpp);
//   - status codes are IntegrationStatus (the F77 engine's IERR values), a failure never
//     throws: bad input is status bad_input with a message;
//   - no allocation per step (work arrays are allocated at construction).
// OdeIntegrator<I, Scalar> below checks the signatures; each integrator's header asserts it.
#pragma once
#include <array>
#include <concepts>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "nanopush/numerics/scalar.hpp"

namespace nanopush {

inline constexpr int Dynamic = -1;

/// A state-sized work vector: std::array for a compile-time dimension N, else std::vector
/// (sized once, at construction).
template <typename Scalar, int N>
using StateVec = std::conditional_t<N == Dynamic, std::vector<Scalar>, std::array<Scalar, (N > 0 ? N : 1)>>;

/// Size work vectors for n components (at least one), zeroed: a std::vector (N = Dynamic) is
/// allocated here, once; a std::array (a compile-time N) has its size already and is left as is.
template <typename... Vecs>
void size_states(int n, Vecs&... vs) {
  const auto sz = static_cast<std::size_t>(n > 0 ? n : 1);
  auto size_one = [sz](auto& v) {
    using Scalar = typename std::remove_reference_t<decltype(v)>::value_type;
    if constexpr (requires { v.assign(sz, Scalar(0)); }) v.assign(sz, Scalar(0));
  };
  (size_one(vs), ...);
}

/// An rtol of `eps_units` epsilons of the scalar S: how an integrator states the smallest rtol
/// it accepts (below it its error estimate is mostly rounding).
template <typename S>
double rtol_in_eps(double eps_units) {
  return eps_units * static_cast<double>(num::epsilon<S>());
}

/// What a step hook asks for after an accepted step.
enum StepHookAction : int {
  kHookContinue = 0,     ///< commit the step and go on
  kHookStopBefore = 1,   ///< an event lies inside the step: do not commit it, return at its start
  kHookStopAfter = 2,    ///< commit the step, then return (an event at its end)
};

/// The default step hook: never stops (compiled away).
struct NoStepHook {
  template <class S>
  int operator()(S, const S*, S, const S*) const noexcept {
    return 0;
  }
};

/// Status codes of every integrator, identical to the F77 engine's IERR.
enum class IntegrationStatus : int {
  success = 0,
  bad_input = 1,
  too_many_steps = 2,
  step_underflow = 3,
  rhs_failed = 4,
  not_finite = 5,
};

/// The outcome of integrate(): status and counts (an integrator may derive to add its own).
struct IntegrationResult {
  IntegrationStatus status = IntegrationStatus::success;
  int rhs_status = 0;          ///< the RHS's own non-zero return, when status == rhs_failed
  std::int64_t nfcn = 0;       ///< right-hand-side evaluations
  std::int64_t naccpt = 0;     ///< accepted steps
  std::int64_t nrejct = 0;     ///< rejected steps
  double t_reached = 0;        ///< last time reached
  bool stopped_by_hook = false;  ///< the step hook asked to stop (an event in (t_reached, t_event_end])
  double t_event_end = 0;
  std::string message;
  [[nodiscard]] bool ok() const { return status == IntegrationStatus::success; }
};

/// The names the Bulirsch–Stoer engine grew up with (the F77 engine's statuses, every
/// Trajectory's stats).
using BsStatus = IntegrationStatus;
using BsResult = IntegrationResult;

inline const char* to_string(IntegrationStatus s) {
  switch (s) {
    case IntegrationStatus::success: return "success";
    case IntegrationStatus::bad_input: return "bad input";
    case IntegrationStatus::too_many_steps: return "too many steps";
    case IntegrationStatus::step_underflow: return "step size underflow";
    case IntegrationStatus::rhs_failed: return "right-hand side failed";
    case IntegrationStatus::not_finite: return "non-finite state";
  }
  return "unknown";
}

namespace integration_detail {
/// A time or tolerance in a status message (%.6g).
inline std::string fmt_g(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}
/// Status rhs_failed with the RHS's own value and the time it failed at.
inline void fail_rhs(IntegrationResult& res, int st, double t) {
  res.status = IntegrationStatus::rhs_failed;
  res.rhs_status = st;
  res.message = "right-hand side returned status " + std::to_string(st) + " at t = " + fmt_g(t);
}

/// The contract's callables, for checking signatures only.
struct ContractRhs {
  template <class S>
  int operator()(S, const S*, S*) const noexcept {
    return 0;
  }
};
struct ContractObserver {
  template <class S>
  void operator()(std::size_t, S, const S*) const noexcept {}
};
}  // namespace integration_detail

/// What every integrator has besides the integrate() it writes, integrate(rhs, t0, y, tout,
/// observer, hook): the options and the dimension it was made with (options(), size()), and
/// the overloads without a step hook and to one output time without an observer. Integrator
/// derives from IntegratorBase<Integrator, Scalar, Result, Options>, constructs it from its
/// options and n, and says `using Base::integrate;` (and `using Base::opt_, Base::n_;`).
template <class Integrator, typename Scalar, class Result, class Options>
class IntegratorBase {
 public:
  [[nodiscard]] int size() const { return n_; }
  [[nodiscard]] const Options& options() const { return opt_; }

  /// Integrate; y holds the initial state on entry and the state at t_reached on return.
  template <class Rhs, class Observer>
  Result integrate(Rhs&& rhs, Scalar t0, Scalar* y, std::span<const Scalar> tout, Observer&& observer) {
    return self().integrate(std::forward<Rhs>(rhs), t0, y, tout, std::forward<Observer>(observer), NoStepHook{});
  }

  /// Convenience: one output time, no observer.
  template <class Rhs>
  Result integrate(Rhs&& rhs, Scalar t0, Scalar* y, Scalar t1) {
    const Scalar tt[1] = {t1};
    return integrate(std::forward<Rhs>(rhs), t0, y, std::span<const Scalar>(tt, 1),
                     [](std::size_t, Scalar, const Scalar*) {});
  }

 protected:
  IntegratorBase(Options opt, int n) : opt_(std::move(opt)), n_(n) {}
  Options opt_;
  int n_;

 private:
  Integrator& self() { return static_cast<Integrator&>(*this); }
};

/// An integrator follows the contract above (signatures; the behaviour is tested).
template <class I, class Scalar>
concept OdeIntegrator = requires(I& integrator, const I& ci, Scalar* y, std::span<const Scalar> tout) {
  { ci.size() } -> std::convertible_to<int>;
  ci.options();
  {
    integrator.integrate(integration_detail::ContractRhs{}, Scalar(0), y, tout, integration_detail::ContractObserver{})
  } -> std::convertible_to<IntegrationResult>;
};

/// An integrator that also takes the step hook (event location; BulirschStoer does).
template <class I, class Scalar>
concept HookedOdeIntegrator =
    OdeIntegrator<I, Scalar> && requires(I& integrator, Scalar* y, std::span<const Scalar> tout) {
      {
        integrator.integrate(integration_detail::ContractRhs{}, Scalar(0), y, tout,
                             integration_detail::ContractObserver{}, NoStepHook{})
      } -> std::convertible_to<IntegrationResult>;
    };

}  // namespace nanopush
