// Bulirsch–Stoer: Gragg's modified midpoint rule, the stepper whose results the tableau
// extrapolates (docs/bulirsch_stoer.md). One line (m substeps over [t, t+H]) at a time, or
// lines 1..jg interleaved substep by substep so the latency of one line's RHS overlaps the
// others' (the operations of each line the same, in the same order: the same bits).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "nanopush/numerics/bs/tables.hpp"
#include "nanopush/numerics/integration.hpp"

namespace nanopush::bs {

template <typename Scalar, int N>
class GraggMidpoint {
 public:
  using Vec = StateVec<Scalar, N>;

  /// Work space for n components, allocated once.
  void allocate(int n) {
    n_ = n;
    size_states(n_, zm_, z_, fz_);
    for (auto& row : held_) size_states(n_, row);
    zg_.assign(static_cast<std::size_t>(3 * kL) * static_cast<std::size_t>(n_ > 0 ? n_ : 1), Scalar(0));
  }

  /// The result of line j of the last group().
  const Vec& held(int j) const { return held_[j]; }

  /// One line: m substeps from (t, y0) with f0 = f(t, y0) over [t, t+hbig]; result into out.
  /// Dense output: fsl receives f at every substep 0..m (m+1 vectors), ymid the state at
  /// substep m/2; both null otherwise. Returns 0 or the RHS's non-zero status.
  template <class Rhs>
  int line(Rhs& rhs, const Scalar* y0, const Scalar* f0, Scalar t, Scalar hbig, int m, Vec& out,
           IntegrationResult& res, Scalar* fsl, Scalar* ymid) {
    const Scalar hs = hbig / Scalar(m);
    const Scalar h2 = Scalar(2) * hs;
    // The two latest midpoint states; their roles swap by pointer (no copy per substep).
    Scalar* zm = &zm_[0];
    Scalar* z = &z_[0];
    start(y0, f0, zm, z, hs, fsl);
    for (int s = 1; s <= m - 1; ++s) {
      if (ymid && 2 * s == m) copy_n(z, ymid);
      Scalar* fz = fsl ? fsl + static_cast<std::size_t>(s) * static_cast<std::size_t>(n_) : &fz_[0];
      const int st = rhs(t + Scalar(s) * hs, static_cast<const Scalar*>(z), fz);
      if (st != 0) {
        res.nfcn += s;
        return st;
      }
      add_scaled(zm, h2, fz);  // z_{s+1} = z_{s-1} + 2 hs f(z_s)
      std::swap(zm, z);
    }
    Scalar* fz = fsl ? fsl + static_cast<std::size_t>(m) * static_cast<std::size_t>(n_) : &fz_[0];
    const int st = rhs(t + hbig, static_cast<const Scalar*>(z), fz);
    res.nfcn += m;  // one call per substep (counted here, not in the loop: a register, not memory)
    if (st != 0) return st;
    smoothing_step(z, zm, hs, fz, &out[0]);
    return 0;
  }

  /// Lines 1..jg (step numbers nj[1..jg]) interleaved; results in held(j). With dense output
  /// the store gives each line's RHS slots (fs_line) and midpoint state (ys_line).
  template <bool dense, class Rhs, class Store>
  int group(Rhs& rhs, const Scalar* y0, const Scalar* f0, Scalar t, Scalar hbig, int jg,
            const std::array<int, kKmaxLimit + 2>& nj, Store& store, IntegrationResult& res) {
    const std::size_t nn = static_cast<std::size_t>(n_);
    std::array<Scalar, kKmaxLimit + 2> hs, h2;  // only 1..jg are used
    std::array<Scalar*, kKmaxLimit + 2> zm, z;
    for (int j = 1; j <= jg; ++j) {
      hs[j] = hbig / Scalar(nj[j]);
      h2[j] = Scalar(2) * hs[j];
      zm[j] = &zg_[static_cast<std::size_t>(2 * j) * nn];
      z[j] = &zg_[static_cast<std::size_t>(2 * j + 1) * nn];
      start(y0, f0, zm[j], z[j], hs[j], dense ? store.fs_line(j) : nullptr);
    }
    const int mmax = nj[jg];
    std::int64_t calls = 0;  // added to res.nfcn on return (a register across the calls)
    for (int s = 1; s <= mmax; ++s) {
      for (int j = jg; j >= 1; --j) {  // longest line first
        const int m = nj[j];
        if (s > m) break;  // the shorter lines are done
        Scalar* fz;
        if constexpr (dense)
          fz = store.fs_line(j) + static_cast<std::size_t>(s) * nn;
        else
          fz = &zg_[static_cast<std::size_t>(2 * kL + j) * nn];
        if (s < m) {
          if constexpr (dense)
            if (2 * s == m) copy_n(z[j], store.ys_line(j));
          const int st = rhs(t + Scalar(s) * hs[j], static_cast<const Scalar*>(z[j]), fz);
          ++calls;
          if (st != 0) {
            res.nfcn += calls;
            return st;
          }
          add_scaled(zm[j], h2[j], fz);  // z_{s+1} = z_{s-1} + 2 hs f(z_s)
          std::swap(zm[j], z[j]);
        } else {
          const int st = rhs(t + hbig, static_cast<const Scalar*>(z[j]), fz);
          ++calls;
          if (st != 0) {
            res.nfcn += calls;
            return st;
          }
          smoothing_step(z[j], zm[j], hs[j], fz, &held_[j][0]);
        }
      }
    }
    res.nfcn += calls;
    return 0;
  }

 private:
  // The pieces of the modified midpoint rule, written once for line() and group()
  // (restrict-qualified so the short loops vectorise).
  // zm = y0, z = y0 + hs f0; the dense line's first f value is f0.
  void start(const Scalar* __restrict__ y0, const Scalar* __restrict__ f0, Scalar* __restrict__ zm,
             Scalar* __restrict__ z, Scalar hs, Scalar* __restrict__ fsl) const {
    const int n = (N == Dynamic) ? n_ : N;
    for (int i = 0; i < n; ++i) {
      zm[i] = y0[i];
      z[i] = y0[i] + hs * f0[i];
    }
    if (fsl)
      for (int i = 0; i < n; ++i) fsl[i] = f0[i];
  }
  // zm = zm + h2 f
  void add_scaled(Scalar* __restrict__ zm, Scalar h2, const Scalar* __restrict__ f) const {
    const int n = (N == Dynamic) ? n_ : N;
    for (int i = 0; i < n; ++i) zm[i] = zm[i] + h2 * f[i];
  }
  // out = 0.5 (z + zm + hs f), the operations in that order
  void smoothing_step(const Scalar* __restrict__ z, const Scalar* __restrict__ zm, Scalar hs,
                      const Scalar* __restrict__ f, Scalar* __restrict__ out) const {
    const int n = (N == Dynamic) ? n_ : N;
    for (int i = 0; i < n; ++i) out[i] = Scalar(0.5) * (z[i] + zm[i] + hs * f[i]);
  }
  void copy_n(const Scalar* __restrict__ from, Scalar* __restrict__ to) const {
    const int n = (N == Dynamic) ? n_ : N;
    for (int i = 0; i < n; ++i) to[i] = from[i];
  }

  int n_ = 0;
  Vec zm_{}, z_{}, fz_{};
  // Interleaved lines (group): zm, z of line j in rows 2j, 2j+1, its f in row 2 kL + j
  // (non-dense); the line results in held_.
  std::vector<Scalar> zg_;
  std::array<Vec, kKmaxLimit + 2> held_{};
};

}  // namespace nanopush::bs
