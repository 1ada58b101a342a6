// The preset rule (nanopush/scenes/presets.hpp), shared by the command line and Python: where
// a name is found, in which order the folders are searched, and the list with short names.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/presets.hpp"

using namespace nanopush;
namespace fs = std::filesystem;

TEST_CASE("presets: a name is found as NAME.toml, NAME, then in thesis/, bench/, examples/", "[presets][unit]") {
  const fs::path dir = fs::temp_directory_path() / ("nanopush_presets_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  for (const char* sub : {"thesis", "bench", "examples"}) fs::create_directories(dir / sub);
  auto write = [&](const fs::path& p, const std::string& comment) { std::ofstream(p) << "# " << comment << "\n"; };
  write(dir / "top.toml", "at the top");
  write(dir / "thesis" / "twice.toml", "thesis copy");
  write(dir / "bench" / "twice.toml", "bench copy");
  write(dir / "examples" / "only_here.toml", "  an example  ");
  CHECK(find_preset(dir, "top") == dir / "top.toml");
  CHECK(find_preset(dir, "top.toml") == dir / "top.toml");
  CHECK(find_preset(dir, "twice") == dir / "thesis" / "twice.toml");  // thesis/ before bench/
  CHECK(find_preset(dir, "bench/twice") == dir / "bench/twice.toml");
  CHECK(find_preset(dir, "only_here") == dir / "examples" / "only_here.toml");
  CHECK_FALSE(find_preset(dir, "none").has_value());
  CHECK_FALSE(find_preset(dir, "thesis").has_value());  // a directory is no preset

  const auto list = list_presets(dir);
  REQUIRE(list.size() == 4);
  CHECK(std::is_sorted(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.name < b.name; }));
  auto entry = [&](const std::string& name) {
    return *std::find_if(list.begin(), list.end(), [&](const PresetEntry& e) { return e.name == name; });
  };
  CHECK(entry("thesis/twice").short_name == "twice");
  CHECK(entry("bench/twice").short_name.empty());  // the short name finds the thesis copy
  CHECK(entry("examples/only_here").short_name == "only_here");
  CHECK(entry("examples/only_here").description == "an example");
  CHECK(entry("top").short_name.empty());  // its name is already short
  fs::remove_all(dir);
  CHECK_THROWS_AS(list_presets(dir), InputError);
}

TEST_CASE("presets: the project's presets resolve by their short names", "[presets][unit]") {
  const fs::path dir = fs::path(NANOPUSH_SOURCE_DIR) / "drivers" / "scenes";
  CHECK(find_preset(dir, "fig3_6a") == dir / "thesis" / "fig3_6a.toml");
  for (const PresetEntry& e : list_presets(dir))
    if (!e.short_name.empty()) CHECK(find_preset(dir, e.short_name) == e.path);
}
