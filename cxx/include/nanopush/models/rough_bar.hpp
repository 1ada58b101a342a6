// Rough-surface sliding of the nanobar (docs/models.md §C; thesis eqs 3.51–3.56 with errata 1–3):
// the smooth-surface equations plus the Coulomb friction resultant over the contact
// rectangle (friction.hpp), evaluated at the iCOR implied by the rigid velocity and rotated
// to world axes.
//
// State (8 components): x, y, theta, vx, vy, omega (world axes, SI) and two work
// accumulators: W_push = ∫ (F·v + tau omega) dt and W_fric = ∫ (f·v + mf omega) dt [J], so
// that the energy balance  ΔKE = W_push + W_fric  is checked on every run.
#pragma once
#include <array>
#include <cmath>

#include "nanopush/models/friction.hpp"
#include "nanopush/models/friction_extended.hpp"
#include "nanopush/models/rigid_body.hpp"

namespace nanopush {

inline constexpr int kWorkPush = 6, kWorkFric = 7, kRoughStateSize = 8;

/// Friction wrench in world axes (fx, fy) [N] and mf [N m], in scalar S.
template <typename S>
struct WorldWrenchT {
  S fx = 0, fy = 0, mf = 0;
};
using WorldWrench = WorldWrenchT<double>;

struct RoughBarModel {
  double mass = 0, inertia = 0;
  BarGeometry geometry;  ///< contact half-width a and half-length b
  double muN = 0;        ///< mu (m g + F_vdw) [N]
  Push push;
  /// World velocity direction (vx, vy, omega) whose friction acts when the body is exactly at
  /// rest; all zero (the thesis law) gives no friction at rest, where eq 3.40 has no direction.
  std::array<double, 3> rest_direction{0.0, 0.0, 0.0};
  /// The `printed` friction law (docs/rough.md): eqs 3.45-3.48 exactly as printed
  /// (thesis_printed_friction_from_velocity) instead of the corrected wrench; false for the
  /// `thesis` and `coulomb` laws.
  bool printed = false;
  /// The printed law's reading of the slips (friction.hpp); eq 3.50 applies here, in the
  /// rotation to world axes.
  PrintedReading reading;
  /// Evaluate the wrench with the F77 routine's forms (friction_detail::*_reference) instead
  /// of the production ones: the same values within a few ulps, at 2-2.5 x the cost. The
  /// faithful method sets it, so that its steps stay the F77 engine's bit for bit.
  bool f77_forms = false;

  /// Friction from the world velocity (vx, vy) and omega at orientation theta: body-axis
  /// velocity v' = R(-theta) v, friction wrench at the implied iCOR, rotated back
  /// (erratum 3: fy = fx' sin theta + fy' cos theta).
  [[nodiscard]] WorldWrench friction(double theta, double vx, double vy, double omega) const noexcept {
    if (muN == 0.0) return {};
    return friction_cs(std::cos(theta), std::sin(theta), vx, vy, omega);
  }
  /// The same from c = cos(theta), s = sin(theta) (computed once per RHS evaluation).
  [[nodiscard]] WorldWrench friction_cs(double c, double s, double vx, double vy, double omega) const noexcept {
    if (muN == 0.0) return {};
    const double vbx = c * vx + s * vy, vby = -s * vx + c * vy;
    if (printed) {
      const FrictionWrench fb = reading.c4_squares
                                    ? thesis_printed_friction_from_velocity(geometry.a, geometry.b, muN, vbx, vby, omega, reading)
                                    : printed_slips(coulomb_wrench(vbx, vby, omega), omega);
      // eq 3.50 as printed: fy = fx' sin(theta) - fy' cos(theta) (erratum 3 corrects the sign)
      return {c * fb.fx - s * fb.fy, reading.eq3_50 ? s * fb.fx - c * fb.fy : s * fb.fx + c * fb.fy, fb.mf};
    }
    const FrictionWrench fb = coulomb_wrench(vbx, vby, omega);
    return {c * fb.fx - s * fb.fy, s * fb.fx + c * fb.fy, fb.mf};
  }

  /// The Coulomb wrench in body axes: the F77 routine's forms (faithful) or the production ones.
  [[nodiscard]] FrictionWrench coulomb_wrench(double vbx, double vby, double omega) const noexcept {
    return f77_forms ? friction_detail::rectangle_friction_from_velocity_reference(geometry.a, geometry.b, muN, vbx, vby,
                                                                                   omega)
                     : rectangle_friction_from_velocity(geometry.a, geometry.b, muN, vbx, vby, omega);
  }
  /// A reading with cubes in C4 is the Coulomb wrench with the reading's sign slips: fy' negated
  /// (F1 as printed) and mf without sign(theta-dot), i.e. times sign(omega) (F3 as printed);
  /// nothing at omega = 0, where the printed forms are pure translation too. Evaluated by the
  /// Coulomb wrench's stable forms: the printed logarithms with cubes cancel as (R/b)^3 and leave
  /// noise that does positive work (docs/rough.md). RGBAR does the same with RECTFV.
  [[nodiscard]] FrictionWrench printed_slips(FrictionWrench w, double omega) const noexcept {
    if (omega == 0.0) return w;
    if (reading.fy_sign) w.fy = -w.fy;
    if (reading.omega_sign && omega < 0.0) w.mf = -w.mf;
    return w;
  }

  /// friction_cs in scalar S: the production forms in double, friction_extended.hpp's in long
  /// double and quad (the thesis and coulomb laws; the printed law and the F77 forms are double).
  template <typename S>
  [[nodiscard]] WorldWrenchT<S> friction_in(S c, S s, S vx, S vy, S omega) const {
    if constexpr (std::is_same_v<S, double>) {
      return friction_cs(c, s, vx, vy, omega);
    } else {
      if (muN == 0.0) return {};
      const S vbx = c * vx + s * vy, vby = -s * vx + c * vy;
      const FrictionWrenchT<S> fb =
          rectangle_friction_from_velocity_extended<S>(S(geometry.a), S(geometry.b), S(muN), vbx, vby, omega);
      return {c * fb.fx - s * fb.fy, s * fb.fx + c * fb.fy, fb.mf};
    }
  }

  /// Applied push wrench in world axes at orientation theta.
  [[nodiscard]] WorldWrench applied(double theta) const noexcept {
    return applied_cs(std::cos(theta), std::sin(theta));
  }
  [[nodiscard]] WorldWrench applied_cs(double c, double s) const noexcept {
    return {push.force * std::cos(push.beta), push.force * std::sin(push.beta), push.torque_cs(c, s)};
  }

  /// applied_cs in scalar S (the push's components computed in S).
  template <typename S>
  [[nodiscard]] WorldWrenchT<S> applied_in(S c, S s) const {
    if constexpr (std::is_same_v<S, double>)
      return applied_cs(c, s);
    else
      return {S(push.force) * num::cos(S(push.beta)), S(push.force) * num::sin(S(push.beta)), push.torque_cs(c, s)};
  }

  /// Right-hand side with a given friction wrench (shared by every friction law).
  template <typename S>
  static void rhs_with(const RoughBarModel& m, const S* y, const WorldWrenchT<S>& ap, const WorldWrenchT<S>& fr,
                       S* d) noexcept {
    d[kX] = y[kVx];
    d[kY] = y[kVy];
    d[kTheta] = y[kOmega];
    d[kVx] = (ap.fx + fr.fx) / m.mass;
    d[kVy] = (ap.fy + fr.fy) / m.mass;
    d[kOmega] = (ap.mf + fr.mf) / m.inertia;
    d[kWorkPush] = ap.fx * y[kVx] + ap.fy * y[kVy] + ap.mf * y[kOmega];
    d[kWorkFric] = fr.fx * y[kVx] + fr.fy * y[kVy] + fr.mf * y[kOmega];
  }

  template <typename S>
  [[nodiscard]] S kinetic_energy(const S* y) const noexcept {
    return 0.5 * S(mass) * (y[kVx] * y[kVx] + y[kVy] * y[kVy]) + 0.5 * S(inertia) * y[kOmega] * y[kOmega];
  }
};

/// The `thesis` friction law: friction at the iCOR implied by the velocity with the sense of
/// rotation sign(theta-dot) (eq 3.40), integrated as one smooth ODE. Where the velocity
/// passes through zero the friction direction flips discontinuously: the integrator
/// chatters there (that is the point of keeping this law: the original runs).
/// With model.printed set it is the `printed` law: the same ODE with the printed wrench.
struct RoughBarThesisRhs {
  RoughBarModel model;
  /// In any scalar S (the printed law in double only).
  template <typename S>
  int operator()(S, const S* y, S* d) const noexcept {
    const S c = num::cos(y[kTheta]), s = num::sin(y[kTheta]);
    const WorldWrenchT<S> ap = model.applied_in(c, s);
    const bool at_rest = y[kVx] == 0.0 && y[kVy] == 0.0 && y[kOmega] == 0.0;
    const auto& rd = model.rest_direction;
    const WorldWrenchT<S> fr = at_rest ? model.friction_in(c, s, S(rd[0]), S(rd[1]), S(rd[2]))
                                       : model.friction_in(c, s, y[kVx], y[kVy], y[kOmega]);
    RoughBarModel::rhs_with(model, y, ap, fr, d);
    return 0;
  }
};

}  // namespace nanopush
