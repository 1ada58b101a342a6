// The choices a scene and a run make (engine, method, friction law, precision, surface kind)
// as types, each with one name table: the names a scene file, the command line, Python, C and
// Fortran use, the order messages list them in, and nothing else compares their text.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "nanopush/numerics/error.hpp"

namespace nanopush {

/// Which engine integrates: the C++ solver or the FORTRAN 77 reproduction.
enum class Engine { cxx, f77 };
/// The C++ engine's method (docs/scenes.md): faithful (the F77 engine's steps), modern (dense
/// output), dop853, cvode (the coulomb law's cross-check), automatic (by rtol, name "auto").
enum class Method { faithful, modern, dop853, cvode, automatic };
/// The friction law of a rough surface: thesis (eq 3.40 sign law), printed (the equations as
/// printed), coulomb (event-located stick-slip).
enum class Law { thesis, printed, coulomb };
/// The scalar of the integration: double, long (x87 80-bit long double), quad (__float128).
enum class Precision { double_, long_, quad };
/// The support surface: smooth (docs/models.md section A) or rough (section C).
enum class SurfaceKind { smooth, rough };

/// The name table of a choice: every value and its name, in the order messages list them.
template <class E>
struct ChoiceNames;
template <>
struct ChoiceNames<Engine> {
  static constexpr std::array<std::pair<Engine, std::string_view>, 2> table{
      {{Engine::cxx, "cxx"}, {Engine::f77, "f77"}}};
};
template <>
struct ChoiceNames<Method> {
  static constexpr std::array<std::pair<Method, std::string_view>, 5> table{{{Method::faithful, "faithful"},
                                                                             {Method::modern, "modern"},
                                                                             {Method::dop853, "dop853"},
                                                                             {Method::cvode, "cvode"},
                                                                             {Method::automatic, "auto"}}};
};
template <>
struct ChoiceNames<Law> {
  static constexpr std::array<std::pair<Law, std::string_view>, 3> table{
      {{Law::thesis, "thesis"}, {Law::printed, "printed"}, {Law::coulomb, "coulomb"}}};
};
template <>
struct ChoiceNames<Precision> {
  static constexpr std::array<std::pair<Precision, std::string_view>, 3> table{
      {{Precision::double_, "double"}, {Precision::long_, "long"}, {Precision::quad, "quad"}}};
};
template <>
struct ChoiceNames<SurfaceKind> {
  static constexpr std::array<std::pair<SurfaceKind, std::string_view>, 2> table{
      {{SurfaceKind::smooth, "smooth"}, {SurfaceKind::rough, "rough"}}};
};

/// The name of a value ("auto" for Method::automatic).
template <class E>
constexpr std::string_view name_of(E e) {
  for (const auto& [v, n] : ChoiceNames<E>::table)
    if (v == e) return n;
  return "?";
}
template <class E>
std::string to_string(E e)
  requires requires { ChoiceNames<E>::table; }
{
  return std::string(name_of(e));
}

/// The value of a name, or nullopt.
template <class E>
constexpr std::optional<E> choice_from_name(std::string_view text) {
  for (const auto& [v, n] : ChoiceNames<E>::table)
    if (n == text) return v;
  return std::nullopt;
}

/// The names joined for a message: "a, b or c" (sep ", ", last " or "), or with `last` = ", "
/// the key table's "a, b, c".
template <class E>
std::string choice_names(std::string_view last = " or ") {
  std::string s;
  const auto& t = ChoiceNames<E>::table;
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
