// C API: a preset scene by name (bindings/nanopush.h, nanopush_scene_preset), found by the one
// preset rule of the command line and Python (nanopush/scenes/presets.hpp).
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>

#include "capi_internal.hpp"
#include "nanopush/scenes/presets.hpp"

using namespace nanopush::capi;
namespace fs = std::filesystem;

namespace {
/// The installed presets of the prefix holding this code: <prefix>/share/nanopush/scenes beside
/// <prefix>/lib/libnanopush_capi.so, or beside <prefix>/bin/PROGRAM when the library is linked
/// statically into a program. Empty when the file holding this code is not known.
fs::path installed_scenes() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&nanopush_scene_preset), &info) == 0 || !info.dli_fname || !*info.dli_fname)
    return {};
  std::error_code ec;
  const fs::path file = fs::canonical(info.dli_fname, ec);
  if (ec) return {};
  return file.parent_path().parent_path() / "share" / "nanopush" / "scenes";
}
}  // namespace

extern "C" {

nanopush_scene nanopush_scene_preset(nanopush_error error, const char* name, const char* scenes_dir) {
  nanopush_scene out = nullptr;
  guarded(error, [&] {
    require_handle(name, "name");
    if (!*name) throw nanopush::InputError("name", "\"\"", "a preset name (nanopush presets lists them)");
    fs::path dir;
    std::string from;
    if (scenes_dir && *scenes_dir) {
      dir = scenes_dir;
      from = "scenes_dir";
    } else if (const char* e = std::getenv("NANOPUSH_SCENES"); e && *e) {
      dir = e;
      from = "$NANOPUSH_SCENES";
    } else {
      dir = installed_scenes();
      from = "the installed presets";
    }
    std::error_code ec;
    if (dir.empty() || !fs::is_directory(dir, ec))
      throw nanopush::InputError("name", name,
                                 "no presets directory: " + from + " = " + (dir.empty() ? "(unknown)" : dir.string()) +
                                     " is not a directory (pass scenes_dir or set NANOPUSH_SCENES to "
                                     "<prefix>/share/nanopush/scenes)");
    const auto file = nanopush::find_preset(dir, name);
    if (!file)
      throw nanopush::InputError("name", name, "no preset of that name under " + dir.string() + " (" + from + ")");
    auto s = std::make_unique<nanopush_scene_s>();
    s->scene = nanopush::load_scene(file->string());
    out = s.release();
    return NANOPUSH_OK;
  });
  return out;
}

}  // extern "C"
