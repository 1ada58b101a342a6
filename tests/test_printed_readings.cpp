// The printed law's readings (docs/rough.md): each of the four slips of eqs 3.45-3.50 printed or
// corrected by one switch, the same in both engines.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

#include "f77_rough.h"
#include "nanopush/engines/engines.hpp"
#include "nanopush/models/friction.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "support/support.hpp"

using namespace nanopush;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

// Body-axis velocity whose iCOR sits at c = -R (cos alpha, sin alpha) with sense s (friction.hpp).
struct Vel {
  double vx, vy, om;
};
Vel velocity_for(double R, double alpha, int sense) {
  const double om = sense * 1e9;
  return {-om * R * std::sin(alpha), om * R * std::cos(alpha), om};
}

PrintedReading flipped(PrintedReading r, int which) {
  if (which == 0) r.fy_sign = !r.fy_sign;
  if (which == 1) r.omega_sign = !r.omega_sign;
  if (which == 2) r.c4_squares = !r.c4_squares;
  if (which == 3) r.eq3_50 = !r.eq3_50;
  return r;
}

Trajectory run_faithful(const Scene& sc, Engine engine) {
  RunSettings s;
  s.engine = engine;
  s.law = Law::printed;
  s.method = Method::faithful;
  s.allow_partial = true;  // a reading that blows up stops the same way in both engines
  s.error_estimate = false;
  return run_engine(sc, s);
}

}  // namespace

TEST_CASE("Printed readings: the index, the names and the words", "[printed][unit]") {
  for (int i = 0; i < 16; ++i) CHECK(printed_reading_index(printed_reading(i)) == i);
  CHECK(printed_reading(0) == PrintedReading{});
  CHECK(printed_reading_named("literal") == PrintedReading{});
  const PrintedReading drawn = *printed_reading_named("as_drawn");
  CHECK(drawn.fy_sign);
  CHECK_FALSE(drawn.omega_sign);
  CHECK_FALSE(drawn.c4_squares);
  CHECK(drawn.eq3_50);
  const PrintedReading corrected = *printed_reading_named("corrected");
  CHECK_FALSE(corrected.fy_sign);
  CHECK_FALSE(corrected.omega_sign);
  CHECK_FALSE(corrected.c4_squares);
  CHECK_FALSE(corrected.eq3_50);
  CHECK_FALSE(printed_reading_named("literally").has_value());
  CHECK(printed_reading_name(drawn) == "as_drawn");
  CHECK(printed_reading_name(printed_reading(9)).empty());
  CHECK(printed_reading_text(PrintedReading{}) == "F1 printed, F3 printed, C4 squares (nm), 3.50 corrected");
}

TEST_CASE("Printed readings: each switch changes exactly its term", "[printed][unit]") {
  // Body axes: F1 negates fy' and nothing else; F3 multiplies mf by sign(omega) and nothing else;
  // C4 changes mf only. World axes (RoughBarModel): eq 3.50 changes fy only, to fx' sin - fy' cos.
  const double a = 27.5e-9, b = 50e-9, muN = 3e-6;
  RoughBarModel m;
  m.geometry = {a, b};
  m.muN = muN;
  m.printed = true;
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int changed_c4 = 0;
  for (int k = 0; k < 400; ++k) {
    const double R = 1e-9 * std::pow(10.0, 2.5 * (u(rng) + 1.0)), alpha = 3.0 * u(rng);
    const int sense = k % 2 == 0 ? 1 : -1;
    const Vel v = velocity_for(R, alpha, sense);
    const PrintedReading base = printed_reading(k % 16);
    const FrictionWrench w = thesis_printed_friction_from_velocity(a, b, muN, v.vx, v.vy, v.om, base);
    INFO("R " << R << " alpha " << alpha << " sense " << sense << " reading " << k % 16);
    REQUIRE(std::isfinite(w.fx + w.fy + w.mf));
    const FrictionWrench f1 = thesis_printed_friction_from_velocity(a, b, muN, v.vx, v.vy, v.om, flipped(base, 0));
    CHECK(f1.fx == w.fx);
    CHECK(f1.fy == -w.fy);
    CHECK(f1.mf == w.mf);
    const FrictionWrench f3 = thesis_printed_friction_from_velocity(a, b, muN, v.vx, v.vy, v.om, flipped(base, 1));
    CHECK(f3.fx == w.fx);
    CHECK(f3.fy == w.fy);
    CHECK(f3.mf == (sense > 0 ? w.mf : -w.mf));
    const FrictionWrench c4 = thesis_printed_friction_from_velocity(a, b, muN, v.vx, v.vy, v.om, flipped(base, 2));
    CHECK(c4.fx == w.fx);
    CHECK(c4.fy == w.fy);
    if (c4.mf != w.mf) ++changed_c4;
    const FrictionWrench e = thesis_printed_friction_from_velocity(a, b, muN, v.vx, v.vy, v.om, flipped(base, 3));
    CHECK(e.fx == w.fx);  // eq 3.50 is not in the body-axis wrench
    CHECK(e.fy == w.fy);
    CHECK(e.mf == w.mf);
    // World axes, at orientation theta: only fy moves under the eq 3.50 switch.
    const double theta = 2.0 * u(rng), c = std::cos(theta), s = std::sin(theta);
    const double vx = c * v.vx - s * v.vy, vy = s * v.vx + c * v.vy;
    m.reading = base;
    const WorldWrench ww = m.friction(theta, vx, vy, v.om);
    m.reading = flipped(base, 3);
    const WorldWrench we = m.friction(theta, vx, vy, v.om);
    CHECK(we.fx == ww.fx);
    CHECK(we.mf == ww.mf);
    // The body-axis wrench the law rotates: the printed forms with squares, the stable Coulomb
    // wrench with the sign slips with cubes (the next test).
    const double vbx = c * vx + s * vy, vby = -s * vx + c * vy;
    const FrictionWrench fb = base.c4_squares ? thesis_printed_friction_from_velocity(a, b, muN, vbx, vby, v.om, base)
                                              : m.printed_slips(m.coulomb_wrench(vbx, vby, v.om), v.om);
    CHECK(ww.fy == (base.eq3_50 ? s * fb.fx - c * fb.fy : s * fb.fx + c * fb.fy));
    CHECK(we.fy == (base.eq3_50 ? s * fb.fx + c * fb.fy : s * fb.fx - c * fb.fy));
  }
  CHECK(changed_c4 > 390);  // squares and cubes differ wherever a corner term is defined
}

TEST_CASE("Printed readings: the corrected reading is the Coulomb wrench of the thesis law", "[printed][numeric]") {
  // Oracle: rectangle_friction_wrench (checked against cubature in test_friction.cpp). With F1-F3
  // corrected the printed logarithmic forms are exact where their logarithms are defined and R is
  // moderate (beyond, they cancel: errata F5).
  const double a = 27.5e-9, b = 50e-9, muN = 3e-6;
  const PrintedReading corrected = *printed_reading_named("corrected");
  for (double R : {0.3e-9, 10e-9, 40e-9, 120e-9, 1e-6}) {
    for (double alpha : {0.1, 1.0, 2.5, -2.0}) {
      for (int sense : {1, -1}) {
        const Vel v = velocity_for(R, alpha, sense);
        const FrictionWrench p = thesis_printed_friction_from_velocity(a, b, muN, v.vx, v.vy, v.om, corrected);
        const FrictionWrench x = rectangle_friction_wrench(a, b, muN, R, alpha, sense);
        INFO("R " << R << " alpha " << alpha << " sense " << sense);
        CHECK(std::fabs(p.fx - x.fx) <= 1e-9 * muN);
        CHECK(std::fabs(p.fy - x.fy) <= 1e-9 * muN);
        CHECK(std::fabs(p.mf - x.mf) <= 1e-9 * muN * b);
      }
    }
  }
}

TEST_CASE("Printed readings with cubes: the printed forms are the Coulomb wrench with the sign slips",
          "[printed][numeric]") {
  // Where the printed logarithms are defined and R is moderate, the cube readings' printed forms
  // equal the stable Coulomb wrench with fy' negated (F1 printed) and mf times sign(omega) (F3
  // printed), which is how the law evaluates them (RoughBarModel::printed_slips). Beyond, the
  // logarithmic forms cancel and the stable ones do not.
  const double a = 27.5e-9, b = 50e-9, muN = 3e-6;
  RoughBarModel m;
  m.geometry = {a, b};
  m.muN = muN;
  m.printed = true;
  for (int i : {4, 5, 6, 7, 12, 13, 14, 15}) {
    m.reading = printed_reading(i);
    for (double R : {0.3e-9, 10e-9, 40e-9, 120e-9, 1e-6}) {
      for (double alpha : {0.1, 1.0, 2.5, -2.0}) {
        for (int sense : {1, -1}) {
          const Vel v = velocity_for(R, alpha, sense);
          const FrictionWrench p = thesis_printed_friction_from_velocity(a, b, muN, v.vx, v.vy, v.om, m.reading);
          const FrictionWrench x = m.printed_slips(m.coulomb_wrench(v.vx, v.vy, v.om), v.om);
          INFO("reading " << i << " R " << R << " alpha " << alpha << " sense " << sense);
          CHECK(std::fabs(p.fx - x.fx) <= 1e-9 * muN);
          CHECK(std::fabs(p.fy - x.fy) <= 1e-9 * muN);
          CHECK(std::fabs(p.mf - x.mf) <= 1e-9 * muN * b);
        }
      }
    }
    // World axes: the law's wrench is the stable one (no cancellation at R = 1e4 b).
    const Vel far = velocity_for(1e4 * b, 0.7, -1);
    const WorldWrench w = m.friction(0.0, far.vx, far.vy, far.om);
    const FrictionWrench x = m.printed_slips(m.coulomb_wrench(far.vx, far.vy, far.om), far.om);
    CHECK(w.fx == x.fx);
    CHECK(w.mf == x.mf);
    CHECK(std::hypot(w.fx, w.fy) <= muN * (1 + 1e-12));
  }
}

TEST_CASE("Printed readings: the C++ and F77 right-hand sides are bit-identical under all 16",
          "[printed][crosslang][regression]") {
  const Scene sc = test::thesis_preset(18);
  const RoughBarModel m = rough_model(sc);
  const double params[12] = {m.mass, m.inertia, m.push.force, m.push.beta, m.push.pbx, m.push.pby,
                             m.geometry.a, m.geometry.b, m.muN, 0.0, 0.0, 0.0};
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 16; ++i) {
    RoughBarModel mp = m;
    mp.printed = true;
    mp.f77_forms = true;  // cubes readings take the Coulomb wrench: the F77 routine's forms, as faithful does
    mp.reading = printed_reading(i);
    const RoughBarThesisRhs rhs{mp};
    for (int k = 0; k < 250; ++k) {
      double y[8] = {0, 0, 3 * u(rng), 1e3 * u(rng), 1e3 * u(rng), 1e11 * u(rng), 0, 0};
      if (k % 5 == 1) y[5] = 0.0;
      double dc[8], df[8];
      rhs(0.0, y, dc);
      REQUIRE(np_f77_rough_bar_rhs_law(0.0, y, df, params, 1 + i) == 0);
      for (int c = 0; c < 8; ++c) {
        INFO("reading " << i << " state " << k << " component " << c);
        REQUIRE(std::isfinite(dc[c]));
        REQUIRE(dc[c] == df[c]);
      }
    }
  }
  double dummy[8];
  const double y0[8] = {0, 0, 0, 1, 0, 1, 0, 0};
  CHECK(np_f77_rough_bar_rhs_law(0.0, y0, dummy, params, 3) == 0);
  double yy[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  const double t1 = 1e-12;
  int nstat[3];
  const double atol[8] = {1, 1, 1, 1, 1, 1, 1, 1};
  CHECK(np_f77_bsint_rough_bar_law(8, 0.0, yy, 1, &t1, yy, 1e-6, atol, 0.0, 0.0, 8, 1, 10, params, 17, nstat) == 1);
}

TEST_CASE("Printed readings: both engines identical under every reading on fig3_18 and fig3_29",
          "[printed][crosslang][regression]") {
  int same = 0;
  for (int fig : {18, 29}) {
    for (int i = 0; i < 16; ++i) {
      Scene sc = test::thesis_preset(fig);
      const PrintedReading r = printed_reading(i);
      sc.set({{"surface.printed.fy_sign", r.fy_sign},
              {"surface.printed.omega_sign", r.omega_sign},
              {"surface.printed.c4", std::string(r.c4_squares ? "squares_nm" : "cubes")},
              {"surface.printed.eq3_50", r.eq3_50},
              {"solver.t_end", 0.4e-9},
              {"solver.samples", 41}});
      REQUIRE(sc.surface.printed == r);
      const Trajectory c = run_faithful(sc, Engine::cxx), f = run_faithful(sc, Engine::f77);
      INFO("fig3_" << fig << " reading " << i << " (" << printed_reading_text(r) << ")");
      // The same steps, so the same rows; where the C++ engine diagnoses a rest the sign law
      // cannot hold (or a blow-up) it stops there, and its rows are the F77 engine's first ones.
      REQUIRE(c.rows.size() > 1);
      REQUIRE(c.rows.size() <= f.rows.size());
      for (std::size_t k = 0; k < c.rows.size(); ++k)
        for (std::size_t j = 0; j < c.rows[k].size(); ++j) REQUIRE(c.rows[k][j] == f.rows[k][j]);
      if (c.outcome == Outcome::ok || c.outcome == Outcome::solver_failure) {  // the same run, or the same failure
        same += c.outcome == Outcome::ok ? 1 : 0;
        CHECK(c.rows.size() == f.rows.size());
        CHECK(c.stats.status == f.stats.status);
        CHECK(c.stats.nfcn == f.stats.nfcn);
      } else {
        CHECK((c.outcome == Outcome::no_static_friction || c.outcome == Outcome::law_blowup));
      }
    }
  }
  CHECK(same >= 16);  // at least half the readings run the whole interval in both engines
}

TEST_CASE("Printed readings: scene keys, names and refusals", "[printed][unit]") {
  Scene sc = test::thesis_preset(18);
  CHECK(sc.surface.printed == PrintedReading{});
  sc.set("surface.printed.reading", std::string("as_drawn"));
  CHECK(sc.surface.printed == *printed_reading_named("as_drawn"));
  sc.set("surface.printed.omega_sign", true);  // a switch over the reading
  CHECK(printed_reading_index(sc.surface.printed) == 12);
  sc.set("surface.printed.c4", std::string("squares_nm"));
  CHECK(printed_reading_index(sc.surface.printed) == 8);
  const auto message = [&](const std::string& key, const SceneValue& v) {
    Scene s = test::thesis_preset(18);
    try {
      s.set(key, v);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  CHECK_THAT(message("surface.printed.reading", std::string("best")),
             Catch::Contains("surface.printed.reading") && Catch::Contains("best") && Catch::Contains("literal, as_drawn, corrected"));
  CHECK_THAT(message("surface.printed.c4", std::string("squares")),
             Catch::Contains("squares") && Catch::Contains("squares_nm, cubes"));
  CHECK_THAT(message("surface.printed.fy_sign", 1.0), Catch::Contains("true or false"));
  Scene smooth = test::preset("thesis/fig3_6a.toml");
  try {
    smooth.set("surface.printed.fy_sign", false);
    FAIL("a smooth scene took surface.printed");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("surface.printed"));
  }
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
