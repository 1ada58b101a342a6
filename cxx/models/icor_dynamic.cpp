#include "nanopush/models/icor_dynamic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "nanopush/numerics/error.hpp"
#include "nanopush/models/friction.hpp"
#include "nanopush/models/rough_bar.hpp"
#include "nanopush/models/stick_slip.hpp"
#include "nanopush/models/surface_forces.hpp"

namespace nanopush::icor {

double rod_contact_half_width(const Rod& rod) {
  rod.validate();
  const auto g = forces::find_material("graphite");
  if (!g) throw SolverError("the built-in material table has no graphite");
  const double Es = forces::effective_modulus(g->youngs_modulus, g->poisson_ratio, g->youngs_modulus, g->poisson_ratio);
  return forces::hertz_line_half_width(rod.radius, Es, rod.load() / rod.length);
}

DynamicIntegrator parse_dynamic_integrator(const std::string& field, const std::string& text) {
  // "bulirsch_stoer" too: Python's keyword spelling.
  return parse_choice<DynamicIntegrator>(field, text == "bulirsch_stoer" ? "bulirsch-stoer" : text);
}

std::string to_string(DynamicIntegrator i) { return std::string(name_of(i)); }

QuasiStaticIcor rectangle_quasi_static(double a, double b, double yn) {
  require_positive("a", a, "m");
  require_positive("b", b, "m");
  require_range("yn", yn, 0.0, b, "m; the push line crosses the rectangle: at most b");
  if (a < kFrictionMinAspect * b || b < kFrictionMinAspect * a)
    throw InputError("a/b", fmt(a / b), "aspect ratio must lie within [1e-6, 1e6]");
  if (yn == 0.0) {  // a push through the CM translates the rectangle: R = infinity
    QuasiStaticIcor q;
    q.R = std::numeric_limits<double>::infinity();
    q.alpha = M_PI / 2;
    q.force = 1.0;
    q.omega_sign = 0;
    q.converged = true;
    return q;
  }
  auto wrench = [a, b](double R, double alpha) {
    const FrictionWrench w = rectangle_friction_wrench(a, b, 1.0, R, alpha, +1);
    return Wrench{w.fx, w.fy, w.mf};
  };
  // Start from the line-contact answer (eq 4.13), on the far side of the CM (alpha = pi/2
  // puts the iCOR at (0, -R)).
  const double R0 = unknown_pressure(yn, 2.0 * b);
  return quasi_static_icor(wrench, 0.0, yn, 1.0, 0.0, R0, M_PI / 2, std::max(a, b));
}

namespace {
/// `integrate` with the integrator asked, or under automatic the one suited to the push and
/// the other if it fails: CVODE near the minimum force (the slow start is stiff), else
/// Bulirsch-Stoer.
template <class Integrate>
StickSlipResult integrate_either(const Integrate& integrate, const DynamicIcorSetup& s, double minimum_force) {
  if (s.integrator != DynamicIntegrator::automatic) return integrate(s.integrator);
#ifdef NANOPUSH_HAVE_SUNDIALS
  const bool near_min = s.force < 1.09 * minimum_force;
#else
  const bool near_min = false;
  (void)minimum_force;
#endif
  const DynamicIntegrator first = near_min ? DynamicIntegrator::cvode : DynamicIntegrator::bulirsch_stoer;
  const DynamicIntegrator second = near_min ? DynamicIntegrator::bulirsch_stoer : DynamicIntegrator::cvode;
  try {
    return integrate(first);
  } catch (const SolverError&) {
#ifdef NANOPUSH_HAVE_SUNDIALS
    return integrate(second);
#else
    (void)second;
    throw;
#endif
  }
}

}  // namespace

DynamicIcorRun dynamic_icor(const DynamicIcorSetup& s) {
  s.rod.validate();
  require_positive("mu", s.mu);
  require_nonnegative("half-width", s.half_width, "m");
  require_range("yn", s.yn, 0.0, s.rod.half_length(), "m; push point on the rod, at most b = L/2");
  require_positive("force", s.force, "N");
  require_range("rtol", s.rtol, 1e-14, 1e-3);
  if (s.times.empty()) throw InputError("times", "(none)", "give at least one output time");
  double prev = 0.0;
  for (double t : s.times) {
    require_positive("time", t, "s");
    if (!(t >= prev)) throw InputError("time", fmt(t), "output times must be ascending");
    prev = t;
  }
  const double b = s.rod.half_length();
  const double a = s.half_width > 0.0 ? s.half_width : rod_contact_half_width(s.rod);
  if (a < kFrictionMinAspect * b || a > b)
    throw InputError("half-width", fmt(a), "must lie within [1e-6 b, b] (b = " + fmt(b) + " m)");

  DynamicIcorRun run;
  run.load = s.rod.load();
  run.half_width = a;
  RoughBarModel model;
  model.mass = s.rod.mass();
  model.inertia = s.rod.inertia();
  model.geometry = {a, b};
  model.muN = s.mu * run.load;
  model.push = Push{s.force, 0.0, 0.0, s.yn};

  // Absolute tolerances from the scales of a frictionless push over the whole span, 1e-3 of
  // rtol times each: the tolerances stay far below the motion even close to the minimum force.
  const double T = s.times.back(), F = s.force, m = model.mass, I = model.inertia;
  const double lever = std::max(s.yn, a);
  const double v_s = F * T / m, x_s = v_s * T, w_s = F * lever * T / I, th_s = w_s * T;
  const double e_s = F * x_s + F * lever * th_s;
  const double k = 1e-3 * s.rtol;
  std::vector<double> atol = {k * x_s, k * x_s, k * th_s, k * v_s, k * v_s, k * w_s, k * e_s, k * e_s};
  auto options = BsOptions<double>::faithful(s.rtol, atol);
  options.maxstp = 200000;

  run.minimum_force = rectangle_quasi_static(a, b, s.yn).force * model.muN;
  std::array<double, kRoughStateSize> y0{};
  auto integrate = [&](DynamicIntegrator which) {
    run.samples.clear();
    run.integrator = which;
    auto observe = [&](double t, const double* y, const WorldWrench&) {
      DynamicIcorSample q{.t = t, .theta = y[kTheta], .vx = y[kVx], .vy = y[kVy], .omega = y[kOmega]};
      q.moving = !(y[kVx] == 0.0 && y[kVy] == 0.0 && y[kOmega] == 0.0);
      if (q.moving) {
        const VelocityIcor c = icor_from_velocity(y[kVx], y[kVy], y[kOmega]);
        q.translation = c.translation;
        q.R = c.R;
        if (c.translation) {
          q.axial = std::numeric_limits<double>::infinity();
        } else {
          const double ct = std::cos(q.theta), st = std::sin(q.theta);
          q.offset = ct * c.cx + st * c.cy;     // body x'
          q.axial = -(-st * c.cx + ct * c.cy);  // -(body y')
        }
      }
      run.samples.push_back(q);
    };
    if (which == DynamicIntegrator::cvode) {
#ifdef NANOPUSH_HAVE_SUNDIALS
      return integrate_coulomb_cvode(model, s.rtol, atol, y0.data(), s.times, observe);
#else
      throw InputError("integrator", "cvode", "this build has no SUNDIALS; use bulirsch-stoer");
#endif
    }
    return integrate_coulomb(model, options, y0.data(), s.times, observe);
  };
  StickSlipResult r;
  try {
    r = integrate_either(integrate, s, run.minimum_force);
  } catch (const SolverError& e) {  // say which run failed: the caller's times and push
    throw SolverError("the dynamic iCOR (F = " + fmt(s.force) + " N at yn = " + fmt(s.yn) + " m, outputs to t = " +
                          fmt(s.times.empty() ? 0.0 : s.times.back()) + " s): " + e.what(),
                      e.outcome());
  }
  run.stuck = !r.events.empty() && r.events.front().t == 0.0 && r.events.front().stuck;
  run.rhs_evaluations = r.stats.nfcn;
  return run;
}

}  // namespace nanopush::icor
