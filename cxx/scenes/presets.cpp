#include "nanopush/scenes/presets.hpp"

#include <algorithm>
#include <fstream>

#include "nanopush/numerics/error.hpp"

namespace nanopush {

namespace fs = std::filesystem;

namespace {
/// The first comment line of a scene file, without its '#' and surrounding blanks.
std::string first_comment(const fs::path& file) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] != '#') continue;
    const auto text_start = line.find_first_not_of("# \t", start);
    std::string text = text_start == std::string::npos ? std::string() : line.substr(text_start);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.pop_back();
    return text;
  }
  return {};
}
bool regular(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}
}  // namespace

std::optional<fs::path> find_preset(const fs::path& dir, const std::string& name) {
  for (const fs::path& cand : {dir / (name + ".toml"), dir / name})
    if (regular(cand)) return cand;
  // Presets live in subdirectories (thesis/, bench/, examples/): searched in that order.
  for (const char* sub : {"thesis", "bench", "examples"})
    if (const fs::path cand = dir / sub / (name + ".toml"); regular(cand)) return cand;
  return std::nullopt;
}

std::vector<PresetEntry> list_presets(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError("scenes directory", dir.string(), "no such directory (set NANOPUSH_SCENES)");
  std::vector<PresetEntry> out;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".toml") continue;
    PresetEntry p;
    p.path = entry.path();
    p.name = fs::relative(entry.path(), dir).replace_extension().generic_string();
    const std::string stem = entry.path().stem().string();
    if (stem != p.name)
      if (const auto found = find_preset(dir, stem); found && fs::equivalent(*found, entry.path(), ec)) p.short_name = stem;
    p.description = first_comment(entry.path());
    out.push_back(std::move(p));
  }
  std::sort(out.begin(), out.end(), [](const PresetEntry& a, const PresetEntry& b) { return a.name < b.name; });
  return out;
}

}  // namespace nanopush
