// Pairs of doubles for the division-heavy loops of the integrators (GCC vector extensions:
// SSE2 on x86-64, scalar code elsewhere). Each lane is one IEEE operation, so results equal
// the scalar loops bit for bit; only the throughput of the divider changes.
#pragma once
#include <type_traits>

#include "nanopush/numerics/integration.hpp"

namespace nanopush::pairs {

/// Whether the pair loops apply: double, a compile-time dimension, and an even one.
template <class Scalar, int N>
inline constexpr bool kPairs = std::is_same_v<Scalar, double> && N != Dynamic && N % 2 == 0;

typedef double V2 __attribute__((vector_size(16)));
typedef double V2u __attribute__((vector_size(16), aligned(8), may_alias));
typedef long long L2 __attribute__((vector_size(16)));
inline V2 ld2(const double* p) { return *reinterpret_cast<const V2u*>(p); }
inline void st2(double* p, V2 v) { *reinterpret_cast<V2u*>(p) = v; }
inline V2 abs2(V2 v) {
  const L2 mask = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL};
  return reinterpret_cast<V2>(reinterpret_cast<L2>(v) & mask);
}

}  // namespace nanopush::pairs
