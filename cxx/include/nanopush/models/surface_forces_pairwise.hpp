// Thesis chapter 2-3 content that feeds a normal load, an adhesion or a contact and that
// surface_forces.hpp did not have (issue 22 item 6): the pair potential behind the Hamaker
// constant (eq 2.12), the exact sphere-flat van der Waals interaction (eq 2.18 for n = 6, with
// its limits 2.21-2.23), contact energies of molecular-scale bodies (2.27-2.30), effective
// surface energies from the pair energy (2.42-2.44, 3.7), the lattice energy (3.2) and the
// work of adhesion at a gap (3.3-3.5); and Tables 2.2-2.3 (surface energies of metals).
// What is not implemented, and why, is listed in docs/forces.md.
//
// Conventions as in surface_forces.hpp: SI, *_force returns an attractive magnitude,
// energies are signed (negative = bound), C is the London coefficient of w(r) = -C/r^6 [J m^6],
// rho a number density [1/m^3], sigma a molecular (atomic) diameter [m].
#pragma once
#include <string>
#include <vector>

namespace nanopush::forces {

inline constexpr double kBoltzmann = 1.380649e-23;        ///< [J/K]
inline constexpr double kElectronVolt = 1.602176634e-19;  ///< [J]
inline constexpr double kAvogadro = 6.02214076e23;        ///< N0 [1/mol]

/// London dispersion coefficient (eq 2.12): C = (3/4) alpha'^2 I, with alpha' = alpha0/(4 pi eps0)
/// the polarisability volume [m^3] and I = h nu the first ionisation energy [J]. Returns C [J m^6].
double london_coefficient(double polarisability_volume, double ionisation_energy);
/// Hamaker constant from the pair potential (the definition under eq 3.1): A = pi^2 C rho1 rho2 [J].
double hamaker_from_london(double C, double rho1, double rho2);
/// Number density of a close-packed solid of molecules of diameter sigma: sqrt(2)/sigma^3 [1/m^3]
/// (the value the thesis uses for eqs 2.27-2.30).
double close_packed_density(double sigma);

/// Exact van der Waals energy of a sphere (radius R) and a flat half-space at gap D, by pairwise
/// summation (eq 2.18 with n = 6): w = -(A/6) [R/D + R/(D+2R) + ln(D/(D+2R))] [J].
/// Reduces to -A R/(6D) (2.21) for D << R and to -(2/9) A R^3/D^3 (2.23) for D >> R.
double sphere_flat_vdw_energy_exact(double A, double R, double D);
/// Its force -dw/dD as an attractive magnitude: 2 A R^3 / (3 D^2 (D+2R)^2) [N]
/// (-> A R/(6 D^2), eq 2.22, for D << R; -> 2 A R^3/(3 D^4) for D >> R).
double sphere_flat_vdw_force_exact(double A, double R, double D);

/// Contact energies of molecular-scale bodies at D = sigma with rho = sqrt(2)/sigma^3 [J]:
/// a molecule and a flat surface -sqrt(2) pi C/(6 sigma^6) = -0.74 C/sigma^6 (eq 2.27);
double molecule_surface_contact_energy(double C, double sigma);
/// a sphere of radius R >= sigma/2 and a flat surface -pi^2 C R/(3 sigma^7) = -1.6 (2R/sigma) C/sigma^6
/// (eq 2.30; eq 2.28 at R = sigma/2);
double sphere_surface_contact_energy(double C, double sigma, double R);
/// two spheres of atomic size (R = sigma/2): half of eq 2.28, -0.8 C/sigma^6 (eq 2.29).
double atomic_spheres_contact_energy(double C, double sigma);

/// Effective surface energy [J/m^2] from the pair energy w > 0 of two molecules in contact (eqs
/// 2.42-2.44): planar close-packed surface sqrt(3) w/sigma^2 (2.42), isolated molecule
/// 12 w / (2 * 4 pi (sigma/2)^2) = 1.9 w/sigma^2 (2.43), 13-molecule cluster
/// 12*7 w / (2 * 4 pi (3 sigma/2)^2) = 1.5 w/sigma^2 (2.44).
enum class MolecularSurface { planar, isolated_molecule, cluster_of_13 };
double effective_surface_energy(double w, double sigma, MolecularSurface kind);
/// Surface energy of a close-packed solid from its Hamaker constant (eq 3.7):
/// gamma = sqrt(3) A / (2 pi^2 sigma^2) [J/m^2].
double surface_energy_molecular(double A, double sigma);
/// Molar lattice (cohesive) energy of a van der Waals solid (eq 3.2): U = 7.22 N0 C / sigma^6 with
/// C of eq 2.12 [J/mol].
double lattice_energy(double C, double sigma);
/// Work to separate two flat surfaces from contact (D0) to a gap D >= D0, per area (eqs 3.3-3.4):
/// A/(12 pi) (1/D0^2 - 1/D^2) = W (1 - D0^2/D^2) with W = A/(12 pi D0^2) = 2 gamma (eq 3.5)
/// [J/m^2]. The adhesion a flat contact loses when its gap opens from D0 to D.
double work_of_adhesion_at_gap(double A, double D0, double D);

/// One row of the thesis' Table 2.2 (surface energies of metals and others, after ref [59]).
struct Table22Row {
  std::string material, kind;  ///< kind: metal, semiconductor, weak conductor
  double boiling_point;        ///< T_B [K] at 760 mm Hg
  double melting_point;        ///< T_M [K]
  double gamma_above_melting;  ///< [J/m^2], just above T_M
  double gamma_below_melting;  ///< [J/m^2], just below T_M (approximate; "~" for silicon)
  double gamma_300K;           ///< [J/m^2] at 300 K
};
const std::vector<Table22Row>& thesis_table_2_2();
/// One row of Table 2.3 (metal-metal interfaces, after ref [62]); NaN where not printed.
struct Table23Row {
  std::string interface, kind;  ///< kind: similar, dissimilar
  double commensurate;          ///< [J/m^2], lattices in register
  double incommensurate;        ///< [J/m^2], lattices out of register (NaN: not printed)
  std::string note;
};
const std::vector<Table23Row>& thesis_table_2_3();

}  // namespace nanopush::forces
