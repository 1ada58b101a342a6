/* nanopush: C view of the FORTRAN 77 rectangle friction wrench (fortran/rectfr.f, bridged by
 * fortran/bridge/f77_friction.f90). Same conventions and algorithm as nanopush::rectangle_friction_*
 * (cxx/include/nanopush/models/friction.hpp): body axes at the centre of mass, x' across the width,
 * y' along the length, iCOR at -R (cos alpha, sin alpha). SI units. Functions return 0 on
 * success and a positive status otherwise (wrench set to zero); they never stop the program.
 * Status: 1 a, 2 b not finite > 0; 3 aspect ratio min/max < 1e-12; 4 muN not finite >= 0;
 * 5 R not finite >= 0; 6 alpha not finite; 7 sense not +-1; 8 velocity not finite. */
#ifndef NANOPUSH_F77_FRICTION_H
#define NANOPUSH_F77_FRICTION_H

#ifdef __cplusplus
extern "C" {
#endif

/* a [m] half-width, b [m] half-length, mun = mu N [N], r [m] >= 0, alpha [rad],
 * sense +1 (counter-clockwise, omega > 0) or -1.
 * wrench[3]: (fx [N], fy [N], mf [N m]) in body axes, mf about the centre of mass. */
int np_f77_rectangle_friction(double a, double b, double mun, double r, double alpha, int sense,
                              double* wrench);

/* The same from the body-axis rigid velocity: vx, vy [m/s] (centre of mass), omega [rad/s].
 * omega = 0 is pure translation (mf = 0); at rest the wrench is zero. wrench[3] as above. */
int np_f77_rectangle_friction_velocity(double a, double b, double mun, double vx, double vy,
                                       double omega, double* wrench);

/* Message for a status code, copied into buf[buflen] (NUL-terminated, truncated if short).
 * Returns the full message length. */
int np_f77_friction_message(int status, char* buf, int buflen);

#ifdef __cplusplus
}
#endif
#endif
