// The sweep library in memory: plans (axes, cartesian order) and evaluate_points, the entry
// point the reproduce steps use (docs/sweeps.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "nanopush/models/friction.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/sweeps/sweep.hpp"
#include "support/support.hpp"

using namespace nanopush;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
using nanopush::test::input_error_of;


}  // namespace

TEST_CASE("sweep: axes and the cartesian order", "[sweep][unit]") {
  SECTION("FROM:TO:N hits both ends exactly") {
    const auto a = sweep::parse_axis("R=1e-9:3e-7:7");
    REQUIRE(a.key == "R");
    REQUIRE(a.values.size() == 7);
    CHECK(a.values.front().number() == 1e-9);
    CHECK(a.values.back().number() == 3e-7);
    for (std::size_t i = 1; i < a.values.size(); ++i) CHECK(a.values[i].number() > a.values[i - 1].number());
    const auto g = sweep::parse_axis("R=1e-9:1e-6:4", true);
    REQUIRE(g.values.size() == 4);
    CHECK(g.values.front().number() == 1e-9);
    CHECK(g.values.back().number() == 1e-6);
    CHECK(g.values[1].number() == Approx(1e-8).epsilon(1e-12));
    const auto one = sweep::parse_axis("yn=5e-8:9e-8:1");
    REQUIRE(one.values.size() == 1);
    CHECK(one.values[0].number() == 5e-8);
  }
  SECTION("a list") {
    const auto a = sweep::parse_axis("alpha=0,0.5,1.5707963267948966");
    REQUIRE(a.values.size() == 3);
    CHECK(a.values[1].number() == 0.5);
    CHECK(a.values[2].number() == 1.5707963267948966);
  }
  SECTION("the last axis varies fastest") {
    const auto p = sweep::cartesian({sweep::parse_axis("R=1,2"), sweep::parse_axis("alpha=10,20,30")});
    REQUIRE(p.keys == std::vector<std::string>{"R", "alpha"});
    REQUIRE(p.size() == 6);
    const double want[6][2] = {{1, 10}, {1, 20}, {1, 30}, {2, 10}, {2, 20}, {2, 30}};
    for (std::size_t i = 0; i < 6; ++i) {
      CHECK(p.points[i][0].number() == want[i][0]);
      CHECK(p.points[i][1].number() == want[i][1]);
      const auto s = p.settings(i);
      CHECK(s[0].first == "R");
      CHECK(s[1].second.number() == want[i][1]);
    }
  }
  SECTION("bad specs name the option") {
    for (const std::string spec : {"R", "=1:2:3", "R=1:2", "R=1:2:0", "R=1:2:2.5", "R=1,,2", "R=1:inf:3"}) {
      INFO(spec);
      const auto msg = input_error_of([&] { (void)sweep::parse_axis(spec); });
      CHECK(msg.find("--vary") != std::string::npos);
    }
    CHECK(input_error_of([] { (void)sweep::parse_axis("R=a:2:3"); }).find("R") != std::string::npos);  // the key
    CHECK(input_error_of([] { (void)sweep::parse_axis("R=-1:1:3", true); }).find("--vary-log") != std::string::npos);
    CHECK(input_error_of([] { (void)sweep::parse_axis("R=1,2", true); }).find("--vary-log") != std::string::npos);
    CHECK(input_error_of([] {
            (void)sweep::cartesian({sweep::parse_axis("R=1,2"), sweep::parse_axis("R=3,4")});
          }).find("--vary") != std::string::npos);
  }
}

TEST_CASE("sweep: evaluate_points gives evaluate_row's rows in point order", "[sweep][unit]") {
  // A friction grid with a failing point (R < 0) and an iCOR grid (yn beyond the rod fails).
  const auto fr = sweep::make_friction_task({{"a", 27.5e-9}, {"b", 50e-9}});
  const auto pf = sweep::cartesian({sweep::parse_axis("R=-1e-9,0,1e-9,3e-8,2e-7,1e-5"),
                                    sweep::parse_axis("alpha=0:3.141592653589793:5")});
  const auto ic = sweep::make_icor_task({{"force", 1e-6}});
  const auto pi = sweep::cartesian({sweep::parse_axis("yn=0:400e-9:9"), sweep::parse_axis("mu=0.05,0.1")});
  for (const auto* c : {&pf, &pi}) {
    const auto& plan = *c;
    const auto& task = c == &pf ? *fr : *ic;
    std::vector<std::vector<std::string>> one_by_one;
    for (std::size_t i = 0; i < plan.size(); ++i) one_by_one.push_back(sweep::evaluate_row(plan, task, i));
    bool some_failed = false, some_ok = false;
    for (const auto& r : one_by_one) (sweep::row_failed(r) ? some_failed : some_ok) = true;
    CHECK(some_failed);  // a failing point keeps its row, status and message
    CHECK(some_ok);
    for (unsigned jobs : {1u, 2u}) {
      INFO(task.name() << ", jobs " << jobs);
      CHECK(sweep::evaluate_points(plan, task, jobs) == one_by_one);
    }
  }
}

TEST_CASE("sweep: cells read back exactly, columns by name", "[sweep][unit]") {
  const auto task = sweep::make_friction_task({{"a", 27.5e-9}, {"b", 50e-9}});
  const auto plan = sweep::cartesian({sweep::parse_axis("R=0:2e-7:11"), sweep::parse_axis("alpha=0,1")});
  const auto rows = sweep::evaluate_points(plan, *task, 2);
  const auto ifx = sweep::column_index(plan, *task, "fx"), imf = sweep::column_index(plan, *task, "mf");
  CHECK(ifx == 3);
  CHECK(sweep::column_index(plan, *task, "alpha") == 2);
  CHECK_THROWS_AS(sweep::column_index(plan, *task, "nope"), InputError);
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const auto w = rectangle_friction_wrench_checked(27.5e-9, 50e-9, 1.0, plan.points[i][0].number(),
                                                     plan.points[i][1].number(), 1);
    CHECK(sweep::cell_number(rows[i][ifx]) == w.fx);
    CHECK(sweep::cell_number(rows[i][imf]) == w.mf);
  }
  CHECK(std::isnan(sweep::cell_number("")));
  CHECK(sweep::cell_number("3e-08") == 3e-8);
  CHECK(sweep::cell_number("-0") == 0.0);
  CHECK_THROWS_AS(sweep::cell_number("1x"), InputError);
}

TEST_CASE("sweep: the icor task gives both branches of eq 5.4 from the chosen cubic solver", "[sweep][unit]") {
  const auto rod = icor::nanorod();
  for (const char* solver : {"brent", "eigen"}) {
    INFO(solver);
    const auto task = sweep::make_icor_task({{"cubic", solver}});
    const auto plan = sweep::cartesian({sweep::parse_axis("yn=0:295e-9:12")});
    const auto rows = sweep::evaluate_points(plan, *task, 2);
    const auto ineg = sweep::column_index(plan, *task, "R_constrained_negative");
    const auto ipos = sweep::column_index(plan, *task, "R_constrained_positive");
    const auto method = std::string(solver) == "brent" ? icor::CubicMethod::Brent : icor::CubicMethod::Eigen;
    for (std::size_t i = 0; i < plan.size(); ++i) {
      // The oracle: the solver called directly (the task adds nothing but the cell).
      const auto s = icor::solve_constrained_cubic(plan.points[i][0].number(), rod.length, rod.gyration_squared(), method);
      REQUIRE(!sweep::row_failed(rows[i]));
      CHECK(rows[i][ineg] == (s.negative ? csv_number(*s.negative) : std::string()));
      CHECK(rows[i][ipos] == (s.positive ? csv_number(*s.positive) : std::string()));
    }
  }
  // A choice is checked with the plan, before any work: a word the task does not know, or a
  // word for a number.
  const auto task = sweep::make_icor_task({});
  CHECK_THROWS_AS(sweep::make_icor_task({{"cubic", "lapack"}}), InputError);
  CHECK_THROWS_AS(sweep::make_icor_task({{"cubic", 1.0}}), InputError);
  CHECK_THROWS_AS(sweep::table_columns(sweep::cartesian({sweep::parse_axis("cubic=brent,qr")}), *task), InputError);
  CHECK_THROWS_AS(sweep::table_columns(sweep::cartesian({sweep::parse_axis("yn=1e-8,abc")}), *task), InputError);
  CHECK_NOTHROW(sweep::table_columns(sweep::cartesian({sweep::parse_axis("cubic=brent,eigen")}), *task));
  CHECK_THROWS_AS(sweep::parse_axis("yn=0:abc:3"), InputError);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
