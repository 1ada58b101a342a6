#include "nanopush/scenes/scene.hpp"

#include "nanopush_toml.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cctype>
#include <cmath>
#include <limits>
#include <fstream>
#include <set>
#include <sstream>

#include "nanopush/models/afm_probe.hpp"
#include "nanopush/models/tip_dynamic.hpp"
#include "nanopush/scenes/environment_toml.hpp"
#include "nanopush/numerics/error.hpp"

namespace nanopush {
namespace {

/// A TOML value as the user wrote it, for error messages.
std::string node_text(const toml::node& n) {
  std::ostringstream s;
  if (auto v = n.as_string()) return "\"" + v->get() + "\"";
  if (auto v = n.as_floating_point()) return fmt(v->get());
  if (auto v = n.as_integer()) return std::to_string(v->get());
  if (auto v = n.as_boolean()) return v->get() ? "true" : "false";
  if (n.is_array()) return "(an array)";
  if (n.is_table()) return "(a table)";
  return "(a date/time)";
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

/// Reject keys the schema does not know (catches typos such as "lenght").
void check_keys(const toml::table& t, const std::string& where, const std::vector<std::string>& allowed) {
  for (auto&& [k, v] : t) {
    const std::string key(k.str());
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      const std::string full = where.empty() ? key : where + "." + key;
      const std::string near = nearest_scene_key(full);
      throw InputError(full, "(present)",
                       "unknown key; " + (near.empty() ? "" : "did you mean " + near + "? ") +
                           "allowed here: " + join(allowed));
    }
  }
}

const toml::table& require_table(const toml::table& root, const std::string& name) {
  const toml::node* n = root.get(name);
  if (!n) throw InputError(name, "(missing)", "the scene needs a [" + name + "] table");
  if (!n->is_table()) throw InputError(name, "(not a table)", "must be a [" + name + "] table");
  return *n->as_table();
}

std::optional<double> opt_number(const toml::table& t, const std::string& where, const std::string& key) {
  const toml::node* n = t.get(key);
  if (!n) return std::nullopt;
  // An integer is a number whatever its size (value<double> refuses an int64 that a double
  // does not hold exactly, 9223372036854775807); the range checks then name it as written.
  if (n->is_integer()) return static_cast<double>(n->value<std::int64_t>().value_or(0));
  if (auto v = n->value<double>(); v && n->is_floating_point()) return *v;
    throw InputError(where + "." + key, node_text(*n), "must be a number");
}

double number(const toml::table& t, const std::string& where, const std::string& key) {
  auto v = opt_number(t, where, key);
  if (!v) throw InputError(where + "." + key, "(missing)", "required number");
  return *v;
}

std::optional<std::string> opt_string(const toml::table& t, const std::string& where, const std::string& key) {
  const toml::node* n = t.get(key);
  if (!n) return std::nullopt;
  if (auto v = n->value<std::string>(); v && n->is_string()) return *v;
    throw InputError(where + "." + key, node_text(*n), "must be a string");
}

std::optional<bool> opt_bool(const toml::table& t, const std::string& where, const std::string& key) {
  const toml::node* n = t.get(key);
  if (!n) return std::nullopt;
  if (!n->is_boolean()) throw InputError(where + "." + key, node_text(*n), "must be true or false");
  return n->value<bool>();
}

void require_one_of(const std::string& field, const std::string& v, const std::vector<std::string>& allowed) {
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
    throw InputError(field, "\"" + v + "\"", "must be one of: " + join(allowed));
}

/// A choice key of the scene file: its value by the choice's name table, or InputError
/// "field = \"text\": must be one of: a, b, c".
template <class E>
E scene_choice(const std::string& field, const std::string& text) {
  if (const auto v = choice_from_name<E>(text)) return *v;
  throw InputError(field, "\"" + text + "\"", "must be one of: " + choice_names<E>(", "));
}

/// A scene name becomes part of output file names: letters, digits, '_', '-' and '.', not
/// starting with '.' or '-' (no paths, no hidden files, nothing that reads as an option).
bool is_identifier(const std::string& s) {
  if (s.empty() || s.size() > 200 || s[0] == '.' || s[0] == '-') return false;
  for (unsigned char c : s)
    if (!std::isalnum(c) && c != '_' && c != '-' && c != '.') return false;
  return true;
}

/// The file stem as a name: every other character becomes '_'.
std::string identifier_from(const std::string& stem) {
  std::string r = stem.substr(0, 200);
  for (char& c : r)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '_';
  if (r.empty() || r[0] == '.' || r[0] == '-') r = "scene_" + r;
  return r;
}

/// Magnitudes the integrators represent: within [kTiny, kHuge] (or 0 where allowed), so that
/// the squares and products the error norms and right-hand sides form stay normal doubles.
constexpr double kHuge = 1e150, kTiny = 1e-150;

/// `v` (from `fields`, computed as `what`) must be 0 or within [kTiny, kHuge] in magnitude.
void require_representable(const std::string& fields, double v, const std::string& unit, const std::string& what = {}) {
  const double a = std::fabs(v);
  if (std::isfinite(v) && (a == 0.0 || (a >= kTiny && a <= kHuge))) return;
  throw InputError(fields, fmt(v),
                   (what.empty() ? std::string() : "gives " + what + " = " + fmt(v) + " " + unit + ", ") +
                       "outside the magnitudes the integrators represent: 0 or 1e-150 to 1e150" +
                       (unit.empty() ? "" : " (" + unit + ")"));
}

/// Every number of a scene and the quantities its dynamics derive from them (docs/errors.md,
/// "Magnitudes"): the inputs first, so that the message names the field the user wrote.
void check_representable(const Scene& sc) {
  require_representable("object.length", sc.length, "m");
  require_representable("object.width", sc.width, "m");
  if (sc.height > 0) require_representable("object.height", sc.height, "m");
  if (sc.density > 0) require_representable("object.density", sc.density, "kg/m^3");
  require_representable(sc.density > 0 ? "object.density" : "object.mass", sc.mass, "kg",
                        sc.density > 0 ? "the mass density x length x width x height" : "");
  require_representable("object.inertia", sc.inertia, "kg m^2", "the moment of inertia");
  require_representable("push.force", sc.push.force, "N");
  require_representable("push.direction", sc.push.beta, "rad");
  const char* const initial_keys[] = {"x", "y", "theta", "vx", "vy", "omega"};
  const char* const initial_units[] = {"m", "m", "rad", "m/s", "m/s", "rad/s"};
  for (std::size_t i = 0; i < sc.initial.size() && i < 6; ++i)
    require_representable(std::string("initial.") + initial_keys[i], sc.initial[i], initial_units[i]);
  require_representable("push.force, object.mass", sc.push.force / sc.mass, "m/s^2", "the acceleration F/m");
  require_representable("push.force, push point, object.inertia",
                        sc.push.force * std::max(sc.push.lever(), 1e-3 * std::max(sc.length, sc.width)) / sc.inertia,
                        "rad/s^2", "the angular acceleration F lever / I");
  if (sc.rough()) {
    require_representable("surface.f_vdw", sc.surface.f_vdw, "N");
    require_representable("surface.g", sc.surface.g, "m/s^2");
    require_representable("surface.normal_load", sc.normal_load(), "N", "the normal load N");
    require_representable("surface.mu, normal load, object.mass", sc.friction_limit() / sc.mass, "m/s^2",
                          "the friction deceleration mu N / m");
  }
  require_representable("solver.t_end", sc.solver.t_end, "s");
  require_representable("solver.t_end, solver.samples", sc.solver.t_end / (sc.solver.samples - 1), "s",
                        "the output spacing");
  // The spacing of the output times must be a step the integrator can take from t_end.
  if (sc.solver.t_end / (sc.solver.samples - 1) < 64 * std::numeric_limits<double>::epsilon() * sc.solver.t_end)
    throw InputError("solver.samples", std::to_string(sc.solver.samples),
                     "output times closer than 64 ulps of t_end apart: fewer samples");
  require_representable("solver.h0", sc.solver.h0, "s");
  require_representable("solver.hmax", sc.solver.hmax, "s");
  require_representable("solver.atol", sc.solver.atol, "SI");
  // The state scales (Scene::state_scales), each named by the inputs it comes from.
  const char* const len_key = sc.length >= sc.width ? "object.length" : "object.width";
  const double len = std::max(sc.length, sc.width);
  if (sc.push_mode == PushMode::tip) {
    require_representable("tip.speed", sc.tip.speed, "m/s");
    require_representable(std::string("tip.speed, ") + len_key, sc.tip.speed / len, "rad/s",
                          "the rotation rate scale tip.speed / length");
    require_representable(std::string("surface.mu, normal load, ") + len_key, sc.friction_limit() * len, "J",
                          "the work scale mu N length");
  } else {
    const double torque = sc.push.force * std::max(sc.push.lever(), 1e-3 * len);
    const double w = std::sqrt(torque / sc.inertia);
    require_representable("push.force, push point, object.inertia", w, "rad/s",
                          "the rotation rate scale sqrt(F lever / I)");
    require_representable(std::string("push.force, push point, object.inertia, ") + len_key, len * w, "m/s",
                          "the speed scale length sqrt(F lever / I)");
    require_representable(std::string("push.force, ") + len_key, sc.push.force * len, "J", "the work scale F length");
  }
  for (double x : sc.state_scales()) require_representable("the scene's scales", x, "SI", "a state scale");  // (named above)
}

}  // namespace

std::string extended_precision_obstacle(bool rough, Law law, Engine engine, Method method) {
  const std::string need =
      "long and quad need engine = cxx, method faithful or modern, on a smooth scene (smooth surface), or method "
      "modern on a rough scene under the thesis or coulomb law";
  if (engine != Engine::cxx) return need + " (the F77 engine is REAL*8)";
  if (method == Method::dop853)
    return need + " (dop853 is double only: its coefficients are tabulated to long double, so its order conditions "
                  "hold to ~1e-19)";
  // auto picks modern in extended precision (resolve_settings).
  if (method == Method::cvode) return need + " (CVODE is double)";
  if (rough && law == Law::printed) return need + " (the printed law's forms are evaluated in double)";
  if (rough && method == Method::faithful)
    return need + " (faithful evaluates the F77 routine's friction forms, in double)";
  return "";
}

std::vector<double> Scene::output_times() const {
  if (!times.empty()) return times;
  std::vector<double> t(static_cast<std::size_t>(solver.samples));
  const int n = solver.samples;
  for (int i = 0; i < n; ++i) t[static_cast<std::size_t>(i)] = solver.t_end * i / (n - 1);
  t.back() = solver.t_end;
  return t;
}

TipModel Scene::tip_model_run() const {
  if (tip_model != TipModel::automatic) return tip_model;
  return tip::inertia_ratio(mass, tip.speed, friction_limit(), tip.travel) <= tip::kAutoInertiaRatio
             ? TipModel::quasi_static
             : TipModel::dynamic;
}

std::array<double, 8> Scene::state_scales() const {
  const double len = std::max(length, width);
  if (push_mode == PushMode::tip) {  // the tip sets the pace: its speed, and mu N its work
    const double v = tip.speed, work = friction_limit() * len;
    return {len, len, 1.0, v, v, v / len, work, work};
  }
  // Rotational time scale: the small-oscillation period of the push torque.
  const double torque = push.force * std::max(push.lever(), 1e-3 * len);
  const double w = std::sqrt(torque / inertia);
  return {len, len, 1.0, len * w, len * w, w, push.force * len, push.force * len};
}

std::vector<double> Scene::atol_vector(double rtol, double atol, int n) const {
  std::vector<double> v(static_cast<std::size_t>(n));
  const auto sc = state_scales();
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = atol > 0 ? atol : rtol * sc[i];
  return v;
}

namespace {
Scene scene_from_owned_document(std::shared_ptr<const toml::table> doc, const std::string& source_name);
}  // namespace

Scene parse_scene(std::string_view text, const std::string& source_name) {
  return scene_from_owned_document(std::make_shared<toml::table>(parse_toml_document(text, source_name)),
                                   source_name);
}

namespace {

/// [scene]: the name and the description.
void read_scene(const toml::table& root, Scene& sc) {
  if (root.get("scene")) {
    const auto& t = require_table(root, "scene");
    check_keys(t, "scene", scene_table_keys("scene"));
    sc.name = opt_string(t, "scene", "name").value_or("");
    sc.description = opt_string(t, "scene", "description").value_or("");
    if (t.get("name") && !is_identifier(sc.name))
      throw InputError("scene.name", "\"" + sc.name + "\"",
                       "must be an identifier: letters, digits, _ - . (at most 200, not starting with . or -); it "
                       "names the output files, which go only to --out or the working directory");
  }
}

/// [object]: the bar, its mass (given, or density x volume) and moment of inertia.
void read_object(const toml::table& root, Scene& sc) {
  const auto& t = require_table(root, "object");
  check_keys(t, "object", scene_table_keys("object"));
  sc.shape = opt_string(t, "object", "shape").value_or("bar");
  require_one_of("object.shape", sc.shape, {"bar"});
  sc.length = number(t, "object", "length");
  sc.width = number(t, "object", "width");
  require_positive("object.length", sc.length, "m");
  require_positive("object.width", sc.width, "m");
  require_representable("object.length", sc.length, "m");  // before the push point is checked against them
  require_representable("object.width", sc.width, "m");
  sc.geometry = {sc.width / 2, sc.length / 2};
  const auto mass = opt_number(t, "object", "mass");
  const auto density = opt_number(t, "object", "density");
  const auto height = opt_number(t, "object", "height");
  if (height) {
    require_positive("object.height", *height, "m");
    sc.height = *height;
  }
  if (mass) {
    require_positive("object.mass", *mass, "kg");
    if (density) throw InputError("object.density", fmt(*density), "give either object.mass or object.density, not both");
    sc.mass = *mass;
  } else {
    if (!density) throw InputError("object.mass", "(missing)", "give object.mass [kg], or object.density [kg/m^3] with object.height");
    require_positive("object.density", *density, "kg/m^3");
    if (!height) throw InputError("object.height", "(missing)", "needed with object.density to compute the mass (m)");
    sc.density = *density;
    sc.mass = sc.density * sc.length * sc.width * sc.height;
  }
  if (auto in = opt_number(t, "object", "inertia")) {
    require_positive("object.inertia", *in, "kg m^2");
    sc.inertia = *in;
  } else {
    sc.inertia = sc.mass * (sc.length * sc.length + sc.width * sc.width) / 12.0;
  }
}

/// [push]: force, direction and the push point (body axes, or the thesis xn/yn), on the body.
void read_push(const toml::table& root, Scene& sc) {
  const auto& t = require_table(root, "push");
  check_keys(t, "push", scene_table_keys("push"));
  sc.push_mode = scene_choice<PushMode>("push.mode", opt_string(t, "push", "mode").value_or("force"));
  if (sc.push_mode == PushMode::tip) {
    for (const char* k : {"force", "direction", "xn", "yn", "point"})
      if (t.get(k))
        throw InputError(std::string("push.") + k, "(present)",
                         "with push.mode = \"tip\" the tip's keys (tip.*) make the push: remove this key");
    return;
  }
  if (root.get("tip")) throw InputError("tip", "(present)", "the tip's keys need push.mode = \"tip\"");
  const double F = number(t, "push", "force");
  require_positive("push.force", F, "N");
  const double beta = opt_number(t, "push", "direction").value_or(0.0);
  require_finite("push.direction", beta, "rad");
  const auto xn = opt_number(t, "push", "xn");
  const auto yn = opt_number(t, "push", "yn");
  if (xn) require_finite("push.xn", *xn, "m");
  if (yn) require_finite("push.yn", *yn, "m");
  const toml::node* pt = t.get("point");
  if (pt && (xn || yn)) throw InputError("push.point", "(present)", "give either push.point = [x', y'] or the thesis push.xn/push.yn, not both");
  if (pt) {
    const toml::array* arr = pt->as_array();
    if (!arr || arr->size() != 2 || !arr->get(0)->value<double>() || !arr->get(1)->value<double>()) {
              throw InputError("push.point", node_text(*pt), "must be [x', y'], two numbers in body axes (m)");
    }
    sc.push = {F, beta, *arr->get(0)->value<double>(), *arr->get(1)->value<double>()};
  } else {
    if (!xn || !yn) throw InputError(xn ? "push.yn" : "push.xn", "(missing)", "give both push.xn and push.yn (thesis coordinates, m), or push.point");
    sc.push = Push::from_thesis(F, beta, *xn, *yn);
  }
  require_finite("push.point[0]", sc.push.pbx, "m");
  require_finite("push.point[1]", sc.push.pby, "m");
  const double tol = 1e-9 * std::max(sc.geometry.a, sc.geometry.b);
  if (std::fabs(sc.push.pbx) > sc.geometry.a + tol)
    throw InputError(pt ? "push.point[0]" : "push.xn", fmt(pt ? sc.push.pbx : *xn),
                     "the push point must lie on the body: |x'| <= width/2 = " + fmt(sc.geometry.a) + " m");
  if (std::fabs(sc.push.pby) > sc.geometry.b + tol)
    throw InputError(pt ? "push.point[1]" : "push.yn", fmt(pt ? sc.push.pby : *yn),
                     "the push point must lie on the body: |y'| <= length/2 = " + fmt(sc.geometry.b) + " m");
}

/// [tip]: the AFM tip and its straight path (push.mode = tip).
void read_tip(const toml::table& root, Scene& sc) {
  if (sc.push_mode != PushMode::tip) return;
  const auto& t = require_table(root, "tip");
  check_keys(t, "tip", scene_table_keys("tip"));
  tip::TipPath& p = sc.tip;
  p.start_x = number(t, "tip", "start_x");
  p.start_y = number(t, "tip", "start_y");
  p.travel = number(t, "tip", "travel");
  p.direction = opt_number(t, "tip", "direction").value_or(0.0);
  p.speed = opt_number(t, "tip", "speed").value_or(1e-6);
  p.radius = opt_number(t, "tip", "radius").value_or(1e-8);
  p.mu = opt_number(t, "tip", "mu").value_or(0.0);
  p.validate();
  sc.tip_model = scene_choice<TipModel>("tip.model", opt_string(t, "tip", "model").value_or("quasi_static"));
  sc.tip_stiffness = 0;
  if (auto k = opt_number(t, "tip", "stiffness")) {
    require_positive("tip.stiffness", *k, "N/m");
    sc.tip_stiffness = *k;
  }
  if (const toml::node* cn = t.get("cantilever")) {
    if (!cn->is_table()) throw InputError("tip.cantilever", "(not a table)", "must be a [tip.cantilever] table");
    if (sc.tip_stiffness > 0)
      throw InputError("tip.stiffness", fmt(sc.tip_stiffness),
                       "give either tip.stiffness or the tip.cantilever keys, not both");
    const toml::table& c = *cn->as_table();
    check_keys(c, "tip.cantilever", scene_table_keys("tip.cantilever"));
    afm::Cantilever beam;
    const char* const dims[] = {"youngs_modulus", "length", "width", "thickness", "tip_height"};
    double* const vals[] = {&beam.E, &beam.length, &beam.width, &beam.thickness, &beam.tip_height};
    for (int i = 0; i < 5; ++i) {
      *vals[i] = number(c, "tip.cantilever", dims[i]);
      require_positive(std::string("tip.cantilever.") + dims[i], *vals[i], i == 0 ? "Pa" : "m");
    }
    beam.nu = opt_number(c, "tip.cantilever", "poisson_ratio").value_or(beam.nu);
    if (!(beam.nu > -1.0 && beam.nu <= 0.5))
      throw InputError("tip.cantilever.poisson_ratio", fmt(beam.nu), "must be in (-1, 0.5]");
    // The tip's lateral stiffness across the beam: the beam's twist by the lateral force at
    // the tip's height (eq 2.6) and its lateral bending (eq 2.7), in series.
    const afm::SpringConstants k = afm::spring_constants(beam);
    sc.tip_stiffness = 1.0 / (1.0 / k.ktheta + 1.0 / k.kby);
  }
}

/// What a tip push needs of the rest of the scene: friction (a rough surface) and the C++
/// engine's quasi-static model in double (docs/tip.md).
void check_tip_scene(Scene& sc) {
  if (sc.push_mode != PushMode::tip) return;
  if (!sc.rough())
    throw InputError("surface.kind", "\"" + sc.model + "\"",
                     "a tip push moves the object against friction: use \"rough\" (a smooth surface has no quasi-static "
                     "answer)");
  if (sc.surface.law == Law::printed)
    throw InputError("surface.law", "\"printed\"", "the tip push uses the Coulomb wrench: use thesis or coulomb");
  if (!(sc.friction_limit() > 0))
    throw InputError("surface.mu", fmt(sc.surface.mu), "must be > 0 for a tip push (the quasi-static model needs friction)");
  if (sc.solver.engine != Engine::cxx)
    throw InputError("solver.engine", "\"" + to_string(sc.solver.engine) + "\"", "the tip push runs in the C++ engine only");
  if (sc.solver.method != Method::automatic)
    throw InputError("solver.method", "\"" + to_string(sc.solver.method) + "\"",
                     "the quasi-static tip push has its own integrator: leave solver.method out");
  if (sc.solver.precision != Precision::double_)
    throw InputError("solver.precision", "\"" + to_string(sc.solver.precision) + "\"", "the tip push runs in double");
  const char* const rate_keys[] = {"vx", "vy", "omega"};
  for (int i = 0; i < 3; ++i)
    if (sc.initial[3 + i] != 0.0)
      throw InputError(std::string("initial.") + rate_keys[i], fmt(sc.initial[3 + i]),
                       "a tip push starts with the object at rest (the quasi-static model has no inertia): must be 0");
  if (sc.tip_model_run() == TipModel::dynamic) {
    const std::string why =
        sc.tip_model == TipModel::automatic
            ? " (tip.model = \"auto\" chose the dynamic model: m v^2/(mu N travel) = " +
                  fmt(tip::inertia_ratio(sc.mass, sc.tip.speed, sc.friction_limit(), sc.tip.travel)) + " > " +
                  fmt(tip::kAutoInertiaRatio) + ")"
            : "";
    if (!(sc.tip_stiffness > 0))
      throw InputError("tip.stiffness", "(missing)",
                       "the dynamic tip model needs the tip's spring: give tip.stiffness (N/m, > 0) or the "
                       "tip.cantilever keys" + why);
  }
  if (sc.solver.t_end == 0) {
    // The run's length from the tip's keys: they are named, not the solver.t_end nobody wrote.
    require_representable("tip.speed", sc.tip.speed, "m/s");
    require_representable("tip.travel", sc.tip.travel, "m");
    const bool dynamic = sc.tip_model_run() == TipModel::dynamic;
    sc.solver.t_end = dynamic ? tip::dynamic_t_end({sc.mass, sc.inertia, sc.tip_stiffness}, sc.friction_limit(), sc.tip)
                              : sc.tip.t_stop();
    require_representable(dynamic ? "tip.travel, tip.speed, tip.stiffness" : "tip.travel, tip.speed", sc.solver.t_end,
                          "s", "the run's duration (solver.t_end, not given: from tip.travel / tip.speed)");
  }
}

/// [initial]: the state at t = 0.
void read_initial(const toml::table& root, Scene& sc) {
  if (root.get("initial")) {
    const auto& t = require_table(root, "initial");
    const std::vector<std::string> keys = {"x", "y", "theta", "vx", "vy", "omega"};
    const std::vector<std::string> units = {"m", "m", "rad", "m/s", "m/s", "rad/s"};
    check_keys(t, "initial", scene_table_keys("initial"));
    for (std::size_t i = 0; i < keys.size(); ++i) {
      sc.initial[i] = opt_number(t, "initial", keys[i]).value_or(0.0);
      require_finite("initial." + keys[i], sc.initial[i], units[i]);
    }
  }
}

/// [surface.printed]: the printed law's reading, then each switch given over it.
PrintedReading read_printed_reading(const toml::table& t) {
  check_keys(t, "surface.printed", scene_table_keys("surface.printed"));
  PrintedReading r;
  if (auto name = opt_string(t, "surface.printed", "reading")) {
    const auto named = printed_reading_named(*name);
    if (!named) {
      std::string names;
      for (const auto& [n, i] : kPrintedReadingNames) names += (names.empty() ? "" : ", ") + std::string(n);
      throw InputError("surface.printed.reading", "\"" + *name + "\"", "must be one of: " + names);
    }
    r = *named;
  }
  r.fy_sign = opt_bool(t, "surface.printed", "fy_sign").value_or(r.fy_sign);
  r.omega_sign = opt_bool(t, "surface.printed", "omega_sign").value_or(r.omega_sign);
  r.eq3_50 = opt_bool(t, "surface.printed", "eq3_50").value_or(r.eq3_50);
  if (auto c4 = opt_string(t, "surface.printed", "c4"))
    r.c4_squares = scene_choice<PrintedC4>("surface.printed.c4", *c4) == PrintedC4::squares_nm;
  return r;
}

/// [surface]: smooth, or rough with its friction coefficient, load terms and law.
void read_surface(const toml::table& root, Scene& sc) {
  if (root.get("surface")) {
    const auto& t = require_table(root, "surface");
    check_keys(t, "surface", scene_table_keys("surface"));
    sc.model = opt_string(t, "surface", "kind").value_or("smooth");
    sc.surface.kind = scene_choice<SurfaceKind>("surface.kind", sc.model);
    if (sc.surface.kind == SurfaceKind::smooth) {
      for (const char* k : {"mu", "f_vdw", "g", "normal_load", "law", "printed"})
        if (t.get(k)) throw InputError(std::string("surface.") + k, "(present)", "only meaningful with surface.kind = \"rough\"");
    } else {
      sc.surface.mu = number(t, "surface", "mu");
      require_range("surface.mu", sc.surface.mu, 0.0, 10.0);
      sc.surface.f_vdw = opt_number(t, "surface", "f_vdw").value_or(0.0);
      require_nonnegative("surface.f_vdw", sc.surface.f_vdw, "N");
      sc.surface.g = opt_number(t, "surface", "g").value_or(9.81);
      require_nonnegative("surface.g", sc.surface.g, "m/s^2");
      if (auto nl = opt_number(t, "surface", "normal_load")) {
        require_positive("surface.normal_load", *nl, "N");
        sc.surface.normal_load = *nl;
      }
      sc.surface.law = scene_choice<Law>("surface.law", opt_string(t, "surface", "law").value_or("thesis"));
      if (const toml::node* p = t.get("printed")) {
        if (!p->is_table()) throw InputError("surface.printed", node_text(*p), "must be a table of the printed law's switches");
        sc.surface.printed = read_printed_reading(*p->as_table());
      }
    }
  }
}

/// [solver]: output times, tolerances, step settings, engine, method and precision.
void read_solver(const toml::table& root, Scene& sc) {
  const auto& t = require_table(root, "solver");
  check_keys(t, "solver", scene_table_keys("solver"));
  if (auto ms = opt_number(t, "solver", "max_steps")) {
    if (!(*ms >= 1 && *ms <= 1e9) || std::floor(*ms) != *ms)
      throw InputError("solver.max_steps", node_text(*t.get("max_steps")), "must be an integer in [1, 1000000000]");
    sc.solver.max_steps = static_cast<long>(*ms);
  }
  if (sc.push_mode == PushMode::tip && !t.get("t_end")) {
    sc.solver.t_end = 0;  // the tip's travel time (check_tip_scene)
  } else {
    sc.solver.t_end = number(t, "solver", "t_end");
    require_positive("solver.t_end", sc.solver.t_end, "s");
  }
  if (auto s = opt_number(t, "solver", "samples")) {
    if (!(*s >= 2 && *s <= 1e7) || std::floor(*s) != *s)
      throw InputError("solver.samples", node_text(*t.get("samples")), "must be an integer in [2, 10000000]");
    sc.solver.samples = static_cast<int>(*s);
  }
  if (auto r = opt_number(t, "solver", "rtol")) {
    require_range("solver.rtol", *r, 1e-30, 0.1);
    sc.solver.rtol = *r;
  }
  if (auto a = opt_number(t, "solver", "atol")) {
    require_nonnegative("solver.atol", *a);
    sc.solver.atol = *a;
  }
  if (auto e = opt_number(t, "solver", "accuracy")) {
    if (*e != 0.0) require_range("solver.accuracy", *e, kAccuracyMin, kAccuracyMax);
    sc.solver.accuracy = *e;
  }
  sc.solver.error_estimate = opt_bool(t, "solver", "error_estimate").value_or(true);
  sc.solver.engine = scene_choice<Engine>("solver.engine", opt_string(t, "solver", "engine").value_or("cxx"));
  // Default: auto (the fastest method for the rtol asked, docs/dop853.md); a scene on the F77
  // engine has its one method.
  const auto method = opt_string(t, "solver", "method");
  sc.solver.method = method ? scene_choice<Method>("solver.method", *method)
                            : (sc.solver.engine == Engine::f77 ? Method::faithful : Method::automatic);
  if (sc.solver.engine == Engine::f77 && sc.solver.method != Method::faithful)
    throw InputError("solver.method", "\"" + to_string(sc.solver.method) + "\"",
                     "with solver.engine = \"f77\" there is one method (the F77 Bulirsch-Stoer): leave "
                     "solver.method out, or use solver.engine = \"cxx\"");
  sc.solver.precision =
      scene_choice<Precision>("solver.precision", opt_string(t, "solver", "precision").value_or("double"));
  if (sc.solver.precision != Precision::double_) {
    const std::string why = extended_precision_obstacle(sc.rough(), sc.surface.law, sc.solver.engine, sc.solver.method);
    if (!why.empty()) throw InputError("solver.precision", "\"" + to_string(sc.solver.precision) + "\"", why);
  }
  if (auto h = opt_number(t, "solver", "h0")) {
    require_nonnegative("solver.h0", *h, "s");
    sc.solver.h0 = *h;
  }
  if (auto h = opt_number(t, "solver", "hmax")) {
    require_nonnegative("solver.hmax", *h, "s");
    sc.solver.hmax = *h;
  }
}

/// The normal load of a rough surface: from [environment] and [body] when the scene has
/// them (the force models), else m g + F_vdw or the given load; with its report.
void assemble_load(const toml::table& root, Scene& sc) {
  if (root.get("environment") || root.get("body")) {
    if (!root.get("environment")) throw InputError("environment", "(missing)", "a [body] table needs an [environment] table");
    if (!root.get("body"))
      throw InputError("body", "(missing)", "an [environment] table needs a [body] table naming the material");
    if (!sc.rough())
      throw InputError("surface.kind", "\"" + sc.model + "\"", "[environment] sets the normal load of friction: use \"rough\"");
    const auto& st = require_table(root, "surface");
    for (const char* k : {"f_vdw", "normal_load", "g"})
      if (st.get(k))
        throw InputError(std::string("surface.") + k, "(present)",
                         "the normal load comes from [environment] and [body]; remove this key");
    const Environment env = parse_environment(require_table(root, "environment"));
    const Body body = parse_body(require_table(root, "body"));
    if (body.shape != Shape::bar) throw InputError("body.shape", std::string(shape_name(body.shape)), "the sliding model is a bar: must be \"bar\"");
    auto same = [&](const char* key, double a, double b) {
      if (std::fabs(a - b) > 1e-12 * std::max(std::fabs(a), std::fabs(b)))
        throw InputError(std::string("body.") + key, fmt(a), "must equal object." + std::string(key) + " = " + fmt(b));
    };
    same("length", body.length, sc.length);
    same("width", body.width, sc.width);
    LoadOptions lo;
    lo.rtol = sc.solver.rtol;
    const LoadReport rep = assemble_normal_load(env, body, lo);
    sc.surface.g = env.gravity;
    // Sliding friction carries the load without the contact-adhesion term (eq 3.20 form).
    sc.surface.normal_load = rep.sliding_load;
    sc.load_report = rep.to_text() + "friction uses N = " + fmt(rep.sliding_load) + " N (the load without contact adhesion)\n";
  } else if (sc.rough()) {
    const double g = sc.mass * sc.surface.g, N = sc.normal_load();
    std::ostringstream r;
    r.precision(6);
    if (sc.surface.normal_load > 0) {
      r << "normal load N = " << N << " N (given as surface.normal_load)\n";
    } else {
      r << "normal load N = m g + F_vdw = " << N << " N\n"
        << "  gravity  m g   = " << g << " N (" << (N > 0 ? g / N : 0) << " of N)\n"
        << "  adhesion F_vdw = " << sc.surface.f_vdw << " N (" << (N > 0 ? sc.surface.f_vdw / N : 0)
        << " of N, given)\n";
    }
    r << "friction limit mu N = " << sc.friction_limit() << " N\n";
    sc.load_report = r.str();
  }
}

}  // namespace

namespace {
/// The scene of `doc`, which it keeps as its document (no copy).
Scene scene_from_owned_document(std::shared_ptr<const toml::table> doc, const std::string& source_name) {
  const toml::table& root = *doc;
  check_keys(root, "", scene_table_keys(""));
  Scene sc;
  sc.source = source_name;
  read_scene(root, sc);
  if (sc.name.empty()) sc.name = identifier_from(std::filesystem::path(source_name).stem().string());
  read_object(root, sc);
  read_push(root, sc);
  read_tip(root, sc);
  read_initial(root, sc);
  read_surface(root, sc);
  read_solver(root, sc);
  assemble_load(root, sc);
  check_tip_scene(sc);
  check_representable(sc);
  sc.document = std::move(doc);
  return sc;
}
}  // namespace

Scene scene_from_document(const toml::table& root, const std::string& source_name) {
  return scene_from_owned_document(std::make_shared<const toml::table>(root), source_name);
}

Scene load_scene(const std::filesystem::path& path) {
  Scene sc = parse_scene(read_scene_text(path), path.string());
  sc.source = path;
  return sc;
}

}  // namespace nanopush
