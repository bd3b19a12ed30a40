/*
 * test_api.c -- the C API of libpolyccd, through real queries whose answers are known by
 * construction, and every error path of include/polyccd.h.
 *
 * Plain C99 test program (built by `make test-c` with -std=c99 -Wall -Wextra -Werror).
 * Prints every failed check with its inputs, then a last line "N passed, N failed";
 * exit status 0 only when nothing failed (PCCD_TEST_VERBOSE=1 also prints the message of
 * every error path checked). Every handle is freed (`make valgrind` runs this
 * program under valgrind and requires 0 leaks).
 *
 * The known-answer cases run four times, under each IEEE rounding mode (house style 21 and
 * 39): every answer must be the same, and after every single API call the rounding mode
 * must still be the one the test set.
 *
 * Exact times are checked exactly: the p/q strings are parsed into a small decimal bignum
 * (below) and compared by cross-multiplication, so an irrational contact time t* (balls
 * touching at t* = 1/sqrt(2)) is checked as lo^2 < 1/2 < hi^2 without any rounding.
 *
 * Long by design (house style 29): a flat list of known-answer cases and error paths, a few
 * lines each; the bignum lives in exact_rational.h.
 *
 * No "#pragma STDC FENV_ACCESS ON": GCC ignores it with a -Wunknown-pragmas warning (an
 * error under -Werror). This file does no floating-point arithmetic whose rounding matters
 * while a directed rounding mode is set: expected approximations are hex literals, the
 * scaled inputs are built with ldexp/nextafter (exact in every mode), and the fused
 * multiply-add check runs under FE_TONEAREST.
 */
#include "polyccd.h"

#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "exact_rational.h"

/* ------------------------------------------------------------------------------------ */
/* Checks                                                                                 */

static int g_pass, g_fail;
static const char *g_case = "";  /* name of the running case, printed with a failure */
static int g_mode = FE_TONEAREST; /* the rounding mode every API call must leave behind */
static const char *g_mode_name = "FE_TONEAREST";
static long g_calls, g_mode_changed; /* API calls made / calls after which the mode differed */
static int g_verbose; /* PCCD_TEST_VERBOSE set: print the message of every checked error */

static int check_(int ok, const char *expr, int line)
{
  if (ok) {
    g_pass++;
  } else {
    g_fail++;
    printf("FAIL line %d [%s, %s]: %s\n", line, g_case, g_mode_name, expr);
  }
  return ok;
}
#define CHECK(cond) check_((cond) ? 1 : 0, #cond, __LINE__)

static const char *rc_name(int rc)
{
  switch (rc) {
  case PCCD_OK: return "PCCD_OK";
  case PCCD_EINVAL: return "PCCD_EINVAL";
  case PCCD_ENOMEM: return "PCCD_ENOMEM";
  case PCCD_ELIMIT: return "PCCD_ELIMIT";
  case PCCD_ERANGE: return "PCCD_ERANGE";
  case PCCD_ESTATE: return "PCCD_ESTATE";
  case PCCD_EINTERNAL: return "PCCD_EINTERNAL";
  default: return "(unknown status)";
  }
}

/* rc must equal want; on a mismatch the failure shows both and the library's message. */
static int check_rc_(int rc, int want, const char *expr, int line)
{
  if (rc == want) {
    g_pass++;
    return 1;
  }
  g_fail++;
  printf("FAIL line %d [%s, %s]: %s returned %d %s, expected %s; pccd_last_error: \"%s\"\n",
         line, g_case, g_mode_name, expr, rc, rc_name(rc), rc_name(want),
         rc < 0 ? pccd_last_error() : "(not an error)");
  return 0;
}
#define CHECK_RC(call, want) check_rc_((call), (want), #call, __LINE__)

/* Every API call goes through API(): afterwards the rounding mode must be unchanged. */
static int after_call(int rc)
{
  g_calls++;
  if (fegetround() != g_mode) {
    g_mode_changed++;
    fesetround(g_mode);
  }
  return rc;
}
#define API(call) after_call(call)
#define FREE_Q(q) (pccd_query_free(q), after_call(0))
#define FREE_R(r) (pccd_result_free(r), after_call(0))

/* Case-insensitive substring test (the messages' wording is the library's). */
static int mentions(const char *msg, const char *what)
{
  size_t n = strlen(what), i, j;
  for (i = 0; msg[i] != '\0'; i++) {
    for (j = 0; j < n; j++) {
      char a = msg[i + j], b = what[j];
      if (a >= 'A' && a <= 'Z') a = (char)(a - 'A' + 'a');
      if (b >= 'A' && b <= 'Z') b = (char)(b - 'A' + 'a');
      if (a == '\0' || a != b) break;
    }
    if (j == n) return 1;
  }
  return n == 0;
}

/* An error path: rc must be `want`, pccd_last_error() non-NULL, non-empty and, when
 * `mention` is given, it must name the offending place (an index, a value). */
static void check_err_(int rc, int want, const char *mention, const char *expr, int line)
{
  const char *msg;
  if (!check_rc_(rc, want, expr, line)) return;
  msg = pccd_last_error();
  if (g_verbose) printf("ok line %d: %s -> %s: \"%s\"\n", line, expr, rc_name(rc), msg ? msg : "(NULL)");
  if (!check_(msg != NULL, "pccd_last_error() != NULL", line)) return;
  if (!check_(msg[0] != '\0', "pccd_last_error() is not empty", line)) return;
  if (mention != NULL && !mentions(msg, mention)) {
    g_fail++;
    printf("FAIL line %d [%s, %s]: the message of %s does not mention \"%s\": \"%s\"\n",
           line, g_case, g_mode_name, expr, mention, msg);
  } else if (mention != NULL) {
    g_pass++;
  }
}
#define CHECK_ERR(call, want, mention) check_err_(API(call), (want), (mention), #call, __LINE__)

/* ------------------------------------------------------------------------------------ */
/* Helpers around the API                                                                 */

static const size_t NONE = (size_t)-1;

/* Makes a query of `kind` (checked). */
static pccd_query *mk(pccd_kind kind)
{
  pccd_query *q = NULL;
  CHECK_RC(API(pccd_query_new(&q, kind)), PCCD_OK);
  CHECK(q != NULL);
  return q;
}

static pccd_result *mk_res(void)
{
  pccd_result *r = NULL;
  CHECK_RC(API(pccd_result_new(&r)), PCCD_OK);
  CHECK(r != NULL);
  return r;
}

static void set_s_(pccd_query *q, size_t pt, size_t ax, const char *const *c, size_t n, int line)
{
  check_rc_(API(pccd_query_set_coord_s(q, pt, ax, c, n)), PCCD_OK, "pccd_query_set_coord_s", line);
}
static void set_d_(pccd_query *q, size_t pt, size_t ax, const double *c, size_t n, int line)
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
static void fixed_s(pccd_query *q, size_t pt, const char *x, const char *y, const char *z)
{
  SETS(q, pt, 0, x);
  SETS(q, pt, 1, y);
  SETS(q, pt, 2, z);
}

/* The static triangle of the vertex-face cases: f0 = (0,0,0), f1 = (3,0,0), f2 = (0,3,0)
 * (points 1, 2, 3). Its centroid is (1,1,0); its open edge f1 f2 is x + y = 3. */
static void triangle_s(pccd_query *q)
{
  fixed_s(q, 1, "0", "0", "0");
  fixed_s(q, 2, "3", "0", "0");
  fixed_s(q, 3, "0", "3", "0");
}

static int solve(const pccd_query *q, const pccd_config *cfg, pccd_result *r)
{
  return API(pccd_query_solve(q, cfg, r));
}

/* Time `which` of r as a malloc'd string, fetched the documented way (size query with
 * cap 0 first); NULL when the call fails (its status in *rc). */
static char *time_str(const pccd_result *r, int which, int *rc)
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

static int collides(const pccd_result *r)
{
  int c = -1;
  CHECK_RC(API(pccd_result_collides(r, &c)), PCCD_OK);
  CHECK(c == 0 || c == 1);
  return c;
}

static void check_stage(const pccd_result *r)
{
  int st = -1;
  CHECK_RC(API(pccd_result_stage(r, &st)), PCCD_OK);
  CHECK(st >= PCCD_STAGE_BOUNDS && st <= PCCD_STAGE_EXACT);
}

/* The result says: no contact during [0, 1]. */
static void expect_none_(const pccd_result *r, int line)
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
static void expect_exact_(const pccd_result *r, const char *t, double approx, int line)
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
static void expect_enclosure_(const pccd_result *r, const char *tol, long double tol_ld, rat_pred lo_ok,
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
static void expect_feature_(const pccd_result *r, int kind, size_t a, size_t b, size_t c, size_t d,
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

/* ------------------------------------------------------------------------------------ */
/* Known-answer cases                                                                     */

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

static void run_known_answers(void)
{
  pccd_result *r = mk_res();
  case_vertex_face_centre(r);
  case_vertex_face_ulp(r);
  case_vertex_face_1e30(r);
  case_vertex_face_graze(r);
  case_vertex_face_ends(r);
  case_edge_edge_cross(r);
  case_edge_edge_collinear(r);
  case_vertex_edge(r);
  case_vertex_vertex(r);
  case_sphere_sphere(r);
  case_result_reuse(r);
  case_inputs_copied(r);
  FREE_R(r);
}

/* ------------------------------------------------------------------------------------ */
/* Error paths                                                                            */

static void errors_misc(void)
{
  size_t c = 0;
  pccd_config cfg;
  pccd_query *q = NULL;
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
  CHECK_ERR(pccd_kind_points((pccd_kind)5, &c), PCCD_EINVAL, "5");
  CHECK_ERR(pccd_kind_points((pccd_kind)-1, &c), PCCD_EINVAL, NULL);
  CHECK_ERR(pccd_kind_points(PCCD_VERTEX_FACE, NULL), PCCD_EINVAL, "NULL");

  CHECK_ERR(pccd_config_init(NULL), PCCD_EINVAL, "NULL");
  memset(&cfg, 0xAB, sizeof cfg);
  CHECK_RC(API(pccd_config_init(&cfg)), PCCD_OK);
  CHECK(cfg.struct_size == sizeof(pccd_config));
  CHECK(cfg.time_tolerance == NULL);
  CHECK(cfg.want_time == 1);
  CHECK(cfg.want_exact == 1);

  g_case = "handles";
  CHECK_ERR(pccd_query_new(NULL, PCCD_VERTEX_FACE), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_query_new(&q, (pccd_kind)7), PCCD_EINVAL, "7");
  FREE_Q(q); /* NULL, or whatever the failed call left: must be safe either way */
  q = NULL;
  CHECK_ERR(pccd_query_new(&q, (pccd_kind)-3), PCCD_EINVAL, NULL);
  FREE_Q(q);
  CHECK_ERR(pccd_result_new(NULL), PCCD_EINVAL, "NULL");
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

  CHECK_ERR(pccd_query_set_coord_d(NULL, 0, 0, DARR(1.0), 1), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_query_set_coord_s(NULL, 0, 0, SARR("1"), 1), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_query_set_coord_d(q, 4, 0, DARR(1.0), 1), PCCD_EINVAL, "4");
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 3, DARR(1.0), 1), PCCD_EINVAL, "3");
  CHECK_ERR(pccd_query_set_coord_d(q, NONE, 0, DARR(1.0), 1), PCCD_EINVAL, NULL);
  CHECK_ERR(pccd_query_set_coord_s(q, 4, 0, SARR("1"), 1), PCCD_EINVAL, "4");
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 3, SARR("1"), 1), PCCD_EINVAL, "3");
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, NULL, 2), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, NULL, 2), PCCD_EINVAL, "NULL");
  /* non-finite doubles, at coefficient 5: the message names it */
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, DARR(0, 0, 0, 0, 0, nan_), 6), PCCD_EINVAL, "5");
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, DARR(0, 0, 0, 0, 0, inf_), 6), PCCD_EINVAL, "5");
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, DARR(0, 0, 0, 0, 0, -inf_), 6), PCCD_EINVAL, "5");
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, DARR(nan_), 1), PCCD_EINVAL, NULL);
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
      if (!CHECK(mentions(pccd_last_error(), "5")))
        printf("    message for \"%s\": \"%s\"\n", bad[i], pccd_last_error());
    }
  }
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, s6, 6), PCCD_EINVAL, "5"); /* a NULL string */

  /* degree limit: 65 coefficients (degree 64) pass, 66 (degree 65) do not */
  for (i = 0; i < 66; i++) {
    d66[i] = 1.0;
    s66[i] = "1";
  }
  q2 = mk(PCCD_VERTEX_FACE);
  CHECK_RC(API(pccd_query_set_coord_d(q2, 0, 0, d66, PCCD_MAX_TRAJ_DEGREE + 1)), PCCD_OK);
  CHECK_RC(API(pccd_query_set_coord_s(q2, 0, 0, s66, PCCD_MAX_TRAJ_DEGREE + 1)), PCCD_OK);
  FREE_Q(q2);
  CHECK_ERR(pccd_query_set_coord_d(q, 0, 2, d66, PCCD_MAX_TRAJ_DEGREE + 2), PCCD_ELIMIT, NULL);
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, s66, PCCD_MAX_TRAJ_DEGREE + 2), PCCD_ELIMIT, NULL);

  /* text limits: exponent beyond PCCD_MAX_EXPONENT, string beyond PCCD_MAX_NUMBER_CHARS */
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, SARR("1e-100001"), 1), PCCD_ELIMIT, NULL);
  CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, SARR("1e100001"), 1), PCCD_ELIMIT, NULL);
  longnum = (char *)malloc(PCCD_MAX_NUMBER_CHARS + 2);
  if (CHECK(longnum != NULL)) {
    memset(longnum, '7', PCCD_MAX_NUMBER_CHARS + 1);
    longnum[PCCD_MAX_NUMBER_CHARS + 1] = '\0';
    {
      const char *c[1];
      c[0] = longnum;
      CHECK_ERR(pccd_query_set_coord_s(q, 0, 2, c, 1), PCCD_ELIMIT, NULL);
      longnum[PCCD_MAX_NUMBER_CHARS] = '\0'; /* exactly at the limit: accepted */
      q2 = mk(PCCD_VERTEX_FACE);
      CHECK_RC(API(pccd_query_set_coord_s(q2, 0, 0, c, 1)), PCCD_OK);
      CHECK_RC(API(pccd_query_set_coord_s(q2, 0, 0, SARR("1e-100000"), 1)), PCCD_OK);
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
  CHECK_ERR(pccd_query_set_coord_d(q2, 3, 0, DARR(1.0), 1), PCCD_EINVAL, "3");
  FREE_Q(q2);
  q2 = mk(PCCD_VERTEX_VERTEX);
  CHECK_ERR(pccd_query_set_coord_d(q2, 2, 0, DARR(1.0), 1), PCCD_EINVAL, "2");
  FREE_Q(q2);
  q2 = mk(PCCD_SPHERE_SPHERE);
  CHECK_ERR(pccd_query_set_coord_s(q2, 2, 0, SARR("1"), 1), PCCD_EINVAL, "2");
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
  CHECK_ERR(pccd_query_set_linear_d(NULL, p0, p1), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_query_set_linear_d(q, NULL, p1), PCCD_EINVAL, "p_t0");
  CHECK_ERR(pccd_query_set_linear_d(q, p0, NULL), PCCD_EINVAL, "p_t1");
  CHECK_ERR(pccd_query_set_linear_d(q, p0, bad), PCCD_EINVAL, "p_t1");
  bad[5] = -HUGE_VAL;
  CHECK_ERR(pccd_query_set_linear_d(q, bad, p0), PCCD_EINVAL, "p_t0");
  CHECK_RC(solve(q, NULL, r), PCCD_OK); /* unchanged */
  EXPECT_EXACT(r, "1/2", 0.5);

  CHECK_ERR(pccd_solve_linear_d(PCCD_SPHERE_SPHERE, p0, p1, NULL, r), PCCD_EINVAL, NULL);
  CHECK_ERR(pccd_solve_linear_d((pccd_kind)9, p0, p1, NULL, r), PCCD_EINVAL, "9");
  CHECK_ERR(pccd_solve_linear_d(PCCD_VERTEX_FACE, NULL, p1, NULL, r), PCCD_EINVAL, "p_t0");
  CHECK_ERR(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, NULL, NULL, r), PCCD_EINVAL, "p_t1");
  CHECK_ERR(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, bad, NULL, r), PCCD_EINVAL, "p_t1");
  CHECK_ERR(pccd_solve_linear_d(PCCD_VERTEX_FACE, p0, p1, NULL, NULL), PCCD_EINVAL, "NULL");

  g_case = "radius errors";
  s = mk(PCCD_SPHERE_SPHERE);
  CHECK_ERR(pccd_query_set_radius_d(NULL, 0, 1.0), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_query_set_radius_s(NULL, 0, "1"), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_query_set_radius_d(s, 2, 1.0), PCCD_EINVAL, "2");
  CHECK_ERR(pccd_query_set_radius_s(s, 2, "1"), PCCD_EINVAL, "2");
  CHECK_ERR(pccd_query_set_radius_d(s, 0, nan("")), PCCD_EINVAL, NULL);
  CHECK_ERR(pccd_query_set_radius_d(s, 0, HUGE_VAL), PCCD_EINVAL, NULL);
  CHECK_ERR(pccd_query_set_radius_s(s, 0, "abc"), PCCD_EINVAL, NULL);
  CHECK_ERR(pccd_query_set_radius_s(s, 0, "1/0"), PCCD_EINVAL, NULL);
  CHECK_ERR(pccd_query_set_radius_s(s, 0, ""), PCCD_EINVAL, NULL);
  CHECK_ERR(pccd_query_set_radius_s(s, 0, NULL), PCCD_EINVAL, "NULL");
  /* radius on a query without balls: some error (the header does not say which) */
  rc = API(pccd_query_set_radius_d(q, 0, 1.0));
  CHECK(rc < 0);
  CHECK(pccd_last_error()[0] != '\0');

  /* radii default to 0; solving needs both > 0 */
  SETS(s, 1, 0, "4", "-4");
  CHECK_ERR(solve(s, NULL, r), PCCD_EINVAL, NULL);
  CHECK_RC(API(pccd_query_set_radius_d(s, 0, 1.0)), PCCD_OK);
  CHECK_ERR(solve(s, NULL, r), PCCD_EINVAL, NULL);
  /* a negative radius is rejected when set or when solved */
  rc = API(pccd_query_set_radius_s(s, 1, "-1"));
  if (rc == PCCD_OK) {
    CHECK_ERR(solve(s, NULL, r), PCCD_EINVAL, NULL);
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

static void errors_solve_and_result(void)
{
  static const char *const bad_tol[] = {"0", "-1e-6", "abc", "1/0", "", "-0"};
  double p0[12] = {1, 1, 1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  double p1[12] = {1, 1, -1, 0, 0, 0, 3, 0, 0, 0, 3, 0};
  pccd_query *q = mk(PCCD_VERTEX_FACE);
  pccd_result *r = mk_res(), *fresh = mk_res(), *irr = mk_res();
  pccd_config cfg;
  char buf[16];
  size_t needed, count, pts[4];
  int v, rc, kind, which;
  double t;
  size_t i;

  g_case = "solve errors";
  CHECK_RC(API(pccd_query_set_linear_d(q, p0, p1)), PCCD_OK);
  CHECK_ERR(solve(NULL, NULL, r), PCCD_EINVAL, "NULL");
  CHECK_ERR(solve(q, NULL, NULL), PCCD_EINVAL, "NULL");
  for (i = 0; i < sizeof bad_tol / sizeof bad_tol[0]; i++) {
    CHECK_RC(API(pccd_config_init(&cfg)), PCCD_OK);
    cfg.time_tolerance = bad_tol[i];
    CHECK_RC(solve(q, NULL, r), PCCD_OK);
    rc = solve(q, &cfg, r);
    if (!CHECK(rc == PCCD_EINVAL)) printf("    time_tolerance \"%s\" gave %s\n", bad_tol[i], rc_name(rc));
    CHECK(pccd_last_error()[0] != '\0');
    /* on error the result is reset to "nothing solved" */
    CHECK_ERR(pccd_result_collides(r, &v), PCCD_ESTATE, NULL);
  }

  g_case = "an unsolved result";
  CHECK_ERR(pccd_result_collides(fresh, &v), PCCD_ESTATE, NULL);
  for (which = 0; which <= 2; which++) {
    needed = 0;
    CHECK_ERR(pccd_result_time(fresh, which, buf, sizeof buf, &needed), PCCD_ESTATE, NULL);
  }
  CHECK_ERR(pccd_result_time_is_exact(fresh, &v), PCCD_ESTATE, NULL);
  CHECK_ERR(pccd_result_time_approx(fresh, &t), PCCD_ESTATE, NULL);
  CHECK_ERR(pccd_result_feature_count(fresh, &count), PCCD_ESTATE, NULL);
  CHECK_ERR(pccd_result_feature(fresh, 0, &kind, pts), PCCD_ESTATE, NULL);
  v = -1;
  rc = API(pccd_result_stage(fresh, &v));
  CHECK(rc == PCCD_ESTATE || (rc == PCCD_OK && v == PCCD_STAGE_NONE));

  g_case = "NULL arguments of result calls";
  CHECK_RC(solve(q, NULL, r), PCCD_OK);
  CHECK_ERR(pccd_result_collides(NULL, &v), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_collides(r, NULL), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_stage(NULL, &v), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_stage(r, NULL), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_time(NULL, 0, buf, sizeof buf, &needed), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_time_is_exact(NULL, &v), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_time_is_exact(r, NULL), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_time_approx(NULL, &t), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_time_approx(r, NULL), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_feature_count(NULL, &count), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_feature_count(r, NULL), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_feature(NULL, 0, &kind, pts), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_feature(r, 0, NULL, pts), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_feature(r, 0, &kind, NULL), PCCD_EINVAL, "NULL");
  CHECK_ERR(pccd_result_feature(r, 1, &kind, pts), PCCD_EINVAL, "1"); /* one feature: index 0 */
  CHECK_ERR(pccd_result_feature(r, NONE, &kind, pts), PCCD_EINVAL, NULL);
  CHECK_ERR(pccd_result_time(r, 3, buf, sizeof buf, &needed), PCCD_EINVAL, "3");
  CHECK_ERR(pccd_result_time(r, -1, buf, sizeof buf, &needed), PCCD_EINVAL, NULL);

  g_case = "time buffer sizes";
  /* "1/2" needs 4 bytes */
  needed = 0;
  CHECK_ERR(pccd_result_time(r, 0, NULL, 0, &needed), PCCD_ERANGE, NULL);
  CHECK(needed == 4);
  for (i = 0; i < 4; i++) {
    memset(buf, 'X', sizeof buf);
    needed = 0;
    CHECK_ERR(pccd_result_time(r, 2, buf, i, &needed), PCCD_ERANGE, NULL);
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
    CHECK_ERR(pccd_result_time(irr, 2, buf, sizeof buf, &needed), PCCD_ESTATE, NULL);
    FREE_Q(s);
  }

  FREE_Q(q);
  FREE_R(r);
  FREE_R(fresh);
  FREE_R(irr);
}

/* ------------------------------------------------------------------------------------ */
/* Floating-point environment assumptions                                                 */

/* The interval filters assume that a*a + b is rounded twice (a product, then a sum):
 * a fused multiply-add would round once and break their error bounds. The library is
 * built with -ffp-contract=off; this test program is built with -std=c99, under which
 * GCC also does not contract. a = 1 + 2^-27: a*a = 1 + 2^-26 + 2^-54, which rounds to
 * 1 + 2^-26 (2^-54 is below half an ulp of 1), so a*a + b with b = -(1 + 2^-26) is 0
 * when not fused and 2^-54 when fused. */
static void check_no_fma(void)
{
  volatile double a = 0x1.0000002p+0, b = -0x1.0000004p+0;
  double r;
  g_case = "a*a + b is not fused";
  fesetround(FE_TONEAREST);
  r = a * a + b;
  if (!CHECK(r == 0.0)) printf("    a*a + b = %a (fused multiply-add?)\n", r);
}

int main(void)
{
  static const struct {
    int mode;
    const char *name;
  } modes[] = {{FE_TONEAREST, "FE_TONEAREST"},
               {FE_UPWARD, "FE_UPWARD"},
               {FE_DOWNWARD, "FE_DOWNWARD"},
               {FE_TOWARDZERO, "FE_TOWARDZERO"}};
  size_t m;

  g_verbose = getenv("PCCD_TEST_VERBOSE") != NULL;
  check_no_fma();

  for (m = 0; m < sizeof modes / sizeof modes[0]; m++) {
    g_mode = modes[m].mode;
    g_mode_name = modes[m].name;
    g_calls = g_mode_changed = 0;
    if (!CHECK(fesetround(g_mode) == 0)) continue;
    run_known_answers();
    if (m == 1) { /* the error paths once under a directed mode as well */
      errors_set_coord();
      errors_solve_and_result();
    }
    g_case = "rounding mode preserved";
    if (!CHECK(g_mode_changed == 0))
      printf("    %ld of %ld API calls returned with a rounding mode other than %s\n",
             g_mode_changed, g_calls, g_mode_name);
  }
  fesetround(FE_TONEAREST);
  g_mode = FE_TONEAREST;
  g_mode_name = "FE_TONEAREST";

  errors_misc();
  errors_set_coord();
  errors_linear_radius();
  errors_solve_and_result();
  g_case = "rounding mode preserved (error paths)";
  CHECK(g_mode_changed == 0);

  printf("%d passed, %d failed\n", g_pass, g_fail);
  return g_fail == 0 ? 0 : 1;
}
