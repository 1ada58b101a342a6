/* C API hardening: the checks SUNDIALS' CVODE makes before its first step (too much
 * accuracy, output times too close), non-finite arguments, bounded counts, derived quantities,
 * the push point on the rod, and conflicting settings, each a status and a message naming
 * what was passed. Usage: capi_test_hardening fig3_6a.toml */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "nanopush.h"

#include "check.h"

static char msg[1024];
/* The call's status is `want` and the message contains `text`. */
static void expect(nanopush_error err, int status, int want, const char* text, const char* what) {
  nanopush_get_error(err, msg, sizeof msg);
  printf("%s: status %d (%s), \"%s\"\n", what, status, nanopush_status_name(status), msg);
  if (status != want || nanopush_check_error(err) != want || !strstr(msg, text)) {
    fprintf(stderr, "FAIL %s: expected status %d and a message with \"%s\"\n", what, want, text);
    ++failures;
  }
  nanopush_clear_error(err);
}

static int decay(int n, double t, const double* y, double* dydt, void* udata) {
  (void)t;
  (void)udata;
  for (int i = 0; i < n; ++i) dydt[i] = -y[i];
  return 0;
}

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: capi_test_hardening SCENE.toml\n");
    return 2;
  }
  nanopush_error err = nanopush_new_error();
  const double zero = 0.0;
  double y[2], tout[2];

  /* rtol = 1e-300 with atol = 0: more than double precision gives. */
  nanopush_integrator it = nanopush_new_integrator(err, 2, "faithful", 1e-300, &zero, 1);
  CHECK(it != NULL);
  y[0] = 1.0, y[1] = 2.0, tout[0] = 1.0;
  expect(err, nanopush_integrate(err, it, decay, NULL, 0.0, y, 1, tout, NULL, NULL), NANOPUSH_TOO_MUCH_ACCURACY,
         "more accuracy than double precision gives", "rtol 1e-300, atol 0");
  CHECK(y[0] == 1.0 && y[1] == 2.0); /* nothing integrated */
  nanopush_delete_integrator(&it);

  it = nanopush_new_integrator(err, 2, "faithful", 1e-8, &zero, 1);
  /* t0 = NaN: bad input naming t0 (it used to surface as a message about tout). */
  expect(err, nanopush_integrate(err, it, decay, NULL, NAN, y, 1, tout, NULL, NULL), NANOPUSH_BAD_INPUT, "t0 = nan",
         "t0 = NaN");
  /* Output times one ulp apart: too close, as CVODE says (it was a step size underflow). */
  tout[0] = 1.0, tout[1] = nextafter(1.0, 2.0);
  expect(err, nanopush_integrate(err, it, decay, NULL, 0.0, y, 2, tout, NULL, NULL), NANOPUSH_TOUT_TOO_CLOSE,
         "tout[1] = 1.0000000000000002 is too close to tout[0] = 1", "tout one ulp apart");
  /* t0 = 0 and a first output 1e-20 later over a span of 1: closer than the integrator's
   * smallest step (1e-14 of the span) -- it was a step size underflow at t = 0 -- while 1e-13
   * later is a step it takes. */
  tout[0] = 1e-20, tout[1] = 1.0;
  expect(err, nanopush_integrate(err, it, decay, NULL, 0.0, y, 2, tout, NULL, NULL), NANOPUSH_TOUT_TOO_CLOSE,
         "tout[0] = 1e-20 is too close to t0 = 0", "tout 1e-20 after t0");
  tout[0] = 1e-13;
  y[0] = 1.0, y[1] = 2.0;
  CHECK(nanopush_integrate(err, it, decay, NULL, 0.0, y, 2, tout, NULL, NULL) == NANOPUSH_OK);
  CHECK(fabs(y[0] - exp(-1.0)) < 1e-7);
  /* An infinite last output time is bad input naming it (it read as "too close", issue 34). */
  tout[0] = 1.0, tout[1] = INFINITY;
  expect(err, nanopush_integrate(err, it, decay, NULL, 0.0, y, 2, tout, NULL, NULL), NANOPUSH_BAD_INPUT,
         "tout[1] = inf", "tout = +inf");
  tout[1] = -INFINITY;
  expect(err, nanopush_integrate(err, it, decay, NULL, 0.0, y, 2, tout, NULL, NULL), NANOPUSH_BAD_INPUT,
         "tout[1] = -inf", "tout = -inf");
  tout[0] = 1e-13, tout[1] = 1.0;
  y[0] = INFINITY;
  expect(err, nanopush_integrate(err, it, decay, NULL, 0.0, y, 1, tout, NULL, NULL), NANOPUSH_BAD_INPUT,
         "y[0] = inf", "y0 infinite");
  nanopush_delete_integrator(&it);
  CHECK(strcmp(nanopush_status_name(NANOPUSH_TOO_MUCH_ACCURACY), "too much accuracy requested") == 0);
  CHECK(strcmp(nanopush_status_name(NANOPUSH_TOUT_TOO_CLOSE), "output time too close") == 0);

  /* Counts have an upper bound: no attempt to allocate for INT_MAX components. */
  CHECK(nanopush_new_integrator(err, INT_MAX, "faithful", 1e-8, &zero, 1) == NULL);
  expect(err, nanopush_check_error(err), NANOPUSH_BAD_INPUT, "n = 2147483647: must be in [1, 1000000]",
         "n = INT_MAX");

  /* Derived quantities: L = 1e308 is bad input naming the rod's fields, not an infinite mass. */
  double rod[6], props[5];
  CHECK(nanopush_icor_nanorod(err, rod) == NANOPUSH_OK);
  rod[0] = 1e308;
  expect(err, nanopush_icor_rod_properties(err, rod, props), NANOPUSH_BAD_INPUT, "rod.", "rod L = 1e308");
  /* The push point on the rod, as every chapter 4 formula. */
  double roots[3];
  expect(err, nanopush_icor_cubic_roots(err, 300e-9, 590e-9, 590e-9 * 590e-9 / 12, NANOPUSH_CUBIC_BRENT, roots,
                                        NULL, NULL, NULL, NULL, NULL, NULL),
         NANOPUSH_BAD_INPUT, "yn = 3e-07: must be in [0, 2.95e-07]", "cubic roots, yn > L/2");

  /* Conflicting settings: the F77 engine has one method. */
  nanopush_scene sc = nanopush_load_scene(err, argv[1]);
  CHECK(sc != NULL);
  nanopush_trajectory tr = nanopush_run_scene_ex(err, sc, "f77", "modern", NULL, 0.0, -1.0);
  CHECK(tr == NULL);
  expect(err, nanopush_check_error(err), NANOPUSH_BAD_INPUT, "method = modern: the f77 engine has one method",
         "engine f77 with method modern");
  /* A huge finite value names its field. */
  expect(err, nanopush_scene_set_real(err, sc, "push.force", 1e308), NANOPUSH_BAD_INPUT,
         "push.force = 1e+308: outside the magnitudes", "push.force = 1e308");
  expect(err, nanopush_scene_set_string(err, sc, "scene.name", "../x"), NANOPUSH_BAD_INPUT,
         "scene.name = \"../x\": must be an identifier", "scene.name = ../x");
  nanopush_delete_scene(&sc);
  nanopush_delete_error(&err);
  return finish("capi hardening: all checks hold");
}
