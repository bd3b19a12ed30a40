/*
 * fuzz_query.c -- libFuzzer harness of the primitive queries: pccd_query_* (polynomial
 * trajectories from doubles and from rational strings, radii), pccd_query_solve,
 * pccd_solve_linear_d, pccd_solve_linear_batch_d, pccd_config and every pccd_result_*
 * getter, in any of the four rounding modes.
 *
 * Input (fuzz_input.h for u8, number, ...):
 *   u8 head       rounding mode = head % 4, variant = (head / 4) % 4:
 *                   0, 3  a query handle with polynomial coordinates
 *                   1     a linear query as doubles (pccd_solve_linear_d + the batch)
 *                   2     a query handle set by pccd_query_set_linear_d
 *                 bit 4: the cross-checks below (each a second solve: taken for half
 *                 the inputs to keep executions cheap); bit 6: batch threads 1 or 2;
 *                 bit 7: a batch of 1 or 2 copies
 *   u8 kind       kind % 5; kind >= 0xF0: an i32 follows, the raw (maybe invalid) kind
 *   u8 cfg        bit 0: cfg NULL; bits 1-2: want_time from {1, 0, 1, -1}; bits 3-4:
 *                 want_exact from {1, 0, 1, 7}; bit 5: a time_tolerance number follows;
 *                 bit 6: a wrong struct_size; bit 7: a u8 follows choosing min_distance
 *                 (low 3 bits) from {none, "0", "1/4", "1e-30", "-1", "1/3", "2", "x"}
 *   variant 0/3:  per point, per axis: u8 spec, n = spec % (FZ_MAX_DEGREE + 2)
 *                 coefficients (numbers), through _s when spec & 0x80 else _d; then for
 *                 SPHERE_SPHERE two radii: u8 (bit k: radius k through _s), 2 numbers
 *   variant 1/2:  npoints * 3 numbers (t = 0), npoints * 3 numbers (t = 1)
 *   then ops until the input ends: u8 op, op % 4 == 0: set_coord_d with raw u8 point,
 *     u8 axis, u8 n (up to 255 coefficients: PCCD_ELIMIT above 65) and n numbers;
 *     1: the same through _s; 2: set_radius_s (u8 which, number); 3: set_radius_d.
 *
 * Checks beyond fuzz_input.h's: every getter of a solved result is consistent (a
 * contact has lo and hi, at least one feature with indices in range, an approximation
 * in [0, 1]; no contact has no time and no feature); the same query solved again under
 * round-to-nearest gives the same collides answer and the same exact time; the linear
 * entry points agree with the query handle and the batch.
 *
 * Cost limits (README.md): degree <= FZ_MAX_DEGREE per coordinate, and the number
 * limits of fuzz_input.h, for anything that is solved. Every query-handle solve
 * (variants 0, 2, 3) also runs under config.max_work = FZ_MAX_WORK (deterministic; a
 * NULL cfg is replaced by the defaults with that bound), as fuzz_scene's do (issue
 * 33): PCCD_ELIMIT is then an answer, and a cross-check is made only when both calls
 * answered. The linear variant (1) keeps its cfg: degree 1, and its batch of two
 * copies takes twice the single call's work.
 */
#include "fuzz_input.h"

#define FZ_MAX_DEGREE 4
#ifndef FZ_MAX_WORK
#define FZ_MAX_WORK 20000
#endif

typedef struct answer {
  int collides, stage, exact;
  char *lo, *hi, *ex; /* malloc'd texts when collides (ex when exact) */
} answer;

typedef struct time_ctx {
  const pccd_result *res;
  int which;
} time_ctx;

static int get_time(const void *ctx, char *buf, size_t cap, size_t *needed)
{
  const time_ctx *c = (const time_ctx *)ctx;
  return pccd_result_time(c->res, c->which, buf, cap, needed);
}

static void answer_free(answer *a)
{
  free(a->lo);
  free(a->hi);
  free(a->ex);
  memset(a, 0, sizeof *a);
}

/* Reads every getter of a solved result and checks their consistency. */
static answer read_result(const pccd_result *res, size_t npoints)
{
  answer a;
  int rc;
  memset(&a, 0, sizeof a);
  FZ_ASSERT(FZ_RC(pccd_result_collides, res, &a.collides) == PCCD_OK);
  FZ_ASSERT(a.collides == 0 || a.collides == 1);
  FZ_ASSERT(FZ_RC(pccd_result_stage, res, &a.stage) == PCCD_OK);
  FZ_ASSERT(a.stage >= PCCD_STAGE_BOUNDS && a.stage <= PCCD_STAGE_EXACT);
  FZ_ASSERT(FZ_RC(pccd_result_time_is_exact, res, &a.exact) == PCCD_OK);
  FZ_ASSERT(a.exact == 0 || (a.exact == 1 && a.collides));
  time_ctx c0 = {res, 0}, c1 = {res, 1}, c2 = {res, 2}, c3 = {res, 3};
  a.lo = fz_read_text(get_time, &c0, "pccd_result_time", &rc);
  FZ_ASSERT(a.collides ? rc == PCCD_OK : rc == PCCD_ESTATE);
  a.hi = fz_read_text(get_time, &c1, "pccd_result_time", &rc);
  FZ_ASSERT(a.collides ? rc == PCCD_OK : rc == PCCD_ESTATE);
  a.ex = fz_read_text(get_time, &c2, "pccd_result_time", &rc);
  FZ_ASSERT(a.exact ? rc == PCCD_OK : rc == PCCD_ESTATE);
  if (a.exact) FZ_ASSERT(strcmp(a.lo, a.ex) == 0 && strcmp(a.hi, a.ex) == 0);
  FZ_ASSERT(fz_read_text(get_time, &c3, "pccd_result_time", &rc) == NULL && rc == PCCD_EINVAL);
  double t = -1;
  rc = FZ_RC(pccd_result_time_approx, res, &t);
  FZ_ASSERT(a.collides ? rc == PCCD_OK && t >= 0 && t <= 1 : rc == PCCD_ESTATE);
  size_t nf = 99, pts[4];
  int kind = -1;
  FZ_ASSERT(FZ_RC(pccd_result_feature_count, res, &nf) == PCCD_OK);
  FZ_ASSERT(a.collides ? nf >= 1 : nf == 0);
  for (size_t i = 0; i < nf; ++i) {
    FZ_ASSERT(FZ_RC(pccd_result_feature, res, i, &kind, pts) == PCCD_OK);
    FZ_ASSERT(kind >= PCCD_VERTEX_FACE && kind <= PCCD_SPHERE_SPHERE);
    size_t used = 0;
    FZ_ASSERT(FZ_RC(pccd_kind_points, (pccd_kind)kind, &used) == PCCD_OK);
    for (size_t k = 0; k < 4; ++k)
      FZ_ASSERT(k < used ? pts[k] < npoints : pts[k] == (size_t)-1);
  }
  FZ_ASSERT(FZ_RC(pccd_result_feature, res, nf, &kind, pts) == PCCD_EINVAL);
  return a;
}

/* The same answer where it must be the same: collides, and the exact time when both
 * have one. */
static void same_answer(const answer *a, const answer *b)
{
  FZ_ASSERT(a->collides == b->collides);
  if (a->exact && b->exact) FZ_ASSERT(strcmp(a->ex, b->ex) == 0);
}

static void read_config(fz_in *in, pccd_config *cfg, const pccd_config **use, char *tol)
{
  static const int want_time[4] = {1, 0, 1, -1}, want_exact[4] = {1, 0, 1, 7};
  uint8_t b = fz_u8(in);
  FZ_ASSERT(FZ_RC(pccd_config_init, cfg) == PCCD_OK);
  cfg->want_time = want_time[(b >> 1) & 3];
  cfg->want_exact = want_exact[(b >> 3) & 3];
  if (b & 32) {
    fz_num x;
    fz_number(in, &x);
    strcpy(tol, x.text);
    cfg->time_tolerance = tol;
  }
  if (b & 64) cfg->struct_size = sizeof *cfg + 8;
  if (b & 128) {
    static const char *const deltas[8] = {NULL, "0", "1/4", "1e-30", "-1", "1/3", "2", "x"};
    cfg->min_distance = deltas[fz_u8(in) & 7];
  }
  *use = (b & 1) ? NULL : cfg;
}

static void set_coord(fz_in *in, pccd_query *q, size_t point, size_t axis, size_t n, int strings,
                      int *max_degree)
{
  double d[256];
  fz_num x[256];
  const char *s[256];
  for (size_t i = 0; i < n; ++i) {
    fz_number(in, &x[i]);
    d[i] = x[i].d;
    s[i] = x[i].text;
  }
  int rc = strings ? FZ_RC(pccd_query_set_coord_s, q, point, axis, s, n)
                   : FZ_RC(pccd_query_set_coord_d, q, point, axis, d, n);
  if (rc == PCCD_OK && (int)n - 1 > *max_degree) *max_degree = (int)n - 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  fz_in in = {data, size, 0};
  uint8_t head = fz_u8(&in);
  int variant = (head / 4) % 4;
  uint8_t kb = fz_u8(&in);
  int kind = kb >= 0xF0 ? fz_i32(&in) : kb % 5;
  pccd_config cfg;
  const pccd_config *use = NULL;
  char tol[260];
  size_t npoints = 0;
  int max_degree = 0;
  fz_set_mode(head);
  read_config(&in, &cfg, &use, tol);
  pccd_result *res = NULL, *res2 = NULL;
  FZ_ASSERT(FZ_RC(pccd_result_new, &res) == PCCD_OK && FZ_RC(pccd_result_new, &res2) == PCCD_OK);
  if (FZ_RC(pccd_kind_points, (pccd_kind)kind, &npoints) != PCCD_OK) {
    pccd_query *q = NULL;
    FZ_ASSERT(FZ_RC(pccd_query_new, &q, (pccd_kind)kind) == PCCD_EINVAL && q == NULL);
    npoints = 0;
  }

  if (variant == 1) {
    /* A linear query as doubles: pccd_solve_linear_d, the same through a query handle
     * and through the batch (one or two copies, one or two threads). */
    double t0[12] = {0}, t1[12] = {0};
    fz_num x;
    for (size_t i = 0; i < 3 * npoints; ++i) fz_number(&in, &x), t0[i] = x.d;
    for (size_t i = 0; i < 3 * npoints; ++i) fz_number(&in, &x), t1[i] = x.d;
    if (in.too_costly) goto done; /* README.md, limits: the tolerance */
    int rc = FZ_RC(pccd_solve_linear_d, (pccd_kind)kind, t0, t1, use, res);
    if (rc == PCCD_OK && (head & 16)) {
      answer a = read_result(res, npoints), b;
      pccd_query *q = NULL;
      FZ_ASSERT(FZ_RC(pccd_query_new, &q, (pccd_kind)kind) == PCCD_OK);
      FZ_ASSERT(FZ_RC(pccd_query_set_linear_d, q, t0, t1) == PCCD_OK);
      FZ_ASSERT(FZ_RC(pccd_query_solve, q, use, res2) == PCCD_OK);
      b = read_result(res2, npoints);
      same_answer(&a, &b);
      answer_free(&b);
      pccd_query_free(q);
      /* The batch: every entry is the single call's answer. */
      double b0[24], b1[24], lo[2], hi[2];
      unsigned char col[2] = {9, 9}, ex[2] = {9, 9};
      int stage[2] = {-1, -1};
      size_t nq = 1 + ((head >> 7) & 1);
      for (size_t k = 0; k < nq; ++k) { /* query k at k * npoints * 3 */
        memcpy(b0 + 3 * npoints * k, t0, 3 * npoints * sizeof(double));
        memcpy(b1 + 3 * npoints * k, t1, 3 * npoints * sizeof(double));
      }
      pccd_batch_options opt;
      pccd_batch_out out;
      FZ_ASSERT(FZ_RC(pccd_batch_options_init, &opt) == PCCD_OK);
      opt.threads = 1 + ((head >> 6) & 1);
      memset(&out, 0, sizeof out);
      out.struct_size = sizeof out;
      out.collides = col;
      out.stage = stage;
      out.lo = lo;
      out.hi = hi;
      out.exact = ex;
      FZ_ASSERT(FZ_RC(pccd_solve_linear_batch_d, (pccd_kind)kind, nq, b0, b1, use, &opt, &out) ==
                PCCD_OK);
      for (size_t k = 0; k < nq; ++k) {
        FZ_ASSERT(col[k] == a.collides && stage[k] == a.stage && ex[k] == a.exact);
        if (a.collides) {
          double t = -1;
          FZ_ASSERT(pccd_result_time_approx(res, &t) == PCCD_OK);
          FZ_ASSERT(lo[k] <= t && t <= hi[k] && 0 <= lo[k] && hi[k] <= 1);
        } else {
          FZ_ASSERT(isnan(lo[k]) && isnan(hi[k]));
        }
      }
      answer_free(&a);
    } else if (rc == PCCD_OK) {
      answer a = read_result(res, npoints);
      answer_free(&a);
    } else {
      /* an error leaves the result unsolved */
      int c;
      FZ_ASSERT(FZ_RC(pccd_result_collides, res, &c) == PCCD_ESTATE);
    }
    goto done;
  }

  pccd_query *q = NULL;
  if (FZ_RC(pccd_query_new, &q, (pccd_kind)kind) != PCCD_OK) goto done;
  if (variant == 2) {
    double t0[12] = {0}, t1[12] = {0};
    fz_num x;
    for (size_t i = 0; i < 3 * npoints; ++i) fz_number(&in, &x), t0[i] = x.d;
    for (size_t i = 0; i < 3 * npoints; ++i) fz_number(&in, &x), t1[i] = x.d;
    if (FZ_RC(pccd_query_set_linear_d, q, t0, t1) == PCCD_OK) max_degree = 1;
  } else {
    for (size_t i = 0; i < npoints; ++i)
      for (size_t a = 0; a < 3; ++a) {
        uint8_t spec = fz_u8(&in);
        set_coord(&in, q, i, a, (spec & 0x7f) % (FZ_MAX_DEGREE + 2), spec & 0x80, &max_degree);
      }
  }
  if (kind == PCCD_SPHERE_SPHERE) {
    uint8_t api = fz_u8(&in);
    for (size_t k = 0; k < 2; ++k) {
      fz_num r;
      fz_number(&in, &r);
      if (api & (1u << k)) FZ_RC(pccd_query_set_radius_s, q, k, r.text);
      else FZ_RC(pccd_query_set_radius_d, q, k, r.d);
    }
  }
  while (in.n > 0) {
    uint8_t op = fz_u8(&in);
    if (op % 4 < 2) {
      size_t point = fz_u8(&in), axis = fz_u8(&in), n = fz_u8(&in);
      set_coord(&in, q, point, axis, n, op % 4 == 1, &max_degree);
    } else {
      size_t which = fz_u8(&in);
      fz_num r;
      fz_number(&in, &r);
      if (op % 4 == 2) FZ_RC(pccd_query_set_radius_s, q, which, r.text);
      else FZ_RC(pccd_query_set_radius_d, q, which, r.d);
    }
  }
  if (max_degree > FZ_MAX_DEGREE || in.too_costly) goto free_query; /* README.md, limits */
  if (use == NULL) {
    FZ_ASSERT(FZ_RC(pccd_config_init, &cfg) == PCCD_OK);
    use = &cfg;
  }
  cfg.max_work = FZ_MAX_WORK; /* the per-input work bound (above) */

  if (FZ_RC(pccd_query_solve, q, use, res) != PCCD_OK) {
    int c; /* an error leaves the result unsolved */
    FZ_ASSERT(FZ_RC(pccd_result_collides, res, &c) == PCCD_ESTATE);
  } else {
    answer a = read_result(res, npoints), b;
    if (head & 16) {
      /* Solved again into the same result: the same answer; under round-to-nearest
       * when the mode is another: the same decision. */
      FZ_ASSERT(FZ_RC(pccd_query_solve, q, use, res) == PCCD_OK);
      b = read_result(res, npoints);
      FZ_ASSERT(a.collides == b.collides && a.stage == b.stage && a.exact == b.exact);
      if (a.collides) FZ_ASSERT(strcmp(a.lo, b.lo) == 0 && strcmp(a.hi, b.hi) == 0);
      answer_free(&b);
      if (fz_mode != FE_TONEAREST) {
        fz_restore_mode();
        const int rc2 = FZ_RC(pccd_query_solve, q, use, res2);
        FZ_ASSERT(rc2 == PCCD_OK || rc2 == PCCD_ELIMIT); /* the bound: compared when answered */
        if (rc2 == PCCD_OK) {
          b = read_result(res2, npoints);
          same_answer(&a, &b);
          answer_free(&b);
        }
      }
    }
    answer_free(&a);
  }
free_query:
  pccd_query_free(q);
done:
  pccd_result_free(res);
  pccd_result_free(res2);
  fz_restore_mode();
  return 0;
}
