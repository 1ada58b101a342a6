// Seeded Latin hypercubes of rough scenes over the physical keys: the scenes the accuracy
// tests, the accuracy benchmark and the stability atlas draw (docs/accuracy.md). Portable:
// std::mt19937_64 (a defined algorithm) and our own mapping to [0, 1), so a seed gives the
// same scenes under every standard library.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "nanopush/scenes/scene.hpp"

namespace nanopush {

/// One dimension of the hypercube: a key's range, geometric (log) or linear.
struct LhsRange {
  double lo, hi;
  bool log = true;
  [[nodiscard]] double at(double u) const {
    return log ? std::exp(std::log(lo) + u * (std::log(hi) - std::log(lo))) : lo + u * (hi - lo);
  }
};

/// The physical ranges of a rough scene (length 10 nm - 10 um, width/length 0.01 - 1, height
/// 1 nm - 1 um, density 1e3 - 2e4 kg/m^3, push 1e-12 - 1e-3 N, push point anywhere on the
/// body, mu 1e-3 - 2, f_vdw 1e-12 - 1e-3 N, rtol 1e-12 - 1e-4).
struct RoughLhsRanges {
  LhsRange length{10e-9, 10e-6}, aspect{0.01, 1.0}, height{1e-9, 1e-6}, density{1e3, 2e4}, force{1e-12, 1e-3},
      xn{-0.999, 0.999, false}, yn{-0.999, 0.999, false}, mu{1e-3, 2.0}, f_vdw{1e-12, 1e-3}, rtol{1e-12, 1e-4};
};

/// n points in [0, 1)^D, one in each of n strata of every dimension (stratum order shuffled per
/// dimension, position jittered inside it).
template <std::size_t D>
std::vector<std::array<double, D>> latin_hypercube(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto unit = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<std::array<double, D>> pts(n);
  std::vector<std::size_t> perm(n);
  for (std::size_t d = 0; d < D; ++d) {
    for (std::size_t i = 0; i < n; ++i) perm[i] = i;
    for (std::size_t i = n; i > 1; --i) std::swap(perm[i - 1], perm[static_cast<std::size_t>(rng() % i)]);
    for (std::size_t i = 0; i < n; ++i) pts[i][d] = (static_cast<double>(perm[i]) + unit()) / static_cast<double>(n);
  }
  return pts;
}

/// n rough scenes: `base` (a rough scene, e.g. fig3_18) with the physical keys drawn from a
/// seeded Latin hypercube over `r` (its solver.rtol too).
inline std::vector<Scene> rough_lhs_scenes(const Scene& base, std::size_t n, std::uint64_t seed,
                                           const RoughLhsRanges& r = {}) {
  std::vector<Scene> out;
  out.reserve(n);
  for (const auto& u : latin_hypercube<10>(n, seed)) {
    const double length = r.length.at(u[0]), width = length * r.aspect.at(u[1]);
    Scene sc = base;
    sc.set({{"object.length", length},
            {"object.width", width},
            {"object.height", r.height.at(u[2])},
            {"object.density", r.density.at(u[3])},
            {"push.force", r.force.at(u[4])},
            {"push.xn", r.xn.at(u[5]) * width / 2},
            {"push.yn", r.yn.at(u[6]) * length / 2},
            {"surface.mu", r.mu.at(u[7])},
            {"surface.f_vdw", r.f_vdw.at(u[8])},
            {"solver.rtol", r.rtol.at(u[9])}});
    out.push_back(std::move(sc));
  }
  return out;
}

}  // namespace nanopush
