// The dynamic tip-driven push (models/tip_dynamic.hpp, docs/tip.md): the spring contact, the
// agreement with the quasi-static model where both apply (a bound derived from the spring's
// compression, the oscillation and the coasting), the energy balance, contact loss, a push
// through the centre against its closed form, the unilateral contact, and the scene keys
// (tip.model, tip.stiffness, tip.cantilever.*, auto's choice and its cost).
#include <catch2/catch.hpp>
#include <cmath>

#include "nanopush/models/afm_probe.hpp"
#include "nanopush/models/tip_dynamic.hpp"
#include "nanopush/models/tip_push.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "support/support.hpp"

using namespace nanopush;
using tip::ContactMode;

namespace NANOPUSH_UNITY_ID {

// The bar of the quasi-static tests: 10 nm x 100 nm, 10 nm high, graphite; mu N = 1 nN.
constexpr double kA = 5e-9, kB = 50e-9, kMuN = 1e-9, kH = 10e-9, kRho = 2267.0;
constexpr double kMass = kRho * 2 * kA * 2 * kB * kH;
constexpr double kInertia = kMass * (4 * kA * kA + 4 * kB * kB) / 12;

tip::TipPath path_at(double yn, double speed, double travel) {
  tip::TipPath p;
  p.radius = 5e-9;
  p.start_x = -kA - p.radius - 5e-9;  // 5 nm of free travel before contact
  p.start_y = yn;
  p.speed = speed;
  p.travel = travel;
  return p;
}

double kinetic(const tip::TipRow& r) {
  return 0.5 * kMass * (r.vx * r.vx + r.vy * r.vy) + 0.5 * kInertia * r.omega * r.omega;
}

TEST_CASE("Dynamic tip: the spring contact pushes along the normal with k delta, never pulls", "[tip][dynamic][unit]") {
  const BarGeometry g{kA, kB};
  const double r = 5e-9, k = 2.0;
  // Base outside the offset surface: no force, the tip is the base.
  auto s = tip::spring_contact(g, r, k, -kA - r - 1e-9, 10e-9);
  CHECK_FALSE(s.touching);
  CHECK(s.fx == 0.0);
  CHECK(s.fy == 0.0);
  CHECK(s.qx == -kA - r - 1e-9);
  // Base 1 nm inside the offset surface of the face x' = -a: F = k delta along +x'.
  s = tip::spring_contact(g, r, k, -kA - r + 1e-9, 10e-9);
  REQUIRE(s.touching);
  CHECK(s.delta == Approx(1e-9).epsilon(1e-9));
  CHECK(s.fx == Approx(k * 1e-9).epsilon(1e-9));
  CHECK(s.fy == 0.0);
  CHECK(s.qx == Approx(-kA - r).epsilon(1e-15));  // the tip on the surface
  CHECK(s.torque == Approx(-10e-9 * k * 1e-9).epsilon(1e-9));  // p x F = (p_x F_y - p_y F_x)
  // Beyond a corner: along the corner's normal.
  s = tip::spring_contact(g, r, k, kA + 3e-9, kB + 3e-9);
  REQUIRE(s.touching);
  CHECK(s.fx == Approx(s.fy).epsilon(1e-14));
  CHECK(s.fx < 0);
  // The base inside the bar (a soft spring pressed hard): the nearest face's normal.
  s = tip::spring_contact(g, r, k, -kA + 1e-9, 0.0);
  REQUIRE(s.touching);
  CHECK(s.nx == -1.0);
  CHECK(s.delta == Approx(r + 1e-9).epsilon(1e-12));
}

/// The dynamic run of path p (spring k, rtol) against the quasi-static one: the end poses differ
/// by at most ds times the quasi-static pose's sensitivity to the contact's progress and to the
/// path's offset (the bound of the test below), a small part of the motion, and the bar rests.
void check_against_quasi_static(const tip::TipPath& p, double k, double rtol) {
  const BarGeometry g{kA, kB};
  const double v = p.speed;
  const auto qs = tip::run_quasi_static(g, kMuN, p, 0, 0, 0, 0, 201, 1e-10);
  const auto dyn = tip::run_dynamic(g, kMuN, {kMass, kInertia, k}, p, 0, 0, 0, 0, 201, rtol);
  double F_max = 0, rate_pos = 0, rate_th = 0;
  for (const auto& r : qs.rows) {
    F_max = std::max(F_max, std::hypot(r.tip_fx, r.tip_fy));
    rate_pos = std::max(rate_pos, std::hypot(r.vx, r.vy) / v);
    rate_th = std::max(rate_th, std::fabs(r.omega) / v);
  }
  tip::TipPath up = p, down = p;
  up.start_y += 1e-9;
  down.start_y -= 1e-9;
  const auto eu = tip::run_quasi_static(g, kMuN, up, 0, 0, 0, 0, 11, 1e-10).rows.back();
  const auto ed = tip::run_quasi_static(g, kMuN, down, 0, 0, 0, 0, 11, 1e-10).rows.back();
  const double lat_pos = std::hypot(eu.x - ed.x, eu.y - ed.y) / 2e-9, lat_th = std::fabs(eu.theta - ed.theta) / 2e-9;
  const double ds = F_max / k + 2 * v / std::sqrt(k / kMass) + kMass * v * v / (2 * kMuN);
  const auto& a = dyn.run.rows.back();
  const auto& b = qs.rows.back();
  CHECK(std::hypot(a.x - b.x, a.y - b.y) <= ds * (rate_pos + lat_pos));
  CHECK(std::fabs(a.theta - b.theta) <= ds * (rate_th + lat_th));
  // The bound is a small part of the motion: the comparison means something.
  CHECK(ds * (rate_pos + lat_pos) < 0.015 * std::hypot(b.x, b.y));
  CHECK(ds * (rate_th + lat_th) < 0.01 * std::fabs(b.theta));
  // At rest at the end (t_end: the travel time plus the settling allowance).
  CHECK(a.vx == 0.0);
  CHECK(a.vy == 0.0);
  CHECK(a.omega == 0.0);
}

TEST_CASE("Dynamic tip: a slow tip on a stiff spring ends where the quasi-static one does, within the derived bound",
          "[tip][dynamic][numeric]") {
  // v = 1 m/s is slow for this bar: m v^2/(mu N L) = 4e-4. The dynamic tip touches the bar
  // off the quasi-static contact point by at most ds: the spring's compression F_max/k, the
  // oscillation's swing 2 v/omega0 (omega0 = sqrt(k/m)) and the coasting after the tip stops,
  // m v^2/(2 mu N). The quasi-static end pose moves by at most ds times its sensitivity to the
  // contact's progress along the path (max |v_cm|/v, max |omega|/v over the run) plus its
  // sensitivity to the path's offset across it (central differences of two quasi-static runs
  // 1 nm either side). A push through the centre, where the latter is a bifurcation, has its
  // own closed form below.
  const double k = 10.0, v = 1.0, rtol = 1e-9;
  for (double yn : {15e-9, 40e-9}) {
    INFO("yn = " << yn);
    const tip::TipPath p = path_at(yn, v, 60e-9);
    check_against_quasi_static(p, k, rtol);
  }
}

TEST_CASE("Dynamic tip: the spring's work is the kinetic energy gained plus the surface's dissipation",
          "[tip][dynamic][numeric]") {
  const BarGeometry g{kA, kB};
  for (const auto& [yn, k, rtol] : {std::tuple{15e-9, 10.0, 1e-9}, std::tuple{15e-9, 10.0, 1e-11},
                                    std::tuple{15e-9, 100.0, 1e-9}, std::tuple{40e-9, 10.0, 1e-10}}) {
    INFO("yn = " << yn << ", k = " << k << ", rtol = " << rtol);
    const tip::TipPath p = path_at(yn, 1.0, 60e-9);
    // Sampled inside the push, so that some rows catch the bar moving.
    const auto dyn = tip::run_dynamic(g, kMuN, {kMass, kInertia, k}, p, 0, 0, 0, 5.5e-8, 401, rtol);
    const double W = dyn.run.rows.back().work_tip;
    REQUIRE(W > 0);
    bool saw_motion = false;
    double prev_fric = 0;
    for (const auto& r : dyn.run.rows) {
      // The accumulators are integrated with the state at rtol: the balance holds to rtol of the work.
      CHECK(std::fabs(r.work_tip + r.work_fric - kinetic(r)) <= rtol * W);
      CHECK(r.work_fric <= prev_fric);  // friction only dissipates
      prev_fric = r.work_fric;
      saw_motion = saw_motion || kinetic(r) > 1e-6 * W;
    }
    CHECK(saw_motion);
  }
}

TEST_CASE("Dynamic tip: a push near the end turns the bar until the tip slips off, and no force after",
          "[tip][dynamic][numeric]") {
  const BarGeometry g{kA, kB};
  const tip::TipPath p = path_at(45e-9, 1.0, 150e-9);
  const auto dyn = tip::run_dynamic(g, kMuN, {kMass, kInertia, 10.0}, p, 0, 0, 0, 0, 401, 1e-9);
  double t_release = -1;
  for (const auto& e : dyn.run.events)
    if (e.what == "release") t_release = e.t;
  REQUIRE(t_release > 0);
  CHECK(t_release < p.t_stop());
  bool after = false;
  for (const auto& r : dyn.run.rows) {
    if (r.t <= t_release) continue;
    after = true;
    CHECK(r.contact == ContactMode::none);
    CHECK(r.tip_fx == 0.0);
    CHECK(r.tip_fy == 0.0);
    // The tip is off the bar: its centre farther than its radius from the rectangle.
    const double dx = r.tip_x - r.x, dy = r.tip_y - r.y, c = std::cos(r.theta), s = std::sin(r.theta);
    CHECK(tip::contact_geometry(g, c * dx + s * dy, -s * dx + c * dy).distance >= p.radius);
  }
  CHECK(after);
  const auto& last = dyn.run.rows.back();
  CHECK(last.theta < -0.3);  // it turned (clockwise: pushed at +y')
  CHECK(std::fabs(last.work_tip + last.work_fric - kinetic(last)) <= 1e-9 * last.work_tip);
}

TEST_CASE("Dynamic tip: through the centre the bar translates, and ends where the closed form puts it",
          "[tip][dynamic][numeric]") {
  // Along the line of the push the motion is one-dimensional: stuck until k delta = mu N at
  // t1 = t_contact + mu N/(k v), then x = x_tip - mu N/k - (v/omega0) sin(omega0 (t - t1)).
  // When the base stops (phase phi = omega0 (t_stop - t1)) the bar swings on by the
  // amplitude A = (v/omega0) sqrt(2 - 2 cos phi) from the spring's equilibrium and sticks
  // there (A < mu N/k: the tip stays in contact): x_end = x_qs - mu N/k + A.
  const BarGeometry g{kA, kB};
  const double k = 10.0, v = 1.0, w0 = std::sqrt(k / kMass);
  const tip::TipPath p = path_at(0.0, v, 60e-9);
  const auto dyn = tip::run_dynamic(g, kMuN, {kMass, kInertia, k}, p, 0, 0, 0, 0, 201, 1e-10);
  for (const auto& r : dyn.run.rows) {
    CHECK(r.theta == 0.0);
    CHECK(r.y == 0.0);
    CHECK(r.vy == 0.0);
    CHECK(r.omega == 0.0);
  }
  const double t_contact = 5e-9 / v, t1 = t_contact + kMuN / (k * v);
  REQUIRE(dyn.run.events.size() >= 3);
  CHECK(dyn.run.events[0].what == "contact");
  CHECK(dyn.run.events[0].t == Approx(t_contact).epsilon(1e-12));
  CHECK(dyn.run.events[1].what == "slide");
  CHECK(dyn.run.events[1].t == Approx(t1).epsilon(1e-9));
  const double phi = w0 * (p.t_stop() - t1), A = (v / w0) * std::sqrt(2 - 2 * std::cos(phi));
  REQUIRE(A < kMuN / k);
  const double x_end = p.travel - 5e-9 - kMuN / k + A;  // the quasi-static end: the travel after contact
  // To the integration's accuracy: rtol 1e-10 of the swing's phase over ~190 periods, on v/omega0.
  CHECK(dyn.run.rows.back().x == Approx(x_end).margin(1e-6 * kMuN / k));
}

TEST_CASE("Dynamic tip: a slower tip through the centre follows the same closed form, never faster than 2 v",
          "[tip][dynamic][numeric]") {
  // The closed form above at tip speeds where the spring's period 2 pi/omega0 is far shorter
  // than the time mu N/(k v) the force takes to build: the slide's closed-form start must
  // stay within a small part of the period, or the bar leaves at many times the tip's speed.
  // Along the push the bar's speed is v (1 - cos(omega0 (t - t1))) <= 2 v.
  const BarGeometry g{kA, kB};
  const double k = 10.0, w0 = std::sqrt(k / kMass), period = 2 * M_PI / w0;
  for (double v : {0.1, 1e-3, 1e-6}) {
    INFO("v = " << v);
    const double t_contact = 5e-9 / v, t1 = t_contact + kMuN / (k * v);
    const tip::TipPath p = path_at(0.0, v, 5e-9 + kMuN / k + 40.3 * period * v);
    const auto dyn = tip::run_dynamic(g, kMuN, {kMass, kInertia, k}, p, 0, 0, 0, 0, 201, 1e-10);
    REQUIRE(dyn.run.events.size() >= 3);
    CHECK(dyn.run.events[1].what == "slide");
    CHECK(dyn.run.events[1].t == Approx(t1).epsilon(1e-9));
    double vmax = 0;
    for (const auto& r : dyn.run.rows) {
      CHECK(r.theta == 0.0);
      vmax = std::max(vmax, std::fabs(r.vx));
    }
    CHECK(vmax <= 2 * v * (1 + 1e-6));
    const double phi = w0 * (p.t_stop() - t1), A = (v / w0) * std::sqrt(2 - 2 * std::cos(phi));
    REQUIRE(A < kMuN / k);
    const double x_end = p.travel - 5e-9 - kMuN / k + A;
    CHECK(dyn.run.rows.back().x == Approx(x_end).margin(1e-6 * kMuN / k));
  }
}

TEST_CASE("Dynamic tip: the contact never pulls, and a stiff spring bounces the bar off the tip", "[tip][dynamic][numeric]") {
  // k = 100 N/m: the swing v/omega0 exceeds the compression mu N/k, so the bar runs ahead
  // of the tip and the contact breaks and is made again, each change a located event.
  const BarGeometry g{kA, kB};
  const double k = 100.0;
  const tip::TipPath p = path_at(15e-9, 1.0, 60e-9);
  const auto dyn = tip::run_dynamic(g, kMuN, {kMass, kInertia, k}, p, 0, 0, 0, 5e-8, 2001, 1e-9);
  int releases = 0, contacts = 0;
  for (const auto& e : dyn.run.events) {
    releases += e.what == "release";
    contacts += e.what == "contact";
  }
  CHECK(releases >= 3);
  CHECK(contacts >= releases);
  int touching = 0, free_rows = 0;
  for (const auto& r : dyn.run.rows) {
    const double c = std::cos(r.theta), s = std::sin(r.theta);
    const double fbx = c * r.tip_fx + s * r.tip_fy, fby = -s * r.tip_fx + c * r.tip_fy;
    const double dx = r.tip_x - r.x, dy = r.tip_y - r.y;
    const auto geo = tip::contact_geometry(g, c * dx + s * dy, -s * dx + c * dy);
    if (r.contact == ContactMode::none) {
      ++free_rows;
      CHECK(fbx == 0.0);
      CHECK(fby == 0.0);
    } else {
      ++touching;
      // Pushes into the bar along the inward normal: F.n < 0, no tangential part.
      CHECK(fbx * geo.nx + fby * geo.ny < 0);
      CHECK(std::fabs(fbx * geo.ny - fby * geo.nx) <= 1e-9 * std::hypot(fbx, fby));
      CHECK(geo.distance == Approx(p.radius).epsilon(1e-9));  // the tip on the bar's surface
    }
  }
  CHECK(touching > 0);
  CHECK(free_rows > 0);
  // The largest compression: the friction's force plus the impact of a bar met at the tip's
  // speed (1/2 k delta^2 = 1/2 m v^2).
  CHECK(dyn.max_delta <= (kMuN + 1.0 * std::sqrt(kMass * k)) / k);
}

TEST_CASE("Dynamic tip: bad input names the key", "[tip][dynamic][unit]") {
  const BarGeometry g{kA, kB};
  tip::TipPath p = path_at(15e-9, 1.0, 60e-9);
  auto run = [&](const tip::TipPath& pp, double k) {
    (void)tip::run_dynamic(g, kMuN, {kMass, kInertia, k}, pp, 0, 0, 0, 0, 11, 1e-9);
  };
  CHECK_THROWS_WITH(run(p, -1.0), Catch::Contains("tip.stiffness") && Catch::Contains("> 0"));
  CHECK_THROWS_WITH(run(p, 0.0), Catch::Contains("tip.stiffness"));
  p.mu = -0.2;
  CHECK_THROWS_WITH(run(p, 10.0), Catch::Contains("tip.mu") && Catch::Contains("[0, 10]"));
  p.mu = 10.5;
  CHECK_THROWS_WITH(run(p, 10.0), Catch::Contains("tip.mu"));
  p.mu = std::nan("");
  CHECK_THROWS_WITH(run(p, 10.0), Catch::Contains("tip.mu"));
  p.mu = 0;
  p.speed = 0;
  CHECK_THROWS_WITH(run(p, 10.0), Catch::Contains("tip.speed"));
  p.speed = 1;
  p.start_x = 0;
  CHECK_THROWS_WITH(run(p, 10.0), Catch::Contains("tip.start"));
}

TEST_CASE("Dynamic tip: a push the dynamic model cannot follow ends at once with the reason", "[tip][dynamic][numeric]") {
  // The example nanorod (590 x 27 x 27 nm graphite, mu N = 1 nN) at AFM speed, 1 um/s: the
  // spring's wrench leaves the limit surface so slowly that the bar starts at ~1e-11 m/s, where
  // the friction across its direction relaxes in ~1e-20 s, below the steps double can take at
  // t ~ 0.017 s. Without the closed-form start held within the spring's period it left at
  // 0.05 m/s (5e4 times the tip's speed) or underflowed with no word of why.
  const BarGeometry g{13.5e-9, 295e-9};
  const double m = 2267.0 * 27e-9 * 590e-9 * 27e-9, I = m * (27e-9 * 27e-9 + 590e-9 * 590e-9) / 12;
  tip::TipPath p;
  p.radius = 10e-9;
  p.start_x = -40e-9;
  p.start_y = 150e-9;
  p.speed = 1e-6;
  p.travel = 400e-9;
  for (double mu : {0.0, 0.3}) {
    INFO("tip.mu = " << mu);
    p.mu = mu;
    CHECK_THROWS_WITH(tip::run_dynamic(g, 1e-9, {m, I, 10.0}, p, 0, 0, 0, 0, 401, 1e-10),
                      Catch::Contains("step size underflow") && Catch::Contains("relaxes in") &&
                          Catch::Contains("tip.model = quasi_static or auto"));
  }
  // Faster, the run can be followed, but each slide's start and each of the spring's periods
  // costs steps: the budget (solver.max_steps) ends it with the reason, and a larger budget
  // gives the answer.
  p.mu = 0;
  p.speed = 0.1;
  p.travel = 100e-9;
  CHECK_THROWS_WITH(tip::run_dynamic(g, 1e-9, {m, I, 10.0}, p, 0, 0, 0, 0, 101, 1e-10, 5000),
                    Catch::Contains("solver.max_steps = 5000") && Catch::Contains("every period of the spring") &&
                        Catch::Contains("quasi_static"));
  const auto dyn = tip::run_dynamic(g, 1e-9, {m, I, 10.0}, p, 0, 0, 0, 0, 101, 1e-10);
  CHECK(dyn.run.steps <= 100000);
  CHECK(dyn.run.rows.back().theta < -0.2);  // the rod turned, as the quasi-static one does (-0.25 rad)
  CHECK_THROWS_WITH(tip::run_dynamic(g, 1e-9, {m, I, 10.0}, p, 0, 0, 0, 0, 101, 1e-10, 0),
                    Catch::Contains("solver.max_steps"));
}

// ---- tip friction (tip.mu > 0) --------------------------------------------------------

/// A path whose tip meets the face x' = -a at height yn after 5 nm of free travel along x,
/// moving in world direction `direction`.
tip::TipPath oblique_path(double yn, double direction, double speed, double travel, double mu) {
  tip::TipPath p = path_at(yn, speed, travel);
  p.direction = direction;
  p.start_y = yn - 5e-9 * std::tan(direction);
  p.mu = mu;
  return p;
}

/// Where a row's tip touches the bar: the contact point and normal (body axes) from the tip's
/// centre and the pose, and the force's parts along the normal (pushing, > 0) and the tangent
/// t = (-ny, nx).
struct RowContact {
  tip::ContactGeometry geo;
  double Fn = 0, Ft = 0;
};
RowContact row_contact(const BarGeometry& g, const tip::TipRow& r) {
  const double c = std::cos(r.theta), s = std::sin(r.theta);
  const double dx = r.tip_x - r.x, dy = r.tip_y - r.y;
  RowContact rc;
  rc.geo = tip::contact_geometry(g, c * dx + s * dy, -s * dx + c * dy);
  const double fbx = c * r.tip_fx + s * r.tip_fy, fby = -s * r.tip_fx + c * r.tip_fy;
  rc.Fn = -(fbx * rc.geo.nx + fby * rc.geo.ny);
  rc.Ft = -fbx * rc.geo.ny + fby * rc.geo.nx;
  return rc;
}

TEST_CASE("Dynamic tip: the offset surface's points and the sliding contact", "[tip][dynamic][unit]") {
  const BarGeometry g{kA, kB};
  const double r = 5e-9, P = tip::offset_perimeter(g, r);
  // Each point is at distance r from the rectangle along its normal, and its arc length reads back.
  for (int i = 0; i < 400; ++i) {
    const double s = P * (i + 0.5) / 400;
    const tip::OffsetPoint o = tip::offset_point(g, r, s);
    const auto c = tip::contact_geometry(g, o.qx, o.qy);
    CHECK(c.distance == Approx(r).epsilon(1e-12));
    CHECK(c.nx == Approx(o.nx).margin(1e-12));
    CHECK(c.ny == Approx(o.ny).margin(1e-12));
    CHECK(tip::offset_coordinate(g, r, o.qx + 1e-10 * o.nx, o.qy + 1e-10 * o.ny) == Approx(s).margin(1e-12 * P));
  }
  // The sliding contact: b - q along the cone's edge -n + mu sigma t, for bases on the faces and
  // over the corners, inside and outside the offset surface.
  for (const double mu : {0.1, 1.0}) {
    for (const double sigma : {-1.0, 1.0}) {
      for (int i = 0; i < 97; ++i) {
        const tip::OffsetPoint o = tip::offset_point(g, r, P * (i + 0.3) / 97);
        for (const double depth : {1e-10, -1e-11}) {
          const double bx = o.qx - depth * o.nx, by = o.qy - depth * o.ny;
          const tip::SlipPoint sp = tip::slip_point(g, r, mu, sigma, bx, by);
          const double tx = -sp.at.ny, ty = sp.at.nx, dx = -sp.at.nx + mu * sigma * tx, dy = -sp.at.ny + mu * sigma * ty;
          CHECK(bx - sp.at.qx == Approx(sp.lambda * dx).margin(1e-22));
          CHECK(by - sp.at.qy == Approx(sp.lambda * dy).margin(1e-22));
          CHECK((sp.lambda > 0) == (depth > 0));
          CHECK(std::fabs(sp.lambda) <= 2 * std::fabs(depth));
          CHECK(sp.at.joint == Approx(tip::offset_point(g, r, sp.at.s).joint).margin(1e-12 * P));
        }
      }
    }
  }
  // The distance to the nearest joint of a face and an arc: positive on the faces, negative on
  // the arcs, zero at the eight joints, and continuous (slope 1 in arc length) in between.
  const double arc = 0.5 * M_PI * r;
  double s_joint = 0;
  for (int side = 0; side < 4; ++side) {
    const double len = side % 2 == 0 ? 2 * kB : 2 * kA;  // the faces in order x' = a, y' = b, ...
    for (const double u : {0.25 * len, 0.5 * len}) CHECK(tip::offset_point(g, r, s_joint + u).joint == Approx(u).epsilon(1e-12));
    for (const double u : {0.25 * arc, 0.5 * arc})
      CHECK(tip::offset_point(g, r, s_joint + len + u).joint == Approx(-u).epsilon(1e-9));
    for (const double sj : {s_joint + len, s_joint + len + arc}) {
      CHECK((tip::offset_point(g, r, sj - 1e-12).joint > 0) == (sj == s_joint + len));
      CHECK(std::fabs(tip::offset_point(g, r, sj + 1e-12).joint) <= 1.0001e-12);
    }
    s_joint += len + arc;
  }
}

TEST_CASE("Dynamic tip with tip friction: a slow tip ends where the quasi-static one does, within the derived bound",
          "[tip][dynamic][friction][numeric]") {
  // As for the frictionless tip: the dynamic tip's centre lags the base by |F|/k in any
  // direction now (F on the friction cone's edge when the tip slides), so the contact lies
  // off the quasi-static one by at most ds = F_max/k + 2 v/omega0 + m v^2/(2 mu N), and the
  // end poses differ by at most ds times the quasi-static pose's sensitivity to the contact's
  // progress and to the path's offset. Pushes along the normal (the tip sticks and slips
  // tens of times as the bar turns) and an oblique one (it slides from contact).
  const double k = 10.0, v = 1.0, rtol = 1e-9;
  for (const auto& [yn, dir, mu] : {std::tuple{15e-9, 0.0, 0.1}, std::tuple{15e-9, 0.0, 0.3},
                                    std::tuple{40e-9, 0.0, 0.1}, std::tuple{40e-9, 0.0, 0.3},
                                    std::tuple{-20e-9, 0.6, 0.1}}) {
    INFO("yn = " << yn << ", direction = " << dir << ", tip mu = " << mu);
    const tip::TipPath p = oblique_path(yn, dir, v, 60e-9, mu);
    check_against_quasi_static(p, k, rtol);
  }
}

TEST_CASE("Dynamic tip with tip friction: the tip's work is the kinetic energy plus what both frictions take",
          "[tip][dynamic][friction][numeric]") {
  // The run integrates the base's power F.u and the tip friction's -F_t (ds/dt + omega r)
  // (ds/dt from slip_point's implicit derivative); work_tip is the first less the spring's
  // energy |F|^2/(2k) plus the second, so W_tip = work_tip - work_tip_fric is what the tip
  // passes on, and W_tip + W_fric + W_tip_fric = the kinetic energy holds only if the sliding
  // velocity, the stuck tip's rolling and the events are right. (Where the bar rests and
  // slides again hundreds of times, or the tip sticks and slips near the bar's end, the
  // residual is larger: docs/tip.md, "Open".)
  const BarGeometry g{kA, kB};
  for (const auto& [yn, dir, mu, k, rtol] :
       {std::tuple{15e-9, 0.0, 0.1, 10.0, 1e-9}, std::tuple{15e-9, 0.0, 0.3, 10.0, 1e-11},
        std::tuple{-20e-9, 0.6, 0.1, 10.0, 1e-9}, std::tuple{-20e-9, 0.6, 0.1, 10.0, 1e-11}}) {
    INFO("yn = " << yn << ", direction = " << dir << ", tip mu = " << mu << ", k = " << k << ", rtol = " << rtol);
    const tip::TipPath p = oblique_path(yn, dir, 1.0, 60e-9, mu);
    const auto dyn = tip::run_dynamic(g, kMuN, {kMass, kInertia, k}, p, 0, 0, 0, 5.5e-8, 401, rtol);
    REQUIRE(dyn.work_tip_fric.size() == dyn.run.rows.size());
    const double W = dyn.run.rows.back().work_tip - dyn.work_tip_fric.back();
    REQUIRE(W > 0);
    double prev_fric = 0, prev_tip_fric = 0, worst = 0;
    bool saw_motion = false;
    for (std::size_t i = 0; i < dyn.run.rows.size(); ++i) {
      const auto& r = dyn.run.rows[i];
      const double W_tip_fric = dyn.work_tip_fric[i], W_tip = r.work_tip - W_tip_fric;
      worst = std::max(worst, std::fabs(W_tip + r.work_fric + W_tip_fric - kinetic(r)) / W);
      CHECK(r.work_fric <= prev_fric);  // both frictions only dissipate
      CHECK(W_tip_fric <= prev_tip_fric);
      prev_fric = r.work_fric;
      prev_tip_fric = W_tip_fric;
      saw_motion = saw_motion || kinetic(r) > 1e-6 * W;
    }
    CHECK(worst <= rtol);
    CHECK(saw_motion);
    if (dir > 0) CHECK(dyn.work_tip_fric.back() < -0.01 * W);  // the oblique tip slides
  }
}

TEST_CASE("Dynamic tip with tip friction: a tip pushed along the normal sticks, an oblique one slides on the cone's edge",
          "[tip][dynamic][friction][numeric]") {
  const BarGeometry g{kA, kB};
  const double r = 5e-9;
  SECTION("sticks: no sliding at the contact, the force inside the cone") {
    // mu = 3 along the normal at yn = 15 nm: the quasi-static tip sticks all along (at mu = 1
    // it slides once the bar has turned by ~0.5 rad), and so does the dynamic one. The tip does not turn: as the bar turns by dtheta under it, the contact
    // rolls r dtheta along the face, so on the face x' = -a (tangent (0, -1)) p_y - r theta
    // stays where the contact was made.
    const tip::TipPath p = oblique_path(15e-9, 0.0, 1.0, 60e-9, 3.0);
    const auto qs = tip::run_quasi_static(g, kMuN, p, 0, 0, 0, 0, 101, 1e-10);
    for (const auto& q : qs.rows) CHECK(q.contact != ContactMode::slide);
    const auto dyn = tip::run_dynamic(g, kMuN, {kMass, kInertia, 10.0}, p, 0, 0, 0, 5.5e-8, 401, 1e-10);
    for (const auto& e : dyn.run.events) CHECK(e.what != "tip slips");
    bool first = true;
    double anchor = 0;
    int stuck = 0;
    for (double w : dyn.work_tip_fric) CHECK(w == 0.0);
    for (const auto& row : dyn.run.rows) {
      CHECK(row.contact != ContactMode::slide);
      if (row.contact != ContactMode::stick) continue;
      ++stuck;
      const RowContact rc = row_contact(g, row);
      CHECK(rc.geo.nx == -1.0);
      CHECK(rc.Fn > 0);
      CHECK(std::fabs(rc.Ft) <= p.mu * rc.Fn);
      const double pinned = rc.geo.py - r * row.theta;
      if (first) anchor = pinned;
      first = false;
      CHECK(pinned == Approx(anchor).margin(1e-12 * kB));
    }
    CHECK(stuck > 100);
    CHECK(dyn.run.rows.back().theta < -0.05);  // the bar turned under the stuck tip
  }
  SECTION("slides: |F_t| = mu F_n, the tip slipping in the sense its friction drags the bar") {
    const tip::TipPath p = oblique_path(-20e-9, 0.6, 1.0, 60e-9, 0.1);
    const auto dyn = tip::run_dynamic(g, kMuN, {kMass, kInertia, 10.0}, p, 0, 0, 0, 5.5e-8, 401, 1e-10);
    int sliding = 0;
    const tip::TipRow* prev = nullptr;
    for (const auto& row : dyn.run.rows) {
      if (row.contact != ContactMode::slide) {
        prev = nullptr;
        continue;
      }
      ++sliding;
      const RowContact rc = row_contact(g, row);
      CHECK(rc.Fn > 0);
      CHECK(std::fabs(rc.Ft) == Approx(p.mu * rc.Fn).epsilon(1e-9));
      if (prev) {  // the slip between two rows: along the tangent, plus the rolling r dtheta
        const RowContact pc = row_contact(g, *prev);
        const double tx = -rc.geo.ny, ty = rc.geo.nx;
        const double slip = (rc.geo.px - pc.geo.px) * tx + (rc.geo.py - pc.geo.py) * ty + r * (row.theta - prev->theta);
        if (std::fabs(slip) > 1e-12) CHECK((slip > 0) == (rc.Ft > 0));
      }
      prev = &row;
    }
    CHECK(sliding > 100);
  }
}

// ---- scenes: tip.model, tip.stiffness, tip.cantilever ---------------------------------

std::string tip_scene(const std::string& tip_extra, double speed = 1e-6) {
  std::string s = test::kTipSceneText;
  s.replace(s.find("speed = 1e-6"), 12, "speed = " + std::to_string(speed) + "\n" + tip_extra);
  return s;
}

TEST_CASE("Dynamic tip scenes: tip.model chooses the model, the default and auto at AFM speeds are the quasi-static run "
          "bit for bit", "[tip][dynamic][unit]") {
  const Trajectory base = run_scene(parse_scene(tip_scene("")));
  CHECK(base.engine_label == "cxx-quasi-static");
  for (const char* m : {"model = \"quasi_static\"", "model = \"auto\"\nstiffness = 1.0"}) {
    INFO(m);
    const Trajectory tr = run_scene(parse_scene(tip_scene(m)));
    CHECK(tr.engine_label == "cxx-quasi-static");
    REQUIRE(tr.rows.size() == base.rows.size());
    for (std::size_t i = 0; i < tr.rows.size(); ++i) CHECK(tr.rows[i] == base.rows[i]);
  }
  // A dynamic scene: the run says so, and equals the model called directly.
  const Scene sc = parse_scene(tip_scene("model = \"dynamic\"\nstiffness = 10.0", 1.0));
  const Trajectory tr = run_scene(sc);
  CHECK(tr.engine_label == "cxx-tip-dynamic");
  const auto direct = tip::run_dynamic(sc.geometry, sc.friction_limit(), {sc.mass, sc.inertia, 10.0}, sc.tip, 0, 0, 0,
                                       sc.solver.t_end, sc.solver.samples, sc.solver.rtol);
  CHECK(sc.solver.t_end == tip::dynamic_t_end({sc.mass, sc.inertia, 10.0}, sc.friction_limit(), sc.tip));
  CHECK(tr.rows.back()[col::x] == direct.run.rows.back().x);
  CHECK(tr.rows.back()[col::theta] == direct.run.rows.back().theta);
  CHECK(tr.work_push.back() == direct.run.rows.back().work_tip);
}

TEST_CASE("Dynamic tip scenes: auto runs the dynamic model only where inertia counts, a millisecond push stays cheap",
          "[tip][dynamic][numeric]") {
  // A 1 ms push (100 nm at 1e-4 m/s): m v^2/(mu N L) ~ 1e-14, far below 1e-3: quasi-static, at
  // the cost of a quasi-static run (a dynamic run would follow ~1e7 spring periods).
  Scene slow = parse_scene(tip_scene("model = \"auto\"\nstiffness = 10.0", 1e-4));
  slow.set("tip.travel", 100e-9);
  const double ratio = tip::inertia_ratio(slow.mass, 1e-4, slow.friction_limit(), 100e-9);
  CHECK(ratio < 1e-10);
  const Trajectory ts = run_scene(slow);
  CHECK(ts.engine_label == "cxx-quasi-static");
  CHECK(slow.solver.t_end == Approx(1e-3).epsilon(1e-12));
  CHECK(ts.stats.nfcn < 20000);
  const double periods = 1e-3 * std::sqrt(10.0 / slow.mass) / (2 * M_PI);
  CHECK(periods > 1e6);
  // A tip at 30 m/s on this bar: m v^2/(mu N L) > 1e-3: dynamic.
  const Scene fast = parse_scene(tip_scene("model = \"auto\"\nstiffness = 10.0", 30.0));
  CHECK(tip::inertia_ratio(fast.mass, 30.0, fast.friction_limit(), fast.tip.travel) > tip::kAutoInertiaRatio);
  CHECK(run_scene(fast).engine_label == "cxx-tip-dynamic");
}

TEST_CASE("Dynamic tip scenes: the stiffness from the cantilever (eqs 2.6-2.7), and bad keys exit with key and range",
          "[tip][dynamic][unit]") {
  // A silicon contact-mode cantilever (E = 169 GPa, 450 x 50 x 2 um, 17 um tip).
  const std::string cant =
      "[tip.cantilever]\nyoungs_modulus = 169e9\nlength = 450e-6\nwidth = 50e-6\nthickness = 2e-6\n"
      "tip_height = 17e-6\n";
  const Scene sc = parse_scene(tip_scene("model = \"dynamic\"", 1.0) + cant);
  CHECK(sc.tip_model == TipModel::dynamic);
  afm::Cantilever c;
  c.E = 169e9;
  c.length = 450e-6;
  c.width = 50e-6;
  c.thickness = 2e-6;
  c.tip_height = 17e-6;
  const auto kk = afm::spring_constants(c);
  CHECK(sc.tip_stiffness == Approx(1.0 / (1.0 / kk.ktheta + 1.0 / kk.kby)).epsilon(1e-15));
  auto err = [](const std::string& text) { return test::input_error_of([&] { (void)run_scene(parse_scene(text)); }); };
  CHECK_THAT(err(tip_scene("model = \"dynamic\"\nstiffness = -2.0")), Catch::Contains("tip.stiffness") && Catch::Contains("> 0"));
  CHECK_THAT(err(tip_scene("model = \"fast\"")),
             Catch::Contains("tip.model") && Catch::Contains("quasi_static, dynamic, auto"));
  CHECK_THAT(err(tip_scene("model = \"dynamic\"")), Catch::Contains("tip.stiffness"));
  CHECK_THAT(err(tip_scene("model = \"dynamic\"\nstiffness = 1.0\nmu = -0.3")),
             Catch::Contains("tip.mu") && Catch::Contains("[0, 10]"));
  CHECK_THAT(err(tip_scene("model = \"auto\"\nstiffness = 1.0\nmu = 12.0", 30.0)), Catch::Contains("tip.mu"));
  // Tip friction is the dynamic model's too now: the scene runs it.
  CHECK(run_scene(parse_scene(tip_scene("model = \"dynamic\"\nstiffness = 10.0\nmu = 0.3", 1.0))).engine_label ==
        "cxx-tip-dynamic");
  CHECK_THAT(err(tip_scene("stiffness = 1.0") + cant), Catch::Contains("tip.stiffness") && Catch::Contains("not both"));
  CHECK_THAT(err(tip_scene("") + "[tip.cantilever]\nyoungs_modulus = -1.0\n"),
             Catch::Contains("tip.cantilever.youngs_modulus") && Catch::Contains("> 0"));
  CHECK_THAT(err(tip_scene("model = \"dynamic\"\nstiffness = 1.0", 0.0)), Catch::Contains("tip.speed"));
}

}  // namespace NANOPUSH_UNITY_ID
