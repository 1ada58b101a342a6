// What the C++ tests of the C API (tests/capi/test_capi_*.cpp) share: check() counts checks and
// failures and reports each failure, same() compares two doubles bit for bit (NaN equals NaN),
// message() reads the text of a nanopush_error, finish() prints the tally and gives the exit
// status. (The C tests have tests/capi/check.h.)
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "nanopush.h"

namespace nanopush_capi_test {

inline int failures = 0, checks = 0;

inline void check(bool ok, const std::string& what) {
  ++checks;
  if (!ok) {
    ++failures;
    std::fprintf(stderr, "FAIL: %s\n", what.c_str());
  }
}

inline bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

inline std::string message(nanopush_error err) {
  char buf[1024];
  nanopush_get_error(err, buf, sizeof buf);
  return buf;
}

// Prints "N checks, M failures"; 1 when any check failed, else 0 (after printing `passed`, if any).
inline int finish(const char* passed = nullptr) {
  std::printf("%d checks, %d failures\n", checks, failures);
  if (failures) return 1;
  if (passed) std::printf("%s\n", passed);
  return 0;
}

}  // namespace nanopush_capi_test
