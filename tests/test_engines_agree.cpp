// Cross-language tier: the C++ `faithful` engine takes exactly the F77 engine's steps.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "f77_bsint.h"
#include "nanopush/numerics/bulirsch_stoer.hpp"
#include "nanopush/numerics/elliptic.hpp"
#include "nanopush/models/rigid_body.hpp"
#include "nanopush/engines/engines.hpp"
#include "trajectory_checks.hpp"

using namespace nanopush;
using nanopush::test::max_dtheta;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

struct Counts {
  long nfcn, naccpt, nrejct;
  double theta_end;
};

const double kMass = 0.623425e-18;
const double kInertia = kMass * (100e-9 * 100e-9 + 55e-9 * 55e-9) / 12;
const double kParams[6] = {kMass, kInertia, 5e-6, 0.0, 27.5e-9, -45e-9};

std::vector<double> atol_for(double rtol) {
  const double sc[6] = {1e-9, 1e-9, 1, 10, 10, 1e10};
  std::vector<double> a(6);
  for (int i = 0; i < 6; ++i) a[i] = rtol * sc[i];
  return a;
}

Counts run_f77(double theta0, int iextr, double rtol, const std::vector<double>& tout) {
  double y[6] = {0, 0, theta0, 0, 0, 0};
  std::vector<double> yout(6 * tout.size());
  int nstat[3];
  const auto atol = atol_for(rtol);
  const int st = np_f77_bsint_smooth_bar(6, 0.0, y, static_cast<int>(tout.size()), tout.data(), yout.data(), rtol,
                                         atol.data(), 0.0, 0.0, 8, iextr, 0, kParams, nstat);
  REQUIRE(st == 0);
  return {nstat[0], nstat[1], nstat[2], y[2]};
}

Counts run_cxx(double theta0, int iextr, double rtol, const std::vector<double>& tout) {
  BsOptions<double> o = BsOptions<double>::faithful(rtol, atol_for(rtol));
  o.extrapolation = iextr == 1 ? Extrapolation::rational : Extrapolation::polynomial;
  BulirschStoer<double, 6> bs(o);
  double y[6] = {0, 0, theta0, 0, 0, 0};
  const SmoothBarRhs rhs{kParams[0], kParams[1], Push{kParams[2], kParams[3], kParams[4], kParams[5]}};
  auto r = bs.integrate(rhs, 0.0, y, std::span<const double>(tout), [](std::size_t, double, const double*) {});
  REQUIRE(r.ok());
  return {static_cast<long>(r.nfcn), static_cast<long>(r.naccpt), static_cast<long>(r.nrejct), y[2]};
}

std::vector<double> outputs(int n) {
  std::vector<double> t;
  for (int k = 0; k <= n; ++k) t.push_back((1.6e-9 * k) / n);
  return t;
}

}  // namespace

TEST_CASE("C++ faithful reproduces the F77 steps: 101 outputs", "[engines][crosslang][regression]") {
  for (int iextr : {1, 2}) {
    for (double rtol : {1e-6, 1e-9, 1e-12}) {
      const Counts f = run_f77(0.5, iextr, rtol, outputs(100));
      const Counts c = run_cxx(0.5, iextr, rtol, outputs(100));
      INFO("iextr " << iextr << " rtol " << rtol);
      CHECK(c.nfcn == f.nfcn);
      CHECK(c.naccpt == f.naccpt);
      CHECK(c.nrejct == f.nrejct);
      CHECK(c.theta_end == f.theta_end);  // same operations in the same order: bit for bit
    }
  }
}

TEST_CASE("C++ faithful reproduces the F77 steps: free step control with rejections",
          "[engines][crosslang][regression]") {
  struct Case {
    double theta0;
    int iextr;
    double rtol;
    long nfcn, naccpt, nrejct;  // docs/bulirsch_stoer.md, reference table
  };
  const Case cases[] = {{-0.5, 1, 1e-6, 825, 17, 1},  {-0.5, 1, 1e-9, 1679, 27, 4}, {-0.5, 1, 1e-12, 3021, 63, 13},
                        {-0.5, 2, 1e-9, 1703, 27, 5}, {0.5, 1, 1e-9, 1199, 23, 1},  {0.75, 1, 1e-6, 719, 17, 4},
                        {1.5, 2, 1e-12, 2066, 42, 4}};
  for (const auto& k : cases) {
    const std::vector<double> tout = {0.0, 1.6e-9};
    const Counts f = run_f77(k.theta0, k.iextr, k.rtol, tout);
    const Counts c = run_cxx(k.theta0, k.iextr, k.rtol, tout);
    INFO("theta0 " << k.theta0 << " iextr " << k.iextr << " rtol " << k.rtol);
    CHECK(f.nfcn == k.nfcn);
    CHECK(c.nfcn == f.nfcn);
    CHECK(c.naccpt == f.naccpt);
    CHECK(c.nrejct == f.nrejct);
    CHECK(c.nrejct == k.nrejct);
    CHECK(c.theta_end == f.theta_end);
  }
}

TEST_CASE("Every Fig 3.6 preset: identical counts and theta to 1e-12, C++ faithful vs F77",
          "[engines][crosslang][regression]") {
  for (const char* c : {"a", "b", "c", "d", "e", "f", "g", "h"}) {
    const Scene sc = load_scene(std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/thesis/fig3_6" + c + ".toml");
    RunSettings a, b;
    a.engine = nanopush::Engine::cxx;
    a.method = Method::faithful;
    b.engine = nanopush::Engine::f77;
    const Trajectory ta = run_engine(sc, a), tb = run_engine(sc, b);
    INFO("fig3_6" << c);
    CHECK(ta.stats.nfcn == tb.stats.nfcn);
    CHECK(ta.stats.naccpt == tb.stats.naccpt);
    CHECK(ta.stats.nrejct == tb.stats.nrejct);
    const double dev = max_dtheta(ta, tb);
    CHECK(dev <= 1e-12);
  }
}

TEST_CASE("Fig 3.6, F77 engine: exact pendulum at rtol 1e-12", "[smooth][numeric][f77]") {
  for (const char* c : {"a", "b", "c", "d", "e", "f", "g", "h"}) {
    const Scene sc = load_scene(std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/thesis/fig3_6" + c + ".toml");
    RunSettings b;
    b.engine = nanopush::Engine::f77;
    const Trajectory tb = run_engine(sc, b);
    const Pendulum<double> ex(sc.push.theta_equilibrium(), sc.initial[kTheta], sc.push.force * sc.push.lever(),
                              sc.inertia);
    const double acc = sc.push.force / sc.mass;
    double e = 0, xr = 0;
    for (const auto& r : tb.rows) {
      e = std::max(e, std::fabs(r[3] - ex.theta(r[0])));
      if (r[0] > 0) xr = std::max(xr, std::fabs(r[1] - 0.5 * acc * r[0] * r[0]) / (0.5 * acc * r[0] * r[0]));
    }
    INFO("fig3_6" << c << " theta error " << e << " x rel " << xr);
    CHECK(e <= 1e-10);
    CHECK(xr <= 1e-12);
  }
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
