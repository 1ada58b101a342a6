/* nanopush_plan through the C API: the plan of `nanopush plan` bit for bit (its plan.csv, given),
 * found and verified, the chain ending at the last push's pose; a robust plan (nanopush_plan_robust)
 * found in every world; bad input refused with its status and nothing written. Usage: capi_test_plan SCENE.toml PLAN.csv */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

/* plan.csv's rows (push, then NANOPUSH_PLAN_PUSH_SIZE numbers): how many were read into rows. */
static int read_plan_csv(const char* path, double* rows, int capacity) {
  FILE* f = fopen(path, "r");
  if (!f) return -1;
  char line[4096];
  int n = 0;
  if (!fgets(line, sizeof line, f)) n = -1; /* the header */
  while (n >= 0 && n < capacity && fgets(line, sizeof line, f)) {
    char* p = strchr(line, ',');
    for (int c = 0; p && c < NANOPUSH_PLAN_PUSH_SIZE; ++c) {
      rows[n * NANOPUSH_PLAN_PUSH_SIZE + c] = strtod(p + 1, &p);
    }
    ++n;
  }
  fclose(f);
  return n;
}

int main(int argc, char** argv) {
  nanopush_error err = nanopush_new_error();
  if (argc < 3) {
    fprintf(stderr, "usage: capi_test_plan SCENE.toml PLAN.csv\n");
    return 2;
  }
  nanopush_scene scene = scene_argument(argc, argv, err, "capi_test_plan");
  CHECK(scene != NULL);
  const double goal[3] = {60e-9, 40e-9, 0.3}, tol[2] = {2e-9, 0.02};
  enum { kMax = 10 };
  double pushes[kMax * NANOPUSH_PLAN_PUSH_SIZE], summary[NANOPUSH_PLAN_SUMMARY_SIZE];
  int n = -1;
  CHECK(nanopush_plan(err, scene, goal, tol, "pushes", kMax, kMax, pushes, &n, summary) == NANOPUSH_OK);
  CHECK(n >= 1 && n <= kMax);
  CHECK(summary[0] == 1.0 && summary[1] == 1.0); /* found, verified */
  CHECK(summary[5] <= tol[0] && summary[6] <= tol[1]);
  if (n >= 1) /* the chain ends where its last push leaves the bar */
    CHECK(memcmp(&pushes[(n - 1) * NANOPUSH_PLAN_PUSH_SIZE + 5], &summary[2], 3 * sizeof(double)) == 0);
  /* The command line's plan.csv, bit for bit. */
  double cli[kMax * NANOPUSH_PLAN_PUSH_SIZE];
  const int m = read_plan_csv(argv[2], cli, kMax);
  CHECK(m == n);
  if (m == n && n > 0) CHECK(memcmp(cli, pushes, (size_t)n * NANOPUSH_PLAN_PUSH_SIZE * sizeof(double)) == 0);

  /* A robust plan (plan --robust): found and verified in every world; with no worlds given it is
   * nanopush_plan's plan bit for bit. */
  {
    const double range[2] = {0.0, 0.3}, shift[3] = {0.6e-9, 0.6e-9, 0.004};
    double rp[kMax * NANOPUSH_PLAN_PUSH_SIZE], rs[NANOPUSH_PLAN_SUMMARY_SIZE];
    int rn = -1;
    CHECK(nanopush_plan_robust(err, scene, goal, tol, NULL, kMax, range, shift, kMax, rp, &rn, rs) == NANOPUSH_OK);
    CHECK(rn >= 1 && rs[0] == 1.0 && rs[1] == 1.0);
    CHECK(nanopush_plan_robust(err, scene, goal, tol, "pushes", kMax, NULL, NULL, kMax, rp, &rn, rs) == NANOPUSH_OK);
    CHECK(rn == n && memcmp(rp, pushes, (size_t)n * NANOPUSH_PLAN_PUSH_SIZE * sizeof(double)) == 0);
    const double reversed[2] = {0.3, 0.1};
    int untouched_rn = -7;
    char rmsg[512];
    CHECK(nanopush_plan_robust(err, scene, goal, tol, NULL, kMax, reversed, NULL, kMax, rp, &untouched_rn, NULL) ==
          NANOPUSH_BAD_INPUT);
    nanopush_get_error(err, rmsg, sizeof rmsg);
    /* the library's --tip-mu-range named as this function's argument */
    CHECK(strstr(rmsg, "tip_mu_range = 0.3:0.1: ") == rmsg && untouched_rn == -7);
    nanopush_clear_error(err);
  }

  /* Bad input: the status, the argument named, nothing written. */
  int untouched = -7;
  char msg[512];
  CHECK(nanopush_plan(err, scene, goal, tol, NULL, 0, kMax, pushes, &untouched, NULL) == NANOPUSH_BAD_INPUT);
  nanopush_get_error(err, msg, sizeof msg);
  CHECK(strstr(msg, "max_pushes") != NULL && untouched == -7);
  nanopush_clear_error(err);
  CHECK(nanopush_plan(err, scene, goal, tol, "fastest", kMax, kMax, pushes, &untouched, NULL) == NANOPUSH_BAD_INPUT);
  nanopush_get_error(err, msg, sizeof msg);
  CHECK(strstr(msg, "objective = fastest: ") == msg && untouched == -7);
  nanopush_clear_error(err);
  /* What the library names by `nanopush plan`'s flags (--goal, --tolerance) is named as this
   * function's arguments. */
  const double nan_goal[3] = {NAN, 0.0, 0.0};
  CHECK(nanopush_plan(err, scene, nan_goal, tol, NULL, kMax, kMax, pushes, &untouched, NULL) == NANOPUSH_BAD_INPUT);
  nanopush_get_error(err, msg, sizeof msg);
  CHECK(strstr(msg, "goal = nan,0,0: must be three finite numbers") == msg && untouched == -7);
  nanopush_clear_error(err);
  const double bad_tol[2] = {-1.0, 0.01};
  CHECK(nanopush_plan(err, scene, goal, bad_tol, NULL, kMax, kMax, pushes, &untouched, NULL) == NANOPUSH_BAD_INPUT);
  nanopush_get_error(err, msg, sizeof msg);
  CHECK(strstr(msg, "tolerance = -1 m: ") == msg && untouched == -7);
  nanopush_clear_error(err);
  CHECK(nanopush_plan(err, scene, goal, tol, NULL, kMax, kMax - 1, pushes, &untouched, NULL) == NANOPUSH_BUFFER_TOO_SMALL);
  CHECK(untouched == -7);
  nanopush_clear_error(err);
  CHECK(nanopush_plan(err, scene, NULL, tol, NULL, kMax, kMax, pushes, &untouched, NULL) == NANOPUSH_NULL_HANDLE);
  nanopush_clear_error(err);
  CHECK(nanopush_plan(err, NULL, goal, tol, NULL, kMax, kMax, pushes, &untouched, NULL) == NANOPUSH_NULL_HANDLE);
  CHECK(untouched == -7);
  nanopush_clear_error(err);
  /* A goal out of reach in one push: not an error; found = 0, the best plan given. */
  const double far[3] = {400e-9, -300e-9, 1.2};
  CHECK(nanopush_plan(err, scene, far, tol, NULL, 1, 1, pushes, &n, summary) == NANOPUSH_OK);
  CHECK(summary[0] == 0.0 && n <= 1 && summary[5] > tol[0]);

  nanopush_delete_scene(&scene);
  nanopush_delete_error(&err);
  return finish("capi plan: all checks hold");
}
