/*
 * test_motion_between.c -- pccd_motion_set_between_d / _s / _matrices_d through the C API:
 * the end poses and a midpoint of the stated path (r(t) = (1 - t) q0 + t q1', q0 . q1' >= 0),
 * the same motion in every rounding mode, and each error with its place. The values are
 * worked out by hand below (small integers: the rotations are exact rationals).
 */
#include "check.h"

/* The position of body point p at time t, as the library's "x y z" text. */
static void position(const pccd_motion *m, const char *x, const char *y, const char *z,
                     const char *t, char *buf)
{
  const char *p[3] = {x, y, z};
  OK(pccd_motion_position_s(m, p, t, buf, 256, NULL));
}

static void pairs(void)
{
  /* A quarter turn about z (q1 = (1, 0, 0, 1)) while the origin moves from 0 to (2, 0, 0):
   * (1, 0, 0) ends at (0, 1, 0) + (2, 0, 0); at t = 1/2, r = (1, 0, 0, 1/2): tan(theta/2) =
   * 1/2, R (1, 0, 0) = (3/5, 4/5, 0), plus the origin (1, 0, 0). */
  pccd_motion *m = NULL;
  char buf[256];
  const double p0[3] = {0, 0, 0}, q0[4] = {1, 0, 0, 0}, p1[3] = {2, 0, 0}, q1[4] = {1, 0, 0, 1};
  g_case = "pairs";
  OK(pccd_motion_new(&m));
  OK(pccd_motion_set_between_d(m, p0, q0, p1, q1));
  OK(pccd_motion_validate(m));
  position(m, "1", "0", "0", "1", buf);
  CHECK(strcmp(buf, "2 1 0") == 0);
  position(m, "1", "0", "0", "1/2", buf);
  CHECK(strcmp(buf, "8/5 4/5 0") == 0);
  {
    /* -q1 is the same rotation: the same motion (the shorter way round). */
    const char *s0[3] = {"0", "0", "0"}, *r0[4] = {"1", "0", "0", "0"};
    const char *s1[3] = {"2", "0", "0"}, *r1[4] = {"-1", "0", "0", "-1"};
    OK(pccd_motion_set_between_s(m, s0, r0, s1, r1));
    position(m, "1", "0", "0", "1/2", buf);
    CHECK(strcmp(buf, "8/5 4/5 0") == 0);
  }
  pccd_motion_free(m);
}

static void matrices(void)
{
  /* The same quarter turn as matrices: Shepperd's quaternion of the block is exactly
   * (1/sqrt2, 0, 0, 1/sqrt2) rounded; its rotation maps (1, 0, 0) to within 1e-15 of
   * (0, 1, 0), and the translation is exact. */
  pccd_motion *m = NULL;
  char buf[256];
  const double M0[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const double M1[16] = {0, -1, 0, 2, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double bad[16];
  g_case = "matrices";
  OK(pccd_motion_new(&m));
  OK(pccd_motion_set_between_matrices_d(m, M0, M1));
  position(m, "0", "0", "0", "1", buf);
  CHECK(strcmp(buf, "2 0 0") == 0);
  position(m, "1", "0", "0", "0", buf);
  CHECK(strcmp(buf, "1 0 0") == 0);
  memcpy(bad, M1, sizeof bad);
  bad[13] = 1e-300;
  FAILS(pccd_motion_set_between_matrices_d(m, M0, bad), PCCD_EINVAL, "M1[3][1]");
  memcpy(bad, M1, sizeof bad);
  bad[0] = 0.5;
  FAILS(pccd_motion_set_between_matrices_d(m, bad, M1), PCCD_EINVAL, "M0: the upper-left 3x3");
  FAILS(pccd_motion_set_between_matrices_d(m, NULL, M1), PCCD_EINVAL, "M0");
  /* A failed call leaves the motion as it was. */
  position(m, "0", "0", "0", "1", buf);
  CHECK(strcmp(buf, "2 0 0") == 0);
  pccd_motion_free(m);
}

static void errors(void)
{
  pccd_motion *m = NULL;
  const double p[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0}, zero[4] = {0, 0, 0, 0};
  double nan_p[3] = {0, 0, 0};
  const char *s[3] = {"0", "x", "0"}, *r[4] = {"1", "0", "0", "0"};
  g_case = "errors";
  nan_p[1] = strtod("nan", NULL);
  OK(pccd_motion_new(&m));
  FAILS(pccd_motion_set_between_d(NULL, p, q, p, q), PCCD_EINVAL, "m");
  FAILS(pccd_motion_set_between_d(m, p, q, p, zero), PCCD_EINVAL, "q1: the zero quaternion");
  FAILS(pccd_motion_set_between_d(m, p, q, nan_p, q), PCCD_EINVAL, "p1[1]");
  FAILS(pccd_motion_set_between_d(m, p, NULL, p, q), PCCD_EINVAL, "q0");
  FAILS(pccd_motion_set_between_s(m, s, r, s, r), PCCD_EINVAL, "p0[1]");
  pccd_motion_free(m);
}

static void cases(void)
{
  pairs();
  matrices();
  errors();
}

int main(void) { return run_in_every_mode(cases); }
