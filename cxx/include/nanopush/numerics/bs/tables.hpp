// Bulirsch–Stoer: the constants of the step-number sequences and of the dense output, the same
// for every instance and so computed once per process (13 pow() calls and two tables cost more
// than a short solve). Algorithm: docs/bulirsch_stoer.md.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace nanopush::bs {

/// Extrapolation columns at most (BsOptions::kmax is 3..12).
inline constexpr int kKmaxLimit = 12;
/// Highest midpoint derivative of the dense output, and the line index bound (1-based lines).
inline constexpr int kMuLimit = 2 * kKmaxLimit - 3;
inline constexpr int kL = kKmaxLimit + 2;

/// Step-size control (Hairer, Nørsett & Wanner, §II.9; the F77 engine's constants).
inline constexpr double kSafe1 = 0.65;
inline constexpr double kSafe2 = 0.94;
inline constexpr double kSafe3 = 0.02;
inline constexpr double kFac4 = 4.0;

/// First right-hand-side slot of line j (1-based) in the dense output's store: line i holds
/// 4i-1 slots.
constexpr int line_offset(int j) { return (j - 1) * (2 * j - 1); }

template <typename Scalar>
using Table2 = std::array<std::array<Scalar, kKmaxLimit + 2>, kKmaxLimit + 2>;

/// The step numbers of the lines (2j, or 4j-2 with dense output), the smallest step-size
/// factor per line kSafe3^(1/(2j-1)), and the extrapolation constants of line j, column l,
/// (n_j / n_{j-l+1})^2 and 1/(that - 1).
template <typename Scalar>
struct SequenceTables {
  std::array<int, kKmaxLimit + 2> nj{};
  std::array<double, kKmaxLimit + 2> facmin{};
  Table2<Scalar> ratio2{}, rinv{};
};

template <typename Scalar>
const SequenceTables<Scalar>& sequence_tables(bool dense) {
  auto make = [](bool d) {
    SequenceTables<Scalar> t;
    for (int j = 0; j < kKmaxLimit + 2; ++j) t.nj[j] = d ? 4 * j - 2 : 2 * j;
    for (int j = 1; j < kKmaxLimit + 2; ++j) t.facmin[j] = std::pow(kSafe3, 1.0 / static_cast<double>(2 * j - 1));
    for (int j = 2; j < kKmaxLimit + 2; ++j)
      for (int l = 2; l <= j; ++l) {
        const Scalar q = Scalar(t.nj[j]) / Scalar(t.nj[j - l + 1]);
        t.ratio2[j][l] = q * q;
        t.rinv[j][l] = Scalar(1) / (t.ratio2[j][l] - Scalar(1));
      }
    return t;
  };
  static const SequenceTables<Scalar> even = make(false), dense_seq = make(true);
  return dense ? dense_seq : even;
}

/// Index of the extrapolation weight of line j over lines jb..je in dense_tables().
constexpr std::size_t widx(int jb, int je, int j) {
  return (static_cast<std::size_t>(jb) * kL + static_cast<std::size_t>(je)) * kL + static_cast<std::size_t>(j);
}

// Tables of the dense output (step numbers 4j-2): weights of the h^2 polynomial extrapolation
// to h = 0 from lines jb..je, the Lagrange form of Aitken–Neville in x_j = n_j^-2,
// w_j = prod_{l != j} x_l/(x_l - x_j) at widx(jb, je, j); then the binomial coefficients
// C(p, r), p < kMuLimit, at kL^3 + p kMuLimit + r.
template <typename Scalar>
const std::vector<Scalar>& dense_tables() {
  static const std::vector<Scalar> t = [] {
    std::vector<Scalar> v(static_cast<std::size_t>(kL * kL * kL + kMuLimit * kMuLimit), Scalar(0));
    auto x = [](int j) { return Scalar(1) / (Scalar(4 * j - 2) * Scalar(4 * j - 2)); };
    for (int jb = 1; jb < kL; ++jb)
      for (int je = jb; je < kL; ++je)
        for (int j = jb; j <= je; ++j) {
          Scalar w = 1;
          for (int l = jb; l <= je; ++l)
            if (l != j) w = w * x(l) / (x(l) - x(j));
          v[widx(jb, je, j)] = w;
        }
    Scalar* c = &v[static_cast<std::size_t>(kL * kL * kL)];
    for (int p = 0; p < kMuLimit; ++p) {
      c[p * kMuLimit] = 1;
      for (int r = 1; r <= p; ++r)
        c[p * kMuLimit + r] = c[(p - 1) * kMuLimit + r - 1] + (r <= p - 1 ? c[(p - 1) * kMuLimit + r] : Scalar(0));
    }
    return v;
  }();
  return t;
}

// The multiply-adds of the midpoint derivatives (DenseOutput::build), per last line kc and
// order κ = 1..2kc-3: h^κ y^(κ)(mid) ≈ h · Σ c · (slot of the store), c = (±w_j (n_j/2)^(κ-1))
// C(κ-1, q) (the factors multiplied in this order, (n_j/2)^p by successive products), the
// slots being f(mid), S_o (at mid+o) or D_o (at mid-o) of lines ⌈κ/2⌉..kc, w_j the
// extrapolation weight of line j over lines ⌈κ/2⌉..kc, q = (κ-1-o)/2, the sign (-1)^q.
// Terms of (kc, κ) at [start[kc][κ], start[kc][κ+1]), line by line, each line's f(mid)
// first and then o decreasing: the order of the sum, the same in the fixed-size and the
// dynamic path (so both give the same bits). c does not depend on the step, so a step pays
// one multiply-add per term and component and one product by h per row.
template <typename Scalar>
struct DenseTerm {
  int slot;   // row of the store
  Scalar c;   // ±w_j (n_j/2)^p C(p, q): the term's coefficient without the factor h
};
template <typename Scalar>
struct DenseTerms {
  std::vector<DenseTerm<Scalar>> terms;
  std::array<std::array<int, kMuLimit + 2>, kKmaxLimit + 1> start{};
};

template <typename Scalar>
const DenseTerms<Scalar>& dense_terms() {
  static const DenseTerms<Scalar> t = [] {
    DenseTerms<Scalar> d;
    const std::vector<Scalar>& wext = dense_tables<Scalar>();
    const Scalar* binom = &wext[static_cast<std::size_t>(kL * kL * kL)];
    for (int kc = 2; kc <= kKmaxLimit; ++kc) {
      const int mu = 2 * kc - 3;
      for (int kap = 1; kap <= mu + 1; ++kap) {
        d.start[kc][kap] = static_cast<int>(d.terms.size());
        if (kap > mu) break;
        const int p = kap - 1;
        for (int j = (kap + 1) / 2; j <= kc; ++j) {
          const int half = 2 * j - 1;  // n_j / 2 for n_j = 4j - 2
          const Scalar w = wext[widx((kap + 1) / 2, kc, j)];
          const int mid = line_offset(j) + half;
          const Scalar* bn = binom + p * kMuLimit;
          Scalar wp = w;  // w_j (n_j/2)^p
          for (int i = 0; i < p; ++i) wp = wp * Scalar(half);
          const auto c = [wp](Scalar b, bool neg) { return (neg ? -wp : wp) * b; };
          if (p % 2 == 0) d.terms.push_back({mid, c(bn[p / 2], (p / 2) % 2 != 0)});
          for (int q = 0; 2 * q < p; ++q) {
            const int o = p - 2 * q;
            d.terms.push_back({p % 2 == 0 ? mid + o : mid - o, c(bn[q], q % 2 != 0)});
          }
        }
      }
    }
    return d;
  }();
  return t;
}

}  // namespace nanopush::bs
