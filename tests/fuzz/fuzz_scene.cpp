// libFuzzer target: the scene parser and the --set path. An input is TOML text, optionally
// followed by a line "#--set" and lines KEY=VALUE that are applied as `--set` would apply
// them (SceneValue::from_text, then Scene::set). Bad input must end in InputError (or, for a
// scene whose [environment] integrates, SolverError); anything else -- a crash, a sanitizer
// report, another exception, a hang -- is a finding. tests/fuzz/run.sh builds and runs it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > nanopush::kMaxSceneBytes) return -1;  // load_scene never reads more
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kSep = "\n#--set\n";
  const auto sep = in.find(kSep);
  const std::string_view toml = in.substr(0, sep);
  std::vector<std::string> sets;
  if (sep != std::string_view::npos) {
    std::string_view rest = in.substr(sep + kSep.size());
    while (!rest.empty()) {
      const auto nl = rest.find('\n');
      sets.emplace_back(rest.substr(0, nl));
      rest = nl == std::string_view::npos ? std::string_view() : rest.substr(nl + 1);
    }
  }
  try {
    nanopush::Scene sc = nanopush::parse_scene(toml, "fuzz.toml");
    (void)sc.to_toml();
    for (const auto& s : sets) {
      const auto eq = s.find('=');
      if (eq == std::string::npos || eq == 0) continue;  // the CLI refuses these before the scene
      try {
        const std::string key = s.substr(0, eq);
        sc.set(key, nanopush::SceneValue::from_text(key, s.substr(eq + 1)));
        (void)sc.output_times().size();
        (void)sc.state_scales();
      } catch (const nanopush::InputError&) {
      }
    }
  } catch (const nanopush::InputError&) {
  } catch (const nanopush::SolverError&) {
  }
  return 0;
}
