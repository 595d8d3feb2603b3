/* The C API tests' one assertion and their verdict, for C99 and C++ alike (these programs use no
 * test framework: they are built with the library alone). CHECK counts a failure and goes on, so
 * one run lists every failing check with its file and line; check_verdict ends main.
 * Include it once per program. */
#ifndef FRAGSIM_TESTS_CHECK_H
#define FRAGSIM_TESTS_CHECK_H

#include <stdio.h>

static int failures = 0;

#define CHECK(cond)                                                            \
  do {                                                                         \
    if (!(cond)) {                                                             \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
      ++failures;                                                              \
    }                                                                          \
  } while (0)

/* main's exit status: 0 when every check passed; says so, or how many failed, under name. */
static inline int check_verdict(const char* name) {
  if (failures != 0) {
    fprintf(stderr, "%s: %d checks failed\n", name, failures);
    return 1;
  }
  printf("%s: all checks passed\n", name);
  return 0;
}

#endif
