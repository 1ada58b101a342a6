// Assemble the benchmark for one right-hand side: every generic engine and, when there is no
// exact solution, the extended-precision reference. A scene plugs in with
//     auto rhs = std::make_shared<const MyRhs>(...);            // templated on the scalar
//     Reference ref = run_extended_reference<6>(p, *rhs);        // or an exact solution
//     auto engines = generic_engines<6>(p, rhs, samples_from(p, ref), cfg);
// (bench_scene.cpp does this for the smooth nanobar).
#pragma once
#include <memory>

#include "bench/bench_odeint.hpp"
#include "nanopush/numerics/error.hpp"

namespace nanopush::bench {

/// Tightest meaningful rtol of the C++ BS in each precision (tens to hundreds of ulps of
/// the state). Double goes one half-decade further (1e-14) than the other engines (1e-13,
/// Engine::rtol_min): the dense-output engine's global error is 4-60 x rtol, and the
/// sweep must reach an achieved error of 1e-12 (issue 7's range).
template <class S>
constexpr double rtol_floor() {
  if constexpr (std::is_same_v<S, quad>)
    return 1e-28;
  else if constexpr (std::is_same_v<S, long double>)
    return 1e-18;
  else
    return 1e-14;
}

/// Timer of `count` bare calls of rhs in scalar S at the sample states.
template <class S, class Rhs>
std::function<double(std::int64_t)> rhs_timer(std::shared_ptr<const Rhs> rhs, int n, RhsSamples smp) {
  return [rhs, n, smp](std::int64_t count) { return detail::time_rhs_calls<S>(*rhs, n, smp.t, smp.y, count); };
}

/// A solve with its own timed region in Solve::seconds: solve(seconds) is one of
/// bench_engines.hpp's solve_* on its problem, RHS and tolerance, writing that time to *seconds.
template <class SolveFn>
Solve timed(SolveFn&& solve) {
  double sec = 0;
  Solve s = solve(&sec);
  s.seconds = sec;
  return s;
}

namespace detail {
template <class S, int N, class Rhs>
void add_cxx_bs(std::vector<Engine>& v, const Problem& p, const std::shared_ptr<const Rhs>& rhs,
                const RhsSamples& smp, const EngineConfig& cfg) {
  if (!cfg.wants_precision(precision_of<S>())) return;
  for (const int variant : {0, 1, 2}) {  // faithful, modern, modern with ODEX's acceptance
    const bool modern = variant > 0;
    const double dense_accept = variant == 2 ? 10.0 : 1.0;
    Engine e;
    e.name = variant == 2 ? "cxx-modern-odex" : modern ? "cxx-modern" : "cxx-faithful";
    if (variant == 2 ? !cfg.wants_named(e.name) : !cfg.wants(e.name)) continue;
    e.precision = precision_of<S>();
    e.rtol_min = rtol_floor<S>();
    e.note = variant == 2 ? "cxx-modern with ODEX's interpolation acceptance (err_int <= 10, dense_accept = 10)"
             : modern     ? "C++ BS, polynomial extrapolation, kmax 10, step numbers 4j-2, dense output (outputs interpolated)"
                          : "C++ BS, rational extrapolation, kmax 8 (steps of the F77 engine); steps clipped at output times";
    e.solve = [p, rhs, modern, dense_accept](double rtol) {
      return timed([&](double* sec) { return solve_cxx_bs<S, N>(p, *rhs, rtol, modern, sec, dense_accept); });
    };
    e.time_rhs = rhs_timer<S>(rhs, p.n, smp);
    if constexpr (std::is_same_v<S, double>)
      e.replay = replay_of<N>(rhs, [p, modern, dense_accept](const auto& r, double rtol) {
        double sec = 0;
        Solve s = solve_cxx_bs<double, N>(p, r, rtol, modern, &sec, dense_accept);
        s.seconds = sec;
        return s;
      });
    v.push_back(std::move(e));
  }
}
}  // namespace detail

/// Every generic engine (see bench_engines.hpp) for rhs on problem p (p.n must equal N).
template <int N, class Rhs>
std::vector<Engine> generic_engines(const Problem& p, std::shared_ptr<const Rhs> rhs, const RhsSamples& smp,
                                    const EngineConfig& cfg) {
  if (p.n != N) throw InputError("problem.n", std::to_string(p.n), "must be " + std::to_string(N));
  std::vector<Engine> v;
  auto timer = rhs_timer<double>(rhs, p.n, smp);
  // Each engine from one generic solve_with(r, rtol) (any RHS r of the contract, Solve with
  // its seconds): the solve with the scene's RHS, and its replay (Engine::replay).
  auto add = [&](const std::string& name, const std::string& note, auto solve_with) {
    if (!cfg.wants(name)) return;
    Engine e;
    e.name = name;
    e.note = note;
    e.solve = [rhs, solve_with](double rtol) { return solve_with(*rhs, rtol); };
    e.time_rhs = timer;
    e.replay = replay_of<N>(rhs, solve_with);
    v.push_back(std::move(e));
  };
  detail::add_cxx_bs<double, N>(v, p, rhs, smp, cfg);
  if (cfg.wants_precision(Precision::double_)) {
    add("cxx-dop853", "C++ Dormand-Prince 8(5,3) (the method of Hairer's DOP853), dense output of order 7",
        [p](const auto& r, double rtol) {
          return timed([&](double* sec) { return solve_cxx_dop853<N>(p, r, rtol, sec); });
        });
    // As the C++ BS, one half-decade past the other engines: its global error is 5-60 x rtol
    // on the nanobar (docs/dop853.md), and its rtol floor is 10 eps (2.2e-15).
    if (!v.empty() && v.back().name == "cxx-dop853") v.back().rtol_min = rtol_floor<double>();
  }
  detail::add_cxx_bs<long double, N>(v, p, rhs, smp, cfg);
  detail::add_cxx_bs<quad, N>(v, p, rhs, smp, cfg);
  add("f77-callback", "fortran/bsint.f (rational, kmax 8) via np_f77_bsint_fcn, the C++ RHS as its FCN",
      [p](const auto& r, double rtol) {
        return timed([&](double* sec) { return solve_f77_callback(p, r, rtol, sec); });
      });
#ifdef NANOPUSH_HAVE_SUNDIALS
  for (const bool bdf : {false, true}) {
    add(bdf ? "cvode-bdf" : "cvode-adams",
        bdf ? "CVODE BDF 1-5, Newton + dense LU, DQ Jacobian; outputs interpolated"
            : "CVODE Adams 1-12, fixed-point iteration; outputs interpolated",
        [p, bdf](const auto& r, double rtol) {
          return timed([&](double* sec) { return solve_cvode(p, r, rtol, bdf, sec); });
        });
  }
  add("arkode-erk8", "ARKODE ERKStep, ARKODE_FEHLBERG_13_7_8 (order 8); outputs interpolated",
      [p](const auto& r, double rtol) {
        return timed([&](double* sec) { return solve_arkode_erk8(p, r, rtol, sec); });
      });
#endif
#if NANOPUSH_HAVE_ODEINT
  for (const bool dense : {false, true}) {
    add(dense ? "odeint-bs-dense" : "odeint-bs",
        dense ? "Boost.Odeint bulirsch_stoer_dense_out + integrate_times; outputs interpolated"
              : "Boost.Odeint bulirsch_stoer, stepped as integrate_times (steps clipped at output times)",
        [p, dense](const auto& r, double rtol) {
          return timed([&](double* sec) { return solve_odeint_bs<N>(p, r, rtol, dense, sec); });
        });
  }
#endif
  return v;
}

/// Extended-precision reference for scenes without an exact solution: run a = C++ BS
/// faithful (rational, kmax 8) in __float128 at rtol_a, run b = C++ BS modern (polynomial,
/// kmax 10) in __float128 at rtol_b: different extrapolation, order sequence and tolerance.
/// The caller checks the disagreement with accept_reference() once the errors are known.
template <int N, class Rhs>
Reference run_extended_reference(const Problem& p, const Rhs& rhs, double rtol_a = 1e-28, double rtol_b = 1e-28) {
  const Solve a = solve_cxx_bs<quad, N>(p, rhs, rtol_a, false, nullptr);
  const Solve b = solve_cxx_bs<quad, N>(p, rhs, rtol_b, true, nullptr);
  return extended_reference(p, a, b,
                            "C++ BS in __float128: faithful at rtol " + fmt(rtol_a) + " vs modern at rtol " +
                                fmt(rtol_b));
}

}  // namespace nanopush::bench
