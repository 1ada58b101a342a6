/* C API: nanopush_scene_preset loads the file the command line's preset rule finds (the runs
 * agree bit for bit with nanopush_load_scene of that file), from scenes_dir or
 * $NANOPUSH_SCENES, and refuses what it cannot find naming the preset and the directory.
 * Usage: capi_test_preset SCENES_DIR (drivers/scenes) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nanopush.h"

#include "check.h"

/* Run with the scene's own settings; the rows (caller frees), their count in *n; NULL on failure. */
static double* run(nanopush_scene s, int* n) {
  nanopush_error err = nanopush_new_error();
  double* d = NULL;
  nanopush_trajectory t = nanopush_run_scene(err, s, "cxx", NULL, 0.0, -1.0);
  if (t && nanopush_trajectory_get_size(err, t, n) == NANOPUSH_OK) {
    d = malloc(sizeof(double) * (size_t)(*n) * NANOPUSH_TRAJECTORY_COLUMNS);
    if (nanopush_trajectory_get_data(err, t, *n, d) != NANOPUSH_OK) {
      free(d);
      d = NULL;
    }
  }
  nanopush_delete_trajectory(&t);
  nanopush_delete_error(&err);
  return d;
}

/* The preset and the file give the same runs, bit for bit. */
static void same_as_file(nanopush_scene preset, const char* file) {
  nanopush_error err = nanopush_new_error();
  nanopush_scene loaded = nanopush_load_scene(err, file);
  CHECK(loaded != NULL);
  CHECK(preset != NULL);
  if (loaded && preset) {
    int na = 0, nb = 0;
    double* a = run(preset, &na);
    double* b = run(loaded, &nb);
    CHECK(a && b && na == nb && na > 1);
    if (a && b && na == nb) CHECK(memcmp(a, b, sizeof(double) * (size_t)na * NANOPUSH_TRAJECTORY_COLUMNS) == 0);
    free(a);
    free(b);
  }
  nanopush_delete_scene(&loaded);
  nanopush_delete_error(&err);
}

/* The call failed with `status` and a message containing each of the texts. */
static void expect_error(nanopush_scene s, nanopush_error err, int status, const char* text1, const char* text2) {
  char buf[1024];
  CHECK(s == NULL);
  CHECK(nanopush_check_error(err) == status);
  nanopush_get_error(err, buf, sizeof buf);
  if (!strstr(buf, text1) || (text2 && !strstr(buf, text2))) {
    fprintf(stderr, "message: %s\nexpected: %s ... %s\n", buf, text1, text2 ? text2 : "");
    ++failures;
  }
  nanopush_clear_error(err);
}

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  const char* dir = argv[1];
  char file[4096];
  nanopush_error err = nanopush_new_error();
  unsetenv("NANOPUSH_SCENES");

  /* By bare name (found in thesis/) and by path under the directory: the same file. */
  snprintf(file, sizeof file, "%s/thesis/fig3_6c.toml", dir);
  nanopush_scene s = nanopush_scene_preset(err, "fig3_6c", dir);
  CHECK(nanopush_check_error(err) == NANOPUSH_OK);
  same_as_file(s, file);
  char name[64];
  CHECK(s && nanopush_scene_get_name(err, s, name, sizeof name) > 0);
  nanopush_delete_scene(&s);
  s = nanopush_scene_preset(err, "thesis/fig3_18", dir);
  snprintf(file, sizeof file, "%s/thesis/fig3_18.toml", dir);
  same_as_file(s, file);
  nanopush_delete_scene(&s);

  /* scenes_dir NULL or "": $NANOPUSH_SCENES. */
  setenv("NANOPUSH_SCENES", dir, 1);
  s = nanopush_scene_preset(err, "fig3_18", NULL);
  same_as_file(s, file);
  nanopush_delete_scene(&s);
  s = nanopush_scene_preset(err, "fig3_18", "");
  same_as_file(s, file);
  nanopush_delete_scene(&s);

  /* What cannot be found: named, with the directory looked in. */
  s = nanopush_scene_preset(err, "fig9_99", dir);
  expect_error(s, err, NANOPUSH_BAD_INPUT, "name = fig9_99: no preset of that name under ", dir);
  s = nanopush_scene_preset(err, "fig9_99", NULL);
  expect_error(s, err, NANOPUSH_BAD_INPUT, "no preset of that name", "$NANOPUSH_SCENES");
  s = nanopush_scene_preset(err, "fig3_6c", "/nonexistent/scenes");
  expect_error(s, err, NANOPUSH_BAD_INPUT, "scenes_dir = /nonexistent/scenes is not a directory", NULL);
  s = nanopush_scene_preset(err, "", dir);
  expect_error(s, err, NANOPUSH_BAD_INPUT, "name = \"\"", NULL);
  s = nanopush_scene_preset(err, NULL, dir);
  expect_error(s, err, NANOPUSH_NULL_HANDLE, "name", NULL);
  /* No directory given, no $NANOPUSH_SCENES: the installed presets beside this program
   * (<dir>/../share/nanopush/scenes), which a build tree does not have. */
  unsetenv("NANOPUSH_SCENES");
  s = nanopush_scene_preset(err, "fig3_6c", NULL);
  expect_error(s, err, NANOPUSH_BAD_INPUT, "the installed presets = ", "share/nanopush/scenes is not a directory");
  /* A NULL error handle: the status alone (NULL scene), no crash. */
  CHECK(nanopush_scene_preset(NULL, "fig9_99", dir) == NULL);

  nanopush_delete_error(&err);
  return finish("capi preset: all checks hold");
}
