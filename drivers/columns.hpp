// The catalogue of the drivers' output tables: every table's columns (name, unit, description,
// kind) live as data in drivers/columns.toml, compiled into the program as text and parsed on
// the first lookup (never on the start-up path of a command that writes no table).
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "nanopush/outputs/io.hpp"

namespace nanopush::cli {

/// The columns of the output table `table` as drivers/columns.toml declares them, in order
/// (a family that depends on the run is appended by the caller). An unknown table, or a
/// catalogue that does not parse, is an internal error (std::logic_error).
const Columns& columns(std::string_view table);

/// Every table of the catalogue, sorted by name.
std::vector<std::string> column_tables();

/// Parse a catalogue's TOML text: [table] columns = [{ name, description, kind = "number" |
/// "text" | "count", unit (number only), parameters = { key = value } }, ...]. Throws
/// std::logic_error naming `source` and the table at the first fault.
std::map<std::string, Columns, std::less<>> parse_column_catalogue(std::string_view toml_text,
                                                                   const std::string& source);

}  // namespace nanopush::cli
