// Shared between the fitting sources (not installed): the scene at a parameter vector and the
// parameter scales.
#pragma once
#include <string>
#include <vector>

#include "nanopush/scenes/scene.hpp"

namespace nanopush::fit::detail {

/// The scene with free[k] = p[k] (Scene::set, validated together).
Scene scene_at(const Scene& base, const std::vector<std::string>& free, const std::vector<double>& p);
/// Scale of a parameter: |value| when non-zero, else the natural scale of its unit in the scene.
double parameter_scale(const Scene& scene, const std::string& key, double value);
/// The value of a numeric key in the scene's document, or the derived value (mass, inertia,
/// normal load) when the document does not hold it; InputError for keys that cannot be fitted.
double key_value(const Scene& scene, const std::string& key);

}  // namespace nanopush::fit::detail
