/* nanopush_compare from C: the verdict of `nanopush compare` (compare_engines) on a thesis
 * preset, its figures within the tolerance, and bad settings as statuses. Usage: SCENE.toml */
#include <math.h>
#include <stdio.h>

#include "nanopush.h"

#include "check.h"

int main(int argc, char** argv) {
  nanopush_error err = nanopush_new_error();
  nanopush_scene scene = scene_argument(argc, argv, err, "test_capi_compare");
  CHECK(scene != NULL);
  int agree = -1, kind = -1;
  double figures[9];
  const double rtol = 1e-10;
  CHECK(nanopush_compare(err, scene, NULL, NULL, rtol, -1.0, 0.0, &agree, &kind, figures) == NANOPUSH_OK);
  CHECK(agree == 1 && kind == 0);
  for (int c = 0; c < 9; ++c) CHECK(figures[c] >= 0.0 && figures[c] <= 100 * rtol);
  /* faithful takes the F77 engine's steps to the last bit: even a 1e-300 tolerance holds. */
  CHECK(nanopush_compare(err, scene, "faithful", "", rtol, -1.0, 1e-300, &agree, NULL, figures) == NANOPUSH_OK);
  CHECK(agree == 1);
  for (int c = 0; c < 9; ++c) CHECK(figures[c] == 0.0);
  /* Bad settings: statuses with a message naming the value. */
  char msg[256];
  CHECK(nanopush_compare(err, scene, "cvode", NULL, 0.0, -1.0, 0.0, &agree, NULL, NULL) == NANOPUSH_BAD_INPUT);
  CHECK(nanopush_get_error(err, msg, sizeof msg) > 0);
  CHECK(nanopush_compare(err, scene, NULL, NULL, NAN, -1.0, 0.0, &agree, NULL, NULL) == NANOPUSH_BAD_INPUT);
  CHECK(nanopush_compare(err, scene, NULL, NULL, 0.0, -1.0, 0.0, NULL, NULL, NULL) == NANOPUSH_NULL_HANDLE);
  CHECK(nanopush_compare(err, NULL, NULL, NULL, 0.0, -1.0, 0.0, &agree, NULL, NULL) == NANOPUSH_NULL_HANDLE);
  nanopush_delete_scene(&scene);
  nanopush_delete_error(&err);
  return finish("capi compare: ok");
}
