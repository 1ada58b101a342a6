// Numerical reference for the friction wrench (friction.hpp): adaptive Gauss-Kronrod
// cubature of the three contact integrals, for uniform or arbitrary pressure.
// The iCOR coordinates are break points of the subdivision, so the kink of the integrand
// (the direction of sliding turns through 180 degrees across the iCOR) is never inside a panel.
#pragma once

#include <functional>

#include "nanopush/friction.hpp"

namespace nanopush {

struct FrictionCubatureResult {
  FrictionWrench wrench;
  double error_force = 0.0;   ///< estimated absolute error of fx, fy [N]
  double error_moment = 0.0;  ///< estimated absolute error of mf [N m]
  long evaluations = 0;       ///< integrand evaluations
  bool converged = false;
};

/// Uniform pressure. The y' integral is done analytically (1-D antiderivatives of X/r, Y/r and
/// (x X + y Y)/r, not the 2-D corner form), the x' integral by adaptive GK15 with a break point
/// at the iCOR's x'. tol: absolute tolerance on f/muN and on mf/(muN max(a, b)).
/// Same arguments and conventions as rectangle_friction_wrench; inputs are checked (InputError).
FrictionCubatureResult cubature_friction_wrench_uniform(double a, double b, double muN, double R, double alpha,
                                                        int sense, double tol = 1e-13);

/// Arbitrary pressure p(x', y') >= 0 on the rectangle (body coordinates [m]; any scale: it is
/// normalised so that mu times its integral is muN). Fully numerical nested adaptive GK15 in
/// x' and y' with break points at the iCOR. tol as above.
FrictionCubatureResult cubature_friction_wrench(double a, double b, double muN, double R, double alpha, int sense,
                                                const std::function<double(double, double)>& pressure,
                                                double tol = 1e-13);

}  // namespace nanopush
