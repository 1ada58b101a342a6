// The dynamic tip push's slide phase (tip_dynamic_run.hpp): Dormand-Prince 8(5,3) with a step
// hook that stops before a step holding an event (rest, contact or release, a change of the
// tip's state, a joint of a face and an arc), each located by regula falsi on sub-integrations
// from the step's start (one Euler step over the few hundred ulps where a step would underflow).
#include "tip_dynamic_run.hpp"

namespace nanopush::tip::dyn {

template <int N>
bool DynamicTipRun<N>::run_down(double t, const double* s) {
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

template <int N>
void DynamicTipRun<N>::come_to_rest(double t) {
  y[kVx] = y[kVy] = y[kOmega] = 0;
  moving = false;
  event(t, "rest");
}

template <int N>
double DynamicTipRun<N>::slide_phase(double t, double seg_end) {
  if constexpr (kFric) set_base_velocity(t);  // the base moves on the whole segment or not at all
  const std::vector<double> pending = outputs_until(seg_end);
  bool ran_down = false;
  // With tip friction, whether the contact is on a face at the step's start (the last accepted
  // step's end): a step that ends on the other side of a joint is stopped, and the joint located.
  bool on_face = false;
  if constexpr (kFric) on_face = tstate != kFree && spring_at(t, y.data()).joint > 0;
  auto hook = [&](double, const double*, double tn, const double* sn) {
    if (along(sn) <= 0) return kHookStopBefore;
    if constexpr (!kFric) {
      if ((spring_at(tn, sn).sc.delta > 0) != touching) return kHookStopBefore;
    } else {
      const Eval e = spring_at(tn, sn);
      for (int w = 0; w < tip_fns(); ++w)
        if (!(tip_fn(w, e, sn) > 0)) return kHookStopBefore;
      if (tstate != kFree && (e.joint > 0) != on_face) return kHookStopBefore;
      on_face = e.joint > 0;
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

template <int N>
auto DynamicTipRun<N>::state_at(const StepStart& st, double tc) -> State {
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

template <int N>
void DynamicTipRun<N>::euler(double t, State& yc, double tc) {
  double d[N];
  rhs(t, yc.data(), d);
  for (int i = 0; i < N; ++i) yc[static_cast<std::size_t>(i)] += (tc - t) * d[i];
}

template <int N>
template <class Fn>
double DynamicTipRun<N>::locate(const StepStart& st, double tb, const State& yb, Fn&& fn, bool was_positive) {
  double a = st.t, b = tb;
  const double ga = fn(a, st.ys.data()), gb = fn(b, yb.data());
  if ((gb > 0) == was_positive) return tb + 1;  // not this event
  if ((ga > 0) == (gb > 0)) return tb;          // at the step's start within rounding: at its end
  roots::illinois(a, b, ga, gb, 100, [&](double l, double h) { return h - l > 1e-14 * std::max(t_stop, h); },
                  [&](double tc) { return fn(tc, state_at(st, tc).data()); }, [](int) {});
  return b;
}

template <int N>
double DynamicTipRun<N>::first_tip_change(const StepStart& st, double tb, const State& yb, int& which) {
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

template <int N>
double DynamicTipRun<N>::slide_event(double t, double tb) {
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

template <int N>
void DynamicTipRun<N>::finish_slide(const StepStart& st, double t_ev) {
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
// run() (tip_dynamic_run.cpp) calls it for both state sizes.
template double DynamicTipRun<kRoughStateSize>::slide_phase(double, double);
template double DynamicTipRun<kFricStateSize>::slide_phase(double, double);

}  // namespace nanopush::tip::dyn
