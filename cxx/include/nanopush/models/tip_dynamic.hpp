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
// p: a penetration penalty through the spring, along the normal, zero when delta <= 0, so the
// tip never pulls (tip.mu = 0). With tip friction (tip.mu > 0) the tip's centre q lies on
// the offset surface, at arc length s, in one of two states changed at located events:
// stuck (no sliding at the contact: the tip does not turn, so s = s0 - r (theta - theta0))
// or sliding in the sense sigma (b - q = lambda (-n + mu sigma t), the spring's force on the
// edge of the friction cone, t the tangent), and F = k (b - q). The bar obeys
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

/// A point of the offset surface {distance to the rectangle = r} (body axes), at arc length s
/// counter-clockwise from (a + r, -b): the tip's centre q, the contact point p = q - r n on
/// the rectangle, the outward normal n and the tangent t = (-ny, nx).
struct OffsetPoint {
  double s = 0;
  double qx = 0, qy = 0, px = 0, py = 0, nx = 0, ny = 0;
  bool corner = false;  ///< on a corner's arc (p the corner), else on a face
  /// Arc length to the nearest joint of a face and an arc, > 0 on a face and < 0 on an arc:
  /// the curvature, and with it the tip's sliding rate, jumps where it changes sign.
  double joint = 0;
};
/// Length of the offset surface: 4 (a + b) + 2 pi r.
double offset_perimeter(const BarGeometry& g, double radius);
/// The point at arc length s (taken modulo the perimeter).
OffsetPoint offset_point(const BarGeometry& g, double radius, double s);
/// The arc length of the offset surface's point nearest to body-axis point (x, y).
double offset_coordinate(const BarGeometry& g, double radius, double x, double y);

/// A sliding tip whose base is at body-axis point (bx, by): the point q of the offset surface
/// with b - q = lambda (-n + mu sigma t) (the spring's force on the edge of the friction cone,
/// the tip sliding along sigma t), lambda of least magnitude (lambda < 0: the base is outside).
/// Closed forms on each face and corner arc.
struct SlipPoint {
  OffsetPoint at;
  double lambda = 0;  ///< [m]
};
SlipPoint slip_point(const BarGeometry& g, double radius, double mu, double sigma, double bx, double by);

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
  /// rows, events ("contact", "release", "slide", "rest", "tip stops"; with tip friction also
  /// "tip slips" and "tip sticks"), counts
  TipRunResult run;
  std::int64_t rest_analyses = 0; ///< stick/slip decisions at rest
  double max_delta = 0;           ///< largest extension of the spring |b - q| = |F|/k while touching [m]
  /// The tip friction's work at each row [J] (<= 0; all zero for tip.mu = 0): rows' work_tip is
  /// the contact force's work on the bar, work_tip - work_tip_fric what the tip passes on.
  std::vector<double> work_tip_fric;
};

/// The dynamic tip-driven push of a bar at rest from pose (x0, y0, theta0), friction load muN:
/// output at `samples` evenly spaced times over [0, t_end] (t_end <= 0: dynamic_t_end).
/// Dormand-Prince 8(5,3) at rtol between events, at most max_steps attempted steps over the whole
/// run (solver.max_steps; its default). Throws InputError naming the key for bad input
/// (tip.stiffness, tip.mu outside [0, 10], a tip starting inside the bar) and SolverError when
/// the integration fails or the budget is spent, saying why. With tip.mu > 0 the rows' work_tip is the contact force's work on the
/// bar and work_tip_fric the tip friction's (<= 0): the base's work less the spring's energy,
/// W_tip = work_tip - work_tip_fric, closes W_tip + W_fric + W_tip_fric = the kinetic energy.
DynamicRunResult run_dynamic(const BarGeometry& g, double muN, const DynamicBar& bar, const TipPath& tip, double x0,
                             double y0, double theta0, double t_end, int samples, double rtol,
                             std::int64_t max_steps = 100000);

}  // namespace nanopush::tip
