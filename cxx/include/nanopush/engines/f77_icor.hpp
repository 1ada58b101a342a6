// C++ view of the FORTRAN 77 iCOR solvers (the bridge's f77_icor.h; engines layer): status
// codes become exceptions (InputError for bad input, SolverError for numerical failures) and results the same
// CubicSolution the C++ solvers return, so drivers and tests compare like with like.
#pragma once
#include <stdexcept>
#include <string>

#include "f77_icor.h"
#include "nanopush/numerics/error.hpp"
#include "nanopush/numerics/names.hpp"
#include "nanopush/models/icor.hpp"

namespace nanopush::f77 {

enum class IcorCubicMethod { Brent, Lapack };

inline std::string icor_status_message(int status) {
  switch (status) {
    case NP_F77_ICOR_OK: return "ok";
    case NP_F77_ICOR_BAD_INPUT: return "bad input (yn < 0, L <= 0, k2 <= 0, mu <= 0, W <= 0 or non-finite)";
    case NP_F77_ICOR_LAPACK_FAILED: return "LAPACK DGEEV failed (INFO != 0)";
    case NP_F77_ICOR_BRENT_FAILED: return "Brent did not converge";
    case NP_F77_ICOR_BELOW_FMIN: return "push force below the minimum force of eq 4.8";
    case NP_F77_ICOR_WORKSPACE: return "LAPACK workspace too small";
    case NP_F77_ICOR_INDETERMINATE: return "eq 5.2 is 0/0";
    default: return "unknown status " + std::to_string(status);
  }
}

inline void icor_check(int status, const std::string& what) {
  if (status == NP_F77_ICOR_OK) return;
  if (status == NP_F77_ICOR_BAD_INPUT || status == NP_F77_ICOR_BELOW_FMIN)
    throw InputError("F77 " + what + ": " + icor_status_message(status));
  throw SolverError("F77 " + what + ": " + icor_status_message(status));
}

/// Roots of the constrained cubic (5.4) from the FORTRAN 77 code.
inline icor::CubicSolution icor_cubic(double yn, double L, double k2, IcorCubicMethod method) {
  double roots[3] = {0, 0, 0}, resmax = 0;
  int nreal = 0, ncplx = 0, ninf = 0, niter = 0;
  const int st = method == IcorCubicMethod::Lapack
                     ? np_f77_icor_cubic_lapack(yn, L, k2, roots, &nreal, &ncplx, &ninf, &resmax)
                     : np_f77_icor_cubic_brent(yn, L, k2, roots, &nreal, &ncplx, &ninf, &resmax, &niter);
  icor_check(st, method == IcorCubicMethod::Lapack ? "cubic (LAPACK)" : "cubic (Brent)");
  icor::CubicSolution s;
  s.yn = yn;
  s.complex_roots = ncplx;
  s.at_infinity = ninf;
  s.max_residual = resmax;
  for (int i = 0; i < nreal; ++i) s.real_roots.push_back(roots[i]);
  for (double R : s.real_roots) {
    if (R < 0.0) s.negative = R;
    if (R > 0.0 && !s.positive) s.positive = R;
  }
  return s;
}

/// iCOR distance [m] from eq 4.1, 4.2, 4.3, 4.13 or 5.5 (NP_F77_ICOR_EQ_*).
inline double icor_formula(int which, double yn, double L, double k2 = 1.0) {
  double R = 0.0;
  icor_check(np_f77_icor_formula(which, yn, L, k2, &R), "formula " + std::to_string(which));
  return R;
}

/// Force relations 407 (R of 4.7, x = F), 408, 410, 411, 502 (see f77_icor.h).
inline double icor_force(int which, double mu, double W, double yn, double L, double k2, double x) {
  double out = 0.0;
  icor_check(np_f77_icor_force(which, mu, W, yn, L, k2, x, &out), "force relation " + std::to_string(which));
  return out;
}

}  // namespace nanopush::f77

namespace nanopush {

/// The four solvers of the constrained cubic (5.4): the C++ ones (Brent's method, the
/// companion matrix's eigenvalues) and the thesis' FORTRAN 77 routines (Brent, LAPACK DGEEV).
enum class CubicSolver { brent, eigen, brent_f77, lapack_f77 };
NANOPUSH_NAMES(CubicSolver, {CubicSolver::brent, "brent"}, {CubicSolver::eigen, "eigen"},
               {CubicSolver::brent_f77, "brent_f77"}, {CubicSolver::lapack_f77, "lapack_f77"});

/// The roots of the constrained cubic (5.4) by one of the four solvers.
inline icor::CubicSolution solve_cubic(double yn, double L, double k2, CubicSolver solver) {
  switch (solver) {
    case CubicSolver::brent: return icor::solve_constrained_cubic(yn, L, k2, icor::CubicMethod::Brent);
    case CubicSolver::eigen: return icor::solve_constrained_cubic(yn, L, k2, icor::CubicMethod::Eigen);
    case CubicSolver::brent_f77: return f77::icor_cubic(yn, L, k2, f77::IcorCubicMethod::Brent);
    case CubicSolver::lapack_f77: return f77::icor_cubic(yn, L, k2, f77::IcorCubicMethod::Lapack);
  }
  throw std::logic_error("solve_cubic: not a CubicSolver");
}

}  // namespace nanopush

