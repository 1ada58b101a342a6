// Issue 5 items 3 and 4: the dynamic iCOR (rough-surface nanorod under the coulomb law) and
// the quasi-static iCOR of a finite rectangle (closed-form friction), against their limits
// and an independent cubature-based solve.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <unistd.h>
#include <vector>

#include "nanopush/numerics/error.hpp"
#include "nanopush/models/friction_cubature.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/models/icor_dynamic.hpp"

using namespace nanopush;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

const icor::Rod kRod = icor::nanorod();
const double kB = kRod.half_length(), kL = kRod.length, kK2 = kRod.gyration_squared();

/// Independent quasi-static solve for the rectangle: the iCOR on the rod axis (alpha = pi/2,
/// the x' -> -x' symmetry makes fy vanish there), friction from adaptive Gauss-Kronrod
/// cubature, and the one remaining balance (moment about the CM with F = -fx) solved for R
/// by bisection on a bracket found by a logarithmic scan. Push along +x' at (0, yn):
/// clockwise (sense -1); F e + f = 0 gives F = -fx, the moment -yn F + mf = 0.
struct CubatureSolve {
  double R = 0.0, force = 0.0;
  bool found = false;
};
CubatureSolve cubature_quasi_static(double a, double b, double yn) {
  auto g = [&](double R, double* F) {
    const auto c = cubature_friction_wrench_uniform(a, b, 1.0, R, M_PI / 2, -1, 1e-13);
    REQUIRE(c.converged);
    if (F) *F = -c.wrench.fx;
    return yn * c.wrench.fx + c.wrench.mf;  // -yn F + mf with F = -fx
  };
  CubatureSolve s;
  double lo = 1e-3 * b, glo = g(lo, nullptr);
  for (double hi = lo * 1.25; hi < 1e4 * b; lo = hi, hi *= 1.25) {
    const double ghi = g(hi, nullptr);
    if ((glo < 0.0) != (ghi < 0.0)) {
      double l = lo, h = hi, gl = glo;
      for (int it = 0; it < 200 && (h - l) > 1e-15 * h; ++it) {
        const double m = 0.5 * (l + h), gm = g(m, nullptr);
        if ((gm < 0.0) == (gl < 0.0)) {
          l = m;
          gl = gm;
        } else {
          h = m;
        }
      }
      s.R = 0.5 * (l + h);
      g(s.R, &s.force);
      s.found = true;
      return s;
    }
    glo = ghi;
  }
  return s;
}

double rel(double x, double ref) { return std::fabs(x / ref - 1.0); }

icor::DynamicIcorRun run(double yn, double force, std::vector<double> times,
                         icor::DynamicIntegrator integ = icor::DynamicIntegrator::automatic) {
  icor::DynamicIcorSetup s;
  s.yn = yn;
  s.force = force;
  s.times = std::move(times);
  s.integrator = integ;
  return icor::dynamic_icor(s);
}

}  // namespace

// ---- Item 4: the finite rectangle ----------------------------------------------------

TEST_CASE("Finite-rectangle quasi-static iCOR reduces to eq 4.13 as a/b -> 0 (1e-6 at a/b = 1e-4)",
          "[icor][rectangle][numeric]") {
  for (double yn : {1e-9, 5e-9, 50e-9, 150e-9, 250e-9, 295e-9}) {
    INFO("yn = " << yn);
    const auto q = icor::rectangle_quasi_static(1e-4 * kB, kB, yn);
    REQUIRE(q.converged);
    CHECK(q.omega_sign == -1);  // clockwise for a push along +x' at (0, +yn)
    CHECK(rel(q.R, icor::unknown_pressure(yn, kL)) <= 1e-6);
    CHECK(rel(q.force, icor::minimum_force(1.0, 1.0, yn, kL)) <= 1e-6);  // eq 4.8 per mu W
    CHECK(std::remainder(q.alpha - M_PI / 2, 2 * M_PI) == Approx(0.0).margin(1e-9));  // far side, on the axis
  }
  // The deviation from 4.13 falls with the aspect ratio (measured: ~ (a/b)^2 log(b/a)).
  for (double yn : {50e-9, 250e-9}) {
    double prev = 1.0;
    for (double ab : {0.3, 0.1, 0.03, 0.01, 1e-3, 1e-4}) {
      const double d = rel(icor::rectangle_quasi_static(ab * kB, kB, yn).R, icor::unknown_pressure(yn, kL));
      INFO("yn = " << yn << ", a/b = " << ab << ", deviation " << d);
      CHECK(d < prev);
      prev = d;
    }
  }
  // yn = 0: a push through the CM translates the rectangle.
  const auto t = icor::rectangle_quasi_static(0.1 * kB, kB, 0.0);
  CHECK(std::isinf(t.R));
  CHECK(t.force == 1.0);
}

TEST_CASE("Finite-rectangle quasi-static iCOR matches an independent cubature-based solve up to a/b = 1",
          "[icor][rectangle][numeric]") {
  for (double ab : {0.01, 0.1, 0.5, 1.0})
    for (double yn : {20e-9, 120e-9, 295e-9}) {
      INFO("a/b = " << ab << ", yn = " << yn);
      const auto q = icor::rectangle_quasi_static(ab * kB, kB, yn);
      REQUIRE(q.converged);
      const auto c = cubature_quasi_static(ab * kB, kB, yn);
      REQUIRE(c.found);
      CHECK(rel(q.R, c.R) <= 1e-9);
      CHECK(rel(q.force, c.force) <= 1e-10);
      CHECK(std::remainder(q.alpha - M_PI / 2, 2 * M_PI) == Approx(0.0).margin(1e-9));
    }
}

TEST_CASE("Finite-rectangle quasi-static iCOR: bad input is rejected", "[icor][rectangle][unit]") {
  CHECK_THROWS_AS(icor::rectangle_quasi_static(0.0, kB, 1e-8), InputError);
  CHECK_THROWS_AS(icor::rectangle_quasi_static(1e-9, -kB, 1e-8), InputError);
  CHECK_THROWS_AS(icor::rectangle_quasi_static(1e-9, kB, -1e-8), InputError);
  // A push line beyond the end (yn > b) misses the rectangle: no iCOR, not an unconverged one.
  CHECK_THROWS_WITH(icor::rectangle_quasi_static(0.55 * kB, kB, 1.0),
                    Catch::Matchers::StartsWith("yn = 1: must be in [0, " + fmt(kB) + "]"));
  CHECK(icor::rectangle_quasi_static(0.55 * kB, kB, kB).converged);  // at the corner: still on the face
  // Aspect ratio below the friction closed form's limit (kFrictionMinAspect = 1e-12).
  CHECK_THROWS_AS(icor::rectangle_quasi_static(1e-13 * kB, kB, 1e-8), InputError);
}

// ---- Item 3: the dynamic iCOR ----------------------------------------------------------

TEST_CASE("Dynamic iCOR: the contact strip and the minimum force", "[icor][dynamic][unit]") {
  const double a = icor::rod_contact_half_width(kRod);
  // Hertz line contact under W/L with E* = E/(2(1 - nu^2)) (graphite on graphite).
  const double Es = 36.5e9 / (2.0 * (1.0 - 0.2 * 0.2));
  CHECK(a == Approx(std::sqrt(4.0 * (kRod.load() / kL) * kRod.radius / (M_PI * Es))).epsilon(1e-12));
  CHECK(a == Approx(2.7776e-9).epsilon(1e-4));
  // A push just below the rectangle's minimum force leaves the rod stuck ("no motion"),
  // just above it moves it; the line-contact minimum (4.8) is below the rectangle's, so a
  // push at 0.999 of it is stuck as well.
  const double muW = 0.1 * kRod.load();
  for (double yn : {10e-9, 100e-9, 250e-9}) {
    INFO("yn = " << yn);
    const double fmin = icor::rectangle_quasi_static(a, kB, yn).force * muW;
    CHECK(fmin > icor::minimum_force(0.1, kRod.load(), yn, kL));
    for (double f : {0.999 * fmin, 0.999 * icor::minimum_force(0.1, kRod.load(), yn, kL)}) {
      const auto r = run(yn, f, {1e-11, 1e-10});
      CHECK(r.stuck);
      for (const auto& s : r.samples) CHECK_FALSE(s.moving);
    }
    const auto m = run(yn, 1.001 * fmin, {1e-10});
    CHECK_FALSE(m.stuck);
    CHECK(m.samples.at(0).moving);
    CHECK(m.minimum_force == Approx(fmin).epsilon(1e-14));
  }
}

TEST_CASE("Dynamic iCOR tends to the quasi-static one as F falls to the minimum force", "[icor][dynamic][numeric]") {
  const double a = icor::rod_contact_half_width(kRod), muW = 0.1 * kRod.load();
  for (double yn : {20e-9, 100e-9, 200e-9, 295e-9}) {
    const auto qs = icor::rectangle_quasi_static(a, kB, yn);
    const double r413 = icor::unknown_pressure(yn, kL);
    double prev = 1e300;
    for (double eps : {1e-1, 1e-2, 1e-3, 1e-4}) {
      const auto r = run(yn, (1.0 + eps) * qs.force * muW, {1e-10});
      REQUIRE_FALSE(r.stuck);
      if (eps <= 1e-2) CHECK(r.integrator == icor::DynamicIntegrator::cvode);  // stiff start (header)
      const auto& s = r.samples.at(0);
      const double d = rel(s.axial, qs.R);
      INFO("yn = " << yn << ", F/F_min - 1 = " << eps << ": R = " << s.axial << ", quasi-static " << qs.R
                   << ", relative distance " << d);
      CHECK(d < prev);        // monotone approach
      CHECK(d <= 0.5 * eps);  // measured: ~0.2 eps (linear in the excess force)
      CHECK(std::fabs(s.offset) <= 1e-3 * s.axial);  // on the rod axis (theta ~ eps)
      prev = d;
      if (eps == 1e-4) {
        CHECK(d <= 1e-4);
        // and eq 4.13 (line contact) within the strip's own correction, a/b = 0.0094:
        CHECK(rel(s.axial, r413) <= 5e-4);
      }
    }
  }
}

TEST_CASE("Dynamic iCOR tends to the impulsive one (5.5) as F/(mu W) grows at a fixed impulse",
          "[icor][dynamic][numeric]") {
  // Impulsive motion is a large force over a short time: the push's impulse F t is held at
  // that of F = 2 mu W over the thesis' 1e-10 s, t = 2e-10 s / (F/(mu W)). (At a fixed
  // t = 1e-10 s a large force spins the rod, theta ~ 0.011 F/(mu W) at yn = 100 nm, and the
  // reading leaves the impulsive value: next test.)
  const double muW = 0.1 * kRod.load();
  for (double yn : {50e-9, 150e-9, 250e-9}) {
    const double imp = icor::impulsive(yn, kK2);
    double prev = 1e300;
    for (double ratio : {2.0, 5.0, 20.0, 100.0, 1000.0}) {
      const auto r = run(yn, ratio * muW, {2e-10 / ratio});
      REQUIRE_FALSE(r.stuck);
      const auto& s = r.samples.at(0);
      const double d = rel(s.axial, imp);
      INFO("yn = " << yn << ", F/(mu W) = " << ratio << ": R = " << s.axial << ", impulsive " << imp
                   << ", relative distance " << d);
      CHECK(d < prev);
      CHECK(d <= 1.5 / ratio);  // friction's share of the wrench is ~ mu W / F
      prev = d;
      if (ratio == 1000.0) CHECK(d <= 2e-3);
    }
  }
}

TEST_CASE("Dynamic iCOR at the thesis' t = 1e-10 s lies between the quasi-static and impulsive ones",
          "[icor][dynamic][numeric]") {
  // For F/(mu W) = 1.1, 2, 5 (rotation < 0.2 rad by 1e-10 s) the iCOR moves monotonically
  // from the quasi-static value toward the impulsive one as F grows; all three meet where
  // eq 4.13 equals k^2/yn, yn = b/sqrt(3) = 170.3 nm (the thesis reads ~177 nm, Fig 5.3).
  const double a = icor::rod_contact_half_width(kRod), muW = 0.1 * kRod.load();
  const double ycross = kB / std::sqrt(3.0);
  CHECK(icor::unknown_pressure(ycross, kL) == Approx(icor::impulsive(ycross, kK2)).epsilon(1e-14));
  for (double yn : {30e-9, 90e-9, 150e-9, 200e-9, 260e-9, 295e-9}) {
    const double qs = icor::rectangle_quasi_static(a, kB, yn).R, imp = icor::impulsive(yn, kK2);
    // Away from the crossing: within a few nm of b/sqrt(3) the rotation's second-order effect
    // (0.2 % at F = 5 mu W) exceeds the interval itself (docs/icor.md).
    REQUIRE(std::fabs(imp - qs) >= 0.05 * qs);
    double prev = qs;
    for (double ratio : {1.1, 2.0, 5.0}) {
      const auto r = run(yn, ratio * muW, {1e-10});
      const double R = r.samples.at(0).axial;
      INFO("yn = " << yn << ", F/(mu W) = " << ratio << ": quasi-static " << qs << ", dynamic " << R << ", impulsive "
                   << imp);
      CHECK(std::fabs(r.samples.at(0).theta) < 0.2);
      CHECK((R - prev) * (imp - qs) > 0.0);  // moved further toward the impulsive value
      CHECK((imp - R) * (imp - qs) > 0.0);   // not past it
      prev = R;
    }
  }
}

TEST_CASE("Dynamic iCOR: self-similar early motion, self-convergence, pure translation", "[icor][dynamic][numeric]") {
  const double muW = 0.1 * kRod.load();
  // From rest under a constant push the velocity grows along a fixed direction while the
  // rotation is small: the iCOR read along the way is constant to O(theta^2).
  const auto r = run(100e-9, 5.0 * muW, {1e-13, 1e-12, 1e-11});
  REQUIRE(r.samples.size() == 3);
  CHECK(rel(r.samples[1].axial, r.samples[0].axial) <= 1e-6);
  CHECK(rel(r.samples[2].axial, r.samples[0].axial) <= 1e-4);
  CHECK(std::fabs(r.samples[2].theta) < 0.01);
  // Self-convergence of the Bulirsch-Stoer run (the default away from the minimum force).
  // (CVODE, used close to the minimum force and checked there against the quasi-static limit,
  // is far less accurate here: ~1e-5 at rtol 1e-10, and its error test fails in some runs;
  // docs/icor.md.)
  for (double yn : {50e-9, 150e-9, 250e-9})
    for (double ratio : {2.0, 5.0, 20.0}) {
      INFO("yn = " << yn << ", F/(mu W) = " << ratio);
      icor::DynamicIcorSetup s;
      s.yn = yn;
      s.force = ratio * muW;
      s.times = {1e-11, 1e-10};
      s.rtol = 1e-8;
      const auto coarse = icor::dynamic_icor(s);
      s.rtol = 1e-12;
      const auto fine = icor::dynamic_icor(s);
      CHECK(coarse.integrator == icor::DynamicIntegrator::bulirsch_stoer);
      CHECK(fine.integrator == icor::DynamicIntegrator::bulirsch_stoer);
      for (std::size_t i = 0; i < 2; ++i) CHECK(rel(coarse.samples[i].axial, fine.samples[i].axial) <= 1e-8);
    }
  // A push through the CM translates the rod: omega = 0 exactly, R = infinity.
  const auto t = run(0.0, 2.0 * muW, {1e-10});
  CHECK(t.samples.at(0).moving);
  CHECK(t.samples.at(0).translation);
  CHECK(std::isinf(t.samples.at(0).R));
}

TEST_CASE("Dynamic iCOR: bad input is rejected", "[icor][dynamic][unit]") {
  const double muW = 0.1 * kRod.load();
  CHECK_THROWS_AS(run(-1e-9, muW, {1e-10}), InputError);
  CHECK_THROWS_AS(run(kB * 1.01, muW, {1e-10}), InputError);
  CHECK_THROWS_AS(run(1e-7, 0.0, {1e-10}), InputError);
  CHECK_THROWS_AS(run(1e-7, muW, {}), InputError);
  CHECK_THROWS_AS(run(1e-7, muW, {2e-10, 1e-10}), InputError);
  CHECK_THROWS_AS(run(1e-7, muW, {0.0}), InputError);
}

TEST_CASE("Dynamic iCOR: a run that cannot reach its last output says which, and prints nothing",
          "[icor][dynamic][unit]") {
  // 1e10 s of a push at 1e-6 N: CVODE spends its step budget. Its own message goes into the
  // error (the library prints nothing: Python, C and Fortran callers see only the exception).
  std::fflush(stderr);
  const int saved = dup(2);
  std::FILE* sink = std::tmpfile();
  REQUIRE(sink);
  dup2(fileno(sink), 2);
  std::string what;
  try {
    run(1e-7, 1e-6, {1e10});
  } catch (const SolverError& e) {
    what = e.what();
  }
  std::fflush(stderr);
  dup2(saved, 2);
  close(saved);
  std::fseek(sink, 0, SEEK_END);
  const long printed = std::ftell(sink);
  std::fclose(sink);
  CHECK(printed == 0);
  CHECK_THAT(what, Catch::Matchers::StartsWith("the dynamic iCOR (F = 1e-06 N at yn = 1e-07 m, outputs to t = 1e+10 s)"));
  CHECK_THAT(what, Catch::Matchers::Contains("mxstep steps taken before reaching tout"));
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
