// Enumerations named as users write them: one table per enum (NameTable<E>, specialised
// beside the enum) gives every value its name, in the order messages list them; reading a name
// (parse_choice), writing one (name_of, to_string) and listing them (choice_names) go through
// it, so no code compares such a choice as text. Each table stands beside its enum (the scene
// choices in scenes/choices.hpp; `git grep NANOPUSH_NAMES` lists them all).
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "nanopush/numerics/error.hpp"

namespace nanopush {

/// The name table of an enumeration: specialise with
///   static constexpr std::array<std::pair<E, std::string_view>, N> table{...};
/// or, in namespace nanopush, declare it with NANOPUSH_NAMES below.
template <class E>
struct NameTable;

/// Declares the name table of enumeration E (in namespace nanopush), its size taken from the
/// entries:  NANOPUSH_NAMES(Law, {Law::thesis, "thesis"}, {Law::coulomb, "coulomb"});
#define NANOPUSH_NAMES(E, ...)                                                                   \
  template <>                                                                                    \
  struct NameTable<E> {                                                                          \
    static constexpr auto table = std::to_array<std::pair<E, std::string_view>>({__VA_ARGS__}); \
  }

/// The name of a value.
template <class E>
constexpr std::string_view name_of(E e) {
  for (const auto& [v, n] : NameTable<E>::table)
    if (v == e) return n;
  return "?";
}
template <class E>
std::string to_string(E e)
  requires requires { NameTable<E>::table; }
{
  return std::string(name_of(e));
}

/// The value of a name, or nullopt.
template <class E>
constexpr std::optional<E> choice_from_name(std::string_view text) {
  for (const auto& [v, n] : NameTable<E>::table)
    if (n == text) return v;
  return std::nullopt;
}

/// The names joined for a message: "a, b or c" (sep ", ", last " or "), or with `last` = ", "
/// the key table's "a, b, c".
template <class E>
std::string choice_names(std::string_view last = " or ") {
  std::string s;
  const auto& t = NameTable<E>::table;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (i > 0) s += i + 1 == t.size() ? std::string(last) : std::string(", ");
    s += t[i].second;
  }
  return s;
}

/// The name of a choice that may be unset ("" when unset: the scene's).
template <class E>
std::string name_or_empty(const std::optional<E>& e) {
  return e ? std::string(name_of(*e)) : std::string();
}

/// The value of `text`, or InputError "field = text: must be a, b or c".
template <class E>
E parse_choice(const std::string& field, std::string_view text) {
  if (const auto v = choice_from_name<E>(text)) return *v;
  throw InputError(field, std::string(text), "must be " + choice_names<E>());
}
/// As parse_choice, "" = unset (the scene's).
template <class E>
std::optional<E> parse_optional_choice(const std::string& field, std::string_view text) {
  if (text.empty()) return std::nullopt;
  return parse_choice<E>(field, text);
}

}  // namespace nanopush
