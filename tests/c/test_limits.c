/*
 * test_limits.c -- the limits of a call (polyccd.h, pccd_config: max_seconds, max_work,
 * cancel, max_number_bits; pccd_cancel_*): defaults, bad values, the input limit named at
 * its number before any work, work limits ending scenes, batches and index queries with
 * PCCD_ELIMIT and a message naming the limit, answers never depending on the limits,
 * the work count not depending on the thread count, and a cancellation set by another
 * thread while a long scene runs.
 *
 * Plain C99 test program (built by `make test-c`); every case runs under each IEEE
 * rounding mode (check.h). Prints failed checks and "N passed, N failed".
 */
#define _POSIX_C_SOURCE 200809L /* nanosleep, pthreads */
#include "polyccd.h"

#include <math.h>
#include <pthread.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "check.h"

/* The solves of this file, counted by API() (check.h). */
#define SOLVE(s, cfg, opt, rep) API(pccd_scene_solve((s), (cfg), (opt), (rep)))

/* n balls at x = x0 + 0.5 k (k < n) of radius n / 4 + 1, more than half the row's
 * length: every ball reaches every ball of a parallel row through its middle. */
static pccd_body *row_of_balls(size_t n, double x0)
{
  double *c = calloc(3 * n, sizeof *c), *r = calloc(n, sizeof *r);
  pccd_body *b = NULL;
  size_t k;
  for (k = 0; k < n; ++k) {
    c[3 * k] = x0 + 0.5 * (double)k;
    r[k] = (double)n / 4 + 1;
  }
  CHECK(pccd_body_new_spheres_d(&b, c, r, n) == PCCD_OK);
  free(c);
  free(r);
  return b;
}

/* A scene of two rows of n balls, the second sliding along y through the first: every
 * ball pair touches, so with all_contacts the scene has n^2 contacts to solve. */
static pccd_scene *rows_scene(size_t n)
{
  pccd_scene *s = NULL;
  pccd_body *a = row_of_balls(n, 0), *b = row_of_balls(n, 0.25);
  pccd_motion *m = NULL;
  const double from[3] = {0, (double)n, 0}, to[3] = {0, -(double)n, 0};
  CHECK(pccd_scene_new(&s) == PCCD_OK);
  CHECK(pccd_motion_new(&m) == PCCD_OK);
  CHECK(pccd_motion_set_linear_translation_d(m, from, to) == PCCD_OK);
  CHECK(pccd_scene_add(s, a, NULL, NULL) == PCCD_OK);
  CHECK(pccd_scene_add(s, b, m, NULL) == PCCD_OK);
  pccd_body_free(a);
  pccd_body_free(b);
  pccd_motion_free(m);
  return s;
}

static void defaults_and_bad_values(void)
{
  pccd_config cfg;
  pccd_scene *s = rows_scene(3);
  pccd_report *rep = NULL;
  pccd_cancel *c = NULL;
  int v = -1;

  g_case = "limit defaults and bad values";
  OK(pccd_config_init(&cfg));
  CHECK(cfg.max_seconds == 0 && cfg.max_work == 0 && cfg.cancel == NULL);
  CHECK(cfg.max_number_bits == PCCD_DEFAULT_MAX_NUMBER_BITS);
  OK(pccd_report_new(&rep));
  OK(SOLVE(s, &cfg, NULL, rep));
  OK(pccd_report_collides(rep, &v));
  CHECK(v == 1);
  /* A config of the layout before the limits is accepted and solves alike. */
  cfg.struct_size = offsetof(pccd_config, max_seconds);
  OK(SOLVE(s, &cfg, NULL, rep));
  cfg.struct_size = sizeof cfg;
  cfg.max_seconds = -1;
  FAILS(SOLVE(s, &cfg, NULL, rep), PCCD_EINVAL, "config.max_seconds: ");
  CHECK_ERR(pccd_report_collides(rep, &v), PCCD_ESTATE, "holds no answer");
  cfg.max_seconds = NAN;
  FAILS(SOLVE(s, &cfg, NULL, rep), PCCD_EINVAL, "config.max_seconds: ");
  cfg.max_seconds = INFINITY;
  FAILS(SOLVE(s, &cfg, NULL, rep), PCCD_EINVAL, "config.max_seconds: ");
  /* The cancel handle. */
  FAILS(pccd_cancel_new(NULL), PCCD_EINVAL, "out: is NULL");
  OK(pccd_cancel_new(&c));
  OK(pccd_cancel_is_set(c, &v));
  CHECK(v == 0);
  OK(pccd_cancel_set(c));
  OK(pccd_cancel_is_set(c, &v));
  CHECK(v == 1);
  FAILS(pccd_cancel_is_set(c, NULL), PCCD_EINVAL, "is_set: is NULL");
  FAILS(pccd_cancel_reset(NULL), PCCD_EINVAL, "c: is NULL");
  CHECK(pccd_cancel_set(NULL) == PCCD_EINVAL); /* signal-safe: no message is written */
  OK(pccd_config_init(&cfg));
  cfg.cancel = c; /* set: the call ends at its first step */
  FAILS(SOLVE(s, &cfg, NULL, rep), PCCD_ELIMIT, "pccd_scene_solve: config.cancel: the call was cancelled");
  CHECK_ERR(pccd_report_collides(rep, &v), PCCD_ESTATE, "holds no answer");
  OK(pccd_cancel_reset(c));
  OK(SOLVE(s, &cfg, NULL, rep));
  OK(pccd_report_collides(rep, &v));
  CHECK(v == 1);
  pccd_cancel_free(c);
  pccd_cancel_free(NULL);
  pccd_report_free(rep);
  pccd_scene_free(s);
}

/* 1e-5000 has 16,610 + 1 bits as a fraction: above the default limit of 16,384. */
static void input_limit(void)
{
  static const char *const big = "1e-5000";
  const char *const verts[12] = {"0", "0", "0", "1", "0", "0", "0", "1", "0", "0", "0", big};
  const unsigned int tri[3] = {0, 1, 2};
  const char *const coeffs[2] = {"3", big};
  const char *const one = "1";
  pccd_body *mesh = NULL, *ball = NULL;
  pccd_motion *m = NULL;
  pccd_scene *s = NULL;
  pccd_report *rep = NULL;
  pccd_config cfg;
  pccd_query *q = NULL;
  pccd_result *res = NULL;
  pccd_index *ix = NULL;
  double t0[6] = {0.1, 0, 0, 0, 0, 0}, t1[6] = {0, 0, 0, 0, 0, 0};
  int v = -1;

  g_case = "input limit max_number_bits";
  OK(pccd_body_new_mesh_s(&mesh, verts, 4, tri, 1));
  OK(pccd_body_new_spheres_s(&ball, &verts[0], &one, 1));
  OK(pccd_motion_new(&m));
  OK(pccd_motion_set_translation_s(m, 0, coeffs, 2));
  OK(pccd_scene_new(&s));
  OK(pccd_scene_add(s, ball, NULL, NULL));
  OK(pccd_scene_add(s, mesh, NULL, NULL));
  OK(pccd_report_new(&rep));
  OK(pccd_config_init(&cfg));
  FAILS(SOLVE(s, &cfg, NULL, rep), PCCD_ELIMIT,
        "pccd_scene_solve: bodies[1].vertices[3][2]: a number of 16611 bits");
  FAILS(SOLVE(s, NULL, NULL, rep), PCCD_ELIMIT, "config.max_number_bits = 16384");
  cfg.max_number_bits = 0; /* no limit */
  OK(SOLVE(s, &cfg, NULL, rep));
  OK(pccd_report_collides(rep, &v));
  cfg.max_number_bits = 16611; /* just enough */
  OK(SOLVE(s, &cfg, NULL, rep));
  pccd_scene_free(s);
  /* A motion's number: named under the body it moves. */
  OK(pccd_scene_new(&s));
  OK(pccd_scene_add(s, ball, NULL, NULL));
  OK(pccd_scene_add(s, ball, m, NULL));
  cfg.max_number_bits = 16610;
  FAILS(SOLVE(s, &cfg, NULL, rep), PCCD_ELIMIT, "bodies[1].motion.translation[0][1]: a number of 16611 bits");
  cfg.max_number_bits = 16611;
  OK(SOLVE(s, &cfg, NULL, rep));
  /* The index: the stored body, the query body, the query motion. */
  OK(pccd_index_new(&ix, mesh, NULL));
  cfg.max_number_bits = 100;
  FAILS(API(pccd_index_query(ix, ball, NULL, &cfg, NULL, rep)), PCCD_ELIMIT,
        "ix: the stored body's vertices[3][2]");
  pccd_index_free(ix);
  OK(pccd_index_new(&ix, ball, NULL));
  FAILS(API(pccd_index_query(ix, ball, m, &cfg, NULL, rep)), PCCD_ELIMIT, "motion.translation[0][1]");
  OK(API(pccd_index_query(ix, ball, NULL, &cfg, NULL, rep)));
  /* A primitive query, and doubles: 0.1 is 3602879701896397 / 2^55, 52 + 56 bits. */
  OK(pccd_query_new(&q, PCCD_VERTEX_VERTEX));
  OK(pccd_query_set_coord_s(q, 1, 2, coeffs, 2));
  OK(pccd_result_new(&res));
  FAILS(API(pccd_query_solve(q, &cfg, res)), PCCD_ELIMIT, "points[1][2][1]: a number of 16611 bits");
  cfg.max_number_bits = 107;
  FAILS(API(pccd_solve_linear_d(PCCD_VERTEX_VERTEX, t0, t1, &cfg, res)), PCCD_ELIMIT,
        "p_t0[0][0]: a number of 108 bits");
  cfg.max_number_bits = 108;
  OK(API(pccd_solve_linear_d(PCCD_VERTEX_VERTEX, t0, t1, &cfg, res)));
  pccd_query_free(q);
  pccd_result_free(res);
  pccd_index_free(ix);
  pccd_scene_free(s);
  pccd_report_free(rep);
  pccd_motion_free(m);
  pccd_body_free(mesh);
  pccd_body_free(ball);
}

/* Whether the scene solves within max_work = w on `threads` threads. */
static int solves_within(const pccd_scene *s, unsigned long long w, unsigned threads)
{
  pccd_config cfg;
  pccd_scene_options opt;
  pccd_report *rep = NULL;
  int rc;
  CHECK(pccd_config_init(&cfg) == PCCD_OK);
  CHECK(pccd_scene_options_init(&opt) == PCCD_OK);
  cfg.max_work = w;
  opt.threads = threads;
  opt.all_contacts = 1;
  CHECK(pccd_report_new(&rep) == PCCD_OK);
  rc = SOLVE(s, &cfg, &opt, rep);
  CHECK(rc == PCCD_OK || (rc == PCCD_ELIMIT && strstr(pccd_last_error(), "config.max_work: the limit of") &&
                          strstr(pccd_last_error(), "work steps was reached")));
  pccd_report_free(rep);
  return rc == PCCD_OK;
}

/* The work a scene needs is a function of the scene: the smallest max_work that lets
 * it finish is the same on 1, 2 and 3 threads, and the answer within it is the
 * answer without limits. */
static void work_limit_is_deterministic(void)
{
  pccd_scene *s = rows_scene(6);
  unsigned long long lo = 0, hi = 1;
  unsigned threads;
  g_case = "max_work: the same count on every thread count";
  while (!solves_within(s, hi, 1)) hi *= 2;
  while (hi - lo > 1) { /* lo fails, hi solves */
    const unsigned long long mid = lo + (hi - lo) / 2;
    if (solves_within(s, mid, 1)) hi = mid; else lo = mid;
  }
  CHECK(hi > 10); /* a scene of 36 ball pairs takes more than a few steps */
  for (threads = 2; threads <= 3; ++threads) {
    CHECK(solves_within(s, hi, threads));
    if (lo > 0) CHECK(!solves_within(s, lo, threads));
  }
  pccd_scene_free(s);
}

struct canceller {
  pccd_cancel *c;
  int delay_ms;
};

static void *cancel_later(void *arg)
{
  struct canceller *k = arg;
  struct timespec d;
  d.tv_sec = k->delay_ms / 1000;
  d.tv_nsec = (long)(k->delay_ms % 1000) * 1000000L;
  nanosleep(&d, NULL);
  pccd_cancel_set(k->c);
  return NULL;
}

/* A scene of 490,000 touching ball pairs with all contacts (seconds of work) is
 * cancelled by another thread after 30 ms, and stopped by max_seconds = 0.05; both end
 * with PCCD_ELIMIT and the report holds no answer. */
static void cancel_and_deadline(void)
{
  pccd_scene *s = rows_scene(700);
  pccd_config cfg;
  pccd_scene_options opt;
  pccd_report *rep = NULL;
  struct canceller k;
  pthread_t th;
  int v;

  g_case = "cancel from another thread, max_seconds";
  OK(pccd_report_new(&rep));
  OK(pccd_config_init(&cfg));
  OK(pccd_scene_options_init(&opt));
  opt.all_contacts = 1;
  opt.threads = 2;
  OK(pccd_cancel_new(&k.c));
  k.delay_ms = 30;
  cfg.cancel = k.c;
  CHECK(pthread_create(&th, NULL, cancel_later, &k) == 0);
  FAILS(SOLVE(s, &cfg, &opt, rep), PCCD_ELIMIT, "config.cancel: the call was cancelled (after ");
  CHECK(pthread_join(th, NULL) == 0);
  CHECK_ERR(pccd_report_collides(rep, &v), PCCD_ESTATE, "holds no answer");
  cfg.cancel = NULL;
  cfg.max_seconds = 0.05;
  FAILS(SOLVE(s, &cfg, &opt, rep), PCCD_ELIMIT, "config.max_seconds: the time limit of 0.05 s was reached");
  FAILS(SOLVE(s, &cfg, &opt, rep), PCCD_ELIMIT, "work steps and ");
  pccd_cancel_free(k.c);
  pccd_report_free(rep);
  pccd_scene_free(s);
}

/* config.min_distance: a primitive query's first time within distance delta (a point
 * from x = 3 to x = 0 against the origin, delta = 1: |3 - 3t| = 1 at t = 2/3), its bad
 * values, and the scenes that refuse it. */
static void min_distance(void)
{
  pccd_config cfg;
  pccd_result *res = NULL;
  pccd_scene *s = rows_scene(2);
  pccd_report *rep = NULL;
  const double p0[6] = {0, 0, 0, 3, 0, 0}, p1[6] = {0, 0, 0, 0, 0, 0};
  char buf[32];

  g_case = "min_distance";
  OK(pccd_result_new(&res));
  OK(pccd_report_new(&rep));
  OK(pccd_config_init(&cfg));
  CHECK(cfg.min_distance == NULL);
  cfg.min_distance = "1";
  OK(API(pccd_solve_linear_d(PCCD_VERTEX_VERTEX, p0, p1, &cfg, res)));
  OK(pccd_result_time(res, 2, buf, sizeof buf, NULL));
  CHECK(strcmp(buf, "2/3") == 0);
  cfg.min_distance = "-1";
  FAILS(API(pccd_solve_linear_d(PCCD_VERTEX_VERTEX, p0, p1, &cfg, res)), PCCD_EINVAL,
        "config.min_distance: \"-1\" must be >= 0");
  cfg.min_distance = "1";
  OK(SOLVE(s, &cfg, NULL, rep)); /* auto: bvh */
  {
    pccd_scene_options opt;
    OK(pccd_scene_options_init(&opt));
    opt.broad_phase = PCCD_BROAD_RANGE; /* the one phase without delta */
    FAILS(SOLVE(s, &cfg, &opt, rep), PCCD_EINVAL,
          "opt.broad_phase: 2 (PCCD_BROAD_RANGE) does not take config.min_distance > 0");
    opt.broad_phase = PCCD_BROAD_BRUTE;
    OK(SOLVE(s, &cfg, &opt, rep));
    opt.broad_phase = PCCD_BROAD_BVH;
    OK(SOLVE(s, &cfg, &opt, rep));
    opt.broad_phase = PCCD_BROAD_BOXES;
    OK(SOLVE(s, &cfg, &opt, rep));
  }
  cfg.min_distance = "0";
  OK(SOLVE(s, &cfg, NULL, rep));
  pccd_result_free(res);
  pccd_report_free(rep);
  pccd_scene_free(s);
}

/* The calls that took no config before issue 23 (pccd_index_new, pccd_motion_position_s,
 * pccd_motion_validate, pccd_motion_compose) have _cfg twins: NULL is no limit, a set cancel
 * ends them at their first work step with PCCD_ELIMIT under their own name (*out NULL), the
 * input limit names the number, and within the limits they answer as the plain calls. */
static void cfg_twins(void)
{
  const char *const big[2] = {"1", "1e-5000"}; /* 16,611 bits */
  const char *const p[3] = {"1", "2", "3"};
  pccd_config cfg;
  pccd_cancel *c = NULL;
  pccd_body *ball = row_of_balls(2, 0);
  const char *const one_plus_t[2] = {"1", "1"};
  pccd_motion *m = NULL, *mr = NULL, *out = NULL;
  pccd_index *ix = NULL;
  static char a[20000], b[20000]; /* the position of 1e-5000: 10,008 bytes */

  g_case = "the _cfg twins of index_new, position, validate, compose";
  OK(pccd_motion_new(&m));
  OK(pccd_motion_set_translation_s(m, 0, big, 2));
  /* w = x = 1 + t: a common factor, so validation runs a remainder sequence (steps) */
  OK(pccd_motion_new(&mr));
  OK(pccd_motion_set_rotation_s(mr, 0, one_plus_t, 2));
  OK(pccd_motion_set_rotation_s(mr, 1, one_plus_t, 2));
  OK(pccd_config_init(&cfg));
  OK(pccd_cancel_new(&c));
  OK(pccd_cancel_set(c));
  cfg.cancel = c;
  FAILS(pccd_index_new_cfg(&ix, ball, mr, &cfg), PCCD_ELIMIT, "pccd_index_new_cfg: config.cancel: ");
  CHECK(ix == NULL);
  FAILS(pccd_motion_position_cfg_s(m, p, "1/2", &cfg, a, sizeof a, NULL), PCCD_ELIMIT,
        "pccd_motion_position_cfg_s: m.translation[0][1]: a number of 16611 bits");
  cfg.max_number_bits = 0;
  FAILS(pccd_motion_position_cfg_s(m, p, "1/2", &cfg, a, sizeof a, NULL), PCCD_ELIMIT,
        "pccd_motion_position_cfg_s: config.cancel: ");
  FAILS(pccd_motion_validate_cfg(mr, &cfg), PCCD_ELIMIT, "pccd_motion_validate_cfg: config.cancel: ");
  FAILS(pccd_motion_compose_cfg(&out, m, m, &cfg), PCCD_ELIMIT, "pccd_motion_compose_cfg: config.cancel: ");
  CHECK(out == NULL);
  cfg.max_number_bits = 100;
  OK(pccd_cancel_reset(c));
  FAILS(pccd_index_new_cfg(&ix, ball, m, &cfg), PCCD_ELIMIT,
        "pccd_index_new_cfg: motion.translation[0][1]: a number of 16611 bits");
  FAILS(pccd_motion_compose_cfg(&out, m, m, &cfg), PCCD_ELIMIT, "outer.translation[0][1]: a number of");
  cfg.struct_size = 3;
  FAILS(pccd_motion_validate_cfg(m, &cfg), PCCD_EINVAL, "pccd_motion_validate_cfg: config");
  FAILS(pccd_motion_validate_cfg(NULL, NULL), PCCD_EINVAL, "pccd_motion_validate_cfg: m: is NULL");
  /* Within the limits (or none): the plain calls' answers. */
  OK(pccd_config_init(&cfg));
  cfg.max_number_bits = 0;
  cfg.max_work = 1000000;
  OK(pccd_motion_position_cfg_s(m, p, "1/2", &cfg, a, sizeof a, NULL));
  OK(pccd_motion_position_s(m, p, "1/2", b, sizeof b, NULL));
  CHECK(strcmp(a, b) == 0);
  OK(pccd_motion_position_cfg_s(m, p, "1/2", NULL, a, sizeof a, NULL));
  CHECK(strcmp(a, b) == 0);
  OK(pccd_motion_validate_cfg(m, NULL));
  OK(pccd_motion_validate_cfg(mr, &cfg));
  pccd_motion_free(mr);
  OK(pccd_motion_compose_cfg(&out, m, m, &cfg));
  pccd_motion_free(out);
  OK(pccd_index_new_cfg(&ix, ball, m, &cfg));
  pccd_index_free(ix);
  OK(pccd_index_new_cfg(&ix, ball, NULL, NULL));
  pccd_index_free(ix);
  pccd_cancel_free(c);
  pccd_motion_free(m);
  pccd_body_free(ball);
}

static void cases(void)
{
  defaults_and_bad_values();
  input_limit();
  work_limit_is_deterministic();
  cancel_and_deadline();
  min_distance();
  cfg_twins();
}

int main(void) { return run_in_every_mode(cases); }
