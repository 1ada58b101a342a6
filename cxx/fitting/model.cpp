// The forward model at the observed times and its derivatives with respect to the free keys.
//
// Smooth scenes and the thesis law (a right-hand side smooth along the trajectory): forward
// sensitivities s_k = dy/dq_k (q_k = p_k / c_k, relative parameters), integrated with the
// state as one system by Dormand-Prince 8(5,3) (the variational equations):
//   ds_k/dt = J_y s_k + df/dq_k,
// J_y s_k by a central difference quotient of the right-hand side along s_k, df/dq_k by central
// differences between right-hand sides rebuilt from Scene copies with q_k +- eta (Scene::set, so
// derived quantities such as mass from density follow). This is what CVODES's
// difference-quotient sensitivity right-hand side does; CVODES itself cannot be linked beside
// CVODE (the models layer's cross-check): both libraries export the same CVode* symbols.
//
// The coulomb law (rest events: the right-hand side jumps where the body sticks): central
// differences of whole forward solves (Bulirsch-Stoer with event location) at a tight rtol.
#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

#include "nanopush_toml.hpp"

#include "internal.hpp"
#include "nanopush/fitting/fit.hpp"
#include "nanopush/models/rigid_body.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/models/stick_slip.hpp"
#include "nanopush/numerics/dop853.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/rest_watch.hpp"
#include "nanopush/scenes/scene_keys.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush::fit {

namespace detail {

Scene scene_at(const Scene& base, const std::vector<std::string>& free, const std::vector<double>& p) {
  Scene s = base;
  std::vector<SceneSetting> st;
  st.reserve(free.size());
  for (std::size_t k = 0; k < free.size(); ++k) st.emplace_back(free[k], SceneValue(p[k]));
  s.set(st);
  return s;
}

double key_value(const Scene& scene, const std::string& key) {
  const SceneKey* sk = find_scene_key(key);
  if (sk == nullptr) throw InputError("--free", key, "not a scene key (nanopush scene-keys lists them)");
  if (sk->type != KeyType::number)
    throw InputError("--free", key, "must be a numeric key (this one is " + std::string(key_type_name(sk->type)) + ")");
  if (key.rfind("solver.", 0) == 0 || key.rfind("scene.", 0) == 0)
    throw InputError("--free", key, "solver and scene settings are not model parameters");
  if (scene.document) {
    const auto node = scene.document->at_path(key);
    if (const auto v = node.value<double>()) return *v;
  }
  // Not in the file: the value the scene derived or defaulted.
  if (key == "object.mass") return scene.mass;
  if (key == "object.inertia") return scene.inertia;
  if (key == "surface.normal_load") return scene.normal_load();
  if (key == "surface.mu") return scene.surface.mu;
  if (key == "surface.f_vdw") return scene.surface.f_vdw;
  if (key == "surface.g") return scene.surface.g;
  if (key == "push.force") return scene.push.force;
  if (key == "push.direction") return scene.push.beta;
  if (key == "initial.x") return scene.initial[kX];
  if (key == "initial.y") return scene.initial[kY];
  if (key == "initial.theta") return scene.initial[kTheta];
  if (key == "initial.vx") return scene.initial[kVx];
  if (key == "initial.vy") return scene.initial[kVy];
  if (key == "initial.omega") return scene.initial[kOmega];
  throw InputError("--free", key, "this scene does not set the key; set a start value with --set " + key + "=VALUE");
}

double parameter_scale(const Scene& scene, const std::string& key, double value) {
  if (value != 0.0) return std::abs(value);
  const SceneKey* sk = find_scene_key(key);
  const std::string unit = sk ? std::string(sk->unit) : "";
  const auto sc = scene.state_scales();
  const double len = sc[0];
  const double tend = scene.solver.t_end > 0 ? scene.solver.t_end : 1.0;
  if (unit == "m") return len;
  if (unit == "m/s") return len / tend;
  if (unit == "rad/s") return 1.0 / tend;
  if (unit == "N") return scene.push.force;
  return 1.0;
}

}  // namespace detail

namespace {

/// The right-hand side of a scene: the smooth bar (6 states) or the rough bar under the
/// thesis law (8 states), with the friction direction at a start from rest (as the C++
/// engine's non-faithful methods take it: docs/rough.md, "Starting from rest").
struct SceneRhs {
  int n = kStateSize;
  std::optional<SmoothBarRhs> smooth;
  std::optional<RoughBarThesisRhs> rough;
  std::array<double, kRoughStateSize> y0{};
  void operator()(const double* y, double* d) const {
    if (smooth)
      (*smooth)(0.0, y, d);
    else
      (*rough)(0.0, y, d);
  }
};

SceneRhs make_rhs(const Scene& s) {
  SceneRhs r;
  std::copy(s.initial.begin(), s.initial.end(), r.y0.begin());
  if (!s.rough()) {
    r.smooth.emplace(s.mass, s.inertia, s.push);
    return r;
  }
  r.n = kRoughStateSize;
  RoughBarModel m = rough_model(s);
  const double* y = r.y0.data();
  if (m.muN != 0.0 && y[kVx] == 0.0 && y[kVy] == 0.0 && y[kOmega] == 0.0) {
    const RestAnalysis ra = analyse_rest(m, y[kTheta]);
    if (!ra.stuck) m.rest_direction = ra.accel;
  }
  r.rough.emplace(RoughBarThesisRhs{m});
  return r;
}

void check_times(const std::vector<double>& times) {
  if (times.empty()) throw InputError("times", "(none)", "need at least one observation time");
  for (std::size_t i = 0; i < times.size(); ++i) {
    require_finite("times", times[i], "s");
    if (times[i] < 0 || (i > 0 && !(times[i] > times[i - 1])))
      throw InputError("times", fmt(times[i]), "must be >= 0 and strictly increasing");
  }
}

[[noreturn]] void solver_failed(const Scene& s, const std::string& what, const BsResult& r) {
  throw SolverError(s.name + " (" + what + "): " + to_string(r.status) +
                    (r.message.empty() ? " at t = " + fmt(r.t_reached) : ": " + r.message));
}

/// Relative step of the parameter differences.
constexpr double kEta = 1e-5;
/// Floor of the state weights of the difference quotient along s, in units of the state's
/// natural scale: the body starts from rest, where velocities far below their scale change the
/// friction direction (a floor of 1 gave 4e-7 relative errors on fig3_20, 1e-3 gives 5e-10).
constexpr double kWeightFloor = 1e-3;

/// Smooth right-hand side: the state and (optionally) its sensitivities by DOP853.
ModelPoses smooth_poses(const Scene& scene, const std::vector<std::string>& free, const std::vector<double>& p,
                        const std::vector<double>& times, double rtol, bool derivatives) {
  const std::size_t np = derivatives ? free.size() : 0;
  const SceneRhs f0 = make_rhs(scene);
  const int n = f0.n;
  std::vector<double> scale(np);
  std::vector<SceneRhs> plus, minus;
  std::vector<double> width(np, 2 * kEta);  // of each difference, in units of the scale
  for (std::size_t k = 0; k < np; ++k) {
    scale[k] = detail::parameter_scale(scene, free[k], p[k]);
    auto pp = p, pm = p;
    pp[k] += kEta * scale[k];
    pm[k] -= kEta * scale[k];
    // At the end of a key's range (surface.mu = 0) the step beyond it is no scene: a one-sided
    // difference against the centre instead, never an error citing a value nobody wrote.
    auto side = [&](const std::vector<double>& q) -> std::optional<SceneRhs> {
      try {
        return make_rhs(detail::scene_at(scene, free, q));
      } catch (const InputError&) {
        return std::nullopt;
      }
    };
    auto a = side(pp), b = side(pm);
    if (!a && !b) {
      (void)make_rhs(detail::scene_at(scene, free, pp));  // neither side: the error of the + side
    }
    if (!a || !b) width[k] = kEta;
    plus.push_back(a ? std::move(*a) : make_rhs(detail::scene_at(scene, free, p)));
    minus.push_back(b ? std::move(*b) : make_rhs(detail::scene_at(scene, free, p)));
  }
  const int N = n * static_cast<int>(1 + np);
  std::vector<double> y(static_cast<std::size_t>(N), 0.0);
  std::copy(f0.y0.begin(), f0.y0.begin() + n, y.begin());
  for (std::size_t k = 0; k < np; ++k)
    for (int i = 0; i < n; ++i)
      y[static_cast<std::size_t>(n * static_cast<int>(k + 1) + i)] =
          (plus[k].y0[static_cast<std::size_t>(i)] - minus[k].y0[static_cast<std::size_t>(i)]) / width[k];
  const auto scales = scene.state_scales();
  std::vector<double> atol(static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) atol[static_cast<std::size_t>(i)] = rtol * scales[static_cast<std::size_t>(i % n)];

  // The variational system. The state direction s is scaled so the perturbation is
  // delta in the weighted norm (|y| + scale), as CVODES's difference quotients do.
  const double delta = std::cbrt(std::numeric_limits<double>::epsilon());
  std::vector<double> ya(static_cast<std::size_t>(n)), yb(static_cast<std::size_t>(n)), fa(static_cast<std::size_t>(n)),
      fb(static_cast<std::size_t>(n));
  auto rhs = [&](double, const double* Y, double* D) -> int {
    f0(Y, D);
    for (std::size_t k = 0; k < np; ++k) {
      const double* s = Y + n * static_cast<int>(k + 1);
      double* ds = D + n * static_cast<int>(k + 1);
      double norm = 0;
      for (int i = 0; i < n; ++i) {
        const double w = std::abs(Y[i]) + kWeightFloor * scales[static_cast<std::size_t>(i)];
        norm = std::max(norm, std::abs(s[i]) / w);
      }
      if (norm > 0) {
        const double h = delta / norm;
        for (int i = 0; i < n; ++i) {
          ya[static_cast<std::size_t>(i)] = Y[i] + h * s[i];
          yb[static_cast<std::size_t>(i)] = Y[i] - h * s[i];
        }
        f0(ya.data(), fa.data());
        f0(yb.data(), fb.data());
        for (int i = 0; i < n; ++i) ds[i] = (fa[static_cast<std::size_t>(i)] - fb[static_cast<std::size_t>(i)]) / (2 * h);
      } else {
        for (int i = 0; i < n; ++i) ds[i] = 0;
      }
      plus[k](Y, fa.data());
      minus[k](Y, fb.data());
      for (int i = 0; i < n; ++i) ds[i] += (fa[static_cast<std::size_t>(i)] - fb[static_cast<std::size_t>(i)]) / width[k];
    }
    for (int i = 0; i < N; ++i)
      if (!std::isfinite(D[i])) return 1;
    return 0;
  };
  auto opt = Dop853Options<double>::make(rtol, atol);
  opt.maxstp = scene.solver.max_steps;
  opt.h0 = scene.solver.h0;
  opt.hmax = scene.solver.hmax;
  Dop853<double> dp(std::move(opt), N);
  ModelPoses out;
  out.pose.resize(times.size());
  if (derivatives) out.jac.assign(times.size(), std::vector<std::array<double, 3>>(free.size()));
  auto observer = [&](std::size_t i, double, const double* Y) {
    out.pose[i] = {Y[kX], Y[kY], Y[kTheta]};
    for (std::size_t k = 0; k < np; ++k) {
      const double* s = Y + n * static_cast<int>(k + 1);
      out.jac[i][k] = {s[kX] / scale[k], s[kY] / scale[k], s[kTheta] / scale[k]};  // d/dp = d/dq / c
    }
  };
  // A rough body that comes to rest where the thesis law cannot hold it: stop there, as a run does.
  std::optional<RestWatch> watch;
  if (scene.rough()) watch.emplace(rough_model(scene));
  auto hook = [&](double t0, const double* y0, double t1, const double* y1) {
    return watch ? (*watch)(t0, y0, t1, y1) : kHookContinue;
  };
  const auto res = dp.integrate(rhs, 0.0, y.data(), std::span<const double>(times), observer, hook);
  // With sensitivities the error control follows them too, and they blow up as the sign law
  // chatters at rest: the solve can give up before the watch sees a reversal. A failure there
  // is the same rest, as finish_run judges a run's.
  if (watch && !res.ok() && watch->gave_up_at_rest(y.data(), scene.solver.t_end)) {
    watch->came_to_rest = true;
    watch->t_rest = res.t_reached;
  }
  if (watch && watch->came_to_rest) {
    const Law law = rough_model(scene).printed ? Law::printed : Law::thesis;
    throw SolverError(scene.name + " (" + to_string(law) + " law): " +
                          no_static_friction_message(scene, law, watch->t_rest, y[kX], y[kY], y[kTheta]),
                      to_string(Outcome::no_static_friction));
  }
  if (!res.ok()) solver_failed(scene, derivatives ? "dop853 with sensitivities" : "dop853", res);
  return out;
}

/// Coulomb law: one forward solve with event location.
std::vector<std::array<double, 3>> coulomb_poses(const Scene& scene, const std::vector<double>& times, double rtol) {
  const RoughBarModel model = rough_model(scene);
  std::array<double, kRoughStateSize> y{};
  std::copy(scene.initial.begin(), scene.initial.end(), y.begin());
  // The integrator starts at t = 0: prepend it when the first observation is later.
  const bool prepend = times.front() > 0;
  std::vector<double> tout(times.size() + (prepend ? 1 : 0), 0.0);
  std::copy(times.begin(), times.end(), tout.begin() + (prepend ? 1 : 0));
  std::vector<std::array<double, 3>> out;
  out.reserve(tout.size());
  const auto atol = scene.atol_vector(rtol, 0, kRoughStateSize);
  bool skip = prepend;
  try {
    auto opt = BsOptions<double>::faithful(rtol, atol);
    opt.maxstp = scene.solver.max_steps;
    opt.h0 = scene.solver.h0;
    opt.hmax = scene.solver.hmax;
    integrate_coulomb(model, opt, y.data(), tout,
                      [&](double t, const double* yy, const WorldWrench&) {
                        if (!(prepend && t == 0.0 && out.empty() && skip)) out.push_back({yy[kX], yy[kY], yy[kTheta]});
                        skip = false;
                      });
  } catch (const CoulombError& e) {
    throw SolverError(scene.name + " (coulomb law): " + to_string(e.status()) + ": " + e.what());
  }
  if (out.size() != times.size()) throw SolverError(scene.name + " (coulomb law): the integration stopped early");
  return out;
}

}  // namespace

ModelPoses model_poses(const Scene& scene, const std::vector<std::string>& free, const std::vector<double>& p,
                       const std::vector<double>& times, std::optional<Law> law_in, double rtol, bool derivatives,
                       Gradients gradients, std::int64_t* solves) {
  check_times(times);
  require_range("rtol", rtol, 1e-14, 1e-3);
  if (p.size() != free.size()) throw InputError("parameters", std::to_string(p.size()), "one value per free key");
  Scene sc = free.empty() ? scene : detail::scene_at(scene, free, p);
  const Law law = detail::fit_law(scene, law_in);
  const bool coulomb = sc.rough() && law == Law::coulomb;
  // The thesis and printed laws have no static friction: an object that starts where the push
  // cannot break it would chatter through the whole step budget. Say so at once, as a run does.
  if (sc.rough() && !coulomb && starts_stuck(sc))
    throw SolverError(sc.name + " (" + to_string(law) + " law): " +
                          no_static_friction_message(sc, law, 0.0, sc.initial[kX], sc.initial[kY], sc.initial[kTheta]),
                      to_string(Outcome::no_static_friction));
  if (coulomb && gradients == Gradients::sensitivities)
    throw InputError("gradients", "sensitivities",
                     "the coulomb law's right-hand side jumps at its rest events: use differences (or auto)");
  auto count = [&] {
    if (solves) ++*solves;
  };
  const bool differences = derivatives && (coulomb || gradients == Gradients::differences);
  if (!coulomb && !differences) {
    count();
    return smooth_poses(sc, free, p, times, rtol, derivatives);
  }
  auto forward = [&](const Scene& s) {
    count();
    return coulomb ? coulomb_poses(s, times, rtol) : smooth_poses(s, free, {}, times, rtol, false).pose;
  };
  ModelPoses out;
  out.pose = forward(sc);
  if (!derivatives) return out;
  // Central differences of whole forward solves, at a tolerance well below the step.
  const double rtol_d = std::min(rtol, 1e-12);
  out.jac.assign(times.size(), std::vector<std::array<double, 3>>(free.size()));
  for (std::size_t k = 0; k < free.size(); ++k) {
    const double c = detail::parameter_scale(sc, free[k], p[k]);
    const double h = 1e-4 * c;
    auto pp = p, pm = p;
    pp[k] += h;
    pm[k] -= h;
    auto fwd = [&](const std::vector<double>& q) {
      const Scene s = detail::scene_at(scene, free, q);
      auto solve = [&](double r) {
        count();
        return coulomb ? coulomb_poses(s, times, r) : smooth_poses(s, free, {}, times, r, false).pose;
      };
      // The coulomb law's event location fails now and then at 1e-12 (about 1 % of mu on
      // the stick-slip bench scene) where it succeeds at 1e-10: then the fit's rtol.
      try {
        return solve(rtol_d);
      } catch (const SolverError&) {
        if (rtol_d >= rtol) throw;
      }
      return solve(rtol);
    };
    // A side whose solve fails (an event the integrator cannot resolve there) leaves a
    // one-sided difference against the centre, at the same tolerance.
    std::string why;
    // A side beyond the key's range (surface.mu = 0 - h) is no scene: one-sided as well.
    const auto side = [&](const auto& q) -> std::optional<std::vector<std::array<double, 3>>> {
      try {
        return fwd(q);
      } catch (const SolverError& e) {
        why = e.what();
      } catch (const InputError& e) {
        why = e.what();
      }
      return std::nullopt;
    };
    std::optional<std::vector<std::array<double, 3>>> a = side(pp), b = side(pm);
    double width = 2 * h;
    if (!a && !b) throw SolverError("differences in " + free[k] + " failed on both sides: " + why);
    if (!a) {
      a = fwd(p);
      width = h;
    } else if (!b) {
      b = fwd(p);
      width = h;
    }
    for (std::size_t i = 0; i < times.size(); ++i)
      for (std::size_t j = 0; j < 3; ++j) out.jac[i][k][j] = ((*a)[i][j] - (*b)[i][j]) / width;
  }
  return out;
}

}  // namespace nanopush::fit
