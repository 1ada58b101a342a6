// Rolling of nanotubes (docs/models.md E): Fig 3.3 exact points, rolling-vs-sliding decision,
// and the C++ formulas against their FORTRAN 77 versions (fortran/rolling.f via the bridge).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "f77_rolling.h"
#include "nanopush/numerics/error.hpp"
#include "nanopush/models/rolling.hpp"
#include "nanopush/models/surface_forces.hpp"
#include "support/support.hpp"

using namespace nanopush;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {

TEST_CASE("Fig 3.3: fs = 0 at h = r/2, -F/3 at h = r, F/3 at h = 0, exactly (C++ and F77)", "[rolling][unit]") {
  for (double r : {13.5e-9, 1e-9, 7.3e-8}) {
    for (double F : {1e-9, 3.88796e-07, 5e-6}) {
      CHECK(rolling::static_friction(F, r / 2, r) == 0.0);
      CHECK(rolling::static_friction(F, r, r) == -F / 3);
      CHECK(rolling::static_friction(F, 0.0, r) == F / 3);
      double fs = -1;
      REQUIRE(np_f77_rolling_static_friction(F, r / 2, r, &fs) == 0);
      CHECK(fs == 0.0);
      REQUIRE(np_f77_rolling_static_friction(F, r, r, &fs) == 0);
      CHECK(fs == -F / 3);
      REQUIRE(np_f77_rolling_static_friction(F, 0.0, r, &fs) == 0);
      CHECK(fs == F / 3);
    }
  }
}

TEST_CASE("Eq 3.16 follows from eqs 3.10 and 3.12 with a_x = r alpha", "[rolling][unit]") {
  // m a = F - fs; (1/2) m r^2 alpha = F h + fs r  =>  fs from 3.16 satisfies both.
  const double m = 7.6e-19, r = 13.5e-9, F = 2e-7;
  for (double h : {-r, -0.3 * r, 0.0, 0.25 * r, r}) {
    const double fs = rolling::static_friction(F, h, r);
    const double a = (F - fs) / m;
    const double alpha = (F * h + fs * r) / (0.5 * m * r * r);
    CHECK(std::abs(a - r * alpha) <= 16 * test::kEps * std::abs(F / m));
  }
}

TEST_CASE("C++ and F77 rolling formulas agree over a grid", "[rolling][cross][regression]") {
  const double r = 13.5e-9;
  for (int i = 0; i <= 40; ++i) {
    const double h = -r + 2 * r * i / 40.0;
    const double hc = std::max(-r, std::min(r, h));
    double fs = 0;
    REQUIRE(np_f77_rolling_static_friction(3e-7, hc, r, &fs) == 0);
    CHECK(fs == rolling::static_friction(3e-7, hc, r));
  }
  for (double k : {0.0, 0.6e-9, 3e-9}) {
    double fs = 0, Fm = 0;
    REQUIRE(np_f77_rolling_resistance(8.66e-6, k, r, &fs) == 0);
    CHECK(fs == rolling::rolling_resistance(8.66e-6, k, r));
    REQUIRE(np_f77_rolling_min_force(8.66e-6, k, r, 0.01, &Fm) == 0);
    CHECK(Fm == rolling::minimum_rolling_force(8.66e-6, k, r));
  }
  double fv = 0;
  REQUIRE(np_f77_rod_plane_vdw(2.38e-19, 590e-9, 27e-9, 0.2e-9, &fv) == 0);
  CHECK(std::abs(fv - forces::rod_plane_vdw_force(2.38e-19, 590e-9, 27e-9, 0.2e-9)) <= 4 * test::kEps * fv);
  for (double W : {0.0, 0.05, 0.25}) {
    for (double p : {0.0, 1.0, 4.32, 50.0}) {
      double b = 0;
      REQUIRE(np_f77_jkr_line_half_width(r, 19e9, W, p, &b) == 0);
      const double bc = forces::jkr_line_half_width(r, 19e9, W, p);
      CHECK(std::abs(b - bc) <= 1e-13 * bc + 1e-30);
    }
  }
  // Decisions over (F, mu, h).
  for (double mu : {0.0, 0.05, 0.5, 2.0}) {
    for (double F : {0.0, 1e-8, 3e-7, 3e-6, 3e-5}) {
      for (double h : {-r, 0.0, 0.5 * r, r}) {
        rolling::Push p{F, h, r, mu, 2.55e-6, 8.66e-6, 3.6e-9};
        const auto d = rolling::decide(p);
        int mode = -1;
        double fr = 0, fsl = 0, fsr = 0;
        REQUIRE(np_f77_rolling_decide(F, h, r, mu, p.N_slide, p.W_roll, p.k, &mode, &fr, &fsl, &fsr) == 0);
        CHECK(mode == static_cast<int>(d.motion));
        CHECK(fr == d.F_roll);
        CHECK(fsl == d.F_slide);
        CHECK(fsr == d.fs_required);
      }
    }
  }
}

TEST_CASE("Rolling versus sliding decision", "[rolling][unit]") {
  const double r = 13.5e-9;
  rolling::Push p{0.0, 0.0, r, 0.1, 2.5e-6, 8.7e-6, 3.6e-9};
  const double F_roll = 8.7e-6 * 3.6e-9 / r, F_slide = 0.1 * 2.5e-6;
  REQUIRE(F_slide < F_roll);
  p.F = 0.5 * F_slide;
  CHECK(rolling::decide(p).motion == rolling::Motion::stuck);
  p.F = 1.01 * F_slide;
  CHECK(rolling::decide(p).motion == rolling::Motion::sliding);
  p.mu = 2.0;  // now rolling is cheaper; at h = r/2 pure rolling needs no friction at all
  p.F = 1.01 * F_roll;
  p.h = r / 2;
  CHECK(rolling::decide(p).motion == rolling::Motion::rolling);
  p.mu = 1.0;  // F_slide = 2.5e-6 > F_roll = 2.32e-6, but fs(h = -r) = F = 2.6e-6 > mu N: slips
  p.h = -r;
  p.F = 2.6e-6;
  CHECK(rolling::decide(p).motion == rolling::Motion::rolling_with_slip);
}

TEST_CASE("Rolling formulas reject bad input; F77 returns IERR, never stops", "[rolling][validation][unit]") {
  const double r = 13.5e-9;
  CHECK_THROWS_AS(rolling::static_friction(1e-9, 1.5 * r, r), InputError);
  CHECK_THROWS_WITH(rolling::static_friction(1e-9, 1.5 * r, r), Catch::Contains("push height h"));
  CHECK_THROWS_AS(rolling::static_friction(1e-9, 0.0, 0.0), InputError);
  CHECK_THROWS_AS(rolling::rolling_resistance(-1.0, 1e-9, r), InputError);
  CHECK_THROWS_AS(rolling::sliding_threshold(-0.1, 1.0), InputError);
  double out = 0;
  CHECK(np_f77_rolling_static_friction(1e-9, 1.5 * r, r, &out) == 1);
  CHECK(np_f77_rolling_static_friction(1e-9, 0.0, -r, &out) == 1);
  CHECK(np_f77_rolling_resistance(1.0, -1e-9, r, &out) == 1);
  CHECK(np_f77_rod_plane_vdw(-1e-19, 1e-6, 2e-8, 2e-10, &out) == 1);
  CHECK(np_f77_rod_plane_vdw(1e-19, 1e-6, 2e-8, 0.0, &out) == 1);
  CHECK(np_f77_jkr_line_half_width(r, 19e9, 0.25, -1e3, &out) == 2);  // below the line pull-off
  CHECK(np_f77_jkr_line_half_width(r, -1.0, 0.25, 1.0, &out) == 1);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
