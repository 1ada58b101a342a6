// Bulirsch–Stoer: the extrapolation tableau in h^2 (docs/bulirsch_stoer.md). Rational
// extrapolation (Stoer & Bulirsch, Introduction to Numerical Analysis, §7.2.14) or polynomial
// (Aitken–Neville). Two rows, the current and the previous, whose roles swap by a flag, so a
// new line copies nothing.
#pragma once
#include <array>
#include <cstddef>

#include "nanopush/numerics/bs/tables.hpp"
#include "nanopush/numerics/integration.hpp"
#include "nanopush/numerics/simd_pairs.hpp"

namespace nanopush::bs {

template <typename Scalar, int N>
class ExtrapolationTableau {
 public:
  using Row = std::array<StateVec<Scalar, N>, kKmaxLimit + 2>;  ///< columns 1..kmax

  /// Dynamic dimension: size every column for n components (once, at construction).
  void allocate(int n) {
    for (auto& half : tab_)
      for (auto& column : half) size_states(n, column);
  }

  Row& cur() { return tab_[static_cast<std::size_t>(icur_)]; }
  Row& prev() { return tab_[static_cast<std::size_t>(icur_ ^ 1)]; }
  /// The new row becomes the previous one (no copy).
  void flip() { icur_ ^= 1; }

  /// Fill cur()[2..j] from cur()[1] (the new midpoint result of line j) and prev() (line j-1):
  /// n components, the line constants of the step-number sequence.
  void extrapolate(int j, int n_dyn, bool rational, const SequenceTables<Scalar>& seq) {
    const int n = (N == Dynamic) ? n_dyn : N;  // a compile-time bound lets the loops unroll
    auto& cu = cur();
    const auto& pr = prev();
    for (int l = 2; l <= j; ++l) {
      const Scalar r = seq.ratio2[j][l];
      if (!rational) {
        // Aitken–Neville; no division (the reciprocal is tabulated)
        const Scalar inv = seq.rinv[j][l];
        for (int i = 0; i < n; ++i) cu[l][i] = cu[l - 1][i] + (cu[l - 1][i] - pr[l - 1][i]) * inv;
        continue;
      }
      // Stoer–Bulirsch rational step; where e or the denominator vanishes, the polynomial
      // step d/(r-1). Written without branches (both quotients formed, one selected, the
      // same operations as the branching form) so the components go through the vector
      // divider together.
      const Scalar rm1 = r - Scalar(1);
      if constexpr (pairs::kPairs<Scalar, N>) {
        // double, even N: two components per vector operation (IEEE per lane, so the
        // same bits as the scalar loop below)
        using pairs::V2, pairs::ld2, pairs::st2;
        const V2 rv = {r, r}, one = {1.0, 1.0}, rm1v = {rm1, rm1}, zero = {0.0, 0.0};
        for (int i = 0; i < N; i += 2) {
          const V2 c1 = ld2(&cu[l - 1][i]);
          const V2 d = c1 - ld2(&pr[l - 1][i]);
          const V2 e = (l >= 3) ? c1 - ld2(&pr[l - 2][i]) : c1 - zero;
          const V2 den = rv * (one - d / e) - one;
          const V2 div = ((e != zero) & (den != zero)) ? den : rm1v;
          st2(&cu[l][i], c1 + d / div);
        }
        continue;
      }
      for (int i = 0; i < n; ++i) {
        const Scalar d = cu[l - 1][i] - pr[l - 1][i];
        const Scalar back = (l >= 3) ? pr[l - 2][i] : Scalar(0);
        const Scalar e = cu[l - 1][i] - back;
        const Scalar den = r * (Scalar(1) - d / e) - Scalar(1);  // inf/NaN when e == 0: not selected
        const Scalar div = (e != 0 && den != 0) ? den : rm1;
        cu[l][i] = cu[l - 1][i] + d / div;
      }
    }
  }

 private:
  std::array<Row, 2> tab_{};
  int icur_ = 0;
};

}  // namespace nanopush::bs
