// The dynamic tip-driven push's run (tip_dynamic.hpp; docs/tip.md); the contact's geometry is
// tip_dynamic.cpp's.
//
// One event loop with two phases. At rest the bar stays where it is while the spring's wrench
// lies inside the limit surface (the coulomb law's rest analysis, stick_slip.hpp); the base
// moves on in steps no longer than the time the wrench needs to reach the limit surface at
// its fastest (a bound from the base's speed), and the exit is located by regula falsi on the
// power margin. Sliding, Dormand-Prince 8(5,3) integrates the bar with the friction of the
// sliding direction (extended through V = 0 as the coulomb law does), and a step hook stops
// before a step that holds an event: the bar comes to rest (V . mode <= 0), or the contact is
// made or broken (delta changes sign: a kink of the force), each located by regula falsi on
// sub-integrations from the step's start, as the quasi-static run locates its release.
//
// With tip friction (tip.mu > 0) the tip has a state of its own, free, stuck or sliding,
// changed at located events only (each a zero of a function that is positive while the state
// holds, located by the same regula falsi; the force is continuous across each change), and
// the state carries a ninth component, the tip friction's work; the rows and the work
// accumulators say what the state was. With tip.mu = 0 none of this runs: the eight
// components and the arithmetic are the frictionless model's, bit for bit.
//
// The run is a class, DynamicTipRun<N>: its members are the run's state (the inputs, the bar's
// state y, the tip's state, the rows), its member functions the steps, run() the event loop.
// This header holds the class with its model (the spring, the equations of motion, rows and
// events, the tip's state); tip_dynamic_rest.cpp the rest phase, tip_dynamic_slide.cpp the
// slide phase, tip_dynamic_run.cpp the entry point. A private header of nanopush_models.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "nanopush/models/friction.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/models/stick_slip.hpp"
#include "nanopush/models/tip_dynamic.hpp"
#include "nanopush/numerics/dop853.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/numerics/regula_falsi.hpp"
#include "tip_format.hpp"

namespace nanopush::tip::dyn {

using detail::fmt;

constexpr int kMaxEvents = 100000;
constexpr double kEps = std::numeric_limits<double>::epsilon();

/// N = kRoughStateSize (a frictionless tip) or kFricStateSize (tip friction: the tip
/// friction's work as a ninth component).
constexpr int kFricStateSize = kRoughStateSize + 1, kWorkTipFric = kRoughStateSize;

/// The run once the input is valid.
template <int N>
class DynamicTipRun {
 public:
  DynamicTipRun(const BarGeometry& geometry, double mu_n, const DynamicBar& dbar, const TipPath& path, double x0,
                double y0, double theta0, double end, int samples, double rtol, std::int64_t steps)
      : max_steps(steps), g(geometry), muN(mu_n), bar(dbar), tip(path), t_end(end), tout(static_cast<std::size_t>(samples)),
        L(std::max(g.a, g.b)), v(tip.speed), k(bar.stiffness), r(tip.radius), t_stop(tip.t_stop()),
        t_base_end(std::min(t_stop, t_end)), mu(tip.mu) {
    for (int i = 0; i < samples; ++i) tout[static_cast<std::size_t>(i)] = t_end * i / (samples - 1);
    tout.back() = t_end;
    res.rows.resize(tout.size());
    out.work_tip_fric.assign(tout.size(), 0.0);
    model.mass = bar.mass;
    model.inertia = bar.inertia;
    model.geometry = g;
    model.muN = muN;
    y[kX] = x0;  // at rest, no work done
    y[kY] = y0;
    y[kTheta] = theta0;
    {
      const Eval e0 = spring_at(0.0, y.data());
      if (e0.sc.delta > 1e-9 * L)
        throw InputError("tip.start", fmt_point(tip.start_x, tip.start_y),
                         "the tip (radius " + fmt(r) + " m) overlaps the bar at t = 0 by " + fmt(e0.sc.delta) +
                             " m: start it outside the bar");
    }
    // The largest friction moment (rotation about the centre of mass) and the largest lever:
    // the wrench is inside the limit surface while |F|/(mu N) + |tau|/M0 < 1 (the limit surface
    // is convex and holds the disc |f| <= mu N and the points (0, 0, +-M0)).
    M0 = std::fabs(rectangle_friction_from_velocity(g.a, g.b, muN, 0.0, 0.0, 1.0).mf);
    lever = std::hypot(g.a, g.b) + r;
    sm = std::sqrt(bar.mass);
    // The spring's fastest mode with the bar free: k over the mass, and over the inertia at
    // the longest lever.
    w_max = std::sqrt(k * (1 / bar.mass + lever * lever / bar.inertia));
    si = std::sqrt(bar.inertia);
    opt.rtol = rtol;
    opt.atol = {rtol * L, rtol * L, rtol, rtol * v, rtol * v, rtol * v / L, rtol * muN * L, rtol * muN * L};
    if constexpr (kFric) opt.atol.push_back(rtol * muN * L);
  }
  DynamicTipRun(const DynamicTipRun&) = delete;
  DynamicTipRun& operator=(const DynamicTipRun&) = delete;

  /// The event loop: rest and slide phases to t_end, then the rows left.
  DynamicRunResult run() {
    double t = 0;
    bool stopped = false;  // the "tip stops" event recorded
    while (t < t_end) {
      if (!stopped && t >= t_stop) {
        event(t_stop, "tip stops");
        stopped = true;
        if constexpr (kFric) {  // the base's velocity drops to zero: a sliding tip may stick
          if (moving) {
            ux = uy = 0;
            settle_tip(t, y.data());
          }
        }
      }
      if (!moving) {
        t = rest_phase(t);
        continue;
      }
      const double seg_end = (t < t_stop && t_stop < t_end) ? t_stop : t_end;
      t = slide_phase(t, seg_end);
    }
    if (!stopped && t_stop <= t_end) event(t_stop, "tip stops");
    std::stable_sort(res.events.begin(), res.events.end(),
                     [](const TipEvent& a, const TipEvent& b) { return a.t < b.t; });
    while (next < tout.size()) store_row(tout[next], y.data());  // the outputs at t_end (the integration reached it)
    return std::move(out);
  }

 private:
  using State = std::array<double, N>;
  static constexpr bool kFric = N > kRoughStateSize;

  // With tip friction: the tip's state (free, stuck, sliding in the sense sigma along the
  // tangent), changed at located events only; stuck, the tip's centre is at arc length
  // s_stick - r (theta - theta_stick) of the offset surface (no sliding at the contact: the
  // tip does not turn, the bar turns under it); sliding, where slip_point puts it.
  enum TipState { kFree, kStuck, kSliding };
  // Which function of the tip's state reached zero (tip_fn).
  enum Change { kNone = -1, kByFirst = 0, kBySecond = 1 };

  struct Eval {
    SpringContact sc;
    double c = 1, s = 0;
    // with tip friction: the base (body axes), the tangent, the force's normal (pushing > 0)
    // and tangential parts, lambda ((q - b).n stuck; slip_point's sliding), the arc length
    double bx = 0, by = 0, tx = 0, ty = 0, Fn = 0, Ft = 0, lambda = 0, arc = 0;
    bool corner = false;
    double joint = 0;  // the contact's arc length to the nearest joint of a face and an arc (> 0 on a face)
  };
  /// Bounds on how fast the spring's wrench changes while the bar rests, and its size.
  struct WrenchRates {
    double F, dF, dtau;
  };
  /// A slide's step that holds an event: its start (time and state) and, for the few hundred
  /// ulps after it over which an integrator's step would underflow, the span of one Euler step.
  struct StepStart {
    double t;
    State ys;
    double tiny;
  };

  const std::int64_t max_steps;  // the run's budget of attempted steps (solver.max_steps)
  std::int64_t attempted = 0;
  const BarGeometry& g;
  const double muN;
  const DynamicBar& bar;
  const TipPath& tip;
  const double t_end;
  DynamicRunResult out;
  TipRunResult& res = out.run;
  std::vector<double> tout;
  const double L, v, k, r, t_stop, t_base_end, mu;
  RoughBarModel model;
  State y{};
  TipState tstate = kFree;
  double sigma = 1, s_stick = 0, theta_stick = 0;
  double ux = 0, uy = 0;                // the base's velocity on the phase being integrated (0 once it stops)
  std::array<double, 3> mode{1, 0, 0};  // sliding direction in (vx, vy, omega L), unit
  bool moving = false;
  bool touching = false;  // the tip touches the bar (changed at the located events only)
  // At rest the bar does no work: the base's work is the spring's energy plus what the tip's
  // friction takes, integrated (Gauss-Kronrod) from the last time booked.
  double w_bar_rest = 0, t_booked = 0;
  std::size_t next = 0;  // the next row to fill
  double M0 = 0, lever = 0, sm = 0, si = 0, w_max = 0;
  Dop853Options<double> opt;

  // ---- the spring and the equations of motion --------------------------------------------
  Eval spring_at(double t, const double* s) const {
    Eval e;
    e.c = std::cos(s[kTheta]);
    e.s = std::sin(s[kTheta]);
    const auto b = tip.centre(t);
    const double dx = b[0] - s[kX], dy = b[1] - s[kY];
    if constexpr (!kFric) {
      e.sc = spring_contact(g, r, k, e.c * dx + e.s * dy, -e.s * dx + e.c * dy);
    } else {
      e.bx = e.c * dx + e.s * dy;
      e.by = -e.s * dx + e.c * dy;
      if (tstate == kFree) {  // no force until the located contact (delta tells where it is)
        e.sc = spring_contact(g, r, k, e.bx, e.by);
        e.sc.touching = false;
        e.sc.fx = e.sc.fy = e.sc.torque = 0;
        e.sc.qx = e.bx;
        e.sc.qy = e.by;
        return e;
      }
      OffsetPoint op;
      if (tstate == kStuck) {
        op = offset_point(g, r, s_stick - r * (s[kTheta] - theta_stick));
      } else {
        const SlipPoint sp = slip_point(g, r, mu, sigma, e.bx, e.by);
        op = sp.at;
        e.lambda = sp.lambda;
      }
      const bool pushing = tstate == kStuck || e.lambda > 0;  // the tip never pulls
      SpringContact& c = e.sc;
      c = {true, 0.0, op.px, op.py, op.nx, op.ny, op.qx, op.qy, pushing ? k * (e.bx - op.qx) : 0.0,
           pushing ? k * (e.by - op.qy) : 0.0};
      c.torque = c.px * c.fy - c.py * c.fx;
      e.tx = -op.ny;
      e.ty = op.nx;
      e.Fn = -(c.fx * op.nx + c.fy * op.ny);
      e.Ft = c.fx * e.tx + c.fy * e.ty;
      if (tstate == kStuck) e.lambda = (op.qx - e.bx) * op.nx + (op.qy - e.by) * op.ny;
      c.delta = e.lambda;
      e.arc = op.s;
      e.corner = op.corner;
      e.joint = op.joint;
    }
    return e;
  }
  // The base's velocity relative to the bar, body axes: R(-theta)(u - v) + omega (by, -bx).
  std::array<double, 2> bdot(const Eval& e, const double* s) const {
    const double rx = ux - s[kVx], ry = uy - s[kVy];
    return std::array<double, 2>{e.c * rx + e.s * ry + s[kOmega] * e.by, -e.s * rx + e.c * ry - s[kOmega] * e.bx};
  }
  // Sliding: the tip's velocity relative to the bar's point under it along the tangent,
  // ds/dt + omega r, ds/dt by implicit differentiation of slip_point's condition
  // (b - q(s)) x d(s) = 0, d = -n + mu sigma t: (bdot x d) / (1 - lambda (1 + mu^2)/r) on a
  // corner's arc (the curvature 1/r), bdot x d on a face.
  double slip_velocity(const Eval& e, const double* s) const {
    const auto bd = bdot(e, s);
    const double dx = -e.sc.nx + mu * sigma * e.tx, dy = -e.sc.ny + mu * sigma * e.ty;
    const double den = e.corner ? 1 - e.lambda * (1 + mu * mu) / r : 1.0;
    return (bd[0] * dy - bd[1] * dx) / den + s[kOmega] * r;  // bd x (dx, dy)
  }
  double spring_energy(const Eval& e) const { return (e.sc.fx * e.sc.fx + e.sc.fy * e.sc.fy) / (2 * k); }
  int rhs(double t, const double* s, double* d) {
    ++res.nfcn;
    const Eval e = spring_at(t, s);
    const double Fx = e.c * e.sc.fx - e.s * e.sc.fy, Fy = e.s * e.sc.fx + e.c * e.sc.fy;
    const WorldWrench fr = coulomb_friction(model, s, mode);
    d[kX] = s[kVx];
    d[kY] = s[kVy];
    d[kTheta] = s[kOmega];
    d[kVx] = (Fx + fr.fx) / bar.mass;
    d[kVy] = (Fy + fr.fy) / bar.mass;
    d[kOmega] = (e.sc.torque + fr.mf) / bar.inertia;
    if constexpr (!kFric) {
      // The spring's power at the contact point (body axes), and the friction's.
      const double vbx = e.c * s[kVx] + e.s * s[kVy], vby = -e.s * s[kVx] + e.c * s[kVy];
      d[kWorkPush] = e.sc.fx * (vbx - s[kOmega] * e.sc.py) + e.sc.fy * (vby + s[kOmega] * e.sc.px);
    } else {
      // The base's power (the spring's energy and what the tip passes on), and the tip
      // friction's: minus the tangential force times the sliding velocity.
      d[kWorkPush] = Fx * ux + Fy * uy;
      d[kWorkTipFric] = tstate == kSliding ? -e.Ft * slip_velocity(e, s) : 0.0;
    }
    d[kWorkFric] = fr.fx * s[kVx] + fr.fy * s[kVy] + fr.mf * s[kOmega];
    return 0;
  }
  auto rhs_fn() {
    return [this](double t, const double* s, double* d) { return rhs(t, s, d); };
  }

  // ---- the step budget -----------------------------------------------------------------
  // An integrator whose step limit is what is left of the run's budget.
  Dop853<double, N> integrator() {
    opt.maxstp = std::max<std::int64_t>(1, max_steps - attempted);
    return Dop853<double, N>(opt);
  }
  // Books an integration's steps against the budget; if it failed and must succeed, throws
  // with the reason: the budget spent, a slide too slow for double's steps, or the integrator's.
  void spend(const IntegrationResult& ir, bool must_succeed) {
    res.steps += ir.naccpt;
    attempted += ir.naccpt + ir.nrejct;
    if (ir.ok() || !must_succeed) return;
    const double ratio = inertia_ratio(bar.mass, v, muN, tip.travel);
    const std::string advice =
        ratio <= kAutoInertiaRatio ? "; inertia is negligible at this tip speed (m v^2/(mu N L) = " + fmt(ratio) +
                                         " <= " + fmt(kAutoInertiaRatio) + "): use tip.model = quasi_static or auto"
                                   : "";
    if (ir.status == IntegrationStatus::too_many_steps && attempted >= max_steps)
      throw SolverError("dynamic tip push: too many steps: solver.max_steps = " + std::to_string(max_steps) +
                        " steps spent by t = " + fmt(ir.t_reached) + " s of " + fmt(t_end) +
                        " s; the dynamic model follows every period of the spring (" + fmt(2 * M_PI / w_max) + " s at its fastest) and every slide's start" +
                        (advice.empty() ? ": raise solver.max_steps" : advice + ", or raise solver.max_steps"));
    const double speed = std::sqrt(y[kVx] * y[kVx] + y[kVy] * y[kVy] + y[kOmega] * y[kOmega] * L * L);
    if (ir.status == IntegrationStatus::step_underflow && bar.mass * speed / muN < 1e6 * kEps * ir.t_reached)
      throw SolverError("dynamic tip push: step size underflow at t = " + fmt(ir.t_reached) +
                        " s: the bar slides so slowly (|V| = " + fmt(speed) + " m/s) that the friction across its "
                        "direction relaxes in m |V|/(mu N) = " + fmt(bar.mass * speed / muN) +
                        " s, below the steps double precision can take at that time" + advice);
    throw SolverError("dynamic tip push: " + ir.message);
  }

  // ---- rows and events -------------------------------------------------------------------
  TipRow make_row(double t, const double* s) {
    TipRow row{.t = t, .x = s[kX], .y = s[kY], .theta = s[kTheta], .vx = s[kVx], .vy = s[kVy], .omega = s[kOmega],
               .work_tip = s[kWorkPush], .work_fric = s[kWorkFric]};
    const Eval e = spring_at(t, s);
    row.tip_x = s[kX] + e.c * e.sc.qx - e.s * e.sc.qy;
    row.tip_y = s[kY] + e.s * e.sc.qx + e.c * e.sc.qy;
    const double Fx = e.c * e.sc.fx - e.s * e.sc.fy, Fy = e.s * e.sc.fx + e.c * e.sc.fy;
    if (e.sc.touching) {
      row.tip_fx = Fx;
      row.tip_fy = Fy;
      row.contact = ContactMode::slide;  // a frictionless tip slides on the bar
      if constexpr (!kFric) {
        out.max_delta = std::max(out.max_delta, e.sc.delta);
      } else {
        if (tstate == kStuck) row.contact = ContactMode::stick;
        out.max_delta = std::max(out.max_delta, std::hypot(e.sc.fx, e.sc.fy) / k);
      }
    }
    if constexpr (kFric) {  // the work on the bar: the base's less the spring's energy, plus the tip friction's
      row.work_tip = s[kWorkPush] - spring_energy(e) + s[kWorkTipFric];
    }
    if (moving) {
      const WorldWrench fr = coulomb_friction(model, s, mode);
      row.fx = fr.fx;
      row.fy = fr.fy;
      row.mf = fr.mf;
    } else {  // stuck: static friction balances the spring
      row.fx = -Fx;
      row.fy = -Fy;
      row.mf = -e.sc.torque;
    }
    return row;
  }
  // The next row, at time t with state s.
  void store_row(double t, const double* s) {
    if constexpr (kFric) out.work_tip_fric[next] = s[kWorkTipFric];
    res.rows[next++] = make_row(t, s);
  }
  // The integrators' observer: the row, where the output time t is the next row's.
  void observe(double t, const double* s) {
    if (next < tout.size() && tout[next] == t) store_row(t, s);
  }
  auto observer_fn() {
    return [this](std::size_t, double t, const double* s) { observe(t, s); };
  }
  // The output times from the next row's to t_to, and t_to.
  std::vector<double> outputs_until(double t_to) const {
    std::vector<double> ts;
    for (std::size_t i = next; i < tout.size() && tout[i] <= t_to; ++i) ts.push_back(tout[i]);
    if (ts.empty() || ts.back() < t_to) ts.push_back(t_to);
    return ts;
  }
  void event(double t, const char* what) {
    res.events.push_back({t, what});
    if (res.events.size() > static_cast<std::size_t>(kMaxEvents))
      throw SolverError("dynamic tip push: more than " + std::to_string(kMaxEvents) + " events by t = " + fmt(t) +
                        " s (contact or stick-slip chatter)");
  }

  // ---- the tip's state (tip friction) ----------------------------------------------------
  // Each state holds while its functions are positive: free, -delta (the base outside the
  // offset surface); stuck, mu F_n - |F_t| (inside the friction cone); sliding, lambda (the
  // base inside) and sigma times the sliding velocity (it slides on). Each carries a margin
  // of rounding (1e-12 of its scale) so that a state just entered, whose function starts at
  // zero and grows, is not left again at once.
  double tip_fn(int which, const Eval& e, const double* s) const {
    switch (tstate) {
      case kFree: return -e.sc.delta;
      case kStuck:
        return mu * e.Fn - std::fabs(e.Ft) + 1e-12 * std::hypot(e.sc.fx, e.sc.fy) + std::numeric_limits<double>::min();
      case kSliding:
        if (which == kByFirst) return e.lambda + 1e-15 * r;
        {
          const auto bd = bdot(e, s);
          return sigma * slip_velocity(e, s) + 1e-12 * (std::hypot(bd[0], bd[1]) + std::fabs(s[kOmega]) * r) +
                 std::numeric_limits<double>::min();
        }
    }
    return 1.0;
  }
  int tip_fns() const { return tstate == kSliding ? 2 : 1; }
  // The change when function `which` of the state has reached zero at time t (state s).
  void change_tip(double t, const double* s, int which) {
    const Eval e = spring_at(t, s);
    if (tstate == kFree) {  // contact: stuck if the force it starts to build lies in the cone
      const OffsetPoint op = offset_point(g, r, offset_coordinate(g, r, e.bx, e.by));
      const auto bd = bdot(e, s);
      const double ct = bd[0] * -op.ny + bd[1] * op.nx + s[kOmega] * r, cn = -(bd[0] * op.nx + bd[1] * op.ny);
      if (std::fabs(ct) <= mu * cn) {
        tstate = kStuck;
        s_stick = op.s;
        theta_stick = s[kTheta];
      } else {
        tstate = kSliding;
        sigma = ct >= 0 ? 1.0 : -1.0;
      }
      event(t, "contact");
    } else if (tstate == kStuck) {  // the force reached the cone's edge: it slides, or lets go
      if (e.Fn > 0) {
        tstate = kSliding;
        sigma = e.Ft >= 0 ? 1.0 : -1.0;
        event(t, "tip slips");
      } else {
        tstate = kFree;
        event(t, "release");
      }
    } else if (which == kByFirst) {
      tstate = kFree;
      event(t, "release");
    } else {
      tstate = kStuck;
      s_stick = e.arc;
      theta_stick = s[kTheta];
      event(t, "tip sticks");
    }
  }
  // Changes that are due at time t itself (the base or the bar stopped, a velocity jumped).
  void settle_tip(double t, const double* s) {
    for (int i = 0; i < 4; ++i) {
      const Eval e = spring_at(t, s);
      int due = kNone;
      for (int w = 0; w < tip_fns() && due == kNone; ++w)
        if (!(tip_fn(w, e, s) > 0)) due = w;
      if (due == kNone) return;
      change_tip(t, s, due);
    }
  }
  // The base's velocity from time t on: v along the path until the tip stops.
  void set_base_velocity(double t) {
    ux = t < t_stop ? v * std::cos(tip.direction) : 0.0;
    uy = t < t_stop ? v * std::sin(tip.direction) : 0.0;
  }

  // ---- at rest -------------------------------------------------------------------------
  // The work booked at rest up to t1 (tip friction).
  void book_rest(double t1);
  void start_rest_books(double t);
  // The rows before t_limit (and at it, inclusive), the bar at rest.
  void rest_rows_until(double t_limit, bool inclusive);
  // The rest analysis at time t, the bar held at y.
  RestAnalysis analyse(double t);
  // Bounds on how fast the spring's wrench changes while the bar rests: |dF/dt| <= k v,
  // |dtau/dt| <= k v (lever + delta).
  WrenchRates wrench_rates(const Eval& e) const;
  // The slide starts at t (the rest analysis ra there): the first tau0 of it in closed form.
  // Where the spring's wrench has just crossed the limit surface, the acceleration grows from
  // zero and the velocity from zero as s^2; at such small speeds the friction across the
  // sliding direction relaxes at the rate mu N/(m |V|), which no explicit step can follow
  // (the steps over [t, t + tau] add up as 1/tau). Over tau0 = 1e-3 of the time the spring's
  // force takes to change by mu N, the acceleration is linear between its values at t and
  // t + tau0 (the bar held there), which gives V and the displacement to leading order; the
  // work done is booked as the kinetic energy gained plus the friction's share. Holding the
  // bar neglects the spring's relaxation as it moves, a relative (w tau0)^2/6 at the spring's
  // frequency w: tau0 is also at most 1e-2/w_max (1.7e-5), which slow tips reach first.
  double start_slide(double t, const RestAnalysis& ra);
  // From time t with the bar at rest: the time the slide starts (located), or t_end.
  double rest_phase(double t);
  // Tip friction: the tip's state changed in (tp, tt]? The first change, located (the bar
  // held), ends the step there: the force is continuous across it, the rest analysis goes on
  // from it. Returns the step's end.
  double rest_tip_change(double tp, double tt);
  // A frictionless tip: the contact changed between tp and tt (e at tt)? Locate it.
  void rest_contact_change(double tp, double tt, const Eval& e);
  // The wrench has left the limit surface by tt (ra there; stuck at tp): locate the slide's
  // start, begin it, and return the time its closed-form start reaches.
  double slide_from_rest(double tp, double tt, RestAnalysis ra);
  // The base has stopped with the bar at rest: at rest for good; the rows to t_end.
  double end_rest();

  // ---- sliding -------------------------------------------------------------------------
  double along(const double* s) const { return s[kVx] * mode[0] + s[kVy] * mode[1] + s[kOmega] * L * mode[2]; }
  // The slide has run down to the requested accuracy: every velocity component within its
  // absolute tolerance while the kinetic energy falls (near rest the friction across the
  // sliding direction relaxes at the rate mu N/(m |V|), and the problem turns stiff).
  bool run_down(double t, const double* s);
  // The bar comes to rest at t.
  void come_to_rest(double t);
  // From time t, sliding: integrate to the next event (or seg_end); returns the time reached.
  double slide_phase(double t, double seg_end);
  // The state at tc from the step's start (tc >= its start): one Euler step over a tiny span
  // (tip friction), a sub-integration otherwise.
  State state_at(const StepStart& st, double tc);
  // One Euler step from (t, yc) to tc.
  void euler(double t, State& yc, double tc);
  // The zero of fn(t, s) in the step (st.t, tb] (state yb at tb) if fn's sign left was_positive
  // there: tb + 1 if it did not.
  template <class Fn>
  double locate(const StepStart& st, double tb, const State& yb, Fn&& fn, bool was_positive);
  // Tip friction: the first of the tip state's functions to reach zero in (st.t, tb] (which),
  // and when; tb + 1 if none does.
  double first_tip_change(const StepStart& st, double tb, const State& yb, int& which);
  // An event inside (t, tb]: the earliest of rest and contact change, by regula falsi on
  // sub-integrations from t; the slide is taken to it and the event applied.
  double slide_event(double t, double tb);
  // The slide from the step's start to the event at t_ev, with its rows.
  void finish_slide(const StepStart& st, double t_ev);
};

}  // namespace nanopush::tip::dyn
