#include "kinks.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "nanopush/numerics/regula_falsi.hpp"
#include "nanopush/numerics/scalar.hpp"

namespace nanopush::detail {

namespace {

constexpr int kMaxKinks = 8;
/// Kinks located before the run gives up locating (and integrates on across them).
constexpr std::int64_t kMaxLocated = 100000;

void add_counts(IntegrationResult& into, const IntegrationResult& r) {
  into.nfcn += r.nfcn;
  into.naccpt += r.naccpt;
  into.nrejct += r.nrejct;
}

}  // namespace

template <typename S>
KinkResult integrate_across_kinks(const KinkIntegrateT<S>& run, const KinkFunctionsT<S>& kinks, int nk, S* y, int n,
                                  std::span<const double> tout, const KinkObserverT<S>& observer,
                                  const KinkHookT<S>& hook, std::int64_t max_steps) {
  KinkResult out;
  // The steps left of the run's budget; none left: the run ends as an integrator's would.
  const auto left = [&] { return max_steps - (out.stats.naccpt + out.stats.nrejct); };
  const auto spent = [&] {
    out.stats.status = IntegrationStatus::too_many_steps;
    out.stats.message = "more than " + std::to_string(max_steps) + " steps (the run's budget, " +
                        std::to_string(out.located) + " kinks of the wrench located within it)";
    return out;
  };
  nk = std::min(nk, kMaxKinks);
  double t = 0.0;
  std::size_t iout = 0;
  std::vector<S> ystart(static_cast<std::size_t>(n)), yt(static_cast<std::size_t>(n));
  S g0[kMaxKinks], g1[kMaxKinks];
  int crossed = -1;
  double h_next = 0.0;  // the first step after a restart: the step that met the kink
  const KinkHookT<S> no_hook = [](double, const S*, double, const S*) { return static_cast<int>(kHookContinue); };
  const KinkObserverT<S> quiet = [](double, const S*) {};
  // A step whose start is a located kink sees g there within rounding of zero: only a sign
  // change from a clearly non-zero value is a crossing.
  auto crossing = [&](const S* ya, const S* yb) {
    kinks(ya, g0);
    kinks(yb, g1);
    for (int k = 0; k < nk; ++k)
      if (g0[k] * g1[k] < 0.0 && num::abs(g0[k]) > 1e-9 * num::abs(g1[k])) return k;
    return -1;
  };
  while (iout < tout.size()) {
    std::size_t emitted = 0;
    const KinkObserverT<S> count = [&](double tt, const S* yy) {
      observer(tt, yy);
      ++emitted;
    };
    const bool locate = out.located < kMaxLocated;
    const KinkHookT<S> step = [&](double ta, const S* ya, double tb, const S* yb) {
      if (locate) {
        crossed = crossing(ya, yb);
        if (crossed >= 0) return static_cast<int>(kHookStopBefore);
      }
      return hook ? hook(ta, ya, tb, yb) : static_cast<int>(kHookContinue);
    };
    if (left() < 1) return spent();
    const IntegrationResult r = run(t, y, tout.subspan(iout), count, step, h_next, left());
    add_counts(out.stats, r);
    iout += emitted;
    out.stats.status = r.status;
    out.stats.message = r.message;
    out.stats.rhs_status = r.rhs_status;
    out.stats.t_reached = r.t_reached;
    if (!r.ok() || !r.stopped_by_hook) return out;
    if (crossed < 0) {  // the outer hook stopped the run
      out.stopped_by_hook = true;
      return out;
    }
    // A kink of g_k inside (t, t1]: locate it by the Illinois variant of regula falsi, each
    // value from a sub-integration from the step's start.
    const int k = crossed;
    const double t0 = r.t_reached, t1 = r.t_event_end;
    std::copy(y, y + n, ystart.begin());
    auto g_at = [&](double tc) {
      std::copy(ystart.begin(), ystart.end(), yt.begin());
      const double end[1] = {tc};
      if (left() < 1) return std::nan("");
      const IntegrationResult s = run(t0, yt.data(), std::span<const double>(end, 1), quiet, no_hook, tc - t0, left());
      add_counts(out.stats, s);
      if (!s.ok()) return std::nan("");
      S g[kMaxKinks];
      kinks(yt.data(), g);
      return static_cast<double>(g[k]);
    };
    kinks(ystart.data(), g0);
    double a = t0, b = t1;
    const double gb = g_at(b);
    // A failed sub-integration (g not finite) ends the search where it was tried.
    if (std::isfinite(gb))
      roots::illinois(
          a, b, static_cast<double>(g0[k]), gb, 60, [&](double lo, double hi) { return (hi - lo) > 1e-6 * (t1 - t0); },
          [&](double tc) {
            const double gc = g_at(tc);
            return std::isfinite(gc) ? gc : 0.0;
          },
          [](int) {});
    // Integrate to the kink's far side b, giving the outputs before it; restart there.
    std::size_t before = iout;
    while (before < tout.size() && tout[before] < b) ++before;
    std::vector<double> span_out(tout.begin() + static_cast<std::ptrdiff_t>(iout),
                                 tout.begin() + static_cast<std::ptrdiff_t>(before));
    span_out.push_back(b);
    std::copy(ystart.begin(), ystart.end(), y);
    std::size_t given = 0;
    const KinkObserverT<S> to_b = [&](double tt, const S* yy) {
      if (given++ < span_out.size() - 1) observer(tt, yy);
    };
    if (left() < 1) {
      std::copy(ystart.begin(), ystart.end(), y);  // the state at the last committed step
      out.stats.t_reached = t0;
      return spent();
    }
    const IntegrationResult s = run(t0, y, span_out, to_b, no_hook, b - t0, left());
    add_counts(out.stats, s);
    if (!s.ok()) {
      out.stats.status = s.status;
      out.stats.message = s.message;
      out.stats.t_reached = s.t_reached;
      return out;
    }
    iout = before;
    t = b;
    h_next = t1 - t0;
    ++out.located;
  }
  return out;
}

template KinkResult integrate_across_kinks<double>(const KinkIntegrateT<double>&, const KinkFunctionsT<double>&, int,
                                                   double*, int, std::span<const double>, const KinkObserverT<double>&,
                                                   const KinkHookT<double>&, std::int64_t);
template KinkResult integrate_across_kinks<long double>(const KinkIntegrateT<long double>&,
                                                        const KinkFunctionsT<long double>&, int, long double*, int,
                                                        std::span<const double>, const KinkObserverT<long double>&,
                                                        const KinkHookT<long double>&, std::int64_t);
template KinkResult integrate_across_kinks<num::quad>(const KinkIntegrateT<num::quad>&,
                                                      const KinkFunctionsT<num::quad>&, int, num::quad*, int,
                                                      std::span<const double>, const KinkObserverT<num::quad>&,
                                                      const KinkHookT<num::quad>&, std::int64_t);

}  // namespace nanopush::detail
