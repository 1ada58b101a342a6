#include "nanopush/bench_scene.hpp"

#include "f77_bridge.h"
#include "nanopush/bench_suite.hpp"
#include "nanopush/elliptic.hpp"
#include "nanopush/error.hpp"
#include "nanopush/rigid_body.hpp"

namespace nanopush::bench {

Problem problem_from_scene(const Scene& sc) {
  Problem p;
  p.name = sc.name;
  p.n = kStateSize;
  p.t0 = 0;
  p.y0.assign(sc.initial.begin(), sc.initial.end());
  p.tout = sc.output_times();
  const auto s = sc.state_scales();
  p.scale.assign(s.begin(), s.begin() + kStateSize);  // state_scales() also covers the rough model's work states
  return p;
}

bool has_exact_solution(const Scene& sc) { return sc.model == "smooth" && sc.initial[kOmega] == 0; }

std::vector<quad> smooth_exact(const Scene& sc, const Problem& p) {
  if (!has_exact_solution(sc))
    throw InputError("scene " + sc.name, "surface " + sc.model + ", omega0 = " + fmt(sc.initial[kOmega]),
                     "an exact solution needs a smooth surface and omega0 = 0");
  const quad F = sc.push.force, beta = sc.push.beta, pbx = sc.push.pbx, pby = sc.push.pby;
  const quad pi = num::pi<quad>();
  quad theta_eq = beta - num::atan2(pby, pbx);
  while (theta_eq > pi) theta_eq -= 2 * pi;
  while (theta_eq <= -pi) theta_eq += 2 * pi;
  const quad lever = num::sqrt(pbx * pbx + pby * pby);
  const quad theta0 = sc.initial[kTheta];
  if (!(num::abs(theta0 - theta_eq) < pi))
    throw InputError("initial.theta", fmt(sc.initial[kTheta]), "must be within pi of theta* for the exact solution");
  const Pendulum<quad> pend(theta_eq, theta0, F * lever, quad(sc.inertia));
  const quad m = sc.mass;
  const quad ax = F * num::cos(beta) / m, ay = F * num::sin(beta) / m;
  const quad x0 = sc.initial[kX], y0 = sc.initial[kY], vx0 = sc.initial[kVx], vy0 = sc.initial[kVy];
  const std::size_t n = kStateSize;
  std::vector<quad> y(p.nout() * n);
  for (std::size_t k = 0; k < p.nout(); ++k) {
    const quad t = quad(p.tout[k]) - quad(p.t0);
    quad* r = &y[k * n];
    r[kX] = x0 + vx0 * t + ax * t * t / 2;
    r[kY] = y0 + vy0 * t + ay * t * t / 2;
    r[kTheta] = pend.theta(t);
    r[kVx] = vx0 + ax * t;
    r[kVy] = vy0 + ay * t;
    r[kOmega] = pend.omega(t);
  }
  return y;
}

namespace {

/// The F77 RHS through its bridge, for timing the f77-native engine's RHS share.
struct F77SmoothRhs {
  std::array<double, 6> params;
  int operator()(double t, const double* y, double* dydt) const {
    return np_f77_smooth_bar_rhs(t, y, dydt, params.data());
  }
};

std::array<double, 6> smooth_params(const Scene& sc) {
  return {sc.mass, sc.inertia, sc.push.force, sc.push.beta, sc.push.pbx, sc.push.pby};
}

Solve solve_f77_native(const Problem& p, const std::array<double, 6>& params, double rtol) {
  const std::vector<double> atol = p.atol(rtol);
  std::vector<double> y = p.y0, yout(p.nout() * kStateSize, 0.0);
  int nstat[3] = {0, 0, 0};
  const auto t0 = detail::Clock::now();
  const int st = np_f77_bsint_smooth_bar(kStateSize, p.t0, y.data(), static_cast<int>(p.nout()), p.tout.data(),
                                         yout.data(), rtol, atol.data(), 0.0, 0.0, 8, 1, 0, params.data(), nstat);
  Solve s;
  s.seconds = detail::seconds_since(t0);
  s.status = st;
  if (st != 0) s.message = "np_f77_bsint_smooth_bar returned status " + std::to_string(st);
  s.nfcn = nstat[0];
  s.naccpt = nstat[1];
  s.nrejct = nstat[2];
  detail::store(s, yout);
  return s;
}

}  // namespace

Solve extended_run(const Scene& sc, const Problem& p, double rtol, bool modern) {
  if (sc.model != "smooth") throw InputError("surface.kind", sc.model, "the benchmark supports: smooth");
  const SmoothBarRhs rhs{sc.mass, sc.inertia, sc.push};
  return solve_cxx_bs<quad, kStateSize>(p, rhs, rtol, modern, nullptr);
}

std::vector<std::string> engine_names(const Scene& sc) {
  std::vector<std::string> v = generic_engine_names();
  if (sc.model == "smooth") v.insert(v.begin() + 3, "f77-native");
  return v;
}

Bench make_bench(const Scene& sc, const EngineConfig& cfg) {
  Bench b;
  b.problem = problem_from_scene(sc);
  const Problem& p = b.problem;
  if (sc.model == "smooth") {
    auto rhs = std::make_shared<const SmoothBarRhs>(SmoothBarRhs{sc.mass, sc.inertia, sc.push});
    if (has_exact_solution(sc)) {
      b.reference.kind = "exact";
      b.reference.how = "closed form: constant acceleration in x, y; pendulum (Jacobi sn by the AGM) in theta, "
                        "omega; evaluated in __float128";
      b.reference.y = smooth_exact(sc, p);
    } else {
      b.reference = run_extended_reference<kStateSize>(p, *rhs);
    }
    const RhsSamples smp = samples_from(p, b.reference);
    b.engines = generic_engines<kStateSize>(p, rhs, smp, cfg);
    if (cfg.wants("f77-native")) {
      Engine e;
      e.name = "f77-native";
      e.note = "fortran/bsint.f with the F77 RHS fortran/smbar.f (np_f77_bsint_smooth_bar)";
      const auto params = smooth_params(sc);
      e.solve = [p, params](double rtol) { return solve_f77_native(p, params, rtol); };
      e.time_rhs = rhs_timer<double>(std::make_shared<const F77SmoothRhs>(F77SmoothRhs{params}), p.n, smp);
      // Keep the CSV order of engine_names(): after f77-callback.
      auto it = std::find_if(b.engines.begin(), b.engines.end(), [](const Engine& x) { return x.name == "f77-callback"; });
      b.engines.insert(it == b.engines.end() ? b.engines.end() : it + 1, std::move(e));
    }
    // Rough scenes (issue 4) plug in here: else if (sc.model == "rough") { ... } (see the header).
  } else {
    throw InputError("surface.kind", sc.model, "the benchmark supports: smooth");
  }
  return b;
}

}  // namespace nanopush::bench
