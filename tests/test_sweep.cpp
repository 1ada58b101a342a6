// The sweep library in memory: plans (axes, cartesian order) and evaluate_points, the entry
// point the reproduce steps use (docs/sweeps.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <tuple>
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
      CHECK(p.point(i)[0].number() == want[i][0]);
      CHECK(p.point(i)[1].number() == want[i][1]);
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
    const auto w = rectangle_friction_wrench_checked(27.5e-9, 50e-9, 1.0, plan.point(i)[0].number(),
                                                     plan.point(i)[1].number(), 1);
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
      const auto s = icor::solve_constrained_cubic(plan.point(i)[0].number(), rod.length, rod.gyration_squared(), method);
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

TEST_CASE("sweep: grid values as numpy.linspace and numpy.geomspace compute them", "[sweep][numeric]") {
  // numpy.linspace: step = (stop - start) / (n - 1), y_i = i * step + start, y_{n-1} = stop
  // (numpy/core/function_base.py); geomspace: 10^linspace(log10 start, log10 stop), the ends
  // as given, a negative range the positive one negated.
  auto lin = [](double a, double b, std::size_t n, std::size_t i) {
    if (i + 1 == n && n > 1) return b;
    const double step = (b - a) / static_cast<double>(n - 1);
    return static_cast<double>(i) * step + a;
  };
  for (const auto& [a, b, n] : std::vector<std::tuple<double, double, std::size_t>>{
           {-45e-9, 45e-9, 19}, {0, 1, 10}, {0.1, 0.7, 7}, {-3, 7, 1001}, {1e300, -1e300, 5}}) {
    const auto ax = sweep::parse_axis("R=" + csv_number(a) + ":" + csv_number(b) + ":" + std::to_string(n));
    REQUIRE(ax.values.size() == n);
    for (std::size_t i = 0; i < n; ++i) CHECK(ax.values[i].number() == lin(a, b, n, i));
  }
  // as numpy gives them: 0:45e-9:10 holds 5e-9 and 1e-8 exactly (FROM + (TO-FROM) * i/(N-1)
  // gave 4.999999999999999e-09), -45e-9:45e-9:19 holds 4.9999999999999985e-09 where numpy does
  CHECK(sweep::parse_axis("push.yn=0:45e-9:10").values[1].number() == 5e-9);
  CHECK(sweep::parse_axis("push.yn=0:45e-9:10").values[2].number() == 1e-8);
  CHECK(sweep::parse_axis("push.yn=-45e-9:45e-9:19").values[10].number() == 4.9999999999999985e-09);
  CHECK(sweep::parse_axis("R=0:1:11").values[3].number() == 0.30000000000000004);  // numpy: 3 * 0.1
  // a step that underflows: (i / (n - 1)) * delta + start
  CHECK(sweep::linspace_value(5e-324, 1e-323, 3, 1) == (1.0 / 2.0) * (1e-323 - 5e-324) + 5e-324);
  const auto g = sweep::parse_axis("R=-1e-3:-10:13", true);
  for (std::size_t i = 1; i + 1 < 13; ++i)
    CHECK(g.values[i].number() == -std::pow(10.0, lin(std::log10(1e-3), std::log10(10.0), 13, i)));
  CHECK(g.values.front().number() == -1e-3);
  CHECK(g.values.back().number() == -10.0);
}

TEST_CASE("sweep: a grid plan stores its axes, not its points", "[sweep][unit]") {
  std::vector<sweep::Axis> axes = {sweep::parse_axis("a=0:1:1000"), sweep::parse_axis("b=0:1:1000"),
                                   sweep::parse_axis("c=0:1:100")};
  const auto plan = sweep::cartesian(axes);
  CHECK(plan.size() == 100000000);  // 1e8 points, none built
  CHECK(plan.points.empty());
  const std::size_t i = 12345678;
  const auto pt = plan.point(i);
  CHECK(pt[0].number() == axes[0].values[i / 100000].number());
  CHECK(pt[1].number() == axes[1].values[(i / 100) % 1000].number());
  CHECK(pt[2].number() == axes[2].values[i % 100].number());
  CHECK(sweep::cartesian({sweep::parse_axis("x=1,2,3")}).identity_text() !=
        sweep::cartesian({sweep::parse_axis("x=1,2,4")}).identity_text());
}

TEST_CASE("sweep: the table is written in point order through a bounded window", "[sweep][unit]") {
  const auto task = sweep::make_friction_task({});
  const auto plan = sweep::cartesian({sweep::parse_axis("R=1e-8:1e-6:37"), sweep::parse_axis("alpha=0,1,2")});
  const auto rows = sweep::evaluate_points(plan, *task, 1);
  std::vector<std::size_t> order;
  std::vector<std::string> lines;
  sweep::OrderedTable table({}, plan, *task, 0, 1,
                            [&](std::size_t i, const std::string& line) {
                              order.push_back(i);
                              lines.push_back(line);
                            },
                            8);
  // rows arrive out of order (the last first), within the window of 8 positions
  CHECK(table.may_start(7));
  CHECK_FALSE(table.may_start(8));
  for (std::size_t i = 8; i-- > 0;) table.add(i, sweep::join_cells(rows[i]), false);
  CHECK(table.written() == 8);
  CHECK(table.may_start(15));
  for (std::size_t i = 8; i < rows.size(); ++i) table.add(i, sweep::join_cells(rows[i]), false);
  CHECK(table.complete());
  REQUIRE(order.size() == rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    CHECK(order[i] == i);
    CHECK(lines[i] == sweep::join_cells(rows[i]));
  }
  // run_local with a row sink and no file: the same rows in the same order, on 2 threads
  sweep::Options o;
  o.jobs = 2;
  o.window = 4;
  std::vector<std::string> streamed;
  o.row_sink = [&](std::size_t, const std::string& line) { streamed.push_back(line); };
  const auto r = sweep::run_local(plan, *task, o);
  CHECK(r.complete);
  REQUIRE(streamed.size() == rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) CHECK(streamed[i] == sweep::join_cells(rows[i]));
}

TEST_CASE("sweep: a journal of another plan is refused, the difference named", "[sweep][unit]") {
  const auto dir = nanopush::test::scratch_dir("sweep_journal_plan");
  const auto task = sweep::make_friction_task({});
  const auto a = sweep::cartesian({sweep::parse_axis("R=1e-8:1e-6:5")});
  const auto b = sweep::cartesian({sweep::parse_axis("R=1e-8:2e-6:5")});
  const auto path = dir / "t.csv.journal";
  {
    sweep::Journal j(path, sweep::sweep_identity(a, *task, 0, 1), sweep::plan_record(a, *task));
    j.append(0, sweep::evaluate_row(a, *task, 0));
  }
  {
    sweep::Journal again(path, sweep::sweep_identity(a, *task, 0, 1), sweep::plan_record(a, *task));
    CHECK(again.resumed().size() == 1);
  }
  const std::string msg = input_error_of([&] {
    sweep::Journal j(path, sweep::sweep_identity(b, *task, 0, 1), sweep::plan_record(b, *task));
  });
  CHECK_THAT(msg, Catch::Contains("belongs to a different sweep (axis 1: R=1e-8:1e-6:5 there, R=1e-8:2e-6:5 here)"));
  std::filesystem::remove_all(dir);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
