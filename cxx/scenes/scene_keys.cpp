// The scene key table (scene_keys.hpp). Ranges are written as the parser checks them
// (scene.cpp, environment_toml.cpp); tests/test_scene_keys.cpp holds the two together.
#include "nanopush/scenes/scene_keys.hpp"

#include "nanopush/scenes/choices.hpp"

#include <algorithm>
#include <set>
#include <sstream>

namespace nanopush {

std::string_view key_type_name(KeyType t) {
  switch (t) {
    case KeyType::number: return "number";
    case KeyType::integer: return "integer";
    case KeyType::string: return "string";
    case KeyType::boolean: return "boolean";
    case KeyType::array: return "array";
    case KeyType::table: return "table";
  }
  return "?";
}

const std::vector<SceneKey>& scene_keys() {
  using K = KeyType;
  // The choice keys' allowed values come from the choices' name tables (choices.hpp).
  static const std::string kinds = choice_names<SurfaceKind>(", "), laws = choice_names<Law>(", "),
                           engines = choice_names<Engine>(", "), methods = choice_names<Method>(", "),
                           precisions = choice_names<Precision>(", "), push_modes = choice_names<PushMode>(", "),
                           tip_models = choice_names<TipModel>(", ");
  static const std::vector<SceneKey> keys = {
      {"scene.name", K::string, "", "file stem", "letters, digits, _ - . (not first: . -), <= 200", "all",
       "identifier used in output names"},
      {"scene.description", K::string, "", "\"\"", "any text", "all", "one line shown by `nanopush presets`"},

      {"object.shape", K::string, "", "bar", "bar", "all", "a 2a x 2b rectangle seen from above"},
      {"object.length", K::number, "m", "required", "> 0", "all", "along body y' (= 2b)"},
      {"object.width", K::number, "m", "required", "> 0", "all", "along body x' (= 2a)"},
      {"object.height", K::number, "m", "needed with density", "> 0", "all", "height of the bar"},
      {"object.density", K::number, "kg/m^3", "either this or mass", "> 0", "all",
       "mass = density x length x width x height"},
      {"object.mass", K::number, "kg", "either this or density", "> 0", "all", "mass of the object"},
      {"object.inertia", K::number, "kg m^2", "m (length^2 + width^2)/12", "> 0", "all",
       "moment of inertia about the centre of mass, z axis"},

      {"push.mode", K::string, "", "force", push_modes, "all",
       "force: a constant force at a body point (the keys below); tip: an AFM tip moving along a line (tip.*, "
       "rough surface, docs/tip.md)"},
      {"push.force", K::number, "N", "required (mode force)", "> 0", "all", "magnitude F of the push"},
      {"push.direction", K::number, "rad", "0", "finite", "all", "world direction beta of the push"},
      {"push.xn", K::number, "m", "one of xn/yn or point", "abs(xn) <= width/2", "all",
       "thesis push coordinates: the body point (xn, -yn) (docs/models.md section 0)"},
      {"push.yn", K::number, "m", "one of xn/yn or point", "abs(yn) <= length/2", "all",
       "thesis push coordinates: the body point (xn, -yn)"},
      {"push.point", K::array, "m", "one of xn/yn or point", "[x', y'] on the body", "all",
       "push point in body axes"},

      {"tip.start_x", K::number, "m", "required (mode tip)", "finite; the tip outside the bar", "rough",
       "world x of the tip centre at t = 0"},
      {"tip.start_y", K::number, "m", "required (mode tip)", "finite; the tip outside the bar", "rough",
       "world y of the tip centre at t = 0"},
      {"tip.direction", K::number, "rad", "0", "finite", "rough", "world direction the tip moves in"},
      {"tip.speed", K::number, "m/s", "1e-6", "> 0", "rough", "tip speed (AFM tips: 1e-7 to 1e-4 m/s)"},
      {"tip.travel", K::number, "m", "required (mode tip)", "> 0", "rough", "length of the tip's path"},
      {"tip.radius", K::number, "m", "1e-8", "> 0", "rough", "radius of the tip (a disc seen from above)"},
      {"tip.mu", K::number, "1", "0", "[0, 10]", "rough",
       "Coulomb friction between tip and object"},
      {"tip.model", K::string, "", "quasi_static", tip_models, "rough",
       "quasi_static: the object in force equilibrium with the tip; dynamic: its inertia and the tip's spring; "
       "auto: dynamic where m v^2/(mu N travel) > 1e-3 (docs/tip.md)"},
      {"tip.stiffness", K::number, "N/m", "from tip.cantilever; required by the dynamic model without it", "> 0",
       "rough", "lateral spring between the tip and its base (dynamic model)"},
      {"tip.cantilever.youngs_modulus", K::number, "Pa", "required with [tip.cantilever]", "> 0", "rough",
       "the cantilever's Young's modulus: tip.stiffness = twist (eq 2.6) and lateral bending (eq 2.7) in series"},
      {"tip.cantilever.poisson_ratio", K::number, "1", "0.33", "(-1, 0.5]", "rough", "the cantilever's Poisson's ratio"},
      {"tip.cantilever.length", K::number, "m", "required with [tip.cantilever]", "> 0", "rough", "beam length l"},
      {"tip.cantilever.width", K::number, "m", "required with [tip.cantilever]", "> 0", "rough", "beam width w"},
      {"tip.cantilever.thickness", K::number, "m", "required with [tip.cantilever]", "> 0", "rough",
       "beam thickness t"},
      {"tip.cantilever.tip_height", K::number, "m", "required with [tip.cantilever]", "> 0", "rough",
       "height H of the tip (the lateral force's lever on the beam)"},
      {"initial.x", K::number, "m", "0", "finite", "all", "initial x of the centre of mass"},
      {"initial.y", K::number, "m", "0", "finite", "all", "initial y of the centre of mass"},
      {"initial.theta", K::number, "rad", "0", "finite", "all", "initial angle"},
      {"initial.vx", K::number, "m/s", "0", "finite", "all", "initial velocity, x"},
      {"initial.vy", K::number, "m/s", "0", "finite", "all", "initial velocity, y"},
      {"initial.omega", K::number, "rad/s", "0", "finite", "all", "initial angular velocity"},

      {"surface.kind", K::string, "", "smooth", kinds, "all",
       "smooth (docs/models.md section A) or rough (section C)"},
      {"surface.mu", K::number, "1", "required", "[0, 10]", "rough", "Coulomb friction coefficient"},
      {"surface.f_vdw", K::number, "N", "0", ">= 0", "rough", "adhesion (van der Waals) load added to m g"},
      {"surface.g", K::number, "m/s^2", "9.81", ">= 0", "rough", "gravity"},
      {"surface.normal_load", K::number, "N", "m g + f_vdw", "> 0", "rough", "normal load N, given directly"},
      {"surface.law", K::string, "", "thesis", laws, "rough",
       "friction law: the eq 3.40 sign law, the same with eqs 3.45-3.48 as printed, or event-located "
       "stick-slip"},
      {"surface.printed.reading", K::string, "", "literal", "literal, as_drawn, corrected", "rough",
       "the printed law's reading of the slips (docs/rough.md); the four keys below override it"},
      {"surface.printed.fy_sign", K::boolean, "", "the reading's (true)", "true, false", "rough",
       "printed law: eq 3.46's sign of fy' as printed (errata F1); false: the sign of eq 3.43"},
      {"surface.printed.omega_sign", K::boolean, "", "the reading's (true)", "true, false", "rough",
       "printed law: eq 3.47 without sign(theta-dot) as printed (F3); false: mf times sign(theta-dot)"},
      {"surface.printed.c4", K::string, "", "the reading's (squares_nm)", "squares_nm, cubes", "rough",
       "printed law: eq 3.48's C4 with squares, lengths in nm, as printed (F2); cubes: dimensionally consistent"},
      {"surface.printed.eq3_50", K::boolean, "", "the reading's (false)", "true, false", "rough",
       "printed law: eq 3.50's fy = fx' sin - fy' cos as printed; false: erratum 3's +"},

      {"solver.t_end", K::number, "s", "required (mode tip: travel/speed; dynamic: plus the settling time)", "> 0", "all",
       "end time"},
      {"solver.samples", K::integer, "1", "401", "[2, 10000000]", "all",
       "output times, evenly spaced over [0, t_end], both ends included"},
      {"solver.rtol", K::number, "1", "1e-10", "[1e-30, 0.1]", "all", "relative tolerance"},
      {"solver.atol", K::number, "SI of each state", "0", ">= 0", "all",
       "absolute tolerance of every component; 0 = rtol x each component's natural scale"},
      {"solver.accuracy", K::number, "1", "0 (none)", "0 or [1e-14, 0.1]", "all",
       "the error asked for of the final pose (positions / max(length, distance), angle in rad): chooses rtol "
       "(docs/accuracy.md)"},
      {"solver.error_estimate", K::boolean, "", "true", "true, false", "all",
       "estimate the global error of the answer by a companion run at rtol/100 (docs/accuracy.md)"},
      {"solver.engine", K::string, "", "cxx", engines, "all", "the C++ solver or the FORTRAN 77 reproduction"},
      {"solver.method", K::string, "", "auto", methods, "all",
       "C++ integrator: Bulirsch-Stoer configuration (docs/bulirsch_stoer.md), dop853 (Dormand-Prince 8(5,3), "
       "docs/dop853.md: double, not the coulomb law); cvode: rough scenes, coulomb law; auto (default; faithful "
       "with engine f77): dop853 for rtol >= 1e-11 where it runs, else modern"},
      {"solver.precision", K::string, "", "double", precisions, "all",
       "scalar of the integration; long and quad: engine cxx, faithful or modern on a smooth surface, modern on a "
       "rough one (thesis or coulomb law)"},
      {"solver.h0", K::number, "s", "0 (1% of t_end)", ">= 0", "all", "initial step"},
      {"solver.hmax", K::number, "s", "0 (none)", ">= 0", "all", "largest step"},
      {"solver.max_steps", K::integer, "1", "100000", "[1, 1000000000]", "all",
       "attempted steps before giving up"},

      {"environment.medium", K::string, "", "vacuum", "vacuum, humid_air, liquid", "rough",
       "medium between body and substrate (docs/forces.md)"},
      {"environment.humidity", K::number, "1", "required with humid_air", "[0, 1]", "rough",
       "relative humidity p/p_sat (humid_air only)"},
      {"environment.temperature", K::number, "K", "293.15", "> 0", "rough", "temperature (Kelvin radius)"},
      {"environment.liquid", K::string, "", "water", "a liquid name, or a table (below)", "rough",
       "the liquid medium, or the condensate in humid air"},
      {"environment.contact_angle", K::number, "rad", "the liquid's", "[0, pi/2]", "rough",
       "contact angle of the liquid"},
      {"environment.adhesion", K::boolean, "", "true", "true, false", "rough",
       "false: ideal non-adhesive contact, no adhesion model evaluated"},
      {"environment.gap", K::number, "m", "2e-10", "> 0", "rough", "body-substrate separation at contact z0"},
      {"environment.gravity", K::number, "m/s^2", "9.81", ">= 0", "rough", "gravity"},
      {"environment.substrate", K::string, "", "the body's material", "a material name, or a table (below)",
       "rough", "substrate material"},
      {"environment.substrate.material", K::string, "", "custom", "a known material", "rough",
       "start from a known material's constants"},
      {"environment.substrate.density", K::number, "kg/m^3", "the material's", "> 0", "rough", "density"},
      {"environment.substrate.hamaker", K::number, "J", "the material's (required if none)", ">= 0", "rough",
       "Hamaker constant"},
      {"environment.substrate.youngs_modulus", K::number, "Pa", "the material's", ">= 0", "rough",
       "Young's modulus; 0 = rigid"},
      {"environment.substrate.poisson_ratio", K::number, "1", "the material's", "[-1, 0.5]", "rough",
       "Poisson's ratio"},
      {"environment.substrate.surface_energy", K::number, "J/m^2", "from the Hamaker constant", ">= 0", "rough",
       "surface energy gamma"},
      {"environment.liquid.name", K::string, "", "custom", "a known liquid", "rough",
       "start from a known liquid's constants"},
      {"environment.liquid.density", K::number, "kg/m^3", "required if no name", ">= 0", "rough", "density"},
      {"environment.liquid.hamaker", K::number, "J", "required if no name", ">= 0", "rough", "Hamaker constant"},
      {"environment.liquid.surface_tension", K::number, "N/m", "required if no name", "> 0", "rough",
       "surface tension"},
      {"environment.liquid.molar_volume", K::number, "m^3/mol", "required if no name", "> 0", "rough",
       "molar volume"},
      {"environment.liquid.contact_angle", K::number, "rad", "the liquid's", "[0, pi/2]", "rough", "contact angle"},

      {"body.name", K::string, "", "body", "any text", "rough", "label in the load report"},
      {"body.shape", K::string, "", "required", "bar (rod, tube, sphere: `nanopush forces` only)", "rough",
       "shape of the body"},
      {"body.length", K::number, "m", "required", "> 0; = object.length", "rough", "length"},
      {"body.width", K::number, "m", "required (bar)", "> 0; = object.width", "rough", "width"},
      {"body.height", K::number, "m", "required (bar)", "> 0", "rough", "height"},
      {"body.radius", K::number, "m", "required (rod, tube, sphere)", "> 0", "rough", "outer radius"},
      {"body.inner_radius", K::number, "m", "0", "[0, radius)", "rough", "inner radius (tube)"},
      {"body.material", K::string, "", "custom", "a known material", "rough", "the body's material"},
      {"body.density", K::number, "kg/m^3", "the material's (required if none)", "> 0", "rough", "density"},
      {"body.hamaker", K::number, "J", "the material's (required if none)", ">= 0", "rough", "Hamaker constant"},
      {"body.youngs_modulus", K::number, "Pa", "the material's", ">= 0", "rough", "Young's modulus; 0 = rigid"},
      {"body.poisson_ratio", K::number, "1", "the material's", "[-1, 0.5]", "rough", "Poisson's ratio"},
      {"body.surface_energy", K::number, "J/m^2", "from the Hamaker constant", ">= 0", "rough",
       "surface energy gamma"},

      {"sweep", K::table, "", "none", "keys vary, vary_log, set (arrays of \"KEY=...\"), points, task", "all",
       "axes of `nanopush sweep` over this scene (docs/sweeps.md); the other commands ignore it"},
  };
  return keys;
}

const SceneKey* find_scene_key(std::string_view key) {
  for (const auto& k : scene_keys())
    if (k.key == key) return &k;
  return nullptr;
}

std::vector<std::string> scene_table_keys(std::string_view table) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  const std::string prefix = table.empty() ? "" : std::string(table) + ".";
  for (const auto& k : scene_keys()) {
    const std::string_view key = k.key;
    if (key.substr(0, prefix.size()) != prefix) continue;
    const std::string_view rest = key.substr(prefix.size());
    const std::string first(rest.substr(0, rest.find('.')));
    if (seen.insert(first).second) out.push_back(first);
  }
  return out;
}

std::string scene_keys_markdown() {
  std::ostringstream o;
  o << "| key | type | unit | default | allowed | surface | meaning |\n"
    << "|---|---|---|---|---|---|---|\n";
  for (const auto& k : scene_keys())
    o << "| `" << k.key << "` | " << key_type_name(k.type) << " | " << (k.unit.empty() ? "" : k.unit) << " | "
      << k.default_text << " | " << k.range << " | " << k.kinds << " | " << k.description << " |\n";
  return o.str();
}

namespace {

/// Optimal string alignment distance: insertions, deletions, substitutions and transpositions
/// of neighbours, each 1.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

}  // namespace

std::string nearest_scene_key(std::string_view key) {
  if (key.empty() || key.size() > 200) return {};
  const bool bare = key.find('.') == std::string_view::npos;
  const std::size_t limit = std::max<std::size_t>(1, std::min<std::size_t>(3, key.size() / 4));
  std::string best;
  std::size_t best_d = limit + 1;
  for (const auto& k : scene_keys()) {
    std::size_t d = edit_distance(key, k.key);
    if (bare) d = std::min(d, edit_distance(key, k.key.substr(k.key.rfind('.') + 1)));
    if (d < best_d) {
      best_d = d;
      best = std::string(k.key);
    }
  }
  return best;
}

}  // namespace nanopush
