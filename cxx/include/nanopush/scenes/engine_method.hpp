// A front end's --engine against the scene's own method (docs/errors.md, "Bad input").
#pragma once
#include "nanopush/scenes/simulate.hpp"

namespace nanopush {

/// A front end's --engine f77 against the scene's own solver.method (from its file or --set):
/// the F77 engine has one method, so a scene that names another (modern, dop853, cvode) is a
/// conflict, InputError naming both sides; faithful and auto go with either engine.
/// (resolve_settings lets the scene's method go, as compare and reproduce run any scene on the
/// F77 engine.)
void check_engine_method(const Scene& scene, const RunSettings& settings);

}  // namespace nanopush
