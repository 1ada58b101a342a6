#include "registry.hpp"

#include <cstdlib>

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

std::filesystem::path scenes_dir() {
  if (const char* e = std::getenv("NANOPUSH_SCENES"); e && *e) return e;
  return std::filesystem::path(NANOPUSH_SOURCE_DIR) / "drivers" / "scenes";
}

std::filesystem::path resolve_scene(const std::string& arg) {
  namespace fs = std::filesystem;
  if (fs::exists(arg)) return arg;
  const fs::path dir = scenes_dir();
  for (const fs::path& cand : {dir / (arg + ".toml"), dir / arg}) {
    if (fs::exists(cand) && fs::is_regular_file(cand)) return cand;
  }
  // Presets live in subdirectories (thesis/, bench/, examples/): search them in that order.
  for (const char* sub : {"thesis", "bench", "examples"}) {
    const fs::path cand = dir / sub / (arg + ".toml");
    if (fs::exists(cand) && fs::is_regular_file(cand)) return cand;
  }
  throw InputError("SCENE", arg, "no such file, and no preset of that name under " + dir.string());
}

}  // namespace nanopush::cli
