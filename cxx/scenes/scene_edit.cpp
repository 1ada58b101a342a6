// Setting scene keys after loading (--set, Python and C overrides): a value read from text,
// put at its dotted key in the scene's document, and the scene parsed again from it, so a set
// scene is checked exactly as a loaded one; SceneBuilder builds a scene key by key the same way.
#include "nanopush_toml.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <memory>
#include <sstream>

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/scene_keys.hpp"

namespace nanopush {

namespace {

const SceneKey& known_key(const std::string& key, const std::string& value_text) {
  const SceneKey* k = find_scene_key(key);
  if (!k) {
    const std::string near = nearest_scene_key(key);
    throw InputError(key, value_text,
                     "unknown scene key (" + (near.empty() ? "" : "did you mean " + near + "? ") +
                         "`nanopush scene-keys` lists them)");
  }
  return *k;
}

/// Put `value` at the dotted `key` of `doc`, creating tables on the way.
void put(toml::table& doc, const std::string& key, const SceneValue& value) {
  const SceneKey& k = known_key(key, value.to_string());
  const std::string shown = value.kind() == KeyType::string ? "\"" + value.text() + "\"" : value.to_string();
  toml::table* t = &doc;
  std::size_t start = 0;
  for (std::size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', start)) {
    const std::string part = key.substr(start, dot - start);
    toml::node* n = t->get(part);
    if (!n) n = &t->insert_or_assign(part, toml::table{}).first->second;
    if (!n->is_table())
      throw InputError(key, shown, key.substr(0, dot) + " is not a table in this scene (it is a name): set " +
                                       key.substr(0, dot) + " itself, or give its table in the file");
    t = n->as_table();
    start = dot + 1;
  }
  const std::string leaf = key.substr(start);
  switch (k.type) {
    case KeyType::number:
      if (value.kind() != KeyType::number) throw InputError(key, shown, "must be a number (" + std::string(k.unit) + ")");
      t->insert_or_assign(leaf, value.number());
      break;
    case KeyType::integer: {
      const double v = value.number();
      if (value.kind() != KeyType::number || !(std::fabs(v) <= 9e15) || std::floor(v) != v)
        throw InputError(key, shown, "must be a whole number in " + std::string(k.range));
      t->insert_or_assign(leaf, static_cast<std::int64_t>(v));
      break;
    }
    case KeyType::string:
      if (value.kind() != KeyType::string) throw InputError(key, shown, "must be text: " + std::string(k.range));
      t->insert_or_assign(leaf, value.text());
      break;
    case KeyType::boolean:
      if (value.kind() != KeyType::boolean) throw InputError(key, shown, "must be true or false");
      t->insert_or_assign(leaf, value.flag());
      break;
    case KeyType::array:
    case KeyType::table:
      throw InputError(key, shown, "is a" + std::string(k.type == KeyType::array ? "n array" : " table") +
                                       ": set its scalar keys instead (`nanopush scene-keys`)");
  }
}

}  // namespace

SceneValue SceneValue::from_text(std::string_view key, std::string_view text) {
  const SceneKey& k = known_key(std::string(key), std::string(text));
  const std::string s(text);
  const std::string shown = s.empty() ? "\"\" (empty)" : s;
  switch (k.type) {
    case KeyType::number:
    case KeyType::integer: {
      double v = 0;
      const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
      if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size())
        throw InputError(std::string(key), shown, "must be a number" + (k.unit.empty() ? std::string() : " (" + std::string(k.unit) + ")"));
      require_finite(std::string(key), v, std::string(k.unit));
      return v;
    }
    case KeyType::boolean:
      if (s == "true") return true;
      if (s == "false") return false;
      throw InputError(std::string(key), shown, "must be true or false");
    default:
      return s;
  }
}

std::string SceneValue::to_string() const {
  switch (kind_) {
    case KeyType::number: return fmt(number_);
    case KeyType::boolean: return flag_ ? "true" : "false";
    default: return text_;
  }
}

void Scene::set(const std::string& key, const SceneValue& value) { set(std::vector<SceneSetting>{{key, value}}); }

void Scene::set(const std::vector<SceneSetting>& settings) {
  toml::table doc = document ? *document : toml::table{};
  for (const auto& [key, value] : settings) put(doc, key, value);
  const std::filesystem::path keep = source;
  Scene next = scene_from_document(doc, source.string());
  next.source = keep;
  *this = std::move(next);
}

void Scene::unset(const std::string& key) {
  known_key(key, "(unset)");
  toml::table doc = document ? *document : toml::table{};
  toml::table* t = &doc;
  std::size_t start = 0;
  for (std::size_t dot = key.find('.'); dot != std::string::npos && t; dot = key.find('.', start)) {
    toml::node* n = t->get(key.substr(start, dot - start));
    t = n ? n->as_table() : nullptr;
    start = dot + 1;
  }
  if (t) t->erase(key.substr(start));
  const std::filesystem::path keep = source;
  Scene next = scene_from_document(doc, source.string());
  next.source = keep;
  *this = std::move(next);
}

std::string Scene::to_toml() const {
  std::ostringstream o;
  if (document) o << *document << "\n";
  return o.str();
}

SceneBuilder::SceneBuilder() = default;
SceneBuilder::SceneBuilder(const SceneBuilder& other)
    : doc_(other.doc_ ? std::make_unique<toml::table>(*other.doc_) : nullptr) {}
SceneBuilder::SceneBuilder(SceneBuilder&&) noexcept = default;
SceneBuilder& SceneBuilder::operator=(const SceneBuilder& other) {
  if (this != &other) doc_ = other.doc_ ? std::make_unique<toml::table>(*other.doc_) : nullptr;
  return *this;
}
SceneBuilder& SceneBuilder::operator=(SceneBuilder&&) noexcept = default;
SceneBuilder::~SceneBuilder() = default;

SceneBuilder& SceneBuilder::set(const std::string& key, const SceneValue& value) {
  if (!doc_) doc_ = std::make_unique<toml::table>();
  put(*doc_, key, value);
  return *this;
}

Scene SceneBuilder::build(const std::string& name) const {
  toml::table doc = doc_ ? *doc_ : toml::table{};
  if (!doc.get("scene")) doc.insert_or_assign("scene", toml::table{});
  toml::table& st = *doc.get("scene")->as_table();
  if (!st.get("name")) st.insert_or_assign("name", name);
  return scene_from_document(doc, name);
}

}  // namespace nanopush
