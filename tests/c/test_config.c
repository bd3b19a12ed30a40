/*
 * test_config.c -- the library-wide entry points (pccd_version, pccd_last_error,
 * pccd_kind_points) and solve options (pccd_config_init, bad pccd_config fields), each
 * error message checked for its PLACE (polyccd.h, "Error messages": kind, cfg,
 * config.time_tolerance, config.struct_size).
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

/* pccd_version, pccd_kind_points, pccd_config_init and pccd_last_error. */
static void version_kinds_config(void)
{
  size_t c = 0;
  pccd_config cfg;
  static const size_t want_points[5] = {4, 4, 3, 2, 2};
  int k;

  g_case = "version, kinds, config";
  CHECK(pccd_version() != NULL);
  CHECK(strcmp(pccd_version(), PCCD_VERSION_STRING) == 0);
  CHECK(pccd_last_error() != NULL); /* never NULL, even before any error */
  for (k = 0; k < 5; k++) {
    CHECK_RC(API(pccd_kind_points((pccd_kind)k, &c)), PCCD_OK);
    CHECK(c == want_points[k]);
  }
  CHECK_ERR(pccd_kind_points((pccd_kind)5, &c), PCCD_EINVAL,
            "pccd_kind_points: kind: 5 is not a pccd_kind");
  CHECK_ERR(pccd_kind_points((pccd_kind)-1, &c), PCCD_EINVAL, "is not a pccd_kind");
  CHECK_ERR(pccd_kind_points(PCCD_VERTEX_FACE, NULL), PCCD_EINVAL, "count: is NULL");

  CHECK_ERR(pccd_config_init(NULL), PCCD_EINVAL, "pccd_config_init: cfg: is NULL");
  memset(&cfg, 0xAB, sizeof cfg);
  CHECK_RC(API(pccd_config_init(&cfg)), PCCD_OK);
  CHECK(cfg.struct_size == sizeof(pccd_config));
  CHECK(cfg.time_tolerance == NULL);
  CHECK(cfg.want_time == 1);
  CHECK(cfg.want_exact == 1);
}

/* A bad config makes the solve fail with a message naming its field, and leaves the
 * result unsolved. */
static void bad_configs(void)
{
  static const char *const bad_tol[] = {"0", "-1e-6", "abc", "1/0", "", "-0"};
  double p0[12] = {1, 1, 1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double p1[12] = {1, 1, -1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  pccd_query *q = mk(PCCD_VERTEX_FACE);
  pccd_result *r = mk_res();
  pccd_config cfg;
  int v, rc;
  size_t i;

  g_case = "bad configs";
  CHECK_RC(API(pccd_query_set_linear_d(q, p0, p1)), PCCD_OK);
  for (i = 0; i < sizeof bad_tol / sizeof bad_tol[0]; i++) {
    CHECK_RC(API(pccd_config_init(&cfg)), PCCD_OK);
    cfg.time_tolerance = bad_tol[i];
    CHECK_RC(solve(q, NULL, r), PCCD_OK);
    rc = solve(q, &cfg, r);
    if (!CHECK(rc == PCCD_EINVAL)) printf("    time_tolerance \"%s\" gave %s\n", bad_tol[i], rc_name(rc));
    if (!CHECK(mentions(pccd_last_error(), "pccd_query_solve: config.time_tolerance: ")))
      printf("    message: \"%s\"\n", pccd_last_error());
    /* on error the result is reset to "nothing solved" */
    CHECK_ERR(pccd_result_collides(r, &v), PCCD_ESTATE, "res: holds no answer");
  }
  CHECK_RC(API(pccd_config_init(&cfg)), PCCD_OK);
  cfg.struct_size = 3;
  CHECK_ERR(solve(q, &cfg, r), PCCD_EINVAL, "config.struct_size: 3 is not");
  CHECK_ERR(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, p1, &cfg, r), PCCD_EINVAL,
            "pccd_solve_linear_d: config.struct_size: 3 is not");
  FREE_Q(q);
  FREE_R(r);
}

static void cases(void)
{
  version_kinds_config();
  bad_configs();
}

int main(void) { return run_in_every_mode(cases); }
