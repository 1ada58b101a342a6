// nanopush assemble's parts (planning/assemble.hpp): the overlap tests against independent
// geometry, the assignment, and a seeded three-bar assembly replayed push by push.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "nanopush/numerics/error.hpp"
#include "nanopush/planning/assemble.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "support/support.hpp"

using namespace nanopush;

namespace NANOPUSH_UNITY_ID {

struct Pt {
  double x, y;
};

std::vector<Pt> corners(const plan::Pose& p, double a, double b) {
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  std::vector<Pt> v;
  for (auto [u, w] : {std::pair{-a, -b}, {a, -b}, {a, b}, {-a, b}}) v.push_back({p.x + c * u - s * w, p.y + s * u + c * w});
  return v;
}

double cross(Pt o, Pt a, Pt b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool inside(const std::vector<Pt>& poly, Pt q) {  // convex, counter-clockwise
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (cross(poly[i], poly[(i + 1) % poly.size()], q) < 0) return false;
  return true;
}

bool segments_cross(Pt a, Pt b, Pt c, Pt d) {
  return cross(a, b, c) * cross(a, b, d) < 0 && cross(c, d, a) * cross(c, d, b) < 0;
}

/// Independent oracle: two convex polygons intersect iff a vertex of one lies in the other or
/// two edges cross.
bool polygons_intersect(const std::vector<Pt>& p, const std::vector<Pt>& q) {
  for (const Pt& v : p)
    if (inside(q, v)) return true;
  for (const Pt& v : q)
    if (inside(p, v)) return true;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < q.size(); ++j)
      if (segments_cross(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()])) return true;
  return false;
}

TEST_CASE("Assembly: bars_overlap agrees with polygon intersection, disc_touches_bar with sampled distance",
          "[assemble][unit]") {
  const double a = 5e-9, b = 50e-9;
  std::mt19937_64 rng(11);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  int overlapping = 0;
  for (int k = 0; k < 2000; ++k) {
    const plan::Pose p{0, 0, 2 * M_PI * u()}, q{120e-9 * (u() - 0.5), 120e-9 * (u() - 0.5), 2 * M_PI * u()};
    const bool oracle = polygons_intersect(corners(p, a, b), corners(q, a, b));
    INFO("q = " << q.x << ", " << q.y << ", " << q.theta);
    CHECK(plan::bars_overlap(p, q, a, b, 0.0) == oracle);
    overlapping += oracle ? 1 : 0;
  }
  CHECK(overlapping > 200);  // both answers are exercised
  CHECK(overlapping < 1800);
  // The gap: parallel bars 2a + g apart touch at gap g, not at a smaller one.
  CHECK(plan::bars_overlap({0, 0, 0}, {2 * a + 3e-9, 0, 0}, a, b, 3.1e-9));
  CHECK_FALSE(plan::bars_overlap({0, 0, 0}, {2 * a + 3e-9, 0, 0}, a, b, 2.9e-9));
  // A disc against the bar's outline sampled finely.
  for (int k = 0; k < 500; ++k) {
    const plan::Pose p{0, 0, 2 * M_PI * u()};
    const double cx = 140e-9 * (u() - 0.5), cy = 140e-9 * (u() - 0.5), r = 5e-9;
    const auto c = corners(p, a, b);
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < 4; ++e)
      for (int s = 0; s <= 4000; ++s) {
        const double t = s / 4000.0;
        const Pt on{c[e].x + t * (c[(e + 1) % 4].x - c[e].x), c[e].y + t * (c[(e + 1) % 4].y - c[e].y)};
        d = std::min(d, std::hypot(cx - on.x, cy - on.y));
      }
    if (inside(c, {cx, cy})) d = 0;
    if (std::fabs(d - r) < 0.05e-9) continue;  // within the sampling's resolution of the boundary
    CHECK(plan::disc_touches_bar(cx, cy, r, p, a, b, 0.0) == (d < r));
  }
}

TEST_CASE("Assembly: the assignment of least summed distance", "[assemble][unit]") {
  const double L2 = 50e-9;
  // Slots listed in another order than the bars: the exact assignment finds the permutation.
  const std::vector<plan::Pose> bars{{0, 0, 0}, {100e-9, 0, 0}, {200e-9, 0, 0}, {300e-9, 0, 0}};
  const std::vector<plan::Pose> slots{{305e-9, 10e-9, 0.1}, {5e-9, 10e-9, 0.1}, {205e-9, 10e-9, 0.1}, {105e-9, 10e-9, 0.1}};
  CHECK(plan::assign_slots(bars, slots, L2, true) == std::vector<int>{1, 3, 2, 0});
  // Beyond 8 bars: greedy then exchanges; no exchange of two slots lowers the sum.
  std::mt19937_64 rng(5);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<plan::Pose> many, targets;
  for (int i = 0; i < 12; ++i) {
    many.push_back({1e-6 * u(), 1e-6 * u(), u()});
    targets.push_back({1e-6 * u(), 1e-6 * u(), u()});
  }
  const auto s = plan::assign_slots(many, targets, L2, true);
  std::vector<int> sorted = s;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < 12; ++i) CHECK(sorted[static_cast<std::size_t>(i)] == i);  // a permutation
  auto c = [&](int i, int k) { return plan::pose_cost(many[static_cast<std::size_t>(i)], targets[static_cast<std::size_t>(k)], L2, true); };
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j)
      CHECK(c(i, s[i]) + c(j, s[j]) <= c(i, s[j]) + c(j, s[i]) + 1e-15);
}

TEST_CASE("Assembly: three bars into a pattern, replayed push by push, never touching", "[assemble][numeric]") {
  const Scene scene = parse_scene(test::kTipSceneText, "bar.toml");
  const double a = scene.geometry.a, b = scene.geometry.b;
  const std::vector<plan::Pose> bars{{0, 0, 0}, {60e-9, 0, 0}, {120e-9, 0, 0}};
  const std::vector<plan::Pose> slots{{140e-9, 15e-9, 0.15}, {20e-9, 15e-9, 0.15}, {80e-9, 15e-9, 0.15}};
  plan::AssemblyOptions o;
  o.plan.tolerance_distance = 2e-9;
  o.plan.tolerance_angle = 0.02;
  const auto r = plan::assemble(scene, bars, slots, o);
  INFO(r.message);
  REQUIRE(r.assembled());
  CHECK(r.slot_of == std::vector<int>{1, 2, 0});
  CHECK(r.moves.size() == 3);
  // Independent replay: each bar's pushes from where it stands, in the order made; at every
  // sample the bar stays clear of the others (polygon oracle), and it ends at its slot.
  std::vector<plan::Pose> poses = bars;
  Scene dense = scene;
  dense.set("solver.samples", 64);
  for (const auto& m : r.moves) {
    const auto i = static_cast<std::size_t>(m.object);
    plan::Pose at = poses[i];
    for (const auto& p : m.plan.pushes) {
      const Trajectory tr = run_scene(plan::push_scene(dense, at, p));
      for (const auto& row : tr.rows)
        for (std::size_t j = 0; j < poses.size(); ++j)
          if (j != i) CHECK_FALSE(polygons_intersect(corners({row[col::x], row[col::y], row[col::theta]}, a, b), corners(poses[j], a, b)));
      at = p.end;
    }
    poses[i] = at;
    const auto& slot = slots[static_cast<std::size_t>(m.slot)];
    CHECK(std::hypot(at.x - slot.x, at.y - slot.y) <= o.plan.tolerance_distance);
    CHECK(std::fabs(plan::angle_error(at.theta, slot.theta, true)) <= o.plan.tolerance_angle);
    CHECK(at.x == r.final_poses[i].x);
  }
}

TEST_CASE("Assembly: bad input names what was written", "[assemble][unit]") {
  const Scene scene = parse_scene(test::kTipSceneText, "bar.toml");
  plan::AssemblyOptions o;
  const std::vector<plan::Pose> two{{0, 0, 0}, {60e-9, 0, 0}};
  CHECK_THROWS_WITH(plan::assemble(scene, {}, {}, o), Catch::Contains("at least one bar"));
  CHECK_THROWS_WITH(plan::assemble(scene, two, {{0, 0, 0}}, o), Catch::Contains("one slot per bar (2)"));
  CHECK_THROWS_WITH(plan::assemble(scene, {{0, 0, 0}, {5e-9, 0, 0}}, two, o), Catch::Contains("bar 2"));
  CHECK_THROWS_WITH(plan::assemble(scene, two, {{0, 0, 0}, {0, 20e-9, 0.1}}, o), Catch::Contains("slot 2"));
  CHECK_THROWS_WITH(plan::assemble(scene, {{0, 0, 0}, {60e-9, 0, NAN}}, two, o), Catch::Contains("finite"));
}

}  // namespace NANOPUSH_UNITY_ID
