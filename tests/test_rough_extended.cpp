// Rough scenes with more digits than double (solver.precision = long | quad; docs/accuracy.md,
// "References with more digits"): the friction wrench's forms in extended precision against
// each other across their switch, the runs against each other (double < long < quad), and the
// error estimate of every answer judged against long-double references on a seeded Latin
// hypercube of rough scenes, both laws, including answers of --accuracy below rtol 1e-11 that
// a double reference cannot judge.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "nanopush/engines/accuracy.hpp"
#include "nanopush/engines/engines.hpp"
#include "nanopush/models/friction_extended.hpp"
#include "nanopush/scenes/lhs.hpp"

using namespace nanopush;

namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

using Q = num::quad;

Scene preset(const std::string& dir, const std::string& name) {
  return load_scene(std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/" + dir + "/" + name + ".toml");
}

Trajectory run_at(const Scene& sc, Law law, Precision p, double rtol) {
  RunSettings r;
  r.method = Method::modern;
  r.law = law;
  r.precision = p;
  r.rtol = rtol;
  r.error_estimate = false;
  r.allow_partial = true;
  return run_engine(sc, r);
}

double rel(Q x, Q ref, Q scale) { return static_cast<double>(fabsq(x - ref) / scale); }

}  // namespace

TEST_CASE("Friction in quad: the closed form and the far field agree across their switch",
          "[friction][extended][numeric]") {
  // Two independent formulas of the same three integrals (corner antiderivatives; a 40-point
  // Gauss-Legendre product rule of the point-symmetrised integrands) where both hold.
  const auto& rule = friction_detail::gauss_half_rule<Q>(40);
  for (const double aspect : {1.0, 0.3, 0.01}) {
    for (const double rho : {3.5, 10.0, 29.0}) {
      for (const double alpha : {0.1, 0.7, 1.3, 2.9, 4.4}) {
        const Q a = Q(aspect), b = Q(1), xc = Q(rho) * cosq(Q(alpha)), yc = Q(rho) * sinq(Q(alpha));
        const auto cf = friction_detail::closed_form_reference(a, b, xc, yc);
        const auto ff = friction_detail::far_field_reference(a, b, xc, yc, rule.x.data(), rule.w.data(), 20);
        INFO("aspect " << aspect << " rho " << rho << " alpha " << alpha);
        CHECK(rel(cf.ix, ff.ix, 1) <= 1e-27);
        CHECK(rel(cf.iy, ff.iy, 1) <= 1e-27);
        // km ~ L^2/R: relative to its own size
        CHECK(rel(cf.km, ff.km, fabsq(ff.km)) <= 1e-25);
      }
    }
  }
}

TEST_CASE("Friction in long double and quad agrees with double's production forms",
          "[friction][extended][numeric]") {
  const double a = 2.5e-8, b = 1.5e-7, muN = 3e-6;
  int n = 0;
  for (const double vx : {1.0, -0.3, 0.0, 2e-5}) {
    for (const double vy : {0.5, -2.0, 0.0}) {
      for (const double om : {0.0, 1e7, -3e8, 2e-3, 5e13}) {
        if (vx == 0 && vy == 0 && om == 0) continue;
        const FrictionWrench d = rectangle_friction_from_velocity(a, b, muN, vx, vy, om);
        const auto l = rectangle_friction_from_velocity_extended<long double>(a, b, muN, vx, vy, om);
        const auto q = rectangle_friction_from_velocity_extended<Q>(a, b, muN, vx, vy, om);
        INFO("v = (" << vx << ", " << vy << "), omega = " << om);
        // |f| = muN in every regime (a unit vector averaged: |f| <= muN, = at translation)
        CHECK(static_cast<double>(fabsq(q.fx)) <= muN * (1 + 1e-30));
        CHECK(std::fabs(d.fx - static_cast<double>(q.fx)) <= 4e-16 * muN);
        CHECK(std::fabs(d.fy - static_cast<double>(q.fy)) <= 4e-16 * muN);
        CHECK(std::fabs(d.mf - static_cast<double>(q.mf)) <= 4e-15 * muN * b);
        CHECK(rel(Q(l.fx), q.fx, Q(muN)) <= 1e-18);
        CHECK(rel(Q(l.fy), q.fy, Q(muN)) <= 1e-18);
        CHECK(rel(Q(l.mf), q.mf, Q(muN * b)) <= 1e-17);
        ++n;
      }
    }
  }
  CHECK(n == 59);
}

TEST_CASE("Rough scenes in long double and quad: double, long and quad answers nest",
          "[rough][extended][numeric]") {
  struct Case {
    Scene sc;
    Law law;
  };
  const Case cases[] = {{preset("thesis", "fig3_17"), Law::thesis},
                        {preset("thesis", "fig3_18"), Law::coulomb},
                        {preset("bench", "stick_mu015"), Law::coulomb}};
  for (const Case& c : cases) {
    const Trajectory q = run_at(c.sc, c.law, Precision::quad, 1e-22);
    const Trajectory l = run_at(c.sc, c.law, Precision::long_, 1e-16);
    const Trajectory d = run_at(c.sc, c.law, Precision::double_, 1e-12);
    REQUIRE(q.complete);
    REQUIRE(l.complete);
    REQUIRE(d.complete);
    CHECK(q.engine_label.find("-quad") != std::string::npos);
    REQUIRE(q.extended.size() == q.rows.size());
    const auto& e = q.rows.back();
    const double L = std::max(c.sc.length, std::hypot(e[col::x] - q.rows[0][col::x], e[col::y] - q.rows[0][col::y]));
    const double el = pose_error_norm(l.rows.back(), q.rows.back(), L);
    const double ed = pose_error_norm(d.rows.back(), q.rows.back(), L);
    INFO(c.sc.name << " (" << to_string(c.law) << "): long vs quad " << el << ", double vs quad " << ed);
    CHECK(el <= 1e-13);
    CHECK(ed <= 1e-9);
    CHECK(ed > el);
    // The same events in every precision.
    CHECK(q.events.size() == d.events.size());
  }
}

TEST_CASE("Extended precision is refused where the right-hand side is double only",
          "[rough][extended][unit]") {
  const Scene sc = preset("thesis", "fig3_18");
  for (const auto& [law, method] : {std::pair{Law::printed, Method::modern}, std::pair{Law::thesis, Method::faithful},
                                    std::pair{Law::thesis, Method::dop853}, std::pair{Law::coulomb, Method::cvode}}) {
    RunSettings r;
    r.law = law;
    r.method = method;
    r.precision = Precision::quad;
    CHECK_THROWS_AS(run_engine(sc, r), InputError);
  }
}

TEST_CASE("The error estimate is honest against long-double references, --accuracy down to 1e-12 included",
          "[accuracy][rough][extended][lhs][numeric]") {
  for (const Law law : {Law::coulomb, Law::thesis}) {
    for (const double accuracy : {0.0, 1e-12}) {
      int judged = 0, dishonest = 0;
      for (const Scene& sc : rough_lhs_scenes(preset("thesis", "fig3_18"), 12, 4711)) {
        RunSettings s;
        s.law = law;
        s.accuracy = accuracy;
        s.allow_partial = true;
        const Trajectory tr = run_engine(sc, s);
        if (!is_answer(tr.outcome) || !tr.error.available) continue;
        const Trajectory ref = run_at(sc, law, Precision::long_, std::max(1e-18, std::min(1e-16, tr.rtol * 1e-4)));
        if (!ref.complete) continue;
        ++judged;
        const double truth = pose_error_norm(tr.rows.back(), ref.rows.back(), tr.error.length_scale);
        // the reference's own error: long vs quad above, <= 1e-13 on the presets
        const bool honest = truth <= 10 * tr.error.norm + 1e-14;
        const bool met = accuracy == 0 || tr.outcome == Outcome::accuracy_not_reached || truth <= accuracy + 1e-14;
        if (!honest || !met) {
          ++dishonest;
          UNSCOPED_INFO("true " << truth << " vs estimate " << tr.error.norm << " (rtol " << tr.rtol << ", "
                                << tr.engine_label << ")\n" << sc.to_toml());
        }
      }
      INFO(to_string(law) << ", accuracy " << accuracy << ": " << judged << " judged, " << dishonest << " not honest");
      CHECK(judged >= 6);
      CHECK(dishonest == 0);
    }
  }
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
