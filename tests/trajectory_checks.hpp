// Comparisons of trajectories shared by the C++ tests.
#pragma once
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "nanopush/scenes/simulate.hpp"

namespace nanopush::test {

/// max |theta_a - theta_b| over the outputs [rad]; the two must have the same output times.
inline double max_dtheta(const Trajectory& a, const Trajectory& b) {
  REQUIRE(a.rows.size() == b.rows.size());
  double d = 0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) d = std::max(d, std::fabs(a.rows[i][3] - b.rows[i][3]));
  return d;
}

}  // namespace nanopush::test
