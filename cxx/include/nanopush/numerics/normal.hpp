// Standard normal deviates that a seed reproduces on every platform and standard library:
// std::mt19937_64's raw output (an algorithm the C++ standard defines, bit for bit) mapped by
// our own code, Marsaglia's polar method. std::normal_distribution (and Boost.Random's)
// leaves its algorithm to the implementation, so a seed gave other data under another library.
// The transform uses +, *, / and sqrt (correctly rounded by IEEE 754), std::fma (exact then
// rounded once, so no compiler contraction can change it) and one std::log per pair.
#pragma once
#include <cmath>
#include <cstdint>
#include <random>

namespace nanopush::num {

class PortableNormal {
 public:
  explicit PortableNormal(std::uint64_t seed) : rng_(seed) {}

  /// The next N(0, 1) deviate; deviates come in pairs from one accepted point (u, v).
  double operator()() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u = 0, v = 0, s = 0;
    do {
      u = uniform();
      v = uniform();
      s = std::fma(u, u, v * v);
    } while (s >= 1.0 || s == 0.0);
    const double f = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = v * f;
    has_spare_ = true;
    return u * f;
  }

  /// Uniform on [-1, 1) from one raw output: its top 53 bits, k 2^-52 - 1 (exact in double).
  static double to_uniform(std::uint64_t raw) { return static_cast<double>(raw >> 11) * 0x1p-52 - 1.0; }

 private:
  double uniform() { return to_uniform(rng_()); }
  std::mt19937_64 rng_;
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace nanopush::num
