/* nanopush: C view of the FORTRAN 77 Bulirsch-Stoer integrator (fortran/bsint.f) through the
 * bind(C) shim fortran/bridge/f77_bsint.f90. Algorithm: docs/bulirsch_stoer.md.
 *
 * Units: whatever the right-hand side uses (SI throughout nanopush): t in s, y in the state's
 * units, tolerances in the units of each component. Arrays are contiguous doubles, shapes
 * beside each argument; yout is column-major: yout[i + n*k] is component i at tout[k].
 *
 * Status (return value):
 *   0  success
 *   1  bad input: n < 1 or n > 64; nout < 1; kmax not 0 and outside 3..12; iextr not 1 or 2;
 *      maxstp < 0; rtol < 0 or not finite; atol[i] < 0 or not finite; rtol = 0 with
 *      atol[i] = 0; h0 < 0, hmax < 0 or not finite; t0 or tout not finite; tout[0] < t0 or
 *      tout decreasing; y0 not finite; (smooth bar) n != 6
 *   2  more than maxstp attempted steps
 *   3  step size underflow
 *   4  the right-hand side returned a non-zero value (integration stopped at once)
 *   5  non-finite error estimate after 10 consecutive step reductions
 * On failure y holds the state at the last output time reached (or y0 if none) and the
 * columns of yout not reached are left unchanged. nstat is set on every return.
 * The functions never stop the program. They are re-entrant: no global state. */
#ifndef NANOPUSH_F77_BSINT_H
#define NANOPUSH_F77_BSINT_H

#ifdef __cplusplus
extern "C" {
#endif

/* Right-hand side: dydt[n] = f(t, y[n]); udata is passed through unchanged.
 * Return 0 on success, non-zero on failure (the integrator then returns status 4).
 * A C++ callback must not let an exception escape (catch and return non-zero). */
typedef int (*np_f77_bsint_rhs)(int n, double t, const double* y, double* dydt, void* udata);

/* Integrate y' = rhs(t, y) from t0 through the output times.
 *   n        number of components, 1..64
 *   t0       initial time [s]
 *   y[n]     in: state at t0; out: state at the last output time reached
 *   nout     number of output times, >= 1
 *   tout[nout] output times [s], t0 <= tout[0] <= ... <= tout[nout-1] (tout[0] = t0 allowed)
 *   yout[n*nout] out: yout[i + n*k] = y_i(tout[k])
 *   rtol     relative tolerance (>= 0)
 *   atol[n]  absolute tolerance per component (>= 0, > 0 where rtol = 0)
 *   h0       initial step [s], 0 = default 0.01*(tout[nout-1] - t0)
 *   hmax     largest step [s], 0 = no limit
 *   kmax     extrapolation columns 3..12, 0 = default 8
 *   iextr    1 = rational extrapolation (thesis), 2 = polynomial (Aitken-Neville)
 *   maxstp   maximum number of attempted steps, 0 = default 100000
 *   rhs, udata  the right-hand side and its state
 *   nstat[3] out: RHS evaluations, accepted steps, rejected steps */
int np_f77_bsint(int n, double t0, double* y, int nout, const double* tout, double* yout,
                 double rtol, const double* atol, double h0, double hmax, int kmax, int iextr,
                 int maxstp, np_f77_bsint_rhs rhs, void* udata, int* nstat);

/* The right-hand side in BSINT's own calling convention (every argument by reference, as a
 * FORTRAN 77 EXTERNAL subroutine FCN(N, T, Y, DYDT, RPAR, IPAR, IERR)): dydt[*n] = f(*t, y);
 * set *ierr non-zero to stop (status 4). ipar holds udata's bits: read it back with
 * memcpy(&udata, ipar, sizeof udata). rpar is unused. */
typedef void (*np_f77_bsint_fcn_t)(const int* n, const double* t, const double* y, double* dydt,
                                   const double* rpar, int* ipar, int* ierr);

/* As np_f77_bsint, with fcn handed to BSINT as its derivative routine: no trampoline, one call
 * per RHS evaluation (np_f77_bsint makes three: BSINT -> Fortran trampoline -> rhs). Same
 * steps, counts and results. */
int np_f77_bsint_fcn(int n, double t0, double* y, int nout, const double* tout, double* yout,
                     double rtol, const double* atol, double h0, double hmax, int kmax, int iextr,
                     int maxstp, np_f77_bsint_fcn_t fcn, void* udata, int* nstat);

/* As np_f77_bsint on the F77 smooth-surface nanobar RHS (fortran/smbar.f); n must be 6.
 *   y[6], yout[6*nout]: (x [m], y [m], theta [rad], vx [m/s], vy [m/s], omega [rad/s])
 *   atol[6]: in the same units
 *   params[6]: (m [kg], I [kg m^2], F [N], beta [rad], pbx [m], pby [m]) */
int np_f77_bsint_smooth_bar(int n, double t0, double* y, int nout, const double* tout,
                            double* yout, double rtol, const double* atol, double h0,
                            double hmax, int kmax, int iextr, int maxstp, const double* params,
                            int* nstat);

#ifdef __cplusplus
}
#endif
#endif
