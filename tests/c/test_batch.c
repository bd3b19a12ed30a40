/*
 * test_batch.c -- pccd_solve_linear_batch_d and pccd_batch_options_init: known answers
 * (a vertex through a triangle at t = 1/2, t = 1/3 (not a double: outward-rounded
 * bounds), a miss, an edge crossing at t = 1/4), every entry equal to the single call
 * pccd_solve_linear_d for 1 and 2 threads on a grid of small-integer queries (ties,
 * touching, coplanar motion), NULL output arrays left alone, and every error path with
 * its PLACE (nothing written when an input is bad). Run under each rounding mode
 * (check.h); valgrind and the sanitizers run it like every tests/c/test_*.c.
 */
#include "polyccd.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

#define N_GRID 600

/* Vertex-face: query k's 4 points at t = 0 and t = 1 (x, y, z each). */
static double g_t0[N_GRID * 12], g_t1[N_GRID * 12];

static pccd_batch_out out_of(unsigned char *col, int *stage, double *lo, double *hi, unsigned char *ex)
{
  pccd_batch_out o;
  memset(&o, 0, sizeof o);
  o.struct_size = sizeof o;
  o.collides = col;
  o.stage = stage;
  o.lo = lo;
  o.hi = hi;
  o.exact = ex;
  return o;
}

static void known_answers(void)
{
  /* 0: vertex (1/4, 1/4, 1) -> (1/4, 1/4, -1) through the triangle z = 0: t = 1/2.
   * 1: the same vertex from z = 1 to z = -2: t = 1/3, not a double.
   * 2: the vertex passes beside the triangle (x = 3): no contact. */
  const double t0[36] = {0.25, 0.25, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0,
                         0.25, 0.25, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0,
                         3, 0.25, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  const double t1[36] = {0.25, 0.25, -1, 0, 0, 0, 1, 0, 0, 0, 1, 0,
                         0.25, 0.25, -2, 0, 0, 0, 1, 0, 0, 0, 1, 0,
                         3, 0.25, -1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  unsigned char col[3], ex[3];
  int stage[3];
  double lo[3], hi[3];
  pccd_batch_out o = out_of(col, stage, lo, hi, ex);
  pccd_batch_options opt;
  g_case = "known answers";
  OK(pccd_batch_options_init(&opt));
  CHECK(opt.struct_size == sizeof opt && opt.threads == 1);
  OK(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, 3, t0, t1, NULL, &opt, &o));
  CHECK(col[0] == 1 && ex[0] == 1 && lo[0] == 0.5 && hi[0] == 0.5);
  /* 1/3 lies strictly between the two doubles around it. */
  CHECK(col[1] == 1 && ex[1] == 1 && lo[1] == 0x1.5555555555555p-2 && hi[1] == 0x1.5555555555556p-2);
  CHECK(col[2] == 0 && ex[2] == 0 && isnan(lo[2]) && isnan(hi[2]) && stage[2] == PCCD_STAGE_BOUNDS);
  CHECK(stage[0] >= PCCD_STAGE_BOUNDS && stage[0] <= PCCD_STAGE_EXACT);
  {
    /* Edge-edge: a0 a1 on the x axis, b0 b1 crossing it at x = 1/2 when z = 0 at t = 1/4. */
    const double e0[12] = {0, 0, 0, 1, 0, 0, 0.5, -1, 0.25, 0.5, 1, 0.25};
    const double e1[12] = {0, 0, 0, 1, 0, 0, 0.5, -1, -0.75, 0.5, 1, -0.75};
    OK(pccd_solve_linear_batch_d(PCCD_EDGE_EDGE, 1, e0, e1, NULL, NULL, &o));
    CHECK(col[0] == 1 && ex[0] == 1 && lo[0] == 0.25 && hi[0] == 0.25);
  }
}

/* Every entry against pccd_solve_linear_d, 1 and 2 threads, with and without a time. */
static void same_as_single(void)
{
  static unsigned char col[N_GRID], ex[N_GRID];
  static int stage[N_GRID];
  static double lo[N_GRID], hi[N_GRID];
  pccd_batch_out o = out_of(col, stage, lo, hi, ex);
  pccd_batch_options opt;
  pccd_config cfg;
  pccd_result *r = NULL;
  unsigned seed = 12345, threads;
  int want_time;
  size_t k, i;
  g_case = "batch == single calls";
  for (k = 0; k < N_GRID * 12; ++k) { /* small integers: ties, touching boxes, coplanar motion */
    seed = seed * 1103515245u + 12345u;
    g_t0[k] = (double)((seed >> 16) % 3) - 1;
    seed = seed * 1103515245u + 12345u;
    g_t1[k] = (double)((seed >> 16) % 3) - 1;
  }
  OK(pccd_result_new(&r));
  OK(pccd_batch_options_init(&opt));
  OK(pccd_config_init(&cfg));
  cfg.time_tolerance = "1e-6";
  for (want_time = 0; want_time <= 1; ++want_time)
    for (threads = 1; threads <= 2; ++threads) {
      size_t differ = 0;
      cfg.want_time = want_time;
      opt.threads = threads;
      OK(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, N_GRID, g_t0, g_t1, &cfg, &opt, &o));
      for (i = 0; i < N_GRID; ++i) {
        int c = 0, s = 0, e = 0;
        char buf[128];
        OK(pccd_solve_linear_d(PCCD_VERTEX_FACE, g_t0 + 12 * i, g_t1 + 12 * i, &cfg, r));
        OK(pccd_result_collides(r, &c));
        OK(pccd_result_stage(r, &s));
        if (c) {
          double approx = 0;
          OK(pccd_result_time_is_exact(r, &e));
          OK(pccd_result_time(r, 0, buf, sizeof buf, NULL));
          OK(pccd_result_time_approx(r, &approx));
          /* The enclosure's doubles bracket the single call's approximation. */
          if (!(lo[i] <= approx && approx <= hi[i])) ++differ;
        } else if (!isnan(lo[i]) || !isnan(hi[i])) {
          ++differ;
        }
        if (col[i] != c || stage[i] != s || ex[i] != e) ++differ;
      }
      CHECK(differ == 0);
    }
  pccd_result_free(r);
}

static void outputs_may_be_null(void)
{
  unsigned char col[4] = {7, 7, 7, 7};
  pccd_batch_out o = out_of(col, NULL, NULL, NULL, NULL);
  g_case = "NULL outputs";
  OK(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, 4, g_t0, g_t1, NULL, NULL, &o));
  CHECK(col[0] <= 1 && col[1] <= 1 && col[2] <= 1 && col[3] <= 1);
  OK(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, 0, NULL, NULL, NULL, NULL, &o));
}

static void errors(void)
{
  unsigned char col[4] = {7, 7, 7, 7};
  pccd_batch_out o = out_of(col, NULL, NULL, NULL, NULL);
  pccd_batch_options opt;
  double bad[48];
  g_case = "errors";
  memcpy(bad, g_t0, sizeof bad);
  bad[12 * 2 + 3 * 1 + 2] = NAN; /* query 2, point 1, z */
  FAILS(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, 4, bad, g_t1, NULL, NULL, &o), PCCD_EINVAL, "t0[2][1][2]");
  CHECK(col[0] == 7 && col[3] == 7); /* nothing written */
  bad[12 * 2 + 3 * 1 + 2] = 0;
  bad[12 * 3] = INFINITY;
  FAILS(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, 4, g_t0, bad, NULL, NULL, &o), PCCD_EINVAL, "t1[3][0][0]");
  FAILS(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, 4, NULL, g_t1, NULL, NULL, &o), PCCD_EINVAL, "t0");
  FAILS(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, 4, g_t0, g_t1, NULL, NULL, NULL), PCCD_EINVAL, "out");
  FAILS(pccd_solve_linear_batch_d(PCCD_SPHERE_SPHERE, 4, g_t0, g_t1, NULL, NULL, &o), PCCD_EINVAL, "kind");
  FAILS(pccd_solve_linear_batch_d((pccd_kind)9, 4, g_t0, g_t1, NULL, NULL, &o), PCCD_EINVAL, "kind");
  OK(pccd_batch_options_init(&opt));
  opt.threads = 0;
  FAILS(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, 4, g_t0, g_t1, NULL, &opt, &o), PCCD_EINVAL, "opt.threads");
  opt.threads = 1;
  opt.struct_size = 3;
  FAILS(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, 4, g_t0, g_t1, NULL, &opt, &o), PCCD_EINVAL, "opt.struct_size");
  o.struct_size = 5;
  FAILS(pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, 4, g_t0, g_t1, NULL, NULL, &o), PCCD_EINVAL, "out.struct_size");
  FAILS(pccd_batch_options_init(NULL), PCCD_EINVAL, "opt");
  CHECK(col[0] == 7);
}

static void cases(void)
{
  known_answers();
  same_as_single();
  outputs_may_be_null();
  errors();
}

int main(void) { return run_in_every_mode(cases); }
