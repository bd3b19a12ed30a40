/*
 * motion_check.h -- a helper shared by the motion and chain C tests (tests/c/test_motion.c,
 * tests/c/test_chain.c): compares a body point's exact position at t with a string.
 * Positions are compared as strings: the library prints canonical "p/q" (lowest terms,
 * positive denominator, "p" for integers), so equal rationals give equal strings.
 */
#ifndef PCCD_TESTS_MOTION_CHECK_H
#define PCCD_TESTS_MOTION_CHECK_H

#include <stdio.h>
#include <string.h>

#include "polyccd.h"

/* The position of body point p = (p0, p1, p2) at t equals `want` ("x y z"). */
static inline int position_is(const pccd_motion *m, const char *p0, const char *p1,
                              const char *p2, const char *t, const char *want)
{
  const char *p[3];
  char buf[4096];
  p[0] = p0;
  p[1] = p1;
  p[2] = p2;
  if (pccd_motion_position_s(m, p, t, buf, sizeof buf, NULL) != PCCD_OK) return 0;
  if (strcmp(buf, want) == 0) return 1;
  printf("     position at t = %s: got \"%s\", want \"%s\"\n", t, buf, want);
  return 0;
}

#endif
