// Values in the tip models' messages (tip_push.cpp, tip_dynamic.cpp): %.6g, the form their
// InputError and SolverError texts have always had (error.hpp's fmt gives the shortest exact
// form instead).
#pragma once
#include <cstdio>
#include <string>

namespace nanopush::tip::detail {

inline std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

}  // namespace nanopush::tip::detail
