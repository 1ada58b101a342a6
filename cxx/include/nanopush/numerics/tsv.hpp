// Tables kept as data in tab-separated text compiled into a layer (nanopush_embed_text in
// cxx/CMakeLists.txt): scenes/scene_keys.tsv, sweeps/task_columns.tsv. A row is a line that is
// neither blank nor a # comment; its fields are separated by single tabs (a field may be empty).
// constexpr, so a table can be split into rows at compile time.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string_view>

namespace nanopush::tsv {

/// Calls f(row) on every row of the text.
template <class F>
constexpr void for_each_row(std::string_view text, F f) {
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    if (!line.empty() && line.front() != '#') f(line);
  }
}

/// The number of rows of the text.
constexpr std::size_t row_count(std::string_view text) {
  std::size_t n = 0;
  for_each_row(text, [&n](std::string_view) { ++n; });
  return n;
}

/// The Fields fields of a row; std::logic_error (at compile time: no constant, the build stops)
/// if it has another number.
template <std::size_t Fields>
constexpr std::array<std::string_view, Fields> fields(std::string_view row) {
  std::array<std::string_view, Fields> f{};
  for (std::size_t i = 0; i < Fields; ++i) {
    const std::size_t tab = row.find('\t');
    if ((tab == std::string_view::npos) != (i + 1 == Fields))
      throw std::logic_error("a row of a compiled-in table (.tsv) has the wrong number of fields");
    f[i] = row.substr(0, tab);
    row.remove_prefix(tab == std::string_view::npos ? row.size() : tab + 1);
  }
  return f;
}

}  // namespace nanopush::tsv
