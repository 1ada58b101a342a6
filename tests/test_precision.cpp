// Precision as a user choice (issue 7): RunSettings::precision / solver.precision = double |
// long | quad on the smooth-surface nanobar, against the exact pendulum evaluated in quad.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "nanopush/numerics/bulirsch_stoer.hpp"
#include "nanopush/numerics/elliptic.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/models/rigid_body.hpp"
#include "nanopush/engines/engines.hpp"
#include "support/support.hpp"

using namespace nanopush;
using Catch::Matchers::Contains;
using num::quad;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

std::string preset(const std::string& name) {
  return std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/thesis/" + name + ".toml";
}

/// Max |theta - theta_exact| over the outputs [rad], the exact pendulum in quad (theta* and
/// the torque amplitude from the push point in quad). `rounded`: use the rows (double)
/// even when the run kept its extended-precision states.
double theta_error(const Scene& sc, const Trajectory& tr, bool rounded = false) {
  const quad pbx = sc.push.pbx, pby = sc.push.pby;
  const quad theta_eq = quad(sc.push.beta) - num::atan2(pby, pbx);
  const Pendulum<quad> ex(theta_eq, quad(sc.initial[kTheta]), quad(sc.push.force) * num::sqrt(pbx * pbx + pby * pby),
                          quad(sc.inertia));
  quad e = 0;
  for (std::size_t i = 0; i < tr.rows.size(); ++i) {
    const quad th = rounded || tr.extended.empty() ? quad(tr.rows[i][3]) : tr.extended[i][kTheta];
    e = std::max(e, num::abs(th - ex.theta(quad(tr.rows[i][0]))));
  }
  return static_cast<double>(e);
}

RunSettings settings(const char* precision, const char* method, double rtol) {
  RunSettings rs;
  rs.engine = nanopush::Engine::cxx;
  rs.precision = parse_optional_choice<Precision>("precision", precision);
  rs.method = parse_optional_choice<Method>("method", method);
  rs.rtol = rtol;
  return rs;
}

/// The rows are the extended states rounded to double, and the labels say the precision.
void check_rows_are_rounded(const Trajectory& tr, const std::string& precision) {
  CHECK(to_string(tr.precision) == precision);
  CHECK(tr.engine_label.ends_with("-" + precision));
  REQUIRE(tr.extended.size() == tr.rows.size());
  for (std::size_t i = 0; i < tr.rows.size(); ++i)
    for (int c = 0; c < kStateSize; ++c)
      REQUIRE(tr.rows[i][static_cast<std::size_t>(c) + 1] == static_cast<double>(tr.extended[i][static_cast<std::size_t>(c)]));
}

}  // namespace

TEST_CASE("precision quad: fig3_6a modern at rtol 1e-24 reaches 1e-20 in theta", "[precision][numeric]") {
  const Scene sc = load_scene(preset("fig3_6a"));
  const Trajectory tr = run_engine(sc, settings("quad", "modern", 1e-24));
  check_rows_are_rounded(tr, "quad");
  CHECK(tr.engine_label == "cxx-modern-quad");
  const double e = theta_error(sc, tr);
  INFO("quad modern rtol 1e-24: |dtheta| " << e << ", naccpt " << tr.stats.naccpt << ", nfcn " << tr.stats.nfcn);
  // Measured 2.7e-24 (132 accepted steps, 17 674 RHS; 4.3e-23 with 83 steps and 14 046 RHS
  // before the interpolant was held to the steps' tolerance). The issue asks for 1e-20; the
  // bound for dense output counts the local errors of naccpt steps: 5 naccpt rtol = 6.6e-22.
  CHECK(e <= 1e-20);
  CHECK(e <= 5 * static_cast<double>(tr.stats.naccpt) * 1e-24);
  // Rounded to double, the rows carry the result to the last bit of theta: within half an
  // ulp of the largest |theta| (2 theta* + 0.5 = 2.54 rad: 2.2e-16) plus the error above,
  // where a double-precision run stops near 1e-14.
  double thmax = 0;
  for (const auto& r : tr.rows) thmax = std::max(thmax, std::fabs(r[3]));
  const double half_ulp = (std::nextafter(thmax, 4.0) - thmax) / 2;
  CHECK(theta_error(sc, tr, true) <= half_ulp + e);
}

TEST_CASE("precision long: rtol 1e-17 beats the floor of double", "[precision][numeric]") {
  const Scene sc = load_scene(preset("fig3_6a"));
  // The floor of double: the best theta error over rtol 1e-10 ... 1e-16, both methods
  // (measured 1.4e-14, faithful at rtol 1e-10 and 1e-12; tighter tolerances only add rounding).
  // The modern method stops at 1e-15: below 4 eps (8.9e-16) dense output refuses the
  // tolerance (its step-size control would follow rounding; test below).
  double floor_double = 1;
  for (const char* method : {"faithful", "modern"})
    for (double rtol : {1e-10, 1e-11, 1e-12, 1e-13, 1e-14, 1e-15, 1e-16}) {
      if (std::string(method) == "modern" && rtol < 1e-15) continue;
      const Trajectory tr = run_engine(sc, settings("double", method, rtol));
      CHECK(tr.extended.empty());
      CHECK(tr.precision == Precision::double_);
      floor_double = std::min(floor_double, theta_error(sc, tr));
    }
  INFO("double floor " << floor_double);
  CHECK(floor_double > 1e-15);  // it is a floor: double cannot resolve the last digits
  for (const char* method : {"faithful", "modern"}) {
    const Trajectory tr = run_engine(sc, settings("long", method, 1e-17));
    check_rows_are_rounded(tr, "long");
    const double e = theta_error(sc, tr), er = theta_error(sc, tr, true);
    INFO("long " << method << " rtol 1e-17: |dtheta| " << e << " (rows in double " << er << "), nfcn "
                 << tr.stats.nfcn);
    // Measured: faithful 2.2e-17, modern 7.6e-17 (3.2e-16 before the interpolant was held to
    // the steps' tolerance), against 1.4e-14 for double:
    // at least 10x below the floor of double, also after rounding to double.
    CHECK(e <= floor_double / 10);
    CHECK(er <= floor_double / 10);
  }
}

TEST_CASE("precision: the modern method refuses rtol below 4 eps of its precision, naming the field and range",
          "[precision][input][unit]") {
  const Scene sc = load_scene(preset("fig3_6a"));
  // double: 4 eps = 8.88e-16; the same rtol is fine in long double, and for the faithful method
  CHECK_THROWS_AS(run_engine(sc, settings("double", "modern", 1e-16)), InputError);
  CHECK_THROWS_WITH(run_engine(sc, settings("double", "modern", 1e-16)),
                    Contains("rtol = 1e-16") && Contains("8.88e-16") && Contains("4 eps of double"));
  CHECK_THROWS_WITH(run_engine(sc, settings("long", "modern", 1e-19)),
                    Contains("rtol = 1e-19") && Contains("4 eps of long"));
  CHECK_NOTHROW(run_engine(sc, settings("double", "modern", 1e-15)));
  CHECK_NOTHROW(run_engine(sc, settings("long", "modern", 1e-16)));
  CHECK_NOTHROW(run_engine(sc, settings("double", "faithful", 1e-16)));
  // the engine itself says the same when called directly (status bad_input, no steps taken)
  const std::vector<double> tout = {0.0, 1e-9};
  std::vector<double> y(sc.initial.begin(), sc.initial.end());
  BulirschStoer<double, 6> bs(BsOptions<double>::modern(1e-16, {1e-25}));
  const BsResult r = bs.integrate(SmoothBarRhs(sc.mass, sc.inertia, sc.push), 0.0, y.data(),
                                  std::span<const double>(tout), [](std::size_t, double, const double*) {});
  CHECK(r.status == BsStatus::bad_input);
  CHECK_THAT(r.message, Contains("rtol = 1e-16") && Contains("4 eps of double"));
  CHECK(r.nfcn == 0);
}

TEST_CASE("precision double is the default, and extended precision takes the same steps at rtol 1e-12",
          "[precision][numeric]") {
  const Scene sc = load_scene(preset("fig3_6a"));
  RunSettings def;  // default settings: the scene's precision (fig3_6a: double)
  CHECK_FALSE(def.precision.has_value());
  const Trajectory a = run_engine(sc, def);
  const Trajectory b = run_engine(sc, settings("double", "faithful", 0));
  CHECK(a.engine_label == "cxx-faithful");
  CHECK(a.precision == Precision::double_);
  CHECK(a.extended.empty());
  REQUIRE(a.rows.size() == b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i) CHECK(a.rows[i] == b.rows[i]);
  // At the scene's rtol 1e-12 the error estimates lie far above the rounding of either
  // scalar: the same steps (same counts), other digits.
  const Trajectory q = run_engine(sc, settings("quad", "faithful", 0));
  CHECK(q.engine_label == "cxx-faithful-quad");
  CHECK(q.stats.nfcn == a.stats.nfcn);
  CHECK(q.stats.naccpt == a.stats.naccpt);
}

TEST_CASE("precision other than double is refused where the RHS is double only", "[precision][unit]") {
  const Scene smooth = load_scene(preset("fig3_6a"));
  const Scene rough = load_scene(preset("fig3_27"));
  RunSettings rs;
  rs.precision = Precision::quad;
  rs.engine = nanopush::Engine::f77;
  CHECK_THROWS_AS(run_engine(smooth, rs), InputError);
  CHECK_THROWS_WITH(run_engine(smooth, rs), Contains("precision = quad") && Contains("engine = cxx") &&
                                               Contains("F77"));
  rs.engine = nanopush::Engine::cxx;
  rs.precision = Precision::long_;
  // Rough scenes: the modern method under the thesis and coulomb laws (test_rough_extended.cpp);
  // the printed law's forms, the F77 routine's forms (faithful) and CVODE are double.
  rs.law = Law::printed;
  CHECK_THROWS_AS(run_engine(rough, rs), InputError);
  CHECK_THROWS_WITH(run_engine(rough, rs), Contains("precision = long") && Contains("printed law"));
  rs.law = Law::thesis;
  rs.method = Method::faithful;
  CHECK_THROWS_WITH(run_engine(rough, rs), Contains("precision = long") && Contains("F77 routine's friction forms"));
  rs.law = Law::coulomb;
  rs.method = Method::cvode;
  CHECK_THROWS_WITH(run_engine(rough, rs), Contains("precision = long") && Contains("CVODE is double"));
  rs.method = Method::automatic;
  CHECK(resolve_settings(rough, rs).method == Method::modern);
  // A name outside the table is refused where it is read (the front ends' parse_choice).
  CHECK_THROWS_AS(parse_optional_choice<Precision>("precision", "bogus"), InputError);
  CHECK_THROWS_WITH(parse_optional_choice<Precision>("precision", "bogus"),
                    Contains("precision = bogus") && Contains("must be double, long or quad"));
  try {
    (void)parse_optional_choice<Precision>("precision", "bogus");
    FAIL("no InputError");
  } catch (const InputError& e) {
    CHECK(e.field() == "precision");
  }
  // double stays allowed everywhere.
  RunSettings d;
  d.precision = Precision::double_;
  d.engine = nanopush::Engine::f77;
  CHECK(resolve_settings(rough, d).precision == Precision::double_);
}

TEST_CASE("solver.precision in a scene file", "[precision][scene][unit]") {
  const std::string base = nanopush::test::kBaseSceneText + R"([initial]
theta = -0.5
[solver]
t_end = 1.6e-9
samples = 5
)";
  CHECK(parse_scene(base, "s").solver.precision == Precision::double_);
  const Scene sc = parse_scene(base + "precision = \"long\"\n", "s");
  CHECK(sc.solver.precision == Precision::long_);
  CHECK_THROWS_WITH(parse_scene(base + "precision = \"octuple\"\n", "s"),
                    Contains("solver.precision = \"octuple\"") && Contains("double, long, quad"));
  CHECK_THROWS_WITH(parse_scene(base + "precision = \"quad\"\nengine = \"f77\"\n", "s"),
                    Contains("solver.precision = \"quad\"") && Contains("F77"));
  CHECK_THROWS_WITH(
      parse_scene(base + "precision = \"quad\"\n[surface]\nkind = \"rough\"\nmu = 0.1\nlaw = \"printed\"\n", "s"),
      Contains("solver.precision = \"quad\"") && Contains("printed law"));
  CHECK(parse_scene(base + "precision = \"quad\"\n[surface]\nkind = \"rough\"\nmu = 0.1\n", "s").solver.precision ==
        Precision::quad);
  // Unset takes the scene's precision (and its method, auto: modern in extended precision);
  // the settings' value overrides it.
  RunSettings from_scene;
  from_scene.precision = std::nullopt;
  const Trajectory tl = run_engine(sc, from_scene);
  CHECK(tl.precision == Precision::long_);
  CHECK(tl.engine_label == "cxx-modern-long");
  CHECK(run_engine(sc, RunSettings{}).precision == Precision::long_);
  RunSettings in_double;
  in_double.precision = Precision::double_;
  CHECK(run_engine(sc, in_double).precision == Precision::double_);
  // A scene's extended precision with the F77 engine asked on the command line: the error
  // names the scene's key.
  from_scene.engine = nanopush::Engine::f77;
  CHECK_THROWS_WITH(run_engine(sc, from_scene), Contains("solver.precision = long"));
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
