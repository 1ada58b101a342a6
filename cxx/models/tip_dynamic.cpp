// The dynamic tip-driven push (tip_dynamic.hpp; docs/tip.md).
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
#include "nanopush/models/tip_dynamic.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>

#include "nanopush/models/friction.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/models/stick_slip.hpp"
#include "nanopush/numerics/dop853.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/numerics/regula_falsi.hpp"

namespace nanopush::tip {

namespace {

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

constexpr int kMaxEvents = 100000;

}  // namespace

SpringContact spring_contact(const BarGeometry& g, double radius, double stiffness, double bx, double by) {
  SpringContact s;
  const ContactGeometry c = contact_geometry(g, bx, by);
  double d = 0;  // signed distance from the base to the rectangle
  if (!c.inside) {
    s.px = c.px;
    s.py = c.py;
    s.nx = c.nx;
    s.ny = c.ny;
    d = c.distance;
  } else {  // the base inside the rectangle: the nearest face
    const double ex = g.a - std::fabs(bx), ey = g.b - std::fabs(by);
    if (ex <= ey) {
      s.nx = bx >= 0 ? 1.0 : -1.0;
      s.px = s.nx * g.a;
      s.py = by;
      d = -ex;
    } else {
      s.ny = by >= 0 ? 1.0 : -1.0;
      s.px = bx;
      s.py = s.ny * g.b;
      d = -ey;
    }
  }
  s.delta = radius - d;
  s.qx = bx;
  s.qy = by;
  if (!(s.delta > 0)) return s;
  s.touching = true;
  s.qx = s.px + radius * s.nx;
  s.qy = s.py + radius * s.ny;
  s.fx = -stiffness * s.delta * s.nx;
  s.fy = -stiffness * s.delta * s.ny;
  s.torque = s.px * s.fy - s.py * s.fx;
  return s;
}

double inertia_ratio(double mass, double speed, double muN, double travel) {
  return mass * speed * speed / (muN * travel);
}

double dynamic_t_end(const DynamicBar& bar, double muN, const TipPath& tip) {
  const double stop = bar.mass * tip.speed / muN, period = 2 * M_PI * std::sqrt(bar.mass / bar.stiffness);
  return tip.t_stop() + 10 * (stop + period);
}

DynamicRunResult run_dynamic(const BarGeometry& g, double muN, const DynamicBar& bar, const TipPath& tip, double x0,
                             double y0, double theta0, double t_end, int samples, double rtol) {
  tip.validate();
  if (!(std::isfinite(bar.stiffness) && bar.stiffness > 0))
    throw InputError("tip.stiffness", fmt(bar.stiffness), "must be > 0 and finite (N/m)");
  if (!(std::isfinite(bar.mass) && bar.mass > 0)) throw InputError("object.mass", fmt(bar.mass), "must be > 0 (kg)");
  if (!(std::isfinite(bar.inertia) && bar.inertia > 0))
    throw InputError("object.inertia", fmt(bar.inertia), "must be > 0 (kg m^2)");
  if (tip.mu != 0.0)
    throw InputError("tip.mu", fmt(tip.mu),
                     "the dynamic tip model has a frictionless tip: must be 0 (tip friction: tip.model = "
                     "\"quasi_static\")");
  if (!(g.a > 0 && g.b > 0)) throw InputError("object.width, object.length", fmt(2 * g.a) + ", " + fmt(2 * g.b), "must be > 0");
  if (!(muN > 0 && std::isfinite(muN))) throw InputError("surface.mu x normal load", fmt(muN), "must be > 0 for a tip push (N)");
  if (samples < 2) throw InputError("solver.samples", std::to_string(samples), "must be >= 2");
  if (!(t_end > 0)) t_end = dynamic_t_end(bar, muN, tip);
  if (!std::isfinite(t_end)) throw InputError("solver.t_end", fmt(t_end), "must be finite (s)");
  if (!(rtol >= dop853_rtol_min<double>() && rtol <= 1e-2))
    throw InputError("solver.rtol", fmt(rtol),
                     "must be in [" + fmt(dop853_rtol_min<double>()) + ", 1e-2] for the dynamic tip push");

  DynamicRunResult out;
  TipRunResult& res = out.run;
  std::vector<double> tout(static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i) tout[static_cast<std::size_t>(i)] = t_end * i / (samples - 1);
  tout.back() = t_end;
  res.rows.resize(tout.size());

  const double L = std::max(g.a, g.b), v = tip.speed, k = bar.stiffness, r = tip.radius;
  const double t_stop = tip.t_stop(), t_base_end = std::min(t_stop, t_end);
  RoughBarModel model;
  model.mass = bar.mass;
  model.inertia = bar.inertia;
  model.geometry = g;
  model.muN = muN;
  using State = std::array<double, kRoughStateSize>;
  State y{x0, y0, theta0, 0, 0, 0, 0, 0};

  struct Eval {
    SpringContact sc;
    double c = 1, s = 0;
  };
  auto spring_at = [&](double t, const double* s) {
    Eval e;
    e.c = std::cos(s[kTheta]);
    e.s = std::sin(s[kTheta]);
    const auto b = tip.centre(t);
    const double dx = b[0] - s[kX], dy = b[1] - s[kY];
    e.sc = spring_contact(g, r, k, e.c * dx + e.s * dy, -e.s * dx + e.c * dy);
    return e;
  };
  {
    const Eval e0 = spring_at(0.0, y.data());
    if (e0.sc.delta > 1e-9 * L)
      throw InputError("tip.start", "[" + fmt(tip.start_x) + ", " + fmt(tip.start_y) + "]",
                       "the tip (radius " + fmt(r) + " m) overlaps the bar at t = 0 by " + fmt(e0.sc.delta) +
                           " m: start it outside the bar");
  }

  std::array<double, 3> mode{1, 0, 0};  // sliding direction in (vx, vy, omega L), unit
  bool moving = false;
  bool touching = false;  // the tip touches the bar (changed at the located events only)
  auto rhs = [&](double t, const double* s, double* d) -> int {
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
    // The spring's power at the contact point (body axes), and the friction's.
    const double vbx = e.c * s[kVx] + e.s * s[kVy], vby = -e.s * s[kVx] + e.c * s[kVy];
    d[kWorkPush] = e.sc.fx * (vbx - s[kOmega] * e.sc.py) + e.sc.fy * (vby + s[kOmega] * e.sc.px);
    d[kWorkFric] = fr.fx * s[kVx] + fr.fy * s[kVy] + fr.mf * s[kOmega];
    return 0;
  };
  auto make_row = [&](double t, const double* s) {
    TipRow row;
    row.t = t;
    row.x = s[kX];
    row.y = s[kY];
    row.theta = s[kTheta];
    row.vx = s[kVx];
    row.vy = s[kVy];
    row.omega = s[kOmega];
    row.work_tip = s[kWorkPush];
    row.work_fric = s[kWorkFric];
    const Eval e = spring_at(t, s);
    row.tip_x = s[kX] + e.c * e.sc.qx - e.s * e.sc.qy;
    row.tip_y = s[kY] + e.s * e.sc.qx + e.c * e.sc.qy;
    const double Fx = e.c * e.sc.fx - e.s * e.sc.fy, Fy = e.s * e.sc.fx + e.c * e.sc.fy;
    if (e.sc.touching) {
      row.tip_fx = Fx;
      row.tip_fy = Fy;
      row.contact = ContactMode::slide;  // a frictionless tip slides on the bar
      out.max_delta = std::max(out.max_delta, e.sc.delta);
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
  };
  std::size_t next = 0;
  auto rest_rows_until = [&](double t_limit, bool inclusive) {
    while (next < tout.size() && (tout[next] < t_limit || (inclusive && tout[next] <= t_limit))) {
      res.rows[next] = make_row(tout[next], y.data());
      ++next;
    }
  };
  auto event = [&](double t, const char* what) {
    res.events.push_back({t, what});
    if (res.events.size() > static_cast<std::size_t>(kMaxEvents))
      throw SolverError("dynamic tip push: more than " + std::to_string(kMaxEvents) + " events by t = " + fmt(t) +
                        " s (contact or stick-slip chatter)");
  };

  // ---- at rest -------------------------------------------------------------------------
  // The largest friction moment (rotation about the centre of mass) and the largest lever:
  // the wrench is inside the limit surface while |F|/(mu N) + |tau|/M0 < 1 (the limit surface
  // is convex and holds the disc |f| <= mu N and the points (0, 0, +-M0)).
  const double M0 = std::fabs(rectangle_friction_from_velocity(g.a, g.b, muN, 0.0, 0.0, 1.0).mf);
  const double lever = std::hypot(g.a, g.b) + r;
  const double sm = std::sqrt(bar.mass), si = std::sqrt(bar.inertia);
  // Bounds on how fast the spring's wrench changes while the bar rests: |dF/dt| <= k v,
  // |dtau/dt| <= k v (lever + delta).
  auto analyse = [&](double t) {
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
  };
  // The slide starts at t (the rest analysis ra there): the first tau0 of it in closed form.
  // Where the spring's wrench has just crossed the limit surface, the acceleration grows from
  // zero and the velocity from zero as s^2; at such small speeds the friction across the
  // sliding direction relaxes at the rate mu N/(m |V|), which no explicit step can follow
  // (the steps over [t, t + tau] add up as 1/tau). Over tau0 = 1e-3 of the time the spring's
  // force takes to change by mu N, the acceleration is linear between its values at t and
  // t + tau0 (the bar held there), which gives V and the displacement to leading order; the
  // work done is booked as the kinetic energy gained plus the friction's share.
  auto start_slide = [&](double t, const RestAnalysis& ra) {
    const double tau0 = std::min(1e-3 * muN / (k * v), std::max(t_base_end - t, 0.0));
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
    for (int i = 0; i < 3; ++i) {
      y[kX + i] += D[i];
      y[kVx + i] = V[i];
    }
    y[kWorkFric] += wf;
    y[kWorkPush] += ke - wf;
    return t + tau0;
  };
  // From time t with the bar at rest: the time the slide starts (located), or t_end.
  auto rest_phase = [&](double t) {
    double tp = t;  // the last time the bar was known stuck
    double tt = t;
    for (long it = 0;; ++it) {
      if (it > 10000000) throw SolverError("dynamic tip push: the rest phase from t = " + fmt(t) + " s does not end");
      const Eval e = spring_at(tt, y.data());
      if (e.sc.touching != touching && tt > tp) {  // the contact changed between tp and tt: locate it
        double a = tp, b = tt;
        const double ga = spring_at(a, y.data()).sc.delta, gb = e.sc.delta;
        roots::illinois(a, b, ga, gb, 200, [&](double l, double h) { return h - l > 1e-15 * t_stop; },
                        [&](double tc) { return spring_at(tc, y.data()).sc.delta; }, [](int) {});
        event(e.sc.touching ? b : a, e.sc.touching ? "contact" : "release");
      }
      touching = e.sc.touching;
      double jump = 0;
      if (e.sc.touching) {
        const double F = k * e.sc.delta, dF = k * v, dtau = k * v * (lever + e.sc.delta);
        const double cheap = F / muN + std::fabs(e.sc.torque) / M0;
        if (cheap < 1) {
          jump = (1 - cheap) / (dF / muN + dtau / M0);
        } else {
          RestAnalysis ra = analyse(tt);
          if (!ra.stuck) {
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
            event(tt, "slide");
            const double t1 = start_slide(tt, ra);
            rest_rows_until(t1, false);  // outputs inside the closed-form start (rare): at its end state
            return t1;
          }
          jump = -ra.margin / (dF / sm + dtau / si);
        }
      } else {
        jump = -e.sc.delta / v;  // the gap closes at most at the base's speed
      }
      if (tt >= t_base_end) break;  // the base no longer moves: at rest for good
      tp = tt;
      tt = std::min(tt + std::max(jump, muN / (16 * k * v)), t_base_end);
    }
    rest_rows_until(t_end, true);
    return t_end;
  };

  // ---- sliding -------------------------------------------------------------------------
  Dop853Options<double> opt;
  opt.rtol = rtol;
  opt.atol = {rtol * L, rtol * L, rtol, rtol * v, rtol * v, rtol * v / L, rtol * muN * L, rtol * muN * L};
  opt.maxstp = 10000000;
  auto along = [&](const double* s) { return s[kVx] * mode[0] + s[kVy] * mode[1] + s[kOmega] * L * mode[2]; };
  // The slide has run down to the requested accuracy: every velocity component within its
  // absolute tolerance while the kinetic energy falls (near rest the friction across the
  // sliding direction relaxes at the rate mu N/(m |V|), and the problem turns stiff).
  auto run_down = [&](double t, const double* s) {
    double d[kRoughStateSize];
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
  };
  // From time t, sliding: integrate to the next event (or seg_end); returns the time reached.
  auto slide_phase = [&](double t, double seg_end) {
    std::vector<double> pending;
    for (std::size_t i = next; i < tout.size() && tout[i] <= seg_end; ++i) pending.push_back(tout[i]);
    if (pending.empty() || pending.back() < seg_end) pending.push_back(seg_end);
    auto observer = [&](std::size_t, double tt, const double* s) {
      if (next < tout.size() && tout[next] == tt) res.rows[next++] = make_row(tt, s);
    };
    bool ran_down = false;
    auto hook = [&](double, const double*, double tn, const double* sn) {
      if (along(sn) <= 0) return kHookStopBefore;
      if ((spring_at(tn, sn).sc.delta > 0) != touching) return kHookStopBefore;
      if (run_down(tn, sn)) {
        ran_down = true;
        return kHookStopAfter;
      }
      return kHookContinue;
    };
    Dop853<double, kRoughStateSize> integ(opt);
    const auto rr = integ.integrate(rhs, t, y.data(), std::span<const double>(pending), observer, hook);
    res.steps += rr.naccpt;
    if (!rr.ok()) throw SolverError("dynamic tip push: " + rr.message);
    t = rr.t_reached;
    if (!rr.stopped_by_hook) return t;
    if (ran_down) {
      y[kVx] = y[kVy] = y[kOmega] = 0;
      moving = false;
      event(t, "rest");
      return t;
    }
    // An event inside (t, t_event_end]: the earliest of rest and contact change, by regula
    // falsi on sub-integrations from t.
    const State ys = y;
    auto state_at = [&](double tc) {
      State yc = ys;
      if (tc > t) {
        Dop853<double, kRoughStateSize> sub(opt);
        const double one[1] = {tc};
        const auto sr = sub.integrate(rhs, t, yc.data(), std::span<const double>(one, 1),
                                      [](std::size_t, double, const double*) {});
        res.steps += sr.naccpt;
      }
      return yc;
    };
    const double tb = rr.t_event_end;
    const State yb = state_at(tb);
    auto locate = [&](auto&& fn, bool was_positive) {
      double a = t, b = tb;
      const double ga = fn(a, ys.data()), gb = fn(b, yb.data());
      if ((gb > 0) == was_positive) return tb + 1;  // not this event
      if ((ga > 0) == (gb > 0)) return tb;          // at the step's start within rounding: at its end
      roots::illinois(a, b, ga, gb, 100, [&](double l, double h) { return h - l > 1e-14 * std::max(t_stop, h); },
                      [&](double tc) { return fn(tc, state_at(tc).data()); }, [](int) {});
      return b;
    };
    const double t_rest = locate([&](double, const double* s) { return along(s); }, true);
    const double t_touch = locate([&](double tc, const double* s) { return spring_at(tc, s).sc.delta; }, touching);
    const double t_ev = std::min({t_rest, t_touch, tb});
    std::vector<double> last;
    for (std::size_t i = next; i < tout.size() && tout[i] <= t_ev; ++i) last.push_back(tout[i]);
    if (last.empty() || last.back() < t_ev) last.push_back(t_ev);
    Dop853<double, kRoughStateSize> fin(opt);
    const auto fr = fin.integrate(rhs, t, y.data(), std::span<const double>(last), observer);
    res.steps += fr.naccpt;
    if (!fr.ok()) throw SolverError("dynamic tip push: " + fr.message);
    if (t_ev == t_rest) {
      y[kVx] = y[kVy] = y[kOmega] = 0;
      moving = false;
      event(t_ev, "rest");
    }
    if (t_ev == t_touch) {  // the located side: after the crossing
      touching = !touching;
      event(t_ev, touching ? "contact" : "release");
    }
    return t_ev;
  };

  double t = 0;
  bool stopped = false;  // the "tip stops" event recorded
  while (t < t_end) {
    if (!stopped && t >= t_stop) {
      event(t_stop, "tip stops");
      stopped = true;
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
  while (next < tout.size()) {  // the outputs at t_end (the integration reached it)
    res.rows[next] = make_row(tout[next], y.data());
    ++next;
  }
  return out;
}

}  // namespace nanopush::tip
