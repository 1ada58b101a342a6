// The dynamic tip-driven push (docs/tip.md, "The dynamic model"): the bar with its mass and
// moment of inertia, the surface's Coulomb friction wrench (friction.hpp, event-located
// stick-slip as the coulomb law's, stick_slip.hpp) and the force of an AFM tip held by a
// lateral spring of stiffness k to its base, which moves along the straight path of TipPath.
//
// The tip is massless: its centre q is the base b while it does not touch the bar, and the
// point of the offset surface {distance to the rectangle = r} nearest to b while b lies
// inside that surface. The spring then carries the contact force
//     F = k (b - q) = -k delta n,   delta = r - d(b) > 0,
// d the signed distance from b to the rectangle and n the outward normal at the contact point
// p: a penetration penalty through the spring, along the normal (a frictionless tip: tip.mu
// = 0), zero when delta <= 0, so the tip never pulls. The bar obeys
//     m dv/dt = F + f(V),   I domega/dt = p x F + mf(V),
// with the two work accumulators W_tip = int F.v_p dt and W_fric = int (f.v + mf omega) dt,
// so that W_tip + W_fric = the kinetic energy gained.
// Events: contact and release (delta changes sign: kinks of the force, located), the bar
// starts to slide (the spring's wrench leaves the limit surface) and comes to rest, the tip's
// base stops (t = travel / speed).
#pragma once
#include <cstdint>

#include "nanopush/models/tip_push.hpp"

namespace nanopush::tip {

/// The spring contact of the massless tip whose base centre is at body-axis point (bx, by).
struct SpringContact {
  bool touching = false;  ///< delta > 0
  double delta = 0;       ///< penetration of the base into the offset surface, r - d [m]
  double px = 0, py = 0;  ///< contact point on the rectangle (body axes) [m]
  double nx = 0, ny = 0;  ///< outward unit normal there
  double qx = 0, qy = 0;  ///< tip centre (body axes): the base, or p + r n when touching [m]
  double fx = 0, fy = 0;  ///< force of the tip on the bar (body axes) [N]
  double torque = 0;      ///< p x F about the centre of mass [N m]
};
SpringContact spring_contact(const BarGeometry& g, double radius, double stiffness, double bx, double by);

/// What the dynamic model needs beyond the quasi-static one.
struct DynamicBar {
  double mass = 0;       ///< [kg]
  double inertia = 0;    ///< about the centre of mass [kg m^2]
  double stiffness = 0;  ///< lateral spring of the tip k [N/m]
};

/// The inertia ratio m v^2 / (mu N L), L = tip.travel: the kinetic energy at the tip's speed
/// against the work of friction over the push, equal to the dynamic time constant m v/(mu N)
/// over the push's duration L/v. `auto` runs the quasi-static model when it is at most
/// kAutoInertiaRatio.
double inertia_ratio(double mass, double speed, double muN, double travel);
inline constexpr double kAutoInertiaRatio = 1e-3;

/// The default end time of a dynamic run: the tip's travel time plus the time a bar moving at
/// the tip's speed takes to stop against friction and the spring's period, ten times each
/// (it ends earlier if the bar is at rest for good).
double dynamic_t_end(const DynamicBar& bar, double muN, const TipPath& tip);

struct DynamicRunResult {
  TipRunResult run;               ///< rows, events ("contact", "release", "slide", "rest", "tip stops"), counts
  std::int64_t rest_analyses = 0; ///< stick/slip decisions at rest
  double max_delta = 0;           ///< largest penetration of the base into the offset surface [m]
};

/// The dynamic tip-driven push of a bar at rest from pose (x0, y0, theta0), friction load muN:
/// output at `samples` evenly spaced times over [0, t_end] (t_end <= 0: dynamic_t_end).
/// Dormand-Prince 8(5,3) at rtol between events. Throws InputError naming the key for bad input
/// (tip.stiffness, tip.mu != 0, a tip starting inside the bar) and SolverError when the
/// integration fails.
DynamicRunResult run_dynamic(const BarGeometry& g, double muN, const DynamicBar& bar, const TipPath& tip, double x0,
                             double y0, double theta0, double t_end, int samples, double rtol);

}  // namespace nanopush::tip
