// Scene environment and bodies, and the assembly of the normal load from only the force
// models a scene needs (issue 6; docs/models.md section F "model only what a scene requires").
// Their scene-file tables are read by nanopush/scenes/environment_toml.hpp (docs/forces.md).
//
// Conventions (surface_forces.hpp): SI, gamma per surface, W = 2 gamma for like materials,
// attractive forces positive (they add to the normal load).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "nanopush/models/surface_forces.hpp"
#include "nanopush/numerics/names.hpp"

namespace nanopush {

enum class Medium { vacuum, humid_air, liquid };
NANOPUSH_NAMES(Medium, {Medium::vacuum, "vacuum"}, {Medium::humid_air, "humid_air"}, {Medium::liquid, "liquid"});
inline std::string_view medium_name(Medium m) { return name_of(m); }

struct Environment {
  Medium medium = Medium::vacuum;
  double humidity = 0.0;        ///< relative humidity p/p_sat in [0, 1] (humid_air)
  double temperature = 293.15;  ///< [K] (Kelvin radius)
  /// The liquid: the medium itself (liquid) or the condensate (humid_air; water by default).
  forces::Liquid liquid = *forces::find_liquid("water");
  bool adhesion = true;  ///< false: ideal non-adhesive contact, no adhesion model is evaluated
  double gap = forces::kContactGap;  ///< body-substrate separation at contact z0 [m] (thesis: 0.2 nm)
  double gravity = forces::kGravity;  ///< [m/s^2]
  bool has_substrate = false;         ///< false: the substrate is the body's own material
  forces::Material substrate;
};

enum class Shape { bar, rod, tube, sphere };
NANOPUSH_NAMES(Shape, {Shape::bar, "bar"}, {Shape::rod, "rod"}, {Shape::tube, "tube"}, {Shape::sphere, "sphere"});
inline std::string_view shape_name(Shape s) { return name_of(s); }

struct Body {
  std::string name = "body";
  Shape shape = Shape::rod;
  double length = 0.0;        ///< bar, rod, tube [m]
  double width = 0.0;         ///< bar footprint width [m]
  double height = 0.0;        ///< bar height [m]
  double radius = 0.0;        ///< rod, tube (outer), sphere [m]
  double inner_radius = 0.0;  ///< tube [m], 0 <= inner < radius
  /// Material constants; surface_energy NaN = derive from the Hamaker constant (eq 3.9),
  /// youngs_modulus 0 = rigid (no contact deformation model).
  forces::Material material;
  [[nodiscard]] double volume() const;  ///< [m^3]
  [[nodiscard]] double mass() const;    ///< [kg]
};

struct LoadOptions {
  /// Relative tolerance of the integration the load feeds (the solver's rtol).
  double rtol = 1e-10;
  /// A term is dropped when |term| < drop_fraction * rtol * |N| AND omitting it changes N
  /// and the sliding load by less than that too (the contact model can amplify a change of
  /// the external load): the friction forces, and so the trajectory, then change by less
  /// than drop_fraction * rtol relative.
  double drop_fraction = 0.1;
  bool drop_negligible = true;
};

enum class TermStatus { evaluated, dropped, not_needed };
NANOPUSH_NAMES(TermStatus, {TermStatus::evaluated, "evaluated"}, {TermStatus::dropped, "dropped"},
               {TermStatus::not_needed, "not needed"});
inline std::string_view term_status_name(TermStatus s) { return name_of(s); }

struct LoadTerm {
  std::string name;   ///< gravity, buoyancy, van_der_waals, capillary, contact_adhesion
  std::string model;  ///< model and equation used
  double value = 0.0; ///< [N], attractive / downward positive; NaN when not evaluated
  double share = 0.0; ///< value / N (NaN when not evaluated)
  TermStatus status = TermStatus::not_needed;
  std::string note;   ///< why not needed / why dropped
};

struct LoadReport {
  double normal_load = 0.0;         ///< N = sum of the kept terms [N]
  double sliding_load = 0.0;        ///< kept terms without contact adhesion (eq 3.20 form) [N]
  double contact_half_width = 0.0;  ///< [m]: JKR/Hertz radius or line half-width; bar: width/2
  std::string contact_model;
  double work_of_adhesion = 0.0;    ///< W used by the contact model [J/m^2] (NaN if none)
  double hamaker = 0.0;             ///< body-substrate(-medium) Hamaker constant [J] (NaN if none)
  double drop_threshold = 0.0;      ///< |term| below this was dropped [N]
  std::vector<LoadTerm> terms;
  [[nodiscard]] const LoadTerm& term(std::string_view name) const;
  /// Human-readable term report (one line per term, with shares of N).
  [[nodiscard]] std::string to_text() const;
};

/// Assemble the normal load and contact half-width of `body` resting on the substrate in
/// `env`, evaluating only the models the scene needs:
/// - gravity always; buoyancy only in a liquid;
/// - van der Waals, contact adhesion and capillary only when env.adhesion is true (and
///   capillary only in humid air with humidity > 0);
/// - a contact model (JKR when adhesive, Hertz otherwise) only when the materials are
///   elastic (Young's modulus > 0); bars use their geometric half-width.
/// Terms below LoadOptions' threshold are evaluated, reported and dropped.
LoadReport assemble_normal_load(const Environment& env, const Body& body, const LoadOptions& opt = {});

}  // namespace nanopush
