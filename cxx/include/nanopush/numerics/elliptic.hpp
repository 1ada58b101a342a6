// Complete elliptic integral K(k) and the Jacobi functions sn(u, k), cn(u, k) from Boost.Math
// (ellint_1, jacobi_elliptic: Carlson's R_F and the descending Landen / AGM recursion of
// A&S 16.4), for every scalar type the integrator is instantiated with: double and long double
// directly, num::quad (__float128) through boost::multiprecision::float128 (link
// -lquadmath, which scalar.hpp already needs). They are the exact solution of the pendulum that
// oracles the smooth-surface nanobar.
#pragma once
#include <type_traits>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/multiprecision/float128.hpp>

#include "nanopush/numerics/scalar.hpp"

namespace nanopush {

namespace elliptic_detail {
/// The type Boost.Math computes in for scalar S (its wrapper for __float128).
template <typename S>
using boost_t = std::conditional_t<std::is_same_v<S, num::quad>, boost::multiprecision::float128, S>;
}  // namespace elliptic_detail

/// K(k) = ∫0^{π/2} dφ / sqrt(1 - k² sin² φ), |k| < 1 (Boost.Math ellint_1; throws
/// std::overflow_error at |k| = 1 and std::domain_error for |k| > 1).
template <typename S>
S elliptic_k(S k) {
  using B = elliptic_detail::boost_t<S>;
  return static_cast<S>(boost::math::ellint_1(B(num::abs(k))));
}

/// sn(u, k) for 0 <= |k| < 1 (Boost.Math jacobi_sn; sn depends on k only through k²).
template <typename S>
S jacobi_sn(S u, S k) {
  using B = elliptic_detail::boost_t<S>;
  return static_cast<S>(boost::math::jacobi_sn(B(num::abs(k)), B(u)));
}

/// cn(u, k) for 0 <= |k| < 1 (Boost.Math jacobi_cn), with its sign.
template <typename S>
S jacobi_cn(S u, S k) {
  using B = elliptic_detail::boost_t<S>;
  return static_cast<S>(boost::math::jacobi_cn(B(num::abs(k)), B(u)));
}

/// dn(u, k) for 0 <= |k| < 1 (Boost.Math jacobi_dn).
template <typename S>
S jacobi_dn(S u, S k) {
  using B = elliptic_detail::boost_t<S>;
  return static_cast<S>(boost::math::jacobi_dn(B(num::abs(k)), B(u)));
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
  /// ω = θ' = -2 k w0 cn(u, k), u = K - w0 t (from φ = 2 asin(k sn(u)), dsn/du = cn dn and
  /// sqrt(1 - k² sn²) = dn), with cn(u) = dn(u) sn(K - u) (sn(u + K) = cn(u)/dn(u)): the
  /// argument K - u = w0 t (mod 4K) is exact at the turning points, so ω is 0 there exactly
  /// (at t = 0: the state starts at rest), where cn(K) from the numerical K is ~eps.
  [[nodiscard]] S omega(S t) const {
    if (k == 0) return S(0);
    const S u = num::fmod(K - w0 * t, 4 * K);
    return -2 * k * w0 * (jacobi_dn(u, k) * jacobi_sn(K - u, k));
  }
};

}  // namespace nanopush
