/* What the C tests of the C API share: CHECK(cond) counts a failed condition in `failures`
 * (one counter per test program) and reports where it failed. */
#ifndef NANOPUSH_TEST_CHECK_H
#define NANOPUSH_TEST_CHECK_H
#include <stdio.h>

static int failures = 0;
#define CHECK(cond)                                                         \
  do {                                                                      \
    if (!(cond)) {                                                          \
      ++failures;                                                           \
      fprintf(stderr, "FAIL %s:%d: %s\n", __FILE__, __LINE__, #cond);       \
    }                                                                       \
  } while (0)

#endif
