// Errors that reach the user. Input errors name the field, the value and the allowed range.
#pragma once
#include <charconv>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace nanopush {

/// Bad user input (scene file, command-line value, API argument).
/// what() reads: "<field> = <value>: <requirement>", e.g.
/// "object.mass = -1: must be > 0 (kg)".
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& field, const std::string& value, const std::string& requirement)
      : std::runtime_error(field + " = " + value + ": " + requirement), field_(field) {}
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  [[nodiscard]] const std::string& field() const noexcept { return field_; }

 private:
  std::string field_;
};

/// A numerical failure (step size underflow, too many steps, non-finite state...).
/// `outcome` names how the run ended (docs/errors.md: solver_failure, no_static_friction,
/// law_blowup, accuracy_not_reached).
class SolverError : public std::runtime_error {
 public:
  explicit SolverError(const std::string& message, std::string outcome = "solver_failure")
      : std::runtime_error(message), outcome_(std::move(outcome)) {}
  [[nodiscard]] const std::string& outcome() const noexcept { return outcome_; }

 private:
  std::string outcome_;
};

/// Format a double in the shortest form that reads back exactly, for messages.
inline std::string fmt(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

/// A point for messages: "[x, y]".
inline std::string fmt_point(double x, double y) {
  std::string s = "[";
  s.append(fmt(x)).append(", ").append(fmt(y)).append("]");
  return s;
}

/// Throw InputError unless lo < v < hi (strict) or lo <= v <= hi (closed), v finite.
inline void require_finite(const std::string& field, double v, const std::string& unit = "") {
  if (!(v == v) || v - v != 0.0)
    throw InputError(field, fmt(v), "must be a finite number" + (unit.empty() ? "" : " (" + unit + ")"));
}
/// A point given as its two coordinates (tip.start: start_x, start_y), named as one.
inline void require_finite_point(const std::string& field, double x, double y, const std::string& unit = "") {
  if (!(x - x == 0.0 && y - y == 0.0))
    throw InputError(field, fmt_point(x, y), "must be finite numbers" + (unit.empty() ? "" : " (" + unit + ")"));
}
inline void require_positive(const std::string& field, double v, const std::string& unit = "") {
  require_finite(field, v, unit);
  if (!(v > 0.0)) throw InputError(field, fmt(v), "must be > 0" + (unit.empty() ? "" : " (" + unit + ")"));
}
inline void require_nonnegative(const std::string& field, double v, const std::string& unit = "") {
  require_finite(field, v, unit);
  if (!(v >= 0.0)) throw InputError(field, fmt(v), "must be >= 0" + (unit.empty() ? "" : " (" + unit + ")"));
}
inline void require_range(const std::string& field, double v, double lo, double hi,
                          const std::string& unit = "") {
  require_finite(field, v, unit);
  if (!(v >= lo && v <= hi))
    throw InputError(field, fmt(v),
                     "must be in [" + fmt(lo) + ", " + fmt(hi) + "]" + (unit.empty() ? "" : " (" + unit + ")"));
}

}  // namespace nanopush
