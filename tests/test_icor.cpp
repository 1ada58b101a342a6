// iCOR toolkit (issue 5): Table 5.1 from four solvers in two languages, the error analysis
// of section 5.6.1.1, the change of coordinates between eqs 4.2, 4.3 and 4.13, cubic
// residuals, no-NaN and bad-input behaviour, and the friction-coefficient uncertainty.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "nanopush/engines/f77_icor.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/numerics/roots.hpp"
#include "support/support.hpp"

using namespace nanopush;
using icor::CubicMethod;
using icor::CubicSolution;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
const double kL = icor::nanorod().length;
const double kK2 = icor::nanorod().gyration_squared();

struct Solver {
  const char* name;
  CubicSolution (*solve)(double yn);
};

const std::vector<Solver>& solvers() {
  static const std::vector<Solver> s = {
      {"brent C++", [](double yn) { return icor::solve_constrained_cubic(yn, kL, kK2, CubicMethod::Brent); }},
      {"eigen C++", [](double yn) { return icor::solve_constrained_cubic(yn, kL, kK2, CubicMethod::Eigen); }},
      {"brent F77", [](double yn) { return f77::icor_cubic(yn, kL, kK2, f77::IcorCubicMethod::Brent); }},
      {"lapack F77", [](double yn) { return f77::icor_cubic(yn, kL, kK2, f77::IcorCubicMethod::Lapack); }},
  };
  return s;
}

using nanopush::test::kRelAgree;
using nanopush::test::rel;

}  // namespace

TEST_CASE("nanorod parameters follow docs/models.md section D", "[icor][unit]") {
  const auto rod = icor::nanorod();
  CHECK(rod.length == 590e-9);
  CHECK(rod.half_length() == 295e-9);
  const double m = 2267.0 * M_PI * 13.5e-9 * 13.5e-9 * 590e-9;
  CHECK(rel(rod.mass(), m) < 4 * kEps);
  CHECK(rel(rod.inertia(), m * 590e-9 * 590e-9 / 12.0) < 8 * kEps);
  CHECK(rel(rod.gyration_squared(), rod.inertia() / rod.mass()) < 8 * kEps);
  // Parsegian rod-plane force, written out: F = L H sqrt(d) / (16 z0^(5/2)), d = 27 nm.
  const double Fv = 590e-9 * rod.hamaker * std::sqrt(27e-9) / (16.0 * std::pow(0.2e-9, 2.5));
  CHECK(rel(rod.vdw_force(), Fv) < 8 * kEps);
  CHECK(rel(rod.load(), m * 9.81 + Fv) < 8 * kEps);
}

TEST_CASE("Table 5.1: every row matches the printed digits from all four solvers", "[icor][regression]") {
  for (const auto& row : icor::thesis_table_5_1()) {
    for (const auto& s : solvers()) {
      INFO("yn = " << row.yn << " m, solver " << s.name);
      const auto sol = s.solve(row.yn);
      REQUIRE(sol.negative.has_value());
      const double shown = icor::round_significant(-*sol.negative, row.digits());
      CHECK(rel(shown, row.printed) < 1e-12);
      CHECK(sol.max_residual <= 1e-12);
    }
  }
}

TEST_CASE("Table 5.1: Brent, Eigen and LAPACK agree to 1e-12 relative on both branches",
          "[icor][cross-language][regression]") {
  for (const auto& row : icor::thesis_table_5_1()) {
    const auto ref = solvers()[0].solve(row.yn);
    for (const auto& s : solvers()) {
      INFO("yn = " << row.yn << " m, solver " << s.name);
      const auto sol = s.solve(row.yn);
      REQUIRE(sol.real_roots.size() == ref.real_roots.size());
      CHECK(sol.at_infinity == ref.at_infinity);
      CHECK(sol.complex_roots == ref.complex_roots);
      for (std::size_t i = 0; i < sol.real_roots.size(); ++i) CHECK(rel(sol.real_roots[i], ref.real_roots[i]) <= kRelAgree);
      REQUIRE(sol.positive.has_value() == ref.positive.has_value());
      if (sol.positive) CHECK(rel(*sol.positive, *ref.positive) <= kRelAgree);
    }
  }
}

TEST_CASE("Erratum 9: at yn = 1, 2 nm the two branches differ; at yn = 0 they are +-b/3 exactly",
          "[icor][regression]") {
  const double b = 0.5 * kL;
  // yn = 0: the quadratic -3 k2 R^2 + k2 (b^2 - 2 k2) = 0, R = +-sqrt((b^2 - 2 k2)/3) = +-b/3.
  const double r0 = std::sqrt((b * b - 2.0 * kK2) / 3.0);
  CHECK(rel(r0, b / 3.0) < 4 * kEps);
  for (const auto& s : solvers()) {
    INFO("solver " << s.name);
    const auto z = s.solve(0.0);
    CHECK(z.at_infinity == 1);
    REQUIRE(z.real_roots.size() == 2);
    CHECK(rel(-*z.negative, r0) < 4 * kEps);
    CHECK(rel(*z.positive, r0) < 4 * kEps);
    const auto y1 = s.solve(1e-9), y2 = s.solve(2e-9);
    REQUIRE((y1.positive && y2.positive && y1.negative && y2.negative));
    CHECK(icor::round_significant(*y1.negative, 4) == Approx(-9.822e-8).epsilon(1e-12));
    CHECK(icor::round_significant(*y2.negative, 4) == Approx(-9.811e-8).epsilon(1e-12));
    // The positive roots are larger than the printed +-9.822e-8 and +-9.811e-8.
    CHECK(icor::round_significant(*y1.positive, 4) == Approx(9.844e-8).epsilon(1e-12));
    CHECK(icor::round_significant(*y2.positive, 4) == Approx(9.856e-8).epsilon(1e-12));
    CHECK(*y1.positive + *y1.negative > 2e-10);
    CHECK(*y2.positive + *y2.negative > 4e-10);
    // Three real roots there: the third runs off towards infinity as yn -> 0, near 3 k2/(2 yn).
    REQUIRE(y1.real_roots.size() == 3);
    CHECK(rel(y1.real_roots[2], 3.0 * kK2 / (2.0 * 1e-9)) < 1e-3);
  }
}

TEST_CASE("Section 5.6.1.1: the two sample standard deviations", "[icor][regression]") {
  for (auto m : {CubicMethod::Brent, CubicMethod::Eigen}) {
    const auto e = icor::error_analysis(kL, kK2, m);
    CHECK(e.n == 296);
    // Printed to four decimals. 49.698725... rounds and truncates to 49.6987.
    CHECK(std::trunc(e.std_unknown_pressure_nm * 1e4) / 1e4 == Approx(icor::kThesisStdUnknownPressure).epsilon(1e-12));
    CHECK(std::round(e.std_unknown_pressure_nm * 1e4) / 1e4 == Approx(icor::kThesisStdUnknownPressure).epsilon(1e-12));
    // 5.395080... truncates to the printed 5.3950 (rounding would give 5.3951: docs/errata.md).
    CHECK(std::trunc(e.std_constrained_nm * 1e4) / 1e4 == Approx(icor::kThesisStdConstrained).epsilon(1e-12));
    CHECK(std::fabs(e.std_constrained_nm - icor::kThesisStdConstrained) < 1e-4);
    CHECK(std::round(e.std_constrained_nm * 1e4) / 1e4 == Approx(5.3951).epsilon(1e-12));
  }
}

TEST_CASE("Eqs 4.2 and 4.3 are eq 4.13 after the change of coordinates (1e-14)", "[icor][unit]") {
  const double b = 0.5 * kL;
  for (int i = 0; i <= 590; ++i) {
    const double yn = b * i / 590.0;
    INFO("yn = " << yn);
    const double r413 = icor::unknown_pressure(yn, kL);
    CHECK(rel(r413, std::sqrt(b * b + yn * yn) - yn) <= 1e-14);
    CHECK(rel(icor::falvo(yn, kL), r413) <= 1e-14);
    CHECK(rel(icor::li(yn, kL), r413) <= 1e-14);
    CHECK(rel(f77::icor_formula(NP_F77_ICOR_EQ_4_2, yn, kL), r413) <= 1e-14);
    CHECK(rel(f77::icor_formula(NP_F77_ICOR_EQ_4_3, yn, kL), r413) <= 1e-14);
    CHECK(rel(f77::icor_formula(NP_F77_ICOR_EQ_4_13, yn, kL), r413) <= 1e-14);
    CHECK(rel(f77::icor_formula(NP_F77_ICOR_EQ_4_1, yn, kL), icor::experimental_fit(yn, kL)) <= 1e-14);
  }
  // Native coordinates: Li's other branch (push right of the middle) mirrors the first.
  for (double l : {0.0, 0.1 * kL, 0.3 * kL}) CHECK(rel(icor::li_position(kL - l, kL), kL - icor::li_position(l, kL)) < 1e-14);
  // Eq 4.1 at the ends: R = b at the CM, and b (1 - 1/sqrt 2) at yn = b.
  CHECK(icor::experimental_fit(0.0, kL) == b);
  CHECK(rel(icor::experimental_fit(b, kL), b * (1.0 - 1.0 / std::sqrt(2.0))) < 4 * kEps);
}

TEST_CASE("Force-iCOR relations 4.7, 4.8, 4.10, 4.11 are consistent", "[icor][unit]") {
  const auto rod = icor::nanorod();
  const double W = rod.load(), b = rod.half_length();
  for (double mu : {0.01, 0.1, 1.0})
    for (double yn : {0.0, 10e-9, 100e-9, 295e-9}) {
      INFO("mu = " << mu << " yn = " << yn);
      const double Fmin = icor::minimum_force(mu, W, yn, kL);
      const double R = icor::unknown_pressure(yn, kL);
      // At the minimum force the known-pressure iCOR is the unknown-pressure one (4.7 -> 4.13).
      CHECK(rel(icor::known_pressure(mu, W, yn, Fmin, kL), R) < 1e-7);
      // 4.10 and 4.11 cross at R of 4.13, at the force of 4.8.
      CHECK(rel(icor::force_from_icor(mu, W, R, kL), Fmin) < 8 * kEps);
      CHECK(rel(icor::force_unknown_pressure(mu, W, R, yn, kL), Fmin) < 8 * kEps);
      // 4.7 solves the moment balance 4.6: F (R + yn) = mu W (b^2 + R^2)/(2 b).
      const double F = 3.0 * Fmin, R7 = icor::known_pressure(mu, W, yn, F, kL);
      CHECK(rel(F * (R7 + yn), mu * W * (b * b + R7 * R7) / (2.0 * b)) < 1e-13);
      CHECK_THROWS_AS(icor::known_pressure(mu, W, yn, 0.5 * Fmin, kL), InputError);
      // The F77 relations agree.
      CHECK(rel(f77::icor_force(408, mu, W, yn, kL, kK2, 0.0), Fmin) < 8 * kEps);
      CHECK(rel(f77::icor_force(407, mu, W, yn, kL, kK2, F), R7) < 8 * kEps);
      CHECK(rel(f77::icor_force(410, mu, W, yn, kL, kK2, R), Fmin) < 8 * kEps);
      CHECK(rel(f77::icor_force(411, mu, W, yn, kL, kK2, R), Fmin) < 8 * kEps);
      CHECK_THROWS_AS(f77::icor_force(407, mu, W, yn, kL, kK2, 0.5 * Fmin), InputError);
    }
}

TEST_CASE("Eq 5.4 is the stationarity condition of eq 5.2, and the printed form reduces to ours", "[icor][unit]") {
  const auto rod = icor::nanorod();
  const double W = rod.load(), mu = 0.1;
  for (double yn : {5e-9, 50e-9, 150e-9, 295e-9}) {
    const auto printed = icor::constrained_cubic_printed(yn, rod);
    const auto reduced = icor::constrained_cubic(yn, kL, kK2);
    const double scale = rod.mass() * rod.mass() * W;
    for (int i = 0; i < 4; ++i) CHECK(printed[i] / scale == Approx(reduced[i]).epsilon(1e-13).margin(1e-300));
    const auto sol = icor::solve_constrained_cubic(yn, kL, kK2, CubicMethod::Brent);
    for (double R : sol.real_roots) {
      INFO("yn = " << yn << " R = " << R);
      // Central difference of F(R) at the root vanishes against the finite-difference scale.
      const double h = 1e-6 * std::fabs(R);
      const double fp = icor::constrained_force(mu, W, R + h, yn, kL, kK2);
      const double fm = icor::constrained_force(mu, W, R - h, yn, kL, kK2);
      const double f0 = icor::constrained_force(mu, W, R, yn, kL, kK2);
      const double dfdr = (fp - fm) / (2.0 * h);
      CHECK(std::fabs(dfdr) * std::fabs(R) < 1e-8 * std::fabs(f0));
      CHECK(rel(f77::icor_force(502, mu, W, yn, kL, kK2, R), f0) < 16 * kEps);
    }
  }
  // The physical branch needs a positive push: F > 0 at Table 5.1's negative root.
  const auto s = icor::solve_constrained_cubic(100e-9, kL, kK2, CubicMethod::Eigen);
  CHECK(icor::constrained_force(mu, W, *s.negative, 100e-9, kL, kK2) > 0.0);
}

TEST_CASE("Impulsive iCOR 5.5 and the pole of 5.2", "[icor][unit]") {
  const auto rod = icor::nanorod();
  CHECK(icor::impulsive(100e-9, kK2) == Approx(kK2 / 100e-9).epsilon(4 * kEps));
  CHECK(std::isinf(icor::impulsive(0.0, kK2)));
  CHECK(std::isinf(f77::icor_formula(NP_F77_ICOR_EQ_5_5, 0.0, kL, kK2)));
  CHECK(rel(f77::icor_formula(NP_F77_ICOR_EQ_5_5, 100e-9, kL, kK2), kK2 / 100e-9) < 4 * kEps);
  // At R = k^2/yn the constrained force is infinite (the impulsive limit), not NaN.
  const double yn = 100e-9, R = 2 * kK2 / (2 * yn);
  const double F = icor::constrained_force(0.1, rod.load(), R, yn, kL, kK2);
  CHECK(std::isinf(F));
}

TEST_CASE("Cubic residual <= 1e-12 of the coefficient scale for yn from 1e-15 m to b", "[icor][numeric]") {
  const double b = 0.5 * kL;
  int cases = 0;
  for (double lg = -15.0; lg <= std::log10(b) + 1e-12; lg += 0.05) {
    const double yn = std::min(std::pow(10.0, lg), b);
    const auto ref = solvers()[1].solve(yn);
    for (const auto& s : solvers()) {
      INFO("yn = " << yn << " solver " << s.name);
      const auto sol = s.solve(yn);
      CHECK(sol.max_residual <= 1e-12);
      CHECK(sol.real_roots.size() + static_cast<std::size_t>(sol.complex_roots + sol.at_infinity) == 3);
      CHECK(sol.real_roots.size() == ref.real_roots.size());
      for (double R : sol.real_roots) CHECK(std::isfinite(R));
      // Independent residual in SI with the unscaled coefficients.
      const auto c = icor::constrained_cubic(yn, kL, kK2);
      const std::vector<double> cv(c.begin(), c.end());
      for (double R : sol.real_roots)
        CHECK(std::fabs(roots::polyval(cv, R)) <= 1e-12 * roots::polyscale(cv, R));
      ++cases;
    }
  }
  CHECK(cases == 4 * 170);  // 170 push points, log-spaced by 0.05 decades
}

TEST_CASE("No NaN for any finite input; roots at infinity are counted", "[icor][numeric]") {
  const double tiny = std::numeric_limits<double>::denorm_min();
  for (double yn : {0.0, tiny, 1e-310, 1e-300, 1e-200, 1e-15, 1e-9, 295e-9, 1e-3, 1.0, 1e100, 1e300})
    for (double L : {1e-12, 590e-9, 1.0, 1e6}) {
      const double k2 = L * L / 12.0;
      if (!std::isfinite(2.0 * yn / (0.5 * L))) {
        // yn/b not representable: a clear InputError naming yn, in both languages.
        CHECK_THROWS_WITH(icor::solve_constrained_cubic(yn, L, k2, CubicMethod::Eigen), Catch::Matchers::StartsWith("yn = "));
        CHECK_THROWS_AS(f77::icor_cubic(yn, L, k2, f77::IcorCubicMethod::Lapack), InputError);
        continue;
      }
      for (const auto m : {CubicMethod::Brent, CubicMethod::Eigen}) {
        INFO("yn = " << yn << " L = " << L << " " << nanopush::to_string(m));
        const auto s = icor::solve_constrained_cubic(yn, L, k2, m);
        CHECK(s.real_roots.size() + static_cast<std::size_t>(s.complex_roots + s.at_infinity) == 3);
        for (double R : s.real_roots) CHECK(std::isfinite(R));
        CHECK(std::isfinite(s.max_residual));
        CHECK(s.negative.has_value());
      }
      for (const auto m : {f77::IcorCubicMethod::Brent, f77::IcorCubicMethod::Lapack}) {
        INFO("F77 yn = " << yn << " L = " << L);
        const auto s = f77::icor_cubic(yn, L, k2, m);
        for (double R : s.real_roots) CHECK(std::isfinite(R));
        CHECK(s.negative.has_value());
        CHECK(s.real_roots.size() + static_cast<std::size_t>(s.complex_roots + s.at_infinity) == 3);
      }
    }
  // A subnormal push distance: the runaway root overflows and is reported at infinity.
  const auto s = icor::solve_constrained_cubic(tiny, kL, kK2, CubicMethod::Eigen);
  CHECK(s.at_infinity == 1);
  const auto t = icor::solve_constrained_cubic(tiny, kL, kK2, CubicMethod::Brent);
  CHECK(t.at_infinity == 1);
  // Between, the runaway root lies near the overflow threshold (1e299-1e308): the companion
  // matrix is scaled so that its QR iteration does not overflow (it failed for yn in
  // [1.3e-314, 2.1e-313]); the physical roots stay Brent's.
  for (const double yn : {1.3e-314, 2e-314, 5e-314, 1e-313, 2.1e-313, 3e-313}) {
    INFO("yn = " << yn);
    const auto e = icor::solve_constrained_cubic(yn, kL, kK2, CubicMethod::Eigen);
    const auto b = icor::solve_constrained_cubic(yn, kL, kK2, CubicMethod::Brent);
    REQUIRE(e.negative.has_value());
    REQUIRE(b.negative.has_value());
    CHECK(std::fabs(*e.negative - *b.negative) <= 1e-12 * std::fabs(*b.negative));
    CHECK(e.real_roots.size() + static_cast<std::size_t>(e.complex_roots + e.at_infinity) == 3);
  }
}

TEST_CASE("Bad input is rejected with a clear error (C++ and F77)", "[icor][unit]") {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(message([] { icor::solve_constrained_cubic(-1e-9, kL, kK2, CubicMethod::Brent); }),
             Catch::Matchers::StartsWith("yn = -1e-09: must be >= 0"));
  CHECK_THAT(message([] { icor::solve_constrained_cubic(1e-9, 0.0, kK2, CubicMethod::Eigen); }),
             Catch::Matchers::StartsWith("L = 0: must be > 0"));
  CHECK_THAT(message([] { icor::solve_constrained_cubic(1e-9, -1.0, kK2, CubicMethod::Eigen); }),
             Catch::Matchers::StartsWith("L = -1: must be > 0"));
  CHECK_THAT(message([] { icor::unknown_pressure(-1.0, kL); }), Catch::Matchers::StartsWith("yn = -1"));
  CHECK_THAT(message([] { icor::solve_constrained_cubic(std::nan(""), kL, kK2, CubicMethod::Eigen); }),
             Catch::Matchers::Contains("finite"));
  CHECK_THROWS_AS(icor::falvo(kL, kL), InputError);  // push beyond the rod end
  // Inputs that overflow a double give no mu, from every front end (they all call these).
  const auto rod = icor::nanorod();
  CHECK_THAT(message([&] { icor::estimate_mu_from_force(rod, {1e308, 0}, {2e-7, 0}); }),
             Catch::Matchers::StartsWith("F = 1e+308, yn = 2e-07: mu or its uncertainty is not a finite number"));
  CHECK_THAT(message([&] { icor::estimate_mu_from_icor(rod, {1e308, 1e306}, {1e-300, 0}); }),
             Catch::Matchers::StartsWith("F = 1e+308, R = 1e-300: mu or its uncertainty is not a finite number"));
  // A finite mu whose uncertainty overflows: named by the input whose contribution does, not
  // by F and yn, which are fine.
  const auto msg_L = message([&] { icor::estimate_mu_from_force(rod, {1e-7, 0}, {1e-7, 0}, 1e308); });
  CHECK_THAT(msg_L, Catch::Matchers::StartsWith("L uncertainty = 1e+308: its contribution to the uncertainty of mu"));
  CHECK_THAT(msg_L, !Catch::Matchers::Contains("F = "));
  CHECK_THAT(message([&] { icor::estimate_mu_from_force(rod, {1e-7, 1e300}, {1e-7, 0}); }),
             Catch::Matchers::StartsWith("F uncertainty = 1e+300: its contribution to the uncertainty of mu"));
  CHECK_THAT(message([&] { icor::estimate_mu_from_icor(rod, {1e-7, 0}, {1e-7, 0}, 0, 1e308); }),
             Catch::Matchers::StartsWith("H uncertainty = 1e+308: "));
  icor::MuEstimate e;  // a derivative that is not finite names the value
  e.mu = 1;
  e.contributions = {{"F", 1, 0, 1}, {"yn", 0, 0, 1}, {"L", 1e-300, 1e-9, std::numeric_limits<double>::infinity()}};
  CHECK_THAT(message([&] { icor::propagate_uncertainty(e); }), Catch::Matchers::StartsWith("L = 1e-300: mu or its uncertainty"));
  CHECK(icor::estimate_mu_from_force(rod, {1e-7, 1e-9}, {1e-7, 1e-9}, 1e-9, 1e-21).sigma > 0);
  CHECK_THROWS_AS(f77::icor_cubic(-1e-9, kL, kK2, f77::IcorCubicMethod::Lapack), InputError);
  CHECK_THROWS_AS(f77::icor_cubic(1e-9, 0.0, kK2, f77::IcorCubicMethod::Brent), InputError);
  CHECK_THROWS_AS(f77::icor_formula(NP_F77_ICOR_EQ_4_13, -1e-9, kL), InputError);
  double roots[3];
  int nr, nc, ni;
  double res;
  CHECK(np_f77_icor_cubic_lapack(1e-9, -1.0, kK2, roots, &nr, &nc, &ni, &res) == NP_F77_ICOR_BAD_INPUT);
}

TEST_CASE("Brent and the companion matrix on polynomials with known roots", "[roots][numeric]") {
  // Round trip: (x - 1)(x - 2)(x + 3) = x^3 - 7x + 6.
  const auto pr = roots::polynomial_roots({6.0, -7.0, 0.0, 1.0});
  REQUIRE(pr.roots.size() == 3);
  CHECK(pr.roots[0].real() == Approx(-3.0).epsilon(1e-14));
  CHECK(pr.roots[1].real() == Approx(1.0).epsilon(1e-14));
  CHECK(pr.roots[2].real() == Approx(2.0).epsilon(1e-14));
  const auto br = icor::real_roots_brent({6.0, -7.0, 0.0, 1.0});
  REQUIRE(br.roots.size() == 3);
  CHECK(br.roots[0] == Approx(-3.0).epsilon(1e-15));
  CHECK(br.roots[1] == Approx(1.0).epsilon(1e-15));
  CHECK(br.roots[2] == Approx(2.0).epsilon(1e-15));
  // Complex pair: x^2 + 1 (and a leading zero counted at infinity).
  const auto z = roots::polynomial_roots({1.0, 0.0, 1.0, 0.0});
  CHECK(z.at_infinity == 1);
  REQUIRE(z.roots.size() == 2);
  CHECK(std::fabs(z.roots[0].imag()) == Approx(1.0).epsilon(1e-14));
  CHECK(icor::real_roots_brent({1.0, 0.0, 1.0}).roots.empty());
  // Brent on a transcendental function: cos x = x at 0.7390851332151607.
  const auto r = roots::brent([](double x) { return std::cos(x) - x; }, 0.0, 1.0);
  CHECK(r.converged);
  CHECK(r.x == Approx(0.7390851332151607).epsilon(4 * kEps));
  CHECK_THROWS_AS(roots::brent([](double x) { return x * x + 1.0; }, -1.0, 1.0), InputError);
  // Widely scaled coefficients: roots 1e-8, 1e8 (balancing keeps both accurate).
  const auto w = roots::polynomial_roots({1.0, -(1e8 + 1e-8), 1.0});
  CHECK(w.roots[0].real() == Approx(1e-8).epsilon(1e-13));
  CHECK(w.roots[1].real() == Approx(1e8).epsilon(1e-13));
}

TEST_CASE("Friction coefficient estimates: first-order uncertainty vs finite differences and Monte Carlo",
          "[icor][numeric]") {
  const auto rod = icor::nanorod();
  const double mu_true = 0.1, yn = 200e-9;
  const double F = icor::minimum_force(mu_true, rod.load(), yn, rod.length);
  const icor::Measured Fm{F, 0.03 * F}, ynm{yn, 5e-9};
  const double sL = 10e-9, sH = 0.05 * rod.hamaker;
  const auto e = icor::estimate_mu_from_force(rod, Fm, ynm, sL, sH);
  CHECK(rel(e.mu, mu_true) < 1e-13);  // inverse of 4.8

  // Finite-difference oracle: recompute mu from perturbed inputs (W recomputed from the rod).
  auto mu_force = [](icor::Rod r, double f, double y) {
    return icor::estimate_mu_from_force(r, {f, 0}, {y, 0}).mu;
  };
  auto central = [](auto&& g, double x, double h) { return (g(x + h) - g(x - h)) / (2.0 * h); };
  const double dF = central([&](double x) { return mu_force(rod, x, yn); }, F, 1e-4 * F);
  const double dY = central([&](double x) { return mu_force(rod, F, x); }, yn, 1e-4 * yn);
  const double dL = central([&](double x) { auto r = rod; r.length = x; return mu_force(r, F, yn); }, rod.length, 1e-4 * rod.length);
  const double dH = central([&](double x) { auto r = rod; r.hamaker = x; return mu_force(r, F, yn); }, rod.hamaker, 1e-4 * rod.hamaker);
  REQUIRE(e.contributions.size() == 4);
  CHECK(e.contributions[0].derivative == Approx(dF).epsilon(1e-7));
  CHECK(e.contributions[1].derivative == Approx(dY).epsilon(1e-7));
  CHECK(e.contributions[2].derivative == Approx(dL).epsilon(1e-7));
  CHECK(e.contributions[3].derivative == Approx(dH).epsilon(1e-7));
  const double sigma_fd = std::sqrt(std::pow(dF * Fm.sigma, 2) + std::pow(dY * ynm.sigma, 2) +
                                    std::pow(dL * sL, 2) + std::pow(dH * sH, 2));
  CHECK(e.sigma == Approx(sigma_fd).epsilon(1e-7));

  // Monte Carlo (fixed seed, small input uncertainties so first order holds): N = 40000,
  // the sample std of mu has a relative standard error ~ 1/sqrt(2N) = 0.35%; allow 2%.
  std::mt19937_64 gen(12345);
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<double> mus;
  for (int i = 0; i < 40000; ++i) {
    auto r = rod;
    r.length += sL * n01(gen);
    r.hamaker += sH * n01(gen);
    const double f = F + Fm.sigma * n01(gen);
    const double y = yn + ynm.sigma * n01(gen);
    mus.push_back(mu_force(r, f, y));
  }
  CHECK(icor::sample_std(mus) == Approx(e.sigma).epsilon(0.02));

  // From an observed iCOR (eq 4.10 inverted): d mu / d L = 0, the rest against differences.
  const double R = icor::unknown_pressure(yn, rod.length);
  const double F10 = icor::force_from_icor(mu_true, rod.load(), R, rod.length);
  const auto g = icor::estimate_mu_from_icor(rod, {F10, 0.02 * F10}, {R, 3e-9}, sL, sH);
  CHECK(rel(g.mu, mu_true) < 1e-13);
  auto mu_icor = [](icor::Rod r, double f, double rr) { return icor::estimate_mu_from_icor(r, {f, 0}, {rr, 0}).mu; };
  CHECK(g.contributions[1].derivative ==
        Approx(central([&](double x) { return mu_icor(rod, F10, x); }, R, 1e-4 * R)).epsilon(1e-7));
  CHECK(std::fabs(central([&](double x) { auto r = rod; r.length = x; return mu_icor(r, F10, R); }, rod.length,
                          1e-4 * rod.length)) < 1e-9 * g.mu / rod.length);
  CHECK(g.contributions[3].derivative ==
        Approx(central([&](double x) { auto r = rod; r.hamaker = x; return mu_icor(r, F10, R); }, rod.hamaker,
                       1e-4 * rod.hamaker)).epsilon(1e-7));
  // Bad input.
  CHECK_THROWS_AS(icor::estimate_mu_from_force(rod, {-1.0, 0}, {yn, 0}), InputError);
  CHECK_THROWS_AS(icor::estimate_mu_from_force(rod, {F, -1.0}, {yn, 0}), InputError);
  CHECK_THROWS_AS(icor::estimate_mu_from_icor(rod, {F, 0}, {0.0, 0}), InputError);
}

TEST_CASE("Extension point: the iCOR read off a velocity state has zero velocity", "[icor][unit]") {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    const double vx = u(gen), vy = u(gen), w = u(gen);
    const auto c = icor::icor_from_velocity(vx, vy, w);
    // Velocity of the point c: v + omega z x c = (vx - w cy, vy + w cx) = 0.
    CHECK(std::fabs(vx - w * c.cy) <= 1e-14 * (std::fabs(vx) + std::fabs(w * c.cy)));
    CHECK(std::fabs(vy + w * c.cx) <= 1e-14 * (std::fabs(vy) + std::fabs(w * c.cx)));
    CHECK(c.R == Approx(std::hypot(vx, vy) / std::fabs(w)).epsilon(1e-14));
  }
  // Push along +x at yn > 0 turns the rod clockwise: the iCOR is on the far side (y < 0).
  const auto c = icor::icor_from_velocity(1.0, 0.0, -2.0);
  CHECK(c.cx == 0.0);
  CHECK(c.cy == -0.5);
  const auto t = icor::icor_from_velocity(1.0, 0.0, 0.0);
  CHECK(t.translation);
  CHECK(std::isinf(t.R));
  CHECK_THROWS_AS(icor::icor_from_velocity(std::nan(""), 0.0, 1.0), InputError);
}

TEST_CASE("Extension point: line-contact wrench against midpoint cubature", "[icor][numeric]") {
  const double b = 295e-9;
  for (double R : {0.0, 50e-9, 200e-9, 400e-9})
    for (double alpha : {0.0, 0.3, M_PI / 2, 2.0, M_PI, 4.0}) {
      INFO("R = " << R << " alpha = " << alpha);
      const double cx = -R * std::cos(alpha), cy = -R * std::sin(alpha);
      const int n = 200000;
      double fx = 0, fy = 0, mf = 0;
      for (int i = 0; i < n; ++i) {
        const double y = -b + (i + 0.5) * 2.0 * b / n, dy = 2.0 * b / n;
        const double vx = -(y - cy), vy = -cx, sp = std::hypot(vx, vy);  // omega = +1
        if (sp == 0.0) continue;
        const double dfx = -vx / sp / (2 * b) * dy, dfy = -vy / sp / (2 * b) * dy;
        fx += dfx;
        fy += dfy;
        mf += -y * dfx;  // x = 0
      }
      const auto w = icor::line_contact_wrench(b, R, alpha);
      CHECK(w.fx == Approx(fx).margin(1e-6));
      CHECK(w.fy == Approx(fy).margin(1e-6));
      CHECK(w.mf == Approx(mf).margin(1e-6 * b));
    }
}

TEST_CASE("Extension point: the generic quasi-static solver with the line contact is eq 4.13", "[icor][numeric]") {
  const double b = 295e-9, L = 2 * b;
  auto wrench = [b](double R, double a) { return icor::line_contact_wrench(b, R, a); };
  for (double yn : {10e-9, 50e-9, 150e-9, 295e-9}) {
    INFO("yn = " << yn);
    // Push along body +x at (0, yn): clockwise rotation about an iCOR on the far side.
    const auto q = icor::quasi_static_icor(wrench, 0.0, yn, 1.0, 0.0, 0.8 * b, M_PI / 2 + 0.2, b);
    REQUIRE(q.converged);
    CHECK(q.omega_sign == -1);
    CHECK(q.R == Approx(icor::unknown_pressure(yn, L)).epsilon(1e-9));
    CHECK(std::remainder(q.alpha - M_PI / 2, 2 * M_PI) == Approx(0.0).margin(1e-9));
    CHECK(q.force == Approx(icor::minimum_force(1.0, 1.0, yn, L)).epsilon(1e-9));
  }
}

TEST_CASE("Errata evidence: at Table 5.1's root, F of eq 5.2 is positive and a local maximum in R",
          "[icor][regression]") {
  const auto rod = icor::nanorod();
  const double W = rod.load(), mu = 0.1;
  for (double yn : {0.0, 1e-9, 50e-9, 150e-9, 295e-9}) {
    INFO("yn = " << yn);
    const auto s = icor::solve_constrained_cubic(yn, kL, kK2, CubicMethod::Brent);
    REQUIRE(s.negative.has_value());
    const double R = *s.negative, h = 1e-4 * std::fabs(R);
    auto F = [&](double r) { return icor::constrained_force(mu, W, r, yn, kL, kK2); };
    CHECK(F(R) > 0.0);
    CHECK(F(R + h) < F(R));  // both neighbours lower: a maximum of F(R), not a minimum
    CHECK(F(R - h) < F(R));
    CHECK((F(R + h) - 2 * F(R) + F(R - h)) / (h * h) < 0.0);
  }
  // At yn = 0 in closed form: F(R) = 3 mu W (R^3 - b^2 R/3)/(2 b^3), so F(-b/3) = +mu W/9 is
  // the local maximum and F(+b/3) = -mu W/9 the local minimum (a negative push).
  const double b = 0.5 * kL;
  CHECK(icor::constrained_force(mu, W, -b / 3, 0.0, kL, kK2) == Approx(mu * W / 9).epsilon(1e-14));
  CHECK(icor::constrained_force(mu, W, b / 3, 0.0, kL, kK2) == Approx(-mu * W / 9).epsilon(1e-14));
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
