// Cross-language: the FORTRAN 77 friction wrench (fortran/rectfr.f via fortran/bridge/f77_friction.f90)
// against the C++ one, at every point of the random set, the far-field sweep and the edge cases.
#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "f77_friction.h"
#include "nanopush/models/friction.hpp"

using namespace nanopush;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Relative difference of two wrenches: force vector relative to |f| and moment relative to
/// |mf|, each with a floor of 1e-300 so exact zeros compare as equal.
void require_agree(const FrictionWrench& c, const double* f, double tol, const std::string& what) {
  const double df = std::hypot(c.fx - f[0], c.fy - f[1]);
  const double fm = std::hypot(c.fx, c.fy);
  const double dm = std::fabs(c.mf - f[2]);
  INFO(what << " C++ (" << c.fx << ", " << c.fy << ", " << c.mf << ") F77 (" << f[0] << ", " << f[1] << ", " << f[2]
            << ") rel df " << df / std::max(fm, 1e-300) << " rel dm " << dm / std::max(std::fabs(c.mf), 1e-300));
  CHECK(df <= tol * fm);
  CHECK(dm <= tol * std::fabs(c.mf));
}

}  // namespace

// The F77 routine evaluates the corner sum of the closed form as the faithful method's C++ forms
// do (friction_detail::*_reference): the two agree to 1e-13 relative in the moment too, where the
// moment is small and both are 1e-12 relative from the exact value (an absolute error of a few
// eps (R/L)^2 of muN L, docs/friction.md). The production C++ form rounds differently within the
// same bound; it is checked against an exact quad-precision oracle in test_friction_fast.cpp.
using friction_detail::rectangle_friction_from_velocity_reference;
using friction_detail::rectangle_friction_wrench_reference;

TEST_CASE("friction: C++ and F77 agree to 1e-13 relative", "[friction][cross-language][regression]") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int n = 0;
  for (int i = 0; i < 20000; ++i) {
    const double L = std::pow(10.0, -9.0 + 3.0 * u(rng));
    const double a = L * std::pow(10.0, -1.3 * u(rng)), b = L * std::pow(10.0, -1.3 * u(rng));
    double R;
    switch (i % 4) {
      case 0: R = std::max(a, b) * 4.0 * u(rng); break;                      // near and inside
      case 1: R = std::max(a, b) * std::pow(10.0, 15.0 * u(rng)); break;     // far
      case 2: R = std::hypot(a, b); break;                                   // corner radius
      default: R = (u(rng) < 0.5 ? a : b) * (0.5 + u(rng)); break;           // edges region
    }
    const double alpha = (i % 7 == 0) ? kPi * std::floor(4 * u(rng)) / 2 : 2 * kPi * u(rng);
    const int sense = (i % 2) ? 1 : -1;
    const double muN = 0.1 + u(rng);
    const auto c = rectangle_friction_wrench_reference(a, b, muN, R, alpha, sense);
    double f[3];
    REQUIRE(np_f77_rectangle_friction(a, b, muN, R, alpha, sense, f) == 0);
    require_agree(c, f, 1e-13, "R/L=" + std::to_string(R / std::max(a, b)) + " alpha=" + std::to_string(alpha));
    // Velocity interface.
    const double om = (u(rng) - 0.5) * 1e6, vx = (u(rng) - 0.5) * 1e-2, vy = (u(rng) - 0.5) * 1e-2;
    const auto cv = rectangle_friction_from_velocity_reference(a, b, muN, vx, vy, om);
    REQUIRE(np_f77_rectangle_friction_velocity(a, b, muN, vx, vy, om, f) == 0);
    require_agree(cv, f, 1e-13, "velocity");
    ++n;
  }
  // Exact special points: centre, corners, edges, switch points, extreme R.
  const double a = 27.5e-9, b = 50e-9;
  for (double R : {0.0, a, b, std::hypot(a, b), 3.0 * b * (1 - 1e-16), 3.0 * b, 1e9 * b, 1e15 * b, 1e300})
    for (double alpha : {0.0, kPi / 2, kPi, -kPi / 2, std::atan2(b, a), 0.3}) {
      const auto c = rectangle_friction_wrench_reference(a, b, 1.0, R, alpha, 1);
      double f[3];
      REQUIRE(np_f77_rectangle_friction(a, b, 1.0, R, alpha, 1, f) == 0);
      require_agree(c, f, 1e-13, "special R=" + std::to_string(R) + " alpha=" + std::to_string(alpha));
      ++n;
    }
  for (double om : {0.0, 1e-300, -1e-20, 1.0}) {
    const auto c = rectangle_friction_from_velocity_reference(a, b, 1.0, 1e-3, -2e-3, om);
    double f[3];
    REQUIRE(np_f77_rectangle_friction_velocity(a, b, 1.0, 1e-3, -2e-3, om, f) == 0);
    require_agree(c, f, 1e-13, "omega=" + std::to_string(om));
  }
  double f[3];
  REQUIRE(np_f77_rectangle_friction_velocity(a, b, 1.0, 0.0, 0.0, 0.0, f) == 0);
  CHECK((f[0] == 0.0 && f[1] == 0.0 && f[2] == 0.0));
  CHECK(n > 20000);
}

TEST_CASE("friction: F77 bad input returns a status and a message, never stops", "[friction][cross-language][unit]") {
  const double nan = std::nan(""), inf = HUGE_VAL;
  double f[3] = {7, 7, 7};
  char msg[128];
  struct Bad {
    double a, b, mun, r, alpha;
    int sense, status;
    const char* word;
  };
  for (const Bad& c : {Bad{0.0, 1.0, 1.0, 1.0, 0.0, 1, 1, "a:"}, Bad{-1.0, 1.0, 1.0, 1.0, 0.0, 1, 1, "a:"},
                       Bad{nan, 1.0, 1.0, 1.0, 0.0, 1, 1, "a:"}, Bad{1.0, inf, 1.0, 1.0, 0.0, 1, 2, "b:"},
                       Bad{1.0, 1e-13, 1.0, 1.0, 0.0, 1, 3, "aspect"}, Bad{1.0, 1.0, -1.0, 1.0, 0.0, 1, 4, "muN"},
                       Bad{1.0, 1.0, 1.0, inf, 0.0, 1, 5, "R:"}, Bad{1.0, 1.0, 1.0, -1.0, 0.0, 1, 5, "R:"},
                       Bad{1.0, 1.0, 1.0, nan, 0.0, 1, 5, "R:"}, Bad{1.0, 1.0, 1.0, 1.0, -inf, 1, 6, "alpha"},
                       Bad{1.0, 1.0, 1.0, 1.0, 0.0, 0, 7, "sense"}}) {
    const int st = np_f77_rectangle_friction(c.a, c.b, c.mun, c.r, c.alpha, c.sense, f);
    CHECK(st == c.status);
    CHECK((f[0] == 0.0 && f[1] == 0.0 && f[2] == 0.0));
    np_f77_friction_message(st, msg, sizeof msg);
    CHECK(std::string(msg).find(c.word) != std::string::npos);
  }
  CHECK(np_f77_rectangle_friction_velocity(1.0, 1.0, 1.0, nan, 0.0, 1.0, f) == 8);
  // Truncation of the message into a short buffer.
  char small[4];
  const int len = np_f77_friction_message(5, small, 4);
  CHECK(len > 4);
  CHECK(std::string(small) == "R: ");
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
