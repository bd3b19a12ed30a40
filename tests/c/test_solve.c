/*
 * test_solve.c -- known answers of edge-edge, vertex-edge, vertex-vertex and
 * sphere-sphere queries, a result reused, and inputs copied by the library. Exact times
 * are checked exactly: an irrational contact time t* (balls touching at t* = 1/sqrt(2))
 * is checked as lo^2 < 1/2 < hi^2 with the bignum of exact_rational.h, no rounding.
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

/* Edge a = (-1,0,0)-(1,0,0) static; edge b along y at x = xb, z(t) = 1 - 4t: they meet
 * at t = 1/4. xb = 0: the open edges cross; xb = 1: b passes through a's endpoint a1
 * (vertex a1 inside the open edge b); xb one ulp beyond 1: no contact. */
static void case_edge_edge_cross(pccd_result *r)
{
  double p0[12] = {-1, 0, 0, 1, 0, 0, 0, -1, 1, 0, 1, 1};
  double p1[12] = {-1, 0, 0, 1, 0, 0, 0, -1, -3, 0, 1, -3};
  g_case = "edge-edge crossing at t = 1/4";
  CHECK_RC(API(pccd_solve_linear_d(PCCD_EDGE_EDGE, p0, p1, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "1/4", 0.25);
  EXPECT_FEATURE(r, PCCD_EDGE_EDGE, 0, 1, 2, 3);

  g_case = "edge-edge through the endpoint a1 at t = 1/4";
  p0[6] = p0[9] = p1[6] = p1[9] = 1;
  CHECK_RC(API(pccd_solve_linear_d(PCCD_EDGE_EDGE, p0, p1, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "1/4", 0.25);
  EXPECT_FEATURE(r, PCCD_VERTEX_EDGE, 1, 2, 3, NONE);

  g_case = "edge-edge one ulp beyond the endpoint a1";
  p0[6] = p0[9] = p1[6] = p1[9] = nextafter(1.0, 2.0);
  CHECK_RC(API(pccd_solve_linear_d(PCCD_EDGE_EDGE, p0, p1, NULL, r)), PCCD_OK);
  EXPECT_NONE(r);
}

/* Collinear edges sliding onto each other: a = (0,0,0)-(1,0,0) static, b = (3-4t,0,0)-
 * (4-4t,0,0); b0 reaches a1 at t = 1/2 (a vertex-vertex contact). Lifted off the line by
 * 1e-30 (parallel, never touching). */
static void case_edge_edge_collinear(pccd_result *r)
{
  pccd_query *q = mk(PCCD_EDGE_EDGE);
  g_case = "collinear edges sliding together";
  fixed_s(q, 0, "0", "0", "0");
  fixed_s(q, 1, "1", "0", "0");
  SETS(q, 2, 0, "3", "-4");
  SETS(q, 3, 0, "4", "-4");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  EXPECT_FEATURE_VV(r, 1, 2);

  g_case = "parallel edges sliding 1e-30 apart";
  SETS(q, 2, 1, "1e-30");
  SETS(q, 3, 1, "1e-30");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_NONE(r);

  /* Overlapping from the start: collinear, sharing [0.5, 1] at t = 0. Features at t = 0:
   * not asserted (two vertex-edge contacts). */
  g_case = "collinear edges overlapping at t = 0";
  SETS(q, 2, 1, "0");
  SETS(q, 3, 1, "0");
  SETS(q, 2, 0, "1/2", "5");
  SETS(q, 3, 0, "3/2", "5");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "0", 0.0);
  FREE_Q(q);
}

/* Vertex-edge: e = (0,0,0)-(2,0,0); v moves along -y at x = xv and crosses y = 0 at
 * t = 1/2: inside the edge (xv = 1), through e1 (xv = 2), beyond it (xv = 3). */
static void case_vertex_edge(pccd_result *r)
{
  pccd_query *q = mk(PCCD_VERTEX_EDGE);
  g_case = "vertex-edge crossing at t = 1/2";
  fixed_s(q, 1, "0", "0", "0");
  fixed_s(q, 2, "2", "0", "0");
  SETS(q, 0, 0, "1");
  SETS(q, 0, 1, "1", "-2");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  EXPECT_FEATURE(r, PCCD_VERTEX_EDGE, 0, 1, 2, NONE);

  g_case = "vertex-edge through the endpoint e1";
  SETS(q, 0, 0, "2");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  EXPECT_FEATURE_VV(r, 0, 2);

  g_case = "vertex-edge passing beyond the endpoint";
  SETS(q, 0, 0, "3");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_NONE(r);
  FREE_Q(q);
}

/* Vertex-vertex: a = (1,2,3) static, b = (3 - 6t, 2, 3): b meets a at t = 1/3; with b
 * 1e-30 above, never. */
static void case_vertex_vertex(pccd_result *r)
{
  pccd_query *q = mk(PCCD_VERTEX_VERTEX);
  double p0[6] = {1, 2, 3, 3, 2, 3}, p1[6] = {1, 2, 3, -1, 2, 3};
  g_case = "vertex-vertex meeting at t = 1/3";
  fixed_s(q, 0, "1", "2", "3");
  SETS(q, 1, 0, "3", "-6");
  SETS(q, 1, 1, "2");
  SETS(q, 1, 2, "3");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/3", 0x1.5555555555555p-2);
  EXPECT_FEATURE_VV(r, 0, 1);

  g_case = "vertex-vertex missing by 1e-30";
  SETS(q, 1, 2, "3.000000000000000000000000000001");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_NONE(r);
  FREE_Q(q);

  g_case = "vertex-vertex linear doubles, t = 1/2";
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_VERTEX, p0, p1, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  EXPECT_FEATURE_VV(r, 0, 1);
}

/* t* = 1/sqrt(2): lo <= t*  <=>  2 lo^2 <= 1  <=>  2 p^2 <= q^2 (strict: t* is irrational). */
static int lo_ok_sqrt_half(const rat *x)
{
  static big p2, q2, two, t;
  big_small(&two, 2);
  big_mul(&p2, &x->num, &x->num);
  big_mul(&t, &p2, &two);
  big_mul(&q2, &x->den, &x->den);
  return big_cmp(&t, &q2) < 0;
}
static int hi_ok_sqrt_half(const rat *x)
{
  static big p2, q2, two, t;
  big_small(&two, 2);
  big_mul(&p2, &x->num, &x->num);
  big_mul(&t, &p2, &two);
  big_mul(&q2, &x->den, &x->den);
  return big_cmp(&t, &q2) > 0;
}

/* t* = 1 - sqrt(15)/4: for t in [0, 1], t < t*  <=>  16 (1 - t)^2 > 15  <=>
 * 16 (q - p)^2 > 15 q^2. */
static int cmp_sqrt15(const rat *x)
{
  static big d, d2, l, q2, r, c16, c15;
  if (big_cmp(&x->num, &x->den) > 0) return -1; /* t > 1 > t* */
  big_small(&c16, 16);
  big_small(&c15, 15);
  big_sub(&d, &x->den, &x->num);
  big_mul(&d2, &d, &d);
  big_mul(&l, &d2, &c16);
  big_mul(&q2, &x->den, &x->den);
  big_mul(&r, &q2, &c15);
  return big_cmp(&l, &r); /* > 0: t < t* */
}
static int lo_ok_sqrt15(const rat *x) { return cmp_sqrt15(x) > 0; }
static int hi_ok_sqrt15(const rat *x) { return cmp_sqrt15(x) < 0; }

/* Balls. Rational: a at the origin, b at (4 - 4t, 0, 0), radii 1: touch at t = 1/2.
 * Irrational 1: radii 1/2, b at (2 - 2t^2, 0, 0): |c_b| = 1 at t* = 1/sqrt(2).
 * Irrational 2 (linear): radii 1, b at (2 - 2t, 1/2, 0): (2 - 2t)^2 + 1/4 = 4 at
 * t* = 1 - sqrt(15)/4 ~ 0.0317541634481456. */
static void case_sphere_sphere(pccd_result *r)
{
  static const struct {
    const char *cfg, *exact; /* the tolerance given, and its value as p/q */
    long double value;
  } tols[] = {{NULL, "1/1000000000000", 1e-12L},
              {"1e-6", "1/1000000", 1e-6L},
              {"1/1000", "1/1000", 1e-3L},
              {"0.25", "1/4", 0.25L}};
  pccd_query *q = mk(PCCD_SPHERE_SPHERE);
  pccd_config cfg;
  size_t i;

  g_case = "balls touching at t = 1/2";
  SETS(q, 1, 0, "4", "-4");
  CHECK_RC(API(pccd_query_set_radius_s(q, 0, "1")), PCCD_OK);
  CHECK_RC(API(pccd_query_set_radius_d(q, 1, 1.0)), PCCD_OK);
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  EXPECT_FEATURE(r, PCCD_SPHERE_SPHERE, 0, 1, NONE, NONE);

  g_case = "balls missing by 1e-30";
  CHECK_RC(API(pccd_query_set_radius_s(q, 1, "0.999999999999999999999999999999")), PCCD_OK);
  SETS(q, 1, 0, "4", "-2");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_NONE(r);

  CHECK_RC(API(pccd_query_set_radius_s(q, 0, "1/2")), PCCD_OK);
  CHECK_RC(API(pccd_query_set_radius_d(q, 1, 0.5)), PCCD_OK);
  SETS(q, 1, 0, "2", "0", "-2");
  for (i = 0; i < sizeof tols / sizeof tols[0]; i++) {
    static char name[80];
    sprintf(name, "balls touching at t = 1/sqrt(2), tolerance %s", tols[i].cfg ? tols[i].cfg : "default");
    g_case = name;
    CHECK_RC(API(pccd_config_init(&cfg)), PCCD_OK);
    cfg.time_tolerance = tols[i].cfg;
    CHECK_RC(solve(q, &cfg, r), PCCD_OK);
    EXPECT_ENCLOSURE(r, tols[i].exact, tols[i].value, lo_ok_sqrt_half, hi_ok_sqrt_half,
                     0.707106781186547524400844362104849039L);
    EXPECT_FEATURE(r, PCCD_SPHERE_SPHERE, 0, 1, NONE, NONE);
  }
  FREE_Q(q);

  g_case = "balls touching at t = 1 - sqrt(15)/4 (linear)";
  q = mk(PCCD_SPHERE_SPHERE);
  SETD(q, 1, 0, 2.0, -2.0);
  SETD(q, 1, 1, 0.5);
  CHECK_RC(API(pccd_query_set_radius_d(q, 0, 1.0)), PCCD_OK);
  CHECK_RC(API(pccd_query_set_radius_d(q, 1, 1.0)), PCCD_OK);
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  /* 1 - sqrt(15)/4, sqrt(15) = 3.87298334620741688517926539978... */
  EXPECT_ENCLOSURE(r, "1/1000000000000", 1e-12L, lo_ok_sqrt15, hi_ok_sqrt15, 0.03175416344814577870518365L);
  FREE_Q(q);
}

/* One result reused: a contact, then no contact, then a contact again. */
static void case_result_reuse(pccd_result *r)
{
  double p0[12] = {1, 1, 1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double p1[12] = {1, 1, -1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double m1[12] = {1, 1, 0.5, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  g_case = "result reuse";
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, p1, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, m1, NULL, r)), PCCD_OK);
  EXPECT_NONE(r);
  CHECK_RC(API(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, p1, NULL, r)), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
}

/* The library copies its inputs: overwriting the caller's strings after the set call
 * changes nothing. */
static void case_inputs_copied(pccd_result *r)
{
  char c0[8], c1[8];
  const char *coeffs[2];
  pccd_query *q = mk(PCCD_VERTEX_FACE);
  g_case = "inputs are copied";
  strcpy(c0, "1");
  strcpy(c1, "-2");
  coeffs[0] = c0;
  coeffs[1] = c1;
  triangle_s(q);
  SETS(q, 0, 0, "1");
  SETS(q, 0, 1, "1");
  CHECK_RC(API(pccd_query_set_coord_s(q, 0, 2, coeffs, 2)), PCCD_OK);
  strcpy(c0, "7");
  strcpy(c1, "x");
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  FREE_Q(q);
}

static void cases(void)
{
  pccd_result *r = mk_res();
  case_edge_edge_cross(r);
  case_edge_edge_collinear(r);
  case_vertex_edge(r);
  case_vertex_vertex(r);
  case_sphere_sphere(r);
  case_result_reuse(r);
  case_inputs_copied(r);
  FREE_R(r);
}

int main(void) { return run_in_every_mode(cases); }
