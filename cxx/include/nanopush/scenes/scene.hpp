// Scene files (TOML): the object, the push, the initial state, the surface and the solver
// settings. A scene declares only what it needs; docs/scenes.md documents every key.
#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "nanopush/models/rigid_body.hpp"

namespace nanopush {

/// The support surface (docs/models.md §A, §C).
struct SurfaceSettings {
  std::string kind = "smooth";  ///< smooth | rough
  double mu = 0;                ///< Coulomb friction coefficient
  double f_vdw = 0;             ///< adhesion (Van der Waals) load [N]
  double g = 9.81;              ///< gravity [m/s^2]
  double normal_load = 0;       ///< N [N]; 0 = m g + f_vdw
  std::string law = "thesis";   ///< thesis | coulomb
};

struct SolverSettings {
  double t_end = 0;            ///< [s]
  int samples = 401;           ///< output times, evenly spaced over [0, t_end], both ends included
  double rtol = 1e-10;
  double atol = 0;             ///< 0 = automatic: rtol times each state's natural scale
  std::string engine = "cxx";  ///< cxx | f77
  std::string method = "faithful";  ///< faithful | modern (C++ engine)
  std::string precision = "double";  ///< double | long | quad (long, quad: C++ engine, smooth surface)
  double h0 = 0;               ///< initial step [s]; 0 = 1% of t_end
  double hmax = 0;             ///< largest step [s]; 0 = none
  long max_steps = 100000;     ///< attempted steps before giving up
};

struct Scene {
  std::string name, description;
  std::filesystem::path source;
  std::string model = "smooth";  ///< surface model: smooth (docs/models.md §A) or rough (§C)
  SurfaceSettings surface;
  std::string shape = "bar";
  BarGeometry geometry;          ///< half-width a, half-length b
  double length = 0, width = 0, height = 0;  ///< [m]
  double density = 0;            ///< [kg/m^3]; 0 when mass was given directly
  double mass = 0;               ///< [kg]
  double inertia = 0;            ///< about the CM, z axis [kg m^2]
  Push push;
  std::array<double, kStateSize> initial{};  ///< x, y, theta, vx, vy, omega
  SolverSettings solver;
  /// Term report of the normal load (rough scenes): from the [environment]/[body] models
  /// when the scene names them, else the given m g + F_vdw.
  std::string load_report;

  /// Output times 0, t_end/(samples-1), ..., t_end.
  [[nodiscard]] std::vector<double> output_times() const;
  /// Natural scale of each state component (length, angle 1, velocity, rate, and the work
  /// accumulators of the rough model, F L), for atol.
  [[nodiscard]] std::array<double, 8> state_scales() const;
  /// Absolute tolerances for the first n components: atol if set, else rtol * state_scales().
  [[nodiscard]] std::vector<double> atol_vector(double rtol, double atol, int n = kStateSize) const;
  /// Normal load N [N] of a rough scene.
  [[nodiscard]] double normal_load() const {
    return surface.normal_load > 0 ? surface.normal_load : mass * surface.g + surface.f_vdw;
  }
  [[nodiscard]] bool rough() const { return surface.kind == "rough"; }
};

/// Parse a scene; throws InputError naming the TOML key, the value and the allowed range.
/// Why extended precision (long, quad) cannot run with this surface, engine and method, or
/// "" when it can: the right-hand side must be templated on the scalar (the smooth bar in the
/// C++ Bulirsch–Stoer). One rule for scene files and run settings.
std::string extended_precision_obstacle(bool rough, const std::string& engine, const std::string& method);

Scene parse_scene(std::string_view toml_text, const std::string& source_name = "<string>");
Scene load_scene(const std::filesystem::path& path);

}  // namespace nanopush
