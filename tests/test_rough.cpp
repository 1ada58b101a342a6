// Rough-surface sliding (docs/models.md §C): invariants, the mu = 0 limit, the two friction laws.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "nanopush/numerics/elliptic.hpp"
#include "nanopush/models/environment.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/engines/engines.hpp"
#include "nanopush/models/stick_slip.hpp"
#include "trajectory_checks.hpp"
#include "support/support.hpp"

using namespace nanopush;
using Catch::Matchers::Contains;
using nanopush::test::max_dtheta;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

Scene preset(int fig) { return nanopush::test::thesis_preset(fig); }

/// The preset with its push force rounded `ulps` ulps up.
Scene pushed_up(int fig, int ulps) {
  Scene sc = preset(fig);
  double f = sc.push.force;
  for (int k = 0; k < ulps; ++k) f = std::nextafter(f, 1.0);
  sc.set("push.force", f);
  return sc;
}

/// The coulomb law's converged solution: the event-locating BS (modern) at rtol 1e-14.
Trajectory coulomb_reference(const Scene& sc) {
  RunSettings ref;
  ref.law = Law::coulomb;
  ref.method = Method::modern;
  ref.rtol = 1e-14;
  return run_engine(sc, ref);
}

struct Balance {
  double energy_rel = 0;     // max |dKE - W_push - W_fric| / max(|W_push|)
  double power_max = -1e300; // max friction power (should be <= 0)
  double f_over_muN = 0;     // max |f| / (mu N)
};

Balance balance(const Scene& sc, const Trajectory& tr) {
  Balance b;
  const auto& r0 = tr.rows.front();
  auto ke = [&](const TrajectoryRow& r) {
    return 0.5 * sc.mass * (r[4] * r[4] + r[5] * r[5]) + 0.5 * sc.inertia * r[6] * r[6];
  };
  double wmax = 0;
  for (double w : tr.work_push) wmax = std::max(wmax, std::fabs(w));
  const double muN = sc.surface.mu * sc.normal_load();
  for (std::size_t i = 0; i < tr.rows.size(); ++i) {
    const auto& r = tr.rows[i];
    const double lhs = ke(r) - ke(r0), rhs = tr.work_push[i] + tr.work_fric[i];
    b.energy_rel = std::max(b.energy_rel, std::fabs(lhs - rhs) / wmax);
    b.power_max = std::max(b.power_max, r[7] * r[4] + r[8] * r[5] + r[9] * r[6]);
    if (muN > 0) b.f_over_muN = std::max(b.f_over_muN, std::hypot(r[7], r[8]) / muN);
  }
  return b;
}

}  // namespace

TEST_CASE("Rough presets carry the captions' parameters", "[rough][scene][unit]") {
  for (int fig = 12; fig <= 32; ++fig) {
    const Scene sc = preset(fig);
    CHECK(sc.rough());
    CHECK(sc.surface.mu == Approx((fig - 12) * 0.01).margin(1e-15));
    CHECK(sc.surface.f_vdw == 0.400252e-4);
    CHECK(sc.mass == Approx(0.623425e-18).epsilon(1e-12));
    CHECK(sc.push.force == 5e-6);
    CHECK(sc.solver.t_end == 1.6e-9);
  }
}

TEST_CASE("mu = 0 reproduces the smooth-surface solution", "[rough][numeric]") {
  Scene sc = preset(12);
  RunSettings rs;
  rs.rtol = 1e-12;
  for (const char* law : {"thesis", "coulomb"}) {
    rs.law = parse_optional_choice<Law>("law", law);
    const Trajectory tr = run_engine(sc, rs);
    const Pendulum<double> ex(sc.push.theta_equilibrium(), 0.0, sc.push.force * sc.push.lever(), sc.inertia);
    double e = 0;
    for (const auto& r : tr.rows) {
      e = std::max(e, std::fabs(r[3] - ex.theta(r[0])));
      CHECK(r[7] == 0.0);
      CHECK(r[9] == 0.0);
    }
    INFO(law << ": theta error " << e);
    CHECK(e <= 1e-10);
  }
}

TEST_CASE("Energy balance and dissipation on every thesis-law run that does not chatter", "[rough][numeric]") {
  for (int fig = 12; fig <= 24; ++fig) {  // mu = 0 ... 0.12 < F/N = 0.1249
    const Scene sc = preset(fig);
    const Trajectory tr = run_engine(sc);
    const Balance b = balance(sc, tr);
    INFO("fig3_" << fig << " energy " << b.energy_rel << " power " << b.power_max << " |f|/muN " << b.f_over_muN
                 << " nfcn " << tr.stats.nfcn);
    CHECK(b.energy_rel <= 1e-8);
    CHECK(b.power_max <= 0.0);
    CHECK(b.f_over_muN <= 1.0 + 1e-12);
  }
}

TEST_CASE("Coulomb law: energy balance, dissipation, no chattering, exact rest", "[rough][numeric][coulomb]") {
  RunSettings rs;
  rs.law = Law::coulomb;
  const Trajectory ref = run_engine(preset(17), rs);  // mu = 0.05
  const long n_ref = static_cast<long>(ref.stats.nfcn);
  for (double mu : {0.05, 0.10, 0.13, 0.15, 0.20, 0.5, 1.0}) {
    Scene sc = preset(12);
    sc.surface.mu = mu;
    const Trajectory tr = run_engine(sc, rs);
    const Balance b = balance(sc, tr);
    INFO("mu " << mu << " nfcn " << tr.stats.nfcn << " (mu 0.05: " << n_ref << ") events " << tr.events.size()
               << " energy " << b.energy_rel << " power " << b.power_max);
    CHECK(b.energy_rel <= 1e-8);
    CHECK(b.power_max <= 0.0);
    CHECK(b.f_over_muN <= 1.0 + 1e-12);
    CHECK(tr.stats.nfcn <= 3 * n_ref);
    // After a stick event the body is exactly at rest.
    for (const auto& ev : tr.events) {
      if (!ev.stuck) continue;
      for (const auto& r : tr.rows) {
        if (r[0] < ev.t) continue;
        CHECK(r[4] == 0.0);
        CHECK(r[5] == 0.0);
        CHECK(r[6] == 0.0);
      }
    }
  }
}

TEST_CASE("Coulomb law: the CVODE cross-check agrees to 1e-8", "[rough][coulomb][crosscheck][numeric]") {
  for (double mu : {0.05, 0.15, 0.5}) {
    Scene sc = preset(12);
    sc.surface.mu = mu;
    RunSettings a, b;
    a.law = b.law = Law::coulomb;
    a.method = Method::faithful;  // the Bulirsch-Stoer of the thesis (the preset states auto)
    // CVODE's global error runs far above its rtol (BDF, order <= 5; ~1e-4 rad at 1e-10 where
    // BS is within 1e-9), so the reference runs 100 times tighter, as in the reproduce step.
    a.rtol = 1e-10;
    b.rtol = 1e-12;
    b.method = Method::cvode;
    const Trajectory ta = run_engine(sc, a), tb = run_engine(sc, b);
    REQUIRE(ta.rows.size() == tb.rows.size());
    // theta in rad; x relative to its largest value over the run (x reaches 100 L here).
    double dth = 0, dx = 0, xmax = 0;
    for (const auto& r : ta.rows) xmax = std::max(xmax, std::fabs(r[1]));
    for (std::size_t i = 0; i < ta.rows.size(); ++i) {
      dth = std::max(dth, std::fabs(ta.rows[i][3] - tb.rows[i][3]));
      dx = std::max(dx, std::fabs(ta.rows[i][1] - tb.rows[i][1]) / xmax);
    }
    INFO("mu " << mu << ": max |dtheta| " << dth << " rad, max |dx|/max|x| " << dx << "; events " << ta.events.size()
               << " vs " << tb.events.size());
    CHECK(dth <= 1e-8);
    CHECK(dx <= 1e-8);
    CHECK(ta.events.size() == tb.events.size());
  }
}

TEST_CASE("Coulomb law: CVODE lands on the converged solution at every rtol and rounding of the push",
          "[rough][coulomb][crosscheck][numeric]") {
  // The solution of a Coulomb slide from rest is unique (the friction is the gradient of a
  // convex dissipation), so rounding-level changes must move the result by the integration
  // error only. With a Jacobian kept over many steps, CVODE's Newton iteration held the
  // velocity's direction still near rest and chose between two results 4.4e-5 rad apart on
  // fig3_23 by rounding (stick_slip_cvode.cpp); the reference is the event-locating BS 1000
  // times tighter than the loosest CVODE run here.
  for (int fig : {23, 31}) {
    for (int ulps : {0, 1, 2, 4}) {
      const Scene sc = pushed_up(fig, ulps);
      const Trajectory tr = coulomb_reference(sc);
      for (double rtol : {1e-11, 3e-12, 1e-12, 3e-13, 1e-13}) {
        RunSettings cv;
        cv.law = Law::coulomb;
        cv.method = Method::cvode;
        cv.rtol = rtol;
        const double dth = max_dtheta(run_engine(sc, cv), tr);
        INFO("fig3_" << fig << ", push + " << ulps << " ulp, CVODE rtol " << rtol << ": max |dtheta| " << dth);
        CHECK(dth <= 1e-8);
      }
    }
  }
}

TEST_CASE("Coulomb law: a slide from rest lands on the converged solution at every rounding of the push",
          "[rough][coulomb][numeric]") {
  // The start direction from rest maximises the power margin on a sphere. Found by comparing
  // values of the margin only, it was right to ~sqrt(eps), and the event-locating BS at the
  // presets' rtol 1e-10 then landed 3e-8 rad off on fig3_31 at a push 4 ulps larger (8e-11 at
  // the others): the answer depended on rounding. Polished on the margin's gradient, every
  // rounding gives the same error.
  // The references themselves (rtol 1e-14): near the velocity's zero the event location once
  // resolved the components of V across the mode with 20000 steps of 1e-20 s and gave up on
  // fig3_31 at a push 4 ulps up; its sub-integrations now end at the terminal test. Every
  // rounding must run and agree within 1000 x rtol (measured 4e-14 rad).
  for (int fig : {23, 30, 31}) {
    Trajectory first;
    for (int ulps = 0; ulps < 10; ++ulps) {
      const Scene sc = pushed_up(fig, ulps);
      RunSettings bs;
      bs.law = Law::coulomb;
      bs.method = Method::faithful;  // at the preset's rtol, as reproduce runs it
      const Trajectory ref = coulomb_reference(sc);
      const double dth = max_dtheta(run_engine(sc, bs), ref);
      INFO("fig3_" << fig << ", push + " << ulps << " ulp: max |dtheta| " << dth);
      CHECK(dth <= 1e-8);
      if (ulps == 0) first = ref;
      const double dref = max_dtheta(ref, first);
      INFO("references at rtol 1e-14, push + " << ulps << " ulp vs + 0: max |dtheta| " << dref);
      CHECK(dref <= 1e-11);
    }
  }
}

TEST_CASE("At rest: stick inside the limit surface, slide by Gauss' principle outside", "[rough][unit][coulomb]") {
  const Scene sc = preset(27);  // mu = 0.15
  RoughBarModel m;
  m.mass = sc.mass;
  m.inertia = sc.inertia;
  m.geometry = sc.geometry;
  m.muN = 0.15 * sc.normal_load();
  SECTION("a push through the CM below mu N sticks") {
    m.push = Push{0.5 * m.muN, 0.3, 0.0, 0.0};
    const RestAnalysis r = analyse_rest(m, 0.0);
    CHECK(r.stuck);
    CHECK(r.margin <= 0.0);
  }
  SECTION("a push through the CM above mu N slides straight, a = (F - mu N)/m") {
    m.push = Push{2.0 * m.muN, 0.0, 0.0, 0.0};
    const RestAnalysis r = analyse_rest(m, 0.0);
    REQUIRE_FALSE(r.stuck);
    CHECK(r.accel[0] == Approx(m.muN / m.mass).epsilon(1e-9));
    CHECK(std::fabs(r.accel[1]) <= 1e-9 * r.accel[0]);
    CHECK(std::fabs(r.accel[2]) * 5e-8 <= 1e-9 * r.accel[0]);
  }
  SECTION("the thesis push at theta = 0 turns the bar: M A = W + F(A) holds") {
    m.push = sc.push;
    const RestAnalysis r = analyse_rest(m, 0.0);
    REQUIRE_FALSE(r.stuck);
    const WorldWrench ap = m.applied(0.0);
    const WorldWrench fr = m.friction(0.0, r.accel[0], r.accel[1], r.accel[2]);
    CHECK(m.mass * r.accel[0] == Approx(ap.fx + fr.fx).epsilon(1e-6));
    CHECK(m.mass * r.accel[1] == Approx(ap.fy + fr.fy).margin(1e-6 * m.muN));
    CHECK(m.inertia * r.accel[2] == Approx(ap.mf + fr.mf).margin(1e-6 * m.muN * 5e-8));
  }
}

TEST_CASE("Friction is continuous through omega = 0 while the bar slides (no switch there)", "[rough][unit]") {
  const Scene sc = preset(17);
  RoughBarModel m;
  m.geometry = sc.geometry;
  m.muN = 1.0;
  const WorldWrench f0 = m.friction(0.3, 5.0, 1.0, 0.0);
  for (double om : {1e-3, -1e-3, 1e-6, -1e-6}) {
    const WorldWrench f = m.friction(0.3, 5.0, 1.0, om);
    CHECK(std::fabs(f.fx - f0.fx) <= 1e-9 * std::fabs(om) * 1e6);
    CHECK(std::fabs(f.fy - f0.fy) <= 1e-9 * std::fabs(om) * 1e6);
    CHECK(std::fabs(f.mf) <= 1e-12 * std::fabs(om) * 1e6);
  }
}

TEST_CASE("Bad rough scenes are rejected clearly", "[rough][scene][unit]") {
  const std::string& base = nanopush::test::kBaseRoughSceneText;
  auto with = [&](const std::string& a, const std::string& b) { return nanopush::test::replaced(base, a, b); };
  CHECK_THROWS_WITH(parse_scene(with("mu = 0.1", "mu = -0.1"), "s"), Contains("surface.mu = -0.1") && Contains("[0, 10]"));
  CHECK_THROWS_WITH(parse_scene(with("mass = 6e-19", "mass = 0"), "s"), Contains("object.mass = 0: must be > 0"));
  CHECK_THROWS_WITH(parse_scene(with("xn = 27.5e-9", "xn = 40e-9"), "s"), Contains("push.xn = 4") && Contains("on the body"));
  CHECK_THROWS_WITH(parse_scene(with("mu = 0.1", "mu = 0.1\nlaw = \"stribeck\""), "s"), Contains("surface.law"));
  CHECK_THROWS_WITH(parse_scene(with("mu = 0.1", "mu = 0.1\nf_vdw = -1"), "s"), Contains("surface.f_vdw = -1"));
}

TEST_CASE("Thesis law: C++ faithful and F77 agree to 1e-9 in theta wherever it does not chatter",
          "[rough][crosslang][regression]") {
  for (int fig = 12; fig <= 24; ++fig) {
    const Scene sc = preset(fig);
    RunSettings a, b;
    a.engine = nanopush::Engine::cxx;
    a.method = Method::faithful;  // the F77 engine's steps (the presets state auto)
    b.engine = nanopush::Engine::f77;
    const Trajectory ta = run_engine(sc, a), tb = run_engine(sc, b);
    REQUIRE(ta.rows.size() == tb.rows.size());
    double d = 0;
    for (std::size_t i = 0; i < ta.rows.size(); ++i) d = std::max(d, std::fabs(ta.rows[i][3] - tb.rows[i][3]));
    INFO("fig3_" << fig << ": max |dtheta| " << d);
    CHECK(d <= 1e-9);
    CHECK(ta.stats.nfcn == tb.stats.nfcn);
  }
  // Where the bar comes to rest inside the limit surface (mu >= 0.13) both end in
  // no_static_friction: the C++ engine's watch stops where the velocity reverses at rest, the
  // F77 engine at its step budget; they agree on every sample both reached.
  RunSettings a, b;
  a.allow_partial = b.allow_partial = true;
  a.method = Method::faithful;
  b.engine = nanopush::Engine::f77;
  const Trajectory ta = run_engine(preset(27), a), tb = run_engine(preset(27), b);
  CHECK_FALSE(ta.complete);
  CHECK_FALSE(tb.complete);
  CHECK(ta.outcome == Outcome::no_static_friction);
  CHECK(tb.outcome == Outcome::no_static_friction);
  REQUIRE(ta.rows.size() > 10);
  REQUIRE(ta.rows.size() <= tb.rows.size());
  double d = 0;
  for (std::size_t i = 0; i < ta.rows.size(); ++i) d = std::max(d, std::fabs(ta.rows[i][col::theta] - tb.rows[i][col::theta]));
  CHECK(d <= 1e-9);
}

TEST_CASE("A rough scene with [environment] and [body] takes its normal load from the force models",
          "[rough][scene][forces][unit]") {
  const Scene sc = load_scene(std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/examples/nanobar_humid_air.toml");
  Environment env;
  env.medium = Medium::humid_air;
  env.humidity = 0.5;
  Body body;
  body.shape = Shape::bar;
  body.length = 100e-9;
  body.width = 55e-9;
  body.height = 50e-9;
  body.material = *forces::find_material("graphite");
  LoadOptions lo;
  lo.rtol = sc.solver.rtol;
  const LoadReport rep = assemble_normal_load(env, body, lo);
  CHECK(sc.normal_load() == rep.sliding_load);
  CHECK_THAT(sc.load_report, Contains("capillary") && Contains("van_der_waals") && Contains("gravity"));
  RunSettings rs;
  const Trajectory tr = run_engine(sc, rs);
  CHECK(tr.complete);
  const std::string& base = nanopush::test::kBaseRoughSceneText;
  CHECK_THROWS_WITH(parse_scene(base + "[environment]\nmedium = \"vacuum\"\n", "s"), Contains("body = (missing)"));
  CHECK_THROWS_WITH(
      parse_scene(base + "[environment]\nmedium = \"vacuum\"\n[body]\nshape = \"bar\"\nlength = 1e-7\nwidth = 4e-8\nheight = 5e-8\nmaterial = \"graphite\"\n", "s"),
      Contains("body.width = 4") && Contains("must equal object.width"));
  std::string with_fvdw = base;
  with_fvdw.replace(with_fvdw.find("mu = 0.1"), 8, "mu = 0.1\nf_vdw = 1e-5");
  CHECK_THROWS_WITH(parse_scene(with_fvdw + "[environment]\nmedium = \"vacuum\"\n[body]\nshape = \"bar\"\nlength = 1e-7\nwidth = 5.5e-8\nheight = 5e-8\nmaterial = \"graphite\"\n", "s"),
                    Contains("surface.f_vdw = (present)"));
  CHECK_THROWS_WITH(parse_scene(base + "[environment]\nmedium = \"humid_air\"\nhumidity = 1.5\n[body]\nshape = \"bar\"\nlength = 1e-7\nwidth = 5.5e-8\nheight = 5e-8\nmaterial = \"graphite\"\n", "s"),
                    Contains("environment.humidity = 1.5"));
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
