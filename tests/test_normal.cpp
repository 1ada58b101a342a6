// The portable normal generator (numerics/normal.hpp): fixed deviates for a seed (the same on
// every platform: std::mt19937_64 is defined bit for bit by the standard, the transform is
// ours), the transform against Marsaglia's polar method evaluated in long double from the raw
// engine output, and the first two moments.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "nanopush/numerics/normal.hpp"

using nanopush::num::PortableNormal;

TEST_CASE("portable normal: fixed deviates for seed 3", "[normal][unit]") {
  // The engine itself, as the standard fixes it: the 10000th output of a default-seeded one.
  std::mt19937_64 e;
  e.discard(9999);
  CHECK(e() == 9981545732273789042ULL);
  PortableNormal n(3);
  const std::vector<double> expected = {0x1.0caca17c9729dp-2,  -0x1.5bbcb62cf00fep+0, 0x1.0769e797095f8p+0,
                                        -0x1.c072badc704c6p+0, 0x1.bb8d46ff4796bp-1,  -0x1.013504ed97633p+1};
  for (double x : expected) CHECK(n() == x);
}

TEST_CASE("portable normal: Marsaglia's polar method on the engine's raw output", "[normal][unit]") {
  // Independently: raw outputs -> uniforms on [-1, 1) -> accept u^2 + v^2 in (0, 1) ->
  // u f, v f with f = sqrt(-2 ln s / s), in long double. The generator rounds s to double
  // (relative error eps), which ln s turns into a relative error eps / |ln s| (large as s -> 1):
  // it agrees within 8 eps (1 + 1 / |ln s|).
  for (std::uint64_t seed : {1ULL, 3ULL, 12345ULL}) {
    std::mt19937_64 raw(seed);
    PortableNormal n(seed);
    for (int pair = 0; pair < 200; ++pair) {
      long double u = 0, v = 0, s = 0;
      do {
        u = static_cast<long double>(raw() >> 11) / 4503599627370496.0L - 1.0L;  // k / 2^52 - 1
        v = static_cast<long double>(raw() >> 11) / 4503599627370496.0L - 1.0L;
        s = u * u + v * v;
      } while (s >= 1.0L || s == 0.0L);
      const long double f = std::sqrt(-2.0L * std::log(s) / s);
      const double bound = 8 * std::numeric_limits<double>::epsilon() * (1 + 1 / std::fabs(static_cast<double>(std::log(s))));
      for (long double want : {u * f, v * f}) {
        const double got = n();
        CHECK(std::fabs(got - static_cast<double>(want)) <= bound * std::fabs(static_cast<double>(want)));
      }
    }
  }
}

TEST_CASE("portable normal: mean 0 and variance 1", "[normal][unit]") {
  PortableNormal n(7);
  const int count = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < count; ++i) {
    const double x = n();
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / count, var = sum2 / count - mean * mean;
  CHECK(std::fabs(mean) < 5.0 / std::sqrt(count));           // 5 sigma of the mean
  CHECK(std::fabs(var - 1.0) < 5.0 * std::sqrt(2.0 / count));  // 5 sigma of the variance
}
