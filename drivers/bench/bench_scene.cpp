#include "bench/bench_scene.hpp"

#include "f77_bridge.h"
#include "bench/bench_suite.hpp"
#include "nanopush/numerics/elliptic.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/models/rigid_body.hpp"
#include "nanopush/scenes/deck.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/process.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "nanopush/models/stick_slip.hpp"

#include <limits>

#include <quadmath.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace nanopush::bench {

Problem problem_from_scene(const Scene& sc) {
  Problem p;
  p.name = sc.name;
  // Rough scenes carry the two work accumulators (rough_bar.hpp) as states 7 and 8.
  p.n = sc.rough() ? kRoughStateSize : kStateSize;
  p.t0 = 0;
  p.y0.assign(sc.initial.begin(), sc.initial.end());
  p.y0.resize(static_cast<std::size_t>(p.n), 0.0);
  p.tout = sc.output_times();
  const auto s = sc.state_scales();
  p.scale.assign(s.begin(), s.begin() + p.n);
  return p;
}

bool has_exact_solution(const Scene& sc) { return !sc.rough() && sc.initial[kOmega] == 0; }

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
  const double seconds = detail::seconds_since(t0);
  Solve s = detail::f77_solve("np_f77_bsint_smooth_bar", st, nstat, yout);
  s.seconds = seconds;
  return s;
}

}  // namespace

/// The rough-surface model for the benchmark: the thesis-law RHS (rough_bar.hpp) in double
/// for every scalar (the friction closed form is double; the extended-precision reference
/// comes from the F77 program built with -freal-8-real-16 instead).
struct RoughBenchRhs {
  RoughBarThesisRhs rhs;
  std::int64_t budget = 0;            ///< evaluations allowed per solve (0 = no limit)
  mutable std::int64_t calls = 0;     ///< since the last reset (the benchmark is sequential)
  template <class S>
  int operator()(S t, const S* y, S* d) const {
    if (budget > 0 && ++calls > budget) return 97;  // the solve fails: RHS budget spent
    double yd[kRoughStateSize], dd[kRoughStateSize];
    for (int i = 0; i < kRoughStateSize; ++i) yd[i] = static_cast<double>(y[i]);
    const int st = rhs(static_cast<double>(t), yd, dd);
    for (int i = 0; i < kRoughStateSize; ++i) d[i] = static_cast<S>(dd[i]);
    return st;
  }
};

/// The coulomb-law RHS for RHS timing (the mode of a slide along +x).
struct CoulombBenchRhs {
  RoughBarModel model;
  template <class S>
  int operator()(S, const S* y, S* d) const {
    double yd[kRoughStateSize], dd[kRoughStateSize];
    for (int i = 0; i < kRoughStateSize; ++i) yd[i] = static_cast<double>(y[i]);
    coulomb_rhs(model, yd, {1.0, 0.0, 0.0}, dd);
    for (int i = 0; i < kRoughStateSize; ++i) d[i] = static_cast<S>(dd[i]);
    return 0;
  }
};

Solve coulomb_solve_from(const Problem& p, const std::function<StickSlipResult(const StickSlipObserver&)>& run) {
  Solve s;
  std::vector<double> yout;
  yout.reserve(p.nout() * static_cast<std::size_t>(p.n));
  const auto t0 = detail::Clock::now();
  try {
    const StickSlipResult r = run([&](double, const double* y, const WorldWrench&) {
      for (int i = 0; i < p.n; ++i) yout.push_back(y[i]);
    });
    s.nfcn = r.stats.nfcn;
    s.naccpt = r.stats.naccpt;
    s.nrejct = r.stats.nrejct;
  } catch (const std::exception& e) {
    s.status = 1;
    s.message = e.what();
  }
  s.seconds = detail::seconds_since(t0);
  detail::store(s, yout);
  if (s.status == 0 && s.y.size() != p.nout() * static_cast<std::size_t>(p.n)) {
    s.status = 1;
    s.message = "incomplete trajectory";
  }
  return s;
}

Solve solve_coulomb(const Problem& p, const RoughBarModel& m, double rtol, bool modern) {
  auto opt = modern ? BsOptions<double>::modern(rtol, p.atol(rtol)) : BsOptions<double>::faithful(rtol, p.atol(rtol));
  opt.maxstp = 1000000;
  return coulomb_solve_from(p, [&](const StickSlipObserver& obs) { return integrate_coulomb(m, opt, p.y0.data(), p.tout, obs); });
}

Solve solve_coulomb_cvode(const Problem& p, const RoughBarModel& m, double rtol) {
  return coulomb_solve_from(
      p, [&](const StickSlipObserver& obs) { return integrate_coulomb_cvode(m, rtol, p.atol(rtol), p.y0.data(), p.tout, obs); });
}

RoughBarModel bench_rough_model(const Scene& sc) {
  RoughBarModel m = rough_model(sc);  // the scene's model (simulate.hpp), then the start below
  // Started from rest, the thesis law has no friction direction at t = 0 and its first step
  // sees friction jump from 0 to mu N (a discontinuity no tolerance below ~1e-12 resolves).
  // The benchmark starts it in the direction the body actually takes (Gauss' principle,
  // stick_slip.hpp), the coulomb law's start; a scene that would stick is not benchmarked here.
  const bool rest = sc.initial[kVx] == 0.0 && sc.initial[kVy] == 0.0 && sc.initial[kOmega] == 0.0;
  if (rest && m.muN > 0) {
    const RestAnalysis ra = analyse_rest(m, sc.initial[kTheta]);
    if (ra.stuck) throw InputError("scene " + sc.name, "at rest inside the limit surface", "the bench scene must slide");
    m.rest_direction = ra.accel;
  }
  return m;
}

/// The extended-precision legacy program: $NANOPUSH_QUAD_PROGRAM, else nanobar_quad beside the
/// running executable (bin/ of an install, the build tree's top), else one directory up (the
/// build tree's tests/). No path is compiled in: an installed prefix may be moved.
std::filesystem::path quad_program() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("NANOPUSH_QUAD_PROGRAM"); env && *env) return env;
  std::error_code ec;
  const fs::path exe_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  for (const fs::path& cand : {exe_dir / "nanobar_quad", exe_dir.parent_path() / "nanobar_quad"})
    if (!ec && fs::is_regular_file(cand)) return cand;
  return exe_dir / "nanobar_quad";
}

/// One run of the extended-precision legacy program on the scene's deck at rtol.
Solve quad_legacy_run(const Scene& sc, const Problem& p, const RoughBarModel& m, double rtol) {
  namespace fs = std::filesystem;
  const fs::path prog = quad_program();
  if (!fs::exists(prog)) throw InputError("NANOPUSH_QUAD_PROGRAM", prog.string(), "no such program (target nanobar_quad)");
  Scene s = sc;
  s.solver.max_steps = 10000000;
  const fs::path dir = fs::temp_directory_path() / ("nanopush-quad-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  write_file_atomic(dir / "case.deck", legacy_deck(s, rtol, p.atol(rtol), m.rest_direction));
  const auto t0 = detail::Clock::now();
  const int rc = run_program({prog.string()}, (dir / "case.deck").string(), (dir / "case.out").string());
  Solve r;
  r.seconds = detail::seconds_since(t0);
  std::ifstream in(dir / "case.out");
  std::string line;
  bool data = false;
  while (std::getline(in, line)) {
    if (!data) {
      if (line.find("RHS evaluations") != std::string::npos) {
        long a = 0, b = 0, c = 0;
        std::sscanf(line.c_str(), " RHS evaluations %ld, accepted steps %ld, rejected steps %ld", &a, &b, &c);
        r.nfcn = a;
        r.naccpt = b;
        r.nrejct = c;
      }
      data = line.find("THETA [rad]") != std::string::npos;
      continue;
    }
    std::istringstream ls(line);
    std::vector<quad> v;
    std::string tok;
    while (ls >> tok) v.push_back(strtoflt128(tok.c_str(), nullptr));
    if (v.size() != 12) continue;
    for (int i : {1, 2, 3, 4, 5, 6, 10, 11}) r.y.push_back(v[static_cast<std::size_t>(i)]);
  }
  fs::remove_all(dir);
  if (rc != 0 || r.y.size() != p.nout() * static_cast<std::size_t>(p.n)) {
    r.status = 1;
    r.message = "nanobar_quad at rtol " + fmt(rtol) + " failed (it " + describe_exit(rc) + ", " +
                std::to_string(r.y.size() / static_cast<std::size_t>(p.n)) + " samples)";
  }
  return r;
}

Solve extended_run(const Scene& sc, const Problem& p, double rtol, bool modern) {
  if (sc.rough()) {
    (void)modern;
    return quad_legacy_run(sc, p, bench_rough_model(sc), rtol);
  }
  const SmoothBarRhs rhs{sc.mass, sc.inertia, sc.push};
  return solve_cxx_bs<quad, kStateSize>(p, rhs, rtol, modern, nullptr);
}

std::vector<std::string> engine_names(const Scene& sc) {
  if (sc.rough() && sc.surface.law == Law::coulomb) {
    std::vector<std::string> v = {"cxx-events", "cvode-events"};
    for (const auto& n : generic_engine_names()) v.push_back(n);
    return v;
  }
  std::vector<std::string> v = generic_engine_names();
  if (!sc.rough()) v.insert(v.begin() + 3, "f77-native");
  v.push_back("cxx-modern-odex");  // run only when named
  return v;
}

Bench make_bench(const Scene& sc, const EngineConfig& cfg) {
  Bench b;
  b.problem = problem_from_scene(sc);
  const Problem& p = b.problem;
  if (!sc.rough()) {
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
  } else if (sc.rough() && sc.surface.law == Law::coulomb) {
    // Stick-slip: the event-locating integrators (C++ BS and CVODE) against every engine
    // integrating the thesis-law ODE without event location (which chatters at rest).
    const RoughBarModel m = bench_rough_model(sc);
    RoughBarModel mc = m;
    mc.rest_direction = {0.0, 0.0, 0.0};
    const Solve a = solve_coulomb(p, mc, 1e-14, false), c = solve_coulomb(p, mc, 1e-13, true);
    b.reference = extended_reference(p, a, c,
                                     "event-locating C++ BS in double (no extended-precision coulomb engine): faithful "
                                     "at rtol 1e-14 vs modern at 1e-13");
    b.reference.kind = "double";
    auto rhs = std::make_shared<const RoughBenchRhs>(RoughBenchRhs{RoughBarThesisRhs{m}, cfg.rhs_budget});
    const RhsSamples smp = samples_from(p, b.reference);
    auto crhs = std::make_shared<const CoulombBenchRhs>(CoulombBenchRhs{mc});
    for (const bool cvode : {false, true}) {
      Engine e;
      e.name = cvode ? "cvode-events" : "cxx-events";
      if (!cfg.wants(e.name)) continue;
      e.note = cvode ? "coulomb law: CVODE BDF with root finding on the rest events (stick_slip_cvode.cpp)"
                     : "coulomb law: C++ BS faithful, rest events located, stick held (stick_slip.cpp)";
      e.solve = [p, mc, cvode](double rtol) { return cvode ? solve_coulomb_cvode(p, mc, rtol) : solve_coulomb(p, mc, rtol, false); };
      e.time_rhs = rhs_timer<double>(crhs, p.n, smp);
      b.engines.push_back(std::move(e));
    }
    EngineConfig dcfg = cfg;
    dcfg.precisions = {Precision::double_};
    for (auto& e : generic_engines<kRoughStateSize>(p, rhs, smp, dcfg)) {
      e.note = "no event location (thesis-law ODE): " + e.note;
      if (cfg.rhs_budget > 0) {
        e.note += "; at most " + std::to_string(cfg.rhs_budget) + " RHS evaluations per solve";
        // every solve and every RHS timing starts a fresh budget
        e.solve = [inner = e.solve, rhs](double rtol) {
          rhs->calls = 0;
          return inner(rtol);
        };
        if (e.replay)  // the recording solve starts a fresh budget too (the replays call no RHS)
          e.replay = [inner = e.replay, rhs](double rtol, const Solve& first) {
            rhs->calls = 0;
            auto timer = inner(rtol, first);
            rhs->calls = 0;
            return timer;
          };
        if (e.time_rhs)
          e.time_rhs = [inner = e.time_rhs, rhs](std::int64_t count) {
            rhs->calls = std::numeric_limits<std::int64_t>::min() / 2;  // timing is never cut short
            const double t = inner(count);
            rhs->calls = 0;
            return t;
          };
      }
      b.engines.push_back(std::move(e));
    }
  } else if (sc.rough()) {
    const RoughBarModel m = bench_rough_model(sc);
    auto rhs = std::make_shared<const RoughBenchRhs>(RoughBenchRhs{RoughBarThesisRhs{m}});
    const Solve a = quad_legacy_run(sc, p, m, 1e-20);
    const Solve c = quad_legacy_run(sc, p, m, 1e-18);
    b.reference = extended_reference(p, a, c,
                                     "fortran/prog_nanobar.f built with -freal-8-real-16 (nanobar_quad): rtol 1e-20 vs "
                                     "1e-18, F77 friction and integrator in REAL(16)");
    EngineConfig dcfg = cfg;
    dcfg.precisions = {Precision::double_};  // the friction closed form is double: no long/quad engines here
    b.engines = generic_engines<kRoughStateSize>(p, rhs, samples_from(p, b.reference), dcfg);
  } else {
    throw InputError("surface.kind", sc.model, "the benchmark supports: smooth, rough");
  }
  return b;
}

}  // namespace nanopush::bench
