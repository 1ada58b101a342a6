/* nanopush: C view of the FORTRAN 77 rolling formulas (fortran/rolling.f) through the
 * bind(C) shims of fortran/bridge/f77_rolling.f90. All quantities SI; scalars only.
 * Return value: 0 = ok, 1 = invalid argument, 2 = load below the pull-off load,
 * 3 = no convergence. Outputs are written through the pointers (never NULL). */
#ifndef NANOPUSH_F77_ROLLING_H
#define NANOPUSH_F77_ROLLING_H

#ifdef __cplusplus
extern "C" {
#endif

/* Static friction for pure rolling, eq 3.16: fs = (F/3)(1 - 2h/r).
 * f push [N] >= 0, h push height above the axis [m] (|h| <= r), r radius [m] > 0; fs [N]. */
int np_f77_rolling_static_friction(double f, double h, double r, double* fs);

/* Rolling resistance fs = w k / r: w load m g + F_vdw + F_adhesion [N], k contact
 * half-width [m], r radius [m]; fs [N]. */
int np_f77_rolling_resistance(double w, double k, double r, double* fs);

/* Minimum rolling push f = (1 + margin) w k / r [N] (thesis: margin = 0.01). */
int np_f77_rolling_min_force(double w, double k, double r, double margin, double* f);

/* Rolling versus sliding. f [N], h [m], r [m], mu [-], n_slide = m g + F_vdw [N],
 * w_roll = m g + F_vdw + F_adhesion [N], k [m].
 * mode: 0 stuck, 1 rolling, 2 rolling with slip, 3 sliding.
 * f_roll = w_roll k / r [N], f_slide = mu n_slide [N], fs_required = eq 3.16 [N]. */
int np_f77_rolling_decide(double f, double h, double r, double mu, double n_slide,
                          double w_roll, double k, int* mode, double* f_roll,
                          double* f_slide, double* fs_required);

/* Parsegian rod-plane van der Waals force fv = l a sqrt(d) / (16 z0^2.5) [N]:
 * a Hamaker constant [J], l rod length [m], d diameter [m], z0 gap [m]. */
int np_f77_rod_plane_vdw(double a, double l, double d, double z0, double* fv);

/* JKR cylinder-plane line contact: half-width b [m] with
 * p = pi E* b^2/(4 r) - sqrt(2 pi E* w b): r radius [m], estar E* [Pa],
 * w work of adhesion [J/m^2] (= 2 gamma), p load per length [N/m]. */
int np_f77_jkr_line_half_width(double r, double estar, double w, double p, double* b);

#ifdef __cplusplus
}
#endif
#endif
