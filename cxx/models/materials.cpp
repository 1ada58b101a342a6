// The one table of material constants (materials.hpp).
#include "nanopush/models/materials.hpp"

#include <cmath>

#include "nanopush/models/surface_forces.hpp"
#include "nanopush/numerics/error.hpp"

namespace nanopush::forces {

double water_surface_tension(double T) {
  require_finite("temperature", T);
  constexpr double Tc = 647.096;  // K, critical temperature of water (IAPWS)
  if (!(T >= 248.15 && T < Tc))
    throw InputError("temperature", fmt(T), "must be in [248.15, 647.096) K for the IAPWS surface tension of water");
  const double tau = 1.0 - T / Tc;
  return 235.8e-3 * std::pow(tau, 1.256) * (1.0 - 0.625 * tau);
}

const std::vector<Material>& solid_materials() {
  // The thesis prints no material constants for its bodies except the graphite density
  // (2267 kg/m^3, nanobar captions). Other numbers are representative handbook values,
  // recorded with their source; override them in the scene for quantitative work.
  static const std::vector<Material> m = {
      {"graphite", kGraphiteDensity, kGraphiteHamaker, 36.5e9, 0.20, kGraphiteHamaker / kThesisHamakerPerGamma,
       "density: thesis captions; A: 4.7e-19 J, Lifshitz-order value for graphite (assumed: the thesis prints "
       "none; one value for every chapter, docs/errata.md); E: c-axis modulus C33 of graphite; gamma: thesis "
       "eq 3.9 from A"},
      {"silicon", 2329.0, 1.865e-19, 169e9, 0.28, 1.865e-19 / kThesisHamakerPerGamma,
       "handbook values (assumed); gamma from eq 3.9"},
      {"silica", 2200.0, 6.5e-20, 73e9, 0.17, 6.5e-20 / kThesisHamakerPerGamma,
       "fused silica, Israelachvili Table 13.2 order of magnitude (assumed); gamma from eq 3.9"},
      {"mica", 2830.0, 10.0e-20, 34.5e9, 0.25, 10.0e-20 / kThesisHamakerPerGamma,
       "muscovite, Israelachvili Table 13.2 order of magnitude (assumed); gamma from eq 3.9"},
      {"gold", 19300.0, 45.0e-20, 79e9, 0.42, 1.5,
       "Israelachvili: metals A ~ 25-40e-20 J (assumed 45e-20); gamma from Table 2.2 order (1.5 J/m^2)"},
  };
  return m;
}

const std::vector<Liquid>& liquids() {
  // Constants at 20 C, the temperature the thesis works at (section 2.5.8: r_k = 0.54 nm).
  static const std::vector<Liquid> l = {
      {"water", 998.21, 3.7e-20, water_surface_tension(293.15), kWaterMolarVolume20C, 0.0,
       "A: thesis Table 3.1; gamma_L: IAPWS 2014 at 20 C (0.07274 N/m); V = M/rho at 20 C", 293.15},
      {"ethanol", 789.0, 4.2e-20, 0.0228, 58.4e-6, 0.0, "A: thesis Table 3.1; gamma: Table 3.1 experimental", 293.15},
      {"n-hexadecane", 770.0, 5.2e-20, 0.0275, 292.9e-6, 0.0, "A: thesis Table 3.1; gamma: Table 3.1 experimental",
       293.15},
  };
  return l;
}

std::optional<Material> find_material(std::string_view name) {
  for (const auto& m : solid_materials())
    if (m.name == name) return m;
  return std::nullopt;
}
std::optional<Liquid> find_liquid(std::string_view name) {
  for (const auto& l : liquids())
    if (l.name == name) return l;
  return std::nullopt;
}

}  // namespace nanopush::forces
