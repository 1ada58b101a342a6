// The trajectory fit: Eigen's Levenberg-Marquardt over the relative parameters, bounds by
// clamping, identifiability from the SVD of the scaled Jacobian, the JSON summary.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>

#include <Eigen/Dense>
#include <unsupported/Eigen/LevenbergMarquardt>

#include "internal.hpp"
#include "nanopush/fitting/fit.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/json.hpp"
#include "nanopush/scenes/scene_keys.hpp"

namespace nanopush::fit {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Bounds from the key's validation range (scene_keys: "> 0", ">= 0", "[a, b]", "finite").
std::array<double, 2> key_bounds(const std::string& key, double start) {
  const double inf = std::numeric_limits<double>::infinity();
  const SceneKey* sk = find_scene_key(key);
  const std::string r = sk ? std::string(sk->range) : "";
  if (r.rfind(">= 0", 0) == 0) return {0.0, inf};
  if (r.rfind("> 0", 0) == 0) return {std::abs(start) * 1e-9, inf};  // strictly positive
  if (!r.empty() && r[0] == '[') {
    double a = 0, b = 0;
    char close = 0;
    std::istringstream s(r.substr(1));
    char comma = 0;
    if (s >> a >> comma >> b >> close && comma == ',' && close == ']') return {a, b};
  }
  return {-inf, inf};
}

/// Named physical quantities that a fit may determine when their factors are not separable.
struct Quantity {
  std::string name, unit, description;
  std::function<double(const Scene&)> value;
};
const std::vector<Quantity>& quantities() {
  static const std::vector<Quantity> q = {
      {"mu*N", "N", "friction force scale: surface.mu times the normal load N",
       [](const Scene& s) { return s.rough() ? s.friction_limit() : 0.0; }},
      {"F/m", "m/s^2", "push acceleration: push.force over the mass", [](const Scene& s) { return s.push.force / s.mass; }},
      {"mu*N/m", "m/s^2", "friction deceleration: mu N over the mass",
       [](const Scene& s) { return s.rough() ? s.friction_limit() / s.mass : 0.0; }},
      {"F/mu*N", "1", "push over friction: push.force / (mu N)",
       [](const Scene& s) { return s.rough() && s.surface.mu > 0 ? s.push.force / (s.friction_limit()) : 0.0; }},
  };
  return q;
}

std::string status_text(Eigen::LevenbergMarquardtSpace::Status s, bool& converged) {
  using namespace Eigen::LevenbergMarquardtSpace;
  converged = false;
  switch (s) {
    case RelativeReductionTooSmall: converged = true; return "converged: relative reduction of chi2 below ftol";
    case RelativeErrorTooSmall: converged = true; return "converged: relative step below xtol";
    case RelativeErrorAndReductionTooSmall: converged = true; return "converged: relative step and reduction below xtol, ftol";
    case CosinusTooSmall: converged = true; return "converged: residuals orthogonal to the Jacobian's columns";
    case FtolTooSmall: converged = true; return "converged: no further reduction of chi2 possible (ftol at rounding)";
    case XtolTooSmall: converged = true; return "converged: no further improvement of the parameters possible (xtol at rounding)";
    case GtolTooSmall: converged = true; return "converged: gradient at rounding";
    case TooManyFunctionEvaluation: return "not converged: the evaluation limit was reached";
    case ImproperInputParameters: return "not converged: improper input parameters";
    case UserAsked: return "not converged: stopped";
    default: return "not converged: status " + std::to_string(static_cast<int>(s));
  }
}

struct Problem : Eigen::DenseFunctor<double> {
  const Scene& scene;
  const Observations& obs;
  const FitOptions& opt;
  std::optional<Law> law;
  Gradients gradients = Gradients::sensitivities;
  std::vector<double> c, lo, hi;  // parameter scales, bounds (in p)
  std::int64_t solves = 0, sens_solves = 0;
  bool eager = false;  // derivatives with every evaluation (sensitivities: no extra solve)
  struct Eval {
    Eigen::VectorXd u;
    ModelPoses m;
  };
  std::vector<Eval> cache;
  std::string last_error;
  bool jacobian_failed = false;

  Problem(const Scene& s, const Observations& o, const FitOptions& op, int nparam, int nvalues)
      : DenseFunctor<double>(nparam, nvalues), scene(s), obs(o), opt(op) {}

  [[nodiscard]] std::vector<double> params(const Eigen::VectorXd& u) const {
    std::vector<double> p(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) p[k] = std::clamp(u[static_cast<Eigen::Index>(k)] * c[k], lo[k], hi[k]);
    return p;
  }
  const ModelPoses* lookup(const Eigen::VectorXd& u, bool need_jac) const {
    for (const auto& e : cache)
      if (e.u == u && (!need_jac || !e.m.jac.empty())) return &e.m;
    return nullptr;
  }
  const ModelPoses& evaluate(const Eigen::VectorXd& u, bool need_jac) {
    if (const auto* m = lookup(u, need_jac)) return *m;
    const bool d = need_jac || eager;
    std::int64_t n = 0;
    ModelPoses m = model_poses(scene, opt.free, params(u), obs.t, law, opt.rtol, d, gradients, &n);
    solves += n;
    if (d && gradients == Gradients::sensitivities) ++sens_solves;
    if (cache.size() >= 4) cache.erase(cache.begin());
    cache.push_back({u, std::move(m)});
    return cache.back().m;
  }
  int operator()(const Eigen::VectorXd& u, Eigen::VectorXd& f) {
    try {
      const ModelPoses& m = evaluate(u, false);
      Eigen::Index r = 0;
      for (std::size_t i = 0; i < obs.t.size(); ++i)
        for (std::size_t j = 0; j < 3; ++j)
          if (obs.has[j]) {
            f[r++] = (m.pose[i][j] - obs.value[j][i]) / obs.sigma[j][i];
          }
    } catch (const InputError& e) {  // a trial point the scene refuses: an infinitely bad point
      last_error = e.what();
      f.setConstant(1e150);
    } catch (const SolverError& e) {
      last_error = e.what();
      f.setConstant(1e150);
    }
    return 0;
  }
  int df(const Eigen::VectorXd& u, Eigen::MatrixXd& J) {
    const ModelPoses* mp = nullptr;
    try {
      mp = &evaluate(u, true);
    } catch (const SolverError& e) {
      last_error = e.what();
      jacobian_failed = true;
      return -1;
    } catch (const InputError& e) {
      last_error = e.what();
      jacobian_failed = true;
      return -1;
    }
    const ModelPoses& m = *mp;
    Eigen::Index r = 0;
    for (std::size_t i = 0; i < obs.t.size(); ++i)
      for (std::size_t j = 0; j < 3; ++j)
        if (obs.has[j]) {
          for (std::size_t k = 0; k < c.size(); ++k) {
            const double p = u[static_cast<Eigen::Index>(k)] * c[k];
            const bool clamped = p < lo[k] || p > hi[k];
            J(r, static_cast<Eigen::Index>(k)) = clamped ? 0.0 : m.jac[i][k][j] * c[k] / obs.sigma[j][i];
          }
          ++r;
        }
    return 0;
  }
};

}  // namespace

namespace {

/// The options' checks and the gradients to use (auto: sensitivities where the right-hand
/// side is smooth, differences under the coulomb law).
Gradients checked_gradients(const Scene& scene, const FitOptions& options, Law law) {
  if (options.free.empty()) throw InputError("--free", "(none)", "name at least one scene key to fit");
  for (std::size_t k = 0; k < options.free.size(); ++k)
    for (std::size_t j = 0; j < k; ++j)
      if (options.free[k] == options.free[j]) throw InputError("--free", options.free[k], "named twice");
  require_range("rtol", options.rtol, 1e-14, 1e-3);
  if (options.max_evaluations < 1 || options.max_evaluations > 100000)
    throw InputError("max_evaluations", std::to_string(options.max_evaluations), "must be in [1, 100000]");
  require_range("xtol", options.xtol, 0, 1);
  require_range("ftol", options.ftol, 0, 1);
  require_range("identifiability_threshold", options.identifiability_threshold, 0, 1);
  const bool coulomb = scene.rough() && law == Law::coulomb;
  Gradients gradients = options.gradients;
  if (gradients == Gradients::automatic) gradients = coulomb ? Gradients::differences : Gradients::sensitivities;
  if (coulomb && gradients == Gradients::sensitivities)
    throw InputError("gradients", "sensitivities",
                     "the coulomb law's right-hand side jumps at its rest events: use differences (or auto)");
  return gradients;
}

/// The start point in scaled parameters u = p / c, the bounds and scales into prob, the
/// parameters' entries of res (key, unit, start, bounds).
Eigen::VectorXd start_point(const Scene& scene, const FitOptions& options, Problem& prob, FitResult& res) {
  const std::size_t np = options.free.size();
  Eigen::VectorXd u(static_cast<Eigen::Index>(np));
  for (std::size_t k = 0; k < np; ++k) {
    const std::string& key = options.free[k];
    const double start = detail::key_value(scene, key);
    // The key must be settable on this scene (a smooth scene has no surface.mu).
    (void)detail::scene_at(scene, {key}, {start});
    auto b = key_bounds(key, start);
    if (auto it = options.bounds.find(key); it != options.bounds.end()) b = it->second;
    if (!(b[0] <= start && start <= b[1]))
      throw InputError(key, fmt(start), "the start value lies outside the bounds [" + fmt(b[0]) + ", " + fmt(b[1]) + "]");
    prob.c.push_back(detail::parameter_scale(scene, key, start));
    prob.lo.push_back(b[0]);
    prob.hi.push_back(b[1]);
    u[static_cast<Eigen::Index>(k)] = start / prob.c.back();
    ParameterEstimate pe;
    pe.key = key;
    pe.unit = std::string(find_scene_key(key)->unit);
    pe.start = start;
    pe.lower = b[0];
    pe.upper = b[1];
    res.parameters.push_back(pe);
  }
  return u;
}

/// Residuals, chi2 and the weighted Jacobian w.r.t. relative parameters (scales crel) at the
/// estimate.
Eigen::MatrixXd residuals_and_jacobian(const Observations& obs, const ModelPoses& mp, const std::vector<double>& crel,
                                       int m, FitResult& res) {
  const std::size_t np = crel.size();
  res.t = obs.t;
  res.fitted = mp.pose;
  res.residuals.assign(obs.t.size(), {kNaN, kNaN, kNaN});
  Eigen::MatrixXd J(m, static_cast<Eigen::Index>(np));  // weighted, w.r.t. relative parameters
  {
    Eigen::Index r = 0;
    for (std::size_t i = 0; i < obs.t.size(); ++i)
      for (std::size_t j = 0; j < 3; ++j)
        if (obs.has[j]) {
          const double rr = (obs.value[j][i] - mp.pose[i][j]) / obs.sigma[j][i];
          res.residuals[i][j] = rr;
          res.chi2 += rr * rr;
          for (std::size_t k = 0; k < np; ++k) J(r, static_cast<Eigen::Index>(k)) = mp.jac[i][k][j] * crel[k] / obs.sigma[j][i];
          ++r;
        }
  }
  return J;
}

/// The singular value decomposition of the scaled Jacobian and what it determines.
struct Svd {
  Eigen::VectorXd S;
  Eigen::MatrixXd V;
  std::vector<Eigen::Index> det, null;  // singular directions above / below the threshold
  Eigen::MatrixXd cov_q;                // covariance of the relative parameters on det
  std::vector<bool> undetermined;
};

/// Identifiability: singular values, the covariance on the determined directions, standard
/// errors and correlations into res.
Svd identifiability(const Eigen::MatrixXd& J, const FitOptions& options, const std::vector<double>& crel, FitResult& res) {
  const std::size_t np = crel.size();
  Svd out;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinV);
  out.S = svd.singularValues();
  out.V = svd.matrixV();
  const Eigen::VectorXd& S = out.S;
  const Eigen::MatrixXd& V = out.V;
  Identifiability& id = res.identifiability;
  id.singular_values.assign(S.data(), S.data() + S.size());
  const double smax = S.size() ? S[0] : 0.0;
  id.condition = S.size() && S[S.size() - 1] > 0 ? smax / S[S.size() - 1] : std::numeric_limits<double>::infinity();
  std::vector<Eigen::Index>& det = out.det;
  std::vector<Eigen::Index>& null = out.null;
  for (Eigen::Index i = 0; i < S.size(); ++i)
    (smax > 0 && S[i] > options.identifiability_threshold * smax ? det : null).push_back(i);
  Eigen::MatrixXd& cov_q = out.cov_q;
  cov_q = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(np), static_cast<Eigen::Index>(np));
  for (Eigen::Index i : det) cov_q += V.col(i) * V.col(i).transpose() / (S[i] * S[i]);
  std::vector<bool>& undetermined = out.undetermined;
  undetermined.assign(np, false);
  for (Eigen::Index i : null)
    for (std::size_t k = 0; k < np; ++k)
      if (std::abs(V(static_cast<Eigen::Index>(k), i)) > 1e-3) undetermined[k] = true;
  for (std::size_t k = 0; k < np; ++k)
    if (undetermined[k]) id.undetermined.push_back(options.free[k]);
  id.identifiable = id.undetermined.empty();
  for (std::size_t k = 0; k < np; ++k) {
    const auto kk = static_cast<Eigen::Index>(k);
    res.parameters[k].stderr_ = undetermined[k] ? kNaN : std::sqrt(cov_q(kk, kk)) * crel[k];
  }
  res.correlation.assign(np, std::vector<double>(np, kNaN));
  for (std::size_t a = 0; a < np; ++a)
    for (std::size_t b = 0; b < np; ++b) {
      if (undetermined[a] || undetermined[b]) continue;
      const auto ia = static_cast<Eigen::Index>(a), ib = static_cast<Eigen::Index>(b);
      const double d = std::sqrt(cov_q(ia, ia) * cov_q(ib, ib));
      res.correlation[a][b] = d > 0 ? cov_q(ia, ib) / d : (a == b ? 1.0 : kNaN);
    }
  return out;
}

/// Not identifiable: what the data do determine (named quantities whose ln-gradient is
/// orthogonal to every undetermined direction, e.g. mu*N, else power products from the SVD),
/// and the message.
void explain_undetermined(const Scene& scene, const FitOptions& options, const std::vector<double>& p,
                          const std::vector<double>& crel, const Svd& svd, FitResult& res) {
  const std::size_t np = p.size();
  Identifiability& id = res.identifiability;
  const Eigen::MatrixXd& V = svd.V;
  const std::vector<Eigen::Index>& det = svd.det;
  const std::vector<Eigen::Index>& null = svd.null;
  const Eigen::MatrixXd& cov_q = svd.cov_q;
  const std::vector<bool>& undetermined = svd.undetermined;
  auto ln_gradient = [&](const Quantity& q) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(np));
    const double q0 = q.value(res.scene);
    if (!(q0 > 0) || !std::isfinite(q0)) return g;
    for (std::size_t k = 0; k < np; ++k) {
      auto pp = p, pm = p;
      const double h = 1e-6 * crel[k];
      pp[k] += h;
      pm[k] -= h;
      try {
        const double a = q.value(detail::scene_at(scene, options.free, pp));
        const double b = q.value(detail::scene_at(scene, options.free, pm));
        g[static_cast<Eigen::Index>(k)] = (std::log(a) - std::log(b)) / (2e-6);
      } catch (const InputError&) {
        g[static_cast<Eigen::Index>(k)] = kNaN;
      }
    }
    return g;
  };
  std::vector<Eigen::VectorXd> named;
  for (const Quantity& q : quantities()) {
    const Eigen::VectorXd g = ln_gradient(q);
    if (!g.allFinite() || g.norm() == 0) continue;
    bool touches = false, orthogonal = true;
    for (std::size_t k = 0; k < np; ++k)
      if (undetermined[k] && std::abs(g[static_cast<Eigen::Index>(k)]) > 1e-3 * g.norm()) touches = true;
    for (Eigen::Index i : null)
      if (std::abs(g.dot(V.col(i))) > 1e-3 * g.norm()) orthogonal = false;
    if (!touches || !orthogonal) continue;
    // One name per direction: with the other factors fixed, mu*N/m is mu*N again.
    bool same = false;
    for (const Eigen::VectorXd& h : named)
      if (std::abs(std::abs(h.dot(g)) - h.norm() * g.norm()) < 1e-6 * h.norm() * g.norm()) same = true;
    if (same) continue;
    named.push_back(g);
    Combination cb;
    cb.name = q.name;
    for (std::size_t k = 0; k < np; ++k)
      if (std::abs(g[static_cast<Eigen::Index>(k)]) > 1e-6) cb.exponents.emplace_back(options.free[k], g[static_cast<Eigen::Index>(k)]);
    cb.value = q.value(res.scene);
    cb.stderr_relative = std::sqrt(g.dot(cov_q * g));
    id.determined.push_back(cb);
  }
  if (id.determined.empty()) {
    // Power products: the directions of the determined subspace restricted to the
    // undetermined keys (exponents scaled so the largest is 1).
    for (Eigen::Index i : det) {
      Eigen::VectorXd w = V.col(i);
      bool touches = false;
      for (std::size_t k = 0; k < np; ++k)
        if (undetermined[k] && std::abs(w[static_cast<Eigen::Index>(k)]) > 1e-3) touches = true;
      if (!touches) continue;
      Eigen::Index imax = 0;
      w.cwiseAbs().maxCoeff(&imax);
      w /= w[imax];
      Combination cb;
      double lnv = 0;
      std::ostringstream name;
      for (std::size_t k = 0; k < np; ++k) {
        const double e = w[static_cast<Eigen::Index>(k)];
        if (std::abs(e) < 1e-3) continue;
        cb.exponents.emplace_back(options.free[k], e);
        if (!cb.name.empty()) name << " * ";
        name << options.free[k] << "^" << std::setprecision(4) << e;
        cb.name = name.str();
        lnv += e * std::log(std::abs(p[k]));
      }
      cb.value = std::exp(lnv);
      cb.stderr_relative = std::sqrt(w.dot(cov_q * w));
      id.determined.push_back(cb);
    }
  }
  std::ostringstream msg;
  for (std::size_t k = 0; k < id.undetermined.size(); ++k)
    msg << (k == 0 ? "" : k + 1 == id.undetermined.size() ? " and " : ", ") << id.undetermined[k];
  msg << (id.undetermined.size() == 1 ? " is" : " are") << " not determined separately by these data";
  if (!id.determined.empty()) {
    msg << "; they determine only ";
    for (std::size_t k = 0; k < id.determined.size(); ++k)
      msg << (k ? ", " : "") << id.determined[k].name << " = " << std::setprecision(6) << id.determined[k].value
          << " (relative stderr " << std::setprecision(3) << id.determined[k].stderr_relative << ")";
  }
  msg << ". No separate standard errors are given for them; fix all but one (--set) or add data that separate them.";
  id.message = msg.str();
}

}  // namespace

FitResult fit_trajectory(const Scene& scene, const Observations& obs, const FitOptions& options_in) {
  const auto t0 = std::chrono::steady_clock::now();
  const Law law = detail::fit_law(scene, options_in.law);
  FitOptions options = options_in;
  const Gradients gradients = checked_gradients(scene, options, law);
  check_observations(obs, scene, options.free.size());
  FitAccuracy accuracy;
  if (options.accuracy < 0) options.accuracy = scene.solver.accuracy;
  if (options.accuracy != 0) {
    accuracy = choose_forward_rtol(scene, obs.t, law, options.accuracy);
    options.rtol = accuracy.rtol_used;
  }

  const std::size_t np = options.free.size();
  const auto m = static_cast<int>(obs.count());
  Problem prob(scene, obs, options, static_cast<int>(np), m);
  prob.law = law;
  prob.gradients = gradients;
  prob.eager = gradients == Gradients::sensitivities;
  FitResult res;
  res.gradients = gradients;
  res.law = scene.rough() ? to_string(law) : "";
  res.accuracy = accuracy;
  Eigen::VectorXd u = start_point(scene, options, prob, res);
  // The start must run: its failure is the user's to see, not a point to step away from.
  (void)prob.evaluate(u, false);

  Eigen::LevenbergMarquardt<Problem> lm(prob);
  lm.setXtol(options.xtol);
  lm.setFtol(options.ftol);
  lm.setMaxfev(options.max_evaluations);
  const auto status = lm.minimize(u);
  res.status = prob.jacobian_failed ? "not converged: the Jacobian could not be computed" : status_text(status, res.converged);
  res.iterations = static_cast<int>(lm.iterations());

  const std::vector<double> p = prob.params(u);
  for (std::size_t k = 0; k < np; ++k) {
    res.parameters[k].value = p[k];
    res.parameters[k].at_bound = p[k] <= prob.lo[k] || p[k] >= prob.hi[k];
  }
  // The model and the Jacobian at the estimate (a failure here is the fit's: reported).
  const ModelPoses& mp = [&]() -> const ModelPoses& {
    try {
      return prob.evaluate(u, true);
    } catch (const SolverError& e) {
      throw SolverError(std::string("fit: the Jacobian at the last parameters failed (") + e.what() + ")");
    }
  }();
  std::vector<double> crel(np);
  for (std::size_t k = 0; k < np; ++k) crel[k] = detail::parameter_scale(scene, options.free[k], p[k]);
  const Eigen::MatrixXd J = residuals_and_jacobian(obs, mp, crel, m, res);
  // chi2 beyond a double (data 1e308 with sigma 1e-300) or NaN is no fit, whatever the
  // minimiser's status said: a failure (exit 3), never "converged".
  if (!std::isfinite(res.chi2)) {
    res.converged = false;
    res.status = "not converged: chi2 = " + fmt(res.chi2) +
                 " is not finite: the weighted residuals (data - model) / sigma overflow a double; check the data's "
                 "values and sigmas";
  }
  res.dof = static_cast<long>(m) - static_cast<long>(np);
  res.chi2_dof = res.chi2 / static_cast<double>(res.dof);
  res.scene = detail::scene_at(scene, options.free, p);

  const Svd svd = identifiability(J, options, crel, res);
  if (!res.identifiability.identifiable) explain_undetermined(scene, options, p, crel, svd, res);
  if (accuracy.requested > 0) {  // the accuracy at the estimate, where the answer is
    res.accuracy.estimate = forward_error(res.scene, obs.t, law, options.rtol);
    res.accuracy.reached = res.accuracy.estimate <= accuracy.requested;
  }
  res.n_forward_solves = prob.solves;
  res.n_sensitivity_solves = prob.sens_solves;
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!res.converged && !prob.last_error.empty()) res.status += " (last refused point: " + prob.last_error + ")";
  return res;
}

std::string fit_json(const FitResult& r) {
  json params = json::object();
  for (const auto& p : r.parameters)
    params[p.key] = {{"value", json_number(p.value)}, {"stderr", json_number(p.stderr_)}, {"unit", p.unit}, {"start", json_number(p.start)},
                     {"lower", json_number(p.lower)}, {"upper", json_number(p.upper)}, {"at_bound", p.at_bound}};
  json correlation = json::array();
  for (const auto& row : r.correlation) {
    json jr = json::array();
    for (double c : row) jr.push_back(json_number(c));
    correlation.push_back(std::move(jr));
  }
  json doc = {{"parameters", std::move(params)},
              {"correlation", std::move(correlation)},
              {"chi2", json_number(r.chi2)},
              {"chi2_dof", json_number(r.chi2_dof)},
              {"dof", r.dof},
              {"converged", r.converged},
              {"status", r.status},
              {"iterations", r.iterations},
              {"n_forward_solves", r.n_forward_solves},
              {"n_sensitivity_solves", r.n_sensitivity_solves},
              {"gradients", to_string(r.gradients)},
              {"law", r.law},
              {"n_observations", r.t.size()}};
  if (r.accuracy.requested > 0)
    doc["accuracy"] = {{"requested", json_number(r.accuracy.requested)},
                       {"rtol_used", json_number(r.accuracy.rtol_used)},
                       {"estimate", json_number(r.accuracy.estimate)},
                       {"reached", r.accuracy.reached}};
  const auto& id = r.identifiability;
  json sv = json::array(), determined = json::array();
  for (double v : id.singular_values) sv.push_back(json_number(v));
  for (const auto& c : id.determined) {
    json ex = json::object();
    for (const auto& [name, e] : c.exponents) ex[name] = json_number(e);
    determined.push_back(
        {{"name", c.name}, {"value", json_number(c.value)}, {"stderr_relative", json_number(c.stderr_relative)}, {"exponents", ex}});
  }
  doc["identifiability"] = {{"identifiable", id.identifiable}, {"condition", json_number(id.condition)},
                            {"singular_values", std::move(sv)}, {"undetermined", id.undetermined},
                            {"determined", std::move(determined)}, {"message", id.message}};
  return json_text(doc);
}

}  // namespace nanopush::fit
