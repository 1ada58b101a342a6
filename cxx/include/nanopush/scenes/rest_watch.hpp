// The rest watch of the thesis and printed laws (docs/rough.md, docs/errors.md): the sign law
// of eq 3.40 has no static friction, so where the push cannot break the coulomb limit surface
// and the body comes to rest the integrator would chatter through its step budget. A step hook
// that stops there (the run's no_static_friction), used by the runs (simulate.cpp) and the
// fit's forward model (fitting/model.cpp).
#pragma once
#include <algorithm>
#include <cmath>

#include "nanopush/models/rough_bar.hpp"
#include "nanopush/models/stick_slip.hpp"
#include "nanopush/numerics/integration.hpp"

namespace nanopush {

/// Where the push cannot break the coulomb limit surface and the body comes to rest, friction
/// reverses at every step and the integrator creeps until it gives up (100,000 steps). The
/// watch stops the run there: after an accepted step that reverses the velocity or the spin
/// while the speed (|v| + |omega| L) is below 1e-3 of the run's largest and within ten steps of
/// friction's deceleration of zero, and where the rest analysis says the push is inside the
/// limit surface. It also sums the work of friction over the steps where it was positive (the
/// printed law injecting energy).
struct RestWatch {
  RoughBarModel coulomb;  ///< the contact under the coulomb law (analyse_rest)
  double accel = 0, spin = 0;  ///< friction's deceleration scales [m/s^2], [rad/s^2]
  double lever = 0;            ///< [m] the body's half-length, the speed's lever for omega
  double max_speed = 0;
  double positive_work = 0;  ///< [J] the work of friction summed over the steps where it was positive
  double last_omega = 0, max_omega = 0;  ///< [rad/s] at the last accepted step, and the largest |omega|
  bool came_to_rest = false;
  double t_rest = 0;

  explicit RestWatch(const RoughBarModel& m) : coulomb(m) {
    coulomb.printed = false;
    coulomb.f77_forms = false;
    coulomb.rest_direction = {0.0, 0.0, 0.0};
    accel = m.muN / m.mass;
    lever = std::max(m.geometry.a, m.geometry.b);
    spin = m.muN * lever / m.inertia;
  }
  /// Whether a run that gave up at state y (speeds below 1e-3 of what friction removes over
  /// t_end, and a pose where the push is inside the limit surface) gave up at rest: the sign
  /// law chattering there, or an integration of its sensitivities that could not follow it.
  [[nodiscard]] bool gave_up_at_rest(const double* y, double t_end) const {
    return std::hypot(y[kVx], y[kVy]) < 1e-3 * accel * t_end && std::fabs(y[kOmega]) < 1e-3 * spin * t_end &&
           analyse_rest(coulomb, y[kTheta]).stuck;
  }
  int operator()(double t0, const double* y0, double t1, const double* y1) {
    positive_work += std::max(0.0, y1[kWorkFric] - y0[kWorkFric]);
    last_omega = y1[kOmega];
    max_omega = std::max(max_omega, std::fabs(last_omega));
    const double speed = std::hypot(y1[kVx], y1[kVy]) + std::fabs(y1[kOmega]) * lever;
    max_speed = std::max(max_speed, speed);
    const bool reversed = y0[kVx] * y1[kVx] + y0[kVy] * y1[kVy] < 0.0 || y0[kOmega] * y1[kOmega] < 0.0;
    if (!reversed || speed > 1e-3 * max_speed) return kHookContinue;
    const double h = t1 - t0;
    if (std::hypot(y1[kVx], y1[kVy]) > 10.0 * accel * h || std::fabs(y1[kOmega]) > 10.0 * spin * h) return kHookContinue;
    if (!analyse_rest(coulomb, y1[kTheta]).stuck) return kHookContinue;
    came_to_rest = true;
    t_rest = t1;
    return kHookStopAfter;
  }
};

}  // namespace nanopush
