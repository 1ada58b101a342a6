// The catalogue of output columns (drivers/columns.toml): it parses, every table in it is valid
// for a CSV and its sidecar, it and the code name the same tables, and a faulty catalogue is an
// internal error that names the table.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include "columns.hpp"
#include "nanopush/outputs/io.hpp"
#include "support/support.hpp"

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {

using nanopush::cli::column_tables;
using nanopush::cli::columns;
using nanopush::cli::parse_column_catalogue;

TEST_CASE("columns: every table of the catalogue makes a valid CSV header and sidecar", "[outputs][unit]") {
  const auto tables = column_tables();
  REQUIRE(tables.size() >= 40);
  const auto dir = nanopush::test::scratch_dir("columns");
  for (const auto& t : tables) {
    INFO(t);
    const auto& c = columns(t);
    REQUIRE_FALSE(c.empty());
    // The writer checks names, units and descriptions; uncommitted, it leaves nothing behind.
    CHECK_NOTHROW(nanopush::CsvWriter(dir / (t + ".csv"), c));
  }
  std::filesystem::remove_all(dir);
  CHECK_THROWS_AS(columns("no_such_table"), std::logic_error);
}

TEST_CASE("columns: the tables drivers/ looks up are the catalogue's tables", "[outputs][unit]") {
  const std::filesystem::path drivers = std::filesystem::path(NANOPUSH_SOURCE_DIR) / "drivers";
  const std::regex lookup(R"re(\bcolumns\("([A-Za-z0-9_]+)"\))re");
  std::set<std::string> named;
  for (const auto& e : std::filesystem::recursive_directory_iterator(drivers)) {
    const auto ext = e.path().extension();
    if (!e.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
    std::ifstream in(e.path());
    std::stringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    for (std::sregex_iterator m(text.begin(), text.end(), lookup), end; m != end; ++m) named.insert((*m)[1].str());
  }
  const auto tables = column_tables();
  const std::set<std::string> declared(tables.begin(), tables.end());
  for (const auto& n : named) {
    INFO("drivers/ looks up " << n);
    CHECK(declared.count(n) == 1);
  }
  for (const auto& d : declared) {
    INFO("drivers/columns.toml declares " << d);
    CHECK(named.count(d) == 1);
  }
}

TEST_CASE("columns: kinds, units and parameters as the catalogue gives them", "[outputs][unit]") {
  const auto c = parse_column_catalogue(R"(
[t]
columns = [
  { name = "x", unit = "m", description = "a length" },
  { name = "label", kind = "text", description = "a name" },
  { name = "n", kind = "count", description = "a count" },
  { name = "f", unit = "N", description = "a family member", parameters = { mu = 0.1 } },
]
)",
                                        "test");
  const auto& t = c.at("t");
  REQUIRE(t.size() == 4);
  CHECK((t[0].unit == "m" && t[0].type == "number"));
  CHECK((t[1].unit.empty() && t[1].type == "string"));
  CHECK((t[2].unit == "1" && t[2].type == "integer"));
  CHECK(t[3].parameters.at("mu") == 0.1);
}

TEST_CASE("columns: a faulty catalogue is an internal error naming its table", "[outputs][unit]") {
  auto fails = [](const std::string& columns_line) {
    try {
      parse_column_catalogue("[bad_table]\ncolumns = [\n  " + columns_line + ",\n]\n", "test");
    } catch (const std::logic_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(fails(R"({ name = "x", description = "no unit" })"), Catch::Contains("[bad_table]"));
  CHECK_THAT(fails(R"({ name = "x", kind = "text", unit = "m", description = "a unit on text" })"),
             Catch::Contains("takes no unit"));
  CHECK_THAT(fails(R"({ name = "x", kind = "integer", unit = "1", description = "no such kind" })"),
             Catch::Contains("kind 'integer'"));
  CHECK_THAT(fails(R"({ name = "x", unit = "m", describe = "a typo" })"), Catch::Contains("unknown key"));
  CHECK_THAT(fails(R"({ name = "x", unit = "m", description = "a" }, { name = "x", unit = "m", description = "b" })"),
             Catch::Contains("twice"));
  CHECK_THROWS_AS(parse_column_catalogue("[t]\ncolumns = [", "test"), std::logic_error);
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
