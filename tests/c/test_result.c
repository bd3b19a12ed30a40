/*
 * test_result.c -- solving into and reading a pccd_result (pccd_query_solve,
 * pccd_result_*): NULL arguments, an unsolved or reset result, bad indices, the ERANGE
 * buffer protocol and an irrational time without an exact value, each message checked
 * for its PLACE (polyccd.h, "Error messages": res, i, which, buf, ...).
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

static void errors_solve_and_result(void)
{
  double p0[12] = {1, 1, 1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double p1[12] = {1, 1, -1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  pccd_query *q = mk(PCCD_VERTEX_FACE);
  pccd_result *r = mk_res(), *fresh = mk_res(), *irr = mk_res();
  char buf[16];
  size_t needed, count, pts[4];
  int v, rc, kind, which;
  double t;
  size_t i;

  g_case = "solve errors";
  CHECK_RC(API(pccd_query_set_linear_d(q, p0, p1)), PCCD_OK);
  CHECK_ERR(solve(NULL, NULL, r), PCCD_EINVAL, "pccd_query_solve: q: is NULL");
  CHECK_ERR(pccd_result_collides(r, &v), PCCD_ESTATE, "res: holds no answer"); /* reset */
  CHECK_ERR(solve(q, NULL, NULL), PCCD_EINVAL, "pccd_query_solve: res: is NULL");

  g_case = "an unsolved result";
  CHECK_ERR(pccd_result_collides(fresh, &v), PCCD_ESTATE,
            "pccd_result_collides: res: holds no answer");
  for (which = 0; which <= 2; which++) {
    needed = 0;
    CHECK_ERR(pccd_result_time(fresh, which, buf, sizeof buf, &needed), PCCD_ESTATE,
              "res: holds no answer");
  }
  CHECK_ERR(pccd_result_time_is_exact(fresh, &v), PCCD_ESTATE, "res: holds no answer");
  CHECK_ERR(pccd_result_time_approx(fresh, &t), PCCD_ESTATE, "res: holds no answer");
  CHECK_ERR(pccd_result_feature_count(fresh, &count), PCCD_ESTATE, "res: holds no answer");
  CHECK_ERR(pccd_result_feature(fresh, 0, &kind, pts), PCCD_ESTATE, "res: holds no answer");
  v = -1;
  rc = API(pccd_result_stage(fresh, &v));
  CHECK(rc == PCCD_ESTATE || (rc == PCCD_OK && v == PCCD_STAGE_NONE));

  g_case = "NULL arguments of result calls";
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  CHECK_ERR(pccd_result_collides(NULL, &v), PCCD_EINVAL, "pccd_result_collides: res: is NULL");
  CHECK_ERR(pccd_result_collides(r, NULL), PCCD_EINVAL, "collides: is NULL");
  CHECK_ERR(pccd_result_stage(NULL, &v), PCCD_EINVAL, "res: is NULL");
  CHECK_ERR(pccd_result_stage(r, NULL), PCCD_EINVAL, "stage: is NULL");
  CHECK_ERR(pccd_result_time(NULL, 0, buf, sizeof buf, &needed), PCCD_EINVAL, "res: is NULL");
  CHECK_ERR(pccd_result_time_is_exact(NULL, &v), PCCD_EINVAL, "res: is NULL");
  CHECK_ERR(pccd_result_time_is_exact(r, NULL), PCCD_EINVAL, "exact: is NULL");
  CHECK_ERR(pccd_result_time_approx(NULL, &t), PCCD_EINVAL, "res: is NULL");
  CHECK_ERR(pccd_result_time_approx(r, NULL), PCCD_EINVAL, "t: is NULL");
  CHECK_ERR(pccd_result_feature_count(NULL, &count), PCCD_EINVAL, "res: is NULL");
  CHECK_ERR(pccd_result_feature_count(r, NULL), PCCD_EINVAL, "count: is NULL");
  CHECK_ERR(pccd_result_feature(NULL, 0, &kind, pts), PCCD_EINVAL, "res: is NULL");
  CHECK_ERR(pccd_result_feature(r, 0, NULL, pts), PCCD_EINVAL, "kind: is NULL");
  CHECK_ERR(pccd_result_feature(r, 0, &kind, NULL), PCCD_EINVAL, "points: is NULL");
  CHECK_ERR(pccd_result_feature(r, 1, &kind, pts), PCCD_EINVAL,
            "pccd_result_feature: i: 1 out of range (1 features)"); /* one feature: index 0 */
  CHECK_ERR(pccd_result_feature(r, NONE, &kind, pts), PCCD_EINVAL, "i: ");
  CHECK_ERR(pccd_result_time(r, 3, buf, sizeof buf, &needed), PCCD_EINVAL,
            "pccd_result_time: which: 3 is not 0 (lo), 1 (hi) or 2 (exact)");
  CHECK_ERR(pccd_result_time(r, -1, buf, sizeof buf, &needed), PCCD_EINVAL, "which: -1 is not");

  g_case = "time buffer sizes";
  /* "1/2" needs 4 bytes */
  needed = 0;
  CHECK_ERR(pccd_result_time(r, 0, NULL, 0, &needed), PCCD_ERANGE,
            "pccd_result_time: buf: 0 bytes are too few; 4 needed");
  CHECK(needed == 4);
  for (i = 0; i < 4; i++) {
    memset(buf, 'X', sizeof buf);
    needed = 0;
    CHECK_ERR(pccd_result_time(r, 2, buf, i, &needed), PCCD_ERANGE, "4 needed");
    CHECK(needed == 4);
    CHECK(buf[0] == 'X' && buf[1] == 'X' && buf[2] == 'X' && buf[3] == 'X'); /* untouched */
  }
  memset(buf, 'X', sizeof buf);
  needed = 0;
  CHECK_RC(API(pccd_result_time(r, 2, buf, 4, &needed)), PCCD_OK);
  CHECK(needed == 4 && strcmp(buf, "1/2") == 0);
  needed = 0;
  CHECK_RC(API(pccd_result_time(r, 1, buf, sizeof buf, &needed)), PCCD_OK);
  CHECK(needed == 4 && strcmp(buf, "1/2") == 0);

  g_case = "irrational time: no exact value";
  {
    pccd_query *s = mk(PCCD_SPHERE_SPHERE);
    SETS(s, 1, 0, "2", "0", "-2");
    CHECK_RC(API(pccd_query_set_radius_s(s, 0, "1/2")), PCCD_OK);
    CHECK_RC(API(pccd_query_set_radius_s(s, 1, "1/2")), PCCD_OK);
    CHECK_RC(solve(s, NULL, irr), PCCD_OK);
    CHECK_ERR(pccd_result_time(irr, 2, buf, sizeof buf, &needed), PCCD_ESTATE,
              "res: the first contact time is not known exactly");
    FREE_Q(s);
  }

  FREE_Q(q);
  FREE_R(r);
  FREE_R(fresh);
  FREE_R(irr);
}

static void cases(void)
{
  errors_solve_and_result();
}

int main(void) { return run_in_every_mode(cases); }
