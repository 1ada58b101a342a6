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
// Integrator contract (what a caller provides and gets):
//   - rhs(t, y, dydt) -> int: writes dydt[0..n), returns 0, or non-zero to abort
//     (that value is reported back in Result::rhs_status).
//   - integrate(rhs, t0, y, tout, observer): advances y from t0 through every output time
//     in `tout` (non-decreasing, >= t0), hitting each exactly (steps are clipped to output
//     times; the step-size proposal and the order survive the clip), and calls
//     observer(i, tout[i], y) at each. Returns a Result with status and counts.
//   - No allocation per step: all work arrays are allocated at construction (fixed-size
//     std::array when N > 0).
// Templated on the scalar (double, long double, __float128) and the dimension N
// (N = Dynamic for a size chosen at run time).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "nanopush/numerics/scalar.hpp"

namespace nanopush {

inline constexpr int Dynamic = -1;

/// The smallest rtol > 0 dense output accepts, in units of the scalar's epsilon: below it the
/// step's error estimate (the difference of two extrapolated values, each rounded) is mostly
/// rounding, and the step size shrinks until it underflows (seen in double at rtol 1e-16).
inline constexpr double kDenseRtolEps = 4.0;
template <typename S>
double dense_rtol_min() {
  return kDenseRtolEps * static_cast<double>(num::epsilon<S>());
}

/// The default step hook: never stops (compiled away).
struct NoStepHook {
  template <class S>
  int operator()(S, const S*, S, const S*) const noexcept {
    return 0;
  }
};

/// What a step hook asks for after an accepted step.
enum StepHookAction : int {
  kHookContinue = 0,     ///< commit the step and go on
  kHookStopBefore = 1,   ///< an event lies inside the step: do not commit it, return at its start
  kHookStopAfter = 2,    ///< commit the step, then return (an event at its end)
};

enum class Extrapolation { rational = 1, polynomial = 2 };

/// Status codes, identical to the F77 engine's IERR.
enum class BsStatus : int {
  success = 0,
  bad_input = 1,
  too_many_steps = 2,
  step_underflow = 3,
  rhs_failed = 4,
  not_finite = 5,
};

const char* to_string(BsStatus s);

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
    BsOptions o;
    o.rtol = rtol;
    o.atol = std::move(atol);
    o.kmax = 8;
    o.extrapolation = Extrapolation::rational;
    return o;
  }
  /// Polynomial extrapolation (no poles), more columns for tight tolerances, dense output
  /// (steps not bound to the output times).
  static BsOptions modern(Scalar rtol, std::vector<Scalar> atol) {
    BsOptions o;
    o.rtol = rtol;
    o.atol = std::move(atol);
    o.kmax = 10;
    o.extrapolation = Extrapolation::polynomial;
    o.dense = true;
    return o;
  }
};

struct BsResult {
  BsStatus status = BsStatus::success;
  int rhs_status = 0;          ///< the RHS's own non-zero return, when status == rhs_failed
  std::int64_t nfcn = 0;       ///< right-hand-side evaluations
  std::int64_t naccpt = 0;     ///< accepted steps
  std::int64_t nrejct = 0;     ///< rejected steps
  double t_reached = 0;        ///< last time reached
  bool stopped_by_hook = false;  ///< the step hook asked to stop (an event in (t_reached, t_event_end])
  double t_event_end = 0;
  std::string message;
  [[nodiscard]] bool ok() const { return status == BsStatus::success; }
};

template <typename Scalar, int N = Dynamic>
class BulirschStoer {
 public:
  static constexpr int kKmaxLimit = 12;
  using Vec = std::conditional_t<N == Dynamic, std::vector<Scalar>, std::array<Scalar, (N > 0 ? N : 1)>>;

  explicit BulirschStoer(BsOptions<Scalar> opt, int n = N) : opt_(std::move(opt)), n_(n) {
    if constexpr (N == Dynamic) {
      const auto sz = static_cast<std::size_t>(n_ > 0 ? n_ : 1);
      for (Vec* v : {&y_, &f0_, &zm_, &z_, &fz_, &sc_, &atol_, &f1_}) v->assign(sz, Scalar(0));
      for (auto& half : tab_)
        for (auto& row : half) row.assign(sz, Scalar(0));
    }
    if constexpr (N == Dynamic)
      for (auto& row : held_) row.assign(static_cast<std::size_t>(n_ > 0 ? n_ : 1), Scalar(0));
    zg_.assign(static_cast<std::size_t>(3 * kL) * static_cast<std::size_t>(n_ > 0 ? n_ : 1), Scalar(0));
    const SequenceTables& st = sequence_tables(opt_.dense);  // built once per process
    nj_ = st.nj;
    facmin_ = &st.facmin;
    ratio2_ = &st.ratio2;
    rinv_ = &st.rinv;
    if (opt_.dense && n_ > 0) {
      // Dense-output work space, allocated once: every right-hand side value of every
      // line (line j has 4j-1 of them), the midpoint values, the interpolation coefficients.
      const auto nn = static_cast<std::size_t>(n_);
      fs_.assign(static_cast<std::size_t>(line_offset(kKmaxLimit + 1)) * nn, Scalar(0));
      ys_.assign(static_cast<std::size_t>(kKmaxLimit + 2) * nn, Scalar(0));
      dcoef_.assign(static_cast<std::size_t>(kMuLimit + 5) * nn, Scalar(0));
      yb_.assign(static_cast<std::size_t>(kBatch) * nn, Scalar(0));
      (void)dense_tables();  // built once per process, here rather than inside a step
      (void)dense_terms();
    }
  }

  [[nodiscard]] int size() const { return n_; }
  [[nodiscard]] const BsOptions<Scalar>& options() const { return opt_; }

  /// Integrate; y holds the initial state on entry and the state at the last output
  /// time reached on return.
  template <class Rhs, class Observer>
  BsResult integrate(Rhs&& rhs, Scalar t0, Scalar* y, std::span<const Scalar> tout, Observer&& observer) {
    return integrate(std::forward<Rhs>(rhs), t0, y, tout, std::forward<Observer>(observer), NoStepHook{});
  }

  /// As above, with a hook called after every accepted step, before it is committed:
  /// hook(t_old, y_old, t_new, y_new) returns a StepHookAction. kHookStopBefore: the
  /// integration returns with `stopped_by_hook` set, y = y_old and t_reached = t_old, so the
  /// caller can locate an event in [t_old, t_new] and restart there. kHookStopAfter: the
  /// step is committed (its outputs emitted) and the integration returns at t_new.
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
    const int kmax = opt_.kmax;
    for (int i = 0; i < n; ++i)
      atol_[i] = opt_.atol.size() == 1 ? opt_.atol[0] : opt_.atol[static_cast<std::size_t>(i)];
    std::array<Scalar, kKmaxLimit + 2> a{};  // work A_j, 1-based
    for (int j = 1; j <= kmax; ++j) a[j] = (j == 1 ? Scalar(seq(1) + 1) : a[j - 1] + Scalar(seq(j)));
    std::array<Scalar, kKmaxLimit + 2> w{}, hh{}, errs{};

    const Scalar rtol = opt_.rtol;
    const std::size_t nout = tout.size();
    const Scalar span_total = tout[nout - 1] - t0;
    int k = std::max(2, std::min(kmax - 1, static_cast<int>(-num::log10(rtol + Scalar(1e-40)) * Scalar(0.6) +
                                                            Scalar(1.5))));
    Scalar h = opt_.h0 > 0 ? opt_.h0 : Scalar(0.01) * span_total;
    if (opt_.hmax > 0) h = std::min(h, opt_.hmax);
    Scalar t = t0;
    for (int i = 0; i < n; ++i) y_[i] = y[i];
    bool have_f0 = false, last_rejected = false;
    int hook_action = kHookContinue;
    int nonfinite_run = 0;

    std::size_t iout = 0;
    auto emit_reached = [&] {
      while (iout < nout && tout[iout] <= t) {
        observer(iout, tout[iout], static_cast<const Scalar*>(&y_[0]));
        ++iout;
      }
    };
    emit_reached();
    // Dense output: the last output time is the only one a step must end on.
    const bool dense = opt_.dense;
    Scalar hoptde = 0;  // step-size bound from the interpolation error (dense output), 0 = none
    double errint_rej = 0;  // the estimate that rejected the last attempt at this t, and its order
    int kc_rej = 0;
    while (iout < nout) {
      const Scalar tend = dense ? tout[nout - 1] : tout[iout];
      // 1.
      if (res.naccpt + res.nrejct >= opt_.maxstp) {
        res.status = BsStatus::too_many_steps;
        res.message = "more than " + std::to_string(opt_.maxstp) + " steps";
        break;
      }
      // 2.
      if (!have_f0) {
        const int st = rhs(t, static_cast<const Scalar*>(&y_[0]), &f0_[0]);
        ++res.nfcn;
        if (st != 0) {
          fail_rhs(res, st, t);
          break;
        }
        have_f0 = true;
      }
      // 3. (re-entered after a non-finite error estimate, without steps 1-2)
      Scalar hwant = h;
      bool clipped = false;
      int kc = 0;
      bool accept = false, failed = false;
      double errint = 0;  // dense output: the interpolation error estimate of an accepted attempt
      for (;;) {
        hwant = h;
        clipped = false;
        if (t + Scalar(1.01) * h >= tend) {
          h = tend - t;
          clipped = true;
        }
        if (h <= 0 || h < Scalar(1e-14) * std::max(num::abs(t), span_total)) {
          res.status = BsStatus::step_underflow;
          res.message = "step size underflow at t = " + fmt_g(static_cast<double>(t));
          failed = true;
          break;
        }
        // 4.
        bool nonfinite = false;
        kc = 0;
        accept = false;
        // Lines 1..max(2, k-1) are computed by every attempt (the first decision comes
        // after line k-1, and none before line 2): their midpoint chains run interleaved, so
        // the latency of one line's RHS overlaps the others'. Not on the retry after a
        // non-finite error estimate (it would evaluate lines a sequential attempt skips).
        const int jgroup = nonfinite_run == 0 ? std::max(2, k - 1) : 0;
        if (jgroup > 0) {
          if (const int st = dense ? midpoint_group<true>(rhs, t, h, jgroup, res)
                                   : midpoint_group<false>(rhs, t, h, jgroup, res);
              st != 0) {
            fail_rhs(res, st, t);
            failed = true;
          }
        }
        for (int j = 1; !failed && j <= k + 1; ++j) {
          if (j <= jgroup) {
            cur()[1] = held_[j];
          } else if (const int st = midpoint(rhs, t, h, seq(j), cur()[1], res, dense ? fs_line(j) : nullptr,
                                             dense ? ys_line(j) : nullptr);
                     st != 0) {
            fail_rhs(res, st, t);
            failed = true;
            break;
          }
          extrapolate(j);
          if (j < 2) {
            icur_ ^= 1;  // the new row becomes the previous one (no copy)
            continue;
          }
          // Scaled differences first (the divisions are independent and vectorise), then
          // the sum in component order (the F77 engine's order: no reassociation).
          std::array<Scalar, (N > 0 ? N : 1)> qbuf;
          Scalar* q = (N == Dynamic) ? &fz_[0] : qbuf.data();
          {
            const Vec& cj = cur()[j];
            const Vec& cj1 = cur()[j - 1];
            if constexpr (kPairs) {
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
          const Scalar err = num::sqrt(s / Scalar(n));
          if (!num::isfinite(err)) {
            nonfinite = true;
            break;
          }
          errs[j] = err;
          bool decided = false;
          if (j == k - 1) {
            if (err <= 1) {
              accept = decided = true;
            } else if (err > sq(Scalar(seq(k + 1) * seq(k)) / Scalar(4))) {
              decided = true;
            }
          } else if (j == k) {
            if (err <= 1) {
              accept = decided = true;
            } else if (err > sq(Scalar(seq(k + 1)) / Scalar(2))) {
              decided = true;
            }
          } else if (j == k + 1) {
            accept = err <= 1;
            decided = true;
          }
          if (decided) {
            kc = j;
            break;
          }
          icur_ ^= 1;  // the new row becomes the previous one (no copy)
        }
        // 6a (first half). Dense output, accepted attempt: f at the step's end (the next
        // step's f0) and the interpolation polynomial with its error estimate. Neither needs
        // the step-size proposals below, so they come first: the proposals' pow() chain then
        // overlaps this work, where after it the chain held back the next step (the same
        // operations and RHS calls in either order; measured 2-4 % less wall, fig3_6a).
        if (!failed && !nonfinite && accept && dense) {
          const Scalar tnew = clipped ? tend : t + h;
          const int st = rhs(tnew, static_cast<const Scalar*>(&cur()[kc][0]), &f1_[0]);
          ++res.nfcn;
          if (st != 0) {
            fail_rhs(res, st, tnew);
            failed = true;
            break;
          }
          errint = build_dense(kc, h);
        }
        if (!failed && !nonfinite) {
          // The step-size proposal of each line. The order and step choices below read
          // lines kc-1..kc, and kc-2 only when the step went past its order (kc = k+1), so
          // only their pow() is paid (the others are never read in this step).
          for (int j = std::max(2, kc > k ? kc - 2 : kc - 1); j <= kc; ++j) {
            // In double for every scalar: a few digits suffice, and pow in long double or
            // __float128 costs as much as a cheap RHS. For Scalar = double these are
            // exactly the F77 engine's operations.
            const double errc = static_cast<double>(errs[j]);
            const double expo = 1.0 / static_cast<double>(2 * j - 1);
            const double facmin = (*facmin_)[j];  // kSafe3^expo
            double fac;
            if (errc == 0)
              fac = 1.0 / facmin;
            else
              fac = kSafe2 * std::pow(kSafe1 / errc, expo);
            fac = std::max(facmin / kFac4, std::min(1.0 / facmin, fac));
            hh[j] = h * static_cast<Scalar>(fac);
            w[j] = a[j] / hh[j];
          }
        }
        if (failed || !nonfinite) break;
        // Non-finite error estimate: quarter the step, keep k, retry from 3.
        ++res.nrejct;
        last_rejected = true;
        if (++nonfinite_run >= kMaxNonFinite) {
          res.status = BsStatus::not_finite;
          res.message = "non-finite error estimate at t = " + fmt_g(static_cast<double>(t));
          failed = true;
          break;
        }
        h = Scalar(0.25) * h;
      }
      if (failed) break;
      nonfinite_run = 0;
      // 5. order proposal
      int kopt;
      if (kc == 2) {
        kopt = last_rejected ? 2 : std::min(3, kmax - 1);
      } else if (kc <= k) {
        kopt = kc;
        if (w[kc - 1] < kOrdDec * w[kc]) kopt = kc - 1;
        if (w[kc] < kOrdInc * w[kc - 1]) kopt = std::min(kc + 1, kmax - 1);
      } else {
        kopt = kc - 1;
        if (kc > 3 && w[kc - 2] < kOrdDec * w[kc - 1]) kopt = kc - 2;
        if (w[kc] < kOrdInc * w[kopt]) kopt = std::min(kc, kmax - 1);
      }
      if (!accept) {
        // 6.
        ++res.nrejct;
        k = std::min(kopt, kc);
        h = std::min(h, hh[k]);
        last_rejected = true;
        continue;
      }
      // 6a (second half). Dense output: a step whose interpolant is poor is rejected
      // (errint from the first half, above).
      if (dense) {
        // Near the precision's floor the estimate is rounding noise: a retry with a smaller
        // step (same order) that is still above the threshold and did not at least halve it
        // is accepted, and sets no bound.
        const bool noise = kc == kc_rej && errint > opt_.dense_accept && errint > 0.5 * errint_rej;
        hoptde = noise ? Scalar(0)
                       : h / static_cast<Scalar>(std::max(
                                 std::pow(errint / (0.1 * opt_.dense_accept), 1.0 / (mu_ + 4)), 0.01));
        if (errint > opt_.dense_accept && !noise) {
          ++res.nrejct;
          h = hoptde;
          last_rejected = true;
          errint_rej = errint;
          kc_rej = kc;
          continue;
        }
        kc_rej = 0;
      }
      // 7.
      if constexpr (!std::is_same_v<std::decay_t<StepHook>, NoStepHook>) {
        const Scalar tnew = clipped ? tend : t + h;
        hook_action = hook(t, static_cast<const Scalar*>(&y_[0]), tnew, static_cast<const Scalar*>(&cur()[kc][0]));
        if (hook_action == kHookStopBefore) {
          ++res.naccpt;
          res.stopped_by_hook = true;
          res.t_event_end = static_cast<double>(tnew);
          break;
        }
      }
      ++res.naccpt;
      const Scalar t_old = t, h_step = h;
      t = clipped ? tend : t + h;
      for (int i = 0; i < n; ++i) y_[i] = cur()[kc][i];
      if (dense) {
        for (int i = 0; i < n; ++i) f0_[i] = f1_[i];
        have_f0 = true;
      } else {
        have_f0 = false;
      }
      Scalar hnew;
      if (kopt <= kc)
        hnew = hh[kopt];
      else if (kc >= 3 && kc < k && w[kc] < kOrdInc * w[kc - 1])
        hnew = hh[kc] * a[kopt + 1] / a[kc];
      else
        hnew = hh[kc] * a[kopt] / a[kc];
      if (last_rejected) {
        kopt = std::min(kopt, kc);
        hnew = std::min(hnew, h);
      }
      k = kopt;
      if (clipped) hnew = std::max(hnew, hwant);
      if (dense && hoptde > 0) hnew = std::min(hnew, hoptde);
      if (opt_.hmax > 0) hnew = std::min(hnew, opt_.hmax);
      h = hnew;
      last_rejected = false;
      res.t_reached = static_cast<double>(t);
      if (dense) {
        // Outputs inside the step from the interpolant, evaluated kBatch at a time (the
        // Horner chains of different outputs are independent); one at the step's end exactly.
        while (iout < nout && tout[iout] <= t) {
          if (tout[iout] == t) {
            observer(iout, tout[iout], static_cast<const Scalar*>(&y_[0]));
            ++iout;
            continue;
          }
          std::array<Scalar, kBatch> theta{};
          int m = 0;
          while (m < kBatch && iout + static_cast<std::size_t>(m) < nout && tout[iout + static_cast<std::size_t>(m)] < t) {
            theta[static_cast<std::size_t>(m)] = (tout[iout + static_cast<std::size_t>(m)] - t_old) / h_step;
            ++m;
          }
          dense_eval(theta, m, &yb_[0]);
          for (int b = 0; b < m; ++b, ++iout)
            observer(iout, tout[iout], static_cast<const Scalar*>(&yb_[static_cast<std::size_t>(b * n)]));
        }
      } else {
        emit_reached();
      }
      if (hook_action == kHookStopAfter) {
        res.stopped_by_hook = true;
        res.t_event_end = static_cast<double>(t);
        break;
      }
    }
    for (int i = 0; i < n; ++i) y[i] = y_[i];
    return res;
  }

  /// Convenience: no observer.
  template <class Rhs>
  BsResult integrate(Rhs&& rhs, Scalar t0, Scalar* y, Scalar t1) {
    const Scalar tt[1] = {t1};
    return integrate(std::forward<Rhs>(rhs), t0, y, std::span<const Scalar>(tt, 1),
                     [](std::size_t, Scalar, const Scalar*) {});
  }

 private:
  static constexpr double kSafe1 = 0.65;
  static constexpr double kSafe2 = 0.94;
  static constexpr double kSafe3 = 0.02;
  static constexpr double kFac4 = 4.0;
  static constexpr Scalar kOrdDec = Scalar(0.8);
  static constexpr Scalar kOrdInc = Scalar(0.9);
  static constexpr int kMaxNonFinite = 10;

  static constexpr int kMuLimit = 2 * kKmaxLimit - 3;
  static constexpr int kBatch = 4;  // outputs interpolated together
  static constexpr int kL = kKmaxLimit + 2;  // line index bound (1-based lines)
  static constexpr std::size_t widx(int jb, int je, int j) {
    return (static_cast<std::size_t>(jb) * kL + static_cast<std::size_t>(je)) * kL + static_cast<std::size_t>(j);
  }
  // Tables of the dense output, the same for every instance (step numbers 4j-2): weights of
  // the h^2 polynomial extrapolation to h = 0 from lines jb..je, the Lagrange form of
  // Aitken–Neville in x_j = n_j^-2, w_j = prod_{l != j} x_l/(x_l - x_j) at widx(jb, je, j);
  // then the binomial coefficients C(p, r), p < kMuLimit, at kL^3 + p kMuLimit + r.
  static const std::vector<Scalar>& dense_tables() {
    static const std::vector<Scalar> t = [] {
      std::vector<Scalar> v(static_cast<std::size_t>(kL * kL * kL + kMuLimit * kMuLimit), Scalar(0));
      auto x = [](int j) { return Scalar(1) / (Scalar(4 * j - 2) * Scalar(4 * j - 2)); };
      for (int jb = 1; jb < kL; ++jb)
        for (int je = jb; je < kL; ++je)
          for (int j = jb; j <= je; ++j) {
            Scalar w = 1;
            for (int l = jb; l <= je; ++l)
              if (l != j) w = w * x(l) / (x(l) - x(j));
            v[widx(jb, je, j)] = w;
          }
      Scalar* c = &v[static_cast<std::size_t>(kL * kL * kL)];
      for (int p = 0; p < kMuLimit; ++p) {
        c[p * kMuLimit] = 1;
        for (int r = 1; r <= p; ++r)
          c[p * kMuLimit + r] = c[(p - 1) * kMuLimit + r - 1] + (r <= p - 1 ? c[(p - 1) * kMuLimit + r] : Scalar(0));
      }
      return v;
    }();
    return t;
  }
  // The multiply-adds of the midpoint derivatives (build_dense), per last line kc and
  // order κ = 1..2kc-3: h^κ y^(κ)(mid) ≈ h · Σ c · (slot of fs_), c = (±w_j (n_j/2)^(κ-1))
  // C(κ-1, q) (the factors multiplied in this order, (n_j/2)^p by successive products), the
  // slots being f(mid), S_o (at mid+o) or D_o (at mid-o) of lines ⌈κ/2⌉..kc, w_j the
  // extrapolation weight of line j over lines ⌈κ/2⌉..kc, q = (κ-1-o)/2, the sign (-1)^q.
  // Terms of (kc, κ) at [start[kc][κ], start[kc][κ+1]), line by line, each line's f(mid)
  // first and then o decreasing: the order of the sum, the same in the fixed-size and the
  // dynamic path (so both give the same bits). c does not depend on the step, so a step pays
  // one multiply-add per term and component and one product by h per row.
  struct DenseTerm {
    int slot;   // row of fs_
    Scalar c;   // ±w_j (n_j/2)^p C(p, q): the term's coefficient without the factor h
  };
  struct DenseTerms {
    std::vector<DenseTerm> terms;
    std::array<std::array<int, kMuLimit + 2>, kKmaxLimit + 1> start{};
  };
  static const DenseTerms& dense_terms() {
    static const DenseTerms t = [] {
      DenseTerms d;
      const std::vector<Scalar>& wext = dense_tables();
      const Scalar* binom = &wext[static_cast<std::size_t>(kL * kL * kL)];
      for (int kc = 2; kc <= kKmaxLimit; ++kc) {
        const int mu = 2 * kc - 3;
        for (int kap = 1; kap <= mu + 1; ++kap) {
          d.start[kc][kap] = static_cast<int>(d.terms.size());
          if (kap > mu) break;
          const int p = kap - 1;
          for (int j = (kap + 1) / 2; j <= kc; ++j) {
            const int half = 2 * j - 1;  // n_j / 2 for n_j = 4j - 2
            const Scalar w = wext[widx((kap + 1) / 2, kc, j)];
            const int mid = line_offset(j) + half;
            const Scalar* bn = binom + p * kMuLimit;
            Scalar wp = w;  // w_j (n_j/2)^p
            for (int i = 0; i < p; ++i) wp = wp * Scalar(half);
            const auto c = [wp](Scalar b, bool neg) { return (neg ? -wp : wp) * b; };
            if (p % 2 == 0) d.terms.push_back({mid, c(bn[p / 2], (p / 2) % 2 != 0)});
            for (int q = 0; 2 * q < p; ++q) {
              const int o = p - 2 * q;
              d.terms.push_back({p % 2 == 0 ? mid + o : mid - o, c(bn[q], q % 2 != 0)});
            }
          }
        }
      }
      return d;
    }();
    return t;
  }
  int seq(int j) const { return nj_[j]; }
  // First right-hand-side slot of line j (1-based) in fs_: line i holds 4i-1 slots.
  static constexpr int line_offset(int j) { return (j - 1) * (2 * j - 1); }
  Scalar* fs_line(int j) { return &fs_[static_cast<std::size_t>(line_offset(j)) * static_cast<std::size_t>(n_)]; }
  Scalar* ys_line(int j) { return &ys_[static_cast<std::size_t>(j) * static_cast<std::size_t>(n_)]; }
  Scalar* dcoef_row(int r) { return &dcoef_[static_cast<std::size_t>(r) * static_cast<std::size_t>(n_)]; }

  // Dense output after an accepted step over [t, t+h] that used lines 1..kc (HNW §II.9):
  // y at the midpoint and its derivatives of order 1..mu = 2kc-3 there, each extrapolated
  // from central differences of the stored right-hand sides of the lines that have enough
  // of them; then the polynomial P(θ) = H(θ) + θ²(1-θ)² Σ a_κ (θ-1/2)^κ/κ!, H the cubic
  // Hermite interpolant of y and h·f at both ends, the a_κ making P^(κ)(1/2) equal the
  // extrapolated h^κ y^(κ). Returns the interpolation error estimate (the size of the last
  // term, weighted as the step's error; > BsOptions::dense_accept rejects the step).
  double build_dense(int kc, Scalar h) {
    const int n = (N == Dynamic) ? n_ : N;
    const int mu = 2 * kc - 3;  // ODEX's default degree (mu + 4 for the polynomial)
    mu_ = mu;
    const std::vector<Scalar>& wext = dense_tables();
    // rows: 0 y0, 1 Δ = y1 - y0, 2 α = Δ - h f1, 3 β = h f0 - Δ, 4 + κ: d_κ then a_κ
    {
      Scalar* r = dcoef_row(4);  // y at the midpoint, extrapolated from every line
      for (int i = 0; i < n; ++i) r[i] = 0;
      for (int j = 1; j <= kc; ++j) {
        const Scalar w = wext[widx(1, kc, j)];
        const Scalar* ym = ys_line(j);
        for (int i = 0; i < n; ++i) r[i] = r[i] + w * ym[i];
      }
    }
    const std::size_t nn = static_cast<std::size_t>(n_);
    // h^κ y^(κ)(mid) ≈ h (n_j/2)^p δ^p f_j(mid), p = κ-1, δ^p f(mid) = Σ_q (-1)^q C(p,q)
    // f(mid+p-2q) (central differences of spacing 2 h_j), extrapolated over the lines
    // kb = ⌈κ/2⌉..kc that hold enough values. The coefficients are symmetric in the offset
    // for even p and antisymmetric for odd p, so each line's f values are first turned, in
    // place, into S_o = f(mid+o) + f(mid-o) (stored at mid+o) and D_o = f(mid+o) - f(mid-o)
    // (at mid-o), and every difference reads half the terms. The products of extrapolation
    // weight, (n_j/2)^p and signed binomial are tabulated per (kc, κ) (dense_terms()), so
    // a row is one list of multiply-adds, summed in registers, times h.
    Scalar* __restrict__ fsb = &fs_[0];
    for (int j = 1; j <= kc; ++j) {
      const int kapmax = std::min(mu, 2 * j);  // line j enters the differences of order < 2j
      Scalar* __restrict__ fmid = fsb + static_cast<std::size_t>(line_offset(j) + seq(j) / 2) * nn;
      for (int o = 1; o < kapmax; ++o) {
        Scalar* __restrict__ fp = fmid + static_cast<std::size_t>(o) * nn;
        Scalar* __restrict__ fm = fmid - static_cast<std::size_t>(o) * nn;
        if constexpr (kPairs) {
          for (int i = 0; i < N; i += 2) {
            const V2 a = ld2(&fp[i]), b = ld2(&fm[i]);
            st2(&fp[i], a + b);
            st2(&fm[i], a - b);
          }
        } else {
          for (int i = 0; i < n; ++i) {
            const Scalar a = fp[i], b = fm[i];
            fp[i] = a + b;
            fm[i] = a - b;
          }
        }
      }
    }
    const DenseTerms& dt = dense_terms();
    for (int kap = 1; kap <= mu; ++kap) {
      const DenseTerm* tb = &dt.terms[static_cast<std::size_t>(dt.start[kc][kap])];
      const DenseTerm* te = &dt.terms[static_cast<std::size_t>(dt.start[kc][kap + 1])];
      Scalar* __restrict__ r = dcoef_row(4 + kap);
      if constexpr (N != Dynamic) {
        Scalar acc[N];
        for (int i = 0; i < N; ++i) acc[i] = 0;
        for (const DenseTerm* tm = tb; tm != te; ++tm) {
          const Scalar cq = tm->c;
          const Scalar* __restrict__ v = fsb + static_cast<std::size_t>(tm->slot) * N;
          for (int i = 0; i < N; ++i) acc[i] = acc[i] + cq * v[i];
        }
        for (int i = 0; i < N; ++i) r[i] = h * acc[i];
      } else {
        for (int i = 0; i < n; ++i) r[i] = 0;
        for (const DenseTerm* tm = tb; tm != te; ++tm) {
          const Scalar cq = tm->c;
          const Scalar* __restrict__ v = fsb + static_cast<std::size_t>(tm->slot) * nn;
          for (int i = 0; i < n; ++i) r[i] = r[i] + cq * v[i];
        }
        for (int i = 0; i < n; ++i) r[i] = h * r[i];
      }
    }
    Scalar* r0 = dcoef_row(0);
    Scalar* r1 = dcoef_row(1);
    Scalar* r2 = dcoef_row(2);
    Scalar* r3 = dcoef_row(3);
    const Scalar* y1 = &cur()[kc][0];
    // The Hermite cubic's θ-derivatives at θ = 1/2 are subtracted from d_0..d_3 (rows 4..7)
    // before the a_κ are formed (a_κ = 16 (d_κ - H^(κ) + C(κ,2) a_{κ-2} - κ!/(κ-4)! a_{κ-4})).
    for (int i = 0; i < n; ++i) {
      const Scalar y0 = y_[i];
      const Scalar del = y1[i] - y0;
      const Scalar al = del - h * f1_[i];
      const Scalar be = h * f0_[i] - del;
      r0[i] = y0;
      r1[i] = del;
      r2[i] = al;
      r3[i] = be;
      const Scalar herm[4] = {Scalar(0.5) * (y0 + y1[i]) + Scalar(0.125) * (al + be), del + Scalar(0.25) * (al - be),
                              -(al + be), Scalar(6) * (be - al)};
      for (int kap = 0; kap <= std::min(mu, 3); ++kap) dcoef_row(4 + kap)[i] = dcoef_row(4 + kap)[i] - herm[kap];
    }
    for (int kap = 0; kap <= mu; ++kap) {
      Scalar* __restrict__ r = dcoef_row(4 + kap);
      const Scalar c2 = Scalar(kap * (kap - 1) / 2);
      const Scalar c4 = Scalar(kap * (kap - 1) * (kap - 2) * (kap - 3));
      const Scalar* __restrict__ a2 = kap >= 2 ? dcoef_row(2 + kap) : r;
      const Scalar* __restrict__ a4 = kap >= 4 ? dcoef_row(kap) : r;
      if constexpr (kPairs) {
        const V2 c2v = {c2, c2}, c4v = {c4, c4}, sixteen = {16.0, 16.0};
        for (int i = 0; i < N; i += 2) {
          V2 v = ld2(&r[i]);
          if (kap >= 2) v = v + c2v * ld2(&a2[i]);
          if (kap >= 4) v = v - c4v * ld2(&a4[i]);
          st2(&r[i], sixteen * v);
        }
      } else {
        for (int i = 0; i < n; ++i) {
          Scalar v = r[i];
          if (kap >= 2) v = v + c2 * a2[i];
          if (kap >= 4) v = v - c4 * a4[i];
          r[i] = Scalar(16) * v;
        }
      }
    }
    double errsum = 0;
    {
      const Scalar* am = dcoef_row(4 + mu);
      for (int i = 0; i < n; ++i) {
        const Scalar sc = atol_[i] + opt_.rtol * std::max(num::abs(y_[i]), num::abs(y1[i]));
        const double q = static_cast<double>(am[i] / sc);
        errsum += q * q;
      }
    }
    // Store a_κ/κ! so that an evaluation needs no division.
    Scalar fact = 1;
    for (int kap = 2; kap <= mu; ++kap) {
      fact = fact * Scalar(kap);
      Scalar* r = dcoef_row(4 + kap);
      if constexpr (kPairs) {
        const V2 f = {fact, fact};
        for (int i = 0; i < N; i += 2) st2(&r[i], ld2(&r[i]) / f);
      } else {
        for (int i = 0; i < n; ++i) r[i] = r[i] / fact;
      }
    }
    // max over θ of θ²(1-θ)² |θ-1/2|^mu / mu!
    const double sx = 0.5 * std::sqrt(static_cast<double>(mu) / (mu + 4.0));
    double errfac = 1.0 / ((mu + 4.0) * (mu + 4.0));
    for (int j = 1; j <= mu; ++j) errfac *= sx / j;
    return std::sqrt(errsum / n) * errfac;
  }

  // The interpolant of the last accepted step at θ_b = (t_b - t_old)/h, b < m <= kBatch,
  // into out[b n + i].
  void dense_eval(const std::array<Scalar, kBatch>& theta, int m, Scalar* out) {
    const int n = (N == Dynamic) ? n_ : N;
    const std::size_t nn = static_cast<std::size_t>(n);
    const Scalar* d = &dcoef_[0];
    if constexpr (kPairs) {
      // double, even N: the same operations on pairs of components (IEEE per lane, so the
      // same bits), the kBatch x N/2 accumulators in vector registers.
      constexpr int P = N / 2;
      V2 acc[kBatch][P];
      V2 sv[kBatch];
      for (int b = 0; b < kBatch; ++b) {
        const double x = (b < m ? theta[b] : 0.5) - 0.5;
        sv[b] = V2{x, x};
      }
      const double* a = d + static_cast<std::size_t>(4 + mu_) * nn;
      for (int b = 0; b < kBatch; ++b)
        for (int i = 0; i < P; ++i) acc[b][i] = ld2(&a[2 * i]);
      for (int kap = mu_ - 1; kap >= 0; --kap) {
        a = d + static_cast<std::size_t>(4 + kap) * nn;
        V2 ak[P];
        for (int i = 0; i < P; ++i) ak[i] = ld2(&a[2 * i]);
        for (int b = 0; b < kBatch; ++b)
          for (int i = 0; i < P; ++i) acc[b][i] = ak[i] + acc[b][i] * sv[b];
      }
      for (int b = 0; b < m; ++b) {
        const double th = theta[b], th1 = 1.0 - th;
        const double w = (th * th1) * (th * th1);
        const V2 thv = {th, th}, th1v = {th1, th1}, wv = {w, w};
        double* o = out + b * N;
        for (int i = 0; i < P; ++i) {
          const V2 herm = ld2(&d[2 * i]) + thv * (ld2(&d[nn + 2 * i]) + th1v * (ld2(&d[2 * nn + 2 * i]) * thv +
                                                                                ld2(&d[3 * nn + 2 * i]) * th1v));
          st2(&o[2 * i], herm + wv * acc[b][i]);
        }
      }
      return;
    } else if constexpr (N != Dynamic) {
      // Fixed size: the kBatch x N Horner accumulators live in registers (a full batch is
      // always evaluated; unused lanes compute at θ = 1/2 and are not stored).
      Scalar acc[kBatch][N];
      Scalar sv[kBatch];
      for (int b = 0; b < kBatch; ++b) sv[b] = (b < m ? theta[b] : Scalar(0.5)) - Scalar(0.5);
      const Scalar* a = d + static_cast<std::size_t>(4 + mu_) * nn;
      for (int b = 0; b < kBatch; ++b)
        for (int i = 0; i < N; ++i) acc[b][i] = a[i];
      for (int kap = mu_ - 1; kap >= 0; --kap) {
        a = d + static_cast<std::size_t>(4 + kap) * nn;
        Scalar ak[N];
        for (int i = 0; i < N; ++i) ak[i] = a[i];
        for (int b = 0; b < kBatch; ++b)
          for (int i = 0; i < N; ++i) acc[b][i] = ak[i] + acc[b][i] * sv[b];
      }
      for (int b = 0; b < m; ++b)
        for (int i = 0; i < N; ++i) out[b * N + i] = dense_finish(d, nn, i, theta[b], acc[b][i]);
      return;
    }
    std::array<Scalar, kBatch> s{};
    for (int b = 0; b < m; ++b) s[b] = theta[b] - Scalar(0.5);
    // Horner in (θ - 1/2) over the a_κ/κ!: m·n independent chains.
    const Scalar* a = d + static_cast<std::size_t>(4 + mu_) * nn;
    for (int b = 0; b < m; ++b)
      for (int i = 0; i < n; ++i) out[b * n + i] = a[i];
    for (int kap = mu_ - 1; kap >= 0; --kap) {
      a = d + static_cast<std::size_t>(4 + kap) * nn;
      for (int b = 0; b < m; ++b) {
        const Scalar sb = s[b];
        Scalar* o = out + b * n;
        for (int i = 0; i < n; ++i) o[i] = a[i] + o[i] * sb;
      }
    }
    for (int b = 0; b < m; ++b)
      for (int i = 0; i < n; ++i) out[b * n + i] = dense_finish(d, nn, i, theta[b], out[b * n + i]);
  }

  // H(θ) + θ²(1-θ)² acc for component i (rows 0..3 of d: y0, Δ, α, β), the operations in
  // this order (the pair version in dense_eval does the same per lane).
  static Scalar dense_finish(const Scalar* d, std::size_t nn, int i, Scalar th, Scalar acc) {
    const Scalar th1 = Scalar(1) - th;
    const Scalar w = (th * th1) * (th * th1);
    const Scalar herm = d[i] + th * (d[nn + i] + th1 * (d[2 * nn + i] * th + d[3 * nn + i] * th1));
    return herm + w * acc;
  }

  static Scalar sq(Scalar x) { return x * x; }

  // Pairs of doubles for the division-heavy loops (GCC vector extensions: SSE2 on x86-64,
  // scalar code elsewhere). Each lane is one IEEE operation, so results equal the scalar
  // loops bit for bit; only the throughput of the divider changes.
  static constexpr bool kPairs = std::is_same_v<Scalar, double> && N != Dynamic && N % 2 == 0;
  typedef double V2 __attribute__((vector_size(16)));
  typedef double V2u __attribute__((vector_size(16), aligned(8), may_alias));
  typedef long long L2 __attribute__((vector_size(16)));
  static V2 ld2(const double* p) { return *reinterpret_cast<const V2u*>(p); }
  static void st2(double* p, V2 v) { *reinterpret_cast<V2u*>(p) = v; }
  static V2 abs2(V2 v) {
    const L2 mask = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL};
    return reinterpret_cast<V2>(reinterpret_cast<L2>(v) & mask);
  }

  static std::string fmt_g(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
  }

  std::string validate(Scalar t0, const Scalar* y, std::span<const Scalar> tout) const {
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
      const double floor = dense_rtol_min<Scalar>();
      if (static_cast<double>(opt_.rtol) < floor)
        return "rtol = " + fmt_g(static_cast<double>(opt_.rtol)) + " is below " + fmt_g(floor) + " (" +
               fmt_g(kDenseRtolEps) + " eps of " + num::name<Scalar>() +
               "): with dense output the step-size control would follow rounding; use a wider precision or the "
               "faithful (clipped) method";
    }
    return {};
  }

  static void fail_rhs(BsResult& res, int st, Scalar t) {
    res.status = BsStatus::rhs_failed;
    res.rhs_status = st;
    res.message = "right-hand side returned status " + std::to_string(st) + " at t = " + fmt_g(static_cast<double>(t));
  }

  // Gragg's modified midpoint rule with m substeps over [t, t+H]; result into out.
  // Dense output: fsl receives f at every substep 0..m (m+1 vectors), ymid the state at
  // substep m/2; both null otherwise.
  template <class Rhs>
  int midpoint(Rhs& rhs, Scalar t, Scalar hbig, int m, Vec& out, BsResult& res, Scalar* fsl, Scalar* ymid) {
    const Scalar hs = hbig / Scalar(m);
    const Scalar h2 = Scalar(2) * hs;
    // The two latest midpoint states; their roles swap by pointer (no copy per substep).
    Scalar* zm = &zm_[0];
    Scalar* z = &z_[0];
    midpoint_start(zm, z, hs, fsl);
    for (int s = 1; s <= m - 1; ++s) {
      if (ymid && 2 * s == m) copy_n(z, ymid);
      Scalar* fz = fsl ? fsl + static_cast<std::size_t>(s) * static_cast<std::size_t>(n_) : &fz_[0];
      const int st = rhs(t + Scalar(s) * hs, static_cast<const Scalar*>(z), fz);
      if (st != 0) {
        res.nfcn += s;
        return st;
      }
      add_scaled(zm, h2, fz);  // z_{s+1} = z_{s-1} + 2 hs f(z_s)
      std::swap(zm, z);
    }
    Scalar* fz = fsl ? fsl + static_cast<std::size_t>(m) * static_cast<std::size_t>(n_) : &fz_[0];
    const int st = rhs(t + hbig, static_cast<const Scalar*>(z), fz);
    res.nfcn += m;  // one call per substep (counted here, not in the loop: a register, not memory)
    if (st != 0) return st;
    smoothing_step(z, zm, hs, fz, &out[0]);
    return 0;
  }

  // Lines 1..jg of one attempt, their midpoint chains interleaved substep by substep; the
  // operations of each line are those of midpoint(), in the same order, so the results
  // (held_[j]) are the same bits.
  template <bool dense, class Rhs>
  int midpoint_group(Rhs& rhs, Scalar t, Scalar hbig, int jg, BsResult& res) {
    const std::size_t nn = static_cast<std::size_t>(n_);
    std::array<Scalar, kKmaxLimit + 2> hs, h2;  // only 1..jg are used
    std::array<Scalar*, kKmaxLimit + 2> zm, z;
    for (int j = 1; j <= jg; ++j) {
      hs[j] = hbig / Scalar(seq(j));
      h2[j] = Scalar(2) * hs[j];
      zm[j] = &zg_[static_cast<std::size_t>(2 * j) * nn];
      z[j] = &zg_[static_cast<std::size_t>(2 * j + 1) * nn];
      midpoint_start(zm[j], z[j], hs[j], dense ? fs_line(j) : nullptr);
    }
    const int mmax = seq(jg);
    std::int64_t calls = 0;  // added to res.nfcn on return (a register across the calls)
    for (int s = 1; s <= mmax; ++s) {
      for (int j = jg; j >= 1; --j) {  // longest line first
        const int m = seq(j);
        if (s > m) break;  // the shorter lines are done
        Scalar* fz;
        if constexpr (dense)
          fz = fs_line(j) + static_cast<std::size_t>(s) * nn;
        else
          fz = &zg_[static_cast<std::size_t>(2 * kL + j) * nn];
        if (s < m) {
          if constexpr (dense)
            if (2 * s == m) copy_n(z[j], ys_line(j));
          const int st = rhs(t + Scalar(s) * hs[j], static_cast<const Scalar*>(z[j]), fz);
          ++calls;
          if (st != 0) {
            res.nfcn += calls;
            return st;
          }
          add_scaled(zm[j], h2[j], fz);  // z_{s+1} = z_{s-1} + 2 hs f(z_s)
          std::swap(zm[j], z[j]);
        } else {
          const int st = rhs(t + hbig, static_cast<const Scalar*>(z[j]), fz);
          ++calls;
          if (st != 0) {
            res.nfcn += calls;
            return st;
          }
          smoothing_step(z[j], zm[j], hs[j], fz, &held_[j][0]);
        }
      }
    }
    res.nfcn += calls;
    return 0;
  }

  // The pieces of the modified midpoint rule, written once for midpoint() and
  // midpoint_group() (restrict-qualified so the 6-component loops vectorise).
  // zm = y, z = y + hs f0; the dense line's first f value is f0.
  void midpoint_start(Scalar* __restrict__ zm, Scalar* __restrict__ z, Scalar hs, Scalar* __restrict__ fsl) const {
    const int n = (N == Dynamic) ? n_ : N;
    for (int i = 0; i < n; ++i) {
      zm[i] = y_[i];
      z[i] = y_[i] + hs * f0_[i];
    }
    if (fsl)
      for (int i = 0; i < n; ++i) fsl[i] = f0_[i];
  }
  // zm = zm + h2 f
  void add_scaled(Scalar* __restrict__ zm, Scalar h2, const Scalar* __restrict__ f) const {
    const int n = (N == Dynamic) ? n_ : N;
    for (int i = 0; i < n; ++i) zm[i] = zm[i] + h2 * f[i];
  }
  // out = 0.5 (z + zm + hs f), the operations in that order
  void smoothing_step(const Scalar* __restrict__ z, const Scalar* __restrict__ zm, Scalar hs,
                      const Scalar* __restrict__ f, Scalar* __restrict__ out) const {
    const int n = (N == Dynamic) ? n_ : N;
    for (int i = 0; i < n; ++i) out[i] = Scalar(0.5) * (z[i] + zm[i] + hs * f[i]);
  }
  void copy_n(const Scalar* __restrict__ from, Scalar* __restrict__ to) const {
    const int n = (N == Dynamic) ? n_ : N;
    for (int i = 0; i < n; ++i) to[i] = from[i];
  }

  // Fill cur()[2..j] from cur()[1] (the new midpoint result) and prev() (row j-1).
  void extrapolate(int j) {
    const int n = (N == Dynamic) ? n_ : N;  // a compile-time bound lets the loops unroll
    const bool rational = opt_.extrapolation == Extrapolation::rational;
    auto& cu = cur();
    const auto& pr = prev();
    for (int l = 2; l <= j; ++l) {
      const Scalar r = (*ratio2_)[j][l];
      if (!rational) {
        // Aitken–Neville; no division (the reciprocal is tabulated)
        const Scalar inv = (*rinv_)[j][l];
        for (int i = 0; i < n; ++i) cu[l][i] = cu[l - 1][i] + (cu[l - 1][i] - pr[l - 1][i]) * inv;
        continue;
      }
      // Stoer–Bulirsch rational step; where e or the denominator vanishes, the polynomial
      // step d/(r-1). Written without branches (both quotients formed, one selected, the
      // same operations as the branching form) so the components go through the vector
      // divider together.
      const Scalar rm1 = r - Scalar(1);
      if constexpr (kPairs) {
        // double, even N: two components per vector operation (IEEE per lane, so the
        // same bits as the scalar loop below)
        const V2 rv = {r, r}, one = {1.0, 1.0}, rm1v = {rm1, rm1}, zero = {0.0, 0.0};
        for (int i = 0; i < N; i += 2) {
          const V2 c1 = ld2(&cu[l - 1][i]);
          const V2 d = c1 - ld2(&pr[l - 1][i]);
          const V2 e = (l >= 3) ? c1 - ld2(&pr[l - 2][i]) : c1 - zero;
          const V2 den = rv * (one - d / e) - one;
          const V2 div = ((e != zero) & (den != zero)) ? den : rm1v;
          st2(&cu[l][i], c1 + d / div);
        }
        continue;
      }
      for (int i = 0; i < n; ++i) {
        const Scalar d = cu[l - 1][i] - pr[l - 1][i];
        const Scalar back = (l >= 3) ? pr[l - 2][i] : Scalar(0);
        const Scalar e = cu[l - 1][i] - back;
        const Scalar den = r * (Scalar(1) - d / e) - Scalar(1);  // inf/NaN when e == 0: not selected
        const Scalar div = (e != 0 && den != 0) ? den : rm1;
        cu[l][i] = cu[l - 1][i] + d / div;
      }
    }
  }

  BsOptions<Scalar> opt_;
  int n_;
  Vec y_{}, f0_{}, zm_{}, z_{}, fz_{}, sc_{}, atol_{}, f1_{};
  std::array<int, kKmaxLimit + 2> nj_{};  // step numbers of the lines, 1-based
  // Constants of the step-number sequence (2j or 4j-2), the same for every instance and so
  // computed once per process (13 pow() calls and two tables cost more than a short solve):
  // the step numbers, the smallest step-size factor per line kSafe3^(1/(2j-1)), and the
  // extrapolation constants of line j, column l, (n_j / n_{j-l+1})^2 and 1/(that - 1).
  using Table2 = std::array<std::array<Scalar, kKmaxLimit + 2>, kKmaxLimit + 2>;
  struct SequenceTables {
    std::array<int, kKmaxLimit + 2> nj{};
    std::array<double, kKmaxLimit + 2> facmin{};
    Table2 ratio2{}, rinv{};
  };
  static const SequenceTables& sequence_tables(bool dense) {
    auto make = [](bool d) {
      SequenceTables t;
      for (int j = 0; j < kKmaxLimit + 2; ++j) t.nj[j] = d ? 4 * j - 2 : 2 * j;
      for (int j = 1; j < kKmaxLimit + 2; ++j) t.facmin[j] = std::pow(kSafe3, 1.0 / static_cast<double>(2 * j - 1));
      for (int j = 2; j < kKmaxLimit + 2; ++j)
        for (int l = 2; l <= j; ++l) {
          const Scalar q = Scalar(t.nj[j]) / Scalar(t.nj[j - l + 1]);
          t.ratio2[j][l] = q * q;
          t.rinv[j][l] = Scalar(1) / (t.ratio2[j][l] - Scalar(1));
        }
      return t;
    };
    static const SequenceTables even = make(false), dense_seq = make(true);
    return dense ? dense_seq : even;
  }
  const std::array<double, kKmaxLimit + 2>* facmin_ = nullptr;
  const Table2* ratio2_ = nullptr;
  const Table2* rinv_ = nullptr;
  std::vector<Scalar> fs_, ys_, dcoef_, yb_;
  // Interleaved lines (midpoint_group): zm, z of line j in rows 2j, 2j+1, its f in row
  // 2 kL + j (non-dense); the line results in held_.
  std::vector<Scalar> zg_;
  std::array<Vec, kKmaxLimit + 2> held_{};  // dense output (empty otherwise); yb_: kBatch outputs
  int mu_ = 0;                            // highest midpoint derivative in the current interpolant
  // The extrapolation tableau's current and previous rows (columns 1..kmax): two rows
  // whose roles swap by flipping icur_, so a new line copies nothing.
  std::array<std::array<Vec, kKmaxLimit + 2>, 2> tab_{};
  int icur_ = 0;
  std::array<Vec, kKmaxLimit + 2>& cur() { return tab_[static_cast<std::size_t>(icur_)]; }
  std::array<Vec, kKmaxLimit + 2>& prev() { return tab_[static_cast<std::size_t>(icur_ ^ 1)]; }
};

inline const char* to_string(BsStatus s) {
  switch (s) {
    case BsStatus::success: return "success";
    case BsStatus::bad_input: return "bad input";
    case BsStatus::too_many_steps: return "too many steps";
    case BsStatus::step_underflow: return "step size underflow";
    case BsStatus::rhs_failed: return "right-hand side failed";
    case BsStatus::not_finite: return "non-finite state";
  }
  return "unknown";
}

}  // namespace nanopush
