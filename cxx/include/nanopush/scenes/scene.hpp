// Scene files (TOML): the object, the push, the initial state, the surface and the solver
// settings. A scene declares only what it needs; docs/scenes.md documents every key.
#pragma once
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "nanopush/models/printed_reading.hpp"
#include "nanopush/models/rigid_body.hpp"
#include "nanopush/models/tip_push.hpp"
#include "nanopush/scenes/choices.hpp"
#include "nanopush/scenes/scene_keys.hpp"
#include "nanopush/scenes/toml_fwd.hpp"

namespace nanopush {

/// The support surface (docs/models.md §A, §C).
struct SurfaceSettings {
  SurfaceKind kind = SurfaceKind::smooth;
  double mu = 0;                ///< Coulomb friction coefficient
  double f_vdw = 0;             ///< adhesion (Van der Waals) load [N]
  double g = 9.81;              ///< gravity [m/s^2]
  double normal_load = 0;       ///< N [N]; 0 = m g + f_vdw
  Law law = Law::thesis;        ///< rough surfaces: the friction law
  PrintedReading printed;       ///< the printed law's reading of the slips ([surface.printed])
};

struct SolverSettings {
  double t_end = 0;            ///< [s]
  int samples = 401;           ///< output times, evenly spaced over [0, t_end], both ends included
  double rtol = 1e-10;
  double atol = 0;             ///< 0 = automatic: rtol times each state's natural scale
  Engine engine = Engine::cxx;
  Method method = Method::automatic;        ///< the C++ engine's method
  Precision precision = Precision::double_;  ///< long, quad: C++ engine, smooth surface
  double h0 = 0;               ///< initial step [s]; 0 = 1% of t_end
  double hmax = 0;             ///< largest step [s]; 0 = none
  long max_steps = 100000;     ///< attempted steps before giving up
  /// The error asked for of the final pose (docs/accuracy.md); 0 = none: run at rtol.
  double accuracy = 0;
  bool error_estimate = true;  ///< estimate the global error (a companion run)
};

/// The accuracies a run can be asked for (solver.accuracy, --accuracy; 0 = none).
inline constexpr double kAccuracyMin = 1e-14, kAccuracyMax = 0.1;

/// A value for a scene key: a number, an integer, a string or a flag. Its type must match the
/// key's (scene_keys.hpp); a number given for an integer key must be a whole number.
class SceneValue {
 public:
  SceneValue(double v) : kind_(KeyType::number), number_(v) {}                     // NOLINT
  SceneValue(int v) : kind_(KeyType::number), number_(v) {}                        // NOLINT
  SceneValue(long v) : kind_(KeyType::number), number_(static_cast<double>(v)) {}  // NOLINT
  SceneValue(bool v) : kind_(KeyType::boolean), flag_(v) {}                        // NOLINT
  SceneValue(const char* v) : kind_(KeyType::string), text_(v) {}                  // NOLINT
  SceneValue(std::string v) : kind_(KeyType::string), text_(std::move(v)) {}       // NOLINT
  /// A value as text (the command line's KEY=VALUE): read as the key's type.
  static SceneValue from_text(std::string_view key, std::string_view text);
  [[nodiscard]] KeyType kind() const { return kind_; }
  [[nodiscard]] double number() const { return number_; }
  [[nodiscard]] bool flag() const { return flag_; }
  [[nodiscard]] const std::string& text() const { return text_; }
  /// As written in messages and tables: a number in its shortest exact form, text as is.
  [[nodiscard]] std::string to_string() const;

 private:
  KeyType kind_;
  double number_ = 0;
  bool flag_ = false;
  std::string text_;
};

using SceneSetting = std::pair<std::string, SceneValue>;

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
  PushMode push_mode = PushMode::force;
  tip::TipPath tip;              ///< push.mode = tip: the tip and its path (docs/tip.md)
  TipModel tip_model = TipModel::quasi_static;  ///< push.mode = tip: tip.model
  double tip_stiffness = 0;      ///< the tip's lateral spring [N/m]: tip.stiffness or tip.cantilever; 0 neither
  /// The tip model a run uses: tip.model, with auto resolved by the inertia ratio (docs/tip.md).
  [[nodiscard]] TipModel tip_model_run() const;
  std::array<double, kStateSize> initial{};  ///< x, y, theta, vx, vy, omega
  SolverSettings solver;
  /// Term report of the normal load (rough scenes): from the [environment]/[body] models
  /// when the scene names them, else the given m g + F_vdw.
  std::string load_report;

  /// Explicit output times (Python's run(t_eval=...)): from 0, strictly increasing, at most
  /// t_end; set in code only (no scene key, not in the document). Empty: `samples` times.
  std::vector<double> times;
  /// Output times: `times` when set, else 0, t_end/(samples-1), ..., t_end.
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
  /// The friction limit mu N [N] of a rough scene: the largest friction force the surface
  /// exerts (the one place it is computed).
  [[nodiscard]] double friction_limit() const { return surface.mu * normal_load(); }
  [[nodiscard]] bool rough() const { return surface.kind == SurfaceKind::rough; }

  /// Set one key after loading, validated as the file is: the whole scene is read again from
  /// its document with the new value, so a value out of range, a key this scene's model does
  /// not use (surface.mu on a smooth surface) or a conflict (object.mass beside
  /// object.density) throws InputError naming the key, and the scene is left unchanged.
  void set(const std::string& key, const SceneValue& value);
  /// Several keys at once (then validated together: surface.kind = "rough" with surface.mu).
  void set(const std::vector<SceneSetting>& settings);
  /// Remove a key (back to its default); the scene must still be valid.
  void unset(const std::string& key);
  /// The scene file's document, with every set() applied (TOML).
  [[nodiscard]] std::string to_toml() const;
  /// The document behind this scene (toml++; include <toml++/toml.h> to read it). Null for a
  /// default-constructed Scene.
  std::shared_ptr<const toml::table> document;
};

/// A scene built from nothing in code: set keys, then build() validates the whole, e.g.
///   SceneBuilder b; b.set("object.length", 100e-9); ... ; Scene s = b.build();
class SceneBuilder {
 public:
  SceneBuilder();
  SceneBuilder(const SceneBuilder& other);
  SceneBuilder(SceneBuilder&&) noexcept;
  SceneBuilder& operator=(const SceneBuilder& other);
  SceneBuilder& operator=(SceneBuilder&&) noexcept;
  ~SceneBuilder();
  /// Checks the key exists and the value's type; the rest waits for build().
  SceneBuilder& set(const std::string& key, const SceneValue& value);
  [[nodiscard]] Scene build(const std::string& name = "scene") const;

 private:
  std::unique_ptr<toml::table> doc_;  ///< the keys set so far; null: none
};

/// Why extended precision (long, quad) cannot run with this surface, friction law, engine and
/// method, or "" when it can: the right-hand side must be templated on the scalar (the C++
/// Bulirsch-Stoer; on a rough surface the modern method under the thesis or coulomb law). One
/// rule for scene files and run settings.
std::string extended_precision_obstacle(bool rough, Law law, Engine engine, Method method);

/// The largest scene file load_scene reads [bytes].
inline constexpr std::size_t kMaxSceneBytes = 1u << 20;

/// Parse a scene; throws InputError naming the TOML key, the value and the allowed range.
/// Beyond each key's range, every number and the quantities derived from them (mass,
/// inertia, loads, accelerations, the output spacing, the state scales) must be 0 or of
/// magnitude 1e-150 to 1e150, which the integrators represent (docs/errors.md).
Scene parse_scene(std::string_view toml_text, const std::string& source_name = "<string>");
/// A scene from a parsed TOML document (what parse_scene and Scene::set use; include
/// <toml++/toml.h> to build one).
Scene scene_from_document(const toml::table& doc, const std::string& source_name = "<string>");
/// Load a scene file: a regular file of at most kMaxSceneBytes (InputError otherwise).
Scene load_scene(const std::filesystem::path& path);
/// The text of a scene file, with load_scene's checks (a regular file of at most
/// kMaxSceneBytes; InputError otherwise).
std::string read_scene_text(const std::filesystem::path& path);
/// A TOML document (include <toml++/toml.h> to read it): InputError "SOURCE:LINE:COLUMN: TOML
/// syntax: ..." for a syntax error, or for a character toml++ 3.3 cannot read safely
/// (check_toml_characters).
toml::table parse_toml_document(std::string_view toml_text, const std::string& source_name);
/// Refuses (InputError, naming line and column) a non-ASCII character outside strings and
/// comments, where TOML allows none, and one that follows a backslash in a multi-line basic
/// string: where toml++ 3.3 tests for Unicode whitespace, such a character is undefined
/// behaviour in its lexer (cxx/scenes/toml_text.cpp).
void check_toml_characters(std::string_view toml_text, const std::string& source_name);

}  // namespace nanopush
