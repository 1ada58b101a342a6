// The dynamic tip push's rest phase (tip_dynamic_run.hpp): the bar held while the spring's
// wrench lies inside the limit surface, the base moving on in steps bounded by how fast that
// wrench can reach it, the slide's start located by regula falsi on the power margin and its
// first instants taken in closed form; with tip friction, the tip's state changes located with
// the bar held and the work booked by Gauss-Kronrod quadrature.
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "tip_dynamic_run.hpp"

namespace nanopush::tip::dyn {

template <int N>
void DynamicTipRun<N>::book_rest(double t1) {
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

template <int N>
void DynamicTipRun<N>::start_rest_books(double t) {
  if constexpr (kFric) {
    w_bar_rest = y[kWorkPush] - spring_energy(spring_at(t, y.data())) + y[kWorkTipFric];
    t_booked = t;
  }
}

template <int N>
void DynamicTipRun<N>::rest_rows_until(double t_limit, bool inclusive) {
  while (next < tout.size() && (tout[next] < t_limit || (inclusive && tout[next] <= t_limit))) {
    book_rest(tout[next]);
    store_row(tout[next], y.data());
  }
}

template <int N>
RestAnalysis DynamicTipRun<N>::analyse(double t) {
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

template <int N>
auto DynamicTipRun<N>::wrench_rates(const Eval& e) const -> WrenchRates {
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

template <int N>
double DynamicTipRun<N>::start_slide(double t, const RestAnalysis& ra) {
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

template <int N>
double DynamicTipRun<N>::rest_phase(double t) {
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

template <int N>
double DynamicTipRun<N>::rest_tip_change(double tp, double tt) {
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

template <int N>
void DynamicTipRun<N>::rest_contact_change(double tp, double tt, const Eval& e) {
  if (e.sc.touching != touching && tt > tp) {
    double a = tp, b = tt;
    const double ga = spring_at(a, y.data()).sc.delta, gb = e.sc.delta;
    roots::illinois(a, b, ga, gb, 200, [&](double l, double h) { return h - l > 1e-15 * t_stop; },
                    [&](double tc) { return spring_at(tc, y.data()).sc.delta; }, [](int) {});
    event(e.sc.touching ? b : a, e.sc.touching ? "contact" : "release");
  }
}

template <int N>
double DynamicTipRun<N>::slide_from_rest(double tp, double tt, RestAnalysis ra) {
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

template <int N>
double DynamicTipRun<N>::end_rest() {
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
// run() (tip_dynamic_run.cpp) calls it for both state sizes.
template double DynamicTipRun<kRoughStateSize>::rest_phase(double);
template double DynamicTipRun<kFricStateSize>::rest_phase(double);

}  // namespace nanopush::tip::dyn
