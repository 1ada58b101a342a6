// nanopush scene-keys: every key a scene file may hold, with type, unit, default and range
// (the table the parser and --set use; docs/scenes.md holds the same table).
#include <iomanip>
#include <iostream>

#include "nanopush/scenes/scene_keys.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

int keys_cmd(bool markdown) {
  if (markdown) {
    std::cout << scene_keys_markdown();
    return 0;
  }
  for (const auto& k : scene_keys()) {
    std::cout << std::left << std::setw(38) << k.key << std::setw(8) << key_type_name(k.type) << " ["
              << (k.unit.empty() ? "-" : k.unit) << "] default " << k.default_text << "; allowed " << k.range << "; "
              << (k.kinds == "all" ? "any surface" : std::string(k.kinds) + " surface") << "\n    " << k.description
              << "\n";
  }
  return 0;
}

RegisterCommand reg{{"scene-keys", "List every scene key: type, unit, default, allowed range (what --set accepts)", 85,
                     [](CLI::App& app) -> std::function<int()> {
                       auto md = std::make_shared<bool>(false);
                       app.add_flag("--markdown", *md, "print the table as Markdown (as in docs/scenes.md)");
                       return [md] { return keys_cmd(*md); };
                     }}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
