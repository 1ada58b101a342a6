/* nanopush: C view of the FORTRAN 77 rough-surface nanobar (fortran/rgbar.f, the thesis and printed
 * friction law) through fortran/bridge/f77_rough.f90. SI units; statuses as in f77_bsint.h. */
#ifndef NANOPUSH_F77_ROUGH_H
#define NANOPUSH_F77_ROUGH_H

#ifdef __cplusplus
extern "C" {
#endif

/* params[12]: m [kg], I [kg m^2], F [N], beta [rad], pbx [m], pby [m], a [m] (contact
 * half-width), b [m] (half-length), muN [N], and the world velocity direction
 * (vx, vy, omega) whose friction acts when the body is exactly at rest (0, 0, 0: none,
 * the thesis law).
 * y[8], dydt[8]: x [m], y [m], theta [rad], vx [m/s], vy [m/s], omega [rad/s],
 * W_push [J], W_fric [J] (work accumulators).
 *
 * law: a friction law code: 0 the thesis law; 1 + i the printed law (eqs 3.45-3.50, FRPRNT in
 * fortran/rgbar.f; docs/rough.md) under reading i = 0..15 (nanopush::printed_reading: bit 0
 * corrects F1, bit 1 F3, bit 2 takes cubes in C4, bit 3 prints eq 3.50; 1 is the literal reading).
 *
 * np_f77_rough_bar_rhs_law: one RHS evaluation; returns 0, or the friction routine's status.
 * np_f77_bsint_rough_bar_law: integrate the rough bar with the F77 Bulirsch-Stoer driver; n must
 * be 8; other arguments as np_f77_bsint_smooth_bar (f77_bsint.h) with params[12] as above;
 * returns 1 for a bad n or a code outside 0..16. */
int np_f77_rough_bar_rhs_law(double t, const double* y, double* dydt, const double* params, int law);
int np_f77_bsint_rough_bar_law(int n, double t0, double* y, int nout, const double* tout, double* yout,
                               double rtol, const double* atol, double h0, double hmax, int kmax, int iextr,
                               int maxstp, const double* params, int law, int* nstat);

#ifdef __cplusplus
}
#endif
#endif
