// Shared between the fitting sources (not installed): the scene at a parameter vector and the
// parameter scales.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"

namespace nanopush::fit::detail {

/// The scene with free[k] = p[k] (Scene::set, validated together).
Scene scene_at(const Scene& base, const std::vector<std::string>& free, const std::vector<double>& p);
/// Scale of a parameter: |value| when non-zero, else the natural scale of its unit in the scene.
double parameter_scale(const Scene& scene, const std::string& key, double value);
/// The value of a numeric key in the scene's document, or the derived value (mass, inertia,
/// normal load) when the document does not hold it; InputError for keys that cannot be fitted.
double key_value(const Scene& scene, const std::string& key);

/// The law a fit runs under: `law`, or the scene's; thesis or coulomb (the printed law is not
/// fitted), else InputError naming --law.
inline Law fit_law(const Scene& scene, std::optional<Law> law) {
  const Law l = law.value_or(scene.surface.law);
  if (l != Law::thesis && l != Law::coulomb) throw InputError("--law", to_string(l), "must be thesis or coulomb");
  return l;
}

}  // namespace nanopush::fit::detail
