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
#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss_kronrod.hpp>
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

namespace nanopush::tip {

namespace {

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
      throw SolverError("dynamic tip push: solver.max_steps = " + std::to_string(max_steps) + " steps spent by t = " +
                        fmt(ir.t_reached) + " s of " + fmt(t_end) + " s; the dynamic model follows every period of the "
                        "spring (" + fmt(2 * M_PI / w_max) + " s at its fastest) and every slide's start" +
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
  void book_rest(double t1) {
    if constexpr (kFric) {
      if (moving || !(t1 > t_booked)) return;
      if (tstate == kSliding) {
        const double X = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
            [&](double tc) {
              const Eval e = spring_at(tc, y.data());
              return e.Ft * slip_velocity(e, y.data());
            },
            t_booked, t1, 10, 1e-12);
        y[kWorkTipFric] -= X;
      }
      y[kWorkPush] = w_bar_rest + spring_energy(spring_at(t1, y.data())) - y[kWorkTipFric];
      t_booked = t1;
    }
  }
  void start_rest_books(double t) {
    if constexpr (kFric) {
      w_bar_rest = y[kWorkPush] - spring_energy(spring_at(t, y.data())) + y[kWorkTipFric];
      t_booked = t;
    }
  }
  // The rows before t_limit (and at it, inclusive), the bar at rest.
  void rest_rows_until(double t_limit, bool inclusive) {
    while (next < tout.size() && (tout[next] < t_limit || (inclusive && tout[next] <= t_limit))) {
      book_rest(tout[next]);
      store_row(tout[next], y.data());
    }
  }
  // The rest analysis at time t, the bar held at y.
  RestAnalysis analyse(double t) {
    const Eval e = spring_at(t, y.data());
    RestAnalysis ra;
    if (!e.sc.touching) {
      ra.margin = -muN / sm;  // nothing pushes (the margin of a vanishing wrench is -min D)
      return ra;
    }
    const double Fx = e.c * e.sc.fx - e.s * e.sc.fy, Fy = e.s * e.sc.fx + e.c * e.sc.fy;
    model.push = Push{std::hypot(Fx, Fy), std::atan2(Fy, Fx), e.sc.px, e.sc.py};
    ra = analyse_rest(model, y[kTheta]);
    model.push = Push{};
    // analyse_rest counts a margin within 1e-12 of the scaled wrench as stuck: the same zero.
    ra.margin -= 1e-12 * std::sqrt((Fx * Fx + Fy * Fy) / bar.mass + e.sc.torque * e.sc.torque / bar.inertia);
    ++out.rest_analyses;
    res.nfcn += ra.evaluations;
    return ra;
  }
  // Bounds on how fast the spring's wrench changes while the bar rests: |dF/dt| <= k v,
  // |dtau/dt| <= k v (lever + delta).
  WrenchRates wrench_rates(const Eval& e) const {
    double F = k * e.sc.delta, dF = k * v, dtau = k * v * (lever + e.sc.delta);
    if constexpr (kFric) {
      // |F| = k |b - q|; stuck, q rests (|dF/dt| <= k v); sliding, q moves at |ds/dt| <=
      // v (1 + mu)/den (den the corner's 1 - lambda (1 + mu^2)/r), so |dF/dt| <= k v (2 + mu)/den,
      // and the lever's end moves with it: |dtau/dt| <= |dF/dt| lever + |dq/dt| F.
      F = std::hypot(e.sc.fx, e.sc.fy);
      const double den = e.corner ? std::max(1 - e.lambda * (1 + mu * mu) / r, 0.5) : 1.0;
      const double cq = tstate == kSliding ? (1 + mu) / den : 0.0;
      dF = k * v * (tstate == kSliding ? (2 + mu) / den : 1.0);
      dtau = dF * lever + v * cq * F;
    }
    return {F, dF, dtau};
  }
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
  double start_slide(double t, const RestAnalysis& ra) {
    const double tau0 = std::min({1e-3 * muN / (k * v), 1e-2 / w_max, std::max(t_base_end - t, 0.0)});
    std::array<double, 3> A0 = ra.accel, A1 = ra.accel;
    if (tau0 > 0) {
      const RestAnalysis r1 = analyse(t + tau0);
      if (!r1.stuck) A1 = r1.accel;
    }
    const double V[3] = {0.5 * (A0[0] + A1[0]) * tau0, 0.5 * (A0[1] + A1[1]) * tau0, 0.5 * (A0[2] + A1[2]) * tau0};
    const double D[3] = {(2 * A0[0] + A1[0]) * tau0 * tau0 / 6, (2 * A0[1] + A1[1]) * tau0 * tau0 / 6,
                         (2 * A0[2] + A1[2]) * tau0 * tau0 / 6};
    const double dir[3] = {tau0 > 0 ? V[0] : A0[0], tau0 > 0 ? V[1] : A0[1], (tau0 > 0 ? V[2] : A0[2]) * L};
    const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    mode = {dir[0] / n, dir[1] / n, dir[2] / n};
    moving = true;
    if (!(tau0 > 0)) return t;
    const WorldWrench f = coulomb_friction(model, y.data(), mode);  // y at rest: the mode's friction
    const double ke = 0.5 * bar.mass * (V[0] * V[0] + V[1] * V[1]) + 0.5 * bar.inertia * V[2] * V[2];
    const double wf = f.fx * D[0] + f.fy * D[1] + f.mf * D[2];
    Eval e0;
    if constexpr (kFric) e0 = spring_at(t, y.data());
    for (int i = 0; i < 3; ++i) {
      y[kX + i] += D[i];
      y[kVx + i] = V[i];
    }
    y[kWorkFric] += wf;
    if constexpr (!kFric) {
      y[kWorkPush] += ke - wf;
    } else {  // the base's work: the bar's, the spring's energy gained, the tip friction's share
      const Eval e1 = spring_at(t + tau0, y.data());
      double X = 0;  // the tangential force times the distance slid, ds + r dtheta
      if (tstate == kSliding) {
        const double P = offset_perimeter(g, r);
        X = 0.5 * (e0.Ft + e1.Ft) * (std::remainder(e1.arc - e0.arc, P) + r * D[2]);
      }
      y[kWorkTipFric] -= X;
      y[kWorkPush] += ke - wf + spring_energy(e1) - spring_energy(e0) + X;
    }
    return t + tau0;
  }
  // From time t with the bar at rest: the time the slide starts (located), or t_end.
  double rest_phase(double t) {
    double tp = t;  // the last time the bar was known stuck
    double tt = t;
    if constexpr (kFric) {
      set_base_velocity(t);
      settle_tip(t, y.data());
      start_rest_books(t);
    }
    for (long it = 0;; ++it) {
      if (it > 10000000) throw SolverError("dynamic tip push: the rest phase from t = " + fmt(t) + " s does not end");
      if constexpr (kFric) tt = rest_tip_change(tp, tt);
      const Eval e = spring_at(tt, y.data());
      if constexpr (!kFric) rest_contact_change(tp, tt, e);
      touching = e.sc.touching;
      double jump = 0;
      if (e.sc.touching) {
        const WrenchRates w = wrench_rates(e);
        const double cheap = w.F / muN + std::fabs(e.sc.torque) / M0;
        if (cheap < 1) {
          jump = (1 - cheap) / (w.dF / muN + w.dtau / M0);
        } else {
          const RestAnalysis ra = analyse(tt);
          if (!ra.stuck) return slide_from_rest(tp, tt, ra);
          jump = -ra.margin / (w.dF / sm + w.dtau / si);
        }
      } else {
        jump = -e.sc.delta / v;  // the gap closes at most at the base's speed
      }
      if (tt >= t_base_end) break;  // the base no longer moves: at rest for good
      tp = tt;
      tt = std::min(tt + std::max(jump, muN / (16 * k * v)), t_base_end);
    }
    return end_rest();
  }
  // Tip friction: the tip's state changed in (tp, tt]? The first change, located (the bar
  // held), ends the step there: the force is continuous across it, the rest analysis goes on
  // from it. Returns the step's end.
  double rest_tip_change(double tp, double tt) {
    if (!(tt > tp)) return tt;
    double t_change = tt + 1;
    int which = kNone;
    for (int w = 0; w < tip_fns(); ++w) {
      auto fn = [&](double tc) { return tip_fn(w, spring_at(tc, y.data()), y.data()); };
      const double gb = fn(tt);
      if (gb > 0) continue;
      double a = tp, b = tt;
      const double ga = fn(a);
      if (ga > 0)
        roots::illinois(a, b, ga, gb, 200, [&](double l, double h) { return h - l > 1e-15 * t_stop; }, fn,
                        [](int) {});
      else
        b = a;
      if (b < t_change) {
        t_change = b;
        which = w;
      }
    }
    if (which != kNone) {
      rest_rows_until(t_change, false);
      book_rest(t_change);
      tt = t_change;
      change_tip(tt, y.data(), which);
      start_rest_books(tt);
    }
    return tt;
  }
  // A frictionless tip: the contact changed between tp and tt (e at tt)? Locate it.
  void rest_contact_change(double tp, double tt, const Eval& e) {
    if (e.sc.touching != touching && tt > tp) {
      double a = tp, b = tt;
      const double ga = spring_at(a, y.data()).sc.delta, gb = e.sc.delta;
      roots::illinois(a, b, ga, gb, 200, [&](double l, double h) { return h - l > 1e-15 * t_stop; },
                      [&](double tc) { return spring_at(tc, y.data()).sc.delta; }, [](int) {});
      event(e.sc.touching ? b : a, e.sc.touching ? "contact" : "release");
    }
  }
  // The wrench has left the limit surface by tt (ra there; stuck at tp): locate the slide's
  // start, begin it, and return the time its closed-form start reaches.
  double slide_from_rest(double tp, double tt, RestAnalysis ra) {
    if (tt > tp) {  // locate where the margin crosses zero in (tp, tt]
      double a = tp, b = tt;
      roots::illinois(a, b, analyse(a).margin, ra.margin, 200,
                      [&](double l, double h) { return h - l > 1e-14 * std::max(t_stop, h); },
                      [&](double tc) { return analyse(tc).margin; }, [](int) {});
      if (b < tt) {
        tt = b;
        ra = analyse(tt);
      }
    }
    // Rounding may leave the located end stuck: step on until the wrench has left.
    for (int i = 0; ra.stuck && i < 60; ++i) {
      tt += std::ldexp(1e-15 * std::max(t_stop, tt), i);
      ra = analyse(tt);
    }
    if (ra.stuck) throw SolverError("dynamic tip push: the start of a slide at t = " + fmt(tt) + " s is not resolved");
    rest_rows_until(tt, true);
    book_rest(tt);
    event(tt, "slide");
    const double t1 = start_slide(tt, ra);
    rest_rows_until(t1, false);  // outputs inside the closed-form start (rare): at its end state
    return t1;
  }
  // The base has stopped with the bar at rest: at rest for good; the rows to t_end.
  double end_rest() {
    if constexpr (kFric) {  // a sliding tip stops sliding with the base
      rest_rows_until(t_base_end, true);
      book_rest(t_base_end);
      if (t_base_end >= t_stop) {
        ux = uy = 0;
        settle_tip(t_base_end, y.data());
        start_rest_books(t_base_end);
      }
    }
    rest_rows_until(t_end, true);
    return t_end;
  }

  // ---- sliding -------------------------------------------------------------------------
  double along(const double* s) const { return s[kVx] * mode[0] + s[kVy] * mode[1] + s[kOmega] * L * mode[2]; }
  // The slide has run down to the requested accuracy: every velocity component within its
  // absolute tolerance while the kinetic energy falls (near rest the friction across the
  // sliding direction relaxes at the rate mu N/(m |V|), and the problem turns stiff).
  bool run_down(double t, const double* s) {
    double d[N];
    rhs(t, s, d);
    const double dke = bar.mass * (s[kVx] * d[kVx] + s[kVy] * d[kVy]) + bar.inertia * s[kOmega] * d[kOmega];
    if (!(dke < 0)) return false;
    if (std::fabs(s[kVx]) <= opt.atol[kVx] && std::fabs(s[kVy]) <= opt.atol[kVy] &&
        std::fabs(s[kOmega]) <= opt.atol[kOmega])
      return true;
    // or (decelerating) the distance and angle still to travel, v^2/(2|a|) and omega^2/(2|alpha|),
    // are within the position and angle tolerances (as the coulomb law's slides end).
    const double v2 = s[kVx] * s[kVx] + s[kVy] * s[kVy], vdota = s[kVx] * d[kVx] + s[kVy] * d[kVy];
    const double acc = std::hypot(d[kVx], d[kVy]);
    const bool lin = v2 == 0.0 || (vdota < 0 && v2 <= 2 * acc * opt.atol[kX]);
    const bool rot = s[kOmega] == 0.0 ||
                     (s[kOmega] * d[kOmega] < 0 && s[kOmega] * s[kOmega] <= 2 * std::fabs(d[kOmega]) * opt.atol[kTheta]);
    return lin && rot;
  }
  // The bar comes to rest at t.
  void come_to_rest(double t) {
    y[kVx] = y[kVy] = y[kOmega] = 0;
    moving = false;
    event(t, "rest");
  }
  // From time t, sliding: integrate to the next event (or seg_end); returns the time reached.
  double slide_phase(double t, double seg_end) {
    if constexpr (kFric) set_base_velocity(t);  // the base moves on the whole segment or not at all
    const std::vector<double> pending = outputs_until(seg_end);
    bool ran_down = false;
    auto hook = [&](double t0, const double* s0, double tn, const double* sn) {
      if (along(sn) <= 0) return kHookStopBefore;
      if constexpr (!kFric) {
        if ((spring_at(tn, sn).sc.delta > 0) != touching) return kHookStopBefore;
      } else {
        const Eval e = spring_at(tn, sn);
        for (int w = 0; w < tip_fns(); ++w)
          if (!(tip_fn(w, e, sn) > 0)) return kHookStopBefore;
        if (tstate != kFree && (e.joint > 0) != (spring_at(t0, s0).joint > 0)) return kHookStopBefore;
      }
      if (run_down(tn, sn)) {
        ran_down = true;
        return kHookStopAfter;
      }
      return kHookContinue;
    };
    Dop853<double, N> integ = integrator();
    const auto rr = integ.integrate(rhs_fn(), t, y.data(), std::span<const double>(pending), observer_fn(), hook);
    spend(rr, true);
    t = rr.t_reached;
    if (!rr.stopped_by_hook) return t;
    if (ran_down) {
      come_to_rest(t);
      return t;
    }
    return slide_event(t, rr.t_event_end);
  }
  // The state at tc from the step's start (tc >= its start): one Euler step over a tiny span
  // (tip friction), a sub-integration otherwise.
  State state_at(const StepStart& st, double tc) {
    State yc = st.ys;
    if (kFric && tc > st.t && tc - st.t <= st.tiny) {
      euler(st.t, yc, tc);
    } else if (tc > st.t) {
      Dop853<double, N> sub = integrator();
      const double one[1] = {tc};
      const auto sr = sub.integrate(rhs_fn(), st.t, yc.data(), std::span<const double>(one, 1),
                                    [](std::size_t, double, const double*) {});
      spend(sr, false);
    }
    return yc;
  }
  // One Euler step from (t, yc) to tc.
  void euler(double t, State& yc, double tc) {
    double d[N];
    rhs(t, yc.data(), d);
    for (int i = 0; i < N; ++i) yc[static_cast<std::size_t>(i)] += (tc - t) * d[i];
  }
  // The zero of fn(t, s) in the step (st.t, tb] (state yb at tb) if fn's sign left was_positive
  // there: tb + 1 if it did not.
  template <class Fn>
  double locate(const StepStart& st, double tb, const State& yb, Fn&& fn, bool was_positive) {
    double a = st.t, b = tb;
    const double ga = fn(a, st.ys.data()), gb = fn(b, yb.data());
    if ((gb > 0) == was_positive) return tb + 1;  // not this event
    if ((ga > 0) == (gb > 0)) return tb;          // at the step's start within rounding: at its end
    roots::illinois(a, b, ga, gb, 100, [&](double l, double h) { return h - l > 1e-14 * std::max(t_stop, h); },
                    [&](double tc) { return fn(tc, state_at(st, tc).data()); }, [](int) {});
    return b;
  }
  // Tip friction: the first of the tip state's functions to reach zero in (st.t, tb] (which),
  // and when; tb + 1 if none does.
  double first_tip_change(const StepStart& st, double tb, const State& yb, int& which) {
    double t_touch = tb + 1;
    for (int w = 0; w < tip_fns(); ++w) {
      auto fn = [&](double tc, const double* s) { return tip_fn(w, spring_at(tc, s), s); };
      double a = st.t, b = tb;
      const double ga = fn(a, st.ys.data()), gb = fn(b, yb.data());
      if (gb > 0) continue;  // not this event
      if (ga > 0)
        roots::illinois(a, b, ga, gb, 100, [&](double l, double h) { return h - l > 1e-14 * std::max(t_stop, h); },
                        [&](double tc) { return fn(tc, state_at(st, tc).data()); }, [](int) {});
      else
        b = st.t;  // due at the step's start
      if (b < t_touch) {
        t_touch = b;
        which = w;
      }
    }
    return t_touch;
  }
  // An event inside (t, tb]: the earliest of rest and contact change, by regula falsi on
  // sub-integrations from t; the slide is taken to it and the event applied.
  double slide_event(double t, double tb) {
    // With tip friction a state may change again within a few hundred ulps of t (a contact
    // grazed and re-made while the bar coasts): over such a span one Euler step is exact to
    // rounding, where an integrator's step would underflow.
    const StepStart st{t, y, 1e4 * std::numeric_limits<double>::epsilon() * std::max(t_stop, std::fabs(t))};
    const State yb = state_at(st, tb);
    const double t_rest = locate(st, tb, yb, [&](double, const double* s) { return along(s); }, true);
    double t_touch = tb + 1, t_joint = tb + 1;
    int which = kNone;  // with tip friction: the function of the tip's state that reached zero first
    if constexpr (!kFric) {
      t_touch = locate(st, tb, yb, [&](double tc, const double* s) { return spring_at(tc, s).sc.delta; }, touching);
    } else {
      t_touch = first_tip_change(st, tb, yb, which);
      // The contact passes a joint of a face and a corner's arc: the tip's sliding rate jumps
      // there (the curvature does), and a step across it loses its order. Restart there.
      if (tstate != kFree) {
        auto joint = [&](double tc, const double* s) { return spring_at(tc, s).joint; };
        t_joint = locate(st, tb, yb, joint, joint(st.t, st.ys.data()) > 0);
      }
    }
    const double t_ev = std::min({t_rest, t_touch, t_joint, tb});
    finish_slide(st, t_ev);
    if (t_ev == t_rest) come_to_rest(t_ev);
    if (t_ev == t_touch) {  // the located side: after the crossing
      if constexpr (!kFric) {
        touching = !touching;
        event(t_ev, touching ? "contact" : "release");
      } else {
        change_tip(t_ev, y.data(), which);
        touching = tstate != kFree;
      }
    }
    return t_ev;
  }
  // The slide from the step's start to the event at t_ev, with its rows.
  void finish_slide(const StepStart& st, double t_ev) {
    const std::vector<double> last = outputs_until(t_ev);
    if (kFric && t_ev - st.t <= st.tiny) {  // (with tip friction a change may be due at the step's start)
      if (t_ev > st.t) euler(st.t, y, t_ev);
      for (double tl : last)
        if (next < tout.size() && tout[next] == tl) observe(tl, y.data());
    } else {
      Dop853<double, N> fin = integrator();
      const auto fr = fin.integrate(rhs_fn(), st.t, y.data(), std::span<const double>(last), observer_fn());
      spend(fr, true);
    }
  }
};

template <int N>
DynamicRunResult run_impl(const BarGeometry& g, double muN, const DynamicBar& bar, const TipPath& tip, double x0,
                          double y0, double theta0, double t_end, int samples, double rtol, std::int64_t max_steps) {
  DynamicTipRun<N> run(g, muN, bar, tip, x0, y0, theta0, t_end, samples, rtol, max_steps);
  return run.run();
}

}  // namespace

DynamicRunResult run_dynamic(const BarGeometry& g, double muN, const DynamicBar& bar, const TipPath& tip, double x0,
                             double y0, double theta0, double t_end, int samples, double rtol,
                             std::int64_t max_steps) {
  tip.validate();
  if (!(std::isfinite(bar.stiffness) && bar.stiffness > 0))
    throw InputError("tip.stiffness", fmt(bar.stiffness), "must be > 0 and finite (N/m)");
  if (!(std::isfinite(bar.mass) && bar.mass > 0)) throw InputError("object.mass", fmt(bar.mass), "must be > 0 (kg)");
  if (!(std::isfinite(bar.inertia) && bar.inertia > 0))
    throw InputError("object.inertia", fmt(bar.inertia), "must be > 0 (kg m^2)");
  if (!(g.a > 0 && g.b > 0)) throw InputError("object.width, object.length", fmt(2 * g.a) + ", " + fmt(2 * g.b), "must be > 0");
  if (!(muN > 0 && std::isfinite(muN))) throw InputError("surface.mu x normal load", fmt(muN), "must be > 0 for a tip push (N)");
  if (samples < 2) throw InputError("solver.samples", std::to_string(samples), "must be >= 2");
  if (!(t_end > 0)) t_end = dynamic_t_end(bar, muN, tip);
  if (!std::isfinite(t_end)) throw InputError("solver.t_end", fmt(t_end), "must be finite (s)");
  if (!(rtol >= rtol_in_eps<double>(kDop853RtolEps) && rtol <= 1e-2))
    throw InputError("solver.rtol", fmt(rtol),
                     "must be in [" + fmt(rtol_in_eps<double>(kDop853RtolEps)) + ", 1e-2] for the dynamic tip push");

  if (max_steps < 1) throw InputError("solver.max_steps", std::to_string(max_steps), "must be >= 1");
  return tip.mu > 0 ? run_impl<kFricStateSize>(g, muN, bar, tip, x0, y0, theta0, t_end, samples, rtol, max_steps)
                    : run_impl<kRoughStateSize>(g, muN, bar, tip, x0, y0, theta0, t_end, samples, rtol, max_steps);
}

}  // namespace nanopush::tip
