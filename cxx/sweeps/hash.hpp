// FNV-1a over text, streamed: the identities of plans, tasks and journal records.
#pragma once
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace nanopush::sweep {

inline constexpr std::uint64_t kFnvBasis = 1469598103934665603ULL;

inline std::uint64_t fnv1a(std::string_view s, std::uint64_t h = kFnvBasis) {
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

inline std::string hex(std::uint64_t v) {
  char b[17];
  std::snprintf(b, sizeof b, "%016" PRIx64, v);
  return b;
}

}  // namespace nanopush::sweep
