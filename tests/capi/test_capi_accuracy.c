/* The error estimate, --accuracy and the outcomes from C (docs/accuracy.md, docs/errors.md):
 * nanopush_run_scene_accuracy, nanopush_trajectory_get_error, nanopush_trajectory_get_outcome
 * and the statuses NANOPUSH_NO_STATIC_FRICTION / NANOPUSH_LAW_BLOWUP / NANOPUSH_ACCURACY_NOT_REACHED /
 * NANOPUSH_TOO_MANY_STEPS (a model's step budget), error_estimate's range, extended precision on
 * a rough scene.
 * Usage: test_capi_accuracy ROUGH_SCENE.toml (fig3_18) */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "nanopush.h"

#include "check.h"

int main(int argc, char** argv) {
  nanopush_error err = nanopush_new_error();
  nanopush_scene scene = scene_argument(argc, argv, err, "test_capi_accuracy");
  CHECK(scene != NULL);
  double e[NANOPUSH_ERROR_SIZE];
  char outcome[32];
  /* A plain run estimates its error (the scene's solver.error_estimate, true). */
  nanopush_trajectory t = nanopush_run_scene_ex(err, scene, NULL, NULL, "coulomb", 0.0, -1.0);
  CHECK(t != NULL);
  CHECK(nanopush_trajectory_get_error(err, t, e) == NANOPUSH_OK);
  CHECK(e[0] > 0.0 && e[0] < 1e-6);          /* the final pose in the accuracy norm */
  CHECK(e[3] >= 0.0 && e[3] <= e[0] + 1e-300); /* |dtheta| <= the norm */
  CHECK(e[4] >= e[0]);                        /* the trajectory's max >= the final pose's */
  CHECK(e[5] == 1e-10);                       /* the scene's rtol */
  CHECK(e[6] > 0.0);
  CHECK(nanopush_trajectory_get_outcome(err, t, outcome, sizeof outcome) == 2 && strcmp(outcome, "ok") == 0);
  nanopush_delete_trajectory(&t);
  /* Without the estimate: NaN. */
  t = nanopush_run_scene_accuracy(err, scene, NULL, NULL, "coulomb", NULL, 0.0, -1.0, 0.0, 0);
  CHECK(t != NULL && nanopush_trajectory_get_error(err, t, e) == NANOPUSH_OK && isnan(e[0]));
  nanopush_delete_trajectory(&t);
  /* --accuracy 1e-9: reached, at a tighter rtol. */
  t = nanopush_run_scene_accuracy(err, scene, NULL, NULL, "coulomb", NULL, 0.0, -1.0, 1e-9, -1);
  CHECK(t != NULL && nanopush_trajectory_get_error(err, t, e) == NANOPUSH_OK);
  CHECK(e[0] <= 1e-9 && e[5] < 1e-9);
  nanopush_delete_trajectory(&t);
  /* Not reached: a status, the best estimate in the message (CVODE stops at rtol 1e-14, in double). */
  char msg[1024];
  t = nanopush_run_scene_accuracy(err, scene, NULL, "cvode", "coulomb", NULL, 0.0, -1.0, 1e-14, -1);
  CHECK(t == NULL && nanopush_check_error(err) == NANOPUSH_ACCURACY_NOT_REACHED);
  CHECK(nanopush_get_error(err, msg, sizeof msg) > 0 && strstr(msg, "accuracy_not_reached") != NULL);
  CHECK(nanopush_run_scene_accuracy(err, scene, NULL, NULL, NULL, NULL, 0.0, -1.0, 1.0, -1) == NULL &&
        nanopush_check_error(err) == NANOPUSH_BAD_INPUT);
  /* A push inside the limit surface: at_rest (coulomb, an answer), no_static_friction (thesis). */
  CHECK(nanopush_scene_set_real(err, scene, "push.force", 1e-7) == NANOPUSH_OK);
  t = nanopush_run_scene_ex(err, scene, NULL, NULL, "coulomb", 0.0, -1.0);
  CHECK(t != NULL);
  CHECK(nanopush_trajectory_get_outcome(err, t, outcome, sizeof outcome) == 7 && strcmp(outcome, "at_rest") == 0);
  nanopush_delete_trajectory(&t);
  t = nanopush_run_scene_ex(err, scene, NULL, NULL, "thesis", 0.0, -1.0);
  CHECK(t == NULL && nanopush_check_error(err) == NANOPUSH_NO_STATIC_FRICTION);
  CHECK(strcmp(nanopush_status_name(NANOPUSH_NO_STATIC_FRICTION), "unknown status") != 0);
  /* The F77 engine runs to its step budget there (integrator status: too many steps) and is
   * classified after: the same status (Python's SolverError.status_code too). */
  nanopush_clear_error(err);
  t = nanopush_run_scene_ex(err, scene, "f77", NULL, "thesis", 0.0, -1.0);
  CHECK(t == NULL && nanopush_check_error(err) == NANOPUSH_NO_STATIC_FRICTION);
  nanopush_clear_error(err);

  /* error_estimate takes 1, 0 or < 0 (nanopush.h): any other value is bad input naming it,
   * never read as "estimate". */
  CHECK(nanopush_scene_set_real(err, scene, "push.force", 5e-6) == NANOPUSH_OK);
  for (int v = 2; v <= 5; v += 3) {
    t = nanopush_run_scene_accuracy(err, scene, NULL, NULL, "coulomb", NULL, 0.0, -1.0, 0.0, v);
    CHECK(t == NULL && nanopush_check_error(err) == NANOPUSH_BAD_INPUT);
    CHECK(nanopush_get_error(err, msg, sizeof msg) > 0 && strstr(msg, "error_estimate = ") == msg &&
          strstr(msg, ": must be 1 (estimate the error), 0 (do not) or < 0") != NULL);
    nanopush_clear_error(err);
  }
  t = nanopush_run_scene_accuracy(err, scene, NULL, NULL, "coulomb", NULL, 0.0, -1.0, 0.0, -7);
  CHECK(t != NULL && nanopush_check_error(err) == NANOPUSH_OK); /* < 0: the scene's */
  nanopush_delete_trajectory(&t);

  /* Extended precision on a rough scene (thesis or coulomb law, method modern): as the header
   * says (docs/accuracy.md, "References with more digits"). */
  char precision[16];
  t = nanopush_run_scene_accuracy(err, scene, NULL, "modern", "coulomb", "long", 0.0, -1.0, 0.0, 0);
  CHECK(t != NULL && nanopush_trajectory_get_precision(err, t, precision, sizeof precision) == 4 &&
        strcmp(precision, "long") == 0);
  nanopush_delete_trajectory(&t);
  nanopush_clear_error(err);

  /* The printed law's blowup: NANOPUSH_LAW_BLOWUP (a point of fig3_18's mu x yn grid where
   * its friction injects energy, tests/test_accuracy.cpp). */
  CHECK(nanopush_scene_set_real(err, scene, "push.force", 5e-6) == NANOPUSH_OK && /* the preset's */
        nanopush_scene_set_real(err, scene, "surface.mu", 0.005) == NANOPUSH_OK &&
        nanopush_scene_set_real(err, scene, "push.yn", -21e-9) == NANOPUSH_OK);
  t = nanopush_run_scene_accuracy(err, scene, NULL, NULL, "printed", NULL, 0.0, -1.0, 0.0, 0);
  CHECK(t == NULL && nanopush_check_error(err) == NANOPUSH_LAW_BLOWUP);
  nanopush_clear_error(err);
  nanopush_delete_scene(&scene);

  /* The dynamic tip model spending its step budget: NANOPUSH_TOO_MANY_STEPS, the status the
   * table gives a budget run out (docs/errors.md), as Python's SolverError.status_code (it was
   * NANOPUSH_SOLVER_FAILED here and None there). */
  scene = nanopush_parse_scene(err,
                               "[object]\nshape = \"bar\"\nlength = 590e-9\nwidth = 27e-9\nheight = 27e-9\n"
                               "density = 2267.0\n[push]\nmode = \"tip\"\n[tip]\nstart_x = -40e-9\n"
                               "start_y = 150e-9\ndirection = 0.0\nspeed = 1.0\ntravel = 400e-9\nradius = 10e-9\n"
                               "mu = 0.3\nmodel = \"dynamic\"\nstiffness = 10.0\n[surface]\nkind = \"rough\"\n"
                               "mu = 0.1\nf_vdw = 1e-8\n[solver]\nsamples = 401\nrtol = 1e-10\nmax_steps = 2000\n",
                               "tip_dynamic.toml");
  CHECK(scene != NULL);
  t = nanopush_run_scene_accuracy(err, scene, NULL, NULL, NULL, NULL, 0.0, -1.0, 0.0, 0);
  CHECK(t == NULL && nanopush_check_error(err) == NANOPUSH_TOO_MANY_STEPS);
  CHECK(nanopush_get_error(err, msg, sizeof msg) > 0 && strstr(msg, "solver.max_steps = 2000 steps spent") != NULL);
  nanopush_delete_scene(&scene);
  nanopush_delete_error(&err);
  return finish("capi accuracy: ok");
}
