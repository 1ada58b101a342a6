// The CSV convention (docs/outputs.md): numbers in the shortest form that reads back to the
// same double, the empty cell for a missing value, a Table Schema sidecar beside every CSV,
// both files written atomically.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "nanopush/outputs/io.hpp"

using nanopush::csv_number;

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
double read_back(const std::string& s) { return std::strtod(s.c_str(), nullptr); }
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST_CASE("csv_number: every double reads back exactly", "[outputs][unit]") {
  const double edge[] = {0.0,
                         -0.0,
                         0.1,
                         3e-08,
                         1.6e-09,
                         1.0 / 3.0,
                         std::numeric_limits<double>::max(),
                         -std::numeric_limits<double>::max(),
                         std::numeric_limits<double>::min(),
                         std::numeric_limits<double>::denorm_min(),
                         -std::numeric_limits<double>::denorm_min(),
                         std::numeric_limits<double>::min() / 3,
                         std::numeric_limits<double>::epsilon(),
                         1.0 + std::numeric_limits<double>::epsilon(),
                         9007199254740992.0,
                         9007199254740993.0,
                         1e300,
                         -2.5e-320,
                         123456789012345678.0};
  for (double x : edge) {
    INFO(csv_number(x));
    CHECK(same_bits(read_back(csv_number(x)), x));
  }
  std::mt19937_64 rng(20121124);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-330, 308);
  for (int i = 0; i < 200000; ++i) {
    const double x = u(rng) * std::pow(10.0, e(rng));
    if (!same_bits(read_back(csv_number(x)), x)) FAIL("no round trip: " << csv_number(x));
    std::uint64_t bits = rng();
    double y;
    std::memcpy(&y, &bits, sizeof y);
    if (std::isfinite(y) && !same_bits(read_back(csv_number(y)), y)) FAIL("no round trip (bits): " << csv_number(y));
  }
}

TEST_CASE("csv_number: the shortest form, plain digits for integers", "[outputs][unit]") {
  CHECK(csv_number(3e-08) == "3e-08");
  CHECK(csv_number(0.1) == "0.1");
  CHECK(csv_number(1.6e-09) == "1.6e-09");
  CHECK(csv_number(0.30000000000000004) == "0.30000000000000004");
  CHECK(csv_number(0.0) == "0");
  CHECK(csv_number(-0.0) == "-0");
  CHECK(csv_number(-0.5) == "-0.5");
  CHECK(csv_number(1e300) == "1e+300");
  CHECK(csv_number(2.75e-08) == "2.75e-08");
  // Integral values (counts) in plain digits up to 2^53, where every integer is exact.
  CHECK(csv_number(100000.0) == "100000");
  CHECK(csv_number(1234.0) == "1234");
  CHECK(csv_number(-42.0) == "-42");
  CHECK(csv_number(9007199254740992.0) == "9007199254740992");
  CHECK(csv_number(1e20) == "1e+20");
}

TEST_CASE("csv_number: missing and infinite values", "[outputs][unit]") {
  CHECK(csv_number(std::numeric_limits<double>::quiet_NaN()).empty());
  CHECK(csv_number(-std::numeric_limits<double>::quiet_NaN()).empty());
  CHECK(csv_number(std::numeric_limits<double>::infinity()) == "inf");
  CHECK(csv_number(-std::numeric_limits<double>::infinity()) == "-inf");
  CHECK(std::isinf(read_back("inf")));
  CHECK(read_back("-inf") < 0);
}

TEST_CASE("CsvWriter: the CSV and its Table Schema sidecar appear together", "[outputs][unit]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("nanopush_test_outputs_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  nanopush::set_provenance("9.9.9", "nanopush test \"quoted\"");
  const fs::path csv = dir / "a.csv";
  CHECK(nanopush::schema_path(csv) == dir / "a.schema.json");
  CHECK(nanopush::schema_path(dir / "b.partial.csv") == dir / "b.partial.schema.json");
  {
    nanopush::CsvWriter w(csv, {{"t", "s", "time"}, {"mu", "1", "friction coefficient", "number", {{"mu", 0.1}}},
                                nanopush::text_column("label", "a name")},
                          "thesis/fig3_6a");
    w.cells({csv_number(3e-08), csv_number(std::nan("")), nanopush::csv_quote("a, b")});
    // Nothing appears before commit().
    CHECK_FALSE(fs::exists(csv));
    CHECK_FALSE(fs::exists(dir / "a.schema.json"));
    w.commit();
  }
  CHECK(slurp(csv) == "t,mu,label\n3e-08,,\"a, b\"\n");
  const std::string j = slurp(dir / "a.schema.json");
  const auto doc = nlohmann::json::parse(j);  // a JSON document, read as one
  CHECK(doc["fields"][0] == nlohmann::json{{"name", "t"}, {"type", "number"}, {"unit", "s"}, {"description", "time"}});
  CHECK(doc["fields"][1]["nanopush:parameters"] == nlohmann::json{{"mu", 0.1}});
  CHECK(doc["fields"][2]["type"] == "string");
  CHECK(doc["fields"][2]["unit"] == "");
  CHECK(doc["missingValues"] == nlohmann::json::array({""}));
  CHECK(doc["nanopush"]["command"] == "nanopush test \"quoted\"");
  CHECK(j.find(R"("version": "9.9.9")") != std::string::npos);
  CHECK(j.find(R"("command": "nanopush test \"quoted\"")") != std::string::npos);
  CHECK(j.find(R"("scene": "thesis/fig3_6a")") != std::string::npos);
  CHECK(j.find(R"("created": "20)") != std::string::npos);
  // A command line that is not UTF-8 (bytes of a file name) still gives a sidecar: U+FFFD.
  nanopush::set_provenance("9.9.9", "nanopush run x --out \xff\xfe.csv");
  {
    nanopush::CsvWriter w(dir / "c.csv", {{"x", "m", "x"}});
    w.row({1.0});
    w.commit();
  }
  CHECK(nlohmann::json::parse(slurp(dir / "c.schema.json"))["nanopush"]["command"] ==
        "nanopush run x --out \xef\xbf\xbd\xef\xbf\xbd.csv");
  fs::remove(dir / "c.csv");
  fs::remove(dir / "c.schema.json");
  nanopush::set_provenance("9.9.9", "nanopush test \"quoted\"");
  // A writer that never commits leaves nothing, not even temporaries.
  {
    nanopush::CsvWriter w(dir / "b.csv", {{"x", "m", "x"}});
    w.row({1.0});
  }
  CHECK_FALSE(fs::exists(dir / "b.csv"));
  CHECK_FALSE(fs::exists(dir / "b.schema.json"));
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  CHECK(n == 2);
  // Bad column declarations are programming errors, refused at once.
  CHECK_THROWS(nanopush::CsvWriter(dir / "c.csv", {{"F_min_mu=0.1", "N", "bad name"}}));
  CHECK_THROWS(nanopush::CsvWriter(dir / "c.csv", {{"x", "", "no unit"}}));
  CHECK_THROWS(nanopush::CsvWriter(dir / "c.csv", {{"x", "m", ""}}));
  // A row of the wrong width too.
  nanopush::CsvWriter w(dir / "d.csv", {{"x", "m", "x"}});
  CHECK_THROWS(w.row({1.0, 2.0}));
  nanopush::set_provenance("", "");
  fs::remove_all(dir);
}

TEST_CASE("join_command_line quotes what a shell would split", "[outputs][unit]") {
  const char* argv[] = {"/usr/bin/nanopush", "run", "my scene.toml", "--out", "-"};
  CHECK(nanopush::join_command_line(5, argv) == "nanopush run 'my scene.toml' --out -");
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
