#include "columns.hpp"

#include <stdexcept>
#include <string_view>
#include "nanopush_toml.hpp"

namespace nanopush::cli {

#include "columns.toml.inc"  // kColumnCatalogueToml: columns.toml, compiled in (drivers/CMakeLists.txt)

namespace {

std::string text_of(const toml::table& t, std::string_view key, const std::string& where) {
  const auto* v = t.get_as<std::string>(key);
  if (!v) throw std::logic_error(where + ": '" + std::string(key) + "' must be a string");
  return v->get();
}

Column column_of(const toml::table& t, const std::string& where) {
  for (const auto& [k, v] : t) {
    (void)v;
    if (k != "name" && k != "unit" && k != "description" && k != "kind" && k != "parameters")
      throw std::logic_error(where + ": unknown key '" + std::string(k.str()) + "'");
  }
  Column c;
  c.name = text_of(t, "name", where);
  const std::string at = where + ", column " + c.name;
  c.description = text_of(t, "description", at);
  const std::string kind = t.contains("kind") ? text_of(t, "kind", at) : "number";
  if (kind == "number") {
    c.unit = text_of(t, "unit", at);
  } else if (kind == "text" || kind == "count") {
    if (t.contains("unit")) throw std::logic_error(at + ": a " + kind + " column takes no unit");
    c = kind == "text" ? text_column(c.name, c.description) : count_column(c.name, c.description);
  } else {
    throw std::logic_error(at + ": kind '" + kind + "' is not number, text or count");
  }
  if (const auto* p = t.get("parameters")) {
    const auto* pt = p->as_table();
    if (!pt) throw std::logic_error(at + ": 'parameters' must be a table");
    for (const auto& [k, v] : *pt) {
      const auto x = v.value<double>();
      if (!x) throw std::logic_error(at + ": parameter '" + std::string(k.str()) + "' must be a number");
      c.parameters[std::string(k.str())] = *x;
    }
  }
  return c;
}

}  // namespace

std::map<std::string, Columns, std::less<>> parse_column_catalogue(std::string_view toml_text,
                                                                   const std::string& source) {
  toml::table doc;
  try {
    doc = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    throw std::logic_error(source + ": " + std::string(e.description()));
  }
  std::map<std::string, Columns, std::less<>> out;
  for (const auto& [name, node] : doc) {
    const std::string where = source + ": [" + std::string(name.str()) + "]";
    const auto* t = node.as_table();
    const auto* cols = t ? t->get_as<toml::array>("columns") : nullptr;
    if (!cols || t->size() != 1) throw std::logic_error(where + ": a table holds one key, columns = [...]");
    Columns c;
    for (const auto& e : *cols) {
      const auto* et = e.as_table();
      if (!et) throw std::logic_error(where + ": every column is a table { name = ..., ... }");
      c.push_back(column_of(*et, where));
    }
    if (c.empty()) throw std::logic_error(where + ": no columns");
    for (std::size_t i = 0; i < c.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (c[i].name == c[j].name) throw std::logic_error(where + ": column " + c[i].name + " twice");
    out.emplace(std::string(name.str()), std::move(c));
  }
  return out;
}

namespace {
const std::map<std::string, Columns, std::less<>>& catalogue() {
  static const auto c = parse_column_catalogue(kColumnCatalogueToml, "drivers/columns.toml");
  return c;
}
}  // namespace

const Columns& columns(std::string_view table) {
  const auto it = catalogue().find(table);
  if (it == catalogue().end()) throw std::logic_error("drivers/columns.toml: no table [" + std::string(table) + "]");
  return it->second;
}

std::vector<std::string> column_tables() {
  std::vector<std::string> names;
  for (const auto& entry : catalogue()) names.push_back(entry.first);
  return names;
}

}  // namespace nanopush::cli
