// What the bench-* commands share: the median of timed repeats, the host's load, the note that
// stands in for a figure not drawn, the report written and printed, and the exit status when a
// benchmark's own check does not hold.
#pragma once
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"

namespace nanopush::cli {

/// The median of `v` (NaN when empty).
inline double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The host's load averages (1, 5, 15 min) from /proc/loadavg; NaN where unreadable.
inline std::array<double, 3> load_average() {
  std::array<double, 3> a{};
  a.fill(std::numeric_limits<double>::quiet_NaN());
  std::ifstream f("/proc/loadavg");
  f >> a[0] >> a[1] >> a[2];
  return a;
}

/// Why a benchmark's figure is not drawn: --no-plot, or no gnuplot on PATH; "" when it is.
inline std::string plot_skipped(bool no_plot) {
  if (no_plot) return "no plot (--no-plot)";
  if (!plot::available()) return "no plot: gnuplot is not on PATH";
  return "";
}

/// Write a benchmark's Markdown report `md` to `file` (atomically), then print it on standard output.
inline void write_and_print_report(const std::filesystem::path& file, const std::string& md) {
  write_file_atomic(file, md);
  std::cout << md;
}

/// A benchmark's exit status: 0 when its check holds, else 4 with `why` on standard error.
inline int bench_status(bool ok, const std::string& why) {
  if (ok) return 0;
  std::cerr << why << "\n";
  return 4;
}

}  // namespace nanopush::cli
