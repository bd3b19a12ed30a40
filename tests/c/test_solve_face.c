/*
 * test_solve_face.c -- known answers of vertex-face queries (pccd_query_solve,
 * pccd_solve_linear_d): through the centroid, one ulp either side of an edge, 1e-30
 * short, grazing double roots with each config option, contacts at t = 0 and t = 1.
 * Exact times are checked exactly (exact_rational.h through query_check.h).
 *
 * Plain C99 test program (built by `make test-c` with -std=c99 -Wall -Wextra -Werror).
 * Prints every failed check with its case and rounding mode, then a last line
 * "N passed, N failed"; exit status 0 only when nothing failed (PCCD_TEST_VERBOSE=1 also
 * prints the message of every error path checked). Every handle is freed (`make
 * valgrind` runs this program under valgrind and requires 0 leaks). Every case runs
 * under each IEEE rounding mode (check.h, run_in_every_mode, after the no-FMA check):
 * the answers must be the same, and after every API call the rounding mode must still
 * be the one the test set (house style 21 and 39).
 */
#include "polyccd.h"

#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "query_check.h"

/* A vertex falls straight through the centroid (1,1,0) of the static triangle
 * (0,0,0) (3,0,0) (0,3,0): z(t) = 1 - 2t reaches the plane at t = 1/2. Through the three
 * entry points, and scaled by powers of two (exact in doubles) from subnormal 2^-1060 to
 * 2^1000, where products of coordinates under- or overflow any double filter. */
static void case_vertex_face_centre(pccd_result *r)
{
  static const int scales[] = {0, -1060, -600, -30, 30, 600, 1000};
  double p0[12] = {1, 1, 1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double p1[12] = {1, 1, -1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  size_t s, i;
  pccd_query *q;

  g_case = "vertex-face centre, pccd_query_set_coord_s";
  q = mk(PCCD_VERTEX_FACE);
  SETS(q, 0, 0, "1");
  SETS(q, 0, 1, "1");
  SETS(q, 0, 2, "1", "-2");
  triangle_s(q);
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  EXPECT_FEATURE(r, PCCD_VERTEX_FACE, 0, 1, 2, 3);
  FREE_Q(q);

  /* The same numbers written in other exact forms; "010/10" is 1 (decimal, not octal). */
  g_case = "vertex-face centre, number forms";
  q = mk(PCCD_VERTEX_FACE);
  SETS(q, 0, 0, "2/2");
  SETS(q, 0, 1, "1.000");
  SETS(q, 0, 2, "010/10", "-20/10");
  fixed_s(q, 1, "0", "-0", "0.0");
  fixed_s(q, 2, "3.0", "0/7", "0e5");
  fixed_s(q, 3, "0", "30e-1", "0");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  FREE_Q(q);

  g_case = "vertex-face centre, pccd_query_set_coord_d";
  q = mk(PCCD_VERTEX_FACE);
  SETD(q, 0, 0, 1.0);
  SETD(q, 0, 1, 1.0, 0.0); /* a zero t coefficient */
  SETD(q, 0, 2, 1.0, -2.0);
  SETD(q, 2, 0, 3.0);
  SETD(q, 3, 1, 3.0);
  CHECK_RC(API(pccd_query_set_coord_d(q, 1, 2, NULL, 0)), PCCD_OK); /* zero polynomial */
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  EXPECT_FEATURE(r, PCCD_VERTEX_FACE, 0, 1, 2, 3);
  FREE_Q(q);

  for (s = 0; s < sizeof scales / sizeof scales[0]; s++) {
    double a0[12], a1[12];
    static char name[96];
    for (i = 0; i < 12; i++) {
      a0[i] = ldexp(p0[i], scales[s]);
      a1[i] = ldexp(p1[i], scales[s]);
    }
    sprintf(name, "vertex-face centre, scaled by 2^%d, pccd_solve_linear_d", scales[s]);
    g_case = name;
    CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, a0, a1, NULL, r)), PCCD_OK);
    EXPECT_EXACT(r, "1/2", 0.5);
    EXPECT_FEATURE(r, PCCD_VERTEX_FACE, 0, 1, 2, 3);

    sprintf(name, "vertex-face centre, scaled by 2^%d, pccd_query_set_linear_d", scales[s]);
    q = mk(PCCD_VERTEX_FACE);
    CHECK_RC(API(pccd_query_set_linear_d(q, a0, a1)), PCCD_OK);
    CHECK_RC(solve(q, NULL, r), PCCD_OK);
    EXPECT_EXACT(r, "1/2", 0.5);
    FREE_Q(q);
  }
}

/* One ulp either side of the triangle's edge x + y = 3: the vertex crosses the plane at
 * t = 1/2 at (1.5, 1.5 -+ ulp): inside (contact) or outside (none). Only exact arithmetic
 * can tell; y = nextafter(1.5, ...) is exact in every rounding mode. */
static void case_vertex_face_ulp(pccd_result *r)
{
  double in0[12] = {1.5, 0, 1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double in1[12] = {1.5, 0, -1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  g_case = "vertex-face one ulp inside the edge";
  in0[1] = in1[1] = nextafter(1.5, 0.0);
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, in0, in1, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  EXPECT_FEATURE(r, PCCD_VERTEX_FACE, 0, 1, 2, 3);

  g_case = "vertex-face exactly on the edge (1.5, 1.5)";
  in0[1] = in1[1] = 1.5;
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, in0, in1, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  EXPECT_FEATURE(r, PCCD_VERTEX_EDGE, 0, 2, 3, NONE); /* vertex inside the open edge f1 f2 */

  g_case = "vertex-face one ulp outside the edge";
  in0[1] = in1[1] = nextafter(1.5, 2.0);
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, in0, in1, NULL, r)), PCCD_OK);
  EXPECT_NONE(r);

  g_case = "vertex-face through the triangle's vertex f0";
  in0[0] = in1[0] = 0;
  in0[1] = in1[1] = 0;
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, in0, in1, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  EXPECT_FEATURE_VV(r, 0, 1);
}

/* z_v(t) = 1 - t reaches z = 0 at t = 1, but the triangle sits at z = -1e-30: the vertex
 * stops 1e-30 short (no double is involved: "1e-30" is exactly 10^-30). With the
 * triangle at z = +1e-30 instead, the contact is at t = 1 - 10^-30, exactly. */
static void case_vertex_face_1e30(pccd_result *r)
{
  pccd_query *q = mk(PCCD_VERTEX_FACE);
  g_case = "vertex stops 1e-30 short of the face";
  fixed_s(q, 1, "0", "0", "-1e-30");
  fixed_s(q, 2, "3", "0", "-1e-30");
  fixed_s(q, 3, "0", "3", "-1e-30");
  SETS(q, 0, 0, "1");
  SETS(q, 0, 1, "1");
  SETS(q, 0, 2, "1", "-1");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_NONE(r);

  g_case = "vertex reaches the face 1e-30 before t = 1";
  SETS(q, 1, 2, "1e-30");
  SETS(q, 2, 2, "1e-30");
  SETS(q, 3, 2, "1/1000000000000000000000000000000");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  /* 1 - 10^-30; its nearest double is 1 */
  EXPECT_EXACT(r, "999999999999999999999999999999/1000000000000000000000000000000", 1.0);
  EXPECT_FEATURE(r, PCCD_VERTEX_FACE, 0, 1, 2, 3);
  FREE_Q(q);
}

/* Grazing: z_v(t) = (t - 1/3)^2 = 1/9 - 2/3 t + t^2 touches the plane z = 0 with a double
 * root at t = 1/3, at (1,1) inside the triangle. Lifted by 1e-30 it never touches; moved
 * to x = 10 it touches the plane outside the triangle. */
static void case_vertex_face_graze(pccd_result *r)
{
  pccd_query *q = mk(PCCD_VERTEX_FACE);
  pccd_config cfg;
  static rat lo, hi, third, tl;
  char *slo, *shi;
  int rc, rc2, ex = -1;

  g_case = "grazing double root at t = 1/3";
  triangle_s(q);
  SETS(q, 0, 0, "1");
  SETS(q, 0, 1, "1");
  SETS(q, 0, 2, "1/9", "-2/3", "1");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/3", 0x1.5555555555555p-2);
  EXPECT_FEATURE(r, PCCD_VERTEX_FACE, 0, 1, 2, 3);

  /* A rational time is reported exactly whatever the tolerance. */
  g_case = "grazing at t = 1/3, time_tolerance 0.25";
  CHECK_RC(API(pccd_config_init(&cfg)), PCCD_OK);
  cfg.time_tolerance = "0.25";
  CHECK_RC(solve(q, &cfg, r), PCCD_OK);
  EXPECT_EXACT(r, "1/3", 0x1.5555555555555p-2);

  /* want_exact = 0: an enclosure of 1/3 no wider than the default 1e-12. */
  g_case = "grazing at t = 1/3, want_exact = 0";
  CHECK_RC(API(pccd_config_init(&cfg)), PCCD_OK);
  cfg.want_exact = 0;
  CHECK_RC(solve(q, &cfg, r), PCCD_OK);
  CHECK(collides(r) == 1);
  slo = time_str(r, 0, &rc);
  shi = time_str(r, 1, &rc2);
  if (CHECK(rc == PCCD_OK && rc2 == PCCD_OK)) {
    CHECK(rat_parse(&lo, slo) && rat_parse(&hi, shi) && rat_parse(&third, "1/3") &&
          rat_parse(&tl, "1/1000000000000"));
    CHECK(rat_cmp(&lo, &third) <= 0 && rat_cmp(&third, &hi) <= 0);
    CHECK(rat_width_le(&lo, &hi, &tl));
  }
  free(slo);
  free(shi);

  /* want_time = 0: the decision only; the enclosure, if any, still holds 1/3. */
  g_case = "grazing at t = 1/3, want_time = 0";
  CHECK_RC(API(pccd_config_init(&cfg)), PCCD_OK);
  cfg.want_time = 0;
  CHECK_RC(solve(q, &cfg, r), PCCD_OK);
  CHECK(collides(r) == 1);
  check_stage(r);
  slo = time_str(r, 0, &rc);
  shi = time_str(r, 1, &rc2);
  if (rc == PCCD_OK && rc2 == PCCD_OK) {
    CHECK(rat_parse(&lo, slo) && rat_parse(&hi, shi) && rat_parse(&third, "1/3"));
    CHECK(rat_cmp(&lo, &third) <= 0 && rat_cmp(&third, &hi) <= 0);
  }
  free(slo);
  free(shi);
  (void)API(pccd_result_time_is_exact(r, &ex));

  g_case = "grazing lifted by 1e-30";
  /* 1/9 + 10^-30 = (10^30 + 9) / (9 * 10^30) */
  SETS(q, 0, 2, "1000000000000000000000000000009/9000000000000000000000000000000", "-2/3", "1");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_NONE(r);

  g_case = "grazing outside the triangle (x = 10)";
  SETS(q, 0, 2, "1/9", "-2/3", "1");
  SETS(q, 0, 0, "10");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_NONE(r);
  FREE_Q(q);
}

/* Contact exactly at t = 0 and exactly at t = 1 (closed time interval). */
static void case_vertex_face_ends(pccd_result *r)
{
  double p0[12] = {1, 1, 0, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double p1[12] = {1, 1, 1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double s0[12] = {1, 1, 1e-300, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  g_case = "contact at t = 0 (moving away)";
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, p1, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "0", 0.0);
  EXPECT_FEATURE(r, PCCD_VERTEX_FACE, 0, 1, 2, 3);

  g_case = "contact at t = 1 (arriving)";
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, p1, p0, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "1", 1.0);
  EXPECT_FEATURE(r, PCCD_VERTEX_FACE, 0, 1, 2, 3);

  g_case = "static and touching";
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, p0, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "0", 0.0);

  g_case = "static, 1e-300 above the face";
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, s0, s0, NULL, r)), PCCD_OK);
  EXPECT_NONE(r);
}

static void cases(void)
{
  pccd_result *r = mk_res();
  case_vertex_face_centre(r);
  case_vertex_face_ulp(r);
  case_vertex_face_1e30(r);
  case_vertex_face_graze(r);
  case_vertex_face_ends(r);
  FREE_R(r);
}

int main(void) { return run_in_every_mode(cases); }
