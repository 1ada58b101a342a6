// A front end's --engine f77 against the scene's own solver.method (engine_method.hpp).
#include "nanopush/scenes/engine_method.hpp"

#include "nanopush/numerics/error.hpp"

namespace nanopush {

void check_engine_method(const Scene& scene, const RunSettings& in) {
  if (in.engine != Engine::f77 || in.method) return;  // a --method of its own: resolve_settings
  const Method m = scene.solver.method;
  if (m == Method::faithful || m == Method::automatic) return;
  throw InputError("--engine", "f77",
                   "conflicts with the scene's solver.method = \"" + to_string(m) +
                       "\": the f77 engine has one method (its Bulirsch-Stoer); drop solver.method or use --engine cxx");
}

}  // namespace nanopush
