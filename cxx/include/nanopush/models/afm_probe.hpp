// AFM probe relations (thesis section 2.3.2.2, eqs 2.1-2.11, after Sitti's 1-D and 2-D
// force-sensing probes): rectangular cantilever spring constants and the motion modes of a
// pushed nanosphere (stick, slide, roll, spin). SI units; conventions of surface_forces.hpp.
#pragma once
#include <string>

namespace nanopush::afm {

/// Rectangular cantilever with a tip of height H at its free end.
struct Cantilever {
  double E = 0.0;          ///< Young's modulus [Pa]
  double nu = 0.33;        ///< Poisson ratio (thesis: ~0.33); G = E / (2 (1 + nu))
  double length = 0.0;     ///< l [m]
  double width = 0.0;      ///< w [m]
  double thickness = 0.0;  ///< t [m]
  double tip_height = 0.0; ///< H [m]
};

struct SpringConstants {
  double kz = 0.0;      ///< normal bending, E w t^3 / (4 l^3) [N/m] (eq 2.4)
  double kxz = 0.0;     ///< bending by the lateral-force moment, (2 Ls / 3) kz, Ls = l/H (2.5)
  double ktheta = 0.0;  ///< twisting by the lateral force, G w t^3 / (3 l H^2) [N/m] (2.6)
  double kby = 0.0;     ///< lateral bending, E t w^3 / (4 l^3) = (w/t)^2 kz [N/m] (2.7)
  double Ls = 0.0;      ///< structural constant l / H [-]
};
/// Eqs 2.4-2.7. Throws InputError for non-positive dimensions or E, nu outside (-1, 0.5].
SpringConstants spring_constants(const Cantilever& c);

/// 1-D sensing, eq 2.1: normal deflection [m] of a beam tilted by alpha [rad] under tip
/// forces Fz (normal) and Fx (lateral, along the beam):
///   dzeta = (Fz cos a - Fx sin a)/kz - (Fz sin a + Fx cos a)/kxz.
/// (The thesis prints "Fz sin a + Fx sin a" in the second numerator; the two numerators are
/// the components of the tip force in the tilted beam frame; see docs/errata.md.)
double deflection_1d(const SpringConstants& k, double Fz, double Fx, double alpha);
/// 2-D sensing, eq 2.2: dzeta = Fz cos a / kz - Fz sin a / kxz [m].
double deflection_2d_normal(const SpringConstants& k, double Fz, double alpha);
/// 2-D sensing, eq 2.3: twist dtheta = S_theta Fy / ktheta, S_theta the sensor coefficient.
double twist_2d(const SpringConstants& k, double Fy, double S_theta);

/// Inputs of the nanosphere motion-mode rules (text after eq 2.10 and eq 2.11).
struct SphereContact {
  double f1 = 0.0;         ///< friction/push at the particle-substrate contact, = Fy [N]
  double f2 = 0.0;         ///< friction at the tip-particle contact [N]
  double R = 0.0;          ///< particle radius [m]
  double Fz = 0.0;         ///< normal load [N]
  double x0 = 0.0;         ///< lateral offset of the push from the centre [m]
  double a = 0.0;          ///< particle-substrate contact radius [m] (A = pi a^2)
  double a2 = 0.0;         ///< tip-particle contact radius [m] (A2 = pi a2^2)
  double tau_s = 0.0;      ///< shear strength particle-substrate [Pa]
  double tau_s2 = 0.0;     ///< shear strength tip-particle [Pa]
  double tau_psi = 0.0;    ///< rolling resistance stress [N/m]
  double tau_theta = 0.0;  ///< rotational (spin) friction coefficient [N/m]
};
struct SphereModes {
  bool stick = false, slide = false, roll = false, spin = false;
  [[nodiscard]] std::string text() const;  ///< e.g. "slide+spin"
};
/// Stick: f1 < tau_s A and f2 < tau_s2 A2. Slide: f1 >= tau_s A and f2 < tau_s2 A2.
/// Roll: (f1 - f2) R >= tau_psi A and f2 >= tau_s2 A2 (eq 2.11). Spin: Fz x0 >= tau_theta A.
SphereModes sphere_modes(const SphereContact& c);

}  // namespace nanopush::afm
