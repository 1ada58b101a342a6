// Numerical reference for the friction wrench (friction.hpp): adaptive Gauss-Kronrod
// cubature of the three contact integrals, for uniform or arbitrary pressure.
// The iCOR coordinates are break points of the subdivision, so the kink of the integrand
// (the direction of sliding turns through 180 degrees across the iCOR) is never inside a panel.
#pragma once

#include <functional>

#include "nanopush/models/friction.hpp"

namespace nanopush {

struct FrictionCubatureResult {
  FrictionWrench wrench;
  double error_force = 0.0;   ///< estimated absolute error of fx, fy [N]
  double error_moment = 0.0;  ///< estimated absolute error of mf [N m]
  long evaluations = 0;       ///< integrand evaluations
  bool converged = false;
};

/// Uniform pressure: nested adaptive GK15 in x' and y' over the half rectangle x' >= 0 of the
/// point-symmetrised integrands (the contributions of (x', y') and (-x', -y') are summed
/// pointwise, which removes the O(R) odd part of the moment integrand without cancellation, so
/// the reference stays accurate for a distant iCOR). Break points at the iCOR and its mirror.
/// tol: absolute tolerance on f/muN and on mf/(muN max(a, b)).
/// Same arguments and conventions as rectangle_friction_wrench; inputs are checked (InputError).
FrictionCubatureResult cubature_friction_wrench_uniform(double a, double b, double muN, double R, double alpha,
                                                        int sense, double tol = 1e-13);

/// Arbitrary pressure p(x', y') >= 0 on the rectangle (body coordinates [m]; any scale: it is
/// normalised so that mu times its integral is muN). Fully numerical nested adaptive GK15 in
/// x' and y' (same symmetrised scheme, with p(x', y') and p(-x', -y')). tol as above.
FrictionCubatureResult cubature_friction_wrench(double a, double b, double muN, double R, double alpha, int sense,
                                                const std::function<double(double, double)>& pressure,
                                                double tol = 1e-13);

}  // namespace nanopush
