// The quasi-static tip-driven push (tip_push.hpp; docs/tip.md).
#include "nanopush/models/tip_push.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <limits>

#include "nanopush/models/friction.hpp"
#include "nanopush/numerics/dop853.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/numerics/regula_falsi.hpp"
#include "tip_format.hpp"

namespace nanopush::tip {

namespace {

using detail::fmt;

/// Surface friction wrench and dissipation rate D = -f.V at a body twist.
struct Dissipation {
  FrictionWrench f{0, 0, 0};
  double D = 0;
};
Dissipation dissipation(const BarGeometry& g, double muN, double vx, double vy, double omega) {
  Dissipation d;
  d.f = rectangle_friction_from_velocity(g.a, g.b, muN, vx, vy, omega);
  d.D = -(d.f.fx * vx + d.f.fy * vy + d.f.mf * omega);
  return d;
}

/// Sticking tip: the contact point moves with the tip, V(omega) = (ux + omega py, uy - omega px,
/// omega); dD/domega = -(fx py - fy px + mf) is non-decreasing (D convex): its zero.
QuasiStaticTwist stick_solution(const BarGeometry& g, double muN, const ContactGeometry& c, double ux, double uy) {
  const double px = c.px, py = c.py;
  auto V = [&](double w) { return std::array<double, 3>{ux + w * py, uy - w * px, w}; };
  auto slope = [&](double w) {
    const auto v = V(w);
    const FrictionWrench f = rectangle_friction_from_velocity(g.a, g.b, muN, v[0], v[1], v[2]);
    return -(f.fx * py - f.fy * px + f.mf);
  };
  const double ell = std::max(g.a, g.b);
  double w = std::hypot(ux, uy) / ell;
  double lo = -w, hi = w, glo = slope(lo), ghi = slope(hi);
  int expand = 0;
  while (glo > 0 && expand < 60) {
    hi = lo;
    ghi = glo;
    lo *= 4;
    glo = slope(lo);
    ++expand;
  }
  while (ghi < 0 && expand < 120) {
    lo = hi;
    glo = ghi;
    hi *= 4;
    ghi = slope(hi);
    ++expand;
  }
  double omega = 0;
  std::uintmax_t iters = 200;
  if (glo == 0) {
    omega = lo;
  } else if (ghi == 0) {
    omega = hi;
  } else if (glo < 0 && ghi > 0) {
    const auto r = boost::math::tools::toms748_solve(slope, lo, hi, glo, ghi,
                                                     boost::math::tools::eps_tolerance<double>(52), iters);
    omega = 0.5 * (r.first + r.second);
  } else {
    omega = glo > 0 ? lo : hi;  // the slope never changes sign: the minimum is at the end
  }
  const auto v = V(omega);
  const Dissipation d = dissipation(g, muN, v[0], v[1], v[2]);
  QuasiStaticTwist q;
  q.mode = ContactMode::stick;
  q.vx = v[0];
  q.vy = v[1];
  q.omega = v[2];
  q.fx = -d.f.fx;
  q.fy = -d.f.fy;
  q.px = px;
  q.py = py;
  q.dissipation = d.D;
  q.residual = muN > 0 ? std::fabs(d.f.fx * py - d.f.fy * px + d.f.mf) / (muN * ell) : 0.0;
  q.iterations = static_cast<int>(iters) + expand;
  return q;
}

/// Known force direction e (unit, body axes) at the contact point: minimise D on the plane
/// w.V = 1 (scaled coordinates V~ = (vx, vy, omega ell)) by Newton's method with a
/// finite-difference Hessian of the analytic gradient -f~ and backtracking; returns the unit-power
/// twist (v_p.e = 1) and lambda = D there (the force magnitude per unit power).
struct PlaneMinimum {
  std::array<double, 3> V{};
  double lambda = 0;
  double residual = 0;
  int iterations = 0;
  bool converged = false;
};
PlaneMinimum minimise_on_plane(const BarGeometry& g, double muN, double px, double py, double ex, double ey) {
  const double ell = std::max(g.a, g.b);
  const std::array<double, 3> w{ex, ey, (px * ey - py * ex) / ell};
  const double w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  const std::array<double, 3> V0{w[0] / w2, w[1] / w2, w[2] / w2};
  // An orthonormal basis of the plane's directions (perpendicular to w).
  const double wn = std::sqrt(w2);
  const std::array<double, 3> u{w[0] / wn, w[1] / wn, w[2] / wn};
  std::array<double, 3> e1 = std::fabs(u[2]) < 0.9 ? std::array<double, 3>{-u[1], u[0], 0.0}
                                                    : std::array<double, 3>{0.0, -u[2], u[1]};
  const double n1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (double& x : e1) x /= n1;
  const std::array<double, 3> e2{u[1] * e1[2] - u[2] * e1[1], u[2] * e1[0] - u[0] * e1[2], u[0] * e1[1] - u[1] * e1[0]};
  auto point = [&](double s1, double s2) {
    std::array<double, 3> v{};
    for (int i = 0; i < 3; ++i) v[i] = V0[i] + s1 * e1[i] + s2 * e2[i];
    return v;
  };
  struct Eval {
    double D;
    double g1, g2;
  };
  auto eval = [&](double s1, double s2) {
    const auto v = point(s1, s2);
    const Dissipation d = dissipation(g, muN, v[0], v[1], v[2] / ell);
    const std::array<double, 3> ft{d.f.fx, d.f.fy, d.f.mf / ell};
    return Eval{d.D, -(ft[0] * e1[0] + ft[1] * e1[1] + ft[2] * e1[2]), -(ft[0] * e2[0] + ft[1] * e2[1] + ft[2] * e2[2])};
  };
  double s1 = 0, s2 = 0;
  Eval cur = eval(s1, s2);
  PlaneMinimum out;
  const double gtol = 1e-12 * muN;
  for (int it = 0; it < 200; ++it) {
    out.iterations = it;
    const double gnorm = std::hypot(cur.g1, cur.g2);
    if (gnorm <= gtol) {
      out.converged = true;
      break;
    }
    const double scale = 1.0 + std::hypot(s1, s2);
    const double h = 1e-7 * scale;
    const Eval a = eval(s1 + h, s2), b = eval(s1 - h, s2), c = eval(s1, s2 + h), d = eval(s1, s2 - h);
    double H11 = (a.g1 - b.g1) / (2 * h), H22 = (c.g2 - d.g2) / (2 * h);
    const double H12 = 0.25 * ((a.g2 - b.g2) + (c.g1 - d.g1)) / h;
    const double det = H11 * H22 - H12 * H12;
    double d1, d2;
    if (H11 > 0 && H22 > 0 && det > 0) {
      d1 = -(H22 * cur.g1 - H12 * cur.g2) / det;
      d2 = -(-H12 * cur.g1 + H11 * cur.g2) / det;
    } else {  // not convex enough here: a gradient step of the problem's own scale
      d1 = -cur.g1 / muN * scale;
      d2 = -cur.g2 / muN * scale;
    }
    // Backtracking: a step is taken when it decreases D (Armijo) or, near the minimum where
    // D's decrease is below its rounding, when it shrinks the gradient without raising D
    // beyond rounding. A step that can do neither ends the search.
    double step = 1.0;
    bool moved = false;
    const double slope0 = cur.g1 * d1 + cur.g2 * d2;
    const double D_noise = 64 * std::numeric_limits<double>::epsilon() * std::fabs(cur.D);
    for (int k = 0; k < 60; ++k) {
      const Eval trial = eval(s1 + step * d1, s2 + step * d2);
      if (trial.D <= cur.D + 1e-4 * step * std::min(slope0, 0.0) ||
          (trial.D <= cur.D + D_noise && std::hypot(trial.g1, trial.g2) < 0.9 * gnorm)) {
        s1 += step * d1;
        s2 += step * d2;
        cur = trial;
        moved = true;
        break;
      }
      step *= 0.5;
    }
    if (!moved) {
      out.converged = std::hypot(cur.g1, cur.g2) <= 1e-9 * muN;
      break;
    }
  }
  const auto v = point(s1, s2);
  out.V = {v[0], v[1], v[2] / ell};
  out.lambda = cur.D;
  out.residual = muN > 0 ? std::hypot(cur.g1, cur.g2) / muN : 0.0;
  return out;
}

}  // namespace

std::array<double, 2> TipPath::centre(double t) const {
  const double s = speed * std::clamp(t, 0.0, t_stop());
  return {start_x + s * std::cos(direction), start_y + s * std::sin(direction)};
}

std::array<double, 2> TipPath::velocity(double t) const {
  if (t < 0 || t >= t_stop()) return {0.0, 0.0};
  return {speed * std::cos(direction), speed * std::sin(direction)};
}

void TipPath::validate() const {
  require_positive("tip.radius", radius, "m");
  require_finite_point("tip.start", start_x, start_y, "m");
  require_finite("tip.direction", direction, "rad");
  require_positive("tip.speed", speed, "m/s");
  require_positive("tip.travel", travel, "m");
  require_range("tip.mu", mu, 0.0, 10.0);
  if (!std::isfinite(t_stop()) || t_stop() <= 0)
    throw InputError("tip.travel / tip.speed", fmt(t_stop()), "the push's duration must be finite and > 0 (s)");
}

ContactGeometry contact_geometry(const BarGeometry& g, double qx, double qy) {
  ContactGeometry c;
  c.px = std::clamp(qx, -g.a, g.a);
  c.py = std::clamp(qy, -g.b, g.b);
  const double dx = qx - c.px, dy = qy - c.py;
  c.distance = std::hypot(dx, dy);
  if (c.distance == 0.0) {
    c.inside = true;
    return c;
  }
  c.nx = dx / c.distance;
  c.ny = dy / c.distance;
  return c;
}

const char* to_string(ContactMode m) {
  switch (m) {
    case ContactMode::none: return "none";
    case ContactMode::stick: return "stick";
    case ContactMode::slide: return "slide";
  }
  return "?";
}

QuasiStaticTwist quasi_static_twist(const BarGeometry& g, double muN, double tip_mu, const ContactGeometry& c, double ux,
                                    double uy) {
  QuasiStaticTwist none;
  none.px = c.px;
  none.py = c.py;
  const double un = ux * c.nx + uy * c.ny;  // < 0: the tip approaches the surface
  if (c.inside || !(un < 0) || muN <= 0) return none;
  const double tx = -c.ny, ty = c.nx;  // tangent
  double sigma = 0;                    // side of the friction cone the force lies on
  if (tip_mu > 0) {
    QuasiStaticTwist st = stick_solution(g, muN, c, ux, uy);
    const double Fn = -(st.fx * c.nx + st.fy * c.ny), Ft = st.fx * tx + st.fy * ty;
    if (Fn > 0 && std::fabs(Ft) <= tip_mu * Fn) return st;
    sigma = Ft >= 0 ? 1.0 : -1.0;
  }
  double ex = -c.nx + sigma * tip_mu * tx, ey = -c.ny + sigma * tip_mu * ty;
  const double en = std::hypot(ex, ey);
  ex /= en;
  ey /= en;
  const PlaneMinimum pm = minimise_on_plane(g, muN, c.px, c.py, ex, ey);
  if (!pm.converged)
    throw SolverError("quasi-static tip push: no equilibrium twist found at contact point (" + fmt(c.px) + ", " +
                      fmt(c.py) + ") m (balance residual " + fmt(pm.residual) + " of mu N)");
  // Scale the unit-power twist so that the contact point's normal velocity is the tip's.
  const double vpx = pm.V[0] - pm.V[2] * c.py, vpy = pm.V[1] + pm.V[2] * c.px;
  const double vpn = vpx * c.nx + vpy * c.ny;
  const double s = un / vpn;
  if (!(s > 0) || !std::isfinite(s))
    throw SolverError("quasi-static tip push: the equilibrium twist does not follow the tip (normal speed ratio " +
                      fmt(s) + ")");
  QuasiStaticTwist q;
  q.mode = ContactMode::slide;
  q.vx = s * pm.V[0];
  q.vy = s * pm.V[1];
  q.omega = s * pm.V[2];
  q.fx = pm.lambda * ex;
  q.fy = pm.lambda * ey;
  q.px = c.px;
  q.py = c.py;
  q.dissipation = s * pm.lambda;
  q.residual = pm.residual;
  q.iterations = pm.iterations;
  return q;
}

const std::vector<std::string>& tip_row_columns() {
  static const std::vector<std::string> c{"t",     "x",     "y",      "theta",  "vx",       "vy",
                                          "omega", "fx",    "fy",     "mf",     "tip_x",    "tip_y",
                                          "tip_fx", "tip_fy", "work_tip", "work_fric", "contact"};
  return c;
}
const std::vector<std::string>& tip_row_units() {
  static const std::vector<std::string> u{"s", "m", "m", "rad", "m/s", "m/s", "rad/s", "N", "N",
                                          "N m", "m", "m", "N", "N", "J", "J", "1"};
  return u;
}

namespace {

constexpr int kQsSize = 5;  // x, y, theta, W_tip, W_fric

/// Everything at one instant of the quasi-static push: the geometry, the twist in body axes and
/// the world quantities.
struct Instant {
  ContactGeometry c;
  QuasiStaticTwist q;
  double cth = 1, sth = 0;
  double un = 0;  ///< tip's normal velocity (< 0 approaching)
};

Instant instant(const BarGeometry& g, double muN, const TipPath& tip, double t, const double* y, bool moving) {
  Instant in;
  in.cth = std::cos(y[2]);
  in.sth = std::sin(y[2]);
  const auto q = tip.centre(t);
  const auto u = moving ? std::array<double, 2>{tip.speed * std::cos(tip.direction), tip.speed * std::sin(tip.direction)}
                        : tip.velocity(t);
  const double dx = q[0] - y[0], dy = q[1] - y[1];
  const double qbx = in.cth * dx + in.sth * dy, qby = -in.sth * dx + in.cth * dy;
  const double ubx = in.cth * u[0] + in.sth * u[1], uby = -in.sth * u[0] + in.cth * u[1];
  in.c = contact_geometry(g, qbx, qby);
  in.un = ubx * in.c.nx + uby * in.c.ny;
  in.q = quasi_static_twist(g, muN, tip.mu, in.c, ubx, uby);
  return in;
}

TipRow make_row(const BarGeometry& g, double muN, const TipPath& tip, double t, const double* y, const Instant* in) {
  TipRow r;
  r.t = t;
  r.x = y[0];
  r.y = y[1];
  r.theta = y[2];
  r.work_tip = y[3];
  r.work_fric = y[4];
  const auto q = tip.centre(t);
  r.tip_x = q[0];
  r.tip_y = q[1];
  if (in && in->q.mode != ContactMode::none) {
    const double c = in->cth, s = in->sth;
    r.vx = c * in->q.vx - s * in->q.vy;
    r.vy = s * in->q.vx + c * in->q.vy;
    r.omega = in->q.omega;
    r.tip_fx = c * in->q.fx - s * in->q.fy;
    r.tip_fy = s * in->q.fx + c * in->q.fy;
    const FrictionWrench f = rectangle_friction_from_velocity(g.a, g.b, muN, in->q.vx, in->q.vy, in->q.omega);
    r.fx = c * f.fx - s * f.fy;
    r.fy = s * f.fx + c * f.fy;
    r.mf = f.mf;
    r.contact = in->q.mode;
  }
  return r;
}

/// The first time in [0, t_path_end] the tip touches the bar (gap(t) <= 0, gap(0) = g0), or -1
/// when it does not. The gap is convex along the straight path: its minimum by golden section,
/// then the first zero before it by the Illinois method.
template <class Gap>
double first_contact(const Gap& gap, double g0, double t_path_end) {
  double t_contact = -1;
  if (g0 <= 0) {
    t_contact = 0;
  } else {
    double lo = 0, hi = t_path_end;
    const double phi = 0.5 * (std::sqrt(5.0) - 1);
    double c1 = hi - phi * (hi - lo), c2 = lo + phi * (hi - lo), f1 = gap(c1), f2 = gap(c2);
    for (int it = 0; it < 200 && hi - lo > 1e-15 * t_path_end; ++it) {
      if (f1 < f2) {
        hi = c2;
        c2 = c1;
        f2 = f1;
        c1 = hi - phi * (hi - lo);
        f1 = gap(c1);
      } else {
        lo = c1;
        c1 = c2;
        f1 = f2;
        c2 = lo + phi * (hi - lo);
        f2 = gap(c2);
      }
    }
    double tmin = 0.5 * (lo + hi);
    if (gap(t_path_end) < gap(tmin)) tmin = t_path_end;
    if (gap(tmin) <= 0) {
      double a = 0, b = tmin;
      double ga = g0, gb = gap(tmin);
      roots::illinois(a, b, ga, gb, 200, [&](double l, double h) { return h - l > 1e-15 * t_path_end; }, gap,
                      [](int) {});
      t_contact = b;
    }
  }
  return t_contact;
}

}  // namespace

TipRunResult run_quasi_static(const BarGeometry& g, double muN, const TipPath& tip, double x0, double y0,
                              double theta0, double t_end, int samples, double rtol) {
  tip.validate();
  if (!(g.a > 0 && g.b > 0)) throw InputError("object.width, object.length", fmt(2 * g.a) + ", " + fmt(2 * g.b), "must be > 0");
  if (!(muN > 0 && std::isfinite(muN))) throw InputError("surface.mu x normal load", fmt(muN), "must be > 0 for a quasi-static push (N)");
  if (samples < 2) throw InputError("solver.samples", std::to_string(samples), "must be >= 2");
  const double t_stop = tip.t_stop();
  if (!(t_end > 0)) t_end = t_stop;
  if (!std::isfinite(t_end)) throw InputError("solver.t_end", fmt(t_end), "must be finite (s)");
  if (!(rtol >= rtol_in_eps<double>(kDop853RtolEps) && rtol <= 1e-2))
    throw InputError("solver.rtol", fmt(rtol),
                     "must be in [" + fmt(rtol_in_eps<double>(kDop853RtolEps)) + ", 1e-2] for the quasi-static push");

  TipRunResult res;
  std::vector<double> tout(samples);
  for (int i = 0; i < samples; ++i) tout[i] = t_end * i / (samples - 1);
  tout.back() = t_end;
  res.rows.resize(samples);

  std::array<double, kQsSize> y{x0, y0, theta0, 0.0, 0.0};
  // Gap between the tip and the bar at rest in its initial pose, along the tip's path.
  const double cth = std::cos(theta0), sth = std::sin(theta0);
  auto gap = [&](double t) {
    const auto q = tip.centre(t);
    const double dx = q[0] - x0, dy = q[1] - y0;
    return contact_geometry(g, cth * dx + sth * dy, -sth * dx + cth * dy).distance - tip.radius;
  };
  const double ell = std::max(g.a, g.b);
  const double g0 = gap(0.0);
  if (g0 < -1e-9 * ell)
    throw InputError("tip.start", fmt_point(tip.start_x, tip.start_y),
                     "the tip (radius " + fmt(tip.radius) + " m) overlaps the bar at t = 0 by " + fmt(-g0) +
                         " m: start it outside the bar");
  const double t_path_end = std::min(t_stop, t_end);
  const double t_contact = first_contact(gap, g0, t_path_end);

  std::size_t next = 0;  // next output index
  auto rest_rows_until = [&](double t_limit, bool inclusive) {
    while (next < tout.size() && (tout[next] < t_limit || (inclusive && tout[next] <= t_limit))) {
      res.rows[next] = make_row(g, muN, tip, tout[next], y.data(), nullptr);
      ++next;
    }
  };
  if (t_contact < 0) {
    rest_rows_until(t_end, true);
    return res;
  }
  res.events.push_back({t_contact, "contact"});
  rest_rows_until(t_contact, false);

  // Quasi-static motion from t_contact while the tip moves and approaches the bar.
  const double t_seg_end = t_path_end;
  Dop853Options<double> opt;
  opt.rtol = rtol;
  opt.atol = {rtol * ell, rtol * ell, rtol, rtol * muN * ell, rtol * muN * ell};
  opt.maxstp = 1000000;
  bool failed = false;
  std::string fail_message;
  auto rhs = [&](double t, const double* s, double* d) -> int {
    ++res.nfcn;
    try {
      const Instant in = instant(g, muN, tip, t, s, true);
      if (in.c.inside) {  // a trial stage past the release (the tip's centre inside the bar): the
        // model does not hold there; NaN makes the integrator shrink the step (the hook then
        // locates the release inside the smaller one)
        for (int i = 0; i < kQsSize; ++i) d[i] = std::numeric_limits<double>::quiet_NaN();
        return 0;
      }
      const double c = in.cth, sn = in.sth;
      d[0] = c * in.q.vx - sn * in.q.vy;
      d[1] = sn * in.q.vx + c * in.q.vy;
      d[2] = in.q.omega;
      // Power of the tip's force at the contact point, and of the surface friction.
      const double vpx = in.q.vx - in.q.omega * in.q.py, vpy = in.q.vy + in.q.omega * in.q.px;
      d[3] = in.q.fx * vpx + in.q.fy * vpy;
      d[4] = -in.q.dissipation;
    } catch (const SolverError& e) {
      failed = true;
      fail_message = e.what();
      return 2;
    }
    return 0;
  };
  auto approach = [&](double t, const double* s) { return instant(g, muN, tip, t, s, true).un; };
  auto record = [&](double t, const double* s) {
    const Instant in = instant(g, muN, tip, t, s, true);
    res.gap_drift = std::max(res.gap_drift, std::fabs(in.c.distance - tip.radius));
    return make_row(g, muN, tip, t, s, &in);
  };
  double t = t_contact;
  std::string end_event = "tip stops";
  double t_release = t_seg_end;
  while (t < t_seg_end) {
    std::vector<double> pending;
    for (std::size_t i = next; i < tout.size() && tout[i] <= t_seg_end; ++i) pending.push_back(tout[i]);
    if (pending.empty() || pending.back() < t_seg_end) pending.push_back(t_seg_end);
    Dop853<double, kQsSize> integ(opt);
    auto observer = [&](std::size_t, double tt, const double* s) {
      if (next < tout.size() && tout[next] == tt) res.rows[next++] = record(tt, s);
    };
    auto hook = [&](double, const double*, double tn, const double* yn) {
      return approach(tn, yn) >= 0 ? kHookStopBefore : kHookContinue;
    };
    const auto r = integ.integrate(rhs, t, y.data(), std::span<const double>(pending), observer, hook);
    res.steps += r.naccpt;
    if (failed) throw SolverError(fail_message);
    if (!r.ok()) throw SolverError("quasi-static tip push: " + r.message);
    t = r.t_reached;
    if (!r.stopped_by_hook) break;
    // The tip stops approaching inside (t, t_event_end]: locate it by regula falsi on
    // sub-integrations from t, then integrate to it.
    const std::array<double, kQsSize> ys = y;
    auto state_at = [&](double tc) {
      std::array<double, kQsSize> yc = ys;
      if (tc > t) {
        Dop853<double, kQsSize> sub(opt);
        const double one[1] = {tc};
        sub.integrate(rhs, t, yc.data(), std::span<const double>(one, 1), [](std::size_t, double, const double*) {});
      }
      return yc;
    };
    double a = t, b = r.t_event_end;
    double ga = approach(a, ys.data());
    auto yb = state_at(b);
    double gb = approach(b, yb.data());
    roots::illinois(a, b, ga, gb, 100, [&](double l, double h) { return h - l > 1e-14 * std::max(1.0, h) * t_stop; },
                    [&](double tc) { return approach(tc, state_at(tc).data()); }, [](int) {});
    t_release = a;
    std::vector<double> last;
    for (std::size_t i = next; i < tout.size() && tout[i] <= t_release; ++i) last.push_back(tout[i]);
    if (last.empty() || last.back() < t_release) last.push_back(t_release);
    Dop853<double, kQsSize> fin(opt);
    fin.integrate(rhs, t, y.data(), std::span<const double>(last), observer);
    end_event = "release";
    t = t_release;
    break;
  }
  res.events.push_back({end_event == "release" ? t_release : t_seg_end, end_event});
  // At rest from here on: the bar stays where the push left it.
  rest_rows_until(t_end, true);
  return res;
}

}  // namespace nanopush::tip
