/* nanopush: C view of the FORTRAN 77 engine (bind(C) shims in fortran/bridge/f77_*.f90).
 * Every name starts with np_f77_. All quantities SI. Arrays are contiguous doubles;
 * shapes are given beside each argument. Functions return 0 on success, a positive
 * status otherwise; they never stop the program. */
#ifndef NANOPUSH_F77_BRIDGE_H
#define NANOPUSH_F77_BRIDGE_H

#ifdef __cplusplus
extern "C" {
#endif

/* Smooth-surface nanobar RHS (fortran/smbar.f).
 * y[6], dydt[6]: (x [m], y [m], theta [rad], vx [m/s], vy [m/s], omega [rad/s]).
 * params[6]: (m [kg], I [kg m^2], F [N], beta [rad], pbx [m], pby [m]). */
int np_f77_smooth_bar_rhs(double t, const double* y, double* dydt, const double* params);

#ifdef __cplusplus
}
#endif
#endif
