// The engines of the work-precision benchmark, for any right-hand side that follows the
// integrator contract of integration.hpp: `int rhs(S t, const S* y, S* dydt) const`,
// templated on the scalar S (double, long double, __float128).
//
// Every engine closure measures its own wall time (Solve + seconds below): from the first
// call into the integrator (including its creation and set-up, which a user also pays) to
// the last output, with the outputs stored in the engine's own precision; conversion to quad
// for the error measurement happens outside the timed region.
//
// Engines (names as in the CSV):
//   cxx-faithful, cxx-modern   the C++ Bulirsch-Stoer (BsOptions::faithful / ::modern), RHS inlined;
//                              in double, long double or __float128 (precision column)
//   cxx-modern-odex            cxx-modern with ODEX's interpolation acceptance (dense_accept = 10);
//                              run only when named in --engines (docs/bulirsch_stoer.md)
//   cxx-dop853                 the C++ Dormand-Prince 8(5,3) (dop853.hpp: the method of Hairer's
//                              DOP853, dense output of order 7), double; RHS inlined
//   f77-callback               fortran/bsint.f through np_f77_bsint_fcn: the same C++ RHS as its FCN
//   cvode-adams, cvode-bdf     SUNDIALS CVODE: Adams-Moulton (orders 1-12) with the fixed-point
//                              nonlinear solver; BDF (orders 1-5) with Newton and the dense direct
//                              solver, difference-quotient Jacobian (its RHS calls are counted)
//   arkode-erk8                SUNDIALS ARKODE ERKStep with ARKODE_FEHLBERG_13_7_8 (the highest-order
//                              explicit table of SUNDIALS 6.4; order 8 with an embedded 7)
//   odeint-bs, odeint-bs-dense Boost.Odeint bulirsch_stoer (steps clipped at the output times, as
//                              integrate_times does) and bulirsch_stoer_dense_out (interpolation);
//                              benchmark only, header-only (bench_odeint.hpp)
// Scene-specific engines (the F77 RHS through np_f77_bsint_smooth_bar) are added by the scene.
#pragma once
#include <cstdlib>
#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "f77_bsint.h"
#include "bench/bench.hpp"
#include "nanopush/numerics/bulirsch_stoer.hpp"
#include "nanopush/numerics/dop853.hpp"

#ifdef NANOPUSH_HAVE_SUNDIALS
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>
#endif

namespace nanopush::bench {

/// Which engines to build. Empty `only` = all.
struct EngineConfig {
  std::vector<Precision> precisions = {Precision::double_};  ///< of the C++ BS
  std::vector<std::string> only;                     ///< engine names to keep
  /// Stick-slip scene: RHS evaluations allowed per solve to the engines without event
  /// location (0 = only their step budgets); past it the RHS fails and so does the solve.
  std::int64_t rhs_budget = 0;
  [[nodiscard]] bool wants(const std::string& name) const {
    return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
  }
  /// Engines run only when named (comparisons of a setting, not peers).
  [[nodiscard]] bool wants_named(const std::string& name) const {
    return std::find(only.begin(), only.end(), name) != only.end();
  }
  [[nodiscard]] bool wants_precision(Precision p) const {
    return std::find(precisions.begin(), precisions.end(), p) != precisions.end();
  }
};

/// Names of every generic engine, in CSV order (the scene may add more).
inline const std::vector<std::string>& generic_engine_names() {
  static const std::vector<std::string> v = {"cxx-faithful", "cxx-modern",  "cxx-dop853",
                                             "f77-callback", "cvode-adams", "cvode-bdf",
                                             "arkode-erk8",  "odeint-bs",   "odeint-bs-dense"};
  return v;
}

namespace detail {

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Keep the optimiser from removing or hoisting RHS calls in the timing loop.
inline void clobber(const void* p) { asm volatile("" : : "r"(p) : "memory"); }

template <class S>
std::vector<S> convert(const std::vector<double>& v) {
  return std::vector<S>(v.begin(), v.end());
}

/// Time `count` calls of rhs in scalar S at the sample states (cycled).
template <class S, class Rhs>
double time_rhs_calls(const Rhs& rhs, int n, const std::vector<double>& times, const std::vector<double>& states,
                      std::int64_t count) {
  const std::vector<S> y = convert<S>(states), t = convert<S>(times);
  std::vector<S> f(static_cast<std::size_t>(n));
  const std::size_t m = times.size();
  std::size_t k = 0;
  const auto t0 = Clock::now();
  for (std::int64_t c = 0; c < count; ++c) {
    rhs(t[k], &y[k * static_cast<std::size_t>(n)], f.data());
    clobber(f.data());
    clobber(y.data());
    if (++k == m) k = 0;
  }
  return seconds_since(t0);
}

// ---------------------------------------------------------------- RHS replay (Engine::replay)
/// Status a replayed RHS returns past the end of its tape: the solve fails (and so differs
/// from the recorded one).
inline constexpr int kReplayExhausted = 98;

/// The RHS values and statuses of one solve, in call order.
struct RhsTape {
  std::vector<double> values;  ///< n per call
  std::vector<int> status;     ///< one per call
  /// An RHS (double) that hands the recorded values and statuses back in order and ignores
  /// its arguments. Its state is the read position: every player starts at the beginning.
  template <int N>
  struct Player {
    mutable const double* v;
    mutable const int* s;
    const int* end;
    int operator()(double, const double*, double* d) const {
      if (s == end) return kReplayExhausted;
      std::memcpy(d, v, N * sizeof(double));
      v += N;
      return *s++;
    }
  };
  template <int N>
  [[nodiscard]] Player<N> player() const {
    return {values.data(), status.data(), status.data() + status.size()};
  }
  /// Wall time [s] of one player handing back the whole tape, with no integrator around it.
  template <int N>
  [[nodiscard]] double copy_seconds() const {
    const Player<N> p = player<N>();
    double d[N];
    int acc = 0;
    const auto t0 = Clock::now();
    for (std::size_t c = 0; c < status.size(); ++c) {
      acc += p(0.0, nullptr, d);
      clobber(d);
    }
    clobber(&acc);
    return seconds_since(t0);
  }
};

/// The RHS, recording what it returns on a tape.
template <int N, class Rhs>
struct RecordingRhs {
  const Rhs* rhs;
  RhsTape* tape;
  int operator()(double t, const double* y, double* d) const {
    const int st = (*rhs)(t, y, d);
    tape->values.insert(tape->values.end(), d, d + N);
    tape->status.push_back(st);
    return st;
  }
};

/// The same solve: status, counts and every output bit for bit.
inline bool same_solve(const Solve& a, const Solve& b) {
  return a.status == b.status && a.nfcn == b.nfcn && a.naccpt == b.naccpt && a.nrejct == b.nrejct && a.y == b.y;
}

template <class S>
void store(Solve& s, const std::vector<S>& yout) {
  s.y.assign(yout.size(), quad(0));
  for (std::size_t i = 0; i < yout.size(); ++i) s.y[i] = static_cast<quad>(yout[i]);
}

/// The solve of a C++ integration (BsResult, Dop853Result): status, message, counts, outputs.
template <class Result, class S>
Solve solve_of(const Result& r, const std::vector<S>& yout) {
  Solve s;
  s.status = static_cast<int>(r.status);
  s.message = r.message;
  s.nfcn = r.nfcn;
  s.naccpt = r.naccpt;
  s.nrejct = r.nrejct;
  store(s, yout);
  return s;
}

/// The solve of an F77 BSINT bridge call: its status (named after `routine` when not 0), the
/// counts nstat = (nfcn, naccpt, nrejct) and the outputs.
inline Solve f77_solve(const char* routine, int st, const int (&nstat)[3], const std::vector<double>& yout) {
  Solve s;
  s.status = st;
  if (st != 0) s.message = std::string(routine) + " returned status " + std::to_string(st);
  s.nfcn = nstat[0];
  s.naccpt = nstat[1];
  s.nrejct = nstat[2];
  store(s, yout);
  return s;
}

}  // namespace detail

/// Samples for RHS timing: states along the reference trajectory (double).
struct RhsSamples {
  std::vector<double> t, y;  ///< nout times, nout*n states
};
inline RhsSamples samples_from(const Problem& p, const Reference& ref) {
  RhsSamples s;
  s.t = p.tout;
  s.y.resize(ref.y.size());
  for (std::size_t i = 0; i < ref.y.size(); ++i) s.y[i] = static_cast<double>(ref.y[i]);
  return s;
}

/// Engine::replay of a double engine. `solve_with(r, rtol)` runs the engine with any RHS r
/// of the contract (here: the recording one, then the player) and returns its Solve with
/// `seconds` set. The timer it returns is valid only for the solve it was recorded from,
/// which the replayed solve must reproduce bit for bit (else no timer).
template <int N, class Rhs, class SolveWith>
std::function<std::function<double()>(double, const Solve&)> replay_of(std::shared_ptr<const Rhs> rhs,
                                                                      SolveWith solve_with) {
  return [rhs, solve_with](double rtol, const Solve& first) -> std::function<double()> {
    auto tape = std::make_shared<detail::RhsTape>();
    if (first.nfcn > 0) {
      tape->values.reserve(static_cast<std::size_t>(first.nfcn) * N);
      tape->status.reserve(static_cast<std::size_t>(first.nfcn));
    }
    if (!detail::same_solve(solve_with(detail::RecordingRhs<N, Rhs>{rhs.get(), tape.get()}, rtol), first)) return {};
    if (!detail::same_solve(solve_with(tape->template player<N>(), rtol), first)) return {};
    return [tape, solve_with, rtol]() {
      const Solve s = solve_with(tape->template player<N>(), rtol);
      return s.seconds - tape->template copy_seconds<N>();
    };
  };
}

// ---------------------------------------------------------------- C++ Bulirsch-Stoer
/// One solve with the C++ engine in scalar S; `seconds` gets the timed region.
/// dense_accept: BsOptions::dense_accept of the modern configuration (1 = ours, 10 = ODEX's).
template <class S, int N, class Rhs>
Solve solve_cxx_bs(const Problem& p, const Rhs& rhs, double rtol, bool modern, double* seconds,
                   double dense_accept = 1.0) {
  const int n = p.n;
  const std::size_t nu = static_cast<std::size_t>(n);
  std::vector<S> atol(nu);
  for (std::size_t i = 0; i < nu; ++i) atol[i] = S(rtol) * S(p.scale[i]);
  const std::vector<S> tout = detail::convert<S>(p.tout);
  std::vector<S> y = detail::convert<S>(p.y0);
  std::vector<S> yout(p.nout() * nu, S(0));
  const auto t0 = detail::Clock::now();
  auto opt = modern ? BsOptions<S>::modern(S(rtol), std::move(atol)) : BsOptions<S>::faithful(S(rtol), std::move(atol));
  opt.dense_accept = dense_accept;
  BulirschStoer<S, N> bs(std::move(opt), n);
  const BsResult r = bs.integrate(rhs, S(p.t0), y.data(), std::span<const S>(tout),
                                  [&](std::size_t k, S, const S* yy) { std::copy(yy, yy + n, &yout[k * nu]); });
  if (seconds) *seconds = detail::seconds_since(t0);
  return detail::solve_of(r, yout);
}

// ---------------------------------------------------------------- C++ Dormand-Prince 8(5,3)
/// One solve with the C++ dop853 (double, default options: dop853.hpp); `seconds` gets the
/// timed region (creation of the integrator to the last output).
template <int N, class Rhs>
Solve solve_cxx_dop853(const Problem& p, const Rhs& rhs, double rtol, double* seconds) {
  const int n = p.n;
  const std::size_t nu = static_cast<std::size_t>(n);
  std::vector<double> y = p.y0;
  std::vector<double> yout(p.nout() * nu, 0.0);
  const auto t0 = detail::Clock::now();
  Dop853<double, N> dp(Dop853Options<double>::make(rtol, p.atol(rtol)), n);
  const Dop853Result r = dp.integrate(rhs, p.t0, y.data(), std::span<const double>(p.tout),
                                      [&](std::size_t k, double, const double* yy) { std::copy(yy, yy + n, &yout[k * nu]); });
  if (seconds) *seconds = detail::seconds_since(t0);
  return detail::solve_of(r, yout);
}

// ---------------------------------------------------------------- F77 BSINT, C callback
namespace detail {
template <class Rhs>
int f77_callback(int /*n*/, double t, const double* y, double* dydt, void* udata) {
  return (*static_cast<const Rhs*>(udata))(t, y, dydt);
}
/// The RHS as BSINT's own derivative routine (np_f77_bsint_fcn): udata's bits in ipar.
template <class Rhs>
void f77_fcn(const int* /*n*/, const double* t, const double* y, double* dydt, const double* /*rpar*/, int* ipar,
             int* ierr) {
  void* udata;
  std::memcpy(&udata, ipar, sizeof udata);
  *ierr = (*static_cast<const Rhs*>(udata))(*t, y, dydt);
}
}  // namespace detail

template <class Rhs>
Solve solve_f77_callback(const Problem& p, const Rhs& rhs, double rtol, double* seconds) {
  const std::vector<double> atol = p.atol(rtol);
  std::vector<double> y = p.y0, yout(p.nout() * static_cast<std::size_t>(p.n), 0.0);
  int nstat[3] = {0, 0, 0};
  const auto t0 = detail::Clock::now();
  const int st = np_f77_bsint_fcn(p.n, p.t0, y.data(), static_cast<int>(p.nout()), p.tout.data(), yout.data(),
                                  rtol, atol.data(), 0.0, 0.0, 8, 1, 0, &detail::f77_fcn<Rhs>,
                                  const_cast<void*>(static_cast<const void*>(&rhs)), nstat);
  if (seconds) *seconds = detail::seconds_since(t0);
  return detail::f77_solve("np_f77_bsint_fcn", st, nstat, yout);
}

#ifdef NANOPUSH_HAVE_SUNDIALS
// ---------------------------------------------------------------- SUNDIALS
namespace detail {
/// SUNDIALS' *GetReturnFlagName returns a malloc'd string the caller must free.
inline std::string flag_name(char* name) {
  std::string out = name ? name : "unknown flag";
  std::free(name);
  return out;
}

template <class Rhs>
int sun_rhs(realtype t, N_Vector y, N_Vector ydot, void* udata) {
  const int st = (*static_cast<const Rhs*>(udata))(double(t), N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  return st == 0 ? 0 : -1;  // negative: unrecoverable, the integrator stops
}

/// Owns the SUNDIALS objects of one solve; frees them in reverse order.
struct SunObjects {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, atol = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  SUNNonlinearSolver NLS = nullptr;
  void* mem = nullptr;
  void (*free_mem)(void**) = nullptr;
  /// The context and the vectors y (= p.y0) and atol (= atol_values) of a problem.
  SunObjects(const Problem& p, const std::vector<double>& atol_values) {
    SUNContext_Create(nullptr, &ctx);
    y = N_VNew_Serial(p.n, ctx);
    atol = N_VNew_Serial(p.n, ctx);
    std::copy(p.y0.begin(), p.y0.end(), N_VGetArrayPointer(y));
    std::copy(atol_values.begin(), atol_values.end(), N_VGetArrayPointer(atol));
  }
  SunObjects(const SunObjects&) = delete;
  SunObjects& operator=(const SunObjects&) = delete;
  ~SunObjects() {
    if (mem && free_mem) free_mem(&mem);
    if (NLS) SUNNonlinSolFree(NLS);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (atol) N_VDestroy(atol);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

/// Steps to every output time of p with evolve(tout, &t) (CVode, ERKStepEvolve), copying y into
/// yout; stops at the first negative flag. Returns the last flag (`flag` if no step was taken).
template <class Evolve>
int to_outputs(const Problem& p, N_Vector y, std::vector<double>& yout, int flag, Evolve&& evolve) {
  const std::size_t nu = static_cast<std::size_t>(p.n);
  realtype t = p.t0;
  for (std::size_t k = 0; k < p.nout() && flag >= 0; ++k) {
    if (p.tout[k] > t) flag = evolve(p.tout[k], &t);
    if (flag >= 0) std::copy(N_VGetArrayPointer(y), N_VGetArrayPointer(y) + p.n, &yout[k * nu]);
  }
  return flag;
}

/// The frame both SUNDIALS engines share: the state and tolerances (SunObjects); on the clock,
/// `run(o, yout)` (create and configure the integrator, step to every output; the last flag);
/// then the status, `count(o, flag, s)` (message and counts) and the outputs stored.
template <class Run, class Count>
Solve sundials_solve(const Problem& p, double rtol, double* seconds, Run&& run, Count&& count) {
  const std::vector<double> atol = p.atol(rtol);
  std::vector<double> yout(p.nout() * static_cast<std::size_t>(p.n), 0.0);
  Solve s;
  const auto t0 = Clock::now();
  {
    SunObjects o(p, atol);
    const int flag = run(o, yout);
    if (seconds) *seconds = seconds_since(t0);
    s.status = flag < 0 ? -flag : 0;
    count(o, flag, s);
  }
  store(s, yout);
  return s;
}
}  // namespace detail

/// CVODE Adams (fixed-point) or BDF (Newton + dense), outputs by CVODE's interpolation (CV_NORMAL).
template <class Rhs>
Solve solve_cvode(const Problem& p, const Rhs& rhs, double rtol, bool bdf, double* seconds) {
  const int n = p.n;
  const auto run = [&](detail::SunObjects& o, std::vector<double>& yout) {
    o.mem = CVodeCreate(bdf ? CV_BDF : CV_ADAMS, o.ctx);
    o.free_mem = &CVodeFree;
    int flag = CVodeInit(o.mem, &detail::sun_rhs<Rhs>, p.t0, o.y);
    if (flag == 0) flag = CVodeSetErrFile(o.mem, nullptr);
    if (flag == 0) flag = CVodeSVtolerances(o.mem, rtol, o.atol);
    if (flag == 0) flag = CVodeSetUserData(o.mem, const_cast<void*>(static_cast<const void*>(&rhs)));
    if (flag == 0) flag = CVodeSetMaxNumSteps(o.mem, 100000);  // the budget of every engine
    if (flag == 0) {
      if (bdf) {
        o.A = SUNDenseMatrix(n, n, o.ctx);
        o.LS = SUNLinSol_Dense(o.y, o.A, o.ctx);
        flag = CVodeSetLinearSolver(o.mem, o.LS, o.A);
      } else {
        o.NLS = SUNNonlinSol_FixedPoint(o.y, 0, o.ctx);
        flag = CVodeSetNonlinearSolver(o.mem, o.NLS);
      }
    }
    return detail::to_outputs(p, o.y, yout, flag, [&](realtype tout, realtype* t) {
      return CVode(o.mem, tout, o.y, t, CV_NORMAL);
    });
  };
  const auto count = [&](detail::SunObjects& o, int flag, Solve& s) {
    if (flag < 0) s.message = "CVODE: " + detail::flag_name(CVodeGetReturnFlagName(flag));
    long nfe = 0, nfels = 0, nst = 0, netf = 0, nncf = 0;
    CVodeGetNumRhsEvals(o.mem, &nfe);
    if (bdf) CVodeGetNumLinRhsEvals(o.mem, &nfels);
    CVodeGetNumSteps(o.mem, &nst);
    CVodeGetNumErrTestFails(o.mem, &netf);
    CVodeGetNumNonlinSolvConvFails(o.mem, &nncf);
    s.nfcn = nfe + nfels;
    s.naccpt = nst;
    s.nrejct = netf + nncf;
  };
  return detail::sundials_solve(p, rtol, seconds, run, count);
}

/// ARKODE ERKStep with the order-8 Fehlberg table; outputs by ARKODE's interpolation (ARK_NORMAL).
template <class Rhs>
Solve solve_arkode_erk8(const Problem& p, const Rhs& rhs, double rtol, double* seconds) {
  const auto run = [&](detail::SunObjects& o, std::vector<double>& yout) {
    o.mem = ERKStepCreate(&detail::sun_rhs<Rhs>, p.t0, o.y, o.ctx);
    o.free_mem = &ERKStepFree;
    int flag = ERKStepSetErrFile(o.mem, nullptr);
    if (flag == 0) flag = ERKStepSVtolerances(o.mem, rtol, o.atol);
    if (flag == 0) flag = ERKStepSetUserData(o.mem, const_cast<void*>(static_cast<const void*>(&rhs)));
    if (flag == 0) flag = ERKStepSetTableNum(o.mem, ARKODE_FEHLBERG_13_7_8);
    if (flag == 0) flag = ERKStepSetMaxNumSteps(o.mem, 100000);  // the budget of every engine
    return detail::to_outputs(p, o.y, yout, flag, [&](realtype tout, realtype* t) {
      return ERKStepEvolve(o.mem, tout, o.y, t, ARK_NORMAL);
    });
  };
  const auto count = [](detail::SunObjects& o, int flag, Solve& s) {
    if (flag < 0) s.message = "ARKODE: " + detail::flag_name(ERKStepGetReturnFlagName(flag));
    long nfe = 0, nst = 0, netf = 0;
    ERKStepGetNumRhsEvals(o.mem, &nfe);
    ERKStepGetNumSteps(o.mem, &nst);
    ERKStepGetNumErrTestFails(o.mem, &netf);
    s.nfcn = nfe;
    s.naccpt = nst;
    s.nrejct = netf;
  };
  return detail::sundials_solve(p, rtol, seconds, run, count);
}
#endif  // NANOPUSH_HAVE_SUNDIALS

}  // namespace nanopush::bench
