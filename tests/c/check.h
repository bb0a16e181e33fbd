/* Shared checks and fixtures of the C tests: pass/fail counts, relative tolerances, the
 * status-and-message check of bad calls, and blade A's beam and damper parameters
 * (blade_a.json; the Fortran suites take them from tests/fortran/fixtures.f90 and
 * udmap_damper_params). Each test includes it once and returns check_finish() from main. */
#ifndef UDMAP_TESTS_CHECK_H
#define UDMAP_TESTS_CHECK_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "udmap.h"

static int failures = 0, passes = 0;

/* Counts one check; prints its name when it fails. */
static inline void check(int ok, const char *name) {
  if (ok) {
    passes++;
  } else {
    failures++;
    printf("FAIL %s\n", name);
  }
}

/* |a - b| <= rtol |b| */
static inline int close_to(double a, double b, double rtol) {
  return fabs(a - b) <= rtol * fabs(b);
}

/* check() of |actual - expected| <= rtol |expected|, printing both values when it fails. */
static inline void check_close(double actual, double expected, double rtol, const char *name) {
  int ok = fabs(actual - expected) <= rtol * fabs(expected);
  if (!ok) printf("  got %.17g expected %.17g\n", actual, expected);
  check(ok, name);
}

/* status 2 and a message containing needle */
static inline void check_error(udmap_error err, int status, const char *needle, const char *name) {
  char msg[1024];
  udmap_get_error(err, msg, sizeof msg);
  int ok = status == UDMAP_EINPUT && udmap_check_error(err) == UDMAP_EINPUT && strstr(msg, needle);
  if (!ok) printf("  status %d, message '%s', expected '%s'\n", status, msg, needle);
  check(ok, name);
}

/* Prints the closing count line; the exit status of main: 1 on any failure. */
static inline int check_finish(void) {
  printf("%d passed, %d failed\n", passes, failures);
  return failures != 0;
}

/* Blade A (blade_a.json): 8 neck and 24 airfoil elements. */
static inline udmap_beam_params blade_a_beam_params(void) {
  udmap_beam_params p = {170e9, 8200.0, 0.002, 0.020, 0.008, 0.020, 0.010, 0.021,
                         1.4e-6, 0.120, 0.004, 0.030, 8, 24};
  return p;
}

/* Blade A's asymmetric damper (udmap_damper_params' blade_a_damper_params). */
static inline udmap_asymmetric_params blade_a_damper_params(void) {
  udmap_asymmetric_params p = {900.0, 0.3, 0.026, 0.006, 45.0, 45.0,
                               -6.724e-3, -1.724e-3, -1.068e-3, 3.932e-3,
                               3.268e-3, 1.768e-3, 60e6, 40e6, 80e6, 50e6};
  return p;
}

#endif
