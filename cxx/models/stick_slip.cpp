#include "nanopush/models/stick_slip.hpp"

#include <algorithm>
#include <cmath>

#include "nanopush/numerics/error.hpp"
#include "nanopush/numerics/regula_falsi.hpp"

namespace nanopush {
namespace {

double length_scale(const RoughBarModel& m) { return std::max(m.geometry.a, m.geometry.b); }

/// h(ξ) = w·ξ − D̃(ξ) in the mass-scaled velocity space u = M^{1/2} V, for unit ξ, and its
/// gradient w + F̃(ξ) (F̃ = M^{-1/2} × friction wrench of the direction M^{-1/2} ξ).
struct PowerMargin {
  const RoughBarModel& m;
  double theta;
  std::array<double, 3> w;  // M^{-1/2} W_applied
  double sm, si;            // sqrt(m), sqrt(I)
  mutable std::int64_t calls = 0;
  double eval(const std::array<double, 3>& xi, std::array<double, 3>* grad) const {
    ++calls;
    const WorldWrench f = m.friction(theta, xi[0] / sm, xi[1] / sm, xi[2] / si);
    const std::array<double, 3> ft = {f.fx / sm, f.fy / sm, f.mf / si};
    if (grad) *grad = {w[0] + ft[0], w[1] + ft[1], w[2] + ft[2]};
    return (w[0] + ft[0]) * xi[0] + (w[1] + ft[1]) * xi[1] + (w[2] + ft[2]) * xi[2];
  }
};

double norm3(const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

std::array<double, 3> normalised(std::array<double, 3> v) {
  const double n = norm3(v);
  return {v[0] / n, v[1] / n, v[2] / n};
}

/// The gradient of h at the unit vector xi split into its normal part gr (returned through
/// the reference) and its tangent part (returned); h(xi) through *h when asked.
std::array<double, 3> tangent_gradient(const PowerMargin& pm, const std::array<double, 3>& xi, double& gr,
                                       double* h = nullptr) {
  std::array<double, 3> g;
  const double hv = pm.eval(xi, &g);
  if (h) *h = hv;
  gr = g[0] * xi[0] + g[1] * xi[1] + g[2] * xi[2];
  return {g[0] - gr * xi[0], g[1] - gr * xi[1], g[2] - gr * xi[2]};
}

}  // namespace

RestAnalysis analyse_rest(const RoughBarModel& model, double theta) {
  RestAnalysis r;
  const WorldWrench ap = model.applied(theta);
  const double sm = std::sqrt(model.mass), si = std::sqrt(model.inertia);
  PowerMargin pm{model, theta, {ap.fx / sm, ap.fy / sm, ap.mf / si}, sm, si};
  const double wn = norm3(pm.w);
  if (wn == 0.0) return r;  // nothing pushes: stuck
  if (model.muN == 0.0) {   // frictionless: A = M^{-1} W
    r.stuck = false;
    r.margin = wn;
    r.accel = {ap.fx / model.mass, ap.fy / model.mass, ap.mf / model.inertia};
    return r;
  }
  // 1. Global search over a Fibonacci sphere (the positive superlevel sets of h on the
  //    sphere are geodesically convex, so a local maximum with h > 0 is global).
  std::array<double, 3> best = normalised(pm.w);
  double hbest = pm.eval(best, nullptr);
  const int n = 600;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double rr = std::sqrt(1.0 - z * z);
    const std::array<double, 3> xi = {rr * std::cos(golden * i), rr * std::sin(golden * i), z};
    const double h = pm.eval(xi, nullptr);
    if (h > hbest) {
      hbest = h;
      best = xi;
    }
  }
  // 2. Projected gradient ascent on the sphere with backtracking.
  double step = 0.5;
  for (int it = 0; it < 500 && step > 1e-14; ++it) {
    double h = 0, gr = 0;
    const std::array<double, 3> tg = tangent_gradient(pm, best, gr, &h);
    const double tn = norm3(tg);
    if (tn <= 1e-13 * wn) break;
    bool improved = false;
    while (step > 1e-14) {
      const auto cand = normalised({best[0] + step * tg[0] / tn, best[1] + step * tg[1] / tn, best[2] + step * tg[2] / tn});
      const double hc = pm.eval(cand, nullptr);
      if (hc > h) {
        best = cand;
        hbest = hc;
        improved = true;
        step = std::min(1.0, step * 2.0);
        break;
      }
      step *= 0.5;
    }
    if (!improved) break;
  }
  // 3. Polish. The line search compares values of h, so it stops where h is flat to
  //    rounding, with the direction right only to ~sqrt(eps): on fig3_31 the tangent gradient
  //    was left at 4e-8 of the normal one. A slide started in that direction carries the error
  //    into its first steps, and the event-locating BS at rtol 1e-10 landed up to 4e-8 rad off
  //    the converged solution, depending on the rounding of the push. Barzilai-Borwein steps
  //    on the tangent gradient itself (not on h) take it to rounding (~5e-16).
  {
    double gr = 0;
    std::array<double, 3> x = best, t = tangent_gradient(pm, best, gr);
    double tn = norm3(t);
    double alpha = 1e-3 / std::max(tn, 1e-300);
    for (int it = 0; it < 60 && tn > 1e-15 * std::fabs(gr); ++it) {
      const auto xn = normalised({x[0] + alpha * t[0], x[1] + alpha * t[1], x[2] + alpha * t[2]});
      double grn = 0;
      const auto tnv = tangent_gradient(pm, xn, grn);
      const std::array<double, 3> sv = {xn[0] - x[0], xn[1] - x[1], xn[2] - x[2]};
      const std::array<double, 3> yv = {tnv[0] - t[0], tnv[1] - t[1], tnv[2] - t[2]};
      const double sy = sv[0] * yv[0] + sv[1] * yv[1] + sv[2] * yv[2];
      const double ss = sv[0] * sv[0] + sv[1] * sv[1] + sv[2] * sv[2];
      x = xn;
      t = tnv;
      if (norm3(tnv) < tn) {  // keep the best point seen
        tn = norm3(tnv);
        best = xn;
      }
      if (!(sy < 0.0) || ss == 0.0) break;  // h is concave near its maximum: sy < 0
      alpha = ss / -sy;
    }
    hbest = pm.eval(best, nullptr);
  }
  r.margin = hbest;
  r.evaluations = pm.calls;
  // On the limit surface within rounding counts as inside (friction can hold it).
  if (hbest <= 1e-12 * wn) {
    r.stuck = true;
    return r;
  }
  r.stuck = false;
  // Optimal scaled acceleration u* = h(ξ*) ξ*; A = M^{-1/2} u*.
  r.accel = {hbest * best[0] / sm, hbest * best[1] / sm, hbest * best[2] / si};
  return r;
}

namespace {

template <typename S>
WorldWrenchT<S> coulomb_friction_cs(const RoughBarModel& model, S c, S s, const S* y, const std::array<S, 3>& mode) {
  const S L = length_scale(model);
  const S vx = y[kVx], vy = y[kVy], om = y[kOmega];
  if (vx == 0.0 && vy == 0.0 && om == 0.0) return model.friction_in(c, s, mode[0], mode[1], S(mode[2] / L));
  const S g = vx * mode[0] + vy * mode[1] + om * L * mode[2];
  if (g >= 0.0) return model.friction_in(c, s, vx, vy, om);
  return model.friction_in(c, s, S(-vx), S(-vy), S(-om));
}

template <typename S>
WorldWrenchT<S> coulomb_friction_t(const RoughBarModel& model, const S* y, const std::array<S, 3>& mode) {
  return coulomb_friction_cs(model, num::cos(y[kTheta]), num::sin(y[kTheta]), y, mode);
}

template <typename S>
void coulomb_rhs_t(const RoughBarModel& model, const S* y, const std::array<S, 3>& mode, S* d) {
  const S c = num::cos(y[kTheta]), s = num::sin(y[kTheta]);
  RoughBarModel::rhs_with(model, y, model.applied_in(c, s), coulomb_friction_cs(model, c, s, y, mode), d);
}

template <typename S>
std::array<S, 3> mode_of(const RoughBarModel& m, S vx, S vy, S om) {
  const S L = length_scale(m);
  const S v[3] = {vx, vy, S(om * L)};
  const S n = num::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

template <typename S>
S speed_scaled(const RoughBarModel& m, const S* y) {
  const S L = length_scale(m);
  return num::sqrt(y[kVx] * y[kVx] + y[kVy] * y[kVy] + y[kOmega] * L * y[kOmega] * L);
}

template <typename S>
WorldWrench to_double(const WorldWrenchT<S>& w) {
  return {static_cast<double>(w.fx), static_cast<double>(w.fy), static_cast<double>(w.mf)};
}

}  // namespace

WorldWrench coulomb_friction(const RoughBarModel& model, const double* y, const std::array<double, 3>& mode) {
  return coulomb_friction_t(model, y, mode);
}

void coulomb_rhs(const RoughBarModel& model, const double* y, const std::array<double, 3>& mode, double* d) {
  coulomb_rhs_t(model, y, mode, d);
}

namespace {

// The coulomb law's stick-slip loop in any scalar S: double (integrate_coulomb), long double
// and quad (integrate_coulomb_extended). Times, the rest analysis and the slide-off direction
// stay in double (docs/accuracy.md, "References with more digits"). One object per run holds
// the state every step reads and writes (the mode, the last state and time, the outputs
// emitted, the events); its steps: start (the rest analysis of a body given at rest), slide
// (one integration up to an event or the last output), locate_rest (the event's instant by
// regula falsi), rest_event (stick, or the direction it slides on by Gauss' principle) and
// hold (the outputs of a body that stays stuck).
template <typename S, class Observer>
class StickSlipLoop {
 public:
  StickSlipLoop(const RoughBarModel& model, const BsOptions<S>& options, const S* y0, const std::vector<double>& tout,
                const Observer& observer)
      : model_(model), tout_(tout), observer_(observer), L_(length_scale(model)), bs_(options),
        sub_options_(options) {
    std::copy(y0, y0 + kRoughStateSize, y_.begin());
    // The event location's sub-integrations need the state at their end time only, so they
    // run without dense output: there is nothing to interpolate, and near the velocity's zero
    // (where the friction turns with V/|V| on the time scale |V|/|A|) the interpolant's error
    // control of the modern method held them at steps of 1e-6 of their span until the step
    // budget ran out (stick_mu015, rtol 1e-12). Steps clipped at the end time as in faithful.
    sub_options_.dense = false;
    // Velocity tolerances: the absolute tolerances of vx, vy, omega (or rtol times the peak).
    for (int i = 0; i < 3; ++i) {
      const std::size_t k = static_cast<std::size_t>(kVx + i);
      vtol_[static_cast<std::size_t>(i)] = options.atol.size() == 1 ? options.atol[0] : options.atol[k];
    }
    // Position and angle tolerances.
    for (int i = 0; i < 3; ++i) {
      const std::size_t k = static_cast<std::size_t>(kX + i);
      ptol_[static_cast<std::size_t>(i)] = options.atol.size() == 1 ? options.atol[0] : options.atol[k];
    }
  }
  StickSlipLoop(const StickSlipLoop&) = delete;
  StickSlipLoop& operator=(const StickSlipLoop&) = delete;

  StickSlipResult run() {
    start();
    while (iout_ < tout_.size()) {
      if (stuck_) {
        hold();
        break;
      }
      emit_due_outputs();
      if (iout_ >= tout_.size()) break;
      const SlideEnd e = slide();
      if (e.all_done) break;  // all outputs done
      if (e.snapped) {
        // Rest within the tolerance at t: the state emitted at outputs up to t stands. The
        // kinetic energy left is dissipated by friction in the remaining motion: book it there
        // (the push's work over that motion is below F times the position tolerance).
        y_[kWorkFric] -= model_.kinetic_energy(y_.data());
        rest_event();
        continue;
      }
      locate_rest(e.t_event_end);
    }
    out_.stuck_at_end = stuck_;
    return std::move(out_);
  }

 private:
  using State = std::array<S, kRoughStateSize>;
  static constexpr int kMaxEvents = 10000;
  /// How one slide's integration ended: every output done, at rest within the tolerances
  /// (snapped), or with the velocity's zero inside the step ending at t_event_end.
  struct SlideEnd {
    bool all_done = false;
    bool snapped = false;
    double t_event_end = 0.0;
  };

  // The body given at rest at t = 0: stick, or the direction it starts sliding in; else the
  // mode follows its velocity.
  void start() {
    if (y_[kVx] == 0.0 && y_[kVy] == 0.0 && y_[kOmega] == 0.0) {
      const bool s = at_rest();
      out_.events.push_back({t_, s});
    } else {
      mode_ = mode_of(model_, y_[kVx], y_[kVy], y_[kOmega]);
    }
    // Speed below which a sign change of g is taken as "came to rest" (not a rotation of V by
    // more than 90 degrees within one step, which the error control makes implausible anyway).
    peak_speed_ = speed_scaled(model_, y_.data());
  }

  WorldWrench static_friction(double theta) const {
    const WorldWrench ap = model_.applied(static_cast<double>(theta));
    return WorldWrench{-ap.fx, -ap.fy, -ap.mf};
  }

  // Enter a rest state at time t: stick, or choose the sliding direction.
  bool at_rest() {
    y_[kVx] = y_[kVy] = y_[kOmega] = 0.0;
    const RestAnalysis ra = analyse_rest(model_, static_cast<double>(y_[kTheta]));
    out_.stats.nfcn += ra.evaluations;
    if (ra.stuck) {
      stuck_ = true;
    } else {
      mode_ = mode_of(model_, S(ra.accel[0]), S(ra.accel[1]), S(ra.accel[2]));
    }
    return ra.stuck;
  }

  // The right-hand side in the current mode, as the integrators call it.
  auto rhs() {
    return [this](S, const S* yy, S* d) {
      coulomb_rhs_t(model_, yy, mode_, d);
      return 0;
    };
  }

  void accumulate(const BsResult& r) {
    out_.stats.nfcn += r.nfcn;
    out_.stats.naccpt += r.naccpt;
    out_.stats.nrejct += r.nrejct;
  }

  // Terminal phase of a slide. Near rest the components of V across its direction relax at
  // the rate mu N/(m |V|), which grows without bound: the problem turns stiff and an explicit
  // integrator's steps shrink with |V|. The slide is over, to the requested accuracy, once
  // the motion still to come is below the tolerances: every velocity component within its
  // absolute tolerance, or (decelerating) the distance and angle still to travel,
  // v^2/(2|a|) and omega^2/(2|alpha|), within the position and angle tolerances.
  bool terminal(const S* yy) {
    S d[kRoughStateSize];
    coulomb_rhs_t(model_, yy, mode_, d);
    ++out_.stats.nfcn;  // an RHS evaluation like any other: counted
    // Only a slide that is running down can end: the kinetic energy must be falling. (A
    // slide that has just started from rest has |V| below the tolerances too, but it speeds up.)
    const S dke = S(model_.mass) * (yy[kVx] * d[kVx] + yy[kVy] * d[kVy]) + S(model_.inertia) * yy[kOmega] * d[kOmega];
    if (!(dke < 0.0)) return false;
    if (num::abs(yy[kVx]) <= vtol_[0] && num::abs(yy[kVy]) <= vtol_[1] && num::abs(yy[kOmega]) <= vtol_[2]) return true;
    const S v2 = yy[kVx] * yy[kVx] + yy[kVy] * yy[kVy];
    const S vdotA = yy[kVx] * d[kVx] + yy[kVy] * d[kVy];
    const S acc = num::hypot(d[kVx], d[kVy]);
    const bool lin_done = v2 == 0.0 || (vdotA < 0.0 && v2 <= 2.0 * acc * std::min(ptol_[0], ptol_[1]));
    const bool rot_done = yy[kOmega] == 0.0 || (yy[kOmega] * d[kOmega] < 0.0 &&
                                               yy[kOmega] * yy[kOmega] <= 2.0 * num::abs(d[kOmega]) * ptol_[2]);
    return lin_done && rot_done;
  }

  // A slide that starts from rest speeds up (the power margin is positive). If it is found
  // at rest again before a single step of it could be committed, the start direction is
  // not resolvable at this tolerance: the push lies within rounding of the limit surface
  // (e.g. just above the minimum force), where the direction of a slide from rest is
  // ill-conditioned. Say so at once instead of cycling through rest events.
  void check_progress() const {
    if (steps_in_slide_ == 0)
      throw CoulombError(BsStatus::step_underflow, "coulomb law: the slide that started from rest at t = " + fmt(t_) +
                        " s stopped again within its first step; the push is too close to the limit surface for "
                        "the start direction to be resolved (near the minimum force; the CVODE path copes)");
  }

  // A rest reached at time t (the state's velocity still to be zeroed): stick, or choose the
  // direction in which it slides on; recorded as an event.
  void rest_event() {
    if (++n_events_ > kMaxEvents)
      throw CoulombError(BsStatus::too_many_steps, "coulomb law: more than " + std::to_string(kMaxEvents) + " rest events");
    check_progress();
    const bool s = at_rest();
    steps_in_slide_ = 0;
    out_.events.push_back({t_, s});
  }

  // Stuck for good: every output still to come holds the state, with static friction.
  void hold() {
    const WorldWrench sf = static_friction(static_cast<double>(y_[kTheta]));
    for (; iout_ < tout_.size(); ++iout_) observer_(tout_[iout_], y_.data(), sf);
  }

  // Outputs at the current time.
  void emit_due_outputs() {
    while (iout_ < tout_.size() && tout_[iout_] <= t_) {
      observer_(tout_[iout_], y_.data(), to_double(coulomb_friction_t(model_, y_.data(), mode_)));
      ++iout_;
    }
  }

  // One slide: integrate from t through the outputs still to come until an event stops it.
  // After each accepted step: (1) g = V·mode < 0 means the velocity passed through zero
  // inside the step: stop before it and locate the instant; (2) a velocity below the
  // absolute tolerances of vx, vy and omega is rest at the requested accuracy: stop after
  // it (near rest the velocity direction can keep turning on a time scale |V|/|A|, and
  // without this the steps would shrink geometrically without ever reaching the zero);
  // (3) otherwise the mode follows the velocity.
  SlideEnd slide() {
    // The output times still to come, in S (a view of tout in double, a copy otherwise).
    std::vector<S> rest_s;
    std::span<const S> rest;
    if constexpr (std::is_same_v<S, double>) {
      rest = std::span<const double>(tout_.data() + iout_, tout_.size() - iout_);
    } else {
      rest_s.assign(tout_.begin() + static_cast<std::ptrdiff_t>(iout_), tout_.end());
      rest = rest_s;
    }
    std::size_t emitted = 0;
    bool snapped = false;
    const auto hook_and_track = [&](S, const S*, S, const S* yn) {
      const S g = yn[kVx] * mode_[0] + yn[kVy] * mode_[1] + yn[kOmega] * L_ * mode_[2];
      if (g < 0.0) return static_cast<int>(kHookStopBefore);
      ++steps_in_slide_;
      if (terminal(yn)) {
        snapped = true;
        return static_cast<int>(kHookStopAfter);
      }
      const S sp = num::sqrt(yn[kVx] * yn[kVx] + yn[kVy] * yn[kVy] + yn[kOmega] * L_ * yn[kOmega] * L_);
      peak_speed_ = std::max(peak_speed_, sp);
      if (sp > 0.0) mode_ = {yn[kVx] / sp, yn[kVy] / sp, yn[kOmega] * L_ / sp};
      return static_cast<int>(kHookContinue);
    };
    BsResult r = bs_.integrate(
        rhs(), S(t_), y_.data(), rest,
        [&](std::size_t, S tt, const S* yy) {
          observer_(static_cast<double>(tt), yy, to_double(coulomb_friction_t(model_, yy, mode_)));
          ++emitted;
        },
        hook_and_track);
    accumulate(r);
    if (!r.ok()) {
      out_.stats.status = r.status;
      out_.stats.message = r.message;
      throw CoulombError(r.status, "coulomb law: " + r.message);
    }
    iout_ += emitted;
    t_ = r.t_reached;
    return {!r.stopped_by_hook, snapped, r.t_event_end};
  }

  // An event lies in (t, t1]: the velocity passed through zero. Locate g(t*) = 0 by the
  // Illinois variant of regula falsi, integrating from the step start each time. A
  // sub-integration that meets the terminal test (the motion still to come within the
  // tolerances, as in the main integration) ends the search there: close to the zero the
  // components of V across the mode relax at the rate mu N/(m |V|), and resolving them to
  // a tight rtol took 20000 steps of 1e-20 s (fig3_31, coulomb law at rtol 1e-14, push
  // rounded 4 ulps up) before the search could reach the zero itself.
  void locate_rest(double t1) {
    const double t0 = t_;
    const State ystart = y_;
    bool rest_found = false;  // a sub-integration met the terminal test at t_rest
    double t_rest = t0;
    State y_rest{};
    auto g_at = [&](double tt, State& yt) {
      yt = ystart;
      if (tt > t0) {
        BulirschStoer<S, kRoughStateSize> sub(sub_options_);
        const S end[1] = {S(tt)};
        BsResult rr = sub.integrate(
            rhs(), S(t0), yt.data(), std::span<const S>(end, 1), [](std::size_t, S, const S*) {},
            [&](S, const S*, S, const S* yn) {
              return static_cast<int>(terminal(yn) ? kHookStopAfter : kHookContinue);
            });
        accumulate(rr);
        out_.root_fcn += rr.nfcn;
        if (!rr.ok()) throw CoulombError(rr.status, "coulomb law, event location: " + rr.message);
        if (rr.stopped_by_hook && (!rest_found || rr.t_reached < t_rest)) {
          rest_found = true;
          t_rest = rr.t_reached;
          y_rest = yt;
        }
      }
      return yt[kVx] * mode_[0] + yt[kVy] * mode_[1] + yt[kOmega] * L_ * mode_[2];
    };
    State ya{}, yb{}, yc{};
    double a = t0, b = t1;
    const S ga = g_at(a, ya), gb = g_at(b, yb);
    roots::illinois(
        a, b, ga, gb, 100,
        [&](double lo, double hi) { return !rest_found && (hi - lo) > 4 * 2.2e-16 * std::max(std::fabs(hi), 1e-300); },
        [&](double c) { return g_at(c, yc); },
        [&](int side) {
          if (side <= 0) ya = yc;
          if (side >= 0) yb = yc;
        });
    if (rest_found) {
      // Rest within the tolerances at t_rest, as when the main integration snaps (run).
      t_ = t_rest;
      y_ = y_rest;
      y_[kWorkFric] -= model_.kinetic_energy(y_.data());
      rest_event();
      return;
    }
    // The rest instant: the end of the bracket on the g >= 0 side, velocity set to zero.
    t_ = a;
    y_ = ya;
    const S sp = speed_scaled(model_, y_.data());
    if (sp > 1e-6 * std::max(peak_speed_, S(1e-300))) {
      // Not a rest: the velocity turned by more than 90 degrees within a step. Follow it.
      mode_ = mode_of(model_, y_[kVx], y_[kVy], y_[kOmega]);
      return;
    }
    rest_event();
  }

  const RoughBarModel& model_;
  const std::vector<double>& tout_;
  const Observer& observer_;
  const S L_;
  StickSlipResult out_;
  State y_{};
  double t_ = 0.0;
  std::size_t iout_ = 0;
  std::array<S, 3> mode_{1, 0, 0};
  bool stuck_ = false;
  BulirschStoer<S, kRoughStateSize> bs_;
  BsOptions<S> sub_options_;
  std::array<S, 3> vtol_{};  // velocity tolerances
  std::array<S, 3> ptol_{};  // position and angle tolerances
  long steps_in_slide_ = 1;  // accepted steps since the last rest (check_progress)
  int n_events_ = 0;
  S peak_speed_{};
};

template <typename S, class Observer>
StickSlipResult integrate_coulomb_t(const RoughBarModel& model, const BsOptions<S>& options, const S* y0,
                                    const std::vector<double>& tout, const Observer& observer) {
  StickSlipLoop<S, Observer> loop(model, options, y0, tout, observer);
  return loop.run();
}

}  // namespace

StickSlipResult integrate_coulomb(const RoughBarModel& model, const BsOptions<double>& options, const double* y0,
                                  const std::vector<double>& tout, const StickSlipObserver& observer) {
  return integrate_coulomb_t<double>(model, options, y0, tout, observer);
}

template <typename S>
StickSlipResult integrate_coulomb_extended(const RoughBarModel& model, const BsOptions<S>& options, const S* y0,
                                           const std::vector<double>& tout, const StickSlipObserverT<S>& observer) {
  return integrate_coulomb_t<S>(model, options, y0, tout, observer);
}

template StickSlipResult integrate_coulomb_extended<long double>(const RoughBarModel&, const BsOptions<long double>&,
                                                                 const long double*, const std::vector<double>&,
                                                                 const StickSlipObserverT<long double>&);
template StickSlipResult integrate_coulomb_extended<num::quad>(const RoughBarModel&, const BsOptions<num::quad>&,
                                                               const num::quad*, const std::vector<double>&,
                                                               const StickSlipObserverT<num::quad>&);

}  // namespace nanopush
