#include "scene_args.hpp"

#include "nanopush/numerics/error.hpp"
#include "registry.hpp"

namespace nanopush::cli {

void add_set_option(CLI::App& app, std::vector<std::string>& sets) {
  app.add_option("--set", sets,
                 "KEY=VALUE: set a scene key after loading, validated as in the file (repeatable; e.g. "
                 "--set surface.mu=0.1 --set push.yn=20e-9; `nanopush scene-keys` lists the keys)")
      ->type_name("KEY=VALUE");
}

std::vector<SceneSetting> parse_settings(const std::vector<std::string>& sets, const std::string& option) {
  std::vector<SceneSetting> out;
  for (const auto& s : sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError(option, s, "must be KEY=VALUE, e.g. surface.mu=0.1");
    const std::string key = s.substr(0, eq);
    out.emplace_back(key, SceneValue::from_text(key, s.substr(eq + 1)));
  }
  return out;
}

Scene load_scene_arg(const std::string& scene, const std::vector<std::string>& sets) {
  Scene sc = load_scene(resolve_scene(scene));
  if (!sets.empty()) sc.set(parse_settings(sets));
  return sc;
}

}  // namespace nanopush::cli
