/*
 * test_threads.c -- many threads solving at once on shared handles give the answers of
 * a serial run, byte for byte (issue 15, item 4). `make tsan` runs it under
 * ThreadSanitizer (tests/c/run_tsan.sh); `make check` runs it as it is.
 *
 * Two identical worlds are built: every handle of a world (primitive queries, bodies,
 * motions, scenes, an index, results and reports) is created once. World 1 is solved
 * serially first: the expected texts, and the results and reports that the reading jobs
 * share. Then THREADS threads run every job ROUNDS times, each in its own order, on
 * world 2, whose bodies were never solved before (so the structures a body builds on
 * first use, e.g. the range phase's trees, are built while the threads race for them),
 * and compare each job's text with world 1's. Shared
 * read-only: queries (pccd_query_solve), bodies and motions (pccd_scene_add from many
 * threads, pccd_index_query, pccd_motion_position_s, pccd_motion_validate), scenes
 * (pccd_scene_solve), the index (pccd_index_query, pccd_index_query_many), results and
 * reports (every getter). Written by one thread only: each job's own result or report.
 * Scene solves and batches inside the threads use 1 or 2 threads of their own. Each
 * thread also checks that pccd_last_error() is its own.
 */
#include <pthread.h>

#include "check.h"
#include "scene_fixtures.h"

#define THREADS 6
#define ROUNDS 1
#define NQ 12     /* primitive queries */
#define NL 16     /* linear double queries (single calls, and one batch of all) */
#define NB 4      /* bodies */
#define NS 4      /* scenes */
#define TEXT 8192 /* room for one job's text */

typedef struct world {
  pccd_query *q[NQ];
  double l0[NL][12], l1[NL][12];
  pccd_body *body[NB];
  pccd_motion *motion[NB];
  pccd_scene *scene[NS];
  pccd_scene_options sopt[NS];
  pccd_index *ix;
  pccd_result *res[NQ]; /* solved once, then only read */
  pccd_report *rep[NS];
} world;

static world w1, w2;
static pccd_config cfg;
static unsigned lcg = 12345u;

static int next(int n) /* a deterministic pseudo-random integer in [0, n) */
{
  lcg = lcg * 1103515245u + 12345u;
  return (int)((lcg >> 16) % (unsigned)n);
}

static void append(char *out, const char *s)
{
  size_t n = strlen(out);
  snprintf(out + n, TEXT - n, "%s", s);
}

static void result_text(const pccd_result *res, char *out)
{
  int c = -1, stage = -1, exact = -1, kind = -1;
  size_t nf = 0, pts[4], i;
  char lo[512] = "-", hi[512] = "-", line[1200];
  pccd_result_collides(res, &c);
  pccd_result_stage(res, &stage);
  pccd_result_time_is_exact(res, &exact);
  pccd_result_time(res, 0, lo, sizeof lo, NULL);
  pccd_result_time(res, 1, hi, sizeof hi, NULL);
  pccd_result_feature_count(res, &nf);
  snprintf(line, sizeof line, "%d %d %d [%s, %s] %zu:", c, stage, exact, lo, hi, nf);
  append(out, line);
  for (i = 0; i < nf; ++i) {
    pccd_result_feature(res, i, &kind, pts);
    snprintf(line, sizeof line, " %d(%zu %zu %zu %zu)", kind, pts[0], pts[1], pts[2], pts[3]);
    append(out, line);
  }
}

static void time_text(const pccd_report *rep, size_t pair, size_t contact, char *out)
{
  char lo[512] = "-", hi[512] = "-", line[1100];
  int exact = -1;
  pccd_report_time(rep, pair, contact, 0, lo, sizeof lo, NULL);
  pccd_report_time(rep, pair, contact, 1, hi, sizeof hi, NULL);
  pccd_report_time_info(rep, pair, contact, &exact, NULL);
  snprintf(line, sizeof line, " [%s, %s]%d", lo, hi, exact);
  append(out, line);
}

static void report_text(const pccd_report *rep, char *out)
{
  int c = -1, first = -1, fi, fj;
  size_t np = 0, p, nc, k, bi, bj, ii, ij;
  char line[160];
  pccd_report_collides(rep, &c);
  pccd_report_pair_count(rep, &np);
  snprintf(line, sizeof line, "%d %zu", c, np);
  append(out, line);
  time_text(rep, PCCD_WHOLE, PCCD_WHOLE, out);
  for (p = 0; p < np; ++p) {
    nc = 0;
    pccd_report_pair(rep, p, &bi, &bj, &first);
    pccd_report_contact_count(rep, p, &nc);
    snprintf(line, sizeof line, "\n(%zu %zu %d)", bi, bj, first);
    append(out, line);
    time_text(rep, p, PCCD_WHOLE, out);
    for (k = 0; k < nc; ++k) {
      pccd_report_contact(rep, p, k, &fi, &ii, &fj, &ij);
      snprintf(line, sizeof line, " %d:%zu-%d:%zu", fi, ii, fj, ij);
      append(out, line);
      time_text(rep, p, k, out);
    }
  }
}

/* ---------------------------------------------------------------- the worlds */

/* NQ primitive queries of small rational polynomials, half of them touching (the
 * first ones of a seeded sequence that fill each half), and NL linear ones. */
static void make_queries(world *w)
{
  static const pccd_kind kinds[4] = {PCCD_VERTEX_FACE, PCCD_EDGE_EDGE, PCCD_VERTEX_EDGE,
                                     PCCD_SPHERE_SPHERE};
  char text[4][16];
  const char *c[4] = {text[0], text[1], text[2], text[3]};
  size_t i = 0, p, a, k, np, quota[2] = {NQ / 2, NQ / 2};
  pccd_result *r = NULL;
  pccd_config decide;
  pccd_config_init(&decide);
  decide.want_time = 0;
  pccd_result_new(&r);
  lcg = 12345u; /* both worlds get the same queries */
  while (i < NQ) {
    pccd_kind kind = kinds[i % 4];
    int hit = 0;
    pccd_kind_points(kind, &np);
    pccd_query_new(&w->q[i], kind);
    for (p = 0; p < np; ++p)
      for (a = 0; a < 3; ++a) {
        size_t n = 1 + (size_t)next(3); /* degree 0 to 2 */
        for (k = 0; k < n; ++k) snprintf(text[k], sizeof text[k], "%d/2", next(5) - 2);
        pccd_query_set_coord_s(w->q[i], p, a, c, n);
      }
    if (kind == PCCD_SPHERE_SPHERE) {
      pccd_query_set_radius_s(w->q[i], 0, "1/2");
      pccd_query_set_radius_s(w->q[i], 1, "3/4");
    }
    pccd_query_solve(w->q[i], &decide, r);
    pccd_result_collides(r, &hit);
    if (quota[hit] > 0) {
      quota[hit]--;
      i++;
    } else {
      pccd_query_free(w->q[i]);
    }
  }
  pccd_result_free(r);
  for (i = 0; i < NL; ++i)
    for (k = 0; k < 12; ++k) {
      w->l0[i][k] = (next(17) - 8) / 8.0;
      w->l1[i][k] = (next(17) - 8) / 8.0;
    }
}

static pccd_motion *motion_of(int which)
{
  static const char *const axis[3] = {"0", "0", "1"}, *const center[3] = {"1/2", "1/2", "0"};
  static const char *const p0[3] = {"3", "1/2", "1/2"}, *const p1[3] = {"-1", "1/2", "1/2"};
  static const char *const up[3] = {"1/4", "1/4", "3/2"}, *const down[3] = {"1/4", "1/4", "-1/2"};
  static const char *const tilt[2] = {"1", "1/3"}, *const zero[1] = {"0"};
  pccd_motion *m = NULL;
  pccd_motion_new(&m);
  switch (which) {
  case 0: break; /* stationary */
  case 1: pccd_motion_set_linear_translation_s(m, p0, p1); break;
  case 2: /* a screw about the z axis through (1/2, 1/2), dropping by 1 */
    pccd_motion_set_screw_s(m, axis, center, "0", "1", "-1");
    break;
  default: /* falling with a polynomial rotation (degree 1 quaternion) */
    pccd_motion_set_linear_translation_s(m, up, down);
    pccd_motion_set_rotation_s(m, 1, tilt, 2);
    pccd_motion_set_rotation_s(m, 2, zero, 1);
  }
  return m;
}

static void make_world(world *w)
{
  static const double centers[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  static const double radii[3] = {0.5, 0.25, 0.375};
  static const double tet_v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  static const unsigned tet_t[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  static const int phases[NS] = {PCCD_BROAD_BOXES, PCCD_BROAD_RANGE, PCCD_BROAD_BRUTE,
                                 PCCD_BROAD_AUTO};
  size_t s, k;
  make_queries(w);
  pccd_body_new_mesh_d(&w->body[0], kCubeV, 8, kCubeT, 12);
  pccd_body_new_spheres_d(&w->body[1], centers, radii, 3);
  pccd_body_new_mesh_d(&w->body[2], tet_v, 4, tet_t, 4);
  pccd_body_new_mesh_d(&w->body[3], kCubeV, 8, kCubeT, 12);
  for (k = 0; k < NB; ++k) w->motion[k] = motion_of((int)k);
  /* scene s: body 0 and bodies s+1 .. (cube + balls, cube + tet, ...), all four in 3 */
  for (s = 0; s < NS; ++s) {
    pccd_scene_new(&w->scene[s]);
    pccd_scene_add(w->scene[s], w->body[0], w->motion[0], NULL);
    for (k = 1; k < NB; ++k)
      if (s == 3 || k == s + 1) pccd_scene_add(w->scene[s], w->body[k], w->motion[k], NULL);
    pccd_scene_options_init(&w->sopt[s]);
    w->sopt[s].broad_phase = phases[s];
    w->sopt[s].threads = 1 + (unsigned)(s % 2);
    w->sopt[s].all_contacts = (int)(s / 2);
  }
  pccd_index_new(&w->ix, w->body[0], w->motion[0]);
  for (k = 0; k < NQ; ++k) pccd_result_new(&w->res[k]);
  for (s = 0; s < NS; ++s) pccd_report_new(&w->rep[s]);
}

static void solve_shared(world *w) /* the results and reports the reading jobs share */
{
  size_t k;
  for (k = 0; k < NQ; ++k) pccd_query_solve(w->q[k], &cfg, w->res[k]);
  for (k = 0; k < NS; ++k) pccd_scene_solve(w->scene[k], &cfg, &w->sopt[k], w->rep[k]);
}

static void free_world(world *w)
{
  size_t k;
  for (k = 0; k < NQ; ++k) pccd_query_free(w->q[k]), pccd_result_free(w->res[k]);
  for (k = 0; k < NB; ++k) pccd_body_free(w->body[k]), pccd_motion_free(w->motion[k]);
  for (k = 0; k < NS; ++k) pccd_scene_free(w->scene[k]), pccd_report_free(w->rep[k]);
  pccd_index_free(w->ix);
}

/* ---------------------------------------------------------------- the jobs */

enum { J_QUERY = 0, J_LINEAR = J_QUERY + NQ, J_BATCH = J_LINEAR + NL, J_SCENE, J_BUILD = J_SCENE + NS,
       J_INDEX = J_BUILD + NS, J_MANY = J_INDEX + NB - 1, J_READ, J_POS = J_READ + NQ + NS,
       NJOBS = J_POS + NB };

/* Job j on world w, its text into out. */
static void run_job(world *w, int j, char *out)
{
  out[0] = 0;
  if (j < J_LINEAR) { /* a shared query, solved into this job's result */
    pccd_result *r = NULL;
    pccd_result_new(&r);
    if (pccd_query_solve(w->q[j], &cfg, r) == PCCD_OK) result_text(r, out);
    pccd_result_free(r);
  } else if (j < J_BATCH) {
    pccd_result *r = NULL;
    pccd_result_new(&r);
    int k = j - J_LINEAR;
    if (pccd_solve_linear_d(k % 2 ? PCCD_EDGE_EDGE : PCCD_VERTEX_FACE, w->l0[k], w->l1[k], &cfg,
                            r) == PCCD_OK)
      result_text(r, out);
    pccd_result_free(r);
  } else if (j == J_BATCH) { /* all vertex-face linear queries, 2 threads */
    double t0[NL * 12], t1[NL * 12], lo[NL], hi[NL];
    unsigned char col[NL], ex[NL];
    int stage[NL];
    pccd_batch_options opt;
    pccd_batch_out bo = {sizeof bo, col, stage, lo, hi, ex};
    char line[128];
    memcpy(t0, w->l0, sizeof t0);
    memcpy(t1, w->l1, sizeof t1);
    pccd_batch_options_init(&opt);
    opt.threads = 2;
    if (pccd_solve_linear_batch_d(PCCD_VERTEX_FACE, NL, t0, t1, &cfg, &opt, &bo) == PCCD_OK)
      for (int k = 0; k < NL; ++k) {
        snprintf(line, sizeof line, "%d %d %a %a %d;", col[k], stage[k], lo[k], hi[k], ex[k]);
        append(out, line);
      }
  } else if (j < J_BUILD) { /* a shared scene, solved into this job's report */
    pccd_report *rep = NULL;
    pccd_report_new(&rep);
    int s = j - J_SCENE;
    if (pccd_scene_solve(w->scene[s], &cfg, &w->sopt[s], rep) == PCCD_OK) report_text(rep, out);
    pccd_report_free(rep);
  } else if (j < J_INDEX) { /* a scene built here from the shared bodies and motions */
    pccd_scene *sc = NULL;
    pccd_report *rep = NULL;
    int s = j - J_BUILD;
    pccd_scene_new(&sc);
    pccd_report_new(&rep);
    for (int k = NB - 1; k >= 0; --k)
      if (k == 0 || k == s || s == 0) pccd_scene_add(sc, w->body[k], w->motion[k], NULL);
    if (pccd_scene_solve(sc, &cfg, &w->sopt[s], rep) == PCCD_OK) report_text(rep, out);
    pccd_report_free(rep);
    pccd_scene_free(sc);
  } else if (j < J_MANY) { /* the shared index, one query */
    pccd_report *rep = NULL;
    int k = j - J_INDEX + 1;
    pccd_report_new(&rep);
    if (pccd_index_query(w->ix, w->body[k], w->motion[k], &cfg, NULL, rep) == PCCD_OK)
      report_text(rep, out);
    pccd_report_free(rep);
  } else if (j == J_MANY) { /* the shared index, every query at once on 2 threads */
    const pccd_body *b[NB - 1];
    const pccd_motion *m[NB - 1];
    pccd_report *reps[NB - 1];
    pccd_scene_options opt;
    pccd_scene_options_init(&opt);
    opt.threads = 2;
    for (int k = 0; k < NB - 1; ++k) {
      b[k] = w->body[k + 1];
      m[k] = w->motion[k + 1];
      pccd_report_new(&reps[k]);
    }
    if (pccd_index_query_many(w->ix, b, m, NB - 1, &cfg, &opt, reps) == PCCD_OK)
      for (int k = 0; k < NB - 1; ++k) report_text(reps[k], out), append(out, "|");
    for (int k = 0; k < NB - 1; ++k) pccd_report_free(reps[k]);
  } else if (j < J_READ + NQ) { /* a shared solved result (of world 1), read */
    result_text(w1.res[j - J_READ], out);
  } else if (j < J_POS) { /* a shared solved report (of world 1), read */
    report_text(w1.rep[j - J_READ - NQ], out);
  } else { /* a shared motion: validity and positions */
    static const char *const p[3] = {"1", "-1/2", "2"};
    static const char *const ts[3] = {"0", "1/3", "1"};
    char buf[512], line[40];
    const pccd_motion *m = w->motion[j - J_POS];
    snprintf(line, sizeof line, "%d:", pccd_motion_validate(m));
    append(out, line);
    for (int k = 0; k < 3; ++k)
      if (pccd_motion_position_s(m, p, ts[k], buf, sizeof buf, NULL) == PCCD_OK)
        append(out, buf), append(out, ";");
  }
}

static char expected[NJOBS][TEXT];

typedef struct worker {
  int id, mismatches, errors, first_bad;
} worker;

static void *work(void *arg)
{
  worker *me = (worker *)arg;
  char got[TEXT], bad[32], want[64];
  pccd_query *q = NULL;
  const char *value[1] = {bad};
  snprintf(bad, sizeof bad, "t%d", me->id);
  snprintf(want, sizeof want, "\"t%d\" is not a number", me->id);
  pccd_query_new(&q, PCCD_VERTEX_VERTEX);
  for (int round = 0; round < ROUNDS; ++round)
    for (int i = 0; i < NJOBS; ++i) {
      int j = (me->id * 7 + round * 3 + i) % NJOBS;
      run_job(&w2, j, got);
      if (strcmp(got, expected[j]) != 0) {
        if (me->mismatches++ == 0) me->first_bad = j;
      }
      /* this thread's own error message, whatever the others did meanwhile */
      if (pccd_query_set_coord_s(q, 0, 0, value, 1) != PCCD_EINVAL ||
          strstr(pccd_last_error(), want) == NULL)
        me->errors++;
    }
  pccd_query_free(q);
  return NULL;
}

int main(void)
{
  pthread_t th[THREADS];
  worker wk[THREADS];
  int t, j, nonempty = 0, collide = 0;
  pccd_config_init(&cfg);
  cfg.time_tolerance = "1e-9";
  make_world(&w1);
  make_world(&w2);
  solve_shared(&w1);
  for (j = 0; j < NJOBS; ++j) {
    run_job(&w1, j, expected[j]);
    nonempty += expected[j][0] != 0;
    collide += expected[j][0] == '1';
  }
  g_case = "serial answers";
  CHECK(nonempty == NJOBS); /* every job solved */
  CHECK(collide >= NJOBS / 4); /* and contacts are common (the texts start with collides) */
  for (t = 0; t < THREADS; ++t) {
    wk[t].id = t;
    wk[t].mismatches = wk[t].errors = 0;
    wk[t].first_bad = -1;
    CHECK(pthread_create(&th[t], NULL, work, &wk[t]) == 0);
  }
  for (t = 0; t < THREADS; ++t) CHECK(pthread_join(th[t], NULL) == 0);
  g_case = "parallel answers equal the serial ones";
  for (t = 0; t < THREADS; ++t) {
    if (!CHECK(wk[t].mismatches == 0))
      printf("    thread %d: %d mismatches, first job %d:\n    expected %s\n", t,
             wk[t].mismatches, wk[t].first_bad, expected[wk[t].first_bad]);
    CHECK(wk[t].errors == 0);
  }
  printf("%d threads x %d rounds x %d jobs\n", THREADS, ROUNDS, NJOBS);
  free_world(&w1);
  free_world(&w2);
  printf("%d passed, %d failed\n", g_pass, g_fail);
  return g_fail == 0 ? 0 : 1;
}
