// Complete elliptic integral K(k) and the Jacobi function sn(u, k) by the arithmetic-
// geometric mean (Abramowitz & Stegun 17.6 and 16.4), for any scalar type: they are the
// exact solution of the pendulum that oracles the smooth-surface nanobar.
#pragma once
#include <array>

#include "nanopush/numerics/scalar.hpp"

namespace nanopush {

/// K(k) = ∫0^{π/2} dφ / sqrt(1 - k² sin² φ), |k| < 1.
template <typename S>
S elliptic_k(S k) {
  S a = 1, b = num::sqrt(S(1) - k * k);
  for (int i = 0; i < 64; ++i) {
    const S an = (a + b) / 2;
    b = num::sqrt(a * b);
    a = an;
    if (num::abs(a - b) <= num::epsilon<S>() * a) break;
  }
  return num::pi<S>() / (2 * a);
}

/// sn(u, k) for 0 <= |k| < 1 (descending Landen transformation / AGM, A&S 16.4).
template <typename S>
S jacobi_sn(S u, S k) {
  constexpr int kMax = 64;
  std::array<S, kMax + 1> a{}, c{};
  a[0] = 1;
  S b = num::sqrt(S(1) - k * k);
  c[0] = num::abs(k);
  int n = 0;
  while (n < kMax && num::abs(c[n]) > num::epsilon<S>() * a[n]) {
    a[n + 1] = (a[n] + b) / 2;
    c[n + 1] = (a[n] - b) / 2;
    b = num::sqrt(a[n] * b);
    ++n;
  }
  S phi = a[n] * u;
  for (int i = 0; i < n; ++i) phi = phi * 2;
  for (int i = n; i >= 1; --i) phi = (phi + num::asin(c[i] / a[i] * num::sin(phi))) / 2;
  return num::sin(phi);
}

/// Exact pendulum I θ'' = -T sin(θ - θ*) from rest at θ0: returns θ(t) and ω(t).
/// With φ = θ - θ*, k = sin(φ0/2), w0 = sqrt(T/I): φ(t) = 2 asin(k sn(K(k) - w0 t, k)).
template <typename S>
struct Pendulum {
  S theta_eq, theta0, w0;
  S k, K;
  Pendulum(S theta_eq_, S theta0_, S torque_amplitude, S inertia)
      : theta_eq(theta_eq_), theta0(theta0_), w0(num::sqrt(torque_amplitude / inertia)) {
    k = num::sin((theta0 - theta_eq) / 2);
    K = elliptic_k(k);
  }
  [[nodiscard]] S period() const { return 4 * K / w0; }
  [[nodiscard]] S theta(S t) const {
    if (k == 0) return theta_eq;
    const S u = num::fmod(K - w0 * t, 4 * K);
    return theta_eq + 2 * num::asin(k * jacobi_sn(u, k));
  }
  /// ω = θ'; from energy: ω² = (4 T/I)(k² - sin²(φ/2)), sign from sn's derivative.
  [[nodiscard]] S omega(S t) const {
    if (k == 0) return S(0);
    const S u = num::fmod(K - w0 * t, 4 * K);
    const S sn = jacobi_sn(u, k);
    // cn dn with signs: cn(u) via sn and the quarter-period position of u.
    const S ks = k * sn;
    S cn = num::sqrt(num::abs(S(1) - sn * sn));
    // cn is positive for u in (-K, K) mod 4K, negative in (K, 3K).
    S uu = num::fmod(u, 4 * K);
    if (uu < 0) uu += 4 * K;
    if (uu > K && uu < 3 * K) cn = -cn;
    const S dn = num::sqrt(S(1) - ks * ks);
    // dφ/dt = 2 k cn dn (-w0) / sqrt(1 - k² sn²) = -2 k w0 cn
    (void)dn;
    return -2 * k * w0 * cn;
  }
};

}  // namespace nanopush
