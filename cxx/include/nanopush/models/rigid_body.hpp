// The pushed rigid body in the plane (docs/models.md §0) and the smooth-surface right-hand side
// (docs/models.md §A; thesis eqs 3.22–3.26 with erratum 1).
#pragma once
#include <cmath>
#include <type_traits>

#include "nanopush/numerics/scalar.hpp"

namespace nanopush {

/// State layout shared by every engine and the CSV output: world axes, SI.
enum StateIndex : int { kX = 0, kY = 1, kTheta = 2, kVx = 3, kVy = 4, kOmega = 5, kStateSize = 6 };

/// A rigid bar seen from above: 2a (body x', width) by 2b (body y', length).
struct BarGeometry {
  double a = 0;  ///< half-width [m]
  double b = 0;  ///< half-length [m]
};

/// Constant push: magnitude F [N], world direction beta [rad], attached at body point (pbx, pby) [m].
struct Push {
  double force = 0, beta = 0, pbx = 0, pby = 0;
  /// Thesis mapping (docs/models.md §0): thesis (xn, yn) -> body point (xn, -yn).
  static Push from_thesis(double F, double beta, double xn, double yn) { return {F, beta, xn, -yn}; }
  /// Torque about the CM at orientation theta: (R(theta) pb) x F.
  template <typename S>
  [[nodiscard]] S torque(S theta) const {
    return torque_cs(num::cos(theta), num::sin(theta));
  }
  /// The same from cos(theta), sin(theta) already at hand (hot path: computed once per RHS).
  template <typename S>
  [[nodiscard]] S torque_cs(S c, S s) const {
    const S pwx = S(pbx) * c - S(pby) * s;
    const S pwy = S(pbx) * s + S(pby) * c;
    const S fx = S(force) * num::cos(S(beta));
    const S fy = S(force) * num::sin(S(beta));
    return pwx * fy - pwy * fx;
  }
  /// |pb| and the torque amplitude F |pb| (pendulum form tau = -F d sin(theta - theta*)).
  [[nodiscard]] double lever() const { return std::hypot(pbx, pby); }
  /// Stable equilibrium orientation theta* (torque zero, d tau/d theta < 0), in (-pi, pi].
  [[nodiscard]] double theta_equilibrium() const {
    // tau = F d sin(beta - theta - phi_b) with phi_b = atan2(pby, pbx): zero and stable at
    // theta = beta - phi_b.
    double th = beta - std::atan2(pby, pbx);
    while (th > M_PI) th -= 2 * M_PI;
    while (th <= -M_PI) th += 2 * M_PI;
    return th;
  }
};

/// Smooth-surface sliding: m v' = F, I omega' = tau(theta). The arithmetic follows
/// fortran/smbar.f operation for operation, so both engines see the same numbers.
struct SmoothBarRhs {
  double mass, inertia;
  Push push;
  /// The push force components, computed once (in double; other scalars compute them in
  /// their own precision at each call, so extended-precision runs keep every digit).
  double fx_d, fy_d;
  SmoothBarRhs(double m, double i, Push p)
      : mass(m), inertia(i), push(p), fx_d(p.force * std::cos(p.beta)), fy_d(p.force * std::sin(p.beta)) {}
  template <typename S>
  int operator()(S /*t*/, const S* y, S* dydt) const {
    const S c = num::cos(y[kTheta]);
    const S s = num::sin(y[kTheta]);
    const S pwx = S(push.pbx) * c - S(push.pby) * s;
    const S pwy = S(push.pbx) * s + S(push.pby) * c;
    S fx, fy;
    if constexpr (std::is_same_v<S, double>) {
      fx = fx_d;  // the same operations as below, done once
      fy = fy_d;
    } else {
      fx = S(push.force) * num::cos(S(push.beta));
      fy = S(push.force) * num::sin(S(push.beta));
    }
    const S tau = pwx * fy - pwy * fx;
    dydt[kX] = y[kVx];
    dydt[kY] = y[kVy];
    dydt[kTheta] = y[kOmega];
    dydt[kVx] = fx / S(mass);
    dydt[kVy] = fy / S(mass);
    dydt[kOmega] = tau / S(inertia);
    return 0;
  }
};

}  // namespace nanopush
