// Elementary functions for every scalar type the integrator is instantiated with:
// double, long double and __float128 (GCC's quad precision, libquadmath).
#pragma once
#include <cmath>
#include <limits>
#include <string>

#include <quadmath.h>

namespace nanopush::num {

using quad = __float128;

inline double abs(double x) { return std::fabs(x); }
inline long double abs(long double x) { return std::fabs(x); }
inline quad abs(quad x) { return fabsq(x); }
inline double sqrt(double x) { return std::sqrt(x); }
inline long double sqrt(long double x) { return std::sqrt(x); }
inline quad sqrt(quad x) { return sqrtq(x); }
inline double pow(double x, double y) { return std::pow(x, y); }
inline long double pow(long double x, long double y) { return std::pow(x, y); }
inline quad pow(quad x, quad y) { return powq(x, y); }
inline double log10(double x) { return std::log10(x); }
inline long double log10(long double x) { return std::log10(x); }
inline quad log10(quad x) { return log10q(x); }
inline double log(double x) { return std::log(x); }
inline long double log(long double x) { return std::log(x); }
inline quad log(quad x) { return logq(x); }
inline double asinh(double x) { return std::asinh(x); }
inline long double asinh(long double x) { return std::asinh(x); }
inline quad asinh(quad x) { return asinhq(x); }
inline double copysign(double x, double y) { return std::copysign(x, y); }
inline long double copysign(long double x, long double y) { return std::copysign(x, y); }
inline quad copysign(quad x, quad y) { return copysignq(x, y); }
inline double hypot(double x, double y) { return std::hypot(x, y); }
inline long double hypot(long double x, long double y) { return std::hypot(x, y); }
inline quad hypot(quad x, quad y) { return hypotq(x, y); }
inline double sin(double x) { return std::sin(x); }
inline long double sin(long double x) { return std::sin(x); }
inline quad sin(quad x) { return sinq(x); }
inline double cos(double x) { return std::cos(x); }
inline long double cos(long double x) { return std::cos(x); }
inline quad cos(quad x) { return cosq(x); }
inline double asin(double x) { return std::asin(x); }
inline long double asin(long double x) { return std::asin(x); }
inline quad asin(quad x) { return asinq(x); }
inline double atan(double x) { return std::atan(x); }
inline long double atan(long double x) { return std::atan(x); }
inline quad atan(quad x) { return atanq(x); }
inline double atan2(double y, double x) { return std::atan2(y, x); }
inline long double atan2(long double y, long double x) { return std::atan2(y, x); }
inline quad atan2(quad y, quad x) { return atan2q(y, x); }
inline double fmod(double x, double y) { return std::fmod(x, y); }
inline long double fmod(long double x, long double y) { return std::fmod(x, y); }
inline quad fmod(quad x, quad y) { return fmodq(x, y); }
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
