/* The C API from C (bindings/nanopush.h): handle life cycles, NULL handles, snprintf-style
 * message truncation, query-then-copy of trajectories, the run engines agreeing, and a C
 * callback with udata integrated by the C++ Bulirsch-Stoer against an exact solution. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nanopush.h"

#include "check.h"

/* y' = -k y, y(0) = 1: exact y = exp(-k t). udata points at k. */
static int decay(int n, double t, const double* y, double* dydt, void* udata) {
  const double k = *(const double*)udata;
  (void)t;
  for (int i = 0; i < n; ++i) dydt[i] = -k * (double)(i + 1) * y[i];
  return 0;
}

static int fails_at_half(int n, double t, const double* y, double* dydt, void* udata) {
  decay(n, t, y, dydt, udata);
  return t > 0.5 ? -3 : 0;
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: test_capi SCENE.toml\n");
    return 2;
  }
  CHECK(nanopush_get_api_version() == NANOPUSH_API_VERSION);
  CHECK(strcmp(nanopush_status_name(NANOPUSH_BUFFER_TOO_SMALL), "buffer too small") == 0);
  CHECK(strcmp(nanopush_status_name(12345), "unknown status") == 0);

  nanopush_error err = nanopush_new_error();
  CHECK(err != NULL);
  CHECK(nanopush_check_error(err) == NANOPUSH_OK);
  CHECK(nanopush_check_error(NULL) == NANOPUSH_NULL_HANDLE);

  /* A bad scene: NULL handle, status and message. */
  nanopush_scene bad = nanopush_parse_scene(err, "[object]\nlength = 1e-7\nwidth = 5e-8\nmass = -1\n"
                                                 "[push]\nforce = 1e-6\nxn = 0\nyn = 0\n[solver]\nt_end = 1e-9\n",
                                            "bad.toml");
  CHECK(bad == NULL);
  CHECK(nanopush_check_error(err) == NANOPUSH_BAD_INPUT);
  char msg[256];
  const int len = nanopush_get_error(err, msg, (int)sizeof msg);
  printf("bad scene: %s\n", msg);
  CHECK(len == (int)strlen(msg));
  CHECK(strstr(msg, "object.mass = -1: must be > 0 (kg)") != NULL);
  /* Truncation: 8 characters of room -> 7 copied + NUL; the return value is the full length. */
  char small[8];
  memset(small, 'X', sizeof small);
  CHECK(nanopush_get_error(err, small, (int)sizeof small) == len);
  CHECK(small[7] == '\0' && strlen(small) == 7 && strncmp(small, msg, 7) == 0);
  CHECK(nanopush_get_error(err, NULL, 0) == len); /* length query */
  nanopush_clear_error(err);
  CHECK(nanopush_check_error(err) == NANOPUSH_OK);

  /* NULL handles and pointers: a status, never a crash; a NULL error handle is allowed. */
  CHECK(nanopush_load_scene(err, NULL) == NULL && nanopush_check_error(err) == NANOPUSH_NULL_HANDLE);
  CHECK(nanopush_run_scene(NULL, NULL, "cxx", NULL, 0, -1) == NULL);
  CHECK(nanopush_trajectory_get_size(err, NULL, NULL) == NANOPUSH_NULL_HANDLE);
  CHECK(nanopush_scene_get_name(err, NULL, msg, 10) == -1);
  nanopush_delete_scene(NULL);
  nanopush_clear_error(err);

  /* Load and run the scene with both engines. */
  nanopush_scene scene = nanopush_load_scene(err, argv[1]);
  CHECK(scene != NULL);
  if (!scene) return 1;
  char name[64];
  CHECK(nanopush_scene_get_name(err, scene, name, (int)sizeof name) > 0);
  double t_end = 0, mass = 0, inertia = 0, initial[6];
  int samples = 0;
  CHECK(nanopush_scene_get_info(err, scene, &t_end, &samples, &mass, &inertia, initial) == NANOPUSH_OK);
  printf("scene %s: t_end %g s, %d samples, mass %g kg, inertia %g kg m^2\n", name, t_end, samples, mass, inertia);
  CHECK(t_end > 0 && samples >= 2 && mass > 0 && inertia > 0);

  nanopush_trajectory tc = nanopush_run_scene(err, scene, "cxx", "faithful", 0, -1);
  nanopush_trajectory tf = nanopush_run_scene(err, scene, "f77", NULL, 0, -1);
  CHECK(tc != NULL && tf != NULL);
  if (!tc || !tf) return 1;
  int rows = 0, rows_f = 0;
  CHECK(nanopush_trajectory_get_size(err, tc, &rows) == NANOPUSH_OK && rows == samples);
  CHECK(nanopush_trajectory_get_size(err, tf, &rows_f) == NANOPUSH_OK && rows_f == samples);
  double* dc = malloc(sizeof(double) * NANOPUSH_TRAJECTORY_COLUMNS * (size_t)rows);
  double* df = malloc(sizeof(double) * NANOPUSH_TRAJECTORY_COLUMNS * (size_t)rows);
  dc[0] = -123;
  CHECK(nanopush_trajectory_get_data(err, tc, rows - 1, dc) == NANOPUSH_BUFFER_TOO_SMALL);
  CHECK(dc[0] == -123); /* nothing written */
  nanopush_clear_error(err);
  CHECK(nanopush_trajectory_get_data(err, tc, rows, dc) == NANOPUSH_OK);
  CHECK(nanopush_trajectory_get_data(err, tf, rows, df) == NANOPUSH_OK);
  CHECK(dc[0] == 0.0 && fabs(dc[NANOPUSH_TRAJECTORY_COLUMNS * (size_t)(rows - 1)] - t_end) <= 1e-15 * t_end);
  /* The faithful C++ engine takes the F77 engine's steps: same counts, same numbers. */
  int64_t cc[3], cf[3];
  CHECK(nanopush_trajectory_get_counts(err, tc, cc) == NANOPUSH_OK);
  CHECK(nanopush_trajectory_get_counts(err, tf, cf) == NANOPUSH_OK);
  CHECK(cc[0] == cf[0] && cc[1] == cf[1] && cc[2] == cf[2] && cc[0] > 0);
  double dev = 0;
  for (int i = 0; i < NANOPUSH_TRAJECTORY_COLUMNS * rows; ++i) dev = fmax(dev, fabs(dc[i] - df[i]) / fmax(fabs(df[i]), 1e-300));
  printf("cxx-faithful vs f77: max relative deviation %.3g, RHS evaluations %lld\n", dev, (long long)cc[0]);
  CHECK(dev <= 1e-12);
  char label[4];
  CHECK(nanopush_trajectory_get_engine(err, tc, label, (int)sizeof label) == 12); /* "cxx-faithful" */
  CHECK(strcmp(label, "cxx") == 0);
  CHECK(nanopush_run_scene(err, scene, "cxx", "modern", 1.0, -1) == NULL); /* rtol > 0.1 */
  CHECK(nanopush_check_error(err) == NANOPUSH_BAD_INPUT);
  CHECK(message_has(err, "rtol = 1", "rtol = 1: must be in ["));

  /* Precision as a choice: quad through the C API, its extra digits as hi + lo. */
  {
    nanopush_trajectory tq = nanopush_run_scene_precision(err, scene, "cxx", "faithful", NULL, "quad", 0, -1);
    CHECK(tq != NULL);
    if (!tq) return 1;
    char prec[8];
    CHECK(nanopush_trajectory_get_precision(err, tq, prec, (int)sizeof prec) == 4 && strcmp(prec, "quad") == 0);
    CHECK(nanopush_trajectory_get_precision(err, tc, prec, (int)sizeof prec) == 6 && strcmp(prec, "double") == 0);
    int rq = 0;
    CHECK(nanopush_trajectory_get_size(err, tq, &rq) == NANOPUSH_OK && rq == rows);
    double* dq = malloc(sizeof(double) * NANOPUSH_TRAJECTORY_COLUMNS * (size_t)rq);
    double* hi = malloc(sizeof(double) * NANOPUSH_STATE_SIZE * (size_t)rq);
    double* lo = malloc(sizeof(double) * NANOPUSH_STATE_SIZE * (size_t)rq);
    CHECK(nanopush_trajectory_get_state_extended(err, tq, rq - 1, hi, lo) == NANOPUSH_BUFFER_TOO_SMALL);
    nanopush_clear_error(err);
    CHECK(nanopush_trajectory_get_data(err, tq, rq, dq) == NANOPUSH_OK);
    CHECK(nanopush_trajectory_get_state_extended(err, tq, rq, hi, lo) == NANOPUSH_OK);
    int lo_nonzero = 0, hi_is_rounded = 1, lo_small = 1;
    double dev_q = 0;
    for (int k = 0; k < rq; ++k)
      for (int i = 0; i < NANOPUSH_STATE_SIZE; ++i) {
        const double h = hi[i + NANOPUSH_STATE_SIZE * k], l = lo[i + NANOPUSH_STATE_SIZE * k];
        /* hi is the trajectory's column (the value rounded to double), lo below half an ulp */
        if (h != dq[1 + i + NANOPUSH_TRAJECTORY_COLUMNS * k]) hi_is_rounded = 0;
        if (!(fabs(l) <= 0.5 * (nextafter(fabs(h), INFINITY) - fabs(h)))) lo_small = 0;
        if (l != 0) lo_nonzero = 1;
        const double d = dc[1 + i + NANOPUSH_TRAJECTORY_COLUMNS * k];
        dev_q = fmax(dev_q, fabs(h - d) / fmax(fabs(d), 1e-300));
      }
    printf("quad vs double run: max relative deviation %.3g\n", dev_q);
    CHECK(hi_is_rounded && lo_small && lo_nonzero);
    CHECK(dev_q <= 1e-7);  /* the same trajectory, each to its own tolerance */
    /* a double run: hi = the state, lo = 0 */
    CHECK(nanopush_trajectory_get_state_extended(err, tc, rows, hi, lo) == NANOPUSH_OK);
    CHECK(hi[2 + NANOPUSH_STATE_SIZE * 5] == dc[3 + NANOPUSH_TRAJECTORY_COLUMNS * 5] && lo[2 + NANOPUSH_STATE_SIZE * 5] == 0);
    free(dq);
    free(hi);
    free(lo);
    nanopush_delete_trajectory(&tq);
    /* Bad precision settings name the field, the value and what is allowed. */
    CHECK(nanopush_run_scene_precision(err, scene, "cxx", NULL, NULL, "octuple", 0, -1) == NULL);
    CHECK(nanopush_check_error(err) == NANOPUSH_BAD_INPUT);
    CHECK(message_has(err, "precision = octuple", "precision = octuple: must be double, long or quad"));
    CHECK(nanopush_run_scene_precision(err, scene, "f77", NULL, NULL, "quad", 0, -1) == NULL);
    CHECK(nanopush_check_error(err) == NANOPUSH_BAD_INPUT);
    CHECK(message_has(err, "f77 in quad", "precision = quad"));
    /* The scene's [solver] precision is used by every run function when none is given. */
    const char* toml =
        "[scene]\nname = \"long_bar\"\n"
        "[object]\nshape = \"bar\"\nlength = 100e-9\nwidth = 55e-9\nheight = 50e-9\ndensity = 2267.0\n"
        "[push]\nforce = 5e-6\ndirection = 0.0\nxn = 27.5e-9\nyn = 45e-9\n"
        "[initial]\ntheta = -0.5\n[surface]\nkind = \"smooth\"\n"
        "[solver]\nt_end = 1e-10\nsamples = 11\nrtol = 1e-10\nprecision = \"long\"\n";
    nanopush_scene ls = nanopush_parse_scene(err, toml, "long_bar");
    CHECK(ls != NULL);
    nanopush_trajectory tl = nanopush_run_scene(err, ls, NULL, NULL, 0, -1);
    CHECK(tl != NULL);
    if (tl) {
      CHECK(nanopush_trajectory_get_precision(err, tl, prec, (int)sizeof prec) == 4 && strcmp(prec, "long") == 0);
      nanopush_delete_trajectory(&tl);
    }
    nanopush_delete_scene(&ls);
  }
  free(dc);
  free(df);
  nanopush_delete_trajectory(&tc);
  nanopush_delete_trajectory(&tf);
  CHECK(tc == NULL && tf == NULL);
  nanopush_delete_scene(&scene);
  CHECK(scene == NULL);

  /* A C right-hand side with udata through the C++ Bulirsch-Stoer (n = 3, dynamic). */
  double k = 2.0, atol = 1e-13;
  nanopush_integrator bs = nanopush_new_integrator(err, 3, "modern", 1e-12, &atol, 1);
  CHECK(bs != NULL);
  double y[3] = {1, 1, 1}, tout[5] = {0, 0.25, 0.5, 0.75, 1.0}, yout[15];
  int64_t counts[3];
  CHECK(nanopush_integrate(err, bs, decay, &k, 0.0, y, 5, tout, yout, counts) == NANOPUSH_OK);
  double worst = 0;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 3; ++i) worst = fmax(worst, fabs(yout[i + 3 * j] - exp(-k * (i + 1) * tout[j])));
  printf("decay: max error %.3g with %lld RHS evaluations\n", worst, (long long)counts[0]);
  CHECK(worst <= 1e-10 && counts[0] > 0);
  /* Failing callback: status 4, message quotes the callback's value. */
  y[0] = y[1] = y[2] = 1;
  CHECK(nanopush_integrate(err, bs, fails_at_half, &k, 0.0, y, 5, tout, yout, counts) == NANOPUSH_RHS_FAILED);
  CHECK(message_has(err, "failing RHS", "right-hand side returned status -3"));
  CHECK(nanopush_integrate(err, bs, NULL, &k, 0.0, y, 5, tout, yout, counts) == NANOPUSH_NULL_HANDLE);
  CHECK(nanopush_integrator_set_extrapolation(err, bs, 2, 1) == NANOPUSH_BAD_INPUT);
  CHECK(nanopush_integrator_set_steps(err, bs, -1, 0, 10) == NANOPUSH_BAD_INPUT);
  CHECK(nanopush_new_integrator(err, 0, NULL, 1e-8, &atol, 1) == NULL);
  nanopush_delete_integrator(&bs);
  CHECK(bs == NULL);

  /* Friction and iCOR from C: closed-form checks (bit-for-bit equality with the C++ library and
   * the CLI is tested by capi.friction_icor_c and capi.friction_icor_cli). */
  {
    double w[3], wm[3], rod[6], props[5], R, roots[3], neg, pos, res;
    int nr, nc, ni, i;
    /* Pure translation (omega = 0): f = -muN v/|v|, mf = 0; v = (3, 4) m/s, muN = 5 N. */
    CHECK(nanopush_friction_from_velocity(err, 27.5e-9, 50e-9, 5.0, 3.0, 4.0, 0.0, w) == NANOPUSH_OK);
    CHECK(w[0] == -3.0 && w[1] == -4.0 && w[2] == 0.0);
    /* Reversing the sense of rotation reverses the wrench. */
    CHECK(nanopush_friction_wrench(err, 27.5e-9, 50e-9, 2e-6, 4e-8, 0.7, 1, w) == NANOPUSH_OK);
    CHECK(nanopush_friction_wrench(err, 27.5e-9, 50e-9, 2e-6, 4e-8, 0.7, -1, wm) == NANOPUSH_OK);
    CHECK(w[0] == -wm[0] && w[1] == -wm[1] && w[2] == -wm[2] && w[0] != 0.0);
    CHECK(nanopush_friction_wrench(err, 27.5e-9, -1.0, 2e-6, 4e-8, 0.7, 1, w) == NANOPUSH_BAD_INPUT);
    CHECK(message_has(err, NULL, "b = -1"));
    /* Eq 4.13 is sqrt(b^2 + yn^2) - yn; the cubic's roots solve 2 yn R^3 - 3 k2 R^2 + k2 (b^2 - 2 k2). */
    CHECK(nanopush_icor_nanorod(err, rod) == NANOPUSH_OK);
    CHECK(nanopush_icor_rod_properties(err, rod, props) == NANOPUSH_OK);
    CHECK(nanopush_icor_unknown_pressure(err, 1e-7, rod[0], &R) == NANOPUSH_OK);
    CHECK(fabs(R - (sqrt(0.25 * rod[0] * rod[0] + 1e-14) - 1e-7)) <= 1e-15 * R);
    CHECK(nanopush_icor_cubic_roots(err, 1e-7, rod[0], props[2], NANOPUSH_CUBIC_EIGEN, roots, &nr, &nc, &ni, &neg,
                                    &pos, &res) == NANOPUSH_OK);
    CHECK(nr == 3 && nc == 0 && ni == 0 && neg == roots[0] && pos == roots[1] && neg < 0.0 && pos > 0.0 && res < 1e-14);
    for (i = 0; i < nr; ++i) {
      const double r = roots[i], k2 = props[2], b2 = 0.25 * rod[0] * rod[0];
      const double p = 2e-7 * r * r * r - 3.0 * k2 * r * r + k2 * (b2 - 2.0 * k2);
      const double scale = fabs(2e-7 * r * r * r) + fabs(3.0 * k2 * r * r) + fabs(k2 * (b2 - 2.0 * k2));
      CHECK(fabs(p) <= 1e-14 * scale);
    }
    CHECK(nanopush_icor_falvo(err, 1e-7, 0.0, &R) == NANOPUSH_BAD_INPUT);
    CHECK(message_has(err, NULL, "L = 0"));
  }
  /* The friction law of rough scenes is checked by name even for a smooth scene. */
  {
    nanopush_scene sc = nanopush_load_scene(err, argv[1]);
    nanopush_trajectory t = nanopush_run_scene_ex(err, sc, "cxx", NULL, "sticky", 0, -1);
    CHECK(sc != NULL && t == NULL && nanopush_check_error(err) == NANOPUSH_BAD_INPUT);
    CHECK(message_has(err, NULL, "law = sticky: must be thesis, printed or coulomb"));
    nanopush_delete_scene(&sc);
  }
  nanopush_delete_error(&err);
  CHECK(err == NULL);

  return finish("all checks hold");
}
