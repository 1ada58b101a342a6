// Boost.Odeint's Bulirsch-Stoer as a peer in the benchmark (never a library dependency:
// header-only, from Debian's libboost-dev; when the headers are absent NANOPUSH_HAVE_ODEINT
// is 0 and the engines are simply not offered).
//
// Odeint takes one scalar absolute tolerance and measures the error in the max norm. To
// give it the same per-component tolerances as every other engine (atol_i = rtol * scale_i)
// it integrates the scaled state u_i = y_i / scale_i with eps_abs = eps_rel = rtol; the two
// multiplications per component and RHS call are counted as integrator overhead.
#pragma once
#if __has_include(<boost/numeric/odeint.hpp>)
#define NANOPUSH_HAVE_ODEINT 1
#include <boost/numeric/odeint.hpp>
#else
#define NANOPUSH_HAVE_ODEINT 0
#endif

#include "bench/bench_engines.hpp"

#if NANOPUSH_HAVE_ODEINT
namespace nanopush::bench {

namespace detail {
template <class Rhs, int N>
struct ScaledSystem {
  using state = std::array<double, N>;
  const Rhs* rhs;
  state scale, inv_scale;
  std::int64_t* count;
  void operator()(const state& u, state& dudt, double t) const {
    state y, f;
    for (int i = 0; i < N; ++i) y[i] = u[i] * scale[i];
    // Budget: a chattering RHS (stick-slip without event location) would otherwise keep
    // odeint busy for minutes; our engines stop at 100 000 steps, odeint at 2e6 evaluations.
    if (++*count > 2000000) throw std::runtime_error("odeint: more than 2e6 RHS evaluations");
    if ((*rhs)(t, y.data(), f.data()) != 0) throw std::runtime_error("right-hand side failed");
    for (int i = 0; i < N; ++i) dudt[i] = f[i] * inv_scale[i];
  }
};
}  // namespace detail

/// Odeint bulirsch_stoer stepped exactly as integrate_times steps a controlled stepper
/// (each step clipped at the next output time, the unclipped proposal kept), with the
/// accepted and rejected attempts counted. dense = true: bulirsch_stoer_dense_out through
/// integrate_times (outputs interpolated; odeint does not report its rejected steps: -1).
template <int N, class Rhs>
Solve solve_odeint_bs(const Problem& p, const Rhs& rhs, double rtol, bool dense, double* seconds) {
  namespace ode = boost::numeric::odeint;
  using state = std::array<double, N>;
  const std::size_t nu = static_cast<std::size_t>(N);
  std::vector<double> yout(p.nout() * nu, 0.0);
  Solve s;
  std::int64_t count = 0;
  detail::ScaledSystem<Rhs, N> sys{&rhs, {}, {}, &count};
  state u;
  for (std::size_t i = 0; i < nu; ++i) {
    sys.scale[i] = p.scale[i];
    sys.inv_scale[i] = 1.0 / p.scale[i];
    u[i] = p.y0[i] / p.scale[i];
  }
  auto record = [&](std::size_t k, const state& x) {
    for (std::size_t i = 0; i < nu; ++i) yout[k * nu + i] = x[i] * sys.scale[i];
  };
  const double dt0 = 0.01 * (p.tout.back() - p.t0);
  const auto t0 = detail::Clock::now();
  try {
    if (!dense) {
      ode::bulirsch_stoer<state> st(rtol, rtol, 1.0, 0.0);
      double t = p.t0, dt = dt0;
      for (std::size_t k = 0; k < p.nout(); ++k) {
        int fails = 0;
        while (t < p.tout[k]) {
          // The same budget as our engines (100 000 attempted steps): a chattering RHS would
          // otherwise keep odeint stepping for ever.
          if (s.naccpt + s.nrejct >= 100000) throw std::runtime_error("odeint: more than 100000 steps");
          double cur = std::min(dt, p.tout[k] - t);
          if (st.try_step(std::cref(sys), u, t, cur) == ode::success) {
            ++s.naccpt;
            fails = 0;
            dt = std::max(dt, cur);
          } else {
            ++s.nrejct;
            if (++fails > 500) throw std::runtime_error("odeint: 500 failed steps in a row");
            dt = cur;
          }
        }
        record(k, u);
      }
    } else {
      ode::bulirsch_stoer_dense_out<state> st(rtol, rtol, 1.0, 0.0);
      std::size_t k = 0;
      std::vector<double> times = p.tout;
      if (times.front() > p.t0) times.insert(times.begin(), p.t0);
      const std::size_t skip = times.size() - p.nout();
      const std::size_t steps =
          ode::integrate_times(
              st, std::cref(sys), u, times.begin(), times.end(), dt0,
              [&](const state& x, double) {
                if (k >= skip) record(k - skip, x);
                ++k;
              },
              ode::max_step_checker(100000));
      s.naccpt = static_cast<std::int64_t>(steps);
      s.nrejct = -1;
    }
  } catch (const std::exception& e) {
    s.status = 1;
    s.message = e.what();
  }
  if (seconds) *seconds = detail::seconds_since(t0);
  s.nfcn = count;
  detail::store(s, yout);
  return s;
}

}  // namespace nanopush::bench
#endif
