// What the bench-* commands share at their end: the note that stands in for a figure not
// drawn, and the exit status when a benchmark's own check does not hold.
#pragma once
#include <iostream>
#include <string>

#include "nanopush/outputs/plot.hpp"

namespace nanopush::cli {

/// Why a benchmark's figure is not drawn: --no-plot, or no gnuplot on PATH; "" when it is.
inline std::string plot_skipped(bool no_plot) {
  if (no_plot) return "no plot (--no-plot)";
  if (!plot::available()) return "no plot: gnuplot is not on PATH";
  return "";
}

/// A benchmark's exit status: 0 when its check holds, else 4 with `why` on standard error.
inline int bench_status(bool ok, const std::string& why) {
  if (ok) return 0;
  std::cerr << why << "\n";
  return 4;
}

}  // namespace nanopush::cli
