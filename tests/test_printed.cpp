// The `printed` friction law (docs/rough.md): eqs 3.45-3.48 exactly as the thesis prints them,
// in both engines.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "f77_rough.h"
#include "nanopush/engines/engines.hpp"
#include "nanopush/models/friction.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "support/support.hpp"

using namespace nanopush;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

Scene preset(int fig) { return nanopush::test::thesis_preset(fig); }

// Faithful unless asked: these tests compare the two engines step for step (the presets' own
// method is auto).
Trajectory run(const Scene& sc, const std::string& engine, const std::string& law,
               const std::string& method = "faithful") {
  RunSettings s;
  s.engine = parse_optional_choice<Engine>("engine", engine);
  s.law = parse_optional_choice<Law>("law", law);
  s.method = parse_optional_choice<Method>("method", method);
  return run_engine(sc, s);
}

// Body-axis velocity whose iCOR sits at c = -R (cos alpha, sin alpha) with sense s (friction.hpp).
struct Vel {
  double vx, vy, om;
};
Vel velocity_for(double R, double alpha, int sense) {
  const double om = sense * 1e9;
  // -c = (vy, -vx)/omega = R (cos, sin)  =>  vy = omega R cos, vx = -omega R sin
  return {-om * R * std::sin(alpha), om * R * std::cos(alpha), om};
}

}  // namespace

TEST_CASE("Printed law: the C++ and F77 right-hand sides are bit-identical", "[printed][crosslang][regression]") {
  const Scene sc = preset(29);
  const RoughBarModel m = rough_model(sc);
  double params[12] = {m.mass, m.inertia, m.push.force, m.push.beta, m.push.pbx, m.push.pby,
                       m.geometry.a, m.geometry.b, m.muN, 0.0, 0.0, 0.0};
  RoughBarModel mp = m;
  mp.printed = true;
  const RoughBarThesisRhs rhs{mp};
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int k = 0; k < 4000; ++k) {
    double y[8] = {0, 0, 3 * u(rng), 1e3 * u(rng), 1e3 * u(rng), 1e11 * u(rng), 0, 0};
    if (k % 4 == 1) y[5] = 0.0;  // translation
    if (k % 4 == 2) {            // iCOR on an edge line of the contact: h1 = 0 (R sin alpha = b)
      const double alpha = 0.3 + u(rng), R = m.geometry.b / std::sin(alpha);
      const Vel v = velocity_for(R, alpha, k % 8 < 4 ? 1 : -1);
      const double c = std::cos(y[2]), s = std::sin(y[2]);
      y[3] = c * v.vx - s * v.vy;
      y[4] = s * v.vx + c * v.vy;
      y[5] = v.om;
    }
    double dc[8], df[8];
    rhs(0.0, y, dc);
    REQUIRE(np_f77_rough_bar_rhs_law(0.0, y, df, params, 1) == 0);
    for (int i = 0; i < 8; ++i) {
      INFO("state " << k << " component " << i);
      REQUIRE(std::isfinite(dc[i]));
      CHECK(dc[i] == df[i]);
    }
    ++checked;
  }
  CHECK(checked == 4000);
  // law 0 of the new entry point is the thesis law, bit for bit, as the faithful method
  // evaluates it (the F77 routine's friction forms; the production forms round differently).
  RoughBarModel mf = m;
  mf.f77_forms = true;
  const RoughBarThesisRhs th{mf};
  double y[8] = {0, 0, 0.4, 2.0, -1.0, 3e9, 0, 0}, dc[8], df[8];
  th(0.0, y, dc);
  REQUIRE(np_f77_rough_bar_rhs_law(0.0, y, df, params, 0) == 0);
  for (int i = 0; i < 8; ++i) CHECK(dc[i] == df[i]);
}

TEST_CASE("Printed wrench: the literal transcription of (3.45)-(3.48), with and without the sense", "[printed][unit]") {
  // Oracle: thesis_printed_friction (tests/test_friction_errata.cpp's literal transcription,
  // muN = 1, s = +1, any unit of length: evaluated here in nanometres as the law is).
  const double a = 27.5e-9, b = 50e-9, muN = 3e-6, nm = kPrintedLengthUnit;
  for (double R : {0.3e-9, 10e-9, 40e-9, 120e-9, 1e-6}) {
    for (double alpha : {0.1, 1.0, 2.5, -2.0}) {
      const FrictionWrench lit = thesis_printed_friction(a / nm, b / nm, R / nm, alpha);
      const FrictionWrench cor = rectangle_friction_wrench(a, b, muN, R, alpha, 1);
      for (int sense : {1, -1}) {
        const Vel v = velocity_for(R, alpha, sense);
        const FrictionWrench p = thesis_printed_friction_from_velocity(a, b, muN, v.vx, v.vy, v.om);
        INFO("R " << R << " alpha " << alpha << " sense " << sense);
        const double tol = 1e-9 * muN;
        CHECK(std::fabs(p.fx - sense * muN * lit.fx) <= tol);
        CHECK(std::fabs(p.fy - sense * muN * lit.fy) <= tol);
        CHECK(std::fabs(p.mf - muN * nm * lit.mf) <= 1e-9 * muN * b);  // no sign(theta-dot): F3
        // (3.45) is right; (3.46) has the opposite sign of the exact wrench (F1).
        CHECK(std::fabs(p.fx - sense * cor.fx) <= tol);
        CHECK(std::fabs(p.fy + sense * cor.fy) <= tol);
      }
    }
  }
}

TEST_CASE("Printed wrench on the edge lines: finite, the limit of its neighbours", "[printed][unit]") {
  // The printed logarithms are undefined where an h_i vanishes (errata F4); the law takes the
  // term h^2 ln(...) as its limit 0 there, so the wrench is continuous across the line.
  const double a = 27.5e-9, b = 50e-9, muN = 1e-6;
  CHECK(std::isnan(thesis_printed_friction(a / 1e-9, b / 1e-9, b / 1e-9, M_PI / 2).fx +
                   thesis_printed_friction(a / 1e-9, b / 1e-9, b / 1e-9, M_PI / 2).mf));
  struct Line {
    double R, alpha;  // a point on the line
  };
  // h1 = 0 (R sin alpha = b), h2 = 0 (R cos alpha = -a), a corner (h1 = h4 = 0), the CM (R = 0).
  for (const Line& l : {Line{b / std::sin(0.9), 0.9}, Line{a / std::cos(0.6), M_PI - 0.6},
                        Line{std::hypot(a, b), std::atan2(b, a)}, Line{0.0, 0.0}}) {
    for (int sense : {1, -1}) {
      const Vel v = velocity_for(l.R, l.alpha, sense);
      const FrictionWrench w0 = thesis_printed_friction_from_velocity(a, b, muN, v.vx, v.vy, v.om);
      INFO("R " << l.R << " alpha " << l.alpha << " sense " << sense);
      REQUIRE(std::isfinite(w0.fx));
      REQUIRE(std::isfinite(w0.fy));
      REQUIRE(std::isfinite(w0.mf));
      double prev = 1e300;
      for (double d : {1e-3, 1e-5, 1e-7}) {  // approach along R, relative step d
        const Vel w = velocity_for(l.R * (1 + d) + d * b, l.alpha, sense);
        const FrictionWrench wd = thesis_printed_friction_from_velocity(a, b, muN, w.vx, w.vy, w.om);
        const double diff = std::max({std::fabs(wd.fx - w0.fx), std::fabs(wd.fy - w0.fy)}) / muN +
                            std::fabs(wd.mf - w0.mf) / (muN * b);
        CHECK(diff < prev);  // converges to the value on the line
        prev = diff;
      }
      CHECK(prev < 1e-5);
    }
  }
}

TEST_CASE("Printed law reduces to the thesis law where the sign slips cannot act", "[printed][numeric]") {
  // The slips act through omega: F1 and F2 change the wrench only at a finite iCOR, F3 only
  // when omega < 0. At omega = 0 (R = infinity) both laws are pure translation, f = -muN v/|v|
  // and mf = 0, so a bar pushed through its CM translates identically under both, bit for bit.
  Scene sc = preset(18);
  sc.set("push.yn", 0.0);
  const Trajectory th = run(sc, "cxx", "thesis"), pr = run(sc, "cxx", "printed");
  REQUIRE(th.complete);
  REQUIRE(pr.complete);
  REQUIRE(th.rows.size() == pr.rows.size());
  for (std::size_t i = 0; i < th.rows.size(); ++i)
    for (std::size_t c = 0; c < th.rows[i].size(); ++c) REQUIRE(th.rows[i][c] == pr.rows[i][c]);
  CHECK(th.rows.back()[3] == 0.0);  // no rotation
  // mu = 0: no friction at all under either law.
  const Scene s0 = preset(12);
  const Trajectory t0 = run(s0, "f77", "thesis"), p0 = run(s0, "f77", "printed");
  REQUIRE(t0.rows.size() == p0.rows.size());
  for (std::size_t i = 0; i < t0.rows.size(); ++i) CHECK(t0.rows[i][3] == p0.rows[i][3]);
}

TEST_CASE("Printed law on fig3_18 and fig3_29: both engines identical, two-signed fx, 1.6 ns",
          "[printed][crosslang][regression]") {
  for (int fig : {18, 29}) {
    const Scene sc = preset(fig);
    const Trajectory c = run(sc, "cxx", "printed"), f = run(sc, "f77", "printed");
    INFO("fig3_" << fig);
    REQUIRE(c.complete);
    REQUIRE(f.complete);
    CHECK(c.engine_label == "cxx-faithful-printed");
    CHECK(f.engine_label == "f77-printed");
    CHECK(c.stats.nfcn == f.stats.nfcn);
    CHECK(c.stats.naccpt == f.stats.naccpt);
    CHECK(c.stats.nrejct == f.stats.nrejct);
    REQUIRE(c.rows.size() == f.rows.size());
    for (std::size_t i = 0; i < c.rows.size(); ++i)
      for (std::size_t k = 0; k < c.rows[i].size(); ++k) REQUIRE(c.rows[i][k] == f.rows[i][k]);
    CHECK(c.rows.back()[0] == Approx(1.6e-9).epsilon(1e-12));
    double fmin = 0, fmax = 0;
    for (const auto& r : c.rows) {
      fmin = std::min(fmin, r[7]);
      fmax = std::max(fmax, r[7]);
    }
    const double muN = sc.surface.mu * sc.normal_load();
    CHECK(fmin < -0.3 * muN);  // the "clock signal": fx takes both signs
    CHECK(fmax > 0.3 * muN);
  }
}

TEST_CASE("Printed law adds energy: friction does positive work", "[printed][numeric]") {
  // Errata F1 and F3 let the printed wrench push the bar: the friction power f.v + mf omega is
  // positive at some samples and the work of friction increases (docs/errata.md).
  const Scene sc = preset(18);
  const Trajectory tr = run(sc, "cxx", "printed");
  REQUIRE(tr.complete);
  int positive = 0;
  double wmax = 0;
  for (std::size_t i = 0; i < tr.rows.size(); ++i) {
    const auto& r = tr.rows[i];
    if (r[7] * r[4] + r[8] * r[5] + r[9] * r[6] > 0) ++positive;
    wmax = std::max(wmax, tr.work_fric[i]);
  }
  CHECK(positive > 0);
  CHECK(wmax > 0);
  // The energy balance still holds (the accumulators integrate what the law does).
  const auto ke = [&](const TrajectoryRow& r) {
    return 0.5 * sc.mass * (r[4] * r[4] + r[5] * r[5]) + 0.5 * sc.inertia * r[6] * r[6];
  };
  const auto& last = tr.rows.back();
  CHECK(std::fabs(ke(last) - (tr.work_push.back() + tr.work_fric.back())) <= 1e-7 * tr.work_push.back());
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
