// The scene key table (scene_keys.hpp), read from scene_keys.tsv. Ranges are written as the
// parser checks them (scene.cpp, environment_toml.cpp); tests/test_scene_keys.cpp holds the two
// together.
#include "nanopush/scenes/scene_keys.hpp"

#include "nanopush/numerics/tsv.hpp"
#include "nanopush/scenes/choices.hpp"

#include <algorithm>
#include <array>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace nanopush {

namespace {

constexpr std::string_view type_name(KeyType t) {
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

// The table is data: scene_keys.tsv, compiled in as kSceneKeysTsv (cxx/scenes/CMakeLists.txt)
// and split into rows at compile time, so a process reads no file and parses nothing. A row of
// the wrong shape (not seven fields, an unknown type) stops the build here.
#include "scene_keys.tsv.inc"

constexpr KeyType parse_type(std::string_view name) {
  for (int t = 0; t <= static_cast<int>(KeyType::table); ++t)
    if (type_name(static_cast<KeyType>(t)) == name) return static_cast<KeyType>(t);
  throw std::logic_error("scene_keys.tsv: unknown key type");
}

template <std::size_t Rows>
constexpr std::array<SceneKey, Rows> parse_table(std::string_view text) {
  std::array<SceneKey, Rows> rows{};
  std::size_t i = 0;
  tsv::for_each_row(text, [&](std::string_view row) {
    const auto f = tsv::fields<7>(row);
    rows[i++] = {f[0], parse_type(f[1]), f[2], f[3], f[4], f[5], f[6]};
  });
  return rows;
}

constexpr auto kTable = parse_table<tsv::row_count(kSceneKeysTsv)>(kSceneKeysTsv);

}  // namespace

std::string_view key_type_name(KeyType t) { return type_name(t); }

const std::vector<SceneKey>& scene_keys() {
  // The choice keys' allowed values ("{laws}" in the table) come from the choices' name tables
  // (choices.hpp).
  static const std::string kinds = choice_names<SurfaceKind>(", "), laws = choice_names<Law>(", "),
                           engines = choice_names<Engine>(", "), methods = choice_names<Method>(", "),
                           precisions = choice_names<Precision>(", "), push_modes = choice_names<PushMode>(", "),
                           tip_models = choice_names<TipModel>(", ");
  static const std::vector<SceneKey> keys = [] {
    const std::pair<std::string_view, const std::string*> choices[] = {
        {"{kinds}", &kinds}, {"{laws}", &laws}, {"{engines}", &engines}, {"{methods}", &methods},
        {"{precisions}", &precisions}, {"{push_modes}", &push_modes}, {"{tip_models}", &tip_models}};
    std::vector<SceneKey> out(kTable.begin(), kTable.end());
    for (SceneKey& k : out)
      for (const auto& [name, values] : choices)
        if (k.range == name) k.range = *values;
    return out;
  }();
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
