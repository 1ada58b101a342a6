/* C API: nanopush_scene_set_real / _string change exactly what an edited scene file changes
 * (the runs agree bit for bit), and refuse bad keys and values with the key named, leaving
 * the scene unchanged. Usage: capi_test_scene_set fig3_18.toml */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nanopush.h"

#include "check.h"

static char* read_file(const char* path) {
  FILE* f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char* s = malloc((size_t)n + 1);
  if (fread(s, 1, (size_t)n, f) != (size_t)n) n = 0;
  s[n] = 0;
  fclose(f);
  return s;
}

/* Replace the first line starting with `from` by `to` (same buffer when to is not longer). */
static void edit_line(char* text, const char* from, const char* to) {
  char* at = strstr(text, from);
  if (!at) {
    fprintf(stderr, "no line %s\n", from);
    exit(1);
  }
  char* end = strchr(at + 1, '\n'); /* the end of the line `from` starts */
  size_t rest = strlen(end);
  memcpy(at, to, strlen(to));
  memmove(at + strlen(to), end, rest + 1);
}

/* Run and return the trajectory rows (caller frees); rows in *n. */
static double* run(nanopush_error err, nanopush_scene s, int* n) {
  nanopush_trajectory t = nanopush_run_scene(err, s, "cxx", "faithful", 0.0, -1.0);
  if (!t) return NULL;
  nanopush_trajectory_get_size(err, t, n);
  double* d = malloc(sizeof(double) * (size_t)(*n) * NANOPUSH_TRAJECTORY_COLUMNS);
  nanopush_trajectory_get_data(err, t, *n, d);
  nanopush_delete_trajectory(&t);
  return d;
}

static int message_starts(nanopush_error err, const char* prefix) {
  char buf[512];
  nanopush_get_error(err, buf, sizeof buf);
  if (strncmp(buf, prefix, strlen(prefix)) != 0) {
    fprintf(stderr, "message: %s\nexpected: %s...\n", buf, prefix);
    return 0;
  }
  return 1;
}

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  nanopush_error err = nanopush_new_error();
  nanopush_scene set = nanopush_load_scene(err, argv[1]);
  CHECK(set != NULL);
  CHECK(nanopush_scene_set_real(err, set, "surface.mu", 0.1) == NANOPUSH_OK);
  CHECK(nanopush_scene_set_string(err, set, "push.yn", "20e-9") == NANOPUSH_OK);
  CHECK(nanopush_scene_set_string(err, set, "surface.law", "thesis") == NANOPUSH_OK);

  char* text = read_file(argv[1]);
  CHECK(text != NULL);
  edit_line(text, "\nmu = 0.06", "\nmu = 0.1");
  edit_line(text, "\nyn = 45e-9", "\nyn = 20e-9");
  nanopush_scene edited = nanopush_parse_scene(err, text, argv[1]);
  CHECK(edited != NULL);

  int na = 0, nb = 0;
  double* a = run(err, set, &na);
  double* b = run(err, edited, &nb);
  CHECK(a && b && na == nb && na > 1);
  if (a && b && na == nb)
    CHECK(memcmp(a, b, sizeof(double) * (size_t)na * NANOPUSH_TRAJECTORY_COLUMNS) == 0);

  /* Bad input: the key named, the scene unchanged (the run gives the same bits again). */
  CHECK(nanopush_scene_set_real(err, set, "surface.muu", 0.1) == NANOPUSH_BAD_INPUT);
  CHECK(message_starts(err, "surface.muu = 0.1: unknown scene key"));
  nanopush_clear_error(err);
  CHECK(nanopush_scene_set_real(err, set, "surface.mu", 11.0) == NANOPUSH_BAD_INPUT);
  CHECK(message_starts(err, "surface.mu = 11: must be in [0, 10]"));
  nanopush_clear_error(err);
  CHECK(nanopush_scene_set_string(err, set, "surface.law", "stick") == NANOPUSH_BAD_INPUT);
  CHECK(message_starts(err, "surface.law = \"stick\": must be one of: thesis, printed, coulomb"));
  nanopush_clear_error(err);
  CHECK(nanopush_scene_set_string(err, set, "surface.mu", "abc") == NANOPUSH_BAD_INPUT);
  CHECK(message_starts(err, "surface.mu = abc: must be a number"));
  nanopush_clear_error(err);
  CHECK(nanopush_scene_set_real(err, NULL, "surface.mu", 0.1) == NANOPUSH_NULL_HANDLE);
  nanopush_clear_error(err);
  CHECK(nanopush_scene_set_string(err, set, "surface.mu", NULL) == NANOPUSH_NULL_HANDLE);
  nanopush_clear_error(err);
  int nc = 0;
  double* c = run(err, set, &nc);
  CHECK(c && nc == na && memcmp(a, c, sizeof(double) * (size_t)na * NANOPUSH_TRAJECTORY_COLUMNS) == 0);

  free(a);
  free(b);
  free(c);
  free(text);
  nanopush_delete_scene(&set);
  nanopush_delete_scene(&edited);
  nanopush_delete_error(&err);
  return finish("capi scene_set: all checks hold");
}
