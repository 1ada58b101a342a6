// Rolling of nanotubes (docs/models.md section E; thesis section 3.2-3.3, eqs 3.10-3.21,
// Figs 3.3-3.4). A rigid cylinder of radius r (I_cm = m r^2 / 2) pushed by a force F
// parallel to the plane at height h above its axis (h in [-r, r]).
//
// Forces follow surface_forces.hpp: SI, attractive magnitudes positive, W = 2 gamma.
// The FORTRAN 77 versions of these formulas live in fortran/rolling.f (bridge:
// fortran/bridge/f77_rolling.h); tests/test_forces_rolling.cpp compares the two.
#pragma once
#include <string>
#include <string_view>

namespace nanopush::rolling {

/// Static friction needed for pure rolling, eq 3.16: fs = (F/3)(1 - 2h/r) [N].
/// fs = 0 at h = r/2, -F/3 at h = r, F/3 at h = 0. Requires r > 0, |h| <= r.
double static_friction(double F, double h, double r);

/// Rolling resistance (thesis section 3.3.1): fs = W k / r [N], with W [N] the total load
/// m g + F_vdw + F_adhesion and k [m] the contact half-width (the lever arm of the load).
double rolling_resistance(double W_load, double k, double r);

/// Minimum push that rolls the tube: F = (1 + margin) W k / r; the thesis takes
/// F ~ fs + 1% fs (margin = 0.01).
double minimum_rolling_force(double W_load, double k, double r, double margin = 0.01);

/// Kinetic (Coulomb) sliding threshold mu N, eq 3.19, with N = m g + F_vdw (3.20) [N].
double sliding_threshold(double mu, double N);

enum class Motion { stuck, rolling, rolling_with_slip, sliding };
std::string_view motion_name(Motion m);

/// A push on a tube lying on a plane.
struct Push {
  double F = 0.0;        ///< push magnitude [N], >= 0
  double h = 0.0;        ///< push height above the axis [m], |h| <= r
  double r = 0.0;        ///< tube radius [m]
  double mu = 0.0;       ///< friction coefficient (static = kinetic, as in the thesis)
  double N_slide = 0.0;  ///< sliding normal load m g + F_vdw (eq 3.20) [N]
  double W_roll = 0.0;   ///< rolling load m g + F_vdw + F_adhesion (section 3.3.1) [N]
  double k = 0.0;        ///< contact half-width [m]
};

struct Decision {
  Motion motion = Motion::stuck;
  double F_roll = 0.0;        ///< rolling threshold W k / r [N]
  double F_slide = 0.0;       ///< sliding threshold mu N [N]
  double fs_required = 0.0;   ///< static friction pure rolling needs, eq 3.16 [N]
  double fs_available = 0.0;  ///< mu N_slide [N]
};

/// Rolling versus sliding (docs/models.md E: "decide from which threshold is lower"):
/// - F below both thresholds: stuck;
/// - rolling threshold lower (or equal) and F >= F_roll: rolling if the static friction
///   eq 3.16 asks for is available (|fs| <= mu N), else rolling_with_slip;
/// - sliding threshold lower and F >= F_slide: sliding.
Decision decide(const Push& p);

}  // namespace nanopush::rolling
