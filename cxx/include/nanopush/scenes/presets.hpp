// Preset scenes: where a preset name is found under a scenes directory, and the list of them.
// The one rule for the command line (nanopush run fig3_6a, nanopush presets) and Python
// (Scene.preset, nanopush.presets()); each front end chooses the directory ($NANOPUSH_SCENES,
// the installed share/nanopush/scenes, the package's copy).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace nanopush {

/// The file of preset `name` under `dir`: NAME.toml or NAME there, then NAME.toml in its
/// thesis/, bench/ and examples/ folders, in that order; nullopt when none is a regular file.
std::optional<std::filesystem::path> find_preset(const std::filesystem::path& dir, const std::string& name);

struct PresetEntry {
  std::string name;         ///< path under the directory without .toml, e.g. thesis/fig3_6a
  std::string short_name;   ///< the bare stem when find_preset(stem) finds this file, else ""
  std::string description;  ///< the first comment line of the file, without '#'
  std::filesystem::path path;
};

/// Every preset (*.toml, recursively) under `dir`, sorted by name. InputError when `dir` is
/// not a directory.
std::vector<PresetEntry> list_presets(const std::filesystem::path& dir);

}  // namespace nanopush
