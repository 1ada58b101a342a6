// The one table of material constants (issue 22 item 3): every chapter's code path reads a
// material from here, so graphite (and every material) has one Hamaker constant, one density,
// one modulus and one surface energy everywhere in nanopush. The thesis prints almost none of
// these numbers; each entry says where its numbers come from (docs/forces.md "Materials",
// docs/errata.md "One material, one set of constants").
//
// Conventions as in surface_forces.hpp: SI units, gamma per surface (W11 = 2 gamma).
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace nanopush::forces {

/// A material for bodies and substrates. NaN = not known.
struct Material {
  std::string name;
  double density = 0.0;          ///< [kg/m^3]
  double hamaker = 0.0;          ///< A11 in vacuum [J]
  double youngs_modulus = 0.0;   ///< E [Pa]; 0 = rigid (no contact deformation model)
  double poisson_ratio = 0.0;    ///< nu [-]
  double surface_energy = 0.0;   ///< gamma [J/m^2] (one surface; W11 = 2 gamma)
  std::string source;            ///< where the numbers come from
};
/// A liquid (environment medium or condensate). Its constants hold at
/// `reference_temperature` (the thesis works at 20 C).
struct Liquid {
  std::string name;
  double density = 0.0;          ///< [kg/m^3]
  double hamaker = 0.0;          ///< A33 [J]
  double surface_tension = 0.0;  ///< gamma_L [N/m]
  double molar_volume = 0.0;     ///< V [m^3/mol]
  double contact_angle = 0.0;    ///< theta on the solids of the scene [rad]
  std::string source;
  double reference_temperature = 293.15;  ///< [K] at which the constants above hold
};

/// Graphite's Hamaker constant [J]: the one value every code path uses (the thesis prints
/// none; docs/errata.md). Chapter 4-5 code (icor::Rod) and chapter 2-3 code (the material
/// table, the normal-load assembly) both read it; a test fails if they disagree.
inline constexpr double kGraphiteHamaker = 4.7e-19;
/// Graphite density [kg/m^3] (thesis: nanobar captions and chapter 4).
inline constexpr double kGraphiteDensity = 2267.0;
/// Body-substrate gap at contact z0 [m] (thesis: 0.2 nm, the interlayer spacing, section 4.2.3).
inline constexpr double kContactGap = 0.2e-9;

/// Built-in solids (graphite, silicon, silica, mica, gold).
const std::vector<Material>& solid_materials();
/// Built-in liquids (water, ethanol, n-hexadecane).
const std::vector<Liquid>& liquids();
std::optional<Material> find_material(std::string_view name);
std::optional<Liquid> find_liquid(std::string_view name);

/// Surface tension of water [N/m] at temperature T [K] (IAPWS 2014 release,
/// 235.8 mN/m (1 - T/Tc)^1.256 (1 - 0.625 (1 - T/Tc)), Tc = 647.096 K; valid 248-647 K).
double water_surface_tension(double T);
/// Molar volume of liquid water [m^3/mol] at 20 C (M = 18.01528 g/mol, rho = 998.21 kg/m^3).
inline constexpr double kWaterMolarVolume20C = 18.01528e-3 / 998.21;

}  // namespace nanopush::forces
