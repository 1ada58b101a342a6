// nanopush presets: the preset scenes (scenes_dir(): installed share/nanopush/scenes, the
// source tree's drivers/scenes, or $NANOPUSH_SCENES), each with the names `nanopush run`
// accepts and its one-line description (the first comment line of the TOML file).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "nanopush/numerics/error.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct Preset {
  std::string name;   ///< path under scenes_dir() without .toml, e.g. thesis/fig3_6a
  std::string short_name;  ///< the bare stem when `nanopush run <stem>` finds this file, else empty
  std::string description;
};

/// The first comment line of a scene file, without its '#' and surrounding blanks.
std::string first_comment(const std::filesystem::path& file) {
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

std::vector<Preset> list_presets(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(dir))
    throw InputError("scenes directory", dir.string(), "no such directory (set NANOPUSH_SCENES)");
  std::vector<Preset> out;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".toml") continue;
    Preset p;
    p.name = fs::relative(entry.path(), dir).replace_extension().generic_string();
    const std::string stem = entry.path().stem().string();
    std::error_code ec;
    try {
      if (stem != p.name && fs::equivalent(resolve_scene(stem), entry.path(), ec)) p.short_name = stem;
    } catch (const InputError&) {
    }
    p.description = first_comment(entry.path());
    out.push_back(std::move(p));
  }
  std::sort(out.begin(), out.end(), [](const Preset& a, const Preset& b) { return a.name < b.name; });
  return out;
}

int presets_cmd() {
  const std::filesystem::path dir = scenes_dir();
  const std::vector<Preset> presets = list_presets(dir);
  std::size_t w_name = 4, w_short = 5;
  for (const auto& p : presets) {
    w_name = std::max(w_name, p.name.size());
    w_short = std::max(w_short, p.short_name.size());
  }
  const auto pad = [](const std::string& s, std::size_t w) { return s + std::string(w - s.size() + 2, ' '); };
  std::cout << "# " << presets.size() << " preset scenes in " << dir.string() << "\n"
            << pad("name", w_name) << pad("short", w_short) << "description\n";
  for (const auto& p : presets)
    std::cout << pad(p.name, w_name) << pad(p.short_name.empty() ? "-" : p.short_name, w_short) << p.description << "\n";
  return 0;
}

RegisterCommand reg_presets{
    {"presets",
     "List the preset scenes, sorted: the names `nanopush run` accepts (thesis/fig3_6a, or the short fig3_6a) "
     "and each scene's one-line description (the first comment line of its TOML file)",
     15, [](CLI::App& app) -> std::function<int()> {
       app.footer("Presets are found in $NANOPUSH_SCENES, else <prefix>/share/nanopush/scenes beside the installed "
                  "nanopush, else the source tree's drivers/scenes (build tree).");
       return [] { return presets_cmd(); };
     }}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
