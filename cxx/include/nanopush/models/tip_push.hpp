// A push by a moving AFM tip (docs/tip.md): a disc of radius r whose centre moves along a
// straight line at constant speed, in unilateral contact with the bar (the tip pushes, never
// pulls), with Coulomb friction tip.mu at the tip-bar contact.
//
// The quasi-static model (thesis chapters 4-5: the object in force equilibrium at every
// instant, inertia neglected). The body's twist V (body axes: vx', vy', omega) is the one that
// minimises the surface friction's dissipation rate D(V) = -f(V).V (f the closed-form Coulomb
// wrench over the contact rectangle, friction.hpp) subject to the contact's kinematic
// constraint (maximum dissipation; Mason's quasi-static pushing):
//   * sticking tip: the contact point moves with the tip, v_p(V) = u, a 1-D convex problem in
//     omega, accepted when the contact force -f(V) lies in the tip's friction cone;
//   * sliding tip (or tip.mu = 0): the contact force lies on the edge of the cone, direction e
//     known; D is minimised on the plane w_e.V = 1 (w_e the unit force's wrench), so that
//     -f(V) = lambda w_e, then V is scaled so that the contact point's normal velocity equals
//     the tip's.
// The tip's normal approach keeps the tip on the body's surface; the contact breaks when the
// tip stops approaching (it slides off an end, or its path turns away).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "nanopush/models/rigid_body.hpp"

namespace nanopush::tip {

/// The tip and its straight path (world axes, SI).
struct TipPath {
  double radius = 10e-9;     ///< tip radius r [m]
  double start_x = 0, start_y = 0;  ///< tip centre at t = 0 [m]
  double direction = 0;      ///< world direction of motion [rad]
  double speed = 1e-6;       ///< [m/s]
  double travel = 100e-9;    ///< path length [m]
  double mu = 0;             ///< tip-bar Coulomb friction coefficient
  /// Time the tip stops: travel / speed [s].
  [[nodiscard]] double t_stop() const { return travel / speed; }
  /// Tip centre at time t (it rests at the end of its travel after t_stop).
  [[nodiscard]] std::array<double, 2> centre(double t) const;
  /// Tip velocity at time t (zero after t_stop).
  [[nodiscard]] std::array<double, 2> velocity(double t) const;
  /// Throws InputError naming the field unless every value is finite and in range.
  void validate() const;
};

/// Where a disc centred at body-axis point (qx, qy) meets the rectangle [-a, a] x [-b, b]:
/// the closest point p, the outward unit normal n there (from the body towards the disc
/// centre) and the distance from the centre to the rectangle (0 inside).
struct ContactGeometry {
  double px = 0, py = 0;  ///< closest point on the rectangle, body axes [m]
  double nx = 0, ny = 0;  ///< outward unit normal, body axes
  double distance = 0;    ///< [m]
  bool inside = false;    ///< the centre lies inside the rectangle (no normal)
};
ContactGeometry contact_geometry(const BarGeometry& g, double qx, double qy);

/// How the tip meets the bar at an instant.
enum class ContactMode : int { none = 0, stick = 1, slide = 2 };
const char* to_string(ContactMode m);

/// The quasi-static answer at an instant, in body axes.
struct QuasiStaticTwist {
  ContactMode mode = ContactMode::none;
  double vx = 0, vy = 0, omega = 0;  ///< body twist: CM velocity (body axes) [m/s], [rad/s]
  double fx = 0, fy = 0;             ///< contact force on the body (body axes) [N]
  double px = 0, py = 0;             ///< contact point (body axes) [m]
  double dissipation = 0;            ///< D(V) = power of the contact force [W]
  double residual = 0;               ///< max |force/moment balance| / (mu N) at the answer
  int iterations = 0;
};

/// The quasi-static twist for a tip moving at body-axis velocity (ux, uy) and touching the bar
/// at contact geometry c (c.distance is not used: the tip is taken as touching). The friction
/// load muN is the surface's mu times the normal load; tip_mu the tip's friction coefficient.
/// Mode none (zero twist) when the tip does not approach the surface (u.n >= 0).
QuasiStaticTwist quasi_static_twist(const BarGeometry& g, double muN, double tip_mu, const ContactGeometry& c,
                                    double ux, double uy);

/// One output row of a tip-driven run (world axes, SI).
struct TipRow {
  double t = 0;
  double x = 0, y = 0, theta = 0, vx = 0, vy = 0, omega = 0;
  double fx = 0, fy = 0, mf = 0;          ///< surface friction wrench on the body (world)
  double tip_x = 0, tip_y = 0;            ///< tip centre
  double tip_fx = 0, tip_fy = 0;          ///< contact force of the tip on the body (world)
  double work_tip = 0, work_fric = 0;     ///< work done by the tip and by the surface friction [J]
  ContactMode contact = ContactMode::none;
};
/// Column names of TipRow (CSV header order), and their units.
const std::vector<std::string>& tip_row_columns();
const std::vector<std::string>& tip_row_units();

/// A contact change located in time.
struct TipEvent {
  double t = 0;
  std::string what;  ///< "contact", "release", "tip stops"
};

struct TipRunResult {
  std::vector<TipRow> rows;
  std::vector<TipEvent> events;
  std::int64_t nfcn = 0;       ///< quasi-static twists evaluated
  std::int64_t steps = 0;      ///< accepted integration steps
  double gap_drift = 0;        ///< max |distance - r| while in contact [m] (the constraint's drift)
};

/// The quasi-static tip-driven push of a bar at rest from pose (x0, y0, theta0) on a surface of
/// friction load muN: the tip moves freely until it touches the bar (located exactly), the
/// pose then follows the quasi-static twist (Dormand-Prince 8(5,3), rtol) until the tip stops
/// or releases the bar (located), after which the bar stays where it is. Output at `samples`
/// evenly spaced times over [0, t_end] (t_end <= 0: t_stop). Throws InputError for bad input
/// (a tip that starts inside the bar) and SolverError if the quasi-static problem has no answer.
TipRunResult run_quasi_static(const BarGeometry& g, double muN, const TipPath& tip, double x0, double y0, double theta0,
                              double t_end, int samples, double rtol);

}  // namespace nanopush::tip
