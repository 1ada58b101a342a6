// Bulirsch–Stoer: dense output (Hairer, Nørsett & Wanner, §II.9; the interpolation of their
// code ODEX; docs/bulirsch_stoer.md). The store of every right-hand side value of every line
// (line j has 4j-1 of them) and the midpoint states, the interpolation polynomial of the last
// accepted step with its error estimate, and its evaluation.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "nanopush/numerics/bs/tables.hpp"
#include "nanopush/numerics/integration.hpp"
#include "nanopush/numerics/scalar.hpp"
#include "nanopush/numerics/simd_pairs.hpp"

namespace nanopush::bs {

template <typename Scalar, int N>
class DenseOutput {
 public:
  static constexpr int kBatch = 4;  ///< outputs interpolated together

  /// Work space for n components, allocated once; the tables built here rather than in a step.
  void allocate(int n) {
    n_ = n;
    const auto nn = static_cast<std::size_t>(n_);
    fs_.assign(static_cast<std::size_t>(line_offset(kKmaxLimit + 1)) * nn, Scalar(0));
    ys_.assign(static_cast<std::size_t>(kKmaxLimit + 2) * nn, Scalar(0));
    dcoef_.assign(static_cast<std::size_t>(kMuLimit + 5) * nn, Scalar(0));
    yb_.assign(static_cast<std::size_t>(kBatch) * nn, Scalar(0));
    (void)dense_tables<Scalar>();  // built once per process
    (void)dense_terms<Scalar>();
  }

  /// The RHS slots of line j, and its midpoint state.
  Scalar* fs_line(int j) { return &fs_[static_cast<std::size_t>(line_offset(j)) * static_cast<std::size_t>(n_)]; }
  Scalar* ys_line(int j) { return &ys_[static_cast<std::size_t>(j) * static_cast<std::size_t>(n_)]; }
  /// kBatch states, one per interpolated output (eval's out).
  Scalar* batch() { return &yb_[0]; }

  // After an accepted step over [t, t+h] that used lines 1..kc, from y0 (f0) to y1 (f1):
  // y at the midpoint and its derivatives of order 1..mu = 2kc-3 there, each extrapolated
  // from central differences of the stored right-hand sides of the lines that have enough
  // of them; then the polynomial P(θ) = H(θ) + θ²(1-θ)² Σ a_κ (θ-1/2)^κ/κ!, H the cubic
  // Hermite interpolant of y and h·f at both ends, the a_κ making P^(κ)(1/2) equal the
  // extrapolated h^κ y^(κ). Returns the interpolation error estimate (the size of the last
  // term, weighted as the step's error with atol and rtol; > BsOptions::dense_accept rejects
  // the step). nj: the lines' step numbers.
  double build(int kc, Scalar h, const Scalar* y0v, const Scalar* y1, const Scalar* f0, const Scalar* f1,
               const Scalar* atol, Scalar rtol, const std::array<int, kKmaxLimit + 2>& nj) {
    const int n = (N == Dynamic) ? n_ : N;
    const int mu = 2 * kc - 3;  // ODEX's default degree (mu + 4 for the polynomial)
    mu_ = mu;
    midpoint_value(kc, n);
    midpoint_derivatives(kc, mu, h, n, nj);
    polynomial(mu, h, y0v, y1, f0, f1, n);
    double errsum = 0;
    {
      const Scalar* am = dcoef_row(4 + mu);
      for (int i = 0; i < n; ++i) {
        const Scalar sc = atol[i] + rtol * std::max(num::abs(y0v[i]), num::abs(y1[i]));
        const double q = static_cast<double>(am[i] / sc);
        errsum += q * q;
      }
    }
    // Store a_κ/κ! so that an evaluation needs no division.
    Scalar fact = 1;
    for (int kap = 2; kap <= mu; ++kap) {
      fact = fact * Scalar(kap);
      Scalar* r = dcoef_row(4 + kap);
      if constexpr (pairs::kPairs<Scalar, N>) {
        const pairs::V2 f = {fact, fact};
        for (int i = 0; i < N; i += 2) pairs::st2(&r[i], pairs::ld2(&r[i]) / f);
      } else {
        for (int i = 0; i < n; ++i) r[i] = r[i] / fact;
      }
    }
    // max over θ of θ²(1-θ)² |θ-1/2|^mu / mu!
    const double sx = 0.5 * std::sqrt(static_cast<double>(mu) / (mu + 4.0));
    double errfac = 1.0 / ((mu + 4.0) * (mu + 4.0));
    for (int j = 1; j <= mu; ++j) errfac *= sx / j;
    return std::sqrt(errsum / n) * errfac;
  }

  /// The degree term of the last interpolant (mu = 2kc-3): the exponent of its step-size bound.
  [[nodiscard]] int mu() const { return mu_; }

  // The interpolant of the last accepted step at θ_b = (t_b - t_old)/h, b < m <= kBatch,
  // into out[b n + i].
  void eval(const std::array<Scalar, kBatch>& theta, int m, Scalar* out) {
    const int n = (N == Dynamic) ? n_ : N;
    const std::size_t nn = static_cast<std::size_t>(n);
    const Scalar* d = &dcoef_[0];
    if constexpr (pairs::kPairs<Scalar, N>) {
      // double, even N: the same operations on pairs of components (IEEE per lane, so the
      // same bits), the kBatch x N/2 accumulators in vector registers.
      using pairs::V2, pairs::ld2, pairs::st2;
      constexpr int P = N / 2;
      V2 acc[kBatch][P];
      V2 sv[kBatch];
      for (int b = 0; b < kBatch; ++b) {
        const double x = (b < m ? theta[b] : 0.5) - 0.5;
        sv[b] = V2{x, x};
      }
      const double* a = d + static_cast<std::size_t>(4 + mu_) * nn;
      for (int b = 0; b < kBatch; ++b)
        for (int i = 0; i < P; ++i) acc[b][i] = ld2(&a[2 * i]);
      for (int kap = mu_ - 1; kap >= 0; --kap) {
        a = d + static_cast<std::size_t>(4 + kap) * nn;
        V2 ak[P];
        for (int i = 0; i < P; ++i) ak[i] = ld2(&a[2 * i]);
        for (int b = 0; b < kBatch; ++b)
          for (int i = 0; i < P; ++i) acc[b][i] = ak[i] + acc[b][i] * sv[b];
      }
      for (int b = 0; b < m; ++b) {
        const double th = theta[b], th1 = 1.0 - th;
        const double w = (th * th1) * (th * th1);
        const V2 thv = {th, th}, th1v = {th1, th1}, wv = {w, w};
        double* o = out + b * N;
        for (int i = 0; i < P; ++i) {
          const V2 herm = ld2(&d[2 * i]) + thv * (ld2(&d[nn + 2 * i]) + th1v * (ld2(&d[2 * nn + 2 * i]) * thv +
                                                                                ld2(&d[3 * nn + 2 * i]) * th1v));
          st2(&o[2 * i], herm + wv * acc[b][i]);
        }
      }
      return;
    } else if constexpr (N != Dynamic) {
      // Fixed size: the kBatch x N Horner accumulators live in registers (a full batch is
      // always evaluated; unused lanes compute at θ = 1/2 and are not stored).
      Scalar acc[kBatch][N];
      Scalar sv[kBatch];
      for (int b = 0; b < kBatch; ++b) sv[b] = (b < m ? theta[b] : Scalar(0.5)) - Scalar(0.5);
      const Scalar* a = d + static_cast<std::size_t>(4 + mu_) * nn;
      for (int b = 0; b < kBatch; ++b)
        for (int i = 0; i < N; ++i) acc[b][i] = a[i];
      for (int kap = mu_ - 1; kap >= 0; --kap) {
        a = d + static_cast<std::size_t>(4 + kap) * nn;
        Scalar ak[N];
        for (int i = 0; i < N; ++i) ak[i] = a[i];
        for (int b = 0; b < kBatch; ++b)
          for (int i = 0; i < N; ++i) acc[b][i] = ak[i] + acc[b][i] * sv[b];
      }
      for (int b = 0; b < m; ++b)
        for (int i = 0; i < N; ++i) out[b * N + i] = finish(d, nn, i, theta[b], acc[b][i]);
      return;
    }
    std::array<Scalar, kBatch> s{};
    for (int b = 0; b < m; ++b) s[b] = theta[b] - Scalar(0.5);
    // Horner in (θ - 1/2) over the a_κ/κ!: m·n independent chains.
    const Scalar* a = d + static_cast<std::size_t>(4 + mu_) * nn;
    for (int b = 0; b < m; ++b)
      for (int i = 0; i < n; ++i) out[b * n + i] = a[i];
    for (int kap = mu_ - 1; kap >= 0; --kap) {
      a = d + static_cast<std::size_t>(4 + kap) * nn;
      for (int b = 0; b < m; ++b) {
        const Scalar sb = s[b];
        Scalar* o = out + b * n;
        for (int i = 0; i < n; ++i) o[i] = a[i] + o[i] * sb;
      }
    }
    for (int b = 0; b < m; ++b)
      for (int i = 0; i < n; ++i) out[b * n + i] = finish(d, nn, i, theta[b], out[b * n + i]);
  }

 private:
  Scalar* dcoef_row(int r) { return &dcoef_[static_cast<std::size_t>(r) * static_cast<std::size_t>(n_)]; }

  // rows of dcoef_: 0 y0, 1 Δ = y1 - y0, 2 α = Δ - h f1, 3 β = h f0 - Δ, 4 + κ: d_κ then a_κ.
  // Row 4: y at the midpoint, extrapolated from every line.
  void midpoint_value(int kc, int n) {
    const std::vector<Scalar>& wext = dense_tables<Scalar>();
    Scalar* r = dcoef_row(4);
    for (int i = 0; i < n; ++i) r[i] = 0;
    for (int j = 1; j <= kc; ++j) {
      const Scalar w = wext[widx(1, kc, j)];
      const Scalar* ym = ys_line(j);
      for (int i = 0; i < n; ++i) r[i] = r[i] + w * ym[i];
    }
  }

  // Rows 4 + κ, κ = 1..mu: h^κ y^(κ)(mid) ≈ h (n_j/2)^p δ^p f_j(mid), p = κ-1, δ^p f(mid) =
  // Σ_q (-1)^q C(p,q) f(mid+p-2q) (central differences of spacing 2 h_j), extrapolated over the
  // lines kb = ⌈κ/2⌉..kc that hold enough values. The coefficients are symmetric in the offset
  // for even p and antisymmetric for odd p, so each line's f values are first turned, in
  // place, into S_o = f(mid+o) + f(mid-o) (stored at mid+o) and D_o = f(mid+o) - f(mid-o)
  // (at mid-o), and every difference reads half the terms. The products of extrapolation
  // weight, (n_j/2)^p and signed binomial are tabulated per (kc, κ) (dense_terms()), so
  // a row is one list of multiply-adds, summed in registers, times h.
  void midpoint_derivatives(int kc, int mu, Scalar h, int n, const std::array<int, kKmaxLimit + 2>& nj) {
    const std::size_t nn = static_cast<std::size_t>(n_);
    Scalar* __restrict__ fsb = &fs_[0];
    for (int j = 1; j <= kc; ++j) {
      const int kapmax = std::min(mu, 2 * j);  // line j enters the differences of order < 2j
      Scalar* __restrict__ fmid = fsb + static_cast<std::size_t>(line_offset(j) + nj[j] / 2) * nn;
      for (int o = 1; o < kapmax; ++o) {
        Scalar* __restrict__ fp = fmid + static_cast<std::size_t>(o) * nn;
        Scalar* __restrict__ fm = fmid - static_cast<std::size_t>(o) * nn;
        if constexpr (pairs::kPairs<Scalar, N>) {
          for (int i = 0; i < N; i += 2) {
            const pairs::V2 a = pairs::ld2(&fp[i]), b = pairs::ld2(&fm[i]);
            pairs::st2(&fp[i], a + b);
            pairs::st2(&fm[i], a - b);
          }
        } else {
          for (int i = 0; i < n; ++i) {
            const Scalar a = fp[i], b = fm[i];
            fp[i] = a + b;
            fm[i] = a - b;
          }
        }
      }
    }
    const DenseTerms<Scalar>& dt = dense_terms<Scalar>();
    for (int kap = 1; kap <= mu; ++kap) {
      const DenseTerm<Scalar>* tb = &dt.terms[static_cast<std::size_t>(dt.start[kc][kap])];
      const DenseTerm<Scalar>* te = &dt.terms[static_cast<std::size_t>(dt.start[kc][kap + 1])];
      Scalar* __restrict__ r = dcoef_row(4 + kap);
      // r = h sum of the terms' c f_slot, summed in acc: m components, f_slot at slot * stride
      // (compile-time constants for a fixed N, so the loops unroll; acc a local array there and
      // the row itself for a run-time size; the same operations in the same order either way).
      auto combine = [&](Scalar* acc, auto m, auto stride) {
        for (int i = 0; i < m; ++i) acc[i] = 0;
        for (const DenseTerm<Scalar>* tm = tb; tm != te; ++tm) {
          const Scalar cq = tm->c;
          const Scalar* __restrict__ v = fsb + static_cast<std::size_t>(tm->slot) * stride;
          for (int i = 0; i < m; ++i) acc[i] = acc[i] + cq * v[i];
        }
        for (int i = 0; i < m; ++i) r[i] = h * acc[i];
      };
      if constexpr (N != Dynamic) {
        Scalar acc[N];
        combine(acc, std::integral_constant<int, N>{}, std::integral_constant<std::size_t, N>{});
      } else {
        combine(r, n, nn);
      }
    }
  }

  // Rows 0..3 (y0, Δ, α, β) and the a_κ: the Hermite cubic's θ-derivatives at θ = 1/2 are
  // subtracted from d_0..d_3 (rows 4..7) before the a_κ are formed (a_κ = 16 (d_κ - H^(κ) +
  // C(κ,2) a_{κ-2} - κ!/(κ-4)! a_{κ-4})).
  void polynomial(int mu, Scalar h, const Scalar* y0v, const Scalar* y1, const Scalar* f0, const Scalar* f1, int n) {
    Scalar* r0 = dcoef_row(0);
    Scalar* r1 = dcoef_row(1);
    Scalar* r2 = dcoef_row(2);
    Scalar* r3 = dcoef_row(3);
    for (int i = 0; i < n; ++i) {
      const Scalar y0 = y0v[i];
      const Scalar del = y1[i] - y0;
      const Scalar al = del - h * f1[i];
      const Scalar be = h * f0[i] - del;
      r0[i] = y0;
      r1[i] = del;
      r2[i] = al;
      r3[i] = be;
      const Scalar herm[4] = {Scalar(0.5) * (y0 + y1[i]) + Scalar(0.125) * (al + be), del + Scalar(0.25) * (al - be),
                              -(al + be), Scalar(6) * (be - al)};
      for (int kap = 0; kap <= std::min(mu, 3); ++kap) dcoef_row(4 + kap)[i] = dcoef_row(4 + kap)[i] - herm[kap];
    }
    for (int kap = 0; kap <= mu; ++kap) {
      Scalar* __restrict__ r = dcoef_row(4 + kap);
      const Scalar c2 = Scalar(kap * (kap - 1) / 2);
      const Scalar c4 = Scalar(kap * (kap - 1) * (kap - 2) * (kap - 3));
      const Scalar* __restrict__ a2 = kap >= 2 ? dcoef_row(2 + kap) : r;
      const Scalar* __restrict__ a4 = kap >= 4 ? dcoef_row(kap) : r;
      if constexpr (pairs::kPairs<Scalar, N>) {
        using pairs::V2, pairs::ld2, pairs::st2;
        const V2 c2v = {c2, c2}, c4v = {c4, c4}, sixteen = {16.0, 16.0};
        for (int i = 0; i < N; i += 2) {
          V2 v = ld2(&r[i]);
          if (kap >= 2) v = v + c2v * ld2(&a2[i]);
          if (kap >= 4) v = v - c4v * ld2(&a4[i]);
          st2(&r[i], sixteen * v);
        }
      } else {
        for (int i = 0; i < n; ++i) {
          Scalar v = r[i];
          if (kap >= 2) v = v + c2 * a2[i];
          if (kap >= 4) v = v - c4 * a4[i];
          r[i] = Scalar(16) * v;
        }
      }
    }
  }

  // H(θ) + θ²(1-θ)² acc for component i (rows 0..3 of d: y0, Δ, α, β), the operations in
  // this order (the pair version in eval does the same per lane).
  static Scalar finish(const Scalar* d, std::size_t nn, int i, Scalar th, Scalar acc) {
    const Scalar th1 = Scalar(1) - th;
    const Scalar w = (th * th1) * (th * th1);
    const Scalar herm = d[i] + th * (d[nn + i] + th1 * (d[2 * nn + i] * th + d[3 * nn + i] * th1));
    return herm + w * acc;
  }

  int n_ = 0;
  int mu_ = 0;  // highest midpoint derivative in the current interpolant
  std::vector<Scalar> fs_, ys_, dcoef_, yb_;
};

}  // namespace nanopush::bs
