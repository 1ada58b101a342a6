// Coulomb friction over a rectangular contact with uniform pressure (docs/models.md §B; thesis
// eqs 3.27-3.50 and Appendix B, after Cheung's rigid-body sliding model).
//
// Geometry (docs/models.md §0). Body axes at the centre of mass (CM): x' across the width
// (half-width a), y' along the length (half-length b). The instantaneous centre of rotation
// (iCOR) sits at c = -R (cos alpha, sin alpha), so seen from the iCOR the CM is at
// (Xc, Yc) = R (cos alpha, sin alpha) and the contact spans X in [Xc - a, Xc + a],
// Y in [Yc - b, Yc + b] (the thesis' h4..h2 and h1..h3). The contact point (X, Y) moves with
// velocity omega (-Y, X); friction per unit area is -mu p times its unit vector.
// With s = sign(omega), p = N / (4ab), r = sqrt(X^2 + Y^2):
//
//   fx' =  muN s <Y/r>,   fy' = -muN s <X/r>,   mf = -muN s <(x X + y Y)/r>
//
// where <.> is the mean over the rectangle and (x, y) = (X - Xc, Y - Yc) are body
// coordinates, so x X + y Y = r^2 - (Xc X + Yc Y) (the thesis' r - R cos(gamma - alpha)).
//
// Three evaluation forms, chosen by rho = R / max(a, b) (docs/friction.md has the derivation):
//  1. rho < kFrictionFarField: the exact corner-term closed form. Antiderivatives
//       FX = (Y r + X^2 asinh(Y/|X|))/2, FY = (X r + Y^2 asinh(X/|Y|))/2,
//       Fr = X Y r/3 + (X^3 asinh(Y/|X|) + Y^3 asinh(X/|Y|))/6
//     combined as F(x1,y1) - F(x0,y1) - F(x1,y0) + F(x0,y0), the difference across the
//     thinner side formed without cancellation (y_difference). The asinh form (instead of the
//     thesis' logarithms of differences) is finite on edges, corners and at R = 0.
//     Rounding error grows like eps rho^2 (force) and eps rho^3 (moment) from the remaining
//     difference along the long side.
//  2. kFrictionFarField <= rho < kFrictionAsymptotic: the far-field multipole series of the
//     integrand, evaluated exactly by an n x n product Gauss-Legendre rule applied to the
//     point-symmetrised integrands (no cancellation: the O(R) odd part of the moment integrand
//     is removed analytically). The rule integrates the series to degree 2n - 1 exactly;
//     n = 12, 8, 6, 4 from rho = 3, 8, 24, 512 keeps the remainder below 1e-16.
//  3. rho >= kFrictionAsymptotic (1e9): the two-term asymptotic form
//       f = muN s (sin alpha, -cos alpha),  mf = -muN s (a^2 sin^2 alpha + b^2 cos^2 alpha)/(3R),
//     whose neglected terms are O((max(a,b)/R)^2) < 1e-17 relative; it is also the exact
//     pure-translation limit (R = infinity) and cannot overflow.
//
// Hot path: no allocation, no exceptions, inline. Preconditions (a, b > 0 finite, aspect
// ratio within [kFrictionMinAspect, 1/kFrictionMinAspect], muN >= 0 finite, R >= 0 finite,
// alpha finite, sense = +/-1) are checked by the *_checked entry points, which throw
// nanopush::InputError, and by NANOPUSH_FRICTION_ASSERT in debug builds.
#pragma once

#include <cassert>
#include <cmath>

#include "nanopush/models/printed_reading.hpp"
#include "nanopush/numerics/scalar.hpp"
#if defined(__GNUC__) && defined(__SSE2__)
#include <emmintrin.h>
#endif

#ifndef NANOPUSH_FRICTION_ASSERT
#define NANOPUSH_FRICTION_ASSERT(cond) assert(cond)
#endif

namespace nanopush {

/// Friction resultant in body axes: force (fx, fy) [N] and moment mf about the CM (z) [N m].
struct FrictionWrench {
  double fx, fy, mf;
};

/// Switch from the corner-term closed form to the far-field form, in units of max(a, b).
inline constexpr double kFrictionFarField = 3.0;
/// Far-field Gauss-Legendre rule by distance (units of max(a, b)): 12 points from
/// kFrictionFarField, then 8, 6 and 4 points from these values. The series' remainder after the
/// exactly integrated degree 2n - 1 falls like (L/(2R))^(2n); each rule is used only where it
/// is below 1e-16 (docs/friction.md has the measured errors).
inline constexpr double kFrictionGl8From = 8.0, kFrictionGl6From = 24.0, kFrictionGl4From = 512.0;

/// Switch from the far-field form to the asymptotic (translation + 1/R moment) form.
inline constexpr double kFrictionAsymptotic = 1e9;
/// Smallest accepted aspect ratio min(a,b)/max(a,b) (tested down to this limit at full
/// accuracy: the closed form differences the thin side without cancellation).
inline constexpr double kFrictionMinAspect = 1e-12;

namespace friction_detail {

/// log(1 + x), accurate for small x (Kahan's device), spelled as in fortran/rectfr.f (FRLG1P)
/// so that the C++ and FORTRAN 77 engines round identically.
/// Templated on the scalar for the extended-precision path (friction_extended.hpp); in double
/// the operations are those of FRLG1P.
template <typename S>
inline S log1p_kahan(S x) noexcept {
  const S u = 1.0 + x;
  return (u == 1.0) ? x : num::log(u) * (x / (u - 1.0));
}

/// asinh(q) accurate over the whole range, as FRASNH in fortran/rectfr.f.
/// In long double and quad the library's asinh (already accurate over the whole range).
template <typename S>
inline S asinh_portable(S q) noexcept {
  if constexpr (!std::is_same_v<S, double>) {
    return num::asinh(q);
  } else {
    const double aq = std::fabs(q);
    double t;
    if (aq > 1e8)
      t = std::log(2.0 * aq) + 0.25 / (aq * aq);
    else if (aq >= 0.5)
      t = std::log(aq + std::sqrt(aq * aq + 1.0));
    else
      t = log1p_kahan(aq + aq * aq / (1.0 + std::sqrt(1.0 + aq * aq)));
    return std::copysign(t, q);
  }
}

/// sqrt(x^2 + y^2) without overflow, as FRHYPT in fortran/rectfr.f.
inline double hypot_portable(double x, double y) noexcept {
  double ax = std::fabs(x), ay = std::fabs(y);
  if (ax < ay) {
    const double t = ax;
    ax = ay;
    ay = t;
  }
  if (ax == 0.0) return 0.0;
  const double t = ay / ax;
  return ax * std::sqrt(1.0 + t * t);
}

/// Two doubles evaluated together (the two long-side ends of form 1, two node pairs of form 2):
/// GCC/Clang vector extensions, SSE2 square roots on x86-64 (correctly rounded, like
/// std::sqrt, so the lanes round as scalar code would); elsewhere lane by lane.
#if defined(__GNUC__)
typedef double Lane2 __attribute__((vector_size(2 * sizeof(double))));
inline Lane2 lane_sqrt(Lane2 x) noexcept {
#if defined(__SSE2__)
  return reinterpret_cast<Lane2>(_mm_sqrt_pd(reinterpret_cast<__m128d>(x)));
#else
  return Lane2{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
}
#else
struct Lane2 {
  double v[2];
  double operator[](int i) const noexcept { return v[i]; }
  double& operator[](int i) noexcept { return v[i]; }
};
inline Lane2 operator+(Lane2 p, Lane2 q) noexcept { return {p[0] + q[0], p[1] + q[1]}; }
inline Lane2 operator-(Lane2 p, Lane2 q) noexcept { return {p[0] - q[0], p[1] - q[1]}; }
inline Lane2 operator*(Lane2 p, Lane2 q) noexcept { return {p[0] * q[0], p[1] * q[1]}; }
inline Lane2 operator/(Lane2 p, Lane2 q) noexcept { return {p[0] / q[0], p[1] / q[1]}; }
inline Lane2 operator+(Lane2 p, double q) noexcept { return {p[0] + q, p[1] + q}; }
inline Lane2 operator-(Lane2 p, double q) noexcept { return {p[0] - q, p[1] - q}; }
inline Lane2 operator*(Lane2 p, double q) noexcept { return {p[0] * q, p[1] * q}; }
inline Lane2 operator/(Lane2 p, double q) noexcept { return {p[0] / q, p[1] / q}; }
inline Lane2 operator+(double p, Lane2 q) noexcept { return {p + q[0], p + q[1]}; }
inline Lane2 operator-(double p, Lane2 q) noexcept { return {p - q[0], p - q[1]}; }
inline Lane2 operator*(double p, Lane2 q) noexcept { return {p * q[0], p * q[1]}; }
inline Lane2 operator/(double p, Lane2 q) noexcept { return {p / q[0], p / q[1]}; }
inline Lane2 lane_sqrt(Lane2 x) noexcept { return {std::sqrt(x[0]), std::sqrt(x[1])}; }
#endif

/// u^2 asinh(v/|u|), continuous with value 0 at u = 0; never NaN for finite u, v.
template <typename S>
inline S sq_asinh(S u, S v) noexcept {
  const S au = num::abs(u);
  if (au == 0.0) return 0.0;
  const S q = v / au;
  if (num::abs(q) < 1e150) return u * u * asinh_portable(q);
  // asinh(q) = sign(q) (ln 2|q| + O(q^-2)); ln|v| - ln|u| avoids overflow of q.
  return num::copysign(u * u * (num::log(S(2.0) * num::abs(v)) - num::log(au)), v);
}

/// The three rectangle integrals, scaled by the area:
///   ix = <X/r>, iy = <Y/r>, km = <(x X + y Y)/r>   (<.> = mean over the rectangle)
template <typename S>
struct MeanIntegralsT {
  S ix, iy, km;
};
using MeanIntegrals = MeanIntegralsT<double>;

/// Differences across y of the corner antiderivatives at fixed X, y0 = yc - b, y1 = yc + b:
///   gx = FX(X, y1) - FX(X, y0), gy = FY(...) - FY(...), gr = Fr(...) - Fr(...),
/// formed without cancellation when b << |yc| (a thin contact): y1 - y0 = 2b, y1 + y0 = 2yc,
/// r1 - r0 = 4 b yc/(r0 + r1), y1 r1 - y0 r0 = b (r0 + r1) + yc (r1 - r0), and for y0, y1 of
/// one sign the asinh addition formula
///   asinh(y1/|X|) - asinh(y0/|X|) = asinh(4 b yc/(y1 r0 + y0 r1)),
///   asinh(X/|y1|) - asinh(X/|y0|) = asinh(-4 b yc X/(y0 y1 (r0 + r1))).
template <typename S>
struct YDifferenceT {
  S gx, gy, gr;
};
template <typename S>
inline YDifferenceT<S> y_difference(S X, S yc, S b) noexcept {
  const S y0 = yc - b, y1 = yc + b;
  const S r0 = num::sqrt(X * X + y0 * y0), r1 = num::sqrt(X * X + y1 * y1);
  const S rs = r0 + r1;
  const S dr = rs > 0.0 ? S(4.0 * b * yc / rs) : S(0.0);  // r1 - r0
  const S dyr = b * rs + yc * dr;                         // y1 r1 - y0 r0
  S x2da, dy2b, dy3b;  // X^2 D[asinh(Y/|X|)], D[Y^2 asinh(X/|Y|)], D[Y^3 asinh(X/|Y|)]
  const S ax = num::abs(X);
  const S ymin = num::abs(y0) < num::abs(y1) ? num::abs(y0) : num::abs(y1);
  if ((y0 > 0.0 || y1 < 0.0) && ymin >= 1e-150 * ax) {
    const S y01 = y0 * y1;  // > 0
    const S da = asinh_portable(S(4.0 * b * yc / (y1 * r0 + y0 * r1)));
    const S b0 = asinh_portable(S(X / num::abs(y0))), b1 = asinh_portable(S(X / num::abs(y1)));
    const S db = asinh_portable(S(-4.0 * b * yc * X / (y01 * rs)));
    x2da = X * X * da;
    dy2b = 2.0 * b * yc * (b1 + b0) + 0.5 * (y1 * y1 + y0 * y0) * db;
    dy3b = b * (y1 * y1 + y1 * y0 + y0 * y0) * (b1 + b0) + 0.5 * (y1 * y1 * y1 + y0 * y0 * y0) * db;
  } else {  // y0 <= 0 <= y1: |y0|, |y1| <= 2b, nothing to cancel
    x2da = sq_asinh(X, y1) - sq_asinh(X, y0);
    dy2b = sq_asinh(y1, X) - sq_asinh(y0, X);
    dy3b = y1 * sq_asinh(y1, X) - y0 * sq_asinh(y0, X);
  }
  return {S(0.5 * (dyr + x2da)), S(0.5 * (X * dr + dy2b)), S(X * dyr / 3.0 + (X * x2da + dy3b) / 6.0)};
}

/// Form 1 as the F77 routine evaluates it (the faithful method's form, kept for the tests and
/// the benchmark, and the fallback of closed_form for coordinates below 1e-100 max(a, b)): corner-term closed form,
/// Delta_x Delta_y F with the y difference taken across the thinner side (transposing x and y
/// when a < b) by y_difference, so a thin contact loses no digits; the x difference cancels
/// like (R/max(a,b))^2 only. 21 log/sqrt calls. Lengths in units of max(a, b).
template <typename S>
inline MeanIntegralsT<S> closed_form_reference(S a, S b, S xc, S yc) noexcept {
  const bool transpose = a < b;
  const S ta = transpose ? b : a, tb = transpose ? a : b;
  const S txc = transpose ? yc : xc, tyc = transpose ? xc : yc;
  const YDifferenceT<S> g1 = y_difference(S(txc + ta), tyc, tb), g0 = y_difference(S(txc - ta), tyc, tb);
  const S area = 4.0 * a * b;
  const S tix = (g1.gx - g0.gx) / area, tiy = (g1.gy - g0.gy) / area;
  const S km = (g1.gr - g0.gr) / area - txc * tix - tyc * tiy;
  return transpose ? MeanIntegralsT<S>{tiy, tix, km} : MeanIntegralsT<S>{tix, tiy, km};
}

/// The plain corner sum +F(x1,y1) - F(x0,y1) - F(x1,y0) + F(x0,y0) (for tests and docs:
/// loses about log10(max(a,b)/min(a,b)) digits on thin contacts).
inline MeanIntegrals closed_form_corner_sum(double a, double b, double xc, double yc) noexcept {
  const double xs[2] = {xc - a, xc + a};
  const double ys[2] = {yc - b, yc + b};
  double sx = 0.0, sy = 0.0, sr = 0.0;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double X = xs[i], Y = ys[j];
      const double r = std::sqrt(X * X + Y * Y);
      const double ax = sq_asinh(X, Y);  // X^2 asinh(Y/|X|)
      const double ay = sq_asinh(Y, X);  // Y^2 asinh(X/|Y|)
      const double fx = 0.5 * (Y * r + ax);
      const double fy = 0.5 * (X * r + ay);
      const double fr = X * Y * r / 3.0 + (X * ax + Y * ay) / 6.0;
      const double sg = (i == j) ? 1.0 : -1.0;  // +F(x1,y1) - F(x0,y1) - F(x1,y0) + F(x0,y0)
      sx += sg * fx;
      sy += sg * fy;
      sr += sg * fr;
    }
  }
  const double area = 4.0 * a * b;
  const double ix = sx / area, iy = sy / area;
  return {ix, iy, sr / area - xc * ix - yc * iy};
}

/// Form 1: the corner-term closed form of closed_form_reference (same antiderivatives, same
/// thin-side difference without cancellation), with 4 logarithms and 4 square roots instead of
/// 21 log/sqrt calls (issue 24). In the frame where y is the thinner side (transposed when
/// a < b) and, by the symmetry y -> -y, yc = w >= 0 (<Y/r> changes sign, the rest does not),
/// the two long-side ends X0,1 = xc -+ a are evaluated together (Lane2) with
/// y0,1 = w -+ b, r_i = sqrt(X^2 + y_i^2):
///   X^2 [asinh(y1/|X|) - asinh(y0/|X|)] = X^2 log1p((2b + r1 - r0)/(y0 + r0)),
///   asinh(X/|y|) = sign(X) ln((|X| + r)/|y|),
/// and the terms of Delta_y (Y^n asinh(X/|Y|)) whose coefficients do not depend on X are
/// differenced across x inside one logarithm each. For y0 > y1/2 (w > 3b, the thin-side
/// difference):
///   Delta_x [asinh(X/y1) + asinh(X/y0)] = ln of a ratio (or product) of (|X| + r0)(|X| + r1),
///   Delta_x [asinh(X/y1) - asinh(X/y0)] = Delta_x asinh(z), z = -4 b w X/(y0 y1 (r0 + r1)),
/// the last with zeta = |z|, C = sqrt(1 + z^2) = (X^2 (y0^2 + y1^2) + y0^2 y1^2)/((r0 r1 + X^2) y0 y1)
/// (no square root), E = zeta + C: for X of one sign ln(E1/E0), or near E1 = E0
/// log1p((zeta1 - zeta0)(1 + (zeta1 + zeta0)/(C1 + C0))/E0); for X0 < 0 < X1 the sum
/// log1p(u0 + u1 + u0 u1), u = zeta + zeta^2/(1 + C). For y0 <= y1/2 (nothing to cancel
/// across y) asinh(X/|y_i|) is differenced across x at each y_i. Coordinates other than 0
/// below 1e-100 (in units of max(a, b)) go to closed_form_reference, where these quotients
/// would underflow.
inline MeanIntegrals closed_form(double a, double b, double xc, double yc) noexcept {
  const bool transpose = a < b;
  const double ta = transpose ? b : a, tb = transpose ? a : b;
  const double txc = transpose ? yc : xc, tyc = transpose ? xc : yc;
  const double w = std::fabs(tyc);
  const double y0 = w - tb, y1 = w + tb;
  const double X0 = txc - ta, X1 = txc + ta;
  constexpr double tiny = 1e-100;
  const auto tiny_nonzero = [](double v) { return v != 0.0 && std::fabs(v) < tiny; };
  if (tiny_nonzero(X0) || tiny_nonzero(X1) || tiny_nonzero(y0)) return closed_form_reference(a, b, xc, yc);
  const Lane2 X = {X0, X1}, AX = {std::fabs(X0), std::fabs(X1)};
  const Lane2 XX = X * X;
  const Lane2 r0 = lane_sqrt(XX + y0 * y0), r1 = lane_sqrt(XX + y1 * y1);
  const Lane2 rs = r0 + r1;                 // >= y1 > 0
  const double bw4 = 4.0 * tb * w;
  const Lane2 dr = bw4 / rs;                // r1 - r0
  const Lane2 dyr = tb * rs + w * dr;       // y1 r1 - y0 r0
  // X^2 Delta_y asinh(Y/|X|) = X^2 log1p(delta), delta = (2b + dr)/(y0 + r0) >= 0, with
  // y0 + r0 = X^2/(r0 - y0) for y0 < 0; zero at X = 0. log1p as log1p_kahan, lane-wise.
  // (2b + dr = (2b rs + 4bw)/rs: one division on the way to the logarithm.)
  const Lane2 delta = y0 > 0.0 ? (2.0 * tb * rs + bw4) / (rs * (y0 + r0)) : (2.0 * tb * rs + bw4) * (r0 - y0) / (rs * XX);
  const Lane2 u1p = 1.0 + delta;
  const Lane2 kahan = delta / (u1p - 1.0);
  Lane2 x2da;
  for (int i = 0; i < 2; ++i)
    x2da[i] = XX[i] == 0.0 ? 0.0 : XX[i] * (u1p[i] == 1.0 ? delta[i] : std::log(u1p[i]) * kahan[i]);
  // Delta_x of a sum of asinh(X/|y|) = sign(X) ln(N/yy): ln(Q1/Q0), Q = (N/yy)^sign(X), from
  // N0 = N(X0), N1 = N(X1) (X1 > X0, so X1 < 0 <= X0 cannot occur; N = yy at X = 0).
  const auto log_dx = [X0, X1](double N0, double N1, double yy) {
    if (X0 >= 0.0) return std::log(N1 / N0);
    if (X1 <= 0.0) return std::log(N0 / N1);
    return std::log(N1 * N0 / (yy * yy));
  };
  double dy2b, dy3b;  // Delta_x Delta_y of Y^2 asinh(X/|Y|) and Y^3 asinh(X/|Y|)
  if (y0 > 0.5 * y1) {  // w > 3b: the thin-side difference
    const double y01 = y0 * y1;
    const Lane2 N = (AX + r0) * (AX + r1);
    const double S = log_dx(N[0], N[1], y01);  // Delta_x [asinh(X/y1) + asinh(X/y0)]
    // Delta_x [asinh(X/y1) - asinh(X/y0)] = Delta_x asinh(z), z = -sign(X) zeta.
    const Lane2 zeta = bw4 * AX / (y01 * rs);
    const Lane2 C = (XX * (y0 * y0 + y1 * y1) + y01 * y01) / ((r0 * r1 + XX) * y01);
    const Lane2 E = zeta + C;  // exp(asinh zeta)
    double D;
    if (X0 < 0.0 && X1 > 0.0) {
      const Lane2 u = zeta + zeta * zeta / (1.0 + C);  // E - 1
      D = -log1p_kahan(u[0] + u[1] + u[0] * u[1]);      // -(asinh zeta1 + asinh zeta0)
    } else {
      const double cs = C[0] + C[1];
      const double t = bw4 * (AX[1] * rs[0] - AX[0] * rs[1]) * (cs + zeta[0] + zeta[1]) /
                       (y01 * rs[0] * rs[1] * cs * E[0]);  // E1/E0 - 1
      const double dd = std::fabs(t) < 0.5 ? log1p_kahan(t) : std::log(E[1] / E[0]);
      D = X0 >= 0.0 ? -dd : dd;  // z = -zeta for X >= 0, +zeta for X <= 0
    }
    dy2b = 2.0 * tb * w * S + 0.5 * (y1 * y1 + y0 * y0) * D;
    dy3b = tb * (y1 * y1 + y1 * y0 + y0 * y0) * S + 0.5 * (y1 * y1 * y1 + y0 * y0 * y0) * D;
  } else {
    // |y0| <= y1/2: nothing to cancel across y (the sum/difference form above would cancel
    // instead, its asinh(X/|y0|) growing as y0 -> 0). Delta_x asinh(X/|y|) at each y != 0.
    const Lane2 N1 = AX + r1;
    const double B1 = log_dx(N1[0], N1[1], y1);
    double B0 = 0.0;
    if (y0 != 0.0) {
      const Lane2 N0 = AX + r0;
      B0 = log_dx(N0[0], N0[1], -y0);
    }
    dy2b = y1 * y1 * B1 - y0 * y0 * B0;
    dy3b = y1 * y1 * y1 * B1 - y0 * y0 * y0 * B0;
  }
  const double inv2 = 1.0 / (8.0 * a * b), inv6 = inv2 * (1.0 / 3.0);  // 1/(2 area), 1/(6 area)
  const double tix = ((dyr[1] - dyr[0]) + (x2da[1] - x2da[0])) * inv2;
  const double tiw = ((X1 * dr[1] - X0 * dr[0]) + dy2b) * inv2;
  const double gr = (2.0 * (X1 * dyr[1] - X0 * dyr[0]) + ((X1 * x2da[1] - X0 * x2da[0]) + dy3b)) * inv6;
  const double km = gr - txc * tix - w * tiw;
  const double tiy = tyc < 0.0 ? -tiw : tiw;
  return transpose ? MeanIntegrals{tiy, tix, km} : MeanIntegrals{tix, tiy, km};
}

/// Gauss-Legendre rules on [-1, 1] with 4, 6, 8 and 12 points: positive nodes and weights.
inline constexpr double kGl4x[2] = {0.3399810435848562648026658, 0.8611363115940525752239465};
inline constexpr double kGl4w[2] = {0.6521451548625461426269361, 0.3478548451374538573730639};
inline constexpr double kGl6x[3] = {0.2386191860831969086305017, 0.6612093864662645136613996,
                                    0.9324695142031520278123016};
inline constexpr double kGl6w[3] = {0.4679139345726910473898703, 0.3607615730481386075698335,
                                    0.1713244923791703450402961};
inline constexpr double kGl8x[4] = {0.1834346424956498049394761, 0.525532409916328985817739,
                                    0.7966664774136267395915539, 0.9602898564975362316835609};
inline constexpr double kGl8w[4] = {0.3626837833783619829651504, 0.3137066458778872873379622,
                                    0.222381034453374470544356, 0.1012285362903762591525314};
inline constexpr double kGl12x[6] = {0.1252334085114689154724414, 0.3678314989981801937526915,
                                     0.5873179542866174472967024, 0.7699026741943046870368938,
                                     0.9041172563704748566784659, 0.9815606342467192506905491};
inline constexpr double kGl12w[6] = {0.2491470458134027850005624, 0.2334925365383548087608499,
                                     0.2031674267230659217490645, 0.1600783285433462263346525,
                                     0.1069393259953184309602547, 0.04717533638651182719461596};

/// Form 2: far field. Point-symmetrised integrands at (x, y) and (-x, -y):
///   u(+) + u(-) for the unit vector u = (X, Y)/r, and for the moment integrand
///   h = (x X + y Y)/r, with d = x Xc + y Yc, e = x Yc - y Xc, rho^2 = x^2 + y^2, R = |(Xc, Yc)|,
///   h(+) + h(-) = e^2/R^2 (1/r+ + 1/r-) + 8 d^2 e^2 / (R^2 r+ r- (r+ + r-)(r+ r- + R^2 - rho^2)),
/// a sum of non-negative terms (the O(R) odd part of h cancels analytically).
/// Requires the rectangle well away from the iCOR (rho >= kFrictionFarField).
/// gx, gw: the h positive nodes and weights of a 2h-point Gauss-Legendre rule.
/// As the F77 routine evaluates it (three square roots and three divisions per pair: the
/// faithful method's form); far_field is the production form.
template <typename S>
inline MeanIntegralsT<S> far_field_reference(S a, S b, S xc, S yc, const S* gx, const S* gw, int h) noexcept {
  const S r = num::sqrt(xc * xc + yc * yc), inv_r2 = 1.0 / (r * r);
  S sx = 0.0, sy = 0.0, sk = 0.0;
  for (int i = 0; i < h; ++i) {
    const S x = a * gx[i];
    S tx = 0.0, ty = 0.0, tk = 0.0;
    for (int j = 0; j < 2 * h; ++j) {
      const S y = (j < h) ? S(b * gx[j]) : S(-b * gx[j - h]);
      const S wy = (j < h) ? gw[j] : gw[j - h];
      const S xp = xc + x, yp = yc + y, xm = xc - x, ym = yc - y;
      const S rp = num::sqrt(xp * xp + yp * yp), rm = num::sqrt(xm * xm + ym * ym);
      const S ip = 1.0 / rp, im = 1.0 / rm;
      const S d = x * xc + y * yc, e = x * yc - y * xc;  // rho.c and rho x c
      const S rho = num::sqrt(x * x + y * y);
      const S rr = rp * rm;
      tx += wy * (xp * ip + xm * im);
      ty += wy * (yp * ip + ym * im);
      // h(+) + h(-) = e^2/R^2 (1/r+ + 1/r-) + 8 d^2 e^2 / (R^2 r+ r- (r+ + r-)(r+ r- + R^2 - rho^2)):
      // both terms >= 0, so no cancellation at any orientation (docs/friction.md).
      const S ee = e * e * inv_r2;
      tk += wy * (ee * (ip + im) + 8.0 * d * d * ee / (rr * (rp + rm) * (rr + (r - rho) * (r + rho))));
    }
    sx += gw[i] * tx;
    sy += gw[i] * ty;
    sk += gw[i] * tk;
  }
  // Sum of weights over [-1,1]^2 is 4; each symmetric pair was summed over half the x nodes,
  // so the mean is (pair sum)/(2 * 4) * 2 = pair sum / 4.
  return {S(0.25 * sx), S(0.25 * sy), S(0.25 * sk)};
}

/// Form 2 (production): the integrands of far_field_reference, two node pairs at a time (the
/// y nodes +-y_j in the two lanes), the rule's size a compile-time constant (H positive
/// nodes). The moment's uses q = R^2 - rho^2 (>= 7 L^2 here, no cancellation) for
/// (R - rho)(R + rho), and 1/R^2 once at the end. For the 12- and 8-point rules (R < 24 L) one
/// division serves both pairs' terms: with s = r+ + r-, P = s (r+ r- + q), v = w_j/(r+ r- P),
///   w_j (X+/r+ + X-/r-) = (X+ r- + X- r+) P v,
///   w_j R^2 (h(+) + h(-)) = e^2 (s P + 8 d^2) v   (still a sum of non-negative terms),
/// two two-lane square roots and one two-lane division per two pairs where far_field_reference
/// takes six scalar square roots and six divisions. For the 6- and 4-point rules (R >= 24 L)
/// the force terms are X+/r+ + X-/r- as there (three two-lane divisions): with the unit
/// vectors nearly parallel the fused form's two extra roundings of w_j/(r+ r-) no longer
/// average out, and |f| would be 2 eps from muN where the test allows 4e-16.
template <int H>
inline MeanIntegrals far_field(double a, double b, double xc, double yc, const double (&gx)[H],
                               const double (&gw)[H]) noexcept {
  const double r2 = xc * xc + yc * yc;
  Lane2 sx = {0.0, 0.0}, sy = {0.0, 0.0}, sk = {0.0, 0.0};
  for (int i = 0; i < H; ++i) {
    const double x = a * gx[i];
    const double xp = xc + x, xm = xc - x;
    Lane2 tx = {0.0, 0.0}, ty = {0.0, 0.0}, tk = {0.0, 0.0};
    for (int j = 0; j < H; ++j) {
      const double yj = b * gx[j];
      const Lane2 y = {yj, -yj};
      const Lane2 yp = yc + y, ym = yc - y;
      const Lane2 rp = lane_sqrt(xp * xp + yp * yp), rm = lane_sqrt(xm * xm + ym * ym);
      const Lane2 d = x * xc + y * yc, e = x * yc - y * xc;  // rho.c and rho x c
      const Lane2 q = r2 - (x * x + y * y);                  // R^2 - rho^2
      const Lane2 rr = rp * rm, s = rp + rm;
      if constexpr (H >= 4) {
        const Lane2 P = s * (rr + q);
        const Lane2 v = gw[j] / (rr * P);
        const Lane2 Pv = P * v;
        tx += (xp * rm + xm * rp) * Pv;
        ty += (yp * rm + ym * rp) * Pv;
        tk += (e * e) * (s * P + 8.0 * (d * d)) * v;
      } else {
        const Lane2 ip = 1.0 / rp, im = 1.0 / rm;
        tx += gw[j] * (xp * ip + xm * im);
        ty += gw[j] * (yp * ip + ym * im);
        tk += gw[j] * (e * e) * ((ip + im) + 8.0 * (d * d) / (rr * s * (rr + q)));
      }
    }
    sx += gw[i] * tx;
    sy += gw[i] * ty;
    sk += gw[i] * tk;
  }
  return {0.25 * (sx[0] + sx[1]), 0.25 * (sy[0] + sy[1]), 0.25 * (sk[0] + sk[1]) / r2};
}

/// Form dispatcher in units of L = max(a, b): a, b <= 1, rho = R/L, (c, s) = (cos, sin) alpha.
/// Returns the mean integrals except in the asymptotic regime, where it sets `asym` and
/// returns ix = c, iy = s, km = (a^2 s^2 + b^2 c^2)/(3 rho) (exact to O(rho^-2)).
inline MeanIntegrals mean_integrals(double a, double b, double rho, double c, double s) noexcept {
  if (!(rho < kFrictionAsymptotic)) {  // also rho = inf
    return {c, s, (a * a * s * s + b * b * c * c) / (3.0 * rho)};
  }
  const double xc = rho * c, yc = rho * s;
  if (rho < kFrictionFarField) return closed_form(a, b, xc, yc);
  if (rho < kFrictionGl8From) return far_field(a, b, xc, yc, kGl12x, kGl12w);
  if (rho < kFrictionGl6From) return far_field(a, b, xc, yc, kGl8x, kGl8w);
  if (rho < kFrictionGl4From) return far_field(a, b, xc, yc, kGl6x, kGl6w);
  return far_field(a, b, xc, yc, kGl4x, kGl4w);
}

/// mean_integrals with the F77 routine's forms (closed_form_reference, far_field_reference):
/// the faithful method's path (see rectangle_friction_from_velocity_reference).
inline MeanIntegrals mean_integrals_reference(double a, double b, double rho, double c, double s) noexcept {
  if (!(rho < kFrictionAsymptotic)) return {c, s, (a * a * s * s + b * b * c * c) / (3.0 * rho)};
  const double xc = rho * c, yc = rho * s;
  if (rho < kFrictionFarField) return closed_form_reference(a, b, xc, yc);
  if (rho < kFrictionGl8From) return far_field_reference(a, b, xc, yc, kGl12x, kGl12w, 6);
  if (rho < kFrictionGl6From) return far_field_reference(a, b, xc, yc, kGl8x, kGl8w, 4);
  if (rho < kFrictionGl4From) return far_field_reference(a, b, xc, yc, kGl6x, kGl6w, 3);
  return far_field_reference(a, b, xc, yc, kGl4x, kGl4w, 2);
}

inline FrictionWrench wrench_from_means(const MeanIntegrals& m, double muN, double sense,
                                        double length) noexcept {
  return {muN * sense * m.iy, -muN * sense * m.ix, -muN * sense * m.km * length};
}

}  // namespace friction_detail

/// Pure translation with body-axis CM velocity (vx, vy) [m/s]: f = -muN v/|v|, mf = 0;
/// the zero wrench when v = 0.
inline FrictionWrench rectangle_friction_translation(double muN, double vx, double vy) noexcept {
  const double v = friction_detail::hypot_portable(vx, vy);
  if (!(v > 0.0)) return {0.0, 0.0, 0.0};
  return {-muN * (vx / v), -muN * (vy / v), 0.0};
}

namespace friction_detail {

using MeansFn = MeanIntegrals (*)(double, double, double, double, double) noexcept;

/// rectangle_friction_wrench and rectangle_friction_from_velocity with a choice of the mean
/// integrals: mean_integrals (production) or mean_integrals_reference (the F77 routine's forms,
/// for the faithful method, the tests and the benchmark).
template <MeansFn Means>
inline FrictionWrench wrench_with(double a, double b, double muN, double R, double alpha, int sense) noexcept {
  NANOPUSH_FRICTION_ASSERT(a > 0.0 && b > 0.0 && R >= 0.0 && (sense == 1 || sense == -1));
  const double L = a > b ? a : b;
  const auto m = Means(a / L, b / L, R / L, std::cos(alpha), std::sin(alpha));
  return wrench_from_means(m, muN, sense < 0 ? -1.0 : 1.0, L);
}

template <MeansFn Means>
inline FrictionWrench from_velocity_with(double a, double b, double muN, double vx, double vy,
                                         double omega) noexcept {
  NANOPUSH_FRICTION_ASSERT(a > 0.0 && b > 0.0);
  const double L = a > b ? a : b;
  const double v = hypot_portable(vx, vy);
  if (omega == 0.0) return rectangle_friction_translation(muN, vx, vy);
  const double sense = omega > 0.0 ? 1.0 : -1.0;
  // CM seen from the iCOR: -c = (vy, -vx)/omega = R (cos alpha, sin alpha).
  double c = 1.0, s = 0.0;  // any direction at R = 0
  if (v > 0.0) {
    c = sense * vy / v;
    s = -sense * vx / v;
  }
  const double rho = (v / std::fabs(omega)) / L;  // may be +inf: asymptotic form
  return wrench_from_means(Means(a / L, b / L, rho, c, s), muN, sense, L);
}

/// The entry points through the F77 routine's forms (the corner-by-corner closed form and three
/// divisions per far-field pair; mean_integrals_reference): the same wrench within a few ulps
/// at 2-2.5 x the cost. The faithful method evaluates these, so that its steps are the F77
/// engine's to the last bit (RoughBarModel::f77_forms).
inline FrictionWrench rectangle_friction_wrench_reference(double a, double b, double muN, double R, double alpha,
                                                          int sense) noexcept {
  return wrench_with<mean_integrals_reference>(a, b, muN, R, alpha, sense);
}
inline FrictionWrench rectangle_friction_from_velocity_reference(double a, double b, double muN, double vx,
                                                                 double vy, double omega) noexcept {
  return from_velocity_with<mean_integrals_reference>(a, b, muN, vx, vy, omega);
}

}  // namespace friction_detail

/// Friction wrench for a 2a x 2b rectangle (a: half-width along body x', b: half-length along
/// body y', m), uniform pressure, total normal friction muN = mu N [N], iCOR at
/// c = -R (cos alpha, sin alpha) in body axes (R [m] >= 0, alpha [rad]), rotating
/// counter-clockwise (sense = +1, omega > 0) or clockwise (sense = -1). Body axes, SI.
/// Unchecked hot path (preconditions in the header comment); see *_checked.
inline FrictionWrench rectangle_friction_wrench(double a, double b, double muN, double R, double alpha,
                                                int sense) noexcept {
  return friction_detail::wrench_with<friction_detail::mean_integrals>(a, b, muN, R, alpha, sense);
}

/// Friction wrench from the body-axis rigid velocity: CM velocity (vx, vy) [m/s] and angular
/// rate omega [rad/s]. The iCOR is c = (-vy, vx)/omega (docs/models.md §0); as omega -> 0 the
/// result joins rectangle_friction_translation smoothly (the moment vanishes like omega);
/// zero wrench at rest. Sense = sign(omega).
inline FrictionWrench rectangle_friction_from_velocity(double a, double b, double muN, double vx, double vy,
                                                       double omega) noexcept {
  return friction_detail::from_velocity_with<friction_detail::mean_integrals>(a, b, muN, vx, vy, omega);
}

/// Checked entry points: throw nanopush::InputError naming the field, value and allowed range
/// (a, b > 0 finite with min/max >= kFrictionMinAspect; muN >= 0 finite; R >= 0 finite;
/// alpha, velocities finite; sense = +1 or -1), then evaluate the hot-path function.
FrictionWrench rectangle_friction_wrench_checked(double a, double b, double muN, double R, double alpha,
                                                 int sense);
FrictionWrench rectangle_friction_translation_checked(double muN, double vx, double vy);
FrictionWrench rectangle_friction_from_velocity_checked(double a, double b, double muN, double vx, double vy,
                                                        double omega);

/// Which evaluation form rectangle_friction_wrench uses at this geometry (for docs and tests):
/// 0 = corner closed form; 1, 2, 3, 4 = far-field series with the 12-, 8-, 6-, 4-point
/// Gauss-Legendre rule; 5 = asymptotic.
int rectangle_friction_form(double a, double b, double R);

/// The thesis' printed closed forms (eqs 3.45, 3.46, 3.47 with 3.48), transcribed literally
/// for the errata tests: muN = 1, s = +1, body axes. May return NaN/Inf where the printed
/// logarithms are undefined. Not for production use.
FrictionWrench thesis_printed_friction(double a, double b, double R, double alpha);
/// The same forms with the corrections of docs/errata.md (sign of fy', cubes in C4, sense
/// factor on mf), still in the printed logarithmic form: correct where its logarithms are
/// defined and R is moderate, NaN on iCOR edge lines, cancelling as R grows. For the errata tests.
FrictionWrench thesis_corrected_friction(double a, double b, double R, double alpha, int sense);

/// The `printed` friction law (docs/rough.md): the wrench of eqs (3.45)-(3.48) under a reading of
/// their slips (by default exactly as printed: fy' with the printed sign, mf without
/// sign(theta-dot) and with squares in C4: errata F1-F3), at the iCOR implied by the body-axis
/// velocity (vx, vy, omega) as in rectangle_friction_from_velocity, SI in and out, body axes
/// (eq 3.50 is the rotation to world axes: RoughBarModel). C4 with squares is not dimensionally
/// consistent: the forms are evaluated with lengths in kPrintedLengthUnit (nanometres, the unit of
/// every length in the thesis' captions; in metres the moment is ~1e6 times too large and no run
/// leaves t = 0, docs/rough.md); cubes are consistent and evaluated in the same unit. On an edge
/// line of the contact a corner term h^k ln(u/v) whose logarithm is undefined is taken as its
/// limit 0 (errata F4); at omega = 0 (R = infinity) pure translation f = -muN v/|v|, mf = 0; zero
/// at rest. The printed forms cancel as R grows (errata F5), as the thesis' program would have.
/// Bit-identical to FRPRNT (fortran/rgbar.f) under every reading.
FrictionWrench thesis_printed_friction_from_velocity(double a, double b, double muN, double vx, double vy,
                                                     double omega, const PrintedReading& reading = {}) noexcept;
/// The unit of length in which the printed forms are evaluated [m] (FRPRNT: the same constant).
inline constexpr double kPrintedLengthUnit = 1e-9;

}  // namespace nanopush
