#include <catch2/catch.hpp>

#include "f77_bridge.h"

TEST_CASE("F77 smooth-bar RHS: force through the CM gives no torque", "[bridge][unit]") {
  const double p[6] = {1.0, 2.0, 3.0, 0.0, 0.5, 0.0};
  const double y[6] = {0, 0, 0, 1, 2, 3};
  double dy[6];
  REQUIRE(np_f77_smooth_bar_rhs(0.0, y, dy, p) == 0);
  CHECK(dy[0] == 1.0);
  CHECK(dy[3] == 3.0);
  CHECK(dy[5] == 0.0);
}
