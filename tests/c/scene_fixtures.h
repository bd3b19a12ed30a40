/* Shared fixtures of the scene and index C tests: the unit cube, a sliding motion and a
 * time check. Header-only; include once per test program. */
#ifndef PCCD_TEST_SCENE_FIXTURES_H
#define PCCD_TEST_SCENE_FIXTURES_H

#include <string.h>

#include "polyccd.h"

/* The unit cube [0,1]^3 as 12 outward triangles. Vertex k is (k & 1, (k >> 1) & 1,
 * k >> 2): the face x = 1 has vertices 1, 3, 5, 7 and triangles 10 = (1, 3, 5),
 * 11 = (3, 7, 5); the face x = 0 has vertices 0, 2, 4, 6 and triangles 8 = (0, 4, 2),
 * 9 = (2, 4, 6). */
static const double kCubeV[24] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                                  0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
static const unsigned int kCubeT[36] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                        2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};

/* Whether time `which` (0 lo, 1 hi, 2 exact) of the report entry reads exactly `want`. */
static inline int time_is(const pccd_report *rep, size_t pair, size_t contact, int which,
                          const char *want)
{
  char buf[64];
  size_t needed = 0;
  return pccd_report_time(rep, pair, contact, which, buf, sizeof buf, &needed) == PCCD_OK &&
         strcmp(buf, want) == 0 && needed == strlen(want) + 1;
}

/* A translation along x from x0 at t = 0 to x1 at t = 1 (NULL on failure). */
static inline pccd_motion *slide_x(double x0, double x1)
{
  pccd_motion *m = NULL;
  const double c[2] = {x0, x1 - x0};
  if (pccd_motion_new(&m) != PCCD_OK) return NULL;
  if (pccd_motion_set_translation_d(m, 0, c, 2) != PCCD_OK) {
    pccd_motion_free(m);
    return NULL;
  }
  return m;
}

/* A motion whose rotation quaternion r(t) = 1 - 2t vanishes at t = 1/2 (NULL on
 * failure): every call that takes a motion must refuse it. */
static inline pccd_motion *vanishing(void)
{
  pccd_motion *m = NULL;
  const char *w[2] = {"1", "-2"};
  if (pccd_motion_new(&m) != PCCD_OK) return NULL;
  if (pccd_motion_set_rotation_s(m, 0, w, 2) != PCCD_OK) {
    pccd_motion_free(m);
    return NULL;
  }
  return m;
}

#endif
