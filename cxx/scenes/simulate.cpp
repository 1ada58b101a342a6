#include "nanopush/scenes/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <functional>
#include <type_traits>

#include "nanopush/numerics/dop853.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/models/rigid_body.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/models/stick_slip.hpp"
#include "kinks.hpp"
#include "nanopush/scenes/rest_watch.hpp"

namespace nanopush {

namespace {
std::string fmt_short(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}
}  // namespace

ResolvedSettings resolve_settings(const Scene& scene, const RunSettings& in) {
  ResolvedSettings s;
  s.allow_partial = in.allow_partial;
  s.progress = in.progress;
  s.engine = in.engine.value_or(scene.solver.engine);
  // The F77 engine has one method, its own Bulirsch-Stoer: asking it for another is a
  // conflict, not a setting to ignore. (A scene's solver.method configures the C++ engine and
  // does not bind a run that chose the F77 engine.)
  if (s.engine == Engine::f77 && in.method && *in.method != Method::faithful)
    throw InputError("method", to_string(*in.method),
                     "the f77 engine has one method (its Bulirsch-Stoer, which faithful reproduces in C++): drop the "
                     "method or use engine cxx");
  if (scene.push_mode == PushMode::tip) {  // the quasi-static tip push (docs/tip.md)
    if (s.engine == Engine::f77)
      throw InputError("engine", "f77", "the tip push (push.mode = tip) runs in the C++ engine only: use engine cxx");
    if (in.method && *in.method != Method::automatic)
      throw InputError("method", to_string(*in.method),
                       "the quasi-static tip push has its own integrator (Dormand-Prince 8(5,3)): leave the method out");
    if (in.precision && *in.precision != Precision::double_)
      throw InputError("precision", to_string(*in.precision), "the tip push runs in double");
    if (in.law && *in.law == Law::printed)
      throw InputError("law", "printed", "the tip push uses the Coulomb wrench: use thesis or coulomb");
  }
  // The field named in a message is the one the value came from (the settings or the scene).
  const std::string mfield = in.method ? "method" : "solver.method";
  s.method = s.engine == Engine::f77 ? Method::faithful : in.method.value_or(scene.solver.method);
  s.law = in.law.value_or(scene.surface.law);
  s.rtol = in.rtol == 0 ? scene.solver.rtol : in.rtol;
  require_range("rtol", s.rtol, 1e-30, 0.1);
  const std::string pfield = in.precision ? "precision" : "solver.precision";
  s.precision = in.precision.value_or(scene.solver.precision);
  const bool coulomb = scene.rough() && s.law == Law::coulomb;
  s.method_automatic = s.method == Method::automatic;
  if (s.method == Method::automatic) {
    // The method that reached the error asked for with the least wall time in the measured
    // work-precision (docs/dop853.md, "Choosing a method"): dop853 down to rtol 1e-11 where it
    // runs (double, smooth scenes and the thesis law), the modern Bulirsch-Stoer below that,
    // in extended precision and under the coulomb law (its rest events).
    const bool dop853_runs = s.precision == Precision::double_ && !coulomb;
    s.method = dop853_runs && s.rtol >= kAutoDop853RtolMin ? Method::dop853 : Method::modern;
  }
  s.atol = in.atol < 0 ? scene.solver.atol : in.atol;
  s.error_estimate = in.error_estimate.value_or(scene.solver.error_estimate);
  s.accuracy = in.accuracy < 0 ? scene.solver.accuracy : in.accuracy;
  if (s.accuracy != 0.0) require_range(in.accuracy < 0 ? "solver.accuracy" : "accuracy", s.accuracy, kAccuracyMin, kAccuracyMax);
  if (s.method == Method::cvode && !(coulomb && s.engine == Engine::cxx))
    throw InputError("method", "cvode", "the CVODE cross-check exists for rough scenes under the coulomb law only");
  // dop853 (docs/dop853.md) integrates a smooth ODE: the smooth scenes, and the rough ones
  // under the thesis law. The coulomb law needs the rest events located and the stick held,
  // which only the Bulirsch-Stoer engine (and the CVODE cross-check) do.
  if (s.method == Method::dop853 && coulomb)
    throw InputError(mfield, "dop853",
                     "the coulomb law needs its rest events located, which dop853 does not do: use faithful, modern "
                     "or cvode, or law thesis");
  if (s.engine == Engine::f77 && coulomb)
    throw InputError("engine", "f77", "the F77 engine implements the thesis friction law only (use --engine cxx)");
  if (s.precision != Precision::double_) {
    const std::string why = extended_precision_obstacle(scene.rough(), s.law, s.engine, s.method);
    if (!why.empty()) throw InputError(pfield, to_string(s.precision), why);
  }
  if (s.method == Method::dop853 && s.rtol < rtol_in_eps<double>(kDop853RtolEps))
    throw InputError("rtol", fmt(s.rtol),
                     "must be >= " + fmt_short(rtol_in_eps<double>(kDop853RtolEps)) + " (" + fmt(kDop853RtolEps) +
                         " eps of double) with the dop853 method; use --method faithful, or modern with --precision "
                         "long or quad");
  if (s.method == Method::modern && s.engine == Engine::cxx) {
    const double floor = s.precision == Precision::quad    ? rtol_in_eps<num::quad>(kDenseRtolEps)
                         : s.precision == Precision::long_ ? rtol_in_eps<long double>(kDenseRtolEps)
                                                           : rtol_in_eps<double>(kDenseRtolEps);
    if (s.rtol < floor)
      throw InputError("rtol", fmt(s.rtol),
                       "must be >= " + fmt_short(floor) + " (" + fmt(kDenseRtolEps) + " eps of " +
                           to_string(s.precision) +
                           ") with the modern method (dense output); use --precision long or quad, or "
                           "--method faithful");
  }
  return s;
}

TrajectoryRow make_row(double t, const double* y, const WorldWrench& f) {
  return {t, y[kX], y[kY], y[kTheta], y[kVx], y[kVy], y[kOmega], f.fx, f.fy, f.mf};
}

RoughBarModel rough_model(const Scene& sc) {
  RoughBarModel m;
  m.mass = sc.mass;
  m.inertia = sc.inertia;
  m.geometry = sc.geometry;
  m.muN = sc.friction_limit();
  m.push = sc.push;
  m.reading = sc.surface.printed;
  return m;
}

namespace {

template <class S = double>
BsOptions<S> options_for(const Scene& sc, const ResolvedSettings& s, const std::vector<S>& atol) {
  auto opt = s.method == Method::modern ? BsOptions<S>::modern(S(s.rtol), atol) : BsOptions<S>::faithful(S(s.rtol), atol);
  opt.h0 = S(sc.solver.h0);
  opt.hmax = S(sc.solver.hmax);
  opt.maxstp = sc.solver.max_steps;
  return opt;
}

/// A dop853 run (docs/dop853.md) in double with the scene's step settings.
template <int NS, class Rhs, class Observer>
BsResult run_dop853(const Scene& sc, const ResolvedSettings& s, const std::vector<double>& atol, const Rhs& rhs, double* y,
                    const std::vector<double>& tout, Observer&& observer) {
  auto opt = Dop853Options<double>::make(s.rtol, atol);
  opt.h0 = sc.solver.h0;
  opt.hmax = sc.solver.hmax;
  opt.maxstp = sc.solver.max_steps;
  Dop853<double, NS> dp(std::move(opt));
  return dp.integrate(rhs, 0.0, y, std::span<const double>(tout), std::forward<Observer>(observer));
}

/// The smooth bar in the C++ engine, integrated in scalar S (double, long double or
/// __float128): initial state, output times, rtol and atol converted to S; the rows are the
/// states rounded back to double. In double this is the plain double run.
template <class S>
Trajectory run_cxx_smooth(const Scene& sc, const ResolvedSettings& s) {
  constexpr bool extended = !std::is_same_v<S, double>;
  Trajectory tr;
  tr.engine_label = "cxx-" + to_string(s.method);
  tr.precision = precision_of<S>();
  if constexpr (extended) tr.engine_label += "-" + to_string(tr.precision);
  tr.rtol = s.rtol;
  tr.atol = sc.atol_vector(s.rtol, s.atol);
  const std::vector<S> atol(tr.atol.begin(), tr.atol.end());
  const SmoothBarRhs rhs{sc.mass, sc.inertia, sc.push};
  const auto tout_d = sc.output_times();
  const std::vector<S> tout(tout_d.begin(), tout_d.end());
  std::array<S, kStateSize> y;
  std::copy(sc.initial.begin(), sc.initial.end(), y.begin());
  tr.rows.reserve(tout.size());
  if constexpr (extended) tr.extended.reserve(tout.size());
  const double n = static_cast<double>(tout.size());
  auto observer = [&](std::size_t i, S t, const S* yy) {
    if constexpr (extended) {
      double yd[kStateSize];
      std::array<num::quad, kStateSize> yq;
      for (int c = 0; c < kStateSize; ++c) {
        yd[c] = static_cast<double>(yy[c]);
        yq[static_cast<std::size_t>(c)] = static_cast<num::quad>(yy[c]);
      }
      tr.rows.push_back(make_row(static_cast<double>(t), yd));
      tr.extended.push_back(yq);
    } else {
      tr.rows.push_back(make_row(t, yy));
    }
    if (s.progress) s.progress(static_cast<double>(i + 1) / n);
  };
  if constexpr (!extended) {
    if (s.method == Method::dop853) {  // double only (resolve_settings)
      tr.stats = run_dop853<kStateSize>(sc, s, tr.atol, rhs, y.data(), tout_d, observer);
      return tr;
    }
  }
  BulirschStoer<S, kStateSize> bs(options_for<S>(sc, s, atol));
  tr.stats = bs.integrate(rhs, S(0), y.data(), std::span<const S>(tout), observer);
  return tr;
}

/// A body at rest that slides: friction at t = 0 in the direction it starts to move. Returns
/// the friction evaluations the analysis took (0 when it is not at rest, or would stick).
std::int64_t set_start_direction(RoughBarModel& m, const double* y) {
  if (m.muN == 0.0 || y[kVx] != 0.0 || y[kVy] != 0.0 || y[kOmega] != 0.0) return 0;
  const RestAnalysis ra = analyse_rest(m, y[kTheta]);
  if (!ra.stuck) m.rest_direction = ra.accel;
  return ra.evaluations;
}

/// The thesis and printed laws have no static friction (eq 3.40's sign has no value at rest).
/// The kinks of the thesis law's wrench: the iCOR (-vby/omega, vbx/omega) in body axes crossing
/// the lines x' = +-a and y' = +-b of the contact's edges, as g = vby^2 - a^2 omega^2 and
/// vbx^2 - b^2 omega^2 (no division: both keep their sign through omega = 0).
template <typename S>
void thesis_kinks(const RoughBarModel& m, const S* y, S* g) {
  const S c = num::cos(y[kTheta]), sn = num::sin(y[kTheta]);
  const S vbx = c * y[kVx] + sn * y[kVy], vby = -sn * y[kVx] + c * y[kVy];
  const S w2 = y[kOmega] * y[kOmega];
  g[0] = vby * vby - S(m.geometry.a) * S(m.geometry.a) * w2;
  g[1] = vbx * vbx - S(m.geometry.b) * S(m.geometry.b) * w2;
}

std::string printed_blowup_message(double work, double t) {
  return "the printed law's friction did +" + fmt_short(work) + " J of positive work by t = " + fmt_short(t) +
         " s: the signs of eqs 3.45-3.48 as printed inject energy, and the motion blows up until the "
         "integrator gives up (docs/rough.md); --law thesis or coulomb";
}

}  // namespace

bool starts_stuck(const Scene& sc) {
  if (!sc.rough() || sc.friction_limit() == 0.0) return false;
  if (sc.initial[kVx] != 0.0 || sc.initial[kVy] != 0.0 || sc.initial[kOmega] != 0.0) return false;
  const RestWatch watch(rough_model(sc));
  return analyse_rest(watch.coulomb, sc.initial[kTheta]).stuck;
}

std::string no_static_friction_message(const Scene& sc, Law law, double t, double x, double y, double theta) {
  return "the object " +
         std::string(t > 0.0 ? "came to rest at t = " + fmt_short(t) + " s" : "starts at rest") + " (x = " + fmt_short(x) +
         " m, y = " + fmt_short(y) + " m, theta = " + fmt_short(theta) + " rad)" +
         " where the push (F = " + fmt_short(sc.push.force) + " N) cannot break static friction (mu N = " +
         fmt_short(sc.friction_limit()) + " N, the coulomb limit surface): the " + to_string(law) +
         " law's sign of the velocity has no static friction, so it cannot hold the object and the "
         "integrator would chatter there; --law coulomb holds it (event-located stick-slip, docs/rough.md)";
}


namespace {

template <typename S>
std::array<S, kRoughStateSize> rough_initial(const Scene& sc) {
  std::array<S, kRoughStateSize> y{};
  std::copy(sc.initial.begin(), sc.initial.end(), y.begin());
  return y;
}

/// A state in scalar S rounded to double (a copy only when S is not double).
template <typename S>
struct AsDouble {
  std::array<double, kRoughStateSize> buf{};
  const double* p;
  explicit AsDouble(const S* y) {
    if constexpr (std::is_same_v<S, double>) {
      p = y;
    } else {
      for (int i = 0; i < kRoughStateSize; ++i) buf[static_cast<std::size_t>(i)] = static_cast<double>(y[i]);
      p = buf.data();
    }
  }
};

/// run_cxx_rough's coulomb law (event-located stick-slip; CVODE with --method cvode): the stats,
/// the rest events and the outcome into `tr`; the integrator's failures become its status.
template <typename S, class Tout, class Record>
void run_coulomb_rough(Trajectory& tr, const Scene& sc, const ResolvedSettings& s, const RoughBarModel& model,
                       const std::vector<S>& atol, S* y, const Tout& tout, Record& record) {
  constexpr bool extended = !std::is_same_v<S, double>;
  StickSlipResult r;
  try {
    if constexpr (extended)
      r = integrate_coulomb_extended<S>(model, options_for<S>(sc, s, atol), y, tout, record);
    else if (s.method == Method::cvode)
      r = integrate_coulomb_cvode(model, s.rtol, tr.atol, y, tout, record);
    else
      r = integrate_coulomb(model, options_for(sc, s, tr.atol), y, tout, record);
  } catch (const CoulombError& e) {
    tr.stats.status = e.status();
    tr.stats.message = e.what();
    return;
  } catch (const SolverError& e) {  // CVODE's failures
    tr.stats.status = BsStatus::rhs_failed;
    tr.stats.message = e.what();
    return;
  }
  tr.stats = r.stats;
  for (const auto& e : r.events) tr.events.push_back({e.t, e.stuck});
  if (tr.events.size() == 1 && tr.events[0].t == 0.0 && tr.events[0].stuck) {
    tr.outcome = Outcome::at_rest;
    tr.outcome_message = "the push (F = " + fmt_short(sc.push.force) +
                         " N) lies inside the limit surface: static friction holds the object where it is";
  }
}

/// The rough bar in the C++ engine in scalar S: double (every method), long double and quad
/// (modern, the thesis and coulomb laws; resolve_settings refuses the rest). Rows in double;
/// extended runs also keep the pose and velocity in quad (Trajectory::extended).
template <typename S>
Trajectory run_cxx_rough(const Scene& sc, const ResolvedSettings& s) {
  constexpr bool extended = !std::is_same_v<S, double>;
  Trajectory tr;
  tr.engine_label = "cxx-" + to_string(s.method) + "-" + to_string(s.law);
  tr.precision = precision_of<S>();
  if constexpr (extended) tr.engine_label += "-" + to_string(tr.precision);
  tr.rtol = s.rtol;
  tr.atol = sc.atol_vector(s.rtol, s.atol, kRoughStateSize);
  const std::vector<S> atol(tr.atol.begin(), tr.atol.end());
  RoughBarModel model = rough_model(sc);
  model.printed = s.law == Law::printed;
  model.f77_forms = s.method == Method::faithful;
  const auto tout = sc.output_times();
  auto y = rough_initial<S>(sc);
  const double n = static_cast<double>(tout.size());
  auto record = [&](double t, const S* yy, const WorldWrench& f) {
    const AsDouble<S> yd(yy);
    tr.rows.push_back(make_row(t, yd.p, f));
    tr.work_push.push_back(yd.p[kWorkPush]);
    tr.work_fric.push_back(yd.p[kWorkFric]);
    if constexpr (extended) {
      std::array<num::quad, kStateSize> yq;
      for (int c = 0; c < kStateSize; ++c) yq[static_cast<std::size_t>(c)] = static_cast<num::quad>(yy[c]);
      tr.extended.push_back(yq);
    }
    if (s.progress) s.progress(static_cast<double>(tr.rows.size()) / n);
  };
  // The rest watch sees states in double.
  auto watch_hook = [](RestWatch& w) {
    return [&w](double t0, const S* y0, double t1, const S* y1) {
      const AsDouble<S> a(y0), b(y1);
      return w(t0, a.p, t1, b.p);
    };
  };
  if (s.law == Law::thesis || s.law == Law::printed) {
    // Started from rest, eq 3.40 gives no friction direction at t = 0, so the first step sees
    // friction jump from 0 to mu N. The faithful method keeps that value (its steps are the
    // F77 engine's); the others take the right limit, friction in the direction the body
    // starts to move (Gauss' principle: analyse_rest). The exact solution is the same (one
    // instant), but without it an extrapolation or Runge-Kutta step across t = 0 misses its
    // tolerance by 100-1000x (docs/rough.md, "Starting from rest").
    RoughBarModel m = model;
    std::int64_t start_evaluations = 0;
    // The printed law keeps zero friction at rest with every method (its wrench has no
    // right limit to take from the coulomb analysis: the printed forms are not a limit surface).
    const auto y_start = rough_initial<double>(sc);
    if (s.method != Method::faithful && !m.printed) start_evaluations = set_start_direction(m, y_start.data());
    const RoughBarThesisRhs rhs{m};
    auto observer = [&](double t, const S* yy) {
      const WorldWrenchT<S> f = model.friction_in(num::cos(yy[kTheta]), num::sin(yy[kTheta]), yy[kVx], yy[kVy], yy[kOmega]);
      record(t, yy, {static_cast<double>(f.fx), static_cast<double>(f.fy), static_cast<double>(f.mf)});
    };
    RestWatch watch(model);
    if (starts_stuck(sc)) {
      record(0.0, y.data(), WorldWrench{});
      tr.stats.t_reached = 0.0;
      tr.outcome = Outcome::no_static_friction;
      tr.outcome_message = no_static_friction_message(sc, s.law, 0.0, sc.initial[kX], sc.initial[kY], sc.initial[kTheta]);
      return tr;
    }
    if (s.law == Law::thesis && s.method != Method::faithful) {
      // modern and dop853: the kinks of the wrench located (kinks.hpp; faithful keeps the F77
      // engine's steps).
      const detail::KinkIntegrateT<S> run = [&](double t0, S* yy, std::span<const double> to,
                                                const detail::KinkObserverT<S>& obs, const detail::KinkHookT<S>& hook,
                                                double h0, std::int64_t max_steps) {
        auto o = [&](std::size_t, S t, const S* v) { obs(static_cast<double>(t), v); };
        if constexpr (!extended) {
          if (s.method == Method::dop853) {
            auto opt = Dop853Options<double>::make(s.rtol, tr.atol);
            opt.h0 = h0 > 0 ? h0 : sc.solver.h0;
            opt.hmax = sc.solver.hmax;
            opt.maxstp = max_steps;
            Dop853<double, kRoughStateSize> dp(std::move(opt));
            return static_cast<IntegrationResult>(dp.integrate(rhs, t0, yy, to, o, std::cref(hook)));
          }
        }
        auto opt = options_for<S>(sc, s, atol);
        if (h0 > 0) opt.h0 = S(h0);
        opt.maxstp = max_steps;
        BulirschStoer<S, kRoughStateSize> bs(opt);
        if constexpr (!extended) {
          return static_cast<IntegrationResult>(bs.integrate(rhs, t0, yy, to, o, std::cref(hook)));
        } else {  // output times and hook times in S
          const std::vector<S> to_s(to.begin(), to.end());
          auto h = [&hook](S ta, const S* ya, S tb, const S* yb) {
            return hook(static_cast<double>(ta), ya, static_cast<double>(tb), yb);
          };
          return static_cast<IntegrationResult>(bs.integrate(rhs, S(t0), yy, std::span<const S>(to_s), o, h));
        }
      };
      const detail::KinkResult kr = detail::integrate_across_kinks<S>(
          run, [&m](const S* v, S* g) { thesis_kinks(m, v, g); }, 2, y.data(), kRoughStateSize,
          std::span<const double>(tout), observer, watch_hook(watch), sc.solver.max_steps);
      tr.stats = kr.stats;
      tr.kinks_located = kr.located;
    } else if constexpr (extended) {
      throw std::logic_error("run_cxx_rough: extended precision outside modern + thesis/coulomb (resolve_settings)");
    } else if (s.method == Method::dop853) {
      auto opt = Dop853Options<double>::make(s.rtol, tr.atol);
      opt.h0 = sc.solver.h0;
      opt.hmax = sc.solver.hmax;
      opt.maxstp = sc.solver.max_steps;
      Dop853<double, kRoughStateSize> dp(std::move(opt));
      auto o = [&](std::size_t, double t, const double* v) { observer(t, v); };
      tr.stats = dp.integrate(rhs, 0.0, y.data(), std::span<const double>(tout), o, std::ref(watch));
    } else {
      auto o = [&](std::size_t, double t, const double* v) { observer(t, v); };
      BulirschStoer<double, kRoughStateSize> bs(options_for(sc, s, tr.atol));
      tr.stats = bs.integrate(rhs, 0.0, y.data(), std::span<const double>(tout), o, std::ref(watch));
    }
    tr.stats.nfcn += start_evaluations;
    if (watch.came_to_rest) {
      tr.outcome = Outcome::no_static_friction;
      const AsDouble<S> yd(y.data());
      tr.outcome_message = no_static_friction_message(sc, s.law, watch.t_rest, yd.p[kX], yd.p[kY], yd.p[kTheta]);
    } else if (!tr.stats.ok() && m.printed && watch.positive_work > 0.0) {
      tr.outcome = Outcome::law_blowup;
      tr.outcome_message = printed_blowup_message(watch.positive_work, tr.stats.t_reached);
    } else if (tr.stats.status == BsStatus::step_underflow && m.printed &&
               std::fabs(watch.last_omega) < 1e-2 * watch.max_omega) {
      // The printed forms jump where omega changes sign (no sgn(omega) in the printed F3):
      // the steps shrink onto the jump until they underflow.
      tr.outcome = Outcome::law_blowup;
      tr.outcome_message = "step size underflow as omega changes sign (omega = " + fmt_short(watch.last_omega) +
                           " rad/s, down from " + fmt_short(watch.max_omega) +
                           "): the printed forms of eqs 3.45-3.48 jump there, and the motion cannot be integrated "
                           "across it (docs/rough.md); --law thesis or coulomb";
    }
    return tr;
  }
  run_coulomb_rough<S>(tr, sc, s, model, atol, y.data(), tout, record);
  return tr;
}

}  // namespace

Trajectory run_scene(const Scene& scene, const RunSettings& settings) {
  RunSettings own = settings;
  if (!own.engine) own.engine = Engine::cxx;  // run_scene is the C++ engine, whatever the scene names
  const ResolvedSettings s = resolve_settings(scene, own);
  if (s.engine == Engine::f77)
    throw InputError("engine", "f77",
                     "run_scene is the C++ engine; the F77 engine runs through nanopush::engines "
                     "(nanopush/engines/engines.hpp: run_engine)");
  return finish_run(scene, s, run_cxx(scene, s));
}

Trajectory run_cxx(const Scene& scene, const ResolvedSettings& s) {
  if (scene.push_mode == PushMode::tip) return run_cxx_tip(scene, s);
  if (scene.rough()) {
    if (s.precision == Precision::long_) return run_cxx_rough<long double>(scene, s);
    if (s.precision == Precision::quad) return run_cxx_rough<num::quad>(scene, s);
    return run_cxx_rough<double>(scene, s);
  }
  if (s.precision == Precision::long_) return run_cxx_smooth<long double>(scene, s);
  if (s.precision == Precision::quad) return run_cxx_smooth<num::quad>(scene, s);
  return run_cxx_smooth<double>(scene, s);
}

Trajectory finish_run(const Scene& scene, const ResolvedSettings& s, Trajectory tr) {
  if (tr.outcome == Outcome::ok && !tr.stats.ok()) {
    tr.outcome = Outcome::solver_failure;
    // A run of the thesis or printed law that gave up where the object is at rest inside the
    // limit surface (the F77 engine has no watch; RestWatch stops the C++ engine earlier).
    if (scene.rough() && s.law != Law::coulomb && !tr.rows.empty()) {
      const auto& r = tr.rows.back();
      const RoughBarModel m = rough_model(scene);
      const RestWatch watch(m);
      std::array<double, kRoughStateSize> y{};
      y[kTheta] = r[col::theta];
      y[kVx] = r[col::vx];
      y[kVy] = r[col::vy];
      y[kOmega] = r[col::omega];
      if (s.law == Law::printed && !tr.work_fric.empty() &&
          *std::max_element(tr.work_fric.begin(), tr.work_fric.end()) > 0.0) {
        tr.outcome = Outcome::law_blowup;
        tr.outcome_message = printed_blowup_message(
            *std::max_element(tr.work_fric.begin(), tr.work_fric.end()), tr.stats.t_reached);
      } else if (watch.gave_up_at_rest(y.data(), scene.solver.t_end)) {
        tr.outcome = Outcome::no_static_friction;
        tr.outcome_message = no_static_friction_message(scene, s.law, r[col::t], r[col::x], r[col::y], r[col::theta]);
      }
    }
  }
  if (tr.outcome == Outcome::solver_failure && tr.stats.status == BsStatus::too_many_steps && tr.rows.size() > 1 &&
      tr.outcome_message.empty()) {
    // A bar pushed hard turns (or swings about the push's line) faster and faster: each turn
    // costs some tens of steps, so say how fast it turns rather than only that the budget is
    // spent. The samples are too sparse to count turns; the largest |omega| bounds them.
    double w = 0;
    for (const auto& r : tr.rows) w = std::max(w, std::fabs(r[col::omega]));
    const double turns = w * scene.solver.t_end / (2 * M_PI);
    if (turns >= 1000)
      tr.outcome_message = std::string(to_string(tr.stats.status)) + ": " + tr.stats.message + " by t = " +
                           fmt_short(tr.stats.t_reached) + " s of " + fmt_short(scene.solver.t_end) +
                           " s; the object turns at up to |omega| = " + fmt_short(w) + " rad/s, a turn in " +
                           fmt_short(2 * M_PI / w) + " s, some " + std::to_string(std::llround(turns)) +
                           " turns or swings over t_end at tens of steps each: shorten solver.t_end or raise "
                           "solver.max_steps";
  }
  if (tr.outcome == Outcome::solver_failure && tr.outcome_message.empty()) {
    const std::string what = to_string(tr.stats.status) + (tr.stats.message.empty() ? "" : ": " + tr.stats.message);
    const auto outputs = static_cast<std::int64_t>(scene.output_times().size());
    // The faithful method and the F77 engine step to every output time (they clip their steps
    // there), so more outputs than the budget cannot be done.
    if (tr.stats.status == BsStatus::too_many_steps && (s.method == Method::faithful || s.engine == Engine::f77) &&
        outputs >= scene.solver.max_steps)
      tr.outcome_message = what + ": the run steps to each of its " + std::to_string(outputs) +
                           " output times (solver.samples; " + (s.engine == Engine::f77 ? "the F77 engine" : "faithful") +
                           " clips its steps there), more than solver.max_steps = " +
                           std::to_string(scene.solver.max_steps) + ": lower solver.samples or raise solver.max_steps";
    // A t_end many orders beyond the motion's time scale (the push's rotational rate; a tip's
    // travel time over the bar) needs more steps than any budget, and its output spacing is
    // beyond what a step can reach: say so rather than only the integrator's words.
    const double rate = scene.state_scales()[5], scales = scene.solver.t_end * rate;
    const bool beyond = (tr.stats.status == BsStatus::step_underflow && scales >= 1e12) ||
                        (tr.stats.status == BsStatus::too_many_steps &&
                         scales >= 10 * static_cast<double>(scene.solver.max_steps));
    if (tr.outcome_message.empty() && rate > 0 && beyond)
      tr.outcome_message = what + ": solver.t_end = " + fmt_short(scene.solver.t_end) + " s is " + fmt_short(scales) +
                           " times the motion's time scale (" + fmt_short(1 / rate) + " s): shorten solver.t_end" +
                           (tr.stats.status == BsStatus::too_many_steps ? " or raise solver.max_steps" : "");
    // One atol for every component: where it is below the rounding of a component's size, no
    // step can meet it.
    if (tr.outcome_message.empty() && tr.stats.status == BsStatus::step_underflow && s.atol > 0) {
      static constexpr const char* kNames[8] = {"x", "y", "theta", "vx", "vy", "omega", "work", "work"};
      const auto sc = scene.state_scales();
      for (std::size_t i = 0; i < 6; ++i)
        if (s.atol < 4 * std::numeric_limits<double>::epsilon() * sc[i]) {
          tr.outcome_message = what + ": solver.atol = " + fmt_short(s.atol) +
                               " (one value for every component) is below the rounding of " + kNames[i] +
                               " (its scale " + fmt_short(sc[i]) + " in SI: 4 eps of it is " +
                               fmt_short(4 * std::numeric_limits<double>::epsilon() * sc[i]) +
                               "): raise solver.atol, or leave it out (each component's then follows rtol)";
          break;
        }
    }
  }
  if (!is_answer(tr.outcome)) {
    tr.complete = false;
    if (tr.outcome_message.empty())
      tr.outcome_message = to_string(tr.stats.status) + (tr.stats.message.empty() ? "" : ": " + tr.stats.message);
    if (!s.allow_partial)
      throw SolverError(scene.name + " (" + tr.engine_label + "): " + tr.outcome_text(), to_string(tr.outcome));
  }
  return tr;
}

}  // namespace nanopush
