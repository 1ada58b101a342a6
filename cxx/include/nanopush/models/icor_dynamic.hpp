// The dynamic iCOR (issue 5 item 3, thesis section 5.5, Fig 5.3) and the quasi-static iCOR of
// a finite rectangle (issue 5 item 4, beyond the thesis), docs/models.md section D.
//
// Geometry shared by both (thesis Fig 4.1 in the frame of docs/models.md section 0): the rod's
// contact is a thin rectangle 2a x 2b, body x' across the width (half-width a), body y' along
// the rod (half-length b = L/2). The push is along world +X (the rod starts at theta = 0, so
// the push is perpendicular to it) and is applied at the body point (0, yn), yn >= 0: the rod
// turns clockwise about an iCOR on the far side of the CM (body y' < 0). Distances along the
// rod are reported with the sign of chapter 4: R_axial > 0 on the far side.
//
// Dynamic iCOR: the rough-surface model (docs/models.md C) for the nanorod under the `coulomb`
// law (stick_slip.hpp: a push inside the limit surface leaves the rod stuck), integrated from
// rest; the iCOR is read off the velocities (icor_from_velocity) at the requested times.
// Limits (docs/icor.md): as F/(mu W) -> infinity at a fixed impulse F t the iCOR tends to the
// impulsive one k^2/yn (5.5); as F falls to the rectangle's minimum force it tends to the
// rectangle's quasi-static iCOR (-> eq 4.13 as a/b -> 0).
#pragma once
#include <string>
#include <vector>

#include "nanopush/models/icor.hpp"
#include "nanopush/numerics/names.hpp"

namespace nanopush::icor {

/// Half-width of the rod's contact strip [m]: the Hertz line contact of a graphite cylinder
/// (radius r) on a graphite plane (E = 36.5 GPa, nu = 0.20, the built-in material table)
/// under the load per length W/L, W = m g + F_vdw (the Parsegian attraction acts as the
/// load, DMT-style; a JKR line contact would count the adhesion twice). 2.78 nm for the
/// nanorod (a/b = 0.0094).
double rod_contact_half_width(const Rod& rod);

/// Quasi-static iCOR of a 2a x 2b rectangle with uniform pressure pushed along body +x' at
/// (0, yn): the closed-form friction wrench (friction.hpp) in quasi_static_icor. R is the
/// distance CM -> iCOR, alpha its direction (c = -R (cos alpha, sin alpha)), force the
/// minimum push |F|/(mu W). yn = 0 is pure translation: R = +inf, force = 1, converged.
/// a, b > 0 with a/b >= 1e-6; 0 <= yn <= b (the push line crosses the rectangle).
QuasiStaticIcor rectangle_quasi_static(double a, double b, double yn);

enum class DynamicIntegrator { automatic, bulirsch_stoer, cvode };
std::string to_string(DynamicIntegrator i);  // its name (the name table below)
/// The integrator named `text` (automatic, bulirsch-stoer or bulirsch_stoer, cvode), or
/// InputError naming `field`.
DynamicIntegrator parse_dynamic_integrator(const std::string& field, const std::string& text);

/// One reading of the dynamic iCOR.
struct DynamicIcorSample {
  double t = 0.0;           ///< [s]
  bool moving = false;      ///< false: at rest (stuck), no iCOR
  bool translation = false; ///< omega = 0 exactly: R = +inf
  double R = 0.0;           ///< |c| [m] (+inf for translation; 0 when not moving)
  double axial = 0.0;       ///< iCOR along the rod, body -y' (> 0: far side from the push) [m]
  double offset = 0.0;      ///< iCOR across the rod, body x' [m]
  double theta = 0.0;       ///< rod orientation [rad]
  double vx = 0.0, vy = 0.0, omega = 0.0;  ///< world velocities [m/s, rad/s]
};

struct DynamicIcorSetup {
  Rod rod = nanorod();
  double mu = 0.1;          ///< friction coefficient [-]
  double half_width = 0.0;  ///< contact half-width a [m]; 0 = rod_contact_half_width(rod)
  double yn = 0.0;          ///< push point from the CM along the rod [m], 0 <= yn <= b
  double force = 0.0;       ///< push magnitude [N] (> 0)
  std::vector<double> times = {1e-10};  ///< output times [s], ascending, > 0
  double rtol = 1e-10;      ///< relative tolerance of the integrator
  /// Integrator of the coulomb law (both event-located stick-slip, stick_slip.hpp):
  /// automatic (the default), the C++ Bulirsch-Stoer engine (integrate_coulomb) or CVODE
  /// (BDF, implicit: integrate_coulomb_cvode). Close to the minimum force the velocity
  /// direction relaxes to its self-similar value at a rate ~ 1/((F/F_min - 1) t): stiff from
  /// t = 0, where the explicit engine's first step after rest fails; far from it the thin
  /// strip (a << b) makes the wrench vary on the scale a as the iCOR drifts across the rod,
  /// where BDF's error test can fail. `automatic` uses CVODE for F < 1.09 F_min (rectangle)
  /// and Bulirsch-Stoer otherwise, and falls back to the other on a SolverError.
  DynamicIntegrator integrator = DynamicIntegrator::automatic;
};

struct DynamicIcorRun {
  bool stuck = false;      ///< the push never started the rod (inside the limit surface)
  double load = 0.0;       ///< W [N]
  double half_width = 0.0; ///< a used [m]
  std::vector<DynamicIcorSample> samples;
  long long rhs_evaluations = 0;
  DynamicIntegrator integrator = DynamicIntegrator::bulirsch_stoer;  ///< the one that produced the run
  double minimum_force = 0.0;  ///< F_min of the rectangle (rectangle_quasi_static) [N]
};

/// Integrate the rough-surface nanorod from rest under the coulomb law and read the iCOR at
/// each output time. Throws InputError on bad input, SolverError if the integrator fails.
DynamicIcorRun dynamic_icor(const DynamicIcorSetup& setup);

}  // namespace nanopush::icor

namespace nanopush {
NANOPUSH_NAMES(icor::DynamicIntegrator, {icor::DynamicIntegrator::automatic, "automatic"},
               {icor::DynamicIntegrator::bulirsch_stoer, "bulirsch-stoer"},
               {icor::DynamicIntegrator::cvode, "cvode"});
}  // namespace nanopush
