// iCOR principles of thesis chapters 4-5 (see icor.hpp; docs/models.md section D).
#include "nanopush/models/icor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "nanopush/numerics/error.hpp"
#include "nanopush/numerics/roots.hpp"

namespace nanopush::icor {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void require_length(double L) { require_positive("L", L, "m"); }

void require_push_on_rod(double yn, double L) {
  require_length(L);
  require_range("yn", yn, 0.0, 0.5 * L, "m; distance from the CM to the push point, at most b = L/2");
}

/// Sign of a polynomial as x -> +inf (dir = +1) or -inf (dir = -1).
double sign_at_infinity(const std::vector<double>& c, int dir) {
  const double lead = c.back();
  const bool odd = (c.size() - 1) % 2 == 1;
  double s = lead > 0.0 ? 1.0 : -1.0;
  if (dir < 0 && odd) s = -s;
  return s;
}

}  // namespace

void Rod::validate() const {
  require_positive("rod.length", length, "m");
  require_positive("rod.radius", radius, "m");
  require_positive("rod.density", density, "kg/m^3");
  require_positive("rod.hamaker", hamaker, "J");
  require_positive("rod.z0", z0, "m");
  require_nonnegative("rod.gravity", gravity, "m/s^2");
  // What the rod's properties derive from them must be finite and > 0, the message naming the
  // inputs (L = 1e308 gave an infinite mass with status OK).
  const auto derived = [](const std::string& fields, const std::string& values, double v, const char* what,
                           const char* unit) {
    if (!(std::isfinite(v) && v > 0.0))
      throw InputError(fields, values, std::string("give ") + what + " = " + fmt(v) + " " + unit +
                                           ", which must be finite and > 0 (inputs too large or too small)");
  };
  const std::string L = fmt(length), r = fmt(radius), rho = fmt(density);
  derived("rod.density, rod.radius, rod.length", rho + ", " + r + ", " + L, mass(), "the mass", "kg");
  derived("rod.length", L, gyration_squared(), "k^2 = L^2/12", "m^2");
  derived("rod.density, rod.radius, rod.length", rho + ", " + r + ", " + L, inertia(), "the moment of inertia",
          "kg m^2");
  derived("rod.length, rod.hamaker, rod.radius, rod.z0", L + ", " + fmt(hamaker) + ", " + r + ", " + fmt(z0),
          vdw_force(), "the van der Waals force", "N");
  derived("rod.density, rod.radius, rod.length, rod.gravity, ...", rho + ", " + r + ", " + L + ", " + fmt(gravity),
          load(), "the load W", "N");
}
double Rod::mass() const { return density * std::numbers::pi * radius * radius * length; }
double Rod::inertia() const { return mass() * length * length / 12.0; }
double Rod::gyration_squared() const { return length * length / 12.0; }
double Rod::vdw_force() const {
  return length * hamaker * std::sqrt(2.0 * radius) / (16.0 * std::pow(z0, 2.5));
}
double Rod::load() const { return mass() * gravity + vdw_force(); }

Rod nanorod() { return Rod{}; }

// ---- Chapter 4 ----------------------------------------------------------------------

double experimental_fit(double yn, double L) {
  require_push_on_rod(yn, L);
  const double beta = (0.5 * L + yn) / L;  // push point from the lower end, normalised
  const double alpha = 0.5 * std::sqrt(std::max(0.0, beta - 0.5));
  return 0.5 * L - alpha * L;
}

double falvo_normalised(double x1_hat) {
  require_range("x1/L", x1_hat, 0.0, 1.0, "normalised push point from the lower end");
  return x1_hat - std::sqrt(x1_hat * x1_hat - 0.5 * (2.0 * x1_hat - 1.0));
}

double falvo(double yn, double L) {
  require_push_on_rod(yn, L);
  const double b = 0.5 * L;
  return b - L * falvo_normalised((b + yn) / L);
}

double li_position(double l, double L) {
  require_length(L);
  require_range("l", l, 0.0, L, "m; push point from the left end");
  const double root = std::sqrt(l * l - l * L + 0.5 * L * L);
  return (l <= 0.5 * L) ? l + root : l - root;
}

double li(double yn, double L) {
  require_push_on_rod(yn, L);
  const double b = 0.5 * L;
  return li_position(b - yn, L) - b;
}

double unknown_pressure(double yn, double L) {
  require_length(L);
  require_nonnegative("yn", yn, "m");
  const double b = 0.5 * L;
  return b * b / (std::hypot(b, yn) + yn);
}

double minimum_force(double mu, double W, double yn, double L) {
  require_positive("mu", mu);
  require_positive("W", W, "N");
  return mu * W * unknown_pressure(yn, L) / (0.5 * L);
}

double known_pressure(double mu, double W, double yn, double F, double L) {
  require_positive("F", F, "N");
  const double Fmin = minimum_force(mu, W, yn, L);  // validates mu, W, yn, L
  const double b = 0.5 * L, muW = mu * W;
  double disc = b * b * F * F - muW * (muW * b * b - 2.0 * b * yn * F);
  if (disc < 0.0) {
    if (F >= Fmin * (1.0 - 8.0 * std::numeric_limits<double>::epsilon()))
      disc = 0.0;  // F at the minimum force, rounding only
    else
      throw InputError("F", fmt(F), "must be >= the minimum force of eq 4.8, " + fmt(Fmin) + " N, for motion to start");
  }
  return (b * F + std::sqrt(disc)) / muW;
}

double force_from_icor(double mu, double W, double R, double L) {
  require_positive("mu", mu);
  require_positive("W", W, "N");
  require_nonnegative("R", R, "m");
  require_length(L);
  return mu * W * R / (0.5 * L);
}

double force_unknown_pressure(double mu, double W, double R, double yn, double L) {
  require_positive("mu", mu);
  require_positive("W", W, "N");
  require_finite("R", R, "m");
  require_nonnegative("yn", yn, "m");
  require_length(L);
  if (!(R + yn > 0.0)) throw InputError("R", fmt(R), "R + yn must be > 0 (moment arm about the iCOR)");
  const double b = 0.5 * L;
  return mu * W * (b * b + R * R) / (2.0 * b * (R + yn));
}

// ---- Chapter 5 ----------------------------------------------------------------------

double impulsive(double yn, double k2) {
  require_nonnegative("yn", yn, "m");
  require_positive("k2", k2, "m^2");
  if (yn == 0.0) return kInf;
  const double R = k2 / yn;
  return R;  // may overflow to +inf for subnormal yn: still not NaN
}

std::array<double, 4> constrained_cubic_printed(double yn, const Rod& rod) {
  rod.validate();
  require_nonnegative("yn", yn, "m");
  const double m = rod.mass(), g = rod.gravity, Fv = rod.vdw_force(), I = rod.inertia();
  const double b = rod.half_length();
  return {(-2.0 * g * m - 2.0 * Fv) * I * I + (b * b * g * m * m + b * b * Fv * m) * I, 0.0,
          (-3.0 * g * m * m - 3.0 * Fv * m) * I, (2.0 * g * m * m * m + 2.0 * Fv * m * m) * yn};
}

std::array<double, 4> constrained_cubic(double yn, double L, double k2) {
  require_length(L);
  require_nonnegative("yn", yn, "m");
  require_positive("k2", k2, "m^2");
  const double b = 0.5 * L;
  return {k2 * (b * b - 2.0 * k2), 0.0, -3.0 * k2, 2.0 * yn};
}

double constrained_force(double mu, double W, double R, double yn, double L, double k2) {
  require_positive("mu", mu);
  require_positive("W", W, "N");
  require_finite("R", R, "m");
  require_nonnegative("yn", yn, "m");
  require_length(L);
  require_positive("k2", k2, "m^2");
  const double b = 0.5 * L;
  const double num = -mu * W * R * (R * R + 2.0 * k2 - b * b);
  const double den = 2.0 * b * (yn * R - k2);
  if (den == 0.0) {
    if (num == 0.0) throw SolverError("eq 5.2 is 0/0 at R = " + fmt(R) + " m, yn = " + fmt(yn) + " m");
    return std::copysign(kInf, num);
  }
  return num / den;
}


BrentRoots real_roots_brent(const std::vector<double>& c_in) {
  for (std::size_t i = 0; i < c_in.size(); ++i) require_finite("c[" + std::to_string(i) + "]", c_in[i]);
  if (c_in.size() > 4) throw InputError("polynomial degree", std::to_string(c_in.size() - 1), "must be <= 3");
  std::vector<double> c = c_in;
  BrentRoots out;
  out.at_infinity = roots::deflate_roots_at_infinity(c);  // the rule of polynomial_roots
  const std::size_t n = c.size() - 1;
  if (n == 0) return out;
  // p(x)/max(1,|x|)^n: same sign and zeros as p, no overflow for huge |x|.
  auto p = [&c](double x) { return roots::polyval_scaled(c, x); };

  // Critical points: real roots of p'(x) (degree n - 1 <= 2), by the stable quadratic formula.
  std::vector<double> crit;
  if (n == 2) {
    crit.push_back(-c[1] / (2.0 * c[2]));
  } else if (n == 3) {
    const double a2 = 3.0 * c[3], a1 = 2.0 * c[2], a0 = c[1];
    const double disc = a1 * a1 - 4.0 * a2 * a0;
    if (disc > 0.0) {
      const double q = -0.5 * (a1 + std::copysign(std::sqrt(disc), a1));
      crit.push_back(q / a2);
      crit.push_back(q != 0.0 ? a0 / q : -q / a2);
    } else if (disc == 0.0) {
      crit.push_back(-a1 / (2.0 * a2));
    }
    std::sort(crit.begin(), crit.end());
  }

  roots::BrentOptions opt;
  auto solve_on = [&](double lo, double hi) {
    const auto r = roots::brent(p, lo, hi, opt);
    out.iterations += r.iterations;
    if (!r.converged) throw SolverError("Brent did not converge on [" + fmt(lo) + ", " + fmt(hi) + "]");
    out.roots.push_back(r.x);
  };
  // Exact zeros at the critical points (multiple roots).
  for (double x : crit)
    if (p(x) == 0.0) out.roots.push_back(x);
  // Bounded monotone pieces.
  for (std::size_t i = 0; i + 1 < crit.size(); ++i) {
    const double fl = p(crit[i]), fh = p(crit[i + 1]);
    if (fl != 0.0 && fh != 0.0 && (fl > 0.0) != (fh > 0.0)) solve_on(crit[i], crit[i + 1]);
  }
  // Unbounded monotone pieces: expand outward from the outermost critical points.
  auto unbounded = [&](double from, int dir) {
    const double f0 = p(from);
    if (f0 == 0.0) return;  // already recorded
    if ((f0 > 0.0) == (sign_at_infinity(c, dir) > 0.0)) return;  // no root out there
    const double step = dir * std::max(1.0, std::fabs(from));
    const auto br = roots::bracket_outward(p, from, step, 2.0);
    if (!br) {
      ++out.at_infinity;  // the root lies beyond the largest double
      return;
    }
    solve_on(br->first, br->second);
  };
  if (crit.empty()) {
    // Monotone everywhere: exactly one real root, on the side where p changes sign.
    const double f0 = p(0.0);
    if (f0 == 0.0) out.roots.push_back(0.0);
    else unbounded(0.0, (f0 > 0.0) == (sign_at_infinity(c, +1) > 0.0) ? -1 : +1);
  } else {
    unbounded(crit.front(), -1);
    unbounded(crit.back(), +1);
  }
  std::sort(out.roots.begin(), out.roots.end());
  return out;
}

CubicSolution solve_constrained_cubic(double yn, double L, double k2, CubicMethod method) {
  require_length(L);
  require_nonnegative("yn", yn, "m");
  require_positive("k2", k2, "m^2");
  const double b = 0.5 * L, kappa = k2 / (b * b);
  if (!std::isfinite(kappa * (1.0 - 2.0 * kappa)) || !std::isfinite(3.0 * kappa))
    throw InputError("k2", fmt(k2), "k2/(L/2)^2 must be representable (got an overflow for L = " + fmt(L) + " m)");
  if (!std::isfinite(2.0 * yn / b))
    throw InputError("yn", fmt(yn), "yn/(L/2) must be representable (got an overflow for L = " + fmt(L) + " m)");
  // Dimensionless r = R/b: (2 yn/b) r^3 - 3 kappa r^2 + kappa (1 - 2 kappa) = 0.
  const std::vector<double> c = {kappa * (1.0 - 2.0 * kappa), 0.0, -3.0 * kappa, 2.0 * yn / b};
  CubicSolution s;
  s.yn = yn;
  std::vector<double> r;
  if (method == CubicMethod::Brent) {
    auto br = real_roots_brent(c);
    r = std::move(br.roots);
    s.at_infinity = br.at_infinity;
    s.complex_roots = 3 - s.at_infinity - static_cast<int>(r.size());
  } else {
    auto pr = roots::polynomial_roots(c);
    s.at_infinity = pr.at_infinity;
    for (const auto& z : pr.roots) {
      if (z.imag() == 0.0) r.push_back(z.real());
      else ++s.complex_roots;
    }
    std::sort(r.begin(), r.end());
  }
  for (double x : r) {
    s.max_residual = std::max(s.max_residual, roots::poly_relative_residual(c, x));
    if (std::isfinite(b * x)) s.real_roots.push_back(b * x);
    else ++s.at_infinity;  // finite in units of b, beyond the largest double in metres
  }
  for (double R : s.real_roots) {
    if (R < 0.0) s.negative = R;  // ascending: the last negative is the closest to 0
    if (R > 0.0 && !s.positive) s.positive = R;
  }
  return s;
}

// ---- Extension points ---------------------------------------------------------------

VelocityIcor icor_from_velocity(double vx, double vy, double omega) {
  require_finite("vx", vx, "m/s");
  require_finite("vy", vy, "m/s");
  require_finite("omega", omega, "rad/s");
  VelocityIcor c;
  if (omega == 0.0) {
    c.translation = true;
    c.R = kInf;
    return c;
  }
  c.cx = -vy / omega;
  c.cy = vx / omega;
  c.R = std::hypot(c.cx, c.cy);
  if (!std::isfinite(c.R)) {  // |v|/|omega| beyond the largest double: translation
    c = VelocityIcor{};
    c.translation = true;
    c.R = kInf;
  }
  return c;
}

Wrench line_contact_wrench(double b, double R, double alpha) {
  require_positive("b", b, "m");
  require_nonnegative("R", R, "m");
  require_finite("alpha", alpha, "rad");
  // Points q = (0, y), |y| <= b; iCOR c = (cx, cy); for omega > 0 the velocity of q is
  // omega (-(y - cy), -cx), so the friction density per unit mu W is
  // (1/(2b)) ((y - cy), cx) / rho, rho = sqrt((y - cy)^2 + cx^2).
  const double cx = -R * std::cos(alpha), cy = -R * std::sin(alpha);
  const double u1 = b - cy, u0 = -b - cy, k = 1.0 / (2.0 * b);
  Wrench w;
  if (std::fabs(cx) <= 1e-15 * b) {
    // iCOR on the rod axis: the density is (sign(u), 0)/(2b).
    const double lp = std::max(0.0, u1) - std::max(0.0, u0);  // length with u > 0
    const double ln = (u1 - u0) - lp;                           // length with u < 0
    w.fx = k * (lp - ln);
    w.fy = 0.0;
    // mf = -int y fx(y) dy, y = u + cy.
    auto int_u = [](double lo, double hi) { return 0.5 * (hi * hi - lo * lo); };
    const double a_p = std::max(0.0, u0), b_p = std::max(0.0, u1);
    const double a_n = std::min(0.0, u0), b_n = std::min(0.0, u1);
    const double iy_pos = int_u(a_p, b_p) + cy * (b_p - a_p);
    const double iy_neg = int_u(a_n, b_n) + cy * (b_n - a_n);
    w.mf = -k * (iy_pos - iy_neg);
    return w;
  }
  const double c2 = cx * cx, ac = std::fabs(cx);
  const double r1 = std::hypot(u1, cx), r0 = std::hypot(u0, cx);
  const double as = std::asinh(u1 / ac) - std::asinh(u0 / ac);
  w.fx = k * (r1 - r0);
  w.fy = k * cx * as;  // int cx/rho du = cx (asinh(u1/|cx|) - asinh(u0/|cx|))
  // mf = sum q x f = -int y fx dy (x = 0); y = u + cy:
  // int u^2/rho du = (u rho - c^2 asinh(u/|c|))/2, int u/rho du = rho.
  const double iuu = 0.5 * ((u1 * r1 - c2 * std::asinh(u1 / ac)) - (u0 * r0 - c2 * std::asinh(u0 / ac)));
  const double iu = r1 - r0;
  w.mf = -k * (iuu + cy * iu);
  return w;
}

QuasiStaticIcor quasi_static_icor(const FrictionWrenchFn& wrench, double px, double py, double dir_x, double dir_y,
                                  double R0, double alpha0, double length_scale) {
  require_finite("px", px, "m");
  require_finite("py", py, "m");
  require_positive("R0", R0, "m");
  require_finite("alpha0", alpha0, "rad");
  require_positive("length_scale", length_scale, "m");
  const double en = std::hypot(dir_x, dir_y);
  if (!(en > 0.0) || !std::isfinite(en)) throw InputError("push direction", "(" + fmt(dir_x) + ", " + fmt(dir_y) + ")", "must be a finite non-zero vector");
  const double ex = dir_x / en, ey = dir_y / en;
  const double arm = px * ey - py * ex;  // (p x e)_z
  QuasiStaticIcor best;
  for (int sgn : {-1, +1}) {
    // Balance: F e + s f = 0, F arm + s mf = 0 with F = -s (f . e). Unknowns z = (ln R, alpha).
    auto g = [&](double lnR, double a, double& F) {
      const Wrench w = wrench(std::exp(lnR), a);
      const double fx = sgn * w.fx, fy = sgn * w.fy, mf = sgn * w.mf;
      F = -(fx * ex + fy * ey);
      return std::array<double, 2>{fx * ey - fy * ex, (F * arm + mf) / length_scale};
    };
    double z0 = std::log(R0), z1 = alpha0, F = 0.0;
    auto r = g(z0, z1, F);
    auto norm = [](const std::array<double, 2>& v) { return std::max(std::fabs(v[0]), std::fabs(v[1])); };
    QuasiStaticIcor q;
    q.omega_sign = sgn;
    for (int it = 1; it <= 100; ++it) {
      q.iterations = it;
      if (norm(r) <= 1e-13) { q.converged = true; break; }
      const double h = 1e-7;
      double Fd = 0.0;
      const auto r0p = g(z0 + h, z1, Fd), r0m = g(z0 - h, z1, Fd);
      const auto r1p = g(z0, z1 + h, Fd), r1m = g(z0, z1 - h, Fd);
      const double J00 = (r0p[0] - r0m[0]) / (2 * h), J10 = (r0p[1] - r0m[1]) / (2 * h);
      const double J01 = (r1p[0] - r1m[0]) / (2 * h), J11 = (r1p[1] - r1m[1]) / (2 * h);
      const double det = J00 * J11 - J01 * J10;
      if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) break;
      const double d0 = -(J11 * r[0] - J01 * r[1]) / det, d1 = -(-J10 * r[0] + J00 * r[1]) / det;
      double t = 1.0;
      bool moved = false;
      for (int k = 0; k < 40; ++k, t *= 0.5) {
        double Ft = 0.0;
        const double s0 = std::clamp(d0 * t, -2.0, 2.0), s1 = std::clamp(d1 * t, -1.0, 1.0);
        const auto rt = g(z0 + s0, z1 + s1, Ft);
        if (std::isfinite(rt[0]) && std::isfinite(rt[1]) && norm(rt) < norm(r)) {
          z0 += s0;
          z1 += s1;
          r = rt;
          F = Ft;
          moved = true;
          break;
        }
      }
      if (!moved) break;
    }
    g(z0, z1, F);
    q.R = std::exp(z0);
    q.alpha = z1;
    q.force = F;
    q.residual = norm(r);
    if (norm(r) <= 1e-13) q.converged = true;
    if (q.converged && F > 0.0 && (!best.converged || q.force < best.force)) best = q;
    else if (!best.converged && (best.iterations == 0 || q.residual < best.residual)) best = q;
  }
  return best;
}

// ---- Inverse maps -------------------------------------------------------------------

namespace {
void check_measured(const std::string& name, const Measured& m, const std::string& unit, bool positive) {
  if (positive) require_positive(name, m.value, unit);
  else require_nonnegative(name, m.value, unit);
  require_nonnegative(name + " uncertainty", m.sigma, unit);
}
}  // namespace

MuEstimate propagate_uncertainty(MuEstimate e) {
  const auto overflow = [&](const std::string& named) {
    return InputError(named + ": mu or its uncertainty is not a finite number: these values overflow a double (forces "
                              "in N, lengths in m; a push force is of the order of the load " + fmt(e.load) + " N)");
  };
  // mu itself: from the measured values (the first two contributions).
  if (!std::isfinite(e.mu))
    throw overflow(e.contributions[0].input + " = " + fmt(e.contributions[0].value) + ", " + e.contributions[1].input +
                   " = " + fmt(e.contributions[1].value));
  // Its uncertainty: named by the input whose contribution (d mu / d input x its uncertainty)
  // is not finite, or the largest when only their sum of squares overflows.
  double var = 0.0;
  const Contribution* worst = nullptr;
  for (const auto& c : e.contributions) {
    const double term = c.derivative * c.sigma;
    if (!std::isfinite(term)) {
      if (!std::isfinite(c.derivative))  // the derivative at the value: the value is what overflows
        throw overflow(c.input + " = " + fmt(c.value));
      throw InputError(c.input + " uncertainty", fmt(c.sigma),
                       "its contribution to the uncertainty of mu (|d mu / d " + c.input + "| = " +
                           fmt(std::fabs(c.derivative)) + " times it) is not a finite number: it overflows a double");
    }
    if (!worst || std::fabs(term) > std::fabs(worst->derivative * worst->sigma)) worst = &c;
    var += term * term;
  }
  e.sigma = std::sqrt(var);
  if (!std::isfinite(e.sigma))
    throw InputError(worst->input + " uncertainty", fmt(worst->sigma),
                     "its contribution to the uncertainty of mu (|d mu / d " + worst->input + "| = " +
                         fmt(std::fabs(worst->derivative)) + " times it) squared is not a finite number: it overflows a double");
  return e;
}

MuEstimate estimate_mu_from_force(const Rod& rod, Measured F, Measured yn, double sigma_L, double sigma_H) {
  rod.validate();
  check_measured("F", F, "N", true);
  check_measured("yn", yn, "m", false);
  require_range("yn", yn.value, 0.0, rod.half_length(), "m; push point on the rod, at most b = L/2");
  require_nonnegative("L uncertainty", sigma_L, "m");
  require_nonnegative("H uncertainty", sigma_H, "J");
  const double b = rod.half_length(), W = rod.load(), s = std::hypot(yn.value, b);
  MuEstimate e;
  e.load = W;
  e.mu = F.value * (s + yn.value) / (W * b);
  // d ln mu: dF/F + dyn/s - (yn/(2 b s) + 1/L) dL - (F_vdw/(H W)) dH   (W proportional to L).
  e.contributions = {
      {"F", F.value, F.sigma, e.mu / F.value},
      {"yn", yn.value, yn.sigma, e.mu / s},
      {"L", rod.length, sigma_L, -e.mu * (yn.value / (2.0 * b * s) + 1.0 / rod.length)},
      {"H", rod.hamaker, sigma_H, -e.mu * rod.vdw_force() / (rod.hamaker * W)},
  };
  return propagate_uncertainty(e);
}

MuEstimate estimate_mu_from_icor(const Rod& rod, Measured F, Measured R, double sigma_L, double sigma_H) {
  rod.validate();
  check_measured("F", F, "N", true);
  check_measured("R", R, "m", true);
  require_nonnegative("L uncertainty", sigma_L, "m");
  require_nonnegative("H uncertainty", sigma_H, "J");
  const double b = rod.half_length(), W = rod.load();
  MuEstimate e;
  e.load = W;
  e.mu = F.value * b / (W * R.value);
  e.contributions = {
      {"F", F.value, F.sigma, e.mu / F.value},
      {"R", R.value, R.sigma, -e.mu / R.value},
      {"L", rod.length, sigma_L, 0.0},
      {"H", rod.hamaker, sigma_H, -e.mu * rod.vdw_force() / (rod.hamaker * W)},
  };
  return propagate_uncertainty(e);
}

double round_significant(double x, int digits) {
  if (x == 0.0 || !std::isfinite(x)) return x;
  const double e = std::floor(std::log10(std::fabs(x)));
  const double scale = std::pow(10.0, static_cast<double>(digits) - 1.0 - e);
  return std::round(x * scale) / scale;
}

// ---- The thesis' printed values -----------------------------------------------------

int ThesisTableRow::digits() const {
  int d = 0;
  for (const char* c = mantissa; *c; ++c)
    if (*c >= '0' && *c <= '9') ++d;
  return d;
}

const std::vector<ThesisTableRow>& thesis_table_5_1() {
  static const std::vector<ThesisTableRow> rows = {
      {295e-9, 7.93e-8, "7.93", false},   {285e-9, 7.97e-8, "7.97", false},
      {275e-9, 8.012e-8, "8.012", false}, {265e-9, 8.054e-8, "8.054", false},
      {255e-9, 8.098e-8, "8.098", false}, {245e-9, 8.142e-8, "8.142", false},
      {235e-9, 8.188e-8, "8.188", false}, {225e-9, 8.235e-8, "8.235", false},
      {215e-9, 8.283e-8, "8.283", false}, {205e-9, 8.333e-8, "8.333", false},
      {195e-9, 8.384e-8, "8.384", false}, {185e-9, 8.436e-8, "8.436", false},
      {175e-9, 8.49e-8, "8.49", false},   {165e-9, 8.546e-8, "8.546", false},
      {155e-9, 8.603e-8, "8.603", false}, {145e-9, 8.662e-8, "8.662", false},
      {135e-9, 8.723e-8, "8.723", false}, {125e-9, 8.787e-8, "8.787", false},
      {115e-9, 8.852e-8, "8.852", false}, {105e-9, 8.92e-8, "8.92", false},
      {95e-9, 8.99e-8, "8.99", false},    {85e-9, 9.064e-8, "9.064", false},
      {75e-9, 9.14e-8, "9.14", false},    {65e-9, 9.219e-8, "9.219", false},
      {55e-9, 9.302e-8, "9.302", false},  {45e-9, 9.388e-8, "9.388", false},
      {35e-9, 9.479e-8, "9.479", false},  {25e-9, 9.574e-8, "9.574", false},
      {15e-9, 9.673e-8, "9.673", false},  {5e-9, 9.779e-8, "9.779", false},
      {4e-9, 9.789e-8, "9.789", false},   {3e-9, 9.800e-8, "9.800", false},
      {2e-9, 9.811e-8, "9.811", true},    {1e-9, 9.822e-8, "9.822", true},
      {0.0, 9.833e-8, "9.833", true},
  };
  return rows;
}

double sample_std(const std::vector<double>& x) {
  if (x.size() < 2) throw InputError("sample size", std::to_string(x.size()), "must be >= 2");
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double ss = 0.0;
  for (double v : x) ss += (v - mean) * (v - mean);
  return std::sqrt(ss / static_cast<double>(x.size() - 1));
}

ErrorAnalysis error_analysis(double L, double k2, CubicMethod method, int n) {
  if (n < 2) throw InputError("n", std::to_string(n), "must be >= 2");
  std::vector<double> a, c;
  for (int i = 0; i < n; ++i) {
    const double yn = i * 1e-9;
    a.push_back(unknown_pressure(yn, L) / 1e-9);
    const auto s = solve_constrained_cubic(yn, L, k2, method);
    if (!s.negative) throw SolverError("eq 5.4 has no negative root at yn = " + fmt(yn) + " m");
    c.push_back(-*s.negative / 1e-9);
  }
  ErrorAnalysis e;
  e.n = n;
  e.std_unknown_pressure_nm = sample_std(a);
  e.std_constrained_nm = sample_std(c);
  for (int i = 0; i < n; ++i) {
    e.mean_unknown_pressure_nm += a[static_cast<std::size_t>(i)] / n;
    e.mean_constrained_nm += c[static_cast<std::size_t>(i)] / n;
  }
  return e;
}

}  // namespace nanopush::icor
