/*
 * query_check.h -- helpers of the query and result tests (test_query.c, test_result.c,
 * test_config.c, test_solve*.c): making queries and results, setting coordinates, and
 * checking a result against a known answer (no contact, an exact time, an enclosure of
 * an irrational time checked exactly with exact_rational.h, the touching feature).
 * Every call goes through API() (check.h), so the rounding mode is checked after each.
 */
#ifndef PCCD_TESTS_QUERY_CHECK_H
#define PCCD_TESTS_QUERY_CHECK_H

#include <math.h>

#include "check.h"
#include "exact_rational.h"

#define FREE_Q(q) (pccd_query_free(q), after_call(0))
#define FREE_R(r) (pccd_result_free(r), after_call(0))

static const size_t NONE = (size_t)-1;

/* Makes a query of `kind` (checked). */
static inline pccd_query *mk(pccd_kind kind)
{
  pccd_query *q = NULL;
  CHECK_RC(API(pccd_query_new(&q, kind)), PCCD_OK);
  CHECK(q != NULL);
  return q;
}

static inline pccd_result *mk_res(void)
{
  pccd_result *r = NULL;
  CHECK_RC(API(pccd_result_new(&r)), PCCD_OK);
  CHECK(r != NULL);
  return r;
}

static inline void set_s_(pccd_query *q, size_t pt, size_t ax, const char *const *c, size_t n, int line)
{
  check_rc_(API(pccd_query_set_coord_s(q, pt, ax, c, n)), PCCD_OK, "pccd_query_set_coord_s", line);
}
static inline void set_d_(pccd_query *q, size_t pt, size_t ax, const double *c, size_t n, int line)
{
  check_rc_(API(pccd_query_set_coord_d(q, pt, ax, c, n)), PCCD_OK, "pccd_query_set_coord_d", line);
}
/* SETS(q, point, axis, "c0", "c1", ...): coordinate polynomial from strings. */
#define SARR(...) ((const char *const[]){__VA_ARGS__})
#define DARR(...) ((const double[]){__VA_ARGS__})
#define SETS(q, pt, ax, ...) \
  set_s_((q), (pt), (ax), SARR(__VA_ARGS__), sizeof SARR(__VA_ARGS__) / sizeof(const char *), __LINE__)
#define SETD(q, pt, ax, ...) \
  set_d_((q), (pt), (ax), DARR(__VA_ARGS__), sizeof DARR(__VA_ARGS__) / sizeof(double), __LINE__)

/* A point that does not move, from strings. */
static inline void fixed_s(pccd_query *q, size_t pt, const char *x, const char *y, const char *z)
{
  SETS(q, pt, 0, x);
  SETS(q, pt, 1, y);
  SETS(q, pt, 2, z);
}

/* The static triangle of the vertex-face cases: f0 = (0,0,0), f1 = (3,0,0), f2 = (0,3,0)
 * (points 1, 2, 3). Its centroid is (1,1,0); its open edge f1 f2 is x + y = 3. */
static inline void triangle_s(pccd_query *q)
{
  fixed_s(q, 1, "0", "0", "0");
  fixed_s(q, 2, "3", "0", "0");
  fixed_s(q, 3, "0", "3", "0");
}

static inline int solve(const pccd_query *q, const pccd_config *cfg, pccd_result *r)
{
  return API(pccd_query_solve(q, cfg, r));
}

/* Time `which` of r as a malloc'd string, fetched the documented way (size query with
 * cap 0 first); NULL when the call fails (its status in *rc). */
static inline char *time_str(const pccd_result *r, int which, int *rc)
{
  size_t needed = 0, needed2 = 0;
  char *buf;
  *rc = API(pccd_result_time(r, which, NULL, 0, &needed));
  if (*rc != PCCD_ERANGE) return NULL;
  CHECK(needed >= 2);
  buf = (char *)malloc(needed);
  if (buf == NULL) return NULL;
  *rc = API(pccd_result_time(r, which, buf, needed, &needed2));
  if (*rc != PCCD_OK) {
    free(buf);
    return NULL;
  }
  CHECK(needed2 == needed);
  CHECK(strlen(buf) + 1 == needed);
  return buf;
}

static inline int collides(const pccd_result *r)
{
  int c = -1;
  CHECK_RC(API(pccd_result_collides(r, &c)), PCCD_OK);
  CHECK(c == 0 || c == 1);
  return c;
}

static inline void check_stage(const pccd_result *r)
{
  int st = -1;
  CHECK_RC(API(pccd_result_stage(r, &st)), PCCD_OK);
  CHECK(st >= PCCD_STAGE_BOUNDS && st <= PCCD_STAGE_EXACT);
}

/* The result says: no contact during [0, 1]. */
static inline void expect_none_(const pccd_result *r, int line)
{
  int rc, ex = -1;
  double t = -1;
  size_t count = 99;
  char *s;
  if (!check_(collides(r) == 0, "no contact expected", line)) return;
  check_stage(r);
  s = time_str(r, 0, &rc);
  check_rc_(rc, PCCD_ESTATE, "pccd_result_time(lo) without contact", line);
  free(s);
  s = time_str(r, 2, &rc);
  check_rc_(rc, PCCD_ESTATE, "pccd_result_time(exact) without contact", line);
  free(s);
  check_rc_(API(pccd_result_time_approx(r, &t)), PCCD_ESTATE, "pccd_result_time_approx", line);
  /* Not pinned down by the header: ESTATE, or "not exact". */
  rc = API(pccd_result_time_is_exact(r, &ex));
  check_(rc == PCCD_ESTATE || (rc == PCCD_OK && ex == 0), "time_is_exact without contact: ESTATE or 0", line);
  /* No contact, no touching features (ESTATE also acceptable). */
  rc = API(pccd_result_feature_count(r, &count));
  check_(rc == PCCD_ESTATE || (rc == PCCD_OK && count == 0), "feature_count without contact: 0", line);
}
#define EXPECT_NONE(r) expect_none_((r), __LINE__)

/* The result says: first contact exactly at `t` (canonical "p/q" or "p"), whose nearest
 * double is `approx`. */
static inline void expect_exact_(const pccd_result *r, const char *t, double approx, int line)
{
  int rc, which, ex = -1;
  double a = -1;
  if (!check_(collides(r) == 1, "a contact expected", line)) return;
  check_stage(r);
  check_rc_(API(pccd_result_time_is_exact(r, &ex)), PCCD_OK, "pccd_result_time_is_exact", line);
  check_(ex == 1, "the first contact time is exact", line);
  for (which = 0; which <= 2; which++) {
    char *s = time_str(r, which, &rc);
    if (check_rc_(rc, PCCD_OK, "pccd_result_time", line)) {
      if (strcmp(s, t) == 0) {
        g_pass++;
      } else {
        g_fail++;
        printf("FAIL line %d [%s, %s]: time %d is \"%s\", expected exactly \"%s\"\n", line,
               g_case, g_mode_name, which, s, t);
      }
    }
    free(s);
  }
  check_rc_(API(pccd_result_time_approx(r, &a)), PCCD_OK, "pccd_result_time_approx", line);
  if (a == approx) {
    g_pass++;
  } else {
    g_fail++;
    printf("FAIL line %d [%s, %s]: time_approx %a (%.17g), expected %a\n", line, g_case,
           g_mode_name, a, a, approx);
  }
}
#define EXPECT_EXACT(r, t, approx) expect_exact_((r), (t), (approx), __LINE__)

/* The result says: a contact, whose first time t* is enclosed in [lo, hi] with hi - lo <=
 * tol (a "p/q" string), and `in_lo(lo)`, `in_hi(hi)` confirm lo <= t* <= hi exactly. */
typedef int (*rat_pred)(const rat *);
static inline void expect_enclosure_(const pccd_result *r, const char *tol, long double tol_ld, rat_pred lo_ok,
                              rat_pred hi_ok, long double t_star, int line)
{
  static rat lo, hi, tl;
  int rc, rc2, ex = -1;
  double a = -1;
  char *slo, *shi, *sx;
  if (!check_(collides(r) == 1, "a contact expected", line)) return;
  check_stage(r);
  slo = time_str(r, 0, &rc);
  shi = time_str(r, 1, &rc2);
  if (check_rc_(rc, PCCD_OK, "pccd_result_time(lo)", line) &&
      check_rc_(rc2, PCCD_OK, "pccd_result_time(hi)", line)) {
    int ok_parse;
    g_big_overflow = 0;
    ok_parse = rat_parse(&lo, slo) && rat_parse(&hi, shi) && rat_parse(&tl, tol);
    if (check_(ok_parse, "lo and hi are p/q strings", line)) {
      int ok = lo_ok(&lo) && hi_ok(&hi) && rat_cmp(&lo, &hi) <= 0 && rat_width_le(&lo, &hi, &tl) &&
               !g_big_overflow;
      if (ok) {
        g_pass++;
      } else {
        g_fail++;
        printf("FAIL line %d [%s, %s]: enclosure [%s, %s] does not contain t* ~ %.21Lg or is "
               "wider than %s%s\n",
               line, g_case, g_mode_name, slo, shi, t_star, tol,
               g_big_overflow ? " (test bignum overflow)" : "");
      }
    }
  }
  free(slo);
  free(shi);
  rc = API(pccd_result_time_is_exact(r, &ex));
  check_rc_(rc, PCCD_OK, "pccd_result_time_is_exact", line);
  check_(ex == 0, "an irrational time is not exact", line);
  sx = time_str(r, 2, &rc);
  check_rc_(rc, PCCD_ESTATE, "pccd_result_time(2) of an irrational time", line);
  free(sx);
  check_rc_(API(pccd_result_time_approx(r, &a)), PCCD_OK, "pccd_result_time_approx", line);
  /* the nearest double to the midpoint of an enclosure of width <= tol around t* */
  check_(fabsl((long double)a - t_star) <= tol_ld / 2 + 1e-16L, "time_approx within tol/2 of t*", line);
}
#define EXPECT_ENCLOSURE(r, tol, tol_ld, lo_ok, hi_ok, t_star) \
  expect_enclosure_((r), (tol), (tol_ld), (lo_ok), (hi_ok), (t_star), __LINE__)

/* r has exactly one touching feature: (kind, a, b, c, d) (NONE for unused entries).
 * any_order: the two points of a VERTEX_VERTEX feature may come in either order. */
static inline void expect_feature_(const pccd_result *r, int kind, size_t a, size_t b, size_t c, size_t d,
                            int any_order, int line)
{
  size_t count = 0, pts[4] = {0, 0, 0, 0};
  int k = -1, ok;
  if (!check_rc_(API(pccd_result_feature_count(r, &count)), PCCD_OK, "pccd_result_feature_count", line))
    return;
  if (!check_(count == 1, "exactly one touching feature", line)) {
    printf("    (feature_count = %lu)\n", (unsigned long)count);
    if (count == 0) return;
  }
  if (!check_rc_(API(pccd_result_feature(r, 0, &k, pts)), PCCD_OK, "pccd_result_feature", line))
    return;
  ok = k == kind && pts[2] == c && pts[3] == d &&
       ((pts[0] == a && pts[1] == b) || (any_order && pts[0] == b && pts[1] == a));
  if (ok) {
    g_pass++;
  } else {
    g_fail++;
    printf("FAIL line %d [%s, %s]: feature (%d; %ld %ld %ld %ld), expected (%d; %ld %ld %ld %ld)\n",
           line, g_case, g_mode_name, k, (long)pts[0], (long)pts[1], (long)pts[2], (long)pts[3],
           kind, (long)a, (long)b, (long)c, (long)d);
  }
}
#define EXPECT_FEATURE(r, kind, a, b, c, d) expect_feature_((r), (kind), (a), (b), (c), (d), 0, __LINE__)
#define EXPECT_FEATURE_VV(r, a, b) expect_feature_((r), PCCD_VERTEX_VERTEX, (a), (b), NONE, NONE, 1, __LINE__)

#endif
