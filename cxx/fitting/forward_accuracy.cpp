// The accuracy of a fit's forward model (FitOptions::accuracy, docs/fitting.md): the rtol of
// the forward solves chosen so that the model's poses at the observation times are within the
// accuracy asked for, in the norm of docs/accuracy.md (positions over max(object length,
// distance travelled), angle in rad), each estimate the difference from a solve 100x tighter.
#include <algorithm>
#include <cmath>

#include "nanopush/fitting/fit.hpp"
#include "nanopush/models/rigid_body.hpp"

namespace nanopush::fit {

namespace {
constexpr double kForwardRtolMin = 1e-14, kForwardRtolMax = 1e-3;
}  // namespace

double forward_error(const Scene& scene, const std::vector<double>& times, std::optional<Law> law, double rtol) {
  const double tight = std::max(rtol / 100, kForwardRtolMin);
  const auto a = model_poses(scene, {}, {}, times, law, rtol, false).pose;
  const auto b = model_poses(scene, {}, {}, times, law, tight, false).pose;
  if (b.empty()) return 0;
  const double L = std::max(scene.length, std::hypot(b.back()[0] - scene.initial[kX], b.back()[1] - scene.initial[kY]));
  double e = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    e = std::max({e, std::fabs(a[i][0] - b[i][0]) / L, std::fabs(a[i][1] - b[i][1]) / L, std::fabs(a[i][2] - b[i][2])});
  // A solve that could not be tighter claims no less than its rtol.
  return tight < rtol ? e : std::max(e, rtol);
}

FitAccuracy choose_forward_rtol(const Scene& scene, const std::vector<double>& times, std::optional<Law> law,
                                double accuracy) {
  require_range("accuracy", accuracy, kAccuracyMin, kAccuracyMax);
  FitAccuracy r;
  r.requested = accuracy;
  double rtol = std::clamp(accuracy, kForwardRtolMin, kForwardRtolMax);
  for (;;) {
    r.rtol_used = rtol;
    r.estimate = forward_error(scene, times, law, rtol);
    r.reached = r.estimate <= accuracy;
    if (r.reached || rtol <= kForwardRtolMin) return r;
    rtol = std::max(rtol / 100, kForwardRtolMin);
  }
}

}  // namespace nanopush::fit
