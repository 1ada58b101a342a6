// Friction over a rectangular contact (issue 3, docs/models.md §B): closed form vs adaptive
// cubature, far-field join, oracles, dissipation, robustness, bad input.
#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "nanopush/numerics/cubature.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/models/friction.hpp"
#include "nanopush/models/friction_cubature.hpp"

using namespace nanopush;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
struct Precision {
  Precision() { Catch::StringMaker<double>::precision = 17; }
} const set_precision;
}  // namespace

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Case {
  double a, b, R, alpha;
  const char* kind;
};

/// iCOR at body point (cx, cy) -> (R, alpha) with c = -R (cos alpha, sin alpha).
Case from_icor(double a, double b, double cx, double cy, const char* kind) {
  return {a, b, std::hypot(cx, cy), std::atan2(-cy, -cx), kind};
}

/// Random cases: iCOR inside, outside near, outside far, on edges, on corners, at the CM.
std::vector<Case> random_cases(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Case> cs;
  cs.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double scale = std::pow(10.0, -9.0 + 3.0 * u(rng));  // 1 nm .. 1 um
    const double a = scale * std::pow(10.0, -1.3 * u(rng)), b = scale * std::pow(10.0, -1.3 * u(rng));
    const double L = std::max(a, b);
    const double sx = u(rng) < 0.5 ? -1.0 : 1.0, sy = u(rng) < 0.5 ? -1.0 : 1.0;
    switch (i % 8) {
      case 0:
      case 1:  // inside
        cs.push_back(from_icor(a, b, a * (2 * u(rng) - 1), b * (2 * u(rng) - 1), "inside"));
        break;
      case 2:  // outside, near
        cs.push_back({a, b, L * (1.0 + 4.0 * u(rng)), 2 * kPi * u(rng), "near"});
        break;
      case 3:  // far (both sides of the far-field switch)
        cs.push_back({a, b, L * std::pow(10.0, 3.0 * u(rng)), 2 * kPi * u(rng), "far"});
        break;
      case 4:  // on an edge x' = +-a (exact: alpha = 0 or pi gives Xc = +-R exactly for R = a)
        cs.push_back(from_icor(a, b, sx * a, b * (2 * u(rng) - 1), "edge-x"));
        break;
      case 5:  // on an edge y' = +-b
        cs.push_back(from_icor(a, b, a * (2 * u(rng) - 1), sy * b, "edge-y"));
        break;
      case 6:  // on a corner, or on an edge line's extension outside
        if (u(rng) < 0.5)
          cs.push_back(from_icor(a, b, sx * a, sy * b, "corner"));
        else
          cs.push_back(from_icor(a, b, sx * a, sy * b * (1.0 + 3.0 * u(rng)), "edge-line"));
        break;
      default:  // exact edge / line cases: alpha multiple of pi/2 is exact for alpha = 0, pi
        if (u(rng) < 0.25)
          cs.push_back({a, b, 0.0, 2 * kPi * u(rng), "centre"});
        else
          cs.push_back({a, b, a * (u(rng) < 0.5 ? 1.0 : 0.5 + 3.0 * u(rng)), u(rng) < 0.5 ? 0.0 : kPi, "axis"});
        break;
    }
  }
  return cs;
}

}  // namespace

TEST_CASE("friction: closed form vs adaptive cubature over 10 000 random iCORs", "[friction][numeric]") {
  const auto cases = random_cases(10000, 20261122);
  int n = 0;
  double worst_f = 0.0, worst_m = 0.0;
  for (const auto& c : cases) {
    const double muN = 1.7e-6;
    const int sense = (n % 3 == 0) ? -1 : 1;
    const auto w = rectangle_friction_wrench(c.a, c.b, muN, c.R, c.alpha, sense);
    const auto q = cubature_friction_wrench_uniform(c.a, c.b, muN, c.R, c.alpha, sense, 1e-13);
    INFO("case " << n << " (" << c.kind << ") a=" << c.a << " b=" << c.b << " R=" << c.R << " alpha=" << c.alpha);
    REQUIRE(q.converged);
    const double fq = std::hypot(q.wrench.fx, q.wrench.fy);
    const double df = std::hypot(w.fx - q.wrench.fx, w.fy - q.wrench.fy);
    const double L = std::max(c.a, c.b);
    // Relative error of f (at R = 0, where f = 0 exactly, an absolute check below).
    const double ef = c.R == 0.0 ? 0.0 : df / fq;
    const double em = std::fabs(w.mf - q.wrench.mf) / (muN * L);
    if (c.R == 0.0) {
      // f = 0 exactly at R = 0: an absolute check (a relative error is meaningless there).
      CHECK(std::hypot(w.fx, w.fy) <= 1e-14 * muN);
    } else {
      worst_f = std::max(worst_f, ef);
    }
    worst_m = std::max(worst_m, em);
    CHECK(ef <= 1e-10);
    CHECK(em <= 1e-10);
    ++n;
  }
  REQUIRE(n >= 10000);
  WARN("closed form vs cubature over " << n << " cases: worst relative |df| " << worst_f << ", worst |dmf|/(muN L) "
                                       << worst_m);
  // Both forms are accurate to ~1e-13; say so, so a regression to 1e-11 is noticed.
  CHECK(worst_f <= 1e-12);
  CHECK(worst_m <= 1e-12);
}

TEST_CASE("friction: cubature with the analytic inner integral agrees with the fully numerical one",
          "[friction][numeric]") {
  const auto cases = random_cases(120, 7);
  for (const auto& c : cases) {
    const auto q1 = cubature_friction_wrench_uniform(c.a, c.b, 1.0, c.R, c.alpha, 1, 1e-13);
    const auto q2 = cubature_friction_wrench(c.a, c.b, 1.0, c.R, c.alpha, 1, [](double, double) { return 3.5; }, 1e-12);
    const auto w = rectangle_friction_wrench(c.a, c.b, 1.0, c.R, c.alpha, 1);
    INFO(c.kind << " a=" << c.a << " b=" << c.b << " R=" << c.R << " alpha=" << c.alpha);
    REQUIRE(q2.converged);
    const double L = std::max(c.a, c.b);
    CHECK(std::fabs(q1.wrench.fx - q2.wrench.fx) <= 1e-11);
    CHECK(std::fabs(q1.wrench.fy - q2.wrench.fy) <= 1e-11);
    CHECK(std::fabs(q1.wrench.mf - q2.wrench.mf) <= 1e-11 * L);
    CHECK(std::fabs(w.fx - q2.wrench.fx) <= 1e-11);
    CHECK(std::fabs(w.fy - q2.wrench.fy) <= 1e-11);
    CHECK(std::fabs(w.mf - q2.wrench.mf) <= 1e-11 * L);
  }
}

TEST_CASE("friction: cubature for non-uniform pressure", "[friction][numeric]") {
  const double a = 27.5e-9, b = 50e-9;
  SECTION("a pressure symmetric about the CM gives f = 0 at R = 0 and mf = -muN <r>_p") {
    auto p = [&](double x, double y) { return 1.0 + 0.8 * (x * x / (a * a)) * (y * y / (b * b)); };
    const auto q = cubature_friction_wrench(a, b, 2.0, 0.0, 0.3, 1, p, 1e-12);
    REQUIRE(q.converged);
    CHECK(std::fabs(q.wrench.fx) <= 1e-11 * 2.0);
    CHECK(std::fabs(q.wrench.fy) <= 1e-11 * 2.0);
    CHECK(q.wrench.mf < 0.0);
  }
  SECTION("far iCOR: any pressure gives the translation limit, to O(max(a,b)/R)") {
    auto p = [&](double x, double y) { return std::exp(x / a) * (2.0 + std::sin(y / b)); };
    const double alpha = 0.7;
    const auto q = cubature_friction_wrench(a, b, 1.0, 1e7 * b, alpha, -1, p, 1e-13);
    REQUIRE(q.converged);
    // An asymmetric pressure moves the centre of pressure by O(L) from the CM, which turns the
    // sliding direction there by O(L/R) = 1e-7: the limit is approached at first order.
    CHECK(q.wrench.fx == Approx(-std::sin(alpha)).margin(2e-7));
    CHECK(q.wrench.fy == Approx(std::cos(alpha)).margin(2e-7));
    CHECK(std::hypot(q.wrench.fx, q.wrench.fy) == Approx(1.0).margin(1e-13));
  }
  SECTION("pressure that vanishes on one half equals the closed form of the other half") {
    // p = 1 on x' > 0, 0 on x' < 0: the right half is a rectangle of half-width a/2 centred at
    // x' = a/2; its iCOR offset is shifted by a/2. (The step sits on the iCOR break line x' = 0
    // when the iCOR is at x' = 0, so choose such iCORs.)
    auto p = [](double x, double) { return x > 0.0 ? 1.0 : 0.0; };
    for (double cy : {-0.7 * b, 0.0, 0.3 * b, 2.0 * b}) {
      const double R = std::fabs(cy), alpha = cy > 0 ? -kPi / 2 : kPi / 2;  // iCOR at (0, cy)
      const auto q = cubature_friction_wrench(a, b, 1.0, R, alpha, 1, p, 1e-12);
      // Half rectangle: centre (a/2, 0); iCOR relative to its centre: (-a/2, cy).
      const double Rh = std::hypot(a / 2, cy), alh = std::atan2(-cy, a / 2);
      const auto h = rectangle_friction_wrench(a / 2, b, 1.0, Rh, alh, 1);
      // Moment about the full CM = moment about the half's centre + (a/2, 0) x f.
      const double mf_cm = h.mf + (a / 2) * h.fy;
      INFO("cy=" << cy);
      REQUIRE(q.converged);
      CHECK(q.wrench.fx == Approx(h.fx).margin(1e-11));
      CHECK(q.wrench.fy == Approx(h.fy).margin(1e-11));
      CHECK(q.wrench.mf == Approx(mf_cm).margin(1e-11 * b));
    }
  }
}

TEST_CASE("friction: joins the translation limit smoothly for R/max(a,b) from 1e2 to 1e15",
          "[friction][numeric]") {
  const double muN = 1.0;
  for (double aspect : {1.0, 0.55, 0.1}) {
    const double a = 27.5e-9 * aspect / 0.55 * 0.55, b = 50e-9;
    const double L = std::max(a, b);
    for (double alpha : {0.0, 0.3, kPi / 4, 1.2, kPi / 2, 2.9, -2.0}) {
      for (int sense : {1, -1}) {
        std::mt19937_64 rng(42);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        std::vector<double> rhos;
        for (int i = 0; i <= 2600; ++i) rhos.push_back(std::pow(10.0, 2.0 + 13.0 * i / 2600.0));
        for (double k : {kFrictionGl4From, kFrictionAsymptotic}) rhos.push_back(k);
        double worst_jump_f = 0.0, worst_jump_m = 0.0;
        for (double rho : rhos) {
          const double R = rho * L;
          // Neighbouring R, 2e-14 apart: the true change is <= 2e-14 relative (mf ~ 1/R), so a
          // difference above 1e-13 is a jump.
          const double R2 = R * (1.0 + 1e-14);
          const double Rm = R * (1.0 - 1e-14);
          const auto w1 = rectangle_friction_wrench(a, b, muN, Rm, alpha, sense);
          const auto w2 = rectangle_friction_wrench(a, b, muN, R2, alpha, sense);
          const double jf = std::hypot(w1.fx - w2.fx, w1.fy - w2.fy) / muN;
          const double jm = std::fabs(w1.mf - w2.mf) / std::fabs(w2.mf);
          worst_jump_f = std::max(worst_jump_f, jf);
          worst_jump_m = std::max(worst_jump_m, jm);
          // Limits: |f| -> muN like (L/R)^2; mf ~ -muN s (a^2 sin^2 + b^2 cos^2)/(3R) (1 + O((L/R)^2)).
          const double fmag = std::hypot(w2.fx, w2.fy);
          CHECK(std::fabs(fmag / muN - 1.0) <= 1.0 / (rho * rho) + 4e-16);
          CHECK(w2.fx == Approx(muN * sense * std::sin(alpha)).margin(1.0 / (rho * rho) + 4e-16));
          CHECK(w2.fy == Approx(-muN * sense * std::cos(alpha)).margin(1.0 / (rho * rho) + 4e-16));
          const double s = std::sin(alpha), c = std::cos(alpha);
          const double mf_asym = -muN * sense * (a * a * s * s + b * b * c * c) / (3.0 * R2);
          CHECK(std::fabs(w2.mf - mf_asym) <= std::fabs(mf_asym) * (2.0 / (rho * rho) + 1e-14));
          CHECK(std::fabs(w2.mf) <= muN * L / rho);
        }
        INFO("aspect " << aspect << " alpha " << alpha << " sense " << sense);
        CHECK(worst_jump_f <= 1e-13);
        CHECK(worst_jump_m <= 1e-13);
      }
    }
  }
}

TEST_CASE("friction: no jump where the evaluation form switches", "[friction][numeric]") {
  // Relative to muN (force) and muN max(a,b) (moment) at the closed-form/far-field switch;
  // relative to |mf| itself at the far-field/asymptotic switch.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const double a = std::pow(10.0, -1.3 * u(rng)), b = std::pow(10.0, -1.3 * u(rng));
    const double L = std::max(a, b), alpha = 2 * kPi * u(rng);
    for (double k : {kFrictionFarField, kFrictionGl8From, kFrictionGl6From, kFrictionGl4From, kFrictionAsymptotic}) {
      const double lo = k * L * (1 - 1e-15), hi = k * L * (1 + 1e-15);
      REQUIRE(rectangle_friction_form(a, b, lo) != rectangle_friction_form(a, b, hi));
      const auto w1 = rectangle_friction_wrench(a, b, 1.0, lo, alpha, 1);
      const auto w2 = rectangle_friction_wrench(a, b, 1.0, hi, alpha, 1);
      INFO("a=" << a << " b=" << b << " alpha=" << alpha << " switch " << k);
      CHECK(std::hypot(w1.fx - w2.fx, w1.fy - w2.fy) <= 1e-14);
      const double mscale = (k == kFrictionFarField) ? L : std::fabs(w2.mf);
      CHECK(std::fabs(w1.mf - w2.mf) <= 1e-13 * mscale);
    }
  }
}

TEST_CASE("friction: rotation about the CM (R = 0) oracle", "[friction][unit]") {
  for (double s : {1e-9, 100e-9, 3.0}) {
    for (int sense : {1, -1}) {
      const double muN = 0.37;
      const auto w = rectangle_friction_wrench(s / 2, s / 2, muN, 0.0, 0.9, sense);
      CHECK(w.fx == 0.0);
      CHECK(w.fy == 0.0);
      const double mean_r = s * (std::sqrt(2.0) + std::log(1.0 + std::sqrt(2.0))) / 6.0;
      CHECK(w.mf == Approx(-sense * muN * mean_r).epsilon(4e-16));
    }
  }
  // Rectangle: mean distance from the centre (closed form from the literature:
  // <r> = [d/3 + a^2/(6b) ln((b + d)/a) + b^2/(6a) ln((a + d)/b)], d = sqrt(a^2 + b^2)).
  for (auto [a, b] : {std::pair{27.5e-9, 50e-9}, std::pair{1.0, 0.01}, std::pair{3.0, 2.0}}) {
    const double d = std::hypot(a, b);
    const double mean_r = d / 3 + a * a / (6 * b) * std::log((b + d) / a) + b * b / (6 * a) * std::log((a + d) / b);
    const auto w = rectangle_friction_wrench(a, b, 1.0, 0.0, 0.0, 1);
    // The corner form loses log10(max/min) digits across a thin rectangle (friction.hpp).
    CHECK(w.mf == Approx(-mean_r).epsilon(1e-15 * std::max(a, b) / std::min(a, b)));
  }
}

TEST_CASE("friction: dissipation f.v + mf omega = -muN |omega| <r> <= 0 over a dense sweep",
          "[friction][numeric]") {
  const double a = 27.5e-9, b = 50e-9, muN = 2.3e-6;
  int checked = 0;
  for (int i = 0; i <= 60; ++i) {
    const double R = (i == 0) ? 0.0 : b * std::pow(10.0, -4.0 + 14.0 * (i - 1) / 59.0);
    for (int k = 0; k < 72; ++k) {
      const double alpha = 2 * kPi * k / 72.0;
      for (double omega : {3.1e6, -0.2}) {
        const int sense = omega > 0 ? 1 : -1;
        const auto w = rectangle_friction_wrench(a, b, muN, R, alpha, sense);
        const double xc = R * std::cos(alpha), yc = R * std::sin(alpha);
        const double vx = -omega * yc, vy = omega * xc;  // CM velocity = omega z x (CM - iCOR)
        const double P = w.fx * vx + w.fy * vy + w.mf * omega;
        CHECK(P <= 0.0);
        // Same wrench through the velocity interface.
        const auto wv = rectangle_friction_from_velocity(a, b, muN, vx, vy, omega);
        const double L = b;
        CHECK(wv.fx == Approx(w.fx).margin(1e-13 * muN));
        CHECK(wv.fy == Approx(w.fy).margin(1e-13 * muN));
        CHECK(wv.mf == Approx(w.mf).margin(1e-13 * muN * L));
        ++checked;
      }
    }
  }
  CHECK(checked == 61 * 72 * 2);
  // Power balance against the cubature: P = -muN |omega| <r>, <r> = mean distance to the iCOR.
  for (double R : {0.0, 10e-9, 40e-9, 200e-9}) {
    const double alpha = 0.4, omega = -5.0;
    const auto w = rectangle_friction_wrench(a, b, muN, R, alpha, -1);
    const double xc = R * std::cos(alpha), yc = R * std::sin(alpha);
    auto q = cubature_friction_wrench(
        a, b, 1.0, R, alpha, 1, [](double, double) { return 1.0; }, 1e-12);
    (void)q;
    // <r> by cubature: integrate r directly.
    auto rr = nanopush::cubature::integrate_rectangle<1>(
        [&](double x, double y, double* o) { o[0] = std::hypot(xc + x, yc + y); }, -a, a, -b, b, {-xc}, {-yc},
        1e-13 * 4 * a * b * b);
    const double mean_r = rr.value[0] / (4 * a * b);
    const double P = w.fx * (-omega * yc) + w.fy * (omega * xc) + w.mf * omega;
    CHECK(P == Approx(-muN * std::fabs(omega) * mean_r).epsilon(1e-12));
  }
}

TEST_CASE("friction: velocity interface joins pure translation as omega -> 0", "[friction][unit]") {
  const double a = 27.5e-9, b = 50e-9, muN = 1.0;
  const double vx = 3e-3, vy = -4e-3;
  const auto t = rectangle_friction_translation(muN, vx, vy);
  CHECK(t.fx == Approx(-0.6).epsilon(1e-15));
  CHECK(t.fy == Approx(0.8).epsilon(1e-15));
  CHECK(t.mf == 0.0);
  auto w0 = rectangle_friction_from_velocity(a, b, muN, vx, vy, 0.0);
  CHECK(w0.fx == t.fx);
  CHECK(w0.fy == t.fy);
  CHECK(w0.mf == 0.0);
  double prev_mf = 0.0;
  for (double om : {1e-300, 1e-30, 1e-10, 1e-3, 1.0, 1e3}) {
    const auto w = rectangle_friction_from_velocity(a, b, muN, vx, vy, om);
    const double rho = std::hypot(vx, vy) / om / b;
    CHECK(std::fabs(w.fx - t.fx) <= 1.0 / (rho * rho) + 2e-16);
    CHECK(std::fabs(w.fy - t.fy) <= 1.0 / (rho * rho) + 2e-16);
    CHECK(w.mf <= 0.0);
    CHECK(std::fabs(w.mf) >= std::fabs(prev_mf));
    prev_mf = w.mf;
    const auto wn = rectangle_friction_from_velocity(a, b, muN, vx, vy, -om);
    CHECK(wn.mf == Approx(-w.mf).margin(1e-300));
  }
  const auto rest = rectangle_friction_from_velocity(a, b, muN, 0.0, 0.0, 0.0);
  CHECK(rest.fx == 0.0);
  CHECK(rest.fy == 0.0);
  CHECK(rest.mf == 0.0);
  const auto spin = rectangle_friction_from_velocity(a, b, muN, 0.0, 0.0, 2.0);
  const auto r0 = rectangle_friction_wrench(a, b, muN, 0.0, 0.0, 1);
  CHECK(spin.fx == 0.0);
  CHECK(spin.mf == r0.mf);
}

TEST_CASE("friction: no NaN or Inf for any finite input", "[friction][unit]") {
  const double big = DBL_MAX, tiny = std::numeric_limits<double>::denorm_min();
  const std::vector<double> lengths = {1e-300, 1e-9, 1.0, 1e300};
  const std::vector<double> aspects = {1.0, 0.3, kFrictionMinAspect};
  const std::vector<double> radii = {0.0, tiny, 1e-300, 1e-9, 1.0, 3.0, 1e20, 1e300, big};
  const std::vector<double> angles = {0.0, 1e-300, kPi / 2, kPi, -kPi / 4, 1e10, 1e300, -big};
  int n = 0;
  for (double L : lengths)
    for (double asp : aspects)
      for (double Rf : radii)
        for (double al : angles)
          for (int sense : {1, -1}) {
            const double a = L * asp, b = L;
            for (double R : {Rf, Rf * L, L * asp}) {
              if (!std::isfinite(R)) continue;
              const auto w = rectangle_friction_wrench(a, b, 1.0, R, al, sense);
              INFO("a=" << a << " b=" << b << " R=" << R << " alpha=" << al);
              CHECK(std::isfinite(w.fx));
              CHECK(std::isfinite(w.fy));
              CHECK(std::isfinite(w.mf));
              CHECK(std::hypot(w.fx, w.fy) <= 1.0 + 1e-12);
              const auto ws = rectangle_friction_wrench(b, a, 1.0, R, al, sense);
              CHECK((std::isfinite(ws.fx) && std::isfinite(ws.fy) && std::isfinite(ws.mf)));
              ++n;
            }
          }
  const std::vector<double> vel = {0.0, tiny, -1e-300, 1e-3, -7.0, 1e300, big, -big};
  for (double L : lengths)
    for (double vx : vel)
      for (double vy : vel)
        for (double om : vel) {
          const auto w = rectangle_friction_from_velocity(0.55 * L, L, 1.0, vx, vy, om);
          INFO("L=" << L << " v=(" << vx << "," << vy << ") omega=" << om);
          CHECK(std::isfinite(w.fx));
          CHECK(std::isfinite(w.fy));
          CHECK(std::isfinite(w.mf));
          const auto t = rectangle_friction_translation(1.0, vx, vy);
          CHECK((std::isfinite(t.fx) && std::isfinite(t.fy)));
          ++n;
        }
  CHECK(n > 1000);
}

TEST_CASE("friction: bad input gets a clear error", "[friction][unit]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  using Catch::Matchers::Contains;
  REQUIRE_THROWS_WITH(rectangle_friction_wrench_checked(0.0, 1.0, 1.0, 1.0, 0.0, 1), Contains("a = 0") && Contains("> 0"));
  REQUIRE_THROWS_WITH(rectangle_friction_wrench_checked(-1.0, 1.0, 1.0, 1.0, 0.0, 1), Contains("a = -1"));
  REQUIRE_THROWS_WITH(rectangle_friction_wrench_checked(1.0, nan, 1.0, 1.0, 0.0, 1), Contains("b = nan"));
  REQUIRE_THROWS_WITH(rectangle_friction_wrench_checked(1.0, 1.0, 1.0, inf, 0.0, 1), Contains("R = inf") && Contains("finite"));
  REQUIRE_THROWS_WITH(rectangle_friction_wrench_checked(1.0, 1.0, 1.0, -2.0, 0.0, 1), Contains("R = -2") && Contains(">= 0"));
  REQUIRE_THROWS_WITH(rectangle_friction_wrench_checked(1.0, 1.0, 1.0, nan, 0.0, 1), Contains("R = nan"));
  REQUIRE_THROWS_WITH(rectangle_friction_wrench_checked(1.0, 1.0, 1.0, 1.0, inf, 1), Contains("alpha = inf"));
  REQUIRE_THROWS_WITH(rectangle_friction_wrench_checked(1.0, 1.0, -1.0, 1.0, 0.0, 1), Contains("muN = -1"));
  REQUIRE_THROWS_WITH(rectangle_friction_wrench_checked(1.0, 1.0, 1.0, 1.0, 0.0, 0), Contains("sense = 0"));
  REQUIRE_THROWS_WITH(rectangle_friction_wrench_checked(1.0, 1e-13, 1.0, 1.0, 0.0, 1), Contains("aspect ratio"));
  REQUIRE_THROWS_AS(rectangle_friction_from_velocity_checked(1.0, 1.0, 1.0, nan, 0.0, 1.0), InputError);
  REQUIRE_THROWS_WITH(rectangle_friction_from_velocity_checked(1.0, 1.0, 1.0, 0.0, 0.0, inf), Contains("omega = inf"));
  REQUIRE_THROWS_WITH(rectangle_friction_translation_checked(1.0, 1.0, -inf), Contains("vy = -inf"));
  REQUIRE_THROWS_AS(cubature_friction_wrench_uniform(0.0, 1.0, 1.0, 1.0, 0.0, 1), InputError);
  REQUIRE_THROWS_AS(cubature_friction_wrench(1.0, 1.0, 1.0, 1.0, 0.0, 1, [](double, double) { return 0.0; }),
                    InputError);
  // Good input passes through unchanged.
  const auto w = rectangle_friction_wrench_checked(0.3, 0.7, 1.0, 0.5, 0.9, 1);
  const auto u = rectangle_friction_wrench(0.3, 0.7, 1.0, 0.5, 0.9, 1);
  CHECK(w.fx == u.fx);
  CHECK(w.mf == u.mf);
}

TEST_CASE("friction: cubature rule is exact for polynomials of degree 22 (GK15)", "[friction][unit]") {
  for (int d = 0; d <= 22; ++d) {
    auto r = nanopush::cubature::integrate<1>(
        [d](double x, double* o) { o[0] = std::pow(x, d); }, -1.0, 1.0, {}, 1e300);
    const double exact = (d % 2 == 0) ? 2.0 / (d + 1) : 0.0;
    CHECK(r.value[0] == Approx(exact).margin(1e-15));
  }
}

TEST_CASE("friction: velocity interface matches the definition f = -mu p v/|v| integrated directly",
          "[friction][numeric]") {
  // Independent of the iCOR parametrisation: integrate -muN/(4ab) v(x)/|v(x)| with
  // v(x) = v + omega z x x (body axes) and its moment about the CM, by nested cubature with
  // break points at the point of zero velocity.
  const double a = 27.5e-9, b = 50e-9, muN = 1.3;
  struct V {
    double vx, vy, om;
  };
  for (const V& c : {V{1e-3, 0.0, 3e4}, V{-2e-3, 5e-4, -1e5}, V{0.0, 1e-3, 2e4}, V{3e-3, -1e-3, 1e3},
                     V{1e-4, 1e-4, -5e5}, V{0.0, 0.0, 7.0}}) {
    const double cx = -c.vy / c.om, cy = c.vx / c.om;  // zero-velocity point (docs/models.md §0)
    auto g = [&](double x, double y, double* out) {
      const double ux = c.vx - c.om * y, uy = c.vy + c.om * x;
      const double s = std::hypot(ux, uy);
      const double fx = s > 0 ? -ux / s : 0.0, fy = s > 0 ? -uy / s : 0.0;
      out[0] = fx;
      out[1] = fy;
      out[2] = x * fy - y * fx;
    };
    auto r = nanopush::cubature::integrate_rectangle<3>(g, -a, a, -b, b, {cx}, {cy}, 1e-13 * 4 * a * b, 4000);
    REQUIRE(r.converged);
    const double A = 4 * a * b;
    const auto w = rectangle_friction_from_velocity(a, b, muN, c.vx, c.vy, c.om);
    INFO("v=(" << c.vx << "," << c.vy << ") omega=" << c.om);
    CHECK(w.fx == Approx(muN * r.value[0] / A).margin(1e-11 * muN));
    CHECK(w.fy == Approx(muN * r.value[1] / A).margin(1e-11 * muN));
    CHECK(w.mf == Approx(muN * r.value[2] / A).margin(1e-11 * muN * b));
  }
}

TEST_CASE("friction: thin contacts down to the aspect-ratio limit vs cubature", "[friction][numeric]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst_f = 0.0, worst_m = 0.0;
  for (int i = 0; i < 600; ++i) {
    const double thin = std::max(kFrictionMinAspect, std::pow(10.0, -12.5 * u(rng)));
    const double a = (i % 2) ? 1e-7 : 1e-7 * thin, b = (i % 2) ? 1e-7 * thin : 1e-7;
    const double L = std::max(a, b);
    const double R = (i % 3 == 0) ? L * u(rng) : L * std::pow(10.0, 2.0 * u(rng) - 1.0);
    const double alpha = 2 * kPi * u(rng);
    const auto w = rectangle_friction_wrench(a, b, 1.0, R, alpha, 1);
    const auto q = cubature_friction_wrench_uniform(a, b, 1.0, R, alpha, 1, 1e-13);
    INFO("a=" << a << " b=" << b << " R=" << R << " alpha=" << alpha);
    REQUIRE(q.converged);
    const double ef = std::hypot(w.fx - q.wrench.fx, w.fy - q.wrench.fy) / std::hypot(q.wrench.fx, q.wrench.fy);
    const double em = std::fabs(w.mf - q.wrench.mf) / L;
    CHECK(ef <= 1e-10);
    CHECK(em <= 1e-10);
    worst_f = std::max(worst_f, ef);
    worst_m = std::max(worst_m, em);
  }
  WARN("thin contacts: worst relative |df| " << worst_f << ", worst |dmf|/(muN L) " << worst_m);
}

TEST_CASE("friction: the plain corner sum loses digits on thin contacts; the stable difference does not",
          "[friction][numeric]") {
  // Evidence for the thin-side rearrangement in closed_form (docs/friction.md, "Thin contacts").
  const double a = 1.0, b = 1e-8, alpha = 0.7, R = 1.5;
  const double xc = R * std::cos(alpha), yc = R * std::sin(alpha);
  const auto q = cubature_friction_wrench_uniform(a, b, 1.0, R, alpha, 1, 1e-14);
  REQUIRE(q.converged);
  const auto plain = friction_detail::closed_form_corner_sum(a, b, xc, yc);
  const auto stable = friction_detail::closed_form(a, b, xc, yc);
  // fx' = muN <Y/r> for sense +1.
  CHECK(std::fabs(plain.iy - q.wrench.fx) > 1e-10);
  CHECK(std::fabs(stable.iy - q.wrench.fx) <= 1e-14);
  CHECK(std::fabs(-stable.km - q.wrench.mf) <= 1e-14);
}

// The wrench as a function of the iCOR c is C^1 everywhere, but where c crosses an edge of
// the contact its second derivatives have a logarithmic singularity (F = -grad of the
// integral of |r - c| over the contact: the third derivatives of that integral are
// log-singular on the boundary). An integrator stepping over such an instant loses order
// there (docs/rough.md, "Where the friction is not smooth"). Measured with central
// differences across the edge x' = a at c_y' = 0.3 b: the first difference converges, the
// second grows by the same amount per decade of the spacing (a log), while at points 0.5 a
// inside and outside the edge both converge.
TEST_CASE("friction: C^1 but log-singular second derivative where the iCOR crosses an edge",
          "[friction][numeric]") {
  const double a = 27.5e-9, b = 50e-9;
  // body velocity with omega = 1: iCOR c = (-vy, vx) = (a + s, 0.3 b)
  const auto F = [&](double s) { return rectangle_friction_from_velocity(a, b, 1.0, 0.3 * b, -(a + s), 1.0); };
  struct Diffs {
    double d1[3], d2[3];
  };
  const auto diffs = [&](double s0, double d) {
    const FrictionWrench p = F(s0 + d), z = F(s0), m = F(s0 - d);
    const double sc[3] = {a, a, 1.0};  // fx, fy per unit s/a; mf [N m] per unit s/a is already x a
    const double fp[3] = {p.fx, p.fy, p.mf}, fz[3] = {z.fx, z.fy, z.mf}, fm[3] = {m.fx, m.fy, m.mf};
    Diffs r{};
    for (int i = 0; i < 3; ++i) {
      r.d1[i] = (fp[i] - fm[i]) / (2 * d) * sc[i];
      r.d2[i] = (fp[i] - 2 * fz[i] + fm[i]) / (d * d) * sc[i] * a;
    }
    return r;
  };
  for (const double s0 : {0.0, -0.5 * a, 0.5 * a}) {
    const Diffs h3 = diffs(s0, 1e-3 * a), h4 = diffs(s0, 1e-4 * a), h5 = diffs(s0, 1e-5 * a);
    for (int i = 0; i < 3; ++i) {
      INFO("s0/a " << s0 / a << " component " << i << ": d1 " << h3.d1[i] << " " << h4.d1[i] << ", d2 " << h3.d2[i]
                   << " " << h4.d2[i] << " " << h5.d2[i]);
      CHECK(std::fabs(h4.d1[i] - h3.d1[i]) <= 1e-5 * (std::fabs(h3.d1[i]) + 1e-3));  // C^1 everywhere
      const double inc1 = h4.d2[i] - h3.d2[i], inc2 = h5.d2[i] - h4.d2[i];
      if (s0 != 0.0 || i == 0) {
        // away from the edge (and fx, which the edge crossing x' = a leaves smooth here):
        // the second difference converges
        CHECK(std::fabs(inc1) <= 1e-4);
        CHECK(std::fabs(inc2) <= 1e-4);
      } else {
        // on the edge: the same increment per decade, ~ ln(10) times the log's coefficient
        CHECK(std::fabs(inc1) >= 0.1);
        CHECK(inc2 == Approx(inc1).epsilon(0.01));
      }
    }
  }
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
