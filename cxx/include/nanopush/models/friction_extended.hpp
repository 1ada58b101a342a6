// The rectangle's Coulomb friction wrench in long double and quad (__float128): the reference
// forms of friction.hpp (closed_form_reference, far_field_reference: no cancellation beyond
// the closed form's eps rho^3) instantiated on the scalar, with rules and switches chosen for
// that scalar's epsilon, so that a rough scene can be integrated with more digits than double
// (solver.precision = long | quad; docs/accuracy.md, "References with more digits").
//
//   closed form        rho < 3 (long double), rho < 30 (quad): rounding eps rho^3 < 6e-30;
//   far field          up to rho = sqrt(10 / eps), an n-point Gauss-Legendre product rule with
//                      the smallest even n for which the series remainder (1/(2 rho))^(2n) is
//                      below eps/10 (n <= 64), nodes and weights computed in the scalar;
//   asymptotic         beyond, where its neglected O(rho^-2) is below eps/10.
// Not the hot path: a quad evaluation costs ~100x a double one.
#pragma once
#include <array>
#include <cmath>
#include <vector>

#include "nanopush/models/friction.hpp"
#include "nanopush/numerics/scalar.hpp"

namespace nanopush {

template <typename S>
struct FrictionWrenchT {
  S fx, fy, mf;
};

namespace friction_detail {

/// The positive half of an n-point Gauss-Legendre rule on [-1, 1] in scalar S (n even): nodes
/// by Newton's iteration on the three-term recurrence of P_n from Tricomi's initial guesses,
/// weights 2 / ((1 - x^2) P_n'(x)^2). Hand-written because Boost.Math's tabulated rules stop at
/// 30 points in compile-time sizes and do not take __float128; ~n^2 operations, once per n.
template <typename S>
struct GaussHalfRule {
  std::vector<S> x, w;
};

template <typename S>
GaussHalfRule<S> make_gauss_half_rule(int n) {
  GaussHalfRule<S> r;
  const int h = n / 2;
  r.x.resize(static_cast<std::size_t>(h));
  r.w.resize(static_cast<std::size_t>(h));
  const S pi = num::pi<S>();
  for (int i = 0; i < h; ++i) {
    S x = num::cos(pi * (S(i) + S(0.75)) / (S(n) + S(0.5)));
    S dp = 1;
    for (int it = 0; it < 100; ++it) {
      S p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const S p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / S(k);
        p0 = p1;
        p1 = p2;
      }
      dp = S(n) * (x * p1 - p0) / (x * x - 1);
      const S dx = p1 / dp;
      x -= dx;
      if (num::abs(dx) <= 4 * num::epsilon<S>() * num::abs(x)) break;
    }
    r.x[static_cast<std::size_t>(i)] = x;
    r.w[static_cast<std::size_t>(i)] = 2 / ((1 - x * x) * dp * dp);
  }
  return r;
}

inline constexpr int kExtendedMaxRule = 64;

/// The rule of n points (even, 4..kExtendedMaxRule), built on first use (thread-safe).
template <typename S>
const GaussHalfRule<S>& gauss_half_rule(int n) {
  static const std::array<GaussHalfRule<S>, kExtendedMaxRule / 2 + 1> rules = [] {
    std::array<GaussHalfRule<S>, kExtendedMaxRule / 2 + 1> all;
    for (int k = 2; k <= kExtendedMaxRule / 2; ++k) all[static_cast<std::size_t>(k)] = make_gauss_half_rule<S>(2 * k);
    return all;
  }();
  return rules[static_cast<std::size_t>(n / 2)];
}

/// Where the closed form hands over to the far field, in units of max(a, b).
template <typename S>
constexpr double extended_far_field_from() {
  return std::is_same_v<S, num::quad> ? 30.0 : 3.0;
}

/// The mean integrals in units of L = max(a, b) (a, b <= 1, rho = R/L, (c, s) = (cos, sin) alpha).
template <typename S>
MeanIntegralsT<S> mean_integrals_extended(S a, S b, S rho, S c, S s) {
  const S tol = num::epsilon<S>() / 10;
  if (!(rho * rho * tol < 1)) return {c, s, (a * a * s * s + b * b * c * c) / (3 * rho)};
  const S xc = rho * c, yc = rho * s;
  if (rho < extended_far_field_from<S>()) return closed_form_reference(a, b, xc, yc);
  // (1/(2 rho))^(2n) <= tol
  const double need = static_cast<double>(num::log(tol) / (2 * num::log(1 / (2 * rho))));
  int n = 2 * static_cast<int>(std::ceil(need / 2.0));
  n = n < 4 ? 4 : (n > kExtendedMaxRule ? kExtendedMaxRule : n);
  const GaussHalfRule<S>& rule = gauss_half_rule<S>(n);
  return far_field_reference(a, b, xc, yc, rule.x.data(), rule.w.data(), n / 2);
}

}  // namespace friction_detail

/// rectangle_friction_from_velocity (friction.hpp) in scalar S: body-axis CM velocity (vx, vy)
/// [m/s], angular rate omega [rad/s]; pure translation at omega = 0, zero wrench at rest.
template <typename S>
FrictionWrenchT<S> rectangle_friction_from_velocity_extended(S a, S b, S muN, S vx, S vy, S omega) {
  const S v = num::sqrt(vx * vx + vy * vy);
  if (omega == 0) {
    if (!(v > 0)) return {0, 0, 0};
    return {-muN * (vx / v), -muN * (vy / v), 0};
  }
  const S L = a > b ? a : b;
  const S sense = omega > 0 ? S(1) : S(-1);
  S c = 1, s = 0;  // any direction at R = 0
  if (v > 0) {
    c = sense * vy / v;
    s = -sense * vx / v;
  }
  const S rho = (v / num::abs(omega)) / L;
  const friction_detail::MeanIntegralsT<S> m = friction_detail::mean_integrals_extended<S>(a / L, b / L, rho, c, s);
  return {muN * sense * m.iy, -muN * sense * m.ix, -muN * sense * m.km * L};
}

}  // namespace nanopush
