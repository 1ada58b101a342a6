/* nanopush: C view of the FORTRAN 77 iCOR routines (fortran/icor.f, fortran/brent.f)
 * through the bind(C) shim fortran/bridge/f77_icor.f90. Every name starts with np_f77_icor_.
 * All quantities SI. Each function returns a status (below); none stops the program.
 * Infinite results (eq 5.5 at yn = 0, the pole of eq 5.2) are IEEE infinities with
 * status 0; no function returns NaN for finite input. */
#ifndef NANOPUSH_F77_ICOR_H
#define NANOPUSH_F77_ICOR_H

#ifdef __cplusplus
extern "C" {
#endif

/* Status codes (IERR of fortran/icor.f). */
enum {
  NP_F77_ICOR_OK = 0,
  NP_F77_ICOR_BAD_INPUT = 1,      /* yn < 0, L <= 0, k2 <= 0, mu <= 0, W <= 0, non-finite... */
  NP_F77_ICOR_LAPACK_FAILED = 2,  /* DGEEV returned INFO != 0 */
  NP_F77_ICOR_BRENT_FAILED = 3,   /* Brent did not converge */
  NP_F77_ICOR_BELOW_FMIN = 4,     /* eq 4.7: F below the minimum force of eq 4.8 */
  NP_F77_ICOR_WORKSPACE = 5,      /* DGEEV asked for more workspace than provided */
  NP_F77_ICOR_INDETERMINATE = 6   /* eq 5.2 evaluated 0/0 */
};

/* Formula selectors for np_f77_icor_formula. */
enum {
  NP_F77_ICOR_EQ_4_1 = 1,   /* experimental fit, R = b - rho */
  NP_F77_ICOR_EQ_4_2 = 2,   /* Falvo et al., mapped to R */
  NP_F77_ICOR_EQ_4_3 = 3,   /* Li et al., mapped to R */
  NP_F77_ICOR_EQ_4_13 = 13, /* unknown pressure */
  NP_F77_ICOR_EQ_5_5 = 55   /* impulsive, R = k2 / yn */
};

/* iCOR distance R [m] (> 0 on the far side of the CM from the push).
 * yn [m] push distance from the CM, L [m] rod length, k2 = I/m [m^2] (5.5 only). */
int np_f77_icor_formula(int which, double yn, double L, double k2, double* R);

/* Force relations. which = 407: out = R [m] of eq 4.7 with x = F [N];
 * 408: out = minimum force [N] of eq 4.8 (x unused); 410: out = F [N] of eq 4.10, x = R [m];
 * 411: out = F [N] of eq 4.11, x = R [m]; 502: out = F [N] of eq 5.2, x = R [m] (uses k2).
 * mu [-], W = m g + F_vdw [N], yn [m], L [m], k2 [m^2]. */
int np_f77_icor_force(int which, double mu, double W, double yn, double L, double k2, double x,
                      double* out);

/* Constrained cubic (5.4), 2 yn R^3 - 3 k2 R^2 + k2 (b^2 - 2 k2) = 0 with b = L/2.
 * roots[3]: the *nreal real roots ascending [m]; *ncplx non-real roots; *ninf roots at
 * infinity (yn -> 0); *resmax = max |p(r)| / sum |c_i r^i| over the real roots (r = R/b).
 * _lapack: companion matrix eigenvalues by LAPACK DGEEV (called from FORTRAN 77).
 * _brent: van Wijngaarden-Dekker-Brent on automatic brackets; *niter Brent iterations. */
int np_f77_icor_cubic_lapack(double yn, double L, double k2, double* roots, int* nreal, int* ncplx,
                             int* ninf, double* resmax);
int np_f77_icor_cubic_brent(double yn, double L, double k2, double* roots, int* nreal, int* ncplx,
                            int* ninf, double* resmax, int* niter);

#ifdef __cplusplus
}
#endif
#endif
