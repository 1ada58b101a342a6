// compare_engines (nanopush/engines/compare.hpp): the one rule behind `nanopush compare`,
// nanopush.compare and nanopush_compare. Oracles: faithful takes the F77 engine's steps (the
// same runs as run_engine, bit for bit); a convergence verdict is consistent with its own
// figures; the laws the F77 engine lacks are refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "nanopush/engines/compare.hpp"
#include "nanopush/engines/engines.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"
#include "support/support.hpp"

using namespace nanopush;
using nanopush::test::preset;
using nanopush::test::thesis_preset;

TEST_CASE("compare: faithful is judged by same steps and its runs are run_engine's", "[compare][regression]") {
  const Scene sc = preset("thesis/fig3_6a.toml");
  const EngineComparison r = compare_engines(sc, {});
  REQUIRE(r.complete);
  REQUIRE(r.failed() == nullptr);
  CHECK(r.kind == CompareKind::same_steps);
  CHECK(r.agree);
  CHECK(r.tolerance == 100 * r.rtol);
  REQUIRE(r.columns.size() == trajectory_columns().size() - 1);
  RunSettings a;
  a.engine = nanopush::Engine::cxx;
  a.method = Method::faithful;
  RunSettings b;
  b.engine = nanopush::Engine::f77;
  const Trajectory ta = run_engine(sc, a), tb = run_engine(sc, b);
  REQUIRE(ta.rows.size() == r.cxx.rows.size());
  REQUIRE(tb.rows.size() == r.f77.rows.size());
  for (std::size_t i = 0; i < ta.rows.size(); ++i) {
    CHECK(ta.rows[i] == r.cxx.rows[i]);
    CHECK(tb.rows[i] == r.f77.rows[i]);
  }
  for (const ColumnVerdict& v : r.columns) {
    double scale = 0, diff = 0;
    const std::size_t c = static_cast<std::size_t>(&v - r.columns.data()) + 1;
    for (std::size_t i = 0; i < ta.rows.size(); ++i) {
      scale = std::max({scale, std::fabs(ta.rows[i][c]), std::fabs(tb.rows[i][c])});
      diff = std::max(diff, std::fabs(ta.rows[i][c] - tb.rows[i][c]));
    }
    CHECK(v.name == trajectory_columns()[c]);
    CHECK(v.scale == scale);
    CHECK(v.max_abs_diff == diff);
    CHECK(v.ok == (v.relative <= r.tolerance));
  }
}

TEST_CASE("compare: modern is judged by convergence against both engines at rtol 1e-14", "[compare][regression]") {
  const Scene sc = thesis_preset(16);
  CompareSettings cs;
  cs.method = Method::modern;
  const EngineComparison r = compare_engines(sc, cs);
  REQUIRE(r.complete);
  CHECK(r.kind == CompareKind::convergence);
  CHECK(r.rtol_tight == kCompareTightRtol);
  CHECK(r.cxx_tight.rtol == kCompareTightRtol);
  CHECK(r.f77_tight.rtol == kCompareTightRtol);
  CHECK(r.agree);
  for (const ColumnVerdict& v : r.columns)
    CHECK(v.ok == (v.diff_tight <= v.error_cxx + v.error_f77 + kCompareRoundingFloor));
  // An impossible tolerance turns the verdict into same steps, and a disagreement.
  cs.tolerance = 1e-30;
  const EngineComparison t = compare_engines(sc, cs);
  CHECK(t.kind == CompareKind::same_steps);
  CHECK_FALSE(t.agree);
}

TEST_CASE("compare: the coulomb law and methods without an F77 peer are refused", "[compare][unit]") {
  const Scene sc = thesis_preset(18);
  CompareSettings cs;
  cs.law = Law::coulomb;
  CHECK_THROWS_AS(compare_engines(sc, cs), InputError);
  CHECK_THROWS_WITH(compare_engines(sc, cs), Catch::Contains("--law coulomb --method cvode"));
  cs.law = std::nullopt;
  cs.method = Method::cvode;
  CHECK_THROWS_AS(compare_engines(sc, cs), InputError);
  bool from_coulomb = true;
  CHECK(compare_law(sc, std::nullopt, &from_coulomb) == sc.surface.law);
  CHECK_FALSE(from_coulomb);
}

TEST_CASE("compare: a tip push has no F77 peer, and says so (not a method the user never gave)", "[compare][unit]") {
  const Scene tip = load_scene(std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/examples/tip_push_nanorod.toml");
  CHECK_THROWS_WITH(compare_engines(tip, CompareSettings{}), Catch::StartsWith("scene = tip_push_nanorod: a tip push: the F77 engine"));
}

TEST_CASE("compare: a tolerance that is no bound is refused (Python and C pass it through)", "[compare][unit]") {
  const Scene sc = thesis_preset(17);
  for (const double t : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    CompareSettings cs;
    cs.tolerance = t;
    INFO("tolerance = " << t);
    CHECK_THROWS_WITH(compare_engines(sc, cs), Catch::StartsWith("tolerance = " + fmt(t) + ": must be a finite number > 0"));
  }
}
