/* nanopush: the C API of the modern C++ solver (implementation: bindings/capi_*.cpp,
 * library target nanopush::capi; Fortran view: module nanopush, bindings/nanopush.f90).
 *
 * Conventions
 *   - Every exported name starts with nanopush_ (macros with NANOPUSH_).
 *   - Units: SI throughout (m, kg, s, rad, N). Arrays are contiguous doubles; shapes are given
 *     beside each argument. "Column-major (r, c)" means element [i + r*j] is row i, column j,
 *     which is the Fortran array a(r, c) and the C array a[c][r].
 *   - Objects are opaque handles with a new / use / delete life cycle. delete functions take
 *     the address of the handle, free it and set it to NULL; deleting NULL is a no-op.
 *   - Errors: every function that can fail takes a nanopush_error as first argument and
 *     returns a status (NANOPUSH_OK = 0 on success), or NULL for constructors. On failure the
 *     status and a message ("<field> = <value>: <requirement>" for bad input) are recorded in
 *     the error handle, which may be NULL if the caller only wants the status. A successful
 *     call leaves the error handle unchanged. No C++ exception ever crosses this interface, and
 *     nothing here stops the program.
 *   - Strings returned to the caller are copied into caller buffers with explicit truncation,
 *     snprintf style: the copy is always NUL-terminated (when size > 0) and the return value is
 *     the full length of the string without the NUL, so a return value >= size means truncated.
 *   - Re-entrant: there is no global state. Distinct handles may be used from distinct threads at
 *     the same time; one handle must not be used by two threads at once.
 */
#ifndef NANOPUSH_H
#define NANOPUSH_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Version of this interface: major * 10000 + minor * 100 + patch. */
#define NANOPUSH_API_VERSION 800
int nanopush_get_api_version(void);

/* ---- Status codes ---------------------------------------------------------------------- */
/* 1..5 are the Bulirsch-Stoer status codes (identical to the F77 engine's IERR). */
#define NANOPUSH_OK 0
#define NANOPUSH_BAD_INPUT 1        /* bad argument, bad scene value or key, missing file */
#define NANOPUSH_TOO_MANY_STEPS 2   /* integrator: more than maxstp steps */
#define NANOPUSH_STEP_UNDERFLOW 3   /* integrator: step size underflow */
#define NANOPUSH_RHS_FAILED 4       /* integrator: the user's right-hand side returned non-zero */
#define NANOPUSH_NOT_FINITE 5       /* integrator: non-finite error estimate */
#define NANOPUSH_SOLVER_FAILED 6    /* another numerical failure */
#define NANOPUSH_NULL_HANDLE 7      /* a required handle or pointer argument was NULL */
#define NANOPUSH_BUFFER_TOO_SMALL 8 /* a caller array is too small; nothing was written */
#define NANOPUSH_OUT_OF_MEMORY 9
#define NANOPUSH_INTERNAL 10        /* any other C++ exception (a bug: please report) */
#define NANOPUSH_TOO_MUCH_ACCURACY 11 /* integrate: rtol/atol ask more than double precision gives */
#define NANOPUSH_TOUT_TOO_CLOSE 12    /* integrate: output times closer than the smallest step */
/* How a run ended when it is not an answer (docs/errors.md, "Outcomes"): */
#define NANOPUSH_NO_STATIC_FRICTION 13  /* thesis/printed law: the object is at rest inside the limit surface */
#define NANOPUSH_LAW_BLOWUP 14          /* printed law: its friction injected energy and the run blew up */
#define NANOPUSH_ACCURACY_NOT_REACHED 15 /* the accuracy asked for could not be met (message: best estimate) */
/* Any other failed run returns the integrator's status, 2..5 (a model's step budget spent, as
 * the dynamic tip model's, is NANOPUSH_TOO_MANY_STEPS), else NANOPUSH_SOLVER_FAILED; Python's
 * SolverError.status_code is the same number for the same run. */

/* Short fixed description of a status code ("bad input", ...); never NULL, static storage. */
const char* nanopush_status_name(int status);

/* ---- Error handle ---------------------------------------------------------------------- */
typedef struct nanopush_error_s* nanopush_error;

/* New error handle in the "no error" state; NULL only when out of memory. */
nanopush_error nanopush_new_error(void);
/* Status recorded in the handle (NANOPUSH_OK if none); NANOPUSH_NULL_HANDLE for NULL. */
int nanopush_check_error(nanopush_error error);
/* Copy the message into buffer[size] (truncated, NUL-terminated); returns its full length. */
int nanopush_get_error(nanopush_error error, char* buffer, int size);
/* Back to "no error". */
void nanopush_clear_error(nanopush_error error);
void nanopush_delete_error(nanopush_error* error);

/* ---- Scenes (docs/scenes.md lists every key) ------------------------------------------- */
typedef struct nanopush_scene_s* nanopush_scene;

/* Load a scene from a TOML file at path (NUL-terminated). NULL on failure (see error). */
nanopush_scene nanopush_load_scene(nanopush_error error, const char* path);
/* Parse a scene from TOML text (NUL-terminated); source_name is used in messages (may be NULL). */
nanopush_scene nanopush_parse_scene(nanopush_error error, const char* toml_text, const char* source_name);
/* Load a preset scene by name ("fig3_6a", "thesis/fig3_18"; `nanopush presets` lists them),
 * found as the command line finds it: NAME.toml or NAME under the presets directory, then
 * NAME.toml in its thesis/, bench/ and examples/ folders. scenes_dir is that directory; NULL or
 * "" = $NANOPUSH_SCENES when set, else the installed presets of this library's prefix
 * (<prefix>/share/nanopush/scenes beside <prefix>/lib, or beside <prefix>/bin when a program
 * links the library statically; CMake: nanopush_SCENES_DIR). NULL on failure:
 * NANOPUSH_BAD_INPUT naming the preset and the directory looked in. */
nanopush_scene nanopush_scene_preset(nanopush_error error, const char* name, const char* scenes_dir);
void nanopush_delete_scene(nanopush_scene* scene);

/* Scene name copied into buffer[size]; returns its full length, or -1 on failure. */
int nanopush_scene_get_name(nanopush_error error, nanopush_scene scene, char* buffer, int size);
/* Scene summary; any output pointer may be NULL.
 *   t_end [s]: end time; samples: number of output times (0, t_end/(samples-1), ..., t_end);
 *   mass [kg]; inertia [kg m^2] about the centre of mass;
 *   initial[6]: (x [m], y [m], theta [rad], vx [m/s], vy [m/s], omega [rad/s]) at t = 0. */
int nanopush_scene_get_info(nanopush_error error, nanopush_scene scene, double* t_end, int* samples,
                            double* mass, double* inertia, double* initial);

/* The constant push: push[4] = (F [N] magnitude, beta [rad] world direction of the force,
 * pbx [m], pby [m] the body-axes point of the centre-of-mass frame where it acts). */
int nanopush_scene_get_push(nanopush_error error, nanopush_scene scene, double* push);

/* Set a scene key after loading ("surface.mu", "push.yn", ...; `nanopush scene-keys` and
 * docs/scenes.md list every key with its unit and range), validated as the file is: a value
 * out of range, of the wrong type, a key the scene's model does not use (surface.mu on a smooth
 * surface) or a conflict gives NANOPUSH_BAD_INPUT naming the key, and the scene is unchanged.
 *   nanopush_scene_set_real:   a number (an integer key needs a whole number), SI units;
 *   nanopush_scene_set_string: the value as text, read as the key's type, as `--set KEY=VALUE`
 *                              does ("coulomb" for surface.law, "0.1" for surface.mu). */
int nanopush_scene_set_real(nanopush_error error, nanopush_scene scene, const char* key, double value);
int nanopush_scene_set_string(nanopush_error error, nanopush_scene scene, const char* key, const char* value);

/* ---- Runs ------------------------------------------------------------------------------ */
typedef struct nanopush_trajectory_s* nanopush_trajectory;

/* Number of trajectory columns: t, x, y, theta, vx, vy, omega, fx, fy, mf
 * (s, m, m, rad, m/s, m/s, rad/s, N, N, N m; world axes; centre-of-mass state). */
#define NANOPUSH_TRAJECTORY_COLUMNS 10

/* Integrate the scene, as `nanopush run` does.
 *   engine: "cxx" (modern C++ Bulirsch-Stoer) or "f77" (FORTRAN 77 BSINT); NULL or "" = scene's
 *   method: "faithful" (steps identical to f77), "modern" or "dop853" (C++ only; dop853: Dormand-Prince
 *           8(5,3), double, not under the coulomb law), "auto" (by rtol, docs/dop853.md); NULL or "" =
 *           scene's (auto unless the scene states one; the thesis presets state faithful)
 *   rtol:   relative tolerance in [1e-30, 0.1]; 0 = scene's
 *   atol:   absolute tolerance for every component; < 0 = scene's; 0 = rtol times each
 *           component's natural scale
 * Returns a trajectory, or NULL on failure (bad settings: NANOPUSH_BAD_INPUT; integrator failure:
 * NANOPUSH_TOO_MANY_STEPS.. NANOPUSH_SOLVER_FAILED). */
nanopush_trajectory nanopush_run_scene(nanopush_error error, nanopush_scene scene, const char* engine,
                                       const char* method, double rtol, double atol);
void nanopush_delete_trajectory(nanopush_trajectory* trajectory);

/* Number of rows (output times) into *rows; columns = NANOPUSH_TRAJECTORY_COLUMNS. */
int nanopush_trajectory_get_size(nanopush_error error, nanopush_trajectory trajectory, int* rows);
/* Copy the trajectory into data, column-major (NANOPUSH_TRAJECTORY_COLUMNS, rows): data[c + 10*i]
 * is column c at output time i (in Fortran: data(10, rows), one time per column).
 * capacity is the number of rows data can hold; if capacity < rows nothing is written and
 * NANOPUSH_BUFFER_TOO_SMALL is returned. */
int nanopush_trajectory_get_data(nanopush_error error, nanopush_trajectory trajectory, int capacity,
                                 double* data);
/* Counts: counts[3] = (RHS evaluations, accepted steps, rejected steps). */
int nanopush_trajectory_get_counts(nanopush_error error, nanopush_trajectory trajectory, int64_t* counts);
/* Engine label ("cxx-faithful", "cxx-modern", "f77") into buffer[size]; full length or -1. */
int nanopush_trajectory_get_engine(nanopush_error error, nanopush_trajectory trajectory, char* buffer,
                                   int size);

/* Both engines on one scene, judged column by column as `nanopush compare` does (one rule,
 * compare_engines in the engines layer; docs/rough.md, "Comparing the engines").
 *   method:    "faithful" (NULL or "": the same steps as f77, judged per column against
 *              tolerance), "modern" or "dop853" (judged by convergence: both engines run again
 *              at rtol 1e-14)
 *   law:       "thesis" or "printed"; NULL or "" = the scene's (thesis for a coulomb scene)
 *   rtol:      0 = scene's; atol: < 0 = scene's; tolerance: > 0 judges by same steps against
 *              it; 0 = by the method (100 rtol for faithful)
 * Out: *agree 1 or 0; *kind (may be NULL) 0 same steps, 1 convergence; figures (may be NULL)
 * [9]: per column x, y, theta, vx, vy, omega, fx, fy, mf the figure judged (same steps:
 * max |diff| / scale; convergence: the tight runs' difference / scale). A run that does not
 * complete (a reference run included) is a solver failure (NANOPUSH_TOO_MANY_STEPS..). */
int nanopush_compare(nanopush_error error, nanopush_scene scene, const char* method, const char* law,
                     double rtol, double atol, double tolerance, int* agree, int* kind, double* figures);

/* ---- Integrating a user's right-hand side with the C++ Bulirsch-Stoer ------------------ */
/* dydt[n] = f(t, y[n]); udata is passed through unchanged (it is how the callback reaches its
 * own data: never use globals). Return 0 on success, non-zero to stop the integration
 * (nanopush_integrate then returns NANOPUSH_RHS_FAILED and the message quotes the value).
 * A C++ callback should return a status rather than throw; if it throws anyway, the exception
 * is caught inside the library and reported (NANOPUSH_BAD_INPUT for nanopush::InputError,
 * NANOPUSH_OUT_OF_MEMORY for std::bad_alloc, NANOPUSH_INTERNAL otherwise). */
typedef int (*nanopush_rhs)(int n, double t, const double* y, double* dydt, void* udata);

typedef struct nanopush_integrator_s* nanopush_integrator;

/* New Bulirsch-Stoer integrator of dimension n >= 1 (chosen at run time).
 *   method: "faithful" (thesis configuration: rational extrapolation, kmax 8; takes the same
 *           steps as the F77 BSINT with iextr = 1, kmax = 8) or "modern" (polynomial, kmax 10);
 *           NULL or "" = faithful
 *   rtol:   relative tolerance >= 0
 *   atol[natol]: absolute tolerance in the units of each component, natol = 1 (one value for
 *           all) or n; >= 0, and > 0 where rtol = 0
 * Defaults: h0 = 1% of the span, no hmax, maxstp = 100000 (see nanopush_integrator_set_*). */
nanopush_integrator nanopush_new_integrator(nanopush_error error, int n, const char* method, double rtol,
                                            const double* atol, int natol);
void nanopush_delete_integrator(nanopush_integrator* integrator);

/* Step control: h0 [time units] initial step (0 = 1% of the span), hmax largest step (0 = none),
 * maxstp maximum number of attempted steps (>= 1). */
int nanopush_integrator_set_steps(nanopush_error error, nanopush_integrator integrator, double h0,
                                  double hmax, int64_t maxstp);
/* Extrapolation: kmax columns in 3..12; extrapolation 1 = rational (thesis), 2 = polynomial. */
int nanopush_integrator_set_extrapolation(nanopush_error error, nanopush_integrator integrator, int kmax,
                                          int extrapolation);

/* Integrate y' = rhs(t, y) from t0 through the output times.
 *   y[n]          in: state at t0; out: state at the last output time reached
 *   nout, tout[nout]: output times, t0 <= tout[0] <= ... <= tout[nout-1] (tout[0] = t0 allowed)
 *   yout          column-major (n, nout): yout[i + n*k] = y_i(tout[k]); may be NULL if unwanted.
 *                 On failure the columns not reached are left unchanged.
 *   counts[3]     out (may be NULL): RHS evaluations, accepted steps, rejected steps
 * Status: NANOPUSH_OK, NANOPUSH_BAD_INPUT (also non-finite t0, y or tout), NANOPUSH_TOO_MANY_STEPS,
 * NANOPUSH_STEP_UNDERFLOW, NANOPUSH_RHS_FAILED, NANOPUSH_NOT_FINITE (as the F77 engine's IERR
 * 0..5), NANOPUSH_NULL_HANDLE; before any step, as SUNDIALS' CVODE: NANOPUSH_TOUT_TOO_CLOSE
 * (consecutive distinct output times, t0 first, less than 1e-14 max(|t|, tout[nout-1] - t0)
 * apart: the integrator's smallest step) and
 * NANOPUSH_TOO_MUCH_ACCURACY (eps times the RMS norm of y0 weighted by 1/(rtol|y_i|+atol_i)
 * above 1, e.g. rtol = 1e-300 with atol = 0).
 * The integrator keeps no state between calls except its options; it is not thread-safe to share
 * one integrator between threads (create one per thread). */
int nanopush_integrate(nanopush_error error, nanopush_integrator integrator, nanopush_rhs rhs, void* udata,
                       double t0, double* y, int nout, const double* tout, double* yout, int64_t* counts);

/* Run with every setting, as `nanopush run` does: nanopush_run_scene plus
 *   law: friction law of rough scenes ([surface] kind = "rough"): "thesis" (eq 3.40 sign law),
 *        "printed" (the same with eqs 3.45-3.48 as printed) or "coulomb" (event-located
 *        stick-slip); NULL or "" = the scene's. Ignored by smooth scenes.
 *   method may also be "cvode" (SUNDIALS cross-check: rough scenes, coulomb law, engine cxx). */
nanopush_trajectory nanopush_run_scene_ex(nanopush_error error, nanopush_scene scene, const char* engine,
                                          const char* method, const char* law, double rtol, double atol);

/* nanopush_run_scene_ex plus
 *   precision: scalar of the integration: "double", "long" (x87 80-bit long double) or "quad"
 *              (__float128, 113-bit); NULL or "" = the scene's [solver] precision (which the
 *              other run functions use too). long and quad: engine "cxx", and on a smooth
 *              scene method "faithful", "modern" or "auto", on a rough scene the thesis or
 *              coulomb law with method "modern" or "auto" (docs/accuracy.md, "References with
 *              more digits"); otherwise NANOPUSH_BAD_INPUT naming the field. Each
 *              costs more per RHS evaluation (docs/performance.md: ~15x long, ~120x quad).
 * nanopush_trajectory_get_data then returns the values rounded to double; the extended
 * digits come from nanopush_trajectory_get_state_extended. */
nanopush_trajectory nanopush_run_scene_precision(nanopush_error error, nanopush_scene scene, const char* engine,
                                                 const char* method, const char* law, const char* precision,
                                                 double rtol, double atol);
/* Precision the trajectory was integrated in ("double", "long", "quad") into buffer[size];
 * full length or -1. */
int nanopush_trajectory_get_precision(nanopush_error error, nanopush_trajectory trajectory, char* buffer,
                                      int size);
/* nanopush_run_scene_precision plus (docs/accuracy.md)
 *   accuracy:       the error asked for of the final pose, in [1e-14, 0.1] (rtol, and under
 *                   method "auto" the method, chosen to reach it); 0 = none (run at rtol);
 *                   < 0 = the scene's solver.accuracy. Not reached: NANOPUSH_ACCURACY_NOT_REACHED
 *                   with the best estimate in the message.
 *   error_estimate: 1 estimate the error of the answer (a companion run at rtol/100), 0 do not,
 *                   < 0 the scene's solver.error_estimate (the other run functions use the scene's);
 *                   any other value is NANOPUSH_BAD_INPUT naming error_estimate. */
nanopush_trajectory nanopush_run_scene_accuracy(nanopush_error error, nanopush_scene scene, const char* engine,
                                                const char* method, const char* law, const char* precision,
                                                double rtol, double atol, double accuracy, int error_estimate);
/* The estimated global error of the answer, NaN where not estimated:
 *   estimate[0] the final pose in the accuracy norm: max(|dx|, |dy|) / length scale, |dtheta|
 *   estimate[1] |dx| [m], [2] |dy| [m], [3] |dtheta| [rad] at t_end
 *   estimate[4] the norm's max over the output times
 *   estimate[5] the rtol the answer used (--accuracy chooses it)
 *   estimate[6] RHS evaluations in all (the answer's and the estimate's) */
#define NANOPUSH_ERROR_SIZE 7
int nanopush_trajectory_get_error(nanopush_error error, nanopush_trajectory trajectory, double* estimate);
/* How the run ended: "ok" or "at_rest" (the push cannot break static friction: the object
 * stays), into buffer[size]; full length or -1 as nanopush_trajectory_get_engine. */
int nanopush_trajectory_get_outcome(nanopush_error error, nanopush_trajectory trajectory, char* buffer, int size);

/* Number of state components: x [m], y [m], theta [rad], vx [m/s], vy [m/s], omega [rad/s]. */
#define NANOPUSH_STATE_SIZE 6
/* The state at each output time to the precision of the integration, as an unevaluated sum of
 * two doubles: value = hi + lo, hi the value rounded to double (the trajectory's columns 1..6),
 * lo the rest rounded to double (|lo| <= ulp(hi)/2). Column-major (NANOPUSH_STATE_SIZE, rows):
 * element [i + 6*k] is component i at output time k (Fortran: hi(6, rows)). long double values
 * are represented exactly; __float128 values to about 2^-106 relative (below any error the
 * integration reaches); double runs give lo = 0. capacity as in nanopush_trajectory_get_data. */
int nanopush_trajectory_get_state_extended(nanopush_error error, nanopush_trajectory trajectory, int capacity,
                                           double* hi, double* lo);

/* ---- Friction resultant over a rectangular contact (docs/friction.md, docs/models.md B) ----- */
/* Coulomb friction over a 2a x 2b rectangle with uniform pressure, rigid rotation about the iCOR.
 *   a [m]      half-width (along body x'), > 0; b [m] half-length (along body y'), > 0;
 *              min(a,b)/max(a,b) not below the library's aspect limit (the message names it)
 *   muN [N]    mu times the normal load, >= 0
 *   R [m] >= 0, alpha [rad]: the iCOR sits at c = -R (cos alpha, sin alpha) from the centre of
 *              mass, body axes
 *   sense      +1 counter-clockwise (omega > 0), -1 clockwise
 *   wrench[3]  out: (fx [N], fy [N], mf [N m]), body axes, moment about the centre of mass
 * Identical (bit for bit) to nanopush::rectangle_friction_wrench_checked and `nanopush friction`
 * (which prints it for muN = 1). Bad input: NANOPUSH_BAD_INPUT, wrench unchanged. */
int nanopush_friction_wrench(nanopush_error error, double a, double b, double muN, double R, double alpha,
                             int sense, double* wrench);
/* The same from the rigid velocity in body axes: centre-of-mass velocity (vx, vy) [m/s] and
 * omega [rad/s] (iCOR c = (-vy, vx)/omega); pure translation (omega = 0: f = -muN v/|v|, mf = 0)
 * and rest (zero wrench) included. */
int nanopush_friction_from_velocity(nanopush_error error, double a, double b, double muN, double vx, double vy,
                                    double omega, double* wrench);

/* ---- iCOR of a pushed nanorod (docs/icor.md, docs/models.md D; thesis chapters 4-5) ---------- */
/* One pattern for every formula: int nanopush_icor_<name>(error, inputs..., double* result).
 * A rod of length L [m] (> 0, half-length b = L/2) is pushed perpendicular to its axis at
 * yn [m] (>= 0) from its centre of mass; R [m] is the distance from the centre of mass to the
 * iCOR (chapter 4 sign convention: R > 0 on the far side from the push point). mu [-] friction
 * coefficient, W [N] normal load, F [N] push force, k2 [m^2] = I/m. Pure translation is
 * R = +infinity (never NaN). Bad input: NANOPUSH_BAD_INPUT, *result unchanged.
 * Identical (bit for bit) to the functions of nanopush::icor and to `nanopush icor formulas`. */
int nanopush_icor_experimental_fit(nanopush_error error, double yn, double L, double* R);  /* eq 4.1, 0 <= yn <= b */
int nanopush_icor_falvo(nanopush_error error, double yn, double L, double* R);             /* eq 4.2 */
int nanopush_icor_li(nanopush_error error, double yn, double L, double* R);                /* eq 4.3 */
int nanopush_icor_unknown_pressure(nanopush_error error, double yn, double L, double* R);  /* eq 4.13 */
/* eq 4.7 (known pressure); requires F >= the minimum force of eq 4.8 */
int nanopush_icor_known_pressure(nanopush_error error, double mu, double W, double yn, double F, double L,
                                 double* R);
/* eq 4.8: the minimum push force F [N] that starts motion */
int nanopush_icor_minimum_force(nanopush_error error, double mu, double W, double yn, double L, double* F);
/* eq 4.10: F [N] = mu W R / b */
int nanopush_icor_force_from_icor(nanopush_error error, double mu, double W, double R, double L, double* F);
/* eq 4.11: F [N] = mu W (b^2 + R^2) / (2 b (R + yn)); requires R + yn > 0 */
int nanopush_icor_force_unknown_pressure(nanopush_error error, double mu, double W, double R, double yn, double L,
                                         double* F);
/* eq 5.2 (erratum 5): push force F [N] for an assumed iCOR R (signed, as the cubic's roots);
 * +-infinity at the pole yn R = k2 */
int nanopush_icor_constrained_force(nanopush_error error, double mu, double W, double R, double yn, double L,
                                    double k2, double* F);
/* eq 5.5 (erratum 6): impulsive iCOR R = k2 / yn [m]; +infinity at yn = 0 */
int nanopush_icor_impulsive(nanopush_error error, double yn, double k2, double* R);

/* Solvers of the constrained cubic (eq 5.4). */
#define NANOPUSH_CUBIC_BRENT 1 /* van Wijngaarden-Dekker-Brent on brackets from the critical points */
#define NANOPUSH_CUBIC_EIGEN 2 /* eigenvalues of the balanced companion matrix (Eigen) */
/* Roots of the constrained cubic (eq 5.4) 2 yn R^3 - 3 k2 R^2 + k2 (b^2 - 2 k2) = 0.
 *   method        NANOPUSH_CUBIC_BRENT or NANOPUSH_CUBIC_EIGEN
 *   roots[3]      out: the finite real roots ascending [m]; the unused entries are NaN
 *   nroots        out: how many finite real roots (0..3)
 *   ncomplex      out: non-real roots (0 or 2); at_infinity out: roots lost as yn -> 0
 *   negative      out: Table 5.1's branch (the negative root closest to 0) [m], NaN if none
 *   positive      out: the other branch (the smallest positive root) [m], NaN if none
 *   max_residual  out: max over the real roots of |p(R)| / sum |c_i R^i|
 * Any output pointer except roots may be NULL. Identical to `nanopush icor roots`. */
int nanopush_icor_cubic_roots(nanopush_error error, double yn, double L, double k2, int method, double* roots,
                              int* nroots, int* ncomplex, int* at_infinity, double* negative, double* positive,
                              double* max_residual);

/* The thesis' nanorod (graphite, L = 590 nm, radius 13.5 nm): rod[6] = (L [m], radius [m],
 * density [kg/m^3], Hamaker constant H [J], rod-plane separation z0 [m], g [m/s^2]). */
int nanopush_icor_nanorod(nanopush_error error, double* rod);
/* Derived quantities of a rod rod[6] (as above; every entry finite and > 0, g >= 0):
 * props[5] = (mass [kg], inertia about the CM [kg m^2], k2 = I/m [m^2], van der Waals force
 * F_vdw [N] (Parsegian), load W = m g + F_vdw [N]). The W and k2 of `nanopush icor`. */
int nanopush_icor_rod_properties(nanopush_error error, const double* rod, double* props);

/* ---- Friction coefficient from measurements (docs/icor.md, thesis Figs 4.4, 4.5) ------------ */
/* mu [-] with its first-order uncertainty (inputs uncorrelated), as `nanopush icor estimate-mu`.
 *   rod[6]       the rod, as nanopush_icor_rod_properties: (L [m], radius [m], density [kg/m^3],
 *                H [J], z0 [m], g [m/s^2]); its load W = m g + F_vdw(L, H) is recomputed
 *   force [N]    measured push force F, > 0; sigma_force [N] its standard uncertainty, >= 0
 *   sigma_L [m], sigma_H [J]  standard uncertainties of the rod length and the Hamaker constant,
 *                >= 0 (0: taken as exact)
 *   mu           out: the friction coefficient [-]
 *   sigma        out: its standard uncertainty [-], sqrt(sum (dmu/dx sigma_x)^2)
 *   load         out: the load W [N] used
 *   derivatives[4] out: (dmu/dF [1/N], dmu/dyn or dmu/dR [1/m], dmu/dL [1/m], dmu/dH [1/J])
 * Any output pointer may be NULL. Identical (bit for bit) to nanopush::icor::estimate_mu_from_force
 * / estimate_mu_from_icor (their contributions' derivatives, by name). Bad input:
 * NANOPUSH_BAD_INPUT, the message naming the library's quantity ("F = 0: must be > 0 (N)",
 * "yn uncertainty = -1e-09: must be >= 0 (m)", "rod.length = 0: ..."); NULL rod:
 * NANOPUSH_NULL_HANDLE. A failed call writes no output. */
/* Fig 4.4, eq 4.8 inverted: mu = F (sqrt(yn^2 + b^2) + yn) / (W b), b = L/2, from the minimum
 * push force F measured at yn [m] from the centre of mass (0 <= yn <= b); sigma_yn [m] >= 0. */
int nanopush_estimate_mu_from_force(nanopush_error error, const double* rod, double force, double sigma_force,
                                    double yn, double sigma_yn, double sigma_L, double sigma_H,
                                    double* mu, double* sigma, double* load, double* derivatives);
/* Fig 4.5, eq 4.10 inverted: mu = F b / (W R) from a push force F and the observed distance
 * R [m] (> 0) from the centre of mass to the iCOR; sigma_R [m] >= 0. dmu/dL = 0 exactly
 * (b and W both scale with L). */
int nanopush_estimate_mu_from_icor(nanopush_error error, const double* rod, double force, double sigma_force,
                                   double R, double sigma_R, double sigma_L, double sigma_H,
                                   double* mu, double* sigma, double* load, double* derivatives);

/* ---- Friction coefficient from N observations in batch (docs/fitting.md, `nanopush fit-icor`) ---- */
#define NANOPUSH_PRESSURE_KNOWN 0   /* thesis 4.2.3.1: eq 4.10 where R is observed, else eq 4.8 */
#define NANOPUSH_PRESSURE_UNKNOWN 1 /* thesis 4.2.3.2: eq 4.11 (needs yn), eq 4.8 where R is not observed */
#define NANOPUSH_BATCH_RESULT_SIZE 11
/* mu of every observation for one pressure distribution, combined by inverse-variance weighting,
 * with a chi^2 consistency check; the numbers of `nanopush fit-icor` (docs/fitting.md says what
 * the combined sigma means and when observations are inconsistent).
 *   rod[6]        as nanopush_estimate_mu_from_force
 *   n             number of observations, >= 1
 *   force[n], sigma_force[n]  push forces [N] (> 0) and their standard uncertainties [N]
 *   yn[n], sigma_yn[n]        push offsets from the centre of mass [m] (0..L/2); NaN in yn: not
 *                 observed in that row; yn = NULL: none observed (then sigma_yn may be NULL)
 *   R[n], sigma_R[n]          observed iCOR distances [m] (> 0), NaN / NULL as for yn
 *                 Each row needs yn or R; each row's propagated sigma of mu must be > 0.
 *   pressure      NANOPUSH_PRESSURE_KNOWN or NANOPUSH_PRESSURE_UNKNOWN
 *   sigma_L [m], sigma_H [J]  rod length and Hamaker constant uncertainties (>= 0), systematic:
 *                 added after the combination, never divided by sqrt(n)
 *   alpha         significance level of the consistency check, in (0, 1) (the CLI's 0.01)
 *   result[NANOPUSH_BATCH_RESULT_SIZE] out: (mu, sigma = sqrt(stat^2 + syst^2), sigma_stat,
 *                 sigma_syst, sigma_scaled (Birge: sigma_stat sqrt(max(1, chi2/dof)) with syst.),
 *                 chi2, chi2/dof (NaN for n = 1), p-value (NaN for n = 1), load W [N],
 *                 dmu/dL [1/m], dmu/dH [1/J])
 *   dof           out: n - 1;  consistent out: 1 if p-value >= alpha (or n = 1), else 0
 *   rows          out: column-major (n, 4): per observation mu, its sigma, its normalised weight,
 *                 its pull (mu_i - mu) / sigma_i
 *   equations[n]  out: the thesis equation each row used: 8 (eq 4.8), 10 (4.10) or 11 (4.11)
 * Any output pointer may be NULL. Bad input: NANOPUSH_BAD_INPUT, the message naming the row from 1
 * ("row 2: yn = 4e-07: must be in [0, 2.95e-07] ..."); NULL rod, force or sigma_force (or a
 * sigma array missing beside its values): NANOPUSH_NULL_HANDLE. A failed call writes no output. */
int nanopush_estimate_mu_batch(nanopush_error error, const double* rod, int n, const double* force,
                               const double* sigma_force, const double* yn, const double* sigma_yn,
                               const double* R, const double* sigma_R, int pressure, double sigma_L,
                               double sigma_H, double alpha, double* result, int* dof, int* consistent,
                               double* rows, int* equations);

/* ---- Push planning (docs/planning.md, `nanopush plan`) ----------------------------------------- */
#define NANOPUSH_PLAN_PUSH_SIZE 8
#define NANOPUSH_PLAN_SUMMARY_SIZE 8
/* Tip pushes that bring the bar of `scene` (a rough surface; its tip.* keys give the tip's radius,
 * speed and friction) from its initial pose to `goal`, planned through the quasi-static tip
 * model and verified by forward runs; the numbers of `nanopush plan`.
 *   goal[3]       x [m], y [m], theta [rad] (world axes)
 *   tolerance[2]  distance [m], angle [rad]; NULL = (1e-9 m, 0.01 rad)
 *   objective     "pushes", "travel", "time" or "force"; NULL or "" = "pushes"
 *   max_pushes    the most pushes a plan may have, 1 ... 1000
 *   capacity      rows `pushes` holds: at least max_pushes (else NANOPUSH_BUFFER_TOO_SMALL)
 *   pushes        out: one row of NANOPUSH_PLAN_PUSH_SIZE per push, row-major: start_x, start_y
 *                 [m], direction [rad], speed [m/s], travel [m] (the scene's tip.* keys), then the
 *                 pose it leaves, x_end, y_end [m], theta_end [rad] (plan.csv's columns)
 *   n_pushes      out: the plan's pushes
 *   summary[NANOPUSH_PLAN_SUMMARY_SIZE] out: found (1/0), verified (1/0), the final pose x, y
 *                 [m], theta [rad], its distance [m] and angle [rad] from the goal, forward runs
 * A goal no plan reaches within max_pushes is not an error: found = 0 and the best plan is
 * given. Any output pointer may be NULL. Bad input: NANOPUSH_BAD_INPUT naming the argument;
 * NULL scene or goal: NANOPUSH_NULL_HANDLE. A failed call writes no output. */
int nanopush_plan(nanopush_error error, nanopush_scene scene, const double* goal, const double* tolerance,
                  const char* objective, int max_pushes, int capacity, double* pushes, int* n_pushes, double* summary);

/* A robust plan (`nanopush plan --robust`, docs/planning.md "Robust plans"): as nanopush_plan, for
 * a set of worlds at once: the model's, the tip friction at both ends of tip_mu_range, and the
 * start shifted by -start_shift[k] and +start_shift[k] in x, y and theta, one at a time.
 *   tip_mu_range[2]  lo, hi with 0 <= lo <= hi <= 10 (a tip scene); NULL: the model's tip friction only
 *   start_shift[3]   dx, dy [m], dtheta [rad], each >= 0 (0: no shift); NULL: none
 * found (summary[0]) = 1 when the plan leaves every world within tolerance; verified when each
 * world's end-to-end replay does too. With both NULL it is nanopush_plan. */
int nanopush_plan_robust(nanopush_error error, nanopush_scene scene, const double* goal, const double* tolerance,
                         const char* objective, int max_pushes, const double* tip_mu_range, const double* start_shift,
                         int capacity, double* pushes, int* n_pushes, double* summary);

/* ---- Assembly (docs/planning.md, `nanopush assemble`) ------------------------------------------ */
#define NANOPUSH_ASSEMBLY_PUSH_SIZE 10
/* Several bars of `scene`'s kind (its bar, surface and tip) from `objects` into `slots`: the
 * assignment of least summed distance, then bar by bar, each bar's pushes planned as by
 * nanopush_plan and kept `gap` [m] clear (bar and tip) of the others; `nanopush assemble`.
 *   n             bars (and slots), 1 ... 20
 *   objects[3n]   the bars' poses, row-major: x [m], y [m], theta [rad] per bar
 *   slots[3n]     the slots' poses, likewise
 *   tolerance[2]  distance [m], angle [rad] within which a bar is in its slot; NULL = (1e-9, 0.01)
 *   max_pushes    the most pushes per bar, 1 ... 1000
 *   gap           the least distance kept between bars, and between a tip and another bar [m]
 *   capacity      rows `pushes` holds: at least n * max_pushes (else NANOPUSH_BUFFER_TOO_SMALL)
 *   pushes        out: one row of NANOPUSH_ASSEMBLY_PUSH_SIZE per push, in the order made:
 *                 bar, slot (from 1), then nanopush_plan's eight columns (assembly.csv's columns)
 *   n_pushes      out: the rows
 *   slot_of[n]    out: each bar's slot (from 1)
 *   final_poses[3n] out: where each bar ends, row-major
 *   assembled     out: 1 every bar in its slot, 0 not (the moves made so far are given)
 * Any output pointer may be NULL. Bad input (counts, overlapping bars or slots, a non-finite
 * pose): NANOPUSH_BAD_INPUT naming it; NULL scene, objects or slots: NANOPUSH_NULL_HANDLE.
 * A failed call writes no output. */
int nanopush_assemble(nanopush_error error, nanopush_scene scene, int n, const double* objects, const double* slots,
                      const double* tolerance, int max_pushes, double gap, int capacity, double* pushes,
                      int* n_pushes, int* slot_of, double* final_poses, int* assembled);

/* ---- Trajectory fit (docs/fitting.md, `nanopush fit`) ---------------------------------------- */
#define NANOPUSH_FIT_SUMMARY_SIZE 6
/* Fit scene keys to observed motion: weighted least squares over the forward model, starting
 * from the scene's values (the scene itself is not changed); the numbers of `nanopush fit`.
 *   scene        the model (law and keys as loaded or set)
 *   data_path    CSV file: t [s] and any of x, y [m], theta [rad], with sigma_x, sigma_y,
 *                sigma_theta columns (docs/fitting.md)
 *   free_keys    comma-separated scene keys to fit, e.g. "surface.mu" or "surface.mu,surface.f_vdw"
 *   law          rough scenes: "thesis", "printed" or "coulomb"; NULL or "" = the scene's
 *   sigma        per-column standard deviations for columns without a sigma column,
 *                "x=2e-9,theta=0.01"; NULL or "" = none (as `--sigma`)
 *   nfree        size of values and stderrs (>= number of free keys, else NANOPUSH_BUFFER_TOO_SMALL)
 *   values       out: the estimates, in the order of free_keys (SI)
 *   stderrs      out: their standard errors; NaN where the data do not determine the key
 *                separately (identifiability: the JSON names the combination they determine)
 *                or the fit did not converge
 *   summary[NANOPUSH_FIT_SUMMARY_SIZE] out: (chi2, chi2/dof, dof, iterations, forward solves,
 *                identifiable 1/0)
 *   converged    out: 1 if the optimiser converged, else 0 (the estimates are then its last state;
 *                a non-converged fit is not an error)
 *   json[json_size] out: the JSON summary of `nanopush fit --json` (truncated, NUL-terminated);
 *                json_length out: its full length (query with json = NULL, json_size = 0)
 * Any output pointer may be NULL. Bad data or options: NANOPUSH_BAD_INPUT naming the row and
 * column or the key; NULL scene, data_path or free_keys: NANOPUSH_NULL_HANDLE. A failed call
 * writes no output. */
int nanopush_fit_trajectory(nanopush_error error, nanopush_scene scene, const char* data_path, const char* free_keys,
                            const char* law, const char* sigma, int nfree, double* values, double* stderrs,
                            double* summary, int* converged, char* json, int json_size, int* json_length);

#ifdef __cplusplus
}
#endif
#endif
