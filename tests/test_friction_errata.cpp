// Evidence for the docs/errata.md entries on the thesis' friction closed forms (3.45)-(3.48):
// each test fails with the printed form and passes with the corrected one / our implementation.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "nanopush/models/friction.hpp"
#include "nanopush/models/friction_cubature.hpp"

using namespace nanopush;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
constexpr double kPi = 3.14159265358979323846;
struct Pt {
  double a, b, R, alpha;
};
// iCOR outside in every quadrant, inside, and near the contact (no h_i = 0).
const Pt kPoints[] = {{0.3, 0.7, 3.0, 0.8},  {0.3, 0.7, 3.0, 2.5},   {0.3, 0.7, 3.0, -2.0}, {0.3, 0.7, 3.0, -0.7},
                      {0.3, 0.7, 0.5, 0.9},  {0.3, 0.7, 0.0, 0.0},   {27.5, 50.0, 60.0, 1.1}, {1.0, 1.0, 1.3, 0.2}};
}  // namespace

TEST_CASE("errata (3.46): the printed fy' has the wrong sign", "[friction][errata][numeric]") {
  for (const auto& p : kPoints) {
    const auto q = cubature_friction_wrench_uniform(p.a, p.b, 1.0, p.R, p.alpha, 1, 1e-13);
    const auto t = thesis_printed_friction(p.a, p.b, p.R, p.alpha);
    INFO("R=" << p.R << " alpha=" << p.alpha);
    CHECK(t.fx == Approx(q.wrench.fx).margin(1e-12));  // (3.45) as printed is right
    if (std::fabs(q.wrench.fy) > 1e-3) {
      CHECK(t.fy != Approx(q.wrench.fy).margin(1e-6));   // printed (3.46): wrong
      CHECK(-t.fy == Approx(q.wrench.fy).margin(1e-12)); // with the sign of (3.43): right
    }
  }
  // Physical consequence: the printed fy' adds energy (f.v > 0) for an iCOR at alpha = 0.8.
  const double R = 3.0, alpha = 0.8, omega = 1.0;
  const auto t = thesis_printed_friction(0.3, 0.7, R, alpha);
  const double vx = -omega * R * std::sin(alpha), vy = omega * R * std::cos(alpha);
  CHECK(t.fx * vx + t.fy * vy + t.mf * omega > 0.0);
  const auto w = rectangle_friction_wrench(0.3, 0.7, 1.0, R, alpha, 1);
  CHECK(w.fx * vx + w.fy * vy + w.mf * omega < 0.0);
}

TEST_CASE("errata (3.48): C4 needs cubes h_i^3 (as in B.37), not squares", "[friction][errata][numeric]") {
  for (const auto& p : kPoints) {
    const auto q = cubature_friction_wrench_uniform(p.a, p.b, 1.0, p.R, p.alpha, 1, 1e-13);
    const auto t = thesis_printed_friction(p.a, p.b, p.R, p.alpha);
    const auto c = thesis_corrected_friction(p.a, p.b, p.R, p.alpha, 1);
    const double L = std::max(p.a, p.b);
    INFO("R=" << p.R << " alpha=" << p.alpha << " printed mf " << t.mf << " corrected " << c.mf << " cubature "
              << q.wrench.mf);
    CHECK(std::fabs(t.mf - q.wrench.mf) > 1e-3 * L);                  // printed: wrong
    CHECK(c.mf == Approx(q.wrench.mf).margin(1e-12 * L));             // cubes: right
    CHECK(c.fx == Approx(q.wrench.fx).margin(1e-12));
    CHECK(c.fy == Approx(q.wrench.fy).margin(1e-12));
  }
}

TEST_CASE("errata (3.47): mf must carry sign(theta-dot); without it friction adds energy",
          "[friction][errata][numeric]") {
  // Rotation about the CM, clockwise: f = 0, so the power is mf * omega.
  const double omega = -2.0;
  const auto t = thesis_printed_friction(0.3, 0.7, 0.0, 0.0);  // (3.47) has no sense factor
  CHECK(t.mf * omega > 0.0);                                     // adds energy: wrong
  const auto w = rectangle_friction_wrench(0.3, 0.7, 1.0, 0.0, 0.0, -1);
  CHECK(w.mf * omega < 0.0);
  const auto c = thesis_corrected_friction(0.3, 0.7, 0.0, 0.0, -1);
  CHECK(c.mf == Approx(w.mf).epsilon(1e-14));
}

TEST_CASE("errata (3.45)-(3.48) validity: the printed logarithms fail on iCOR edge lines",
          "[friction][errata][numeric]") {
  // iCOR on the line of an edge, h1 = R sin(alpha) - b = 0 exactly (alpha = pi/2, R = b), and
  // on a corner: the printed forms give 0 * log(0) or log(x/0) = NaN; ours is finite and right.
  const double a = 0.3, b = 0.7;
  for (const Pt p : {Pt{a, b, b, kPi / 2}, Pt{a, b, a, 0.0}, Pt{a, b, std::hypot(a, b), std::atan2(b, a)}}) {
    const auto t = thesis_printed_friction(p.a, p.b, p.R, p.alpha);
    const auto w = rectangle_friction_wrench(p.a, p.b, 1.0, p.R, p.alpha, 1);
    const auto q = cubature_friction_wrench_uniform(p.a, p.b, 1.0, p.R, p.alpha, 1, 1e-13);
    INFO("R=" << p.R << " alpha=" << p.alpha << " printed " << t.fx << " " << t.fy << " " << t.mf);
    CHECK_FALSE((std::isfinite(t.fx) && std::isfinite(t.fy) && std::isfinite(t.mf) &&
                 std::fabs(t.fx - q.wrench.fx) < 1e-9));
    CHECK(w.fx == Approx(q.wrench.fx).margin(1e-12));
    CHECK(w.fy == Approx(q.wrench.fy).margin(1e-12));
    CHECK(w.mf == Approx(q.wrench.mf).margin(1e-12));
  }
}

TEST_CASE("errata: the printed closed forms cancel catastrophically as R -> infinity", "[friction][errata][numeric]") {
  const double a = 27.5e-9, b = 50e-9, alpha = 0.3;
  double worst_printed = 0.0, worst_ours = 0.0;
  for (double rho : {1e3, 1e4, 1e5}) {
    const double R = rho * b;
    const auto c = thesis_corrected_friction(a, b, R, alpha, 1);
    const auto w = rectangle_friction_wrench(a, b, 1.0, R, alpha, 1);
    // Reference: translation plus O((L/R)^2); for the moment, its asymptotic form (error O(rho^-2)).
    const double mf_ref = -(a * a * std::sin(alpha) * std::sin(alpha) + b * b * std::cos(alpha) * std::cos(alpha)) / (3 * R);
    worst_printed = std::max(worst_printed, std::fabs(c.mf - mf_ref) / std::fabs(mf_ref));
    worst_ours = std::max(worst_ours, std::fabs(w.mf - mf_ref) / std::fabs(mf_ref) - 1.0 / (rho * rho));
    CHECK(std::hypot(w.fx, w.fy) == Approx(1.0).margin(1.0 / (rho * rho)));
  }
  INFO("corrected printed form: relative error of mf up to " << worst_printed << "; ours " << worst_ours);
  CHECK(worst_printed > 1e-3);  // the printed (even corrected) form has lost the moment
  CHECK(worst_ours <= 1e-14);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
