// Every key a scene file may hold: its type, unit, default, allowed range, the surface kinds
// that use it and its meaning. One table serves four readers: the parser (which keys a table
// admits), Scene::set (the type a value must have), `nanopush scene-keys` (the list for
// users) and docs/scenes.md (generated from it; a test keeps them equal). The cross-key rules
// (mass or density, xn/yn or point, the push point on the body, ...) stay in the parser.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace nanopush {

enum class KeyType { number, integer, string, boolean, array, table };
std::string_view key_type_name(KeyType t);

struct SceneKey {
  std::string_view key;          ///< dotted path, e.g. "surface.mu"
  KeyType type;
  std::string_view unit;         ///< SI unit; "1" dimensionless; "" for text and flags
  std::string_view default_text; ///< "required", a value, or how it is derived
  std::string_view range;        ///< allowed values, as the parser checks them
  std::string_view kinds;        ///< surface kinds that use the key: "all", "rough", "smooth"
  std::string_view description;
};

/// The table, in documentation order.
const std::vector<SceneKey>& scene_keys();
/// The entry of a dotted key, or nullptr.
const SceneKey* find_scene_key(std::string_view key);
/// The key nearest to a mistyped one (edit distance with transpositions, at most about a
/// quarter of its length; a bare name such as "mu" also matches a key's last part), for
/// "did you mean surface.mu?"; "" when none is close.
std::string nearest_scene_key(std::string_view key);
/// Keys directly under a table ("object" -> length, width, ...), for the parser's unknown-key
/// check ("" = the top-level tables).
std::vector<std::string> scene_table_keys(std::string_view table);
/// The table as Markdown (the generated part of docs/scenes.md).
std::string scene_keys_markdown();

}  // namespace nanopush
