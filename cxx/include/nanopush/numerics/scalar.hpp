// Elementary functions for every scalar type the integrator is instantiated with:
// double, long double and __float128 (GCC's quad precision, libquadmath).
#pragma once
#include <cmath>
#include <limits>
#include <string>

#include <quadmath.h>

namespace nanopush::num {

using quad = __float128;

// Each function below has three overloads: std:: for double and long double, libquadmath for
// quad. The macros write the three at once, so they cannot drift apart.
#define NANOPUSH_NUM_UNARY(f, stdf, quadf)                        \
  inline double f(double x) { return std::stdf(x); }             \
  inline long double f(long double x) { return std::stdf(x); }   \
  inline quad f(quad x) { return quadf(x); }
#define NANOPUSH_NUM_BINARY(f, quadf)                                          \
  inline double f(double x, double y) { return std::f(x, y); }               \
  inline long double f(long double x, long double y) { return std::f(x, y); } \
  inline quad f(quad x, quad y) { return quadf(x, y); }

NANOPUSH_NUM_UNARY(abs, fabs, fabsq)
NANOPUSH_NUM_UNARY(sqrt, sqrt, sqrtq)
NANOPUSH_NUM_BINARY(pow, powq)
NANOPUSH_NUM_UNARY(log10, log10, log10q)
NANOPUSH_NUM_UNARY(log, log, logq)
NANOPUSH_NUM_UNARY(asinh, asinh, asinhq)
NANOPUSH_NUM_BINARY(copysign, copysignq)
NANOPUSH_NUM_BINARY(hypot, hypotq)
NANOPUSH_NUM_UNARY(sin, sin, sinq)
NANOPUSH_NUM_UNARY(cos, cos, cosq)
NANOPUSH_NUM_UNARY(asin, asin, asinq)
NANOPUSH_NUM_UNARY(atan, atan, atanq)
NANOPUSH_NUM_BINARY(atan2, atan2q)
NANOPUSH_NUM_BINARY(fmod, fmodq)
#undef NANOPUSH_NUM_UNARY
#undef NANOPUSH_NUM_BINARY
inline bool isfinite(double x) { return std::isfinite(x); }
inline bool isfinite(long double x) { return std::isfinite(x); }
inline bool isfinite(quad x) { return finiteq(x) != 0; }

template <typename S>
S pi() {
  if constexpr (std::is_same_v<S, quad>)
    return 4 * atanq(quad(1));
  else
    return static_cast<S>(3.141592653589793238462643383279502884L);
}

template <typename S>
S epsilon() {
  if constexpr (std::is_same_v<S, quad>)
    return ldexpq(quad(1), -112);  // FLT128_EPSILON
  else
    return std::numeric_limits<S>::epsilon();
}

template <typename S>
const char* name() {
  if constexpr (std::is_same_v<S, quad>)
    return "quad";
  else if constexpr (std::is_same_v<S, long double>)
    return "long";
  else
    return "double";
}

}  // namespace nanopush::num
