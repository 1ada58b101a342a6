// The production friction resultant (friction.hpp: closed_form with 4 logarithms and 4 square
// roots, far_field with one division per node pair, two lanes at a time) against exact
// oracles evaluated in __float128, and against the F77 routine's forms (the *_reference
// functions, which the faithful method evaluates, and the benchmark `nanopush bench-friction`
// compares). The cubature tests of test_friction.cpp run on the production forms.
#include <catch2/catch.hpp>

#include <quadmath.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "nanopush/models/friction.hpp"

using namespace nanopush;
using friction_detail::MeanIntegrals;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

using Q = __float128;
constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = DBL_EPSILON;  // 2.2e-16

/// The plain corner sum F(x1,y1) - F(x0,y1) - F(x1,y0) + F(x0,y0) of docs/friction.md in
/// __float128 (lengths in units of max(a, b)): 34 digits, of which a thin contact of aspect
/// 1e-12 loses 12 to the cancellation across its thin side, leaving 1e-22 -- an exact oracle
/// for a double result.
MeanIntegrals corner_sum_quad(double a_, double b_, double xc_, double yc_) {
  const Q a = a_, b = b_, xc = xc_, yc = yc_;
  const Q xs[2] = {xc - a, xc + a}, ys[2] = {yc - b, yc + b};
  const auto sq_asinh = [](Q u, Q v) -> Q { return u == 0 ? Q(0) : u * u * asinhq(v / fabsq(u)); };
  Q sx = 0, sy = 0, sr = 0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const Q X = xs[i], Y = ys[j], r = sqrtq(X * X + Y * Y);
      const Q ax = sq_asinh(X, Y), ay = sq_asinh(Y, X);
      const Q sg = (i == j) ? 1 : -1;
      sx += sg * (Y * r + ax) / 2;
      sy += sg * (X * r + ay) / 2;
      sr += sg * (X * Y * r / 3 + (X * ax + Y * ay) / 6);
    }
  const Q area = 4 * a * b, ix = sx / area, iy = sy / area;
  return {static_cast<double>(ix), static_cast<double>(iy), static_cast<double>(sr / area - xc * ix - yc * iy)};
}

/// The far-field Gauss-Legendre sum (the symmetrised integrands of far_field_reference) in
/// __float128: what far_field evaluates, without its rounding.
MeanIntegrals far_field_quad(double a_, double b_, double xc_, double yc_, const double* gx, const double* gw, int h) {
  const Q a = a_, b = b_, xc = xc_, yc = yc_;
  const Q r = sqrtq(xc * xc + yc * yc);
  Q sx = 0, sy = 0, sk = 0;
  for (int i = 0; i < h; ++i) {
    const Q x = a * Q(gx[i]);
    for (int j = 0; j < 2 * h; ++j) {
      const Q y = j < h ? b * Q(gx[j]) : -b * Q(gx[j - h]);
      const Q wxy = Q(gw[i]) * Q(j < h ? gw[j] : gw[j - h]);
      const Q xp = xc + x, yp = yc + y, xm = xc - x, ym = yc - y;
      const Q rp = sqrtq(xp * xp + yp * yp), rm = sqrtq(xm * xm + ym * ym);
      const Q d = x * xc + y * yc, e = x * yc - y * xc, rho = sqrtq(x * x + y * y), rr = rp * rm;
      const Q ee = e * e / (r * r);
      sx += wxy * (xp / rp + xm / rm);
      sy += wxy * (yp / rp + ym / rm);
      sk += wxy * (ee * (1 / rp + 1 / rm) + 8 * d * d * ee / (rr * (rp + rm) * (rr + (r - rho) * (r + rho))));
    }
  }
  return {static_cast<double>(sx / 4), static_cast<double>(sy / 4), static_cast<double>(sk / 4)};
}

/// A geometry of form 1 in units of L = max(a, b) = 1: the CM at (xc, yc) seen from the iCOR.
struct Geometry {
  double a, b, xc, yc;
  const char* kind;
};

/// iCOR at body point (cx, cy): the CM is at -c seen from it.
Geometry at_icor(double a, double b, double cx, double cy, const char* kind) { return {a, b, -cx, -cy, kind}; }

/// Random iCORs within 3 L of the CM: inside, outside, on edges and corners (exactly), on the
/// edges' lines, one ulp off an edge, at the CM; aspect ratios down to 1e-12 (either side thin).
std::vector<Geometry> closed_form_cases(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Geometry> g;
  for (int i = 0; i < n; ++i) {
    const double thin = (i % 3 == 0) ? std::max(kFrictionMinAspect, std::pow(10.0, -12.5 * u(rng)))
                                     : std::pow(10.0, -1.3 * u(rng));
    const double a = (i % 2) ? 1.0 : thin, b = (i % 2) ? thin : 1.0;
    const double sx = u(rng) < 0.5 ? -1.0 : 1.0, sy = u(rng) < 0.5 ? -1.0 : 1.0;
    switch (i % 10) {
      case 0:
      case 1: {
        const double rho = 3.0 * u(rng), al = 2 * kPi * u(rng);
        g.push_back({a, b, rho * std::cos(al), rho * std::sin(al), "random"});
        break;
      }
      case 2:
        g.push_back(at_icor(a, b, a * (2 * u(rng) - 1), b * (2 * u(rng) - 1), "inside"));
        break;
      case 3:
        g.push_back(at_icor(a, b, sx * a, b * (2 * u(rng) - 1), "edge x'"));
        break;
      case 4:
        g.push_back(at_icor(a, b, a * (2 * u(rng) - 1), sy * b, "edge y'"));
        break;
      case 5:
        g.push_back(at_icor(a, b, sx * a, sy * b, "corner"));
        break;
      case 6:
        g.push_back(at_icor(a, b, sx * a, sy * b * (1.0 + 2.0 * u(rng)), "line x' = +-a"));
        break;
      case 7:
        g.push_back(at_icor(a, b, sx * a * (1.0 + 2.0 * u(rng)), sy * b, "line y' = +-b"));
        break;
      case 8: {  // one ulp (or a few) off an edge, inside or outside
        const double k = 1.0 + sx * kEps * std::floor(1 + 4 * u(rng));
        if (u(rng) < 0.5)
          g.push_back(at_icor(a, b, a * k, b * (2 * u(rng) - 1), "near edge x'"));
        else
          g.push_back(at_icor(a, b, a * (2 * u(rng) - 1), b * k, "near edge y'"));
        break;
      }
      default:
        g.push_back(u(rng) < 0.3 ? Geometry{a, b, 0.0, 0.0, "centre"}
                                 : at_icor(a, b, sx * a * 3 * u(rng), 0.0, "long axis"));
        break;
    }
    const Geometry& last = g.back();
    if (std::hypot(last.xc, last.yc) >= kFrictionFarField) g.pop_back();  // form 1 only
  }
  return g;
}

double max3(const MeanIntegrals& p, const MeanIntegrals& q, double* d) {
  d[0] = std::fabs(p.ix - q.ix);
  d[1] = std::fabs(p.iy - q.iy);
  d[2] = std::fabs(p.km - q.km);
  return std::max({d[0], d[1], d[2]});
}

}  // namespace

// Bound: the mean integrals <X/r>, <Y/r> lie in [-1, 1] and km = <(xX + yY)/r> in [0, 4]
// (units of L), and the closed form differences terms up to (R/L)^2 and (R/L)^3 along the
// long side (docs/friction.md, "Rounding"), so its error is a few eps (R/L)^2. Measured over
// these cases: 7.8e-16 in <X/r>, <Y/r> and 1.8e-15 in km (1.1e-15 and 2.2e-15 over 10^6
// random iCORs); asserted: 3e-15 (13.5 eps, the accuracy docs/friction.md states for the
// closed form's force) and 4e-15 in km. The forms before issue 24 reach 4.9e-15 here (7e-15
// in larger scans: iCORs within an ulp of an edge's line, where their asinh(X/|y0|) grows
// without bound and cancels); reported, not asserted.
TEST_CASE("friction fast: closed form vs an exact quad-precision corner sum (random, edges, corners, thin)",
          "[friction][numeric]") {
  const auto cases = closed_form_cases(60000, 2411);
  REQUIRE(cases.size() >= 50000);
  double worst_new[3] = {0, 0, 0}, worst_old[3] = {0, 0, 0};
  for (const auto& c : cases) {
    const MeanIntegrals q = corner_sum_quad(c.a, c.b, c.xc, c.yc);
    const MeanIntegrals n = friction_detail::closed_form(c.a, c.b, c.xc, c.yc);
    const MeanIntegrals o = friction_detail::closed_form_reference(c.a, c.b, c.xc, c.yc);
    double dn[3], dold[3];
    max3(n, q, dn);
    max3(o, q, dold);
    INFO(c.kind << ": a=" << c.a << " b=" << c.b << " xc=" << c.xc << " yc=" << c.yc << " new " << n.ix << " " << n.iy
                << " " << n.km << " exact " << q.ix << " " << q.iy << " " << q.km);
    REQUIRE(dn[0] <= 3e-15);
    REQUIRE(dn[1] <= 3e-15);
    REQUIRE(dn[2] <= 4e-15);
    for (int k = 0; k < 3; ++k) {
      worst_new[k] = std::max(worst_new[k], dn[k]);
      worst_old[k] = std::max(worst_old[k], dold[k]);
    }
  }
  WARN("closed form vs exact over " << cases.size() << " iCORs: new " << worst_new[0] << " " << worst_new[1] << " "
                                    << worst_new[2] << "; before issue 24 " << worst_old[0] << " " << worst_old[1]
                                    << " " << worst_old[2] << " (<X/r>, <Y/r>, km)");
}

// Bound: the far-field rule's own error is below 1e-16 by construction (docs/friction.md);
// this checks the rounding of its evaluation, which sums positive weights times terms of size
// <= 1 (force) or non-negative terms (moment): measured 4.4e-16 absolute in the force means and
// 7e-16 relative in km, the same as far_field_reference; asserted 4 eps (8.9e-16) and 8 eps
// (1.8e-15) relative.
TEST_CASE("friction fast: far field vs the same Gauss-Legendre sum in quad precision", "[friction][numeric]") {
  struct Rule {
    double from, to;
    const double *x, *w;
    int h;
  };
  const Rule rules[] = {{kFrictionFarField, kFrictionGl8From, friction_detail::kGl12x, friction_detail::kGl12w, 6},
                        {kFrictionGl8From, kFrictionGl6From, friction_detail::kGl8x, friction_detail::kGl8w, 4},
                        {kFrictionGl6From, kFrictionGl4From, friction_detail::kGl6x, friction_detail::kGl6w, 3},
                        {kFrictionGl4From, kFrictionAsymptotic, friction_detail::kGl4x, friction_detail::kGl4w, 2}};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const Rule& rl : rules) {
    double wf = 0, wk = 0;
    for (int i = 0; i < 4000; ++i) {
      const double thin = (i % 3 == 0) ? std::max(kFrictionMinAspect, std::pow(10.0, -12.5 * u(rng)))
                                       : std::pow(10.0, -1.3 * u(rng));
      const double a = (i % 2) ? 1.0 : thin, b = (i % 2) ? thin : 1.0;
      const double rho = rl.from * std::pow(rl.to / rl.from, u(rng));
      const double al = (i % 5 == 0) ? kPi / 2 * std::floor(4 * u(rng)) : 2 * kPi * u(rng);  // on the axes too
      const double xc = rho * std::cos(al), yc = rho * std::sin(al);
      const MeanIntegrals q = far_field_quad(a, b, xc, yc, rl.x, rl.w, rl.h);
      MeanIntegrals n{};
      switch (rl.h) {
        case 6:
          n = friction_detail::far_field(a, b, xc, yc, friction_detail::kGl12x, friction_detail::kGl12w);
          break;
        case 4:
          n = friction_detail::far_field(a, b, xc, yc, friction_detail::kGl8x, friction_detail::kGl8w);
          break;
        case 3:
          n = friction_detail::far_field(a, b, xc, yc, friction_detail::kGl6x, friction_detail::kGl6w);
          break;
        default:
          n = friction_detail::far_field(a, b, xc, yc, friction_detail::kGl4x, friction_detail::kGl4w);
          break;
      }
      const double df = std::max(std::fabs(n.ix - q.ix), std::fabs(n.iy - q.iy));
      const double dk = std::fabs(n.km - q.km) / std::fabs(q.km);
      INFO("rule " << 2 * rl.h << ": a=" << a << " b=" << b << " xc=" << xc << " yc=" << yc);
      REQUIRE(df <= 4 * kEps);
      REQUIRE(dk <= 8 * kEps);
      REQUIRE(n.km > 0.0);
      wf = std::max(wf, df);
      wk = std::max(wk, dk);
    }
    WARN("far field, " << 2 * rl.h << "-point rule: worst force " << wf << ", moment (relative) " << wk);
  }
}

// The public entry points against the F77 routine's forms, every form, R/L from 0 to
// 1e15 and both senses. Bounds: far field -- both forms within 4 eps (force, units of muN) and
// 8 eps (moment, relative) of the same sum (test above), so 8 eps and 16 eps; measured 5.9e-16
// and 8.8e-16. Asymptotic form: unchanged, identical. Closed form -- each within its own
// rounding error of the exact value (above: 3e-15 new, up to 7e-15 before), so 1e-14 in units
// of muN and muN max(a, b); measured 1.1e-15 and 2.7e-15 here, 7e-15 in larger scans, all of
// it the older form's error near edge lines. (Identical to 1e-15 relative, as issue 24 asks,
// holds in the far field; in form 1 the older form is itself farther than that from exact.)
TEST_CASE("friction fast: the public entry points agree with the F77 routine's forms (the faithful method's)",
          "[friction][numeric]") {
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst[6][2] = {};
  for (int i = 0; i < 200000; ++i) {
    const double scale = std::pow(10.0, -9.0 + 3.0 * u(rng));
    const double thin = (i % 4 == 0) ? std::max(kFrictionMinAspect, std::pow(10.0, -12.5 * u(rng)))
                                     : std::pow(10.0, -1.3 * u(rng));
    const double a = scale * ((i % 2) ? 1.0 : thin), b = scale * ((i % 2) ? thin : 1.0);
    const double L = std::max(a, b), muN = 1.7e-6;
    const double rho = (i % 3 == 0) ? 3.0 * u(rng) : std::pow(10.0, -1.0 + 16.0 * u(rng));
    const double alpha = (i % 7 == 0) ? kPi / 2 * std::floor(4 * u(rng)) : 2 * kPi * u(rng);
    const int sense = (i % 5 == 0) ? -1 : 1;
    const double R = rho * L;
    const int form = rectangle_friction_form(a, b, R);
    const FrictionWrench n = rectangle_friction_wrench(a, b, muN, R, alpha, sense);
    const FrictionWrench o = friction_detail::rectangle_friction_wrench_reference(a, b, muN, R, alpha, sense);
    const double df = std::hypot(n.fx - o.fx, n.fy - o.fy) / muN;
    const double dm = std::fabs(n.mf - o.mf) / (form == 0 ? muN * L : std::fabs(o.mf));
    INFO("form " << form << ": a=" << a << " b=" << b << " R=" << R << " alpha=" << alpha << " sense " << sense);
    if (form == 0) {
      REQUIRE(df <= 1e-14);
      REQUIRE(dm <= 1e-14);
    } else if (form == 5) {
      REQUIRE((n.fx == o.fx && n.fy == o.fy && n.mf == o.mf));  // the same two-term formula
    } else {
      REQUIRE(df <= 8 * kEps);
      REQUIRE(dm <= 16 * kEps);
    }
    worst[form][0] = std::max(worst[form][0], df);
    worst[form][1] = std::max(worst[form][1], dm);
  }
  for (int f = 0; f < 6; ++f)
    WARN("form " << f << ": production vs F77 forms, force " << worst[f][0] << ", moment " << worst[f][1]
                 << (f == 0 ? " (units of muN max(a,b))" : " (relative)"));

  // The velocity interface (the rough-surface right-hand side), the same bounds.
  for (int i = 0; i < 50000; ++i) {
    const double a = 27.5e-9, b = 50e-9, L = b;
    const double v = std::pow(10.0, -3.0 + 6.0 * u(rng)), th = 2 * kPi * u(rng);
    const double vx = v * std::cos(th), vy = v * std::sin(th);
    const double omega = (u(rng) < 0.5 ? -1 : 1) * v / (L * std::pow(10.0, -1.0 + 10.0 * u(rng)));
    const FrictionWrench n = rectangle_friction_from_velocity(a, b, 2e-6, vx, vy, omega);
    const FrictionWrench o = friction_detail::rectangle_friction_from_velocity_reference(a, b, 2e-6, vx, vy, omega);
    const double rho = v / std::fabs(omega) / L;
    INFO("vx=" << vx << " vy=" << vy << " omega=" << omega << " R/L=" << rho);
    CHECK(std::hypot(n.fx - o.fx, n.fy - o.fy) / 2e-6 <= (rho < kFrictionFarField ? 1e-14 : 8 * kEps));
    CHECK(std::fabs(n.mf - o.mf) <= (rho < kFrictionFarField ? 1e-14 * 2e-6 * L : 16 * kEps * std::fabs(o.mf)));
  }
}

// iCORs exactly on an edge or a corner, and 1-4 ulps off them on either side, for aspect
// ratios down to the accepted 1e-12: against the exact corner sum (the bound of the first test).
TEST_CASE("friction fast: iCORs on edges and corners and a few ulps off them", "[friction][unit]") {
  std::mt19937_64 rng(100);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0;
  for (int i = 0; i < 6000; ++i) {
    const double thin = (i % 3 == 0) ? std::max(kFrictionMinAspect, std::pow(10.0, -12.5 * u(rng)))
                                     : std::pow(10.0, -1.3 * u(rng));
    const double a = (i % 2) ? 1.0 : thin, b = (i % 2) ? thin : 1.0;
    const double sx = u(rng) < 0.5 ? -1.0 : 1.0, sy = u(rng) < 0.5 ? -1.0 : 1.0;
    const double k = std::floor(4 * u(rng));  // 0: on it; else k ulps inside or outside
    const double ko = 1.0 + (u(rng) < 0.5 ? -1.0 : 1.0) * k * kEps;
    double cx, cy;
    switch (i % 3) {
      case 0:
        cx = sx * a * ko, cy = b * (2 * u(rng) - 1);
        break;
      case 1:
        cx = a * (2 * u(rng) - 1), cy = sy * b * ko;
        break;
      default:
        cx = sx * a * ko, cy = sy * b * (u(rng) < 0.5 ? 1.0 : ko);
        break;
    }
    const MeanIntegrals m = friction_detail::closed_form(a, b, -cx, -cy);
    const MeanIntegrals exact = corner_sum_quad(a, b, -cx, -cy);
    double d[3];
    INFO("a=" << a << " b=" << b << " iCOR (" << cx << ", " << cy << ")");
    const double e = max3(m, exact, d);
    REQUIRE(e <= 4e-15);
    worst = std::max(worst, e);
  }
  WARN("edges and corners: worst " << worst);
}

// Below the accepted aspect ratio the distance y0 from the iCOR to the thin side's line can be
// a nonzero number below 1e-100 max(a, b), where the new form's quotients would underflow: it
// hands such geometries to closed_form_reference. Exactly on the line (y0 = 0) it stays with
// the new form. The wrench is continuous (C^1) in the iCOR, so at offsets of 1e-106 ... 1e-95
// it must agree with its value on the line to rounding, and never be NaN.
TEST_CASE("friction fast: the hand-over below 1e-100 max(a, b) is continuous", "[friction][unit]") {
  std::mt19937_64 rng(101);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double b = 1e-90 * (1 + u(rng)), xc = 4 * u(rng) - 2;
    const double sy = u(rng) < 0.5 ? -1.0 : 1.0;
    const MeanIntegrals on = friction_detail::closed_form(1.0, b, xc, sy * b);  // y0 = 0 exactly
    REQUIRE((std::isfinite(on.ix) && std::isfinite(on.iy) && std::isfinite(on.km)));
    for (const double off : {0x1p-349, 1e-105, 1e-101, 1e-99, 1e-95}) {  // 0x1p-349: 2-4 ulps of b
      const MeanIntegrals m = friction_detail::closed_form(1.0, b, xc, sy * (b + off));
      double d[3];
      INFO("b=" << b << " xc=" << xc << " offset " << off);
      REQUIRE((std::isfinite(m.ix) && std::isfinite(m.iy) && std::isfinite(m.km)));
      CHECK(max3(m, on, d) <= 4e-15);
    }
  }
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
