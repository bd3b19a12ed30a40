/*
 * test_motion.c -- the rigid-motion part of the C API (pccd_motion_*), through motions
 * whose positions are known by construction, and every error path of that section of
 * include/polyccd.h.
 *
 * Plain C99 (built with -std=c99 -Wall -Wextra -Werror). Prints every failed check with
 * the case name, then "N passed, N failed"; exit status 0 only when nothing failed.
 * Every handle is freed (valgrind-clean). The known-answer cases run under each IEEE
 * rounding mode: answers are exact rationals, so the strings must be identical in every
 * mode, and no call may change the mode (house style 21, 39).
 *
 * Positions are compared as strings: the library prints canonical "p/q" (lowest terms,
 * positive denominator, "p" for integers), so equal rationals give equal strings. Every
 * expected value is derived in a comment next to it.
 */
#include "polyccd.h"

#include <fenv.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "motion_check.h"

#define POS(m, p0, p1, p2, t, want) CHECK(position_is((m), (p0), (p1), (p2), (t), (want)))

static void known_answers(void)
{
  pccd_motion *m = NULL, *c = NULL;
  static const char *const z_axis[3] = {"0", "0", "1"}, *const c100[3] = {"1", "0", "0"};

  g_case = "identity";
  OK(pccd_motion_new(&m));
  POS(m, "1", "-2/3", "0.5", "1/2", "1 -2/3 1/2");
  OK(pccd_motion_validate(m));

  g_case = "polynomial translation and rotation";
  {
    /* o = (t, 0, 1 - t^2); r = 1 + t k: at t = 1, r = 1 + k, a quarter turn about z
     * (tan(theta/2) = 1), so (1, 0, 0) -> (0, 1, 0), plus o(1) = (1, 0, 0). */
    const double ox[2] = {0, 1}, oz[3] = {1, 0, -1};
    const char *const rz[2] = {"0", "1"};
    OK(pccd_motion_set_translation_d(m, 0, ox, 2));
    OK(pccd_motion_set_translation_d(m, 2, oz, 3));
    OK(pccd_motion_set_rotation_s(m, 3, rz, 2));
    POS(m, "1", "0", "0", "1", "1 1 0");
    /* t = 1/2: r = 1 + k/2, W = 5/4; R(1,0,0) = ((1 - 1/4), 2 * 1/2, 0) / (5/4) = (3/5, 4/5, 0);
     * o = (1/2, 0, 3/4). */
    POS(m, "1", "0", "0", "1/2", "11/10 4/5 3/4");
    OK(pccd_motion_validate(m));
  }

  g_case = "copy is independent";
  OK(pccd_motion_copy(&c, m));
  OK(pccd_motion_set_translation_d(m, 0, NULL, 0)); /* x translation := 0 */
  POS(c, "1", "0", "0", "1", "1 1 0");
  POS(m, "1", "0", "0", "1", "0 1 0");
  pccd_motion_free(c);
  c = NULL;

  g_case = "linear translation keeps the rotation";
  {
    const double p0[3] = {1, 2, 3}, p1[3] = {3, 2, -1};
    static const char *const s0[3] = {"0", "0", "0"}, *const s1[3] = {"1/3", "0", "0"};
    OK(pccd_motion_set_linear_translation_d(m, p0, p1));
    POS(m, "1", "0", "0", "1", "3 3 -1"); /* (0,1,0) + (3,2,-1) */
    POS(m, "0", "0", "0", "1/2", "2 2 1");
    OK(pccd_motion_new(&c));
    OK(pccd_motion_set_linear_translation_s(c, s0, s1));
    POS(c, "0", "0", "0", "1", "1/3 0 0");
    pccd_motion_free(c);
    c = NULL;
  }

  g_case = "bezier";
  {
    /* c0 = 0, c1 = (1,0,0), c2 = (1,1,0), c3 = (0,1,0): B(1/2) = (3 c1 + 3 c2 + c3) / 8
     * + c0/8 = (6/8, 4/8, 0). */
    const double ctrl[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    OK(pccd_motion_new(&c));
    OK(pccd_motion_set_bezier_translation_d(c, ctrl));
    POS(c, "0", "0", "0", "0", "0 0 0");
    POS(c, "0", "0", "0", "1", "0 1 0");
    POS(c, "0", "0", "0", "1/2", "3/4 1/2 0");
  }

  g_case = "hermite";
  {
    /* p0 = 0, v0 = (1,0,0), p1 = (1,1,1), v1 = 0: h(1/2) = v0/8 + p1/2 + 0 = (5/8, 1/2, 1/2)
     * with the basis h10(1/2) = 1/8, h01(1/2) = 1/2. */
    const double p0[3] = {0, 0, 0}, v0[3] = {1, 0, 0}, p1[3] = {1, 1, 1}, v1[3] = {0, 0, 0};
    OK(pccd_motion_set_hermite_translation_d(c, p0, v0, p1, v1));
    POS(c, "0", "0", "0", "1", "1 1 1");
    POS(c, "0", "0", "0", "1/2", "5/8 1/2 1/2");
  }

  g_case = "axis rotation";
  /* About z through (1, 0, 0), tau 0 -> 1: a quarter turn at t = 1, so (2,0,0) -> (1,1,0);
   * (1, 0, 7) is on the axis and stays. */
  OK(pccd_motion_set_axis_rotation_s(c, z_axis, c100, "0", "1"));
  POS(c, "2", "0", "0", "1", "1 1 0");
  POS(c, "1", "0", "7", "1/3", "1 0 7");
  POS(c, "2", "0", "0", "0", "2 0 0");
  OK(pccd_motion_validate(c));

  g_case = "screw";
  /* The same plus advance 3 along (0,0,1): z grows by 3 t. */
  OK(pccd_motion_set_screw_s(c, z_axis, c100, "0", "1", "3"));
  POS(c, "2", "0", "0", "1", "1 1 3");
  POS(c, "1", "0", "0", "1/2", "1 0 3/2");

  g_case = "compose";
  {
    /* Body side: the pose (quarter turn about z, offset (0,0,1)) first, then the screw
     * at t = 1: (1,0,0) -> (0,1,1) -> rotate about the axis through (1,0,0): (0,1) - (1,0)
     * = (-1,1) -> (-1,-1) + (1,0) = (0,-1); z 1 + 3 = 4. */
    static const char *const q[4] = {"1", "0", "0", "1"}, *const off[3] = {"0", "0", "1"};
    static const char *const half[4] = {"0", "0", "0", "2"}, *const shift[3] = {"5", "0", "0"};
    OK(pccd_motion_compose_pose_s(c, PCCD_POSE_BODY, q, off));
    POS(c, "1", "0", "0", "1", "0 -1 4");
    /* World side: a half turn about z (q = 2k, any length) takes (0, -1, 4) to
     * (0, 1, 4), then + (5, 0, 0). */
    OK(pccd_motion_compose_pose_s(c, PCCD_POSE_WORLD, half, shift));
    POS(c, "1", "0", "0", "1", "5 1 4");
  }

  g_case = "validate";
  {
    /* w = t - 1/2, x = 2t - 1, y = z = 0: common root 1/2. */
    const char *const w[2] = {"-1/2", "1"}, *const x[2] = {"-1", "2"};
    const char *const w2[3] = {"-1/2", "0", "1"};
    pccd_motion_free(m);
    OK(pccd_motion_new(&m));
    OK(pccd_motion_set_rotation_s(m, 0, w, 2));
    OK(pccd_motion_set_rotation_s(m, 1, x, 2));
    FAILS(pccd_motion_validate(m), PCCD_EINVAL, "vanishes at t = 1/2");
    FAILS(pccd_motion_position_s(m, c100, "1/2", NULL, 0, NULL), PCCD_EINVAL, "t = 1/2");
    /* w = t^2 - 1/2 alone: vanishes at 1/sqrt(2), irrational. */
    OK(pccd_motion_set_rotation_s(m, 1, NULL, 0));
    OK(pccd_motion_set_rotation_s(m, 0, w2, 3));
    FAILS(pccd_motion_validate(m), PCCD_EINVAL, "irrational time t with 7");
    /* x = 2t - 1 and w = 1: no common root although x has one. */
    OK(pccd_motion_set_rotation_s(m, 0, c100, 1));
    OK(pccd_motion_set_rotation_s(m, 1, x, 2));
    OK(pccd_motion_validate(m));
    OK(pccd_motion_set_rotation_d(m, 0, NULL, 0));
    OK(pccd_motion_set_rotation_d(m, 1, NULL, 0));
    FAILS(pccd_motion_validate(m), PCCD_EINVAL, "zero polynomial");
  }
  pccd_motion_free(m);
  pccd_motion_free(c);
}

static void error_paths(void)
{
  pccd_motion *m = NULL, *c = NULL;
  const double nan_coeffs[2] = {0, NAN}, big[66] = {0};
  static const char *const bad[2] = {"0", "1/0"}, *const zero3[3] = {"0", "0", "0"};
  static const char *const one_q[4] = {"1", "0", "0", "0"}, *const zero_q[4] = {"0", "0", "0", "0"};
  static const char *const bad3[3] = {"0", "abc", "0"}, *const e1[3] = {"1", "0", "0"};
  char buf[8] = "keep";
  size_t needed = 0;

  g_case = "errors";
  FAILS(pccd_motion_new(NULL), PCCD_EINVAL, "out");
  pccd_motion_free(NULL);
  OK(pccd_motion_new(&m));
  FAILS(pccd_motion_copy(NULL, m), PCCD_EINVAL, "out");
  c = m; /* must be reset to NULL on error */
  FAILS(pccd_motion_copy(&c, NULL), PCCD_EINVAL, "pccd_motion_copy: m: is NULL");
  CHECK(c == NULL);
  FAILS(pccd_motion_set_translation_d(NULL, 0, NULL, 0), PCCD_EINVAL, "m: is NULL");
  FAILS(pccd_motion_set_translation_d(m, 3, NULL, 0), PCCD_EINVAL, "pccd_motion_set_translation_d: axis: 3 out of range");
  FAILS(pccd_motion_set_rotation_d(m, 4, NULL, 0), PCCD_EINVAL, "pccd_motion_set_rotation_d: component: 4 out of range");
  FAILS(pccd_motion_set_translation_d(m, 0, NULL, 2), PCCD_EINVAL, "coeffs: is NULL");
  FAILS(pccd_motion_set_translation_d(m, 1, nan_coeffs, 2), PCCD_EINVAL,
        "pccd_motion_set_translation_d: translation[1][1]: NaN");
  FAILS(pccd_motion_set_rotation_s(m, 3, bad, 2), PCCD_EINVAL, "pccd_motion_set_rotation_s: rotation[3][1]: ");
  FAILS(pccd_motion_set_rotation_d(m, 2, big, 66), PCCD_ELIMIT, "pccd_motion_set_rotation_d: rotation[2]: degree 65");
  OK(pccd_motion_set_rotation_d(m, 2, big, 65)); /* degree 64 of zeros: allowed */
  FAILS(pccd_motion_set_linear_translation_s(m, zero3, bad3), PCCD_EINVAL, "pccd_motion_set_linear_translation_s: p1[1]: ");
  FAILS(pccd_motion_set_hermite_translation_s(m, zero3, zero3, zero3, NULL), PCCD_EINVAL, "v1: is NULL");
  FAILS(pccd_motion_set_axis_rotation_s(m, zero3, zero3, "0", "1"), PCCD_EINVAL, "axis: the direction is the zero vector");
  FAILS(pccd_motion_set_axis_rotation_s(m, e1, zero3, "0", "x"), PCCD_EINVAL, "tau1: \"x\"");
  FAILS(pccd_motion_set_screw_s(m, e1, zero3, "0", "1", NULL), PCCD_EINVAL, "advance: is NULL");
  /* Several bad arguments: the first one is named (conversions run in argument order). */
  FAILS(pccd_motion_set_linear_translation_s(m, bad3, bad3), PCCD_EINVAL, "_s: p0[1]: ");
  FAILS(pccd_motion_set_hermite_translation_s(m, bad3, zero3, zero3, NULL), PCCD_EINVAL, "_s: p0[1]: ");
  FAILS(pccd_motion_set_hermite_translation_s(m, zero3, bad3, bad3, bad3), PCCD_EINVAL, "_s: v0[1]: ");
  FAILS(pccd_motion_set_axis_rotation_s(m, bad3, bad3, "x", "x"), PCCD_EINVAL, "_s: axis[1]: ");
  FAILS(pccd_motion_set_axis_rotation_s(m, e1, zero3, "x", "x"), PCCD_EINVAL, "_s: tau0: ");
  FAILS(pccd_motion_set_screw_s(m, e1, bad3, "x", "x", "x"), PCCD_EINVAL, "_s: center[1]: ");
  FAILS(pccd_motion_set_screw_s(m, e1, zero3, "0", "x", "x"), PCCD_EINVAL, "_s: tau1: ");
  FAILS(pccd_motion_compose_pose_s(m, 2, one_q, zero3), PCCD_EINVAL, "side: 2 is not");
  FAILS(pccd_motion_compose_pose_s(m, PCCD_POSE_WORLD, zero_q, zero3), PCCD_EINVAL, "quat: the zero quaternion");
  FAILS(pccd_motion_compose_pose_s(m, PCCD_POSE_BODY, one_q, bad3), PCCD_EINVAL, "pccd_motion_compose_pose_s: offset[1]: ");
  /* On error the motion is unchanged: still the identity. */
  POS(m, "1", "2", "3", "1", "1 2 3");
  FAILS(pccd_motion_position_s(m, e1, "2", buf, sizeof buf, NULL), PCCD_EINVAL, "t: 2 is outside [0, 1]");
  FAILS(pccd_motion_position_s(m, bad3, "0", buf, sizeof buf, NULL), PCCD_EINVAL, "pccd_motion_position_s: p[1]: ");
  FAILS(pccd_motion_position_s(m, e1, NULL, buf, sizeof buf, NULL), PCCD_EINVAL, "pccd_motion_position_s: t: is NULL");

  g_case = "ERANGE protocol";
  /* "1 0 0" needs 6 bytes. */
  FAILS(pccd_motion_position_s(m, e1, "0", buf, 5, &needed), PCCD_ERANGE, "buf: 5 bytes are too few; 6 needed");
  CHECK(needed == 6 && strcmp(buf, "keep") == 0);
  FAILS(pccd_motion_position_s(m, e1, "0", NULL, 0, &needed), PCCD_ERANGE, "buf: 0 bytes are too few");
  OK(pccd_motion_position_s(m, e1, "0", buf, 6, &needed));
  CHECK(needed == 6 && strcmp(buf, "1 0 0") == 0);

  g_case = "ESTATE after a body offset";
  {
    static const char *const off[3] = {"0", "1", "0"};
    const double one = 1;
    OK(pccd_motion_compose_pose_s(m, PCCD_POSE_BODY, one_q, zero3)); /* no offset: fine */
    OK(pccd_motion_set_rotation_d(m, 0, &one, 1));
    OK(pccd_motion_compose_pose_s(m, PCCD_POSE_BODY, one_q, off));
    FAILS(pccd_motion_set_rotation_d(m, 0, &one, 1), PCCD_ESTATE, "body-side pose");
    /* Setting the translation is still allowed and makes the origin's path (0, 0, 0). */
    OK(pccd_motion_set_translation_d(m, 1, NULL, 0));
    POS(m, "0", "0", "0", "1/2", "0 0 0");
  }
  pccd_motion_free(m);

  g_case = "compose";
  {
    static const char *const ez[3] = {"0", "0", "1"}, *const two[3] = {"2", "0", "0"};
    const double half[2] = {-0.5, 1};
    pccd_motion *outer = NULL, *inner = NULL, *bad_r = NULL, *out = NULL;
    OK(pccd_motion_new(&outer));
    OK(pccd_motion_new(&inner));
    OK(pccd_motion_new(&bad_r));
    /* outer: r = 1 + t k (about the z axis through 0, tan(theta/2) = t); inner: the
     * translation 0 -> (2, 0, 0). At t = 1 the origin is at (2, 0, 0), turned by 90
     * degrees: (0, 2, 0). At t = 1/2: (1, 0, 0) turned by theta with tan(theta/2) = 1/2,
     * cos = (1 - 1/4) / (1 + 1/4) = 3/5, sin = 1 / (5/4) = 4/5: (3/5, 4/5, 0). */
    OK(pccd_motion_set_axis_rotation_s(outer, ez, zero3, "0", "1"));
    OK(pccd_motion_set_linear_translation_s(inner, zero3, two));
    OK(pccd_motion_compose(&out, outer, inner));
    POS(out, "0", "0", "0", "1", "0 2 0");
    POS(out, "0", "0", "0", "1/2", "3/5 4/5 0");
    OK(pccd_motion_validate(out));
    /* The rotation turns the translated origin, so it cannot be set any more. */
    FAILS(pccd_motion_set_rotation_d(out, 0, half, 1), PCCD_ESTATE, "composed");
    pccd_motion_free(out);
    out = NULL;
    /* The other order: turn, then translate: (2, 0, 0) at t = 1 for the origin. */
    OK(pccd_motion_compose(&out, inner, outer));
    POS(out, "0", "0", "0", "1", "2 0 0");
    POS(out, "1", "0", "0", "1", "2 1 0");
    pccd_motion_free(out);
    out = outer; /* must be reset to NULL on error */
    FAILS(pccd_motion_compose(NULL, outer, inner), PCCD_EINVAL, "pccd_motion_compose: out: is NULL");
    FAILS(pccd_motion_compose(&out, NULL, inner), PCCD_EINVAL, "pccd_motion_compose: outer: is NULL");
    CHECK(out == NULL);
    FAILS(pccd_motion_compose(&out, outer, NULL), PCCD_EINVAL, "pccd_motion_compose: inner: is NULL");
    /* r(t) = t - 1/2 vanishes at t = 1/2: named as the factor it is. */
    OK(pccd_motion_set_rotation_d(bad_r, 0, half, 2));
    FAILS(pccd_motion_compose(&out, bad_r, inner), PCCD_EINVAL, "pccd_motion_compose: outer: the rotation quaternion");
    FAILS(pccd_motion_compose(&out, outer, bad_r), PCCD_EINVAL, "inner: the rotation quaternion r(t) = w + x i + y j + z k vanishes at t = 1/2");
    CHECK(out == NULL);
    /* Degrees add: r of degree 40 twice gives 80 > PCCD_MAX_TRAJ_DEGREE. */
    {
      double w[41] = {0};
      w[0] = 1;
      w[40] = 1; /* 1 + t^40 > 0 */
      OK(pccd_motion_set_rotation_d(bad_r, 0, w, 41));
      FAILS(pccd_motion_compose(&out, bad_r, bad_r), PCCD_ELIMIT, "outer, inner: the composite motion has a polynomial of degree 80");
      CHECK(out == NULL);
    }
    pccd_motion_free(outer);
    pccd_motion_free(inner);
    pccd_motion_free(bad_r);
  }
}

static void cases(void)
{
  known_answers();
  error_paths();
}

int main(void) { return run_in_every_mode(cases); }
