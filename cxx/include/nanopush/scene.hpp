// Scene files (TOML): the object, the push, the initial state, the surface and the solver
// settings. A scene declares only what it needs; docs/scenes.md documents every key.
#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "nanopush/rigid_body.hpp"

namespace nanopush {

struct SolverSettings {
  double t_end = 0;            ///< [s]
  int samples = 401;           ///< output times, evenly spaced over [0, t_end], both ends included
  double rtol = 1e-10;
  double atol = 0;             ///< 0 = automatic: rtol times each state's natural scale
  std::string engine = "cxx";  ///< cxx | f77
  std::string method = "faithful";  ///< faithful | modern (C++ engine)
  double h0 = 0;               ///< initial step [s]; 0 = 1% of t_end
  double hmax = 0;             ///< largest step [s]; 0 = none
};

struct Scene {
  std::string name, description;
  std::filesystem::path source;
  std::string model = "smooth";  ///< surface model: smooth (models.md §A)
  std::string shape = "bar";
  BarGeometry geometry;          ///< half-width a, half-length b
  double length = 0, width = 0, height = 0;  ///< [m]
  double density = 0;            ///< [kg/m^3]; 0 when mass was given directly
  double mass = 0;               ///< [kg]
  double inertia = 0;            ///< about the CM, z axis [kg m^2]
  Push push;
  std::array<double, kStateSize> initial{};  ///< x, y, theta, vx, vy, omega
  SolverSettings solver;

  /// Output times 0, t_end/(samples-1), ..., t_end.
  [[nodiscard]] std::vector<double> output_times() const;
  /// Natural scale of each state component (length, angle 1, velocity, rate), for atol.
  [[nodiscard]] std::array<double, kStateSize> state_scales() const;
  /// Absolute tolerances per component: atol if set, else rtol * state_scales().
  [[nodiscard]] std::vector<double> atol_vector(double rtol, double atol) const;
};

/// Parse a scene; throws InputError naming the TOML key, the value and the allowed range.
Scene parse_scene(std::string_view toml_text, const std::string& source_name = "<string>");
Scene load_scene(const std::filesystem::path& path);

}  // namespace nanopush
