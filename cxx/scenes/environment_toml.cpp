// The [environment] and body tables of a scene file: parsed and validated, each error
// naming the TOML field (e.g. "environment.humidity = 1.5: must be in [0, 1]").
#include "nanopush/scenes/environment_toml.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "nanopush_toml.hpp"

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene_keys.hpp"

namespace nanopush {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Shortest round-trip text of a double (the value as the user typed it, e.g. 1e-20).
std::string sfmt(double v) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}
void need_positive(const std::string& field, double v, const std::string& unit) {
  if (!(v > 0.0) || !std::isfinite(v)) throw InputError(field, sfmt(v), "must be > 0 (" + unit + ")");
}
void need_nonnegative(const std::string& field, double v, const std::string& unit) {
  if (!(v >= 0.0) || !std::isfinite(v)) throw InputError(field, sfmt(v), "must be >= 0 (" + unit + ")");
}
void need_range(const std::string& field, double v, double lo, double hi, const std::string& unit = "") {
  if (!(v >= lo && v <= hi))
    throw InputError(field, sfmt(v), "must be in [" + sfmt(lo) + ", " + sfmt(hi) + "]" + (unit.empty() ? "" : " (" + unit + ")"));
}

std::string node_text(const toml::node& n) {
  std::ostringstream s;
  if (auto str = n.value<std::string>()) {
    s << '"' << *str << '"';
  } else if (n.is_table()) {
    s << "{table}";
  } else if (n.is_array()) {
    s << "[array]";
  } else if (n.is_boolean()) {
    s << (n.value<bool>().value_or(false) ? "true" : "false");
  } else if (n.is_integer()) {
    // Typed access only: toml++'s value<int64_t>() on a float casts before its range check
    // (undefined for 5.5e40; found by the fuzz target).
    s << n.as_integer()->get();
  } else if (auto d = n.value<double>()) {
    s << sfmt(*d);
  } else {
    s << "(value)";
  }
  return s.str();
}

std::string join(const std::set<std::string>& keys) {
  std::string out;
  for (auto& k : keys) out += (out.empty() ? "" : ", ") + k;
  return out;
}

/// Field accessors that name the TOML path in their errors.
class Fields {
 public:
  Fields(const toml::table& t, std::string_view path, std::set<std::string> allowed)
      : t_(t), path_(path), allowed_(std::move(allowed)) {
    for (auto&& [k, v] : t_) {
      (void)v;
      const std::string key(k.str());
      if (!allowed_.count(key))
        throw InputError(field(key), node_text(v), "unknown key (allowed: " + join(allowed_) + ")");
    }
  }
  [[nodiscard]] std::string field(std::string_view key) const { return std::string(path_) + "." + std::string(key); }
  [[nodiscard]] bool has(std::string_view key) const { return t_.contains(key); }
  [[nodiscard]] const toml::node* node(std::string_view key) const { return t_.get(key); }

  [[nodiscard]] std::optional<double> number(std::string_view key) const {
    const toml::node* n = t_.get(key);
    if (!n) return std::nullopt;
    if (!n->is_number()) throw InputError(field(key), node_text(*n), "must be a number");
    return n->value<double>();
  }
  [[nodiscard]] double positive(std::string_view key, const std::string& unit, std::optional<double> dflt = {}) const {
    auto v = number(key);
    if (!v && !dflt) throw InputError(field(key), "(missing)", "required, must be > 0 (" + unit + ")");
    const double x = v ? *v : *dflt;
    need_positive(field(key), x, unit);
    return x;
  }
  [[nodiscard]] std::optional<std::string> string(std::string_view key) const {
    const toml::node* n = t_.get(key);
    if (!n) return std::nullopt;
    if (!n->is_string()) throw InputError(field(key), node_text(*n), "must be a string");
    return n->value<std::string>();
  }
  [[nodiscard]] std::optional<bool> boolean(std::string_view key) const {
    const toml::node* n = t_.get(key);
    if (!n) return std::nullopt;
    if (!n->is_boolean()) throw InputError(field(key), node_text(*n), "must be true or false");
    return n->value<bool>();
  }

 private:
  const toml::table& t_;
  std::string_view path_;
  std::set<std::string> allowed_;
};

std::string material_names() {
  std::string s;
  for (auto& m : forces::solid_materials()) s += (s.empty() ? "" : ", ") + m.name;
  return s;
}
std::string liquid_names() {
  std::string s;
  for (auto& l : forces::liquids()) s += (s.empty() ? "" : ", ") + l.name;
  return s;
}

/// The keys a table admits, from the scene key table (scene_keys.cpp).
std::set<std::string> table_keys(std::string_view table) {
  const auto v = scene_table_keys(table);
  return {v.begin(), v.end()};
}

forces::Material parse_material(const Fields& f, bool need_density) {
  forces::Material m;
  m.surface_energy = kNaN;
  bool named = false;
  if (auto name = f.string("material")) {
    auto found = forces::find_material(*name);
    if (!found) throw InputError(f.field("material"), "\"" + *name + "\"", "unknown material (known: " + material_names() + ")");
    m = *found;
    named = true;
  } else {
    m.name = "custom";
  }
  if (auto v = f.number("density")) { need_positive(f.field("density"), *v, "kg/m^3"); m.density = *v; }
  if (auto v = f.number("hamaker")) { need_nonnegative(f.field("hamaker"), *v, "J"); m.hamaker = *v; }
  if (auto v = f.number("youngs_modulus")) { need_nonnegative(f.field("youngs_modulus"), *v, "Pa"); m.youngs_modulus = *v; }
  if (auto v = f.number("poisson_ratio")) { need_range(f.field("poisson_ratio"), *v, -1.0, 0.5); m.poisson_ratio = *v; }
  if (auto v = f.number("surface_energy")) { need_nonnegative(f.field("surface_energy"), *v, "J/m^2"); m.surface_energy = *v; }
  if (!named) {
    if (need_density && !f.has("density"))
      throw InputError(f.field("density"), "(missing)", "required when no material is named, must be > 0 (kg/m^3)");
    if (!f.has("hamaker"))
      throw InputError(f.field("hamaker"), "(missing)", "required when no material is named, must be >= 0 (J)");
    m.source = "explicit constants in the scene";
  } else if (f.has("density") || f.has("hamaker") || f.has("youngs_modulus") || f.has("poisson_ratio") ||
             f.has("surface_energy")) {
    m.source += " (with explicit overrides from the scene)";
  }
  return m;
}

forces::Liquid parse_liquid_node(const toml::node& n, const std::string& path) {
  if (auto name = n.value<std::string>()) {
    auto l = forces::find_liquid(*name);
    if (!l) throw InputError(path, "\"" + *name + "\"", "unknown liquid (known: " + liquid_names() + ")");
    return *l;
  }
  const toml::table* t = n.as_table();
  if (!t) throw InputError(path, node_text(n), "must be a liquid name or a table");
  Fields f(*t, path, table_keys("environment.liquid"));
  forces::Liquid l;
  if (auto name = f.string("name")) {
    auto found = forces::find_liquid(*name);
    if (!found) throw InputError(f.field("name"), "\"" + *name + "\"", "unknown liquid (known: " + liquid_names() + ")");
    l = *found;
  } else {
    l.name = "custom";
    l.source = "explicit constants in the scene";
    for (const char* k : {"density", "hamaker", "surface_tension", "molar_volume"})
      if (!f.has(k)) throw InputError(f.field(k), "(missing)", "required when no liquid name is given");
  }
  if (auto v = f.number("density")) { need_nonnegative(f.field("density"), *v, "kg/m^3"); l.density = *v; }
  if (auto v = f.number("hamaker")) { need_nonnegative(f.field("hamaker"), *v, "J"); l.hamaker = *v; }
  if (auto v = f.number("surface_tension")) { need_positive(f.field("surface_tension"), *v, "N/m"); l.surface_tension = *v; }
  if (auto v = f.number("molar_volume")) { need_positive(f.field("molar_volume"), *v, "m^3/mol"); l.molar_volume = *v; }
  if (auto v = f.number("contact_angle")) { need_range(f.field("contact_angle"), *v, 0.0, forces::kPi / 2, "rad"); l.contact_angle = *v; }
  return l;
}

}  // namespace

Environment parse_environment(const toml::table& t, std::string_view path) {
  Fields f(t, path, table_keys("environment"));
  Environment e;
  const std::string medium = f.string("medium").value_or("vacuum");
  if (const auto m = choice_from_name<Medium>(medium))
    e.medium = *m;
  else
    throw InputError(f.field("medium"), "\"" + medium + "\"", "must be one of: " + choice_names<Medium>(", "));

  if (auto h = f.number("humidity")) {
    need_range(f.field("humidity"), *h, 0.0, 1.0);
    if (e.medium != Medium::humid_air)
      throw InputError(f.field("humidity"), sfmt(*h), "only allowed with medium = \"humid_air\"");
    e.humidity = *h;
  } else if (e.medium == Medium::humid_air) {
    throw InputError(f.field("humidity"), "(missing)", "required with medium = \"humid_air\", must be in [0, 1]");
  }
  e.temperature = f.positive("temperature", "K", e.temperature);
  if (const toml::node* n = f.node("liquid")) {
    if (e.medium == Medium::vacuum)
      throw InputError(f.field("liquid"), node_text(*n), "not allowed with medium = \"vacuum\"");
    e.liquid = parse_liquid_node(*n, f.field("liquid"));
  } else if (e.medium == Medium::liquid) {
    throw InputError(f.field("liquid"), "(missing)", "required with medium = \"liquid\" (known: " + liquid_names() + ")");
  }
  if (auto v = f.number("contact_angle")) {
    need_range(f.field("contact_angle"), *v, 0.0, forces::kPi / 2, "rad");
    e.liquid.contact_angle = *v;
  }
  e.adhesion = f.boolean("adhesion").value_or(true);
  e.gap = f.positive("gap", "m", e.gap);
  if (auto g = f.number("gravity")) {
    need_nonnegative(f.field("gravity"), *g, "m/s^2");
    e.gravity = *g;
  }
  if (const toml::node* n = f.node("substrate")) {
    const std::string sp = f.field("substrate");
    if (auto name = n->value<std::string>()) {
      auto m = forces::find_material(*name);
      if (!m) throw InputError(sp, "\"" + *name + "\"", "unknown material (known: " + material_names() + ")");
      e.substrate = *m;
    } else if (const toml::table* st = n->as_table()) {
      Fields sf(*st, sp, table_keys("environment.substrate"));
      e.substrate = parse_material(sf, false);
    } else {
      throw InputError(sp, node_text(*n), "must be a material name or a table");
    }
    e.has_substrate = true;
  }
  return e;
}

Body parse_body(const toml::table& t, std::string_view path) {
  Fields f(t, path, table_keys("body"));
  Body b;
  b.name = f.string("name").value_or(std::string(path));
  const auto shape = f.string("shape");
  if (!shape) throw InputError(f.field("shape"), "(missing)", "required, one of: " + choice_names<Shape>(", "));
  auto forbid = [&](std::initializer_list<const char*> ks) {
    for (const char* k : ks)
      if (f.has(k)) throw InputError(f.field(k), node_text(*f.node(k)), "not used by shape = \"" + *shape + "\"");
  };
  const auto kind = choice_from_name<Shape>(*shape);
  if (!kind)
    throw InputError(f.field("shape"), "\"" + *shape + "\"", "must be one of: " + choice_names<Shape>(", "));
  b.shape = *kind;
  switch (*kind) {
    case Shape::bar:
      forbid({"radius", "inner_radius"});
      b.length = f.positive("length", "m");
      b.width = f.positive("width", "m");
      b.height = f.positive("height", "m");
      break;
    case Shape::rod:
      forbid({"width", "height", "inner_radius"});
      b.radius = f.positive("radius", "m");
      b.length = f.positive("length", "m");
      break;
    case Shape::tube:
      forbid({"width", "height"});
      b.radius = f.positive("radius", "m");
      b.length = f.positive("length", "m");
      if (auto ri = f.number("inner_radius")) {
        need_nonnegative(f.field("inner_radius"), *ri, "m");
        if (!(*ri < b.radius))
          throw InputError(f.field("inner_radius"), sfmt(*ri), "must be < radius = " + sfmt(b.radius) + " (m)");
        b.inner_radius = *ri;
      }
      break;
    case Shape::sphere:
      forbid({"length", "width", "height", "inner_radius"});
      b.radius = f.positive("radius", "m");
      break;
  }
  b.material = parse_material(f, true);
  return b;
}

}  // namespace nanopush
