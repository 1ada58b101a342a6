#include "registry.hpp"

#include "nanopush/scenes/presets.hpp"

#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

#include "nanopush/numerics/error.hpp"

namespace nanopush::cli {

std::vector<Command>& commands() {
  static std::vector<Command> c;
  return c;
}

std::vector<ReproduceStep>& reproduce_steps() {
  static std::vector<ReproduceStep> s;
  return s;
}

std::filesystem::path executable_dir() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path(".") : exe.parent_path();
}

namespace {
/// The source tree of a build tree: the executable sits at the top of its build tree, beside
/// CMakeCache.txt, which names the source directory. Empty when not run from a build tree.
std::filesystem::path build_tree_source_dir(const std::filesystem::path& exe_dir) {
  std::ifstream cache(exe_dir / "CMakeCache.txt");
  const std::string key = "CMAKE_HOME_DIRECTORY:INTERNAL=";
  for (std::string line; std::getline(cache, line);)
    if (line.rfind(key, 0) == 0) return line.substr(key.size());
  return {};
}
}  // namespace

std::filesystem::path scenes_dir() {
  if (const char* e = std::getenv("NANOPUSH_SCENES"); e && *e) return e;
  // Installed: <prefix>/bin/nanopush and <prefix>/share/nanopush/scenes (wherever the prefix is).
  const fs::path exe_dir = executable_dir();
  const fs::path installed = exe_dir.parent_path() / "share" / "nanopush" / "scenes";
  if (fs::is_directory(installed)) return installed;
  // The build tree: the presets of its source tree.
  if (const fs::path src = build_tree_source_dir(exe_dir); !src.empty()) return src / "drivers" / "scenes";
  return installed;
}

std::filesystem::path resolve_scene(const std::string& arg) {
  if (fs::exists(arg)) return arg;
  const fs::path dir = scenes_dir();
  if (const auto found = find_preset(dir, arg)) return *found;  // the preset rule (scenes/presets.hpp)
  throw InputError("SCENE", arg, "no such file, and no preset of that name under " + dir.string());
}

}  // namespace nanopush::cli
