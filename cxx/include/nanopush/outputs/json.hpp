// JSON documents the project writes (sidecars, fit reports, plans, merged sidecars), through
// nlohmann-json. Used inside the build only: it is not installed (cmake/Install.cmake), so the
// installed headers do not need nlohmann-json.
#pragma once

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

namespace nanopush {

/// Objects keep their keys in the order written.
using json = nlohmann::ordered_json;

/// A number as JSON: null when not finite (JSON has no NaN or infinity).
inline json json_number(double v) { return std::isfinite(v) ? json(v) : json(); }

/// The text of a document as written to a file: indented by two, a final newline; text that
/// is not UTF-8 (a command line's bytes) written with U+FFFD instead of refused.
inline std::string json_text(const json& doc) {
  return doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace nanopush
