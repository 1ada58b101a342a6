// The rate and time left of a running sweep, for a progress line.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <utility>

namespace nanopush::sweep {

/// Points per second and time left from samples (time, points done). The first sample is the
/// moment the work starts (with the points a resume brought), so the first report after it
/// already has the true rate; the rate is taken over the last `window` seconds, so it follows
/// a sweep whose pace changes (slow points at the end of a grid) without the noise of one
/// interval.
class ProgressRate {
 public:
  explicit ProgressRate(double window_seconds = 10.0) : window_(window_seconds) {}
  /// A sample: `t` seconds on a monotone clock, `done` points finished so far.
  void sample(double t, std::size_t done);
  /// Points per second; none before time has passed since the first sample.
  [[nodiscard]] std::optional<double> rate() const;
  /// Seconds until `total` points at the current rate; none without a rate or progress.
  [[nodiscard]] std::optional<double> seconds_left(std::size_t total) const;
  /// "12/100 points, 3.4e+03 points/s, 1 s left" ("rate ..." before the first interval).
  [[nodiscard]] std::string line(std::size_t total) const;

 private:
  double window_;
  std::deque<std::pair<double, std::size_t>> samples_;
};

}  // namespace nanopush::sweep
