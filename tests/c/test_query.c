/*
 * test_query.c -- building primitive queries (pccd_query_new, _set_coord_d/_s,
 * _set_linear_d, _set_radius_d/_s, pccd_solve_linear_d's inputs): every error path of that
 * section of include/polyccd.h, each message checked for its PLACE (polyccd.h, "Error
 * messages": points[0][2][5], p_t1[1][2], radii[0], ...), and a query left unchanged by
 * every failed call.
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

static void handles(void)
{
  pccd_query *q = NULL;
  g_case = "handles";
  CHECK_ERR(pccd_query_new(NULL, PCCD_VERTEX_FACE), PCCD_EINVAL, "pccd_query_new: out: is NULL");
  CHECK_ERR(pccd_query_new(&q, (pccd_kind)7), PCCD_EINVAL, "pccd_query_new: kind: 7 is not a pccd_kind");
  FREE_Q(q); /* NULL, or whatever the failed call left: must be safe either way */
  q = NULL;
  CHECK_ERR(pccd_query_new(&q, (pccd_kind)-3), PCCD_EINVAL, "is not a pccd_kind");
  FREE_Q(q);
  CHECK_ERR(pccd_result_new(NULL), PCCD_EINVAL, "pccd_result_new: out: is NULL");
  pccd_query_free(NULL);
  pccd_result_free(NULL);
}

static void errors_set_coord(void)
{
  static const char *const bad[] = {"abc", "1/0", "", "1/", "/2", "1.2.3", "--1", "1e", "e5",
                                    "nan", "inf", "0x10", "1/2/3", "3-", ".", "1e+", "- 1"};
  double nan_ = nan(""), inf_ = HUGE_VAL;
  double d66[66];
  const char *s66[66];
  const char *s6[6] = {"0", "0", "0", "0", "0", NULL};
  char *longnum;
  size_t i;
  pccd_query *q = mk(PCCD_VERTEX_FACE), *q2;
  pccd_result *r = mk_res();

  g_case = "set_coord errors";
  /* a valid query first: every failing call below must leave it unchanged */
  triangle_s(q);
  SETS(q, 0, 0, "1");
  SETS(q, 0, 1, "1");
  SETS(q, 0, 2, "1", "-2");

  CHECK_ERR(pccd_query_set_coord_d(NULL, 0, 0, DARR(1.0), 1), PCCD_EINVAL, "pccd_query_set_coord_d: q: is NULL");
  CHECK_ERR(pccd_query_set_coord_s(NULL, 0, 0, SARR("1"), 1), PCCD_EINVAL, "pccd_query_set_coord_s: q: is NULL");
  CHECK_ERR(pccd_query_set_coord_d(q, 4, 0, DARR(1.0), 1), PCCD_EINVAL, "point: 4 out of range (this kind has 4 points)");
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 3, DARR(1.0), 1), PCCD_EINVAL, "axis: 3 out of range");
  CHECK_ERR(pccd_query_set_coord_d(q, NONE, 0, DARR(1.0), 1), PCCD_EINVAL, "point: ");
  CHECK_ERR(pccd_query_set_coord_s(q, 4, 0, SARR("1"), 1), PCCD_EINVAL, "point: 4 out of range");
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 3, SARR("1"), 1), PCCD_EINVAL, "axis: 3 out of range");
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, NULL, 2), PCCD_EINVAL, "coeffs: is NULL");
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, NULL, 2), PCCD_EINVAL, "coeffs: is NULL");
  /* non-finite doubles at point 0, axis 2, coefficient 5: the message names points[0][2][5] */
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, DARR(0, 0, 0, 0, 0, nan_), 6), PCCD_EINVAL, "points[0][2][5]: NaN is not a finite number");
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, DARR(0, 0, 0, 0, 0, inf_), 6), PCCD_EINVAL, "points[0][2][5]: infinity");
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, DARR(0, 0, 0, 0, 0, -inf_), 6), PCCD_EINVAL, "points[0][2][5]: infinity");
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, DARR(nan_), 1), PCCD_EINVAL, "points[0][2][0]: NaN");
  /* unparsable strings at coefficient 5 */
  for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    const char *c[6] = {"0", "0", "0", "0", "0", NULL};
    int rc;
    c[5] = bad[i];
    rc = API(pccd_query_set_coord_s(q, 0, 2, c, 6));
    if (!CHECK(rc == PCCD_EINVAL)) {
      printf("    \"%s\" gave %d %s\n", bad[i], rc, rc_name(rc));
    } else {
      CHECK(pccd_last_error()[0] != '\0');
      if (!CHECK(mentions(pccd_last_error(), "pccd_query_set_coord_s: points[0][2][5]: ")))
        printf("    message for \"%s\": \"%s\"\n", bad[i], pccd_last_error());
    }
  }
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, s6, 6), PCCD_EINVAL, "points[0][2][5]: is NULL");

  /* degree limit: 65 coefficients (degree 64) pass, 66 (degree 65) do not */
  for (i = 0; i < 66; i++) {
    d66[i] = 1.0;
    s66[i] = "1";
  }
  q2 = mk(PCCD_VERTEX_FACE);
  CHECK_RC(API(pccd_query_set_coord_d(q2, 0, 0, d66, PCCD_MAX_TRAJ_DEGREE + 1)), PCCD_OK);
  CHECK_RC(API(pccd_query_set_coord_s(q2, 0, 0, s66, PCCD_MAX_TRAJ_DEGREE + 1)), PCCD_OK);
  FREE_Q(q2);
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, d66, PCCD_MAX_TRAJ_DEGREE + 2), PCCD_ELIMIT,
            "points[0][2]: degree 65 exceeds the limit of 64");
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, s66, PCCD_MAX_TRAJ_DEGREE + 2), PCCD_ELIMIT,
            "points[0][2]: degree 65");

  /* text limits: exponent beyond PCCD_MAX_EXPONENT, string beyond PCCD_MAX_NUMBER_CHARS */
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, SARR("1e-100001"), 1), PCCD_ELIMIT, "points[0][2][0]: exponent");
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, SARR("1e100001"), 1), PCCD_ELIMIT, "points[0][2][0]: exponent");
  /* leading zeros of an exponent are none of its digits (bug: corpus vv-exponent-leading-zeros) */
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, SARR("1e-000000000100001"), 1), PCCD_ELIMIT,
            "points[0][2][0]: exponent");
  longnum = (char *)malloc(PCCD_MAX_NUMBER_CHARS + 2);
  if (CHECK(longnum != NULL)) {
    memset(longnum, '7', PCCD_MAX_NUMBER_CHARS + 1);
    longnum[PCCD_MAX_NUMBER_CHARS + 1] = '\0';
    {
      const char *c[1];
      c[0] = longnum;
      CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, c, 1), PCCD_ELIMIT,
                "points[0][2][0]: number text of 100001 characters");
      longnum[PCCD_MAX_NUMBER_CHARS] = '\0'; /* exactly at the limit: accepted */
      q2 = mk(PCCD_VERTEX_FACE);
      CHECK_RC(API(pccd_query_set_coord_s(q2, 0, 0, c, 1)), PCCD_OK);
      CHECK_RC(API(pccd_query_set_coord_s(q2, 0, 0, SARR("1e-100000"), 1)), PCCD_OK);
      CHECK_RC(API(pccd_query_set_coord_s(q2, 0, 0, SARR("1e-000000000100000"), 1)), PCCD_OK);
      FREE_Q(q2);
    }
    free(longnum);
  }

  /* the query is unchanged by all of the above */
  g_case = "query unchanged after failed set_coord";
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);

  /* other kinds: their point counts bound the index */
  g_case = "set_coord point range per kind";
  q2 = mk(PCCD_VERTEX_EDGE);
  CHECK_RC(API(pccd_query_set_coord_d(q2, 2, 0, DARR(1.0), 1)), PCCD_OK);
  CHECK_ERR(pccd_query_set_coord_d(q2, 3, 0, DARR(1.0), 1), PCCD_EINVAL,
            "point: 3 out of range (this kind has 3 points)");
  FREE_Q(q2);
  q2 = mk(PCCD_VERTEX_VERTEX);
  CHECK_ERR(pccd_query_set_coord_d(q2, 2, 0, DARR(1.0), 1), PCCD_EINVAL,
            "point: 2 out of range (this kind has 2 points)");
  FREE_Q(q2);
  q2 = mk(PCCD_SPHERE_SPHERE);
  CHECK_ERR(pccd_query_set_coord_s(q2, 2, 0, SARR("1"), 1), PCCD_EINVAL, "point: 2 out of range");
  FREE_Q(q2);

  FREE_Q(q);
  FREE_R(r);
}

static void errors_linear_radius(void)
{
  double p0[12] = {1, 1, 1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double p1[12] = {1, 1, -1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double bad[12];
  pccd_query *q = mk(PCCD_VERTEX_FACE), *s;
  pccd_result *r = mk_res();
  int rc;

  g_case = "set_linear_d / solve_linear_d errors";
  CHECK_RC(API(pccd_query_set_linear_d(q, p0, p1)), PCCD_OK);
  memcpy(bad, p1, sizeof bad);
  bad[5] = nan("");
  CHECK_ERR(pccd_query_set_linear_d(NULL, p0, p1), PCCD_EINVAL, "pccd_query_set_linear_d: q: is NULL");
  CHECK_ERR(pccd_query_set_linear_d(q, NULL, p1), PCCD_EINVAL, "p_t0: is NULL");
  CHECK_ERR(pccd_query_set_linear_d(q, p0, NULL), PCCD_EINVAL, "p_t1: is NULL");
  CHECK_ERR(pccd_query_set_linear_d(q, p0, bad), PCCD_EINVAL, "p_t1[1][2]: NaN"); /* bad[5] */
  bad[5] = -HUGE_VAL;
  CHECK_ERR(pccd_query_set_linear_d(q, bad, p0), PCCD_EINVAL, "p_t0[1][2]: infinity");
  CHECK_RC(solve(q, NULL, r), PCCD_OK); /* unchanged */
  EXPECT_EXACT(r, "1/2", 0.5);

  CHECK_ERR(pccd_solve_linear_d(PCCD_SPHERE_SPHERE, p0, p1, NULL, r), PCCD_EINVAL,
            "kind: sphere-sphere queries need radii");
  CHECK_ERR(pccd_solve_linear_d((pccd_kind)9, p0, p1, NULL, r), PCCD_EINVAL, "kind: 9 is not a pccd_kind");
  CHECK_ERR(pccd_solve_linear_d(PCCD_VERTEX_FACE, NULL, p1, NULL, r), PCCD_EINVAL, "p_t0: is NULL");
  CHECK_ERR(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, NULL, NULL, r), PCCD_EINVAL, "p_t1: is NULL");
  CHECK_ERR(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, bad, NULL, r), PCCD_EINVAL,
            "pccd_solve_linear_d: p_t1[1][2]: infinity");
  CHECK_ERR(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, p1, NULL, NULL), PCCD_EINVAL, "res: is NULL");

  g_case = "radius errors";
  s = mk(PCCD_SPHERE_SPHERE);
  CHECK_ERR(pccd_query_set_radius_d(NULL, 0, 1.0), PCCD_EINVAL, "pccd_query_set_radius_d: q: is NULL");
  CHECK_ERR(pccd_query_set_radius_s(NULL, 0, "1"), PCCD_EINVAL, "q: is NULL");
  CHECK_ERR(pccd_query_set_radius_d(s, 2, 1.0), PCCD_EINVAL, "which: 2 out of range (0 or 1)");
  CHECK_ERR(pccd_query_set_radius_s(s, 2, "1"), PCCD_EINVAL, "which: 2 out of range");
  CHECK_ERR(pccd_query_set_radius_d(s, 0, nan("")), PCCD_EINVAL, "radii[0]: NaN");
  CHECK_ERR(pccd_query_set_radius_d(s, 0, HUGE_VAL), PCCD_EINVAL, "radii[0]: infinity");
  CHECK_ERR(pccd_query_set_radius_s(s, 0, "abc"), PCCD_EINVAL, "radii[0]: \"abc\" is not a number");
  CHECK_ERR(pccd_query_set_radius_s(s, 0, "1/0"), PCCD_EINVAL, "radii[0]: \"1/0\" has a zero denominator");
  CHECK_ERR(pccd_query_set_radius_s(s, 0, ""), PCCD_EINVAL, "radii[0]: \"\"");
  CHECK_ERR(pccd_query_set_radius_s(s, 0, NULL), PCCD_EINVAL, "radii[0]: is NULL");
  /* radius on a query without balls: some error (the header does not say which) */
  rc = API(pccd_query_set_radius_d(q, 0, 1.0));
  CHECK(rc < 0);
  CHECK(mentions(pccd_last_error(), "radii: only sphere-sphere queries have radii"));

  /* radii default to 0; solving needs both > 0 */
  SETS(s, 1, 0, "4", "-4");
  CHECK_ERR(solve(s, NULL, r), PCCD_EINVAL, "pccd_query_solve: radii[0]: 0 is not > 0");
  CHECK_RC(API(pccd_query_set_radius_d(s, 0, 1.0)), PCCD_OK);
  CHECK_ERR(solve(s, NULL, r), PCCD_EINVAL, "radii[1]: 0 is not > 0");
  /* a negative radius is rejected when set or when solved */
  rc = API(pccd_query_set_radius_s(s, 1, "-1"));
  if (rc == PCCD_OK) {
    CHECK_ERR(solve(s, NULL, r), PCCD_EINVAL, "radii[1]: -1 is not > 0");
  } else {
    CHECK_RC(rc, PCCD_EINVAL);
  }
  CHECK_RC(API(pccd_query_set_radius_s(s, 1, "1")), PCCD_OK);
  CHECK_RC(solve(s, NULL, r), PCCD_OK);
  EXPECT_EXACT(r, "1/2", 0.5);
  FREE_Q(s);
  FREE_Q(q);
  FREE_R(r);
}

static void cases(void)
{
  handles();
  errors_set_coord();
  errors_linear_radius();
}

int main(void) { return run_in_every_mode(cases); }
