/* What the C tests of the C API share: CHECK(cond) counts a failed condition in `failures`
 * (one counter per test program) and reports where it failed; scene_argument() loads the scene
 * the program is given, message_has() reads and clears an error's message, and finish() gives the
 * exit status and the closing line. */
#ifndef NANOPUSH_TEST_CHECK_H
#define NANOPUSH_TEST_CHECK_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nanopush.h"

static int failures = 0;
#define CHECK(cond)                                                         \
  do {                                                                      \
    if (!(cond)) {                                                          \
      ++failures;                                                           \
      fprintf(stderr, "FAIL %s:%d: %s\n", __FILE__, __LINE__, #cond);       \
    }                                                                       \
  } while (0)

/* The scene named by the program's one argument, argv[1]; without one, a usage line
 * "usage: PROGRAM SCENE.toml" and exit status 2. */
static inline nanopush_scene scene_argument(int argc, char** argv, nanopush_error err, const char* program) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s SCENE.toml\n", program);
    exit(2);
  }
  return nanopush_load_scene(err, argv[1]);
}

/* Whether the error's message contains `needle`; prints "label: message" first (label NULL: not
 * printed) and clears the error. */
static inline int message_has(nanopush_error err, const char* label, const char* needle) {
  char msg[256];
  nanopush_get_error(err, msg, (int)sizeof msg);
  if (label) printf("%s: %s\n", label, msg);
  const int found = strstr(msg, needle) != NULL;
  nanopush_clear_error(err);
  return found;
}

/* The program's exit status: 1, with the number of failed checks on standard error, or 0 with
 * `passed` (the line its CTest test looks for) on standard output. */
static inline int finish(const char* passed) {
  if (failures) {
    fprintf(stderr, "%d check(s) failed\n", failures);
    return 1;
  }
  printf("%s\n", passed);
  return 0;
}

#endif
