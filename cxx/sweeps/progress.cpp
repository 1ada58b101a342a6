#include "nanopush/sweeps/progress.hpp"

#include <cmath>
#include <cstdio>

namespace nanopush::sweep {

void ProgressRate::sample(double t, std::size_t done) {
  samples_.emplace_back(t, done);
  // Keep one sample at or before the window's start, so the rate spans the whole window.
  while (samples_.size() > 2 && samples_[1].first <= t - window_) samples_.pop_front();
}

std::optional<double> ProgressRate::rate() const {
  if (samples_.size() < 2) return std::nullopt;
  const auto& [t0, d0] = samples_.front();
  const auto& [t1, d1] = samples_.back();
  if (!(t1 > t0)) return std::nullopt;
  return static_cast<double>(d1 - d0) / (t1 - t0);
}

std::optional<double> ProgressRate::seconds_left(std::size_t total) const {
  const auto r = rate();
  if (!r || !(*r > 0) || samples_.empty()) return std::nullopt;
  const std::size_t done = samples_.back().second;
  return done >= total ? 0.0 : static_cast<double>(total - done) / *r;
}

std::string ProgressRate::line(std::size_t total) const {
  const std::size_t done = samples_.empty() ? 0 : samples_.back().second;
  char b[160];
  const auto r = rate();
  const auto left = seconds_left(total);
  if (!r)
    std::snprintf(b, sizeof b, "%zu/%zu points, rate ...", done, total);
  else if (!left)
    std::snprintf(b, sizeof b, "%zu/%zu points, %.3g points/s", done, total, *r);
  else
    std::snprintf(b, sizeof b, "%zu/%zu points, %.3g points/s, %.0f s left", done, total, *r, std::ceil(*left));
  return b;
}

}  // namespace nanopush::sweep
