// The [environment] table and body tables of a scene file, parsed and validated; each error
// names the offending TOML field, e.g. "environment.humidity = 1.5: must be in [0, 1]".
// The tables are documented in docs/forces.md. Callers include <toml++/toml.h> to build a table.
#pragma once
#include <string_view>

#include "nanopush/models/environment.hpp"
#include "nanopush/scenes/toml_fwd.hpp"

namespace nanopush {

/// Parse an [environment] table. `path` prefixes field names in errors.
Environment parse_environment(const toml::table& t, std::string_view path = "environment");
/// Parse a body table ([body] or one [[bodies]] entry).
Body parse_body(const toml::table& t, std::string_view path = "body");

}  // namespace nanopush
