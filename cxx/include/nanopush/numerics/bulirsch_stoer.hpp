// Bulirsch–Stoer extrapolation integrator (modern C++ engine).
//
// Algorithm: Gragg's modified midpoint rule extrapolated in h^2, rational (Stoer &
// Bulirsch, Introduction to Numerical Analysis, §7.2.14) or polynomial (Aitken–Neville);
// order and step-size control by work per unit step (Deuflhard 1983) in the form of
// Hairer, Nørsett & Wanner, Solving ODEs I, §II.9 (constants SAFE1..3, FAC4 named as
// there). docs/bulirsch_stoer.md states the algorithm step by step; the FORTRAN 77 engine
// (fortran/bsint.f) implements the same steps, and the `faithful` options below reproduce
// its steps exactly (identical RHS-evaluation counts).
//
// The integrator follows the contract of integration.hpp (HookedOdeIntegrator: the step
// hook locates events). Its parts, one header each under bs/: the stepper (midpoint.hpp,
// Gragg's rule), the extrapolation tableau (extrapolation.hpp), the dense output
// (dense_output.hpp) and the constant tables (tables.hpp). This header holds the options
// and the step and order control, integrate() cut into the numbered steps of
// docs/bulirsch_stoer.md.
// Templated on the scalar (double, long double, __float128) and the dimension N
// (N = Dynamic for a size chosen at run time).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "nanopush/numerics/bs/dense_output.hpp"
#include "nanopush/numerics/bs/extrapolation.hpp"
#include "nanopush/numerics/bs/midpoint.hpp"
#include "nanopush/numerics/bs/tables.hpp"
#include "nanopush/numerics/integration.hpp"
#include "nanopush/numerics/scalar.hpp"
#include "nanopush/numerics/simd_pairs.hpp"

namespace nanopush {

/// The smallest rtol > 0 dense output accepts, in units of the scalar's epsilon: below it the
/// step's error estimate (the difference of two extrapolated values, each rounded) is mostly
/// rounding, and the step size shrinks until it underflows (seen in double at rtol 1e-16).
/// rtol_in_eps<S>(kDenseRtolEps) is that rtol in the scalar S.
inline constexpr double kDenseRtolEps = 4.0;

enum class Extrapolation { rational = 1, polynomial = 2 };

template <typename Scalar>
struct BsOptions {
  Scalar rtol = Scalar(1e-10);
  std::vector<Scalar> atol;  ///< per component (size n) or one value for all; must not be empty
  Scalar h0 = 0;             ///< initial step; 0 = 1% of the span
  Scalar hmax = 0;           ///< 0 = no limit
  int kmax = 8;              ///< extrapolation columns, 3..12
  Extrapolation extrapolation = Extrapolation::rational;
  std::int64_t maxstp = 100000;
  /// Dense output (Hairer, Nørsett & Wanner, §II.9; the interpolation of their code ODEX):
  /// step numbers 2, 6, 10, 14, ... (4j-2), outputs interpolated from the extrapolation
  /// tableau instead of clipping a step at every output time, interpolation error
  /// controlled. Needs polynomial extrapolation. Off: every step ends on an output time,
  /// step numbers 2, 4, 6, ... (the F77 engine's scheme).
  bool dense = false;
  /// Dense output: a step is accepted only if its interpolation error estimate, in units of
  /// the tolerance, is <= dense_accept, and the next step aims at dense_accept / 10. ODEX
  /// uses 10; the default 1 holds the interpolant to the steps' own tolerance (the estimate
  /// reads 1.2-5.5 x low on the nanobar, so 10 let interpolants 30 x the tolerance through;
  /// docs/bulirsch_stoer.md, "The interpolant's error control").
  double dense_accept = 1.0;

  /// The thesis-era configuration; takes the F77 engine's steps exactly.
  static BsOptions faithful(Scalar rtol, std::vector<Scalar> atol) {
    return {.rtol = rtol, .atol = std::move(atol), .kmax = 8, .extrapolation = Extrapolation::rational};
  }
  /// Polynomial extrapolation (no poles), more columns for tight tolerances, dense output
  /// (steps not bound to the output times).
  static BsOptions modern(Scalar rtol, std::vector<Scalar> atol) {
    return {.rtol = rtol, .atol = std::move(atol), .kmax = 10, .extrapolation = Extrapolation::polynomial, .dense = true};
  }
};

template <typename Scalar, int N = Dynamic>
class BulirschStoer : public IntegratorBase<BulirschStoer<Scalar, N>, Scalar, BsResult, BsOptions<Scalar>> {
  using Base = IntegratorBase<BulirschStoer, Scalar, BsResult, BsOptions<Scalar>>;

 public:
  static constexpr int kKmaxLimit = bs::kKmaxLimit;
  using Vec = StateVec<Scalar, N>;

  explicit BulirschStoer(BsOptions<Scalar> opt, int n = N) : Base(std::move(opt), n) {
    size_states(n_, y_, f0_, q_, atol_, f1_);
    tableau_.allocate(n_);
    midpoint_.allocate(n_);
    seq_ = &bs::sequence_tables<Scalar>(opt_.dense);  // built once per process
    if (opt_.dense && n_ > 0) dense_.allocate(n_);   // every line's RHS values, allocated once
  }

  /// Integrate without a step hook, or to one output time (integration.hpp).
  using Base::integrate;

  /// Integrate; y holds the initial state on entry and the state at the last output time
  /// reached on return. A hook is called after every accepted step, before it is committed:
  /// hook(t_old, y_old, t_new, y_new) returns a StepHookAction. kHookStopBefore: the
  /// integration returns with `stopped_by_hook` set, y = y_old and t_reached = t_old, so the
  /// caller can locate an event in [t_old, t_new] and restart there. kHookStopAfter: the
  /// step is committed (its outputs emitted) and the integration returns at t_new.
  /// The loop below is docs/bulirsch_stoer.md's steps 1-7, each a named function.
  template <class Rhs, class Observer, class StepHook>
  BsResult integrate(Rhs&& rhs, Scalar t0, Scalar* y, std::span<const Scalar> tout, Observer&& observer,
                     StepHook&& hook) {
    BsResult res;
    res.t_reached = static_cast<double>(t0);
    const int n = (N == Dynamic) ? n_ : N;  // a compile-time bound lets the loops unroll
    if (std::string why = validate(t0, y, tout); !why.empty()) {
      res.status = BsStatus::bad_input;
      res.message = std::move(why);
      return res;
    }
    Walk wk = start(t0, y, tout);
    const std::size_t nout = tout.size();
    emit_reached(wk, tout, observer);
    // Dense output: the last output time is the only one a step must end on.
    const bool dense = opt_.dense;
    while (wk.iout < nout) {
      const Scalar tend = dense ? tout[nout - 1] : tout[wk.iout];
      if (!steps_left(res)) break;                          // 1.
      if (!wk.have_f0 && !first_derivative(rhs, wk, res)) break;  // 2.
      const Attempt at = attempt(rhs, wk, tend, res);       // 3., 4. and 6a's first half
      if (at.failed) break;
      wk.nonfinite_run = 0;
      int kopt = propose_order(wk, at.kc);                  // 5.
      if (!at.accept) {                                     // 6.
        ++res.nrejct;
        wk.k = std::min(kopt, at.kc);
        wk.h = std::min(wk.h, wk.hh[wk.k]);
        wk.last_rejected = true;
        continue;
      }
      if (dense && !interpolant_accepted(wk, at, res)) continue;  // 6a, second half
      // 7.
      if constexpr (!std::is_same_v<std::decay_t<StepHook>, NoStepHook>) {
        const Scalar tnew = at.clipped ? tend : wk.t + wk.h;
        wk.hook_action =
            hook(wk.t, static_cast<const Scalar*>(&y_[0]), tnew, static_cast<const Scalar*>(&tableau_.cur()[at.kc][0]));
        if (wk.hook_action == kHookStopBefore) {
          ++res.naccpt;
          res.stopped_by_hook = true;
          res.t_event_end = static_cast<double>(tnew);
          break;
        }
      }
      const Scalar t_old = wk.t, h_step = wk.h;
      commit(wk, at, kopt, tend, res);
      if (dense)
        emit_interpolated(wk, tout, t_old, h_step, observer);
      else
        emit_reached(wk, tout, observer);
      if (wk.hook_action == kHookStopAfter) {
        res.stopped_by_hook = true;
        res.t_event_end = static_cast<double>(wk.t);
        break;
      }
    }
    for (int i = 0; i < n; ++i) y[i] = y_[i];
    return res;
  }

 private:
  static constexpr Scalar kOrdDec = Scalar(0.8);
  static constexpr Scalar kOrdInc = Scalar(0.9);
  static constexpr int kMaxNonFinite = 10;
  static constexpr bool kPairs = pairs::kPairs<Scalar, N>;
  using Dense = bs::DenseOutput<Scalar, N>;
  using Table = std::array<Scalar, kKmaxLimit + 2>;

  /// The running state of one integrate() call.
  struct Walk {
    Scalar t = 0, h = 0, span_total = 0;
    int k = 0;                    // the order (target line) of the next attempt
    bool have_f0 = false, last_rejected = false;
    int hook_action = kHookContinue;
    int nonfinite_run = 0;        // attempts in a row with a non-finite error estimate
    Scalar hoptde = 0;            // step-size bound from the interpolation error (dense output), 0 = none
    double errint_rej = 0;        // the estimate that rejected the last attempt at this t, and its order
    int kc_rej = 0;
    std::size_t iout = 0;         // next output time
    Table a{};                    // work A_j, 1-based
    Table w{}, hh{}, errs{};      // work per unit step, proposed step and error of each line
  };
  /// One attempt at a step from wk.t.
  struct Attempt {
    Scalar hwant = 0;             // the step wanted before clipping to tend
    bool clipped = false;
    int kc = 0;                   // the line the decision was taken at
    bool accept = false, failed = false;
    double errint = 0;            // dense output: the interpolation error estimate of an accepted attempt
  };

  Walk start(Scalar t0, const Scalar* y, std::span<const Scalar> tout) {
    const int n = (N == Dynamic) ? n_ : N;
    Walk wk;
    const int kmax = opt_.kmax;
    for (int i = 0; i < n; ++i)
      atol_[i] = opt_.atol.size() == 1 ? opt_.atol[0] : opt_.atol[static_cast<std::size_t>(i)];
    for (int j = 1; j <= kmax; ++j) wk.a[j] = (j == 1 ? Scalar(seq(1) + 1) : wk.a[j - 1] + Scalar(seq(j)));
    wk.span_total = tout[tout.size() - 1] - t0;
    wk.k = std::max(2, std::min(kmax - 1, static_cast<int>(-num::log10(opt_.rtol + Scalar(1e-40)) * Scalar(0.6) +
                                                           Scalar(1.5))));
    wk.h = opt_.h0 > 0 ? opt_.h0 : Scalar(0.01) * wk.span_total;
    if (opt_.hmax > 0) wk.h = std::min(wk.h, opt_.hmax);
    wk.t = t0;
    for (int i = 0; i < n; ++i) y_[i] = y[i];
    return wk;
  }

  // 1. The step budget.
  bool steps_left(BsResult& res) const {
    if (res.naccpt + res.nrejct < opt_.maxstp) return true;
    res.status = BsStatus::too_many_steps;
    res.message = "more than " + std::to_string(opt_.maxstp) + " steps";
    return false;
  }

  // 2. f at the step's start (after a clipped step; dense output carries it over).
  template <class Rhs>
  bool first_derivative(Rhs& rhs, Walk& wk, BsResult& res) {
    const int st = rhs(wk.t, static_cast<const Scalar*>(&y_[0]), &f0_[0]);
    ++res.nfcn;
    if (st != 0) {
      fail_rhs(res, st, wk.t);
      return false;
    }
    wk.have_f0 = true;
    return true;
  }

  // 3.-4. Attempts from wk.t until one ends in a decision (or fails): the step clipped to tend,
  // the lines computed and extrapolated until the error decides, then (dense output,
  // accepted) f at the step's end and the interpolant, then the step-size proposals. A
  // non-finite error estimate quarters the step and retries (at most kMaxNonFinite times).
  template <class Rhs>
  Attempt attempt(Rhs& rhs, Walk& wk, Scalar tend, BsResult& res) {
    Attempt at;
    for (;;) {
      at = Attempt{};
      at.hwant = wk.h;
      if (wk.t + Scalar(1.01) * wk.h >= tend) {
        wk.h = tend - wk.t;
        at.clipped = true;
      }
      if (wk.h <= 0 || wk.h < Scalar(1e-14) * std::max(num::abs(wk.t), wk.span_total)) {
        res.status = BsStatus::step_underflow;
        res.message = "step size underflow at t = " + integration_detail::fmt_g(static_cast<double>(wk.t));
        at.failed = true;
        return at;
      }
      const bool nonfinite = compute_lines(rhs, wk, at, res);
      // 6a (first half). Dense output, accepted attempt: f at the step's end (the next
      // step's f0) and the interpolation polynomial with its error estimate. Neither needs
      // the step-size proposals below, so they come first: the proposals' pow() chain then
      // overlaps this work, where after it the chain held back the next step (the same
      // operations and RHS calls in either order; measured 2-4 % less wall, fig3_6a).
      if (!at.failed && !nonfinite && at.accept && opt_.dense) {
        const Scalar tnew = at.clipped ? tend : wk.t + wk.h;
        const int st = rhs(tnew, static_cast<const Scalar*>(&tableau_.cur()[at.kc][0]), &f1_[0]);
        ++res.nfcn;
        if (st != 0) {
          fail_rhs(res, st, tnew);
          at.failed = true;
          return at;
        }
        at.errint = dense_.build(at.kc, wk.h, &y_[0], &tableau_.cur()[at.kc][0], &f0_[0], &f1_[0], &atol_[0],
                                 opt_.rtol, seq_->nj);
      }
      if (!at.failed && !nonfinite) propose_step_sizes(wk, at.kc);
      if (at.failed || !nonfinite) return at;
      // Non-finite error estimate: quarter the step, keep k, retry.
      ++res.nrejct;
      wk.last_rejected = true;
      if (++wk.nonfinite_run >= kMaxNonFinite) {
        res.status = BsStatus::not_finite;
        res.message = "non-finite error estimate at t = " + integration_detail::fmt_g(static_cast<double>(wk.t));
        at.failed = true;
        return at;
      }
      wk.h = Scalar(0.25) * wk.h;
    }
  }

  // 4. Lines 1..k+1 over [t, t+h], each extrapolated, until the error of line k-1, k or k+1
  // decides (accept, or reject as hopeless). Lines 1..max(2, k-1) are computed by every
  // attempt (the first decision comes after line k-1, and none before line 2): their
  // midpoint chains run interleaved, so the latency of one line's RHS overlaps the others'.
  // Not on the retry after a non-finite error estimate (it would evaluate lines a
  // sequential attempt skips). Returns whether the error estimate was non-finite.
  template <class Rhs>
  bool compute_lines(Rhs& rhs, Walk& wk, Attempt& at, BsResult& res) {
    const bool dense = opt_.dense;
    const int k = wk.k;
    const int jgroup = wk.nonfinite_run == 0 ? std::max(2, k - 1) : 0;
    if (jgroup > 0) {
      if (const int st = dense ? midpoint_.template group<true>(rhs, &y_[0], &f0_[0], wk.t, wk.h, jgroup, seq_->nj,
                                                                dense_, res)
                               : midpoint_.template group<false>(rhs, &y_[0], &f0_[0], wk.t, wk.h, jgroup, seq_->nj,
                                                                 dense_, res);
          st != 0) {
        fail_rhs(res, st, wk.t);
        at.failed = true;
      }
    }
    for (int j = 1; !at.failed && j <= k + 1; ++j) {
      if (j <= jgroup) {
        tableau_.cur()[1] = midpoint_.held(j);
      } else if (const int st = midpoint_.line(rhs, &y_[0], &f0_[0], wk.t, wk.h, seq(j), tableau_.cur()[1], res,
                                               dense ? dense_.fs_line(j) : nullptr,
                                               dense ? dense_.ys_line(j) : nullptr);
                 st != 0) {
        fail_rhs(res, st, wk.t);
        at.failed = true;
        break;
      }
      tableau_.extrapolate(j, n_, opt_.extrapolation == Extrapolation::rational, *seq_);
      if (j < 2) {
        tableau_.flip();
        continue;
      }
      const Scalar err = line_error(j);
      if (!num::isfinite(err)) return true;
      wk.errs[j] = err;
      bool decided = false;
      if (j == k - 1) {
        if (err <= 1) {
          at.accept = decided = true;
        } else if (err > sq(Scalar(seq(k + 1) * seq(k)) / Scalar(4))) {
          decided = true;
        }
      } else if (j == k) {
        if (err <= 1) {
          at.accept = decided = true;
        } else if (err > sq(Scalar(seq(k + 1)) / Scalar(2))) {
          decided = true;
        }
      } else if (j == k + 1) {
        at.accept = err <= 1;
        decided = true;
      }
      if (decided) {
        at.kc = j;
        break;
      }
      tableau_.flip();
    }
    return false;
  }

  // The scaled RMS difference of the last two columns of line j. Scaled differences first
  // (the divisions are independent and vectorise), then the sum in component order (the F77
  // engine's order: no reassociation).
  Scalar line_error(int j) {
    const int n = (N == Dynamic) ? n_ : N;
    const Scalar rtol = opt_.rtol;
    std::array<Scalar, (N > 0 ? N : 1)> qbuf;
    Scalar* q = (N == Dynamic) ? &q_[0] : qbuf.data();
    {
      const Vec& cj = tableau_.cur()[j];
      const Vec& cj1 = tableau_.cur()[j - 1];
      if constexpr (kPairs) {
        using pairs::V2, pairs::ld2, pairs::st2, pairs::abs2;
        const V2 rt = {rtol, rtol};
        for (int i = 0; i < N; i += 2) {
          const V2 ay = abs2(ld2(&y_[i])), ac = abs2(ld2(&cj[i]));
          const V2 sc = ld2(&atol_[i]) + rt * ((ay < ac) ? ac : ay);  // std::max(ay, ac)
          st2(&q[i], (ld2(&cj[i]) - ld2(&cj1[i])) / sc);
        }
      } else {
        for (int i = 0; i < n; ++i) {
          const Scalar sc = atol_[i] + rtol * std::max(num::abs(y_[i]), num::abs(cj[i]));
          q[i] = (cj[i] - cj1[i]) / sc;
        }
      }
    }
    Scalar s = 0;
    for (int i = 0; i < n; ++i) s = s + q[i] * q[i];
    return num::sqrt(s / Scalar(n));
  }

  // The step-size proposal of each line. The order and step choices read lines kc-1..kc, and
  // kc-2 only when the step went past its order (kc = k+1), so only their pow() is paid (the
  // others are never read in this step).
  void propose_step_sizes(Walk& wk, int kc) {
    for (int j = std::max(2, kc > wk.k ? kc - 2 : kc - 1); j <= kc; ++j) {
      // In double for every scalar: a few digits suffice, and pow in long double or
      // __float128 costs as much as a cheap RHS. For Scalar = double these are
      // exactly the F77 engine's operations.
      const double errc = static_cast<double>(wk.errs[j]);
      const double expo = 1.0 / static_cast<double>(2 * j - 1);
      const double facmin = seq_->facmin[j];  // kSafe3^expo
      double fac;
      if (errc == 0)
        fac = 1.0 / facmin;
      else
        fac = bs::kSafe2 * std::pow(bs::kSafe1 / errc, expo);
      fac = std::max(facmin / bs::kFac4, std::min(1.0 / facmin, fac));
      wk.hh[j] = wk.h * static_cast<Scalar>(fac);
      wk.w[j] = wk.a[j] / wk.hh[j];
    }
  }

  // 5. The order proposal, by work per unit step.
  int propose_order(const Walk& wk, int kc) const {
    const int kmax = opt_.kmax;
    const int k = wk.k;
    const Table& w = wk.w;
    int kopt;
    if (kc == 2) {
      kopt = wk.last_rejected ? 2 : std::min(3, kmax - 1);
    } else if (kc <= k) {
      kopt = kc;
      if (w[kc - 1] < kOrdDec * w[kc]) kopt = kc - 1;
      if (w[kc] < kOrdInc * w[kc - 1]) kopt = std::min(kc + 1, kmax - 1);
    } else {
      kopt = kc - 1;
      if (kc > 3 && w[kc - 2] < kOrdDec * w[kc - 1]) kopt = kc - 2;
      if (w[kc] < kOrdInc * w[kopt]) kopt = std::min(kc, kmax - 1);
    }
    return kopt;
  }

  // 6a (second half). Dense output: a step whose interpolant is poor is rejected (errint from
  // the first half). Near the precision's floor the estimate is rounding noise: a retry with
  // a smaller step (same order) that is still above the threshold and did not at least halve
  // it is accepted, and sets no bound.
  bool interpolant_accepted(Walk& wk, const Attempt& at, BsResult& res) {
    const double errint = at.errint;
    const int kc = at.kc;
    const bool noise = kc == wk.kc_rej && errint > opt_.dense_accept && errint > 0.5 * wk.errint_rej;
    wk.hoptde = noise ? Scalar(0)
                      : wk.h / static_cast<Scalar>(std::max(
                                   std::pow(errint / (0.1 * opt_.dense_accept), 1.0 / (dense_.mu() + 4)), 0.01));
    if (errint > opt_.dense_accept && !noise) {
      ++res.nrejct;
      wk.h = wk.hoptde;
      wk.last_rejected = true;
      wk.errint_rej = errint;
      wk.kc_rej = kc;
      return false;
    }
    wk.kc_rej = 0;
    return true;
  }

  // 7. Commit the accepted step: the new state (and f0, with dense output), the next step
  // size and order.
  void commit(Walk& wk, const Attempt& at, int kopt, Scalar tend, BsResult& res) {
    const int n = (N == Dynamic) ? n_ : N;
    const bool dense = opt_.dense;
    const int kc = at.kc, k = wk.k;
    const Table& a = wk.a;
    const Table& w = wk.w;
    const Table& hh = wk.hh;
    ++res.naccpt;
    const Scalar h = wk.h;
    wk.t = at.clipped ? tend : wk.t + h;
    for (int i = 0; i < n; ++i) y_[i] = tableau_.cur()[kc][i];
    if (dense) {
      for (int i = 0; i < n; ++i) f0_[i] = f1_[i];
      wk.have_f0 = true;
    } else {
      wk.have_f0 = false;
    }
    Scalar hnew;
    if (kopt <= kc)
      hnew = hh[kopt];
    else if (kc >= 3 && kc < k && w[kc] < kOrdInc * w[kc - 1])
      hnew = hh[kc] * a[kopt + 1] / a[kc];
    else
      hnew = hh[kc] * a[kopt] / a[kc];
    if (wk.last_rejected) {
      kopt = std::min(kopt, kc);
      hnew = std::min(hnew, h);
    }
    wk.k = kopt;
    if (at.clipped) hnew = std::max(hnew, at.hwant);
    if (dense && wk.hoptde > 0) hnew = std::min(hnew, wk.hoptde);
    if (opt_.hmax > 0) hnew = std::min(hnew, opt_.hmax);
    wk.h = hnew;
    wk.last_rejected = false;
    res.t_reached = static_cast<double>(wk.t);
  }

  // The outputs the state has reached (every step ends on an output time, or before it).
  template <class Observer>
  void emit_reached(Walk& wk, std::span<const Scalar> tout, Observer& observer) {
    while (wk.iout < tout.size() && tout[wk.iout] <= wk.t) {
      observer(wk.iout, tout[wk.iout], static_cast<const Scalar*>(&y_[0]));
      ++wk.iout;
    }
  }

  // Dense output: the outputs inside the step from the interpolant, evaluated kBatch at a
  // time (the Horner chains of different outputs are independent); one at the step's end
  // exactly.
  template <class Observer>
  void emit_interpolated(Walk& wk, std::span<const Scalar> tout, Scalar t_old, Scalar h_step, Observer& observer) {
    const int n = (N == Dynamic) ? n_ : N;
    const std::size_t nout = tout.size();
    constexpr int kBatch = Dense::kBatch;
    std::size_t& iout = wk.iout;
    while (iout < nout && tout[iout] <= wk.t) {
      if (tout[iout] == wk.t) {
        observer(iout, tout[iout], static_cast<const Scalar*>(&y_[0]));
        ++iout;
        continue;
      }
      std::array<Scalar, kBatch> theta{};
      int m = 0;
      while (m < kBatch && iout + static_cast<std::size_t>(m) < nout && tout[iout + static_cast<std::size_t>(m)] < wk.t) {
        theta[static_cast<std::size_t>(m)] = (tout[iout + static_cast<std::size_t>(m)] - t_old) / h_step;
        ++m;
      }
      Scalar* yb = dense_.batch();
      dense_.eval(theta, m, yb);
      for (int b = 0; b < m; ++b, ++iout)
        observer(iout, tout[iout], static_cast<const Scalar*>(&yb[static_cast<std::size_t>(b * n)]));
    }
  }

  int seq(int j) const { return seq_->nj[j]; }
  static Scalar sq(Scalar x) { return x * x; }
  static void fail_rhs(BsResult& res, int st, Scalar t) {
    integration_detail::fail_rhs(res, st, static_cast<double>(t));
  }

  std::string validate(Scalar t0, const Scalar* y, std::span<const Scalar> tout) const {
    using integration_detail::fmt_g;
    if (n_ < 1) return "n must be >= 1";
    if constexpr (N != Dynamic)
      if (n_ != N) return "n does not match the compile-time dimension";
    if (opt_.kmax < 3 || opt_.kmax > kKmaxLimit) return "kmax must be in [3, 12]";
    if (opt_.dense && opt_.extrapolation != Extrapolation::polynomial)
      return "dense output needs polynomial extrapolation";
    if (!(opt_.rtol >= 0)) return "rtol must be >= 0";
    if (opt_.atol.empty() || (opt_.atol.size() != 1 && opt_.atol.size() != static_cast<std::size_t>(n_)))
      return "atol must have 1 or n entries";
    for (const Scalar v : opt_.atol) {
      if (!(v >= 0)) return "atol must be >= 0";
      if (v == 0 && opt_.rtol == 0) return "rtol and atol must not both be 0";
    }
    if (tout.empty()) return "no output times";
    if (!num::isfinite(t0) || tout[0] < t0) return "tout(1) must be >= t0";
    for (std::size_t i = 0; i < tout.size(); ++i) {
      if (!num::isfinite(tout[i])) return "output times must be finite";
      if (i > 0 && tout[i] < tout[i - 1]) return "output times must be non-decreasing";
    }
    for (int i = 0; i < n_; ++i)
      if (!num::isfinite(y[i])) return "initial state must be finite";
    if (opt_.maxstp < 1) return "maxstp must be >= 1";
    if (opt_.h0 < 0 || opt_.hmax < 0) return "h0 and hmax must be >= 0";
    if (opt_.dense && !(opt_.dense_accept > 0 && opt_.dense_accept <= 1e6))
      return "dense_accept = " + fmt_g(opt_.dense_accept) + " must be in (0, 1e6]";
    if (opt_.dense && opt_.rtol > 0) {
      const double floor = rtol_in_eps<Scalar>(kDenseRtolEps);
      if (static_cast<double>(opt_.rtol) < floor)
        return "rtol = " + fmt_g(static_cast<double>(opt_.rtol)) + " is below " + fmt_g(floor) + " (" +
               fmt_g(kDenseRtolEps) + " eps of " + num::name<Scalar>() +
               "): with dense output the step-size control would follow rounding; use a wider precision or the "
               "faithful (clipped) method";
    }
    return {};
  }

  using Base::opt_, Base::n_;
  Vec y_{}, f0_{}, f1_{}, atol_{};
  Vec q_{};  // the scaled differences of line_error (dynamic dimension)
  const bs::SequenceTables<Scalar>* seq_ = nullptr;
  bs::ExtrapolationTableau<Scalar, N> tableau_;
  bs::GraggMidpoint<Scalar, N> midpoint_;
  Dense dense_;  // allocated with dense output only
};

static_assert(HookedOdeIntegrator<BulirschStoer<double, 6>, double>);
static_assert(HookedOdeIntegrator<BulirschStoer<double>, double>);

}  // namespace nanopush
