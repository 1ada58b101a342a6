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
#include "nanopush/scenes/presets.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

int presets_cmd() {
  const std::filesystem::path dir = scenes_dir();
  const std::vector<PresetEntry> presets = list_presets(dir);  // scenes/presets.hpp
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
