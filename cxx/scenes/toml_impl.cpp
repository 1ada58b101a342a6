// toml++'s code, compiled once into nanopush_scenes (TOML_IMPLEMENTATION with
// TOML_HEADER_ONLY=0: the library's own way of building it into a program). Every other file
// that includes <toml++/toml.h> sees declarations only (the nanopush_toml target, CMakeLists.txt),
// so no program of the project loads toml++'s shared library, and the installed package needs
// no toml++ (docs/performance.md, "Process start"; scenes/toml_fwd.hpp).
#define TOML_IMPLEMENTATION
#include "nanopush_toml.hpp"
