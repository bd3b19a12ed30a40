/*
 * fuzz_scene.c -- libFuzzer harness of scenes and the on-line index: 2 to 4 small
 * bodies (meshes or balls, numbers from raw bytes) on motions (stationary, linear, axis
 * rotations, screws, polynomial, Bezier with a composed pose), pccd_scene_solve with
 * every option, every pccd_report_* getter, pccd_index_new / pccd_index_query /
 * pccd_index_query_many, in any of the four rounding modes.
 *
 * Input (fuzz_input.h for u8, number, ...):
 *   u8 head   rounding mode = head % 4; bit 2: all_contacts; bits 3-4: broad phase
 *             (boxes, brute, range, auto); bit 5: 2 threads; bit 6: cross-check against
 *             brute force on 1 thread; bit 7: cross-check the index against scenes
 *   u8 bad    >= 0xF8: one option made invalid (bad % 8 picks which)
 *   u8 cfg    bit 0: a time_tolerance number follows; bit 1: want_time 0; bit 2:
 *             want_exact 0
 *   u8 nb     2 + nb % 3 bodies, each:
 *     u8 type   type % 4: mesh_s, mesh_d, spheres_s, spheres_d; then for a mesh u8 nv,
 *               u8 nt (each % (FZ_MAX_ELEMENTS + 1)), nv * 3 numbers, nt * 3 u8 indices
 *               (taken % nv); for balls u8 n (% (FZ_MAX_BALLS + 1)), n * 3 + n numbers
 *     u8 motion % 7: 0 none (NULL), 1 the identity handle, 2 linear translation (6
 *               numbers), 3 axis rotation (8), 4 screw (9), 5 polynomial (3 translation
 *               axes of u8 % 6 + 1 numbers, then 4 rotation components of u8 % 3 + 1),
 *               6 Bezier (12) then a body-side pose (4 + 3)
 *   A body or motion the library rejects is left out (the call's checks still apply).
 *
 * Checks beyond fuzz_input.h's: the report is consistent (collides iff a pair is in
 * contact, pairs ascending with i < j < bodies, at least one first pair, every contact
 * a feature of the right kind with an index in range, every time readable); an error
 * leaves the report unsolved; the chosen broad phase and thread count give the same
 * report, byte for byte, as brute force on one thread (bit 6; in decide mode, want_time
 * 0 without all_contacts, the same answer and the same body pair: polyccd.h's
 * pccd_config.want_time reports the first body pair found in contact with a witness,
 * some of its touching features and an enclosure of one of its contact times, which
 * the phases find in their own order); the index gives the two-body scene's report,
 * and query_many gives query's (bit 7).
 *
 * Cost limits (README.md): FZ_MAX_ELEMENTS triangles and vertices, FZ_MAX_BALLS balls,
 * translations of degree <= 5 and rotations of degree <= 2 (the corpus's largest), and
 * the number limits of fuzz_input.h. Every solve also runs under config.max_work =
 * FZ_MAX_WORK (deterministic): within those shapes an input found by the campaign
 * (crashes/fuzz_scene-oom-...) took 8.4 s and 29 MB with the normal library, but
 * 665 s and 7.4 GB under ASan (its allocator keeps what GMP's growing numbers free),
 * an out-of-memory report at libFuzzer's 3 GB. PCCD_ELIMIT is then an answer: a
 * cross-check is made only when both calls answered.
 */
#include "fuzz_input.h"

#define FZ_MAX_ELEMENTS 12
#define FZ_MAX_BALLS 6
#define FZ_MAX_BODIES 4
#ifndef FZ_MAX_WORK
#define FZ_MAX_WORK 20000
#endif

typedef struct body_info {
  pccd_body *b;
  pccd_motion *m; /* NULL: stationary */
  int mesh;
  size_t nv, ne, nt;
} body_info;

/* Decide mode's contract in two report texts (report_text): the answer ("C " or "- ")
 * and the body pairs reported ("\npair i j" lines), not the witness's features and times. */
static int same_decision(const char *a, const char *b)
{
  if (a[0] != b[0]) return 0;
  for (;;) {
    a = strstr(a, "\npair ");
    b = strstr(b, "\npair ");
    if (!a || !b) return a == b;
    size_t ia = 0, ja = 0, ib = 0, jb = 0;
    if (sscanf(a, "\npair %zu %zu", &ia, &ja) != 2 || sscanf(b, "\npair %zu %zu", &ib, &jb) != 2)
      return 0;
    if (ia != ib || ja != jb) return 0;
    ++a, ++b;
  }
}

/* A growable text: the whole report, to compare two reports byte for byte. */
typedef struct text {
  char *s;
  size_t len, cap;
} text;

static void put(text *t, const char *s)
{
  size_t n = strlen(s);
  if (t->len + n + 1 > t->cap) {
    t->cap = 2 * (t->len + n + 1);
    t->s = (char *)realloc(t->s, t->cap);
    FZ_ASSERT(t->s != NULL);
  }
  memcpy(t->s + t->len, s, n + 1);
  t->len += n;
}

typedef struct time_ctx {
  const pccd_report *rep;
  size_t pair, contact;
  int which;
} time_ctx;

static int get_time(const void *ctx, char *buf, size_t cap, size_t *needed)
{
  const time_ctx *c = (const time_ctx *)ctx;
  return pccd_report_time(c->rep, c->pair, c->contact, c->which, buf, cap, needed);
}

/* Appends the time of (pair, contact) to t and checks its getters. */
static void put_time(text *t, const pccd_report *rep, size_t pair, size_t contact, int any)
{
  int exact = -1, rc;
  double approx = -1;
  rc = FZ_RC(pccd_report_time_info, rep, pair, contact, &exact, &approx);
  FZ_ASSERT(any ? rc == PCCD_OK : rc == PCCD_OK || rc == PCCD_ESTATE);
  FZ_ASSERT(FZ_RC(pccd_report_time_info, rep, pair, contact, NULL, NULL) == rc);
  for (int which = 0; which < 3; ++which) {
    time_ctx c = {rep, pair, contact, which};
    char *s = fz_read_text(get_time, &c, "pccd_report_time", &rc);
    if (which < 2) FZ_ASSERT(any ? rc == PCCD_OK : rc == PCCD_ESTATE);
    else FZ_ASSERT(exact == 1 ? rc == PCCD_OK : rc == PCCD_ESTATE);
    put(t, s ? s : "-");
    put(t, which < 2 ? "," : ";");
    free(s);
  }
  if (any) FZ_ASSERT(approx >= 0 && approx <= 1);
  time_ctx bad = {rep, pair, contact, 3};
  FZ_ASSERT(fz_read_text(get_time, &bad, "pccd_report_time", &rc) == NULL && rc == PCCD_EINVAL);
}

/* The whole report as text, checking every getter on the way. */
static char *report_text(const pccd_report *rep, const body_info *bodies, size_t nb)
{
  text t = {NULL, 0, 0};
  char line[160];
  int collides = -1, any_first = 0;
  size_t np = 0;
  pccd_scene_stats stats;
  FZ_ASSERT(FZ_RC(pccd_report_collides, rep, &collides) == PCCD_OK);
  FZ_ASSERT(FZ_RC(pccd_report_pair_count, rep, &np) == PCCD_OK);
  FZ_ASSERT(collides == (np > 0));
  FZ_ASSERT(FZ_RC(pccd_report_stats, rep, &stats) == PCCD_OK);
  put(&t, collides ? "C " : "- ");
  put_time(&t, rep, PCCD_WHOLE, PCCD_WHOLE, collides);
  size_t pi = 0, pj = 0;
  for (size_t p = 0; p < np; ++p) {
    size_t i = 99, j = 99, nc = 0;
    int first = -1;
    FZ_ASSERT(FZ_RC(pccd_report_pair, rep, p, &i, &j, &first) == PCCD_OK);
    FZ_ASSERT(i < j && j < nb && (first == 0 || first == 1));
    FZ_ASSERT(p == 0 || i > pi || (i == pi && j > pj));
    pi = i, pj = j;
    any_first |= first;
    snprintf(line, sizeof line, "\npair %zu %zu %d ", i, j, first);
    put(&t, line);
    put_time(&t, rep, p, PCCD_WHOLE, 1);
    FZ_ASSERT(FZ_RC(pccd_report_contact_count, rep, p, &nc) == PCCD_OK && nc >= 1);
    for (size_t c = 0; c < nc; ++c) {
      int fi = -1, fj = -1;
      size_t ii = 0, ij = 0;
      FZ_ASSERT(FZ_RC(pccd_report_contact, rep, p, c, &fi, &ii, &fj, &ij) == PCCD_OK);
      const body_info *bs[2] = {&bodies[i], &bodies[j]};
      int fs[2] = {fi, fj};
      size_t is[2] = {ii, ij};
      for (int k = 0; k < 2; ++k) {
        const body_info *b = bs[k];
        if (!b->mesh) FZ_ASSERT(fs[k] == PCCD_FEATURE_SPHERE && is[k] < b->nv);
        else if (fs[k] == PCCD_FEATURE_VERTEX) FZ_ASSERT(is[k] < b->nv);
        else if (fs[k] == PCCD_FEATURE_EDGE) FZ_ASSERT(is[k] < b->ne);
        else FZ_ASSERT(fs[k] == PCCD_FEATURE_TRIANGLE && is[k] < b->nt);
      }
      snprintf(line, sizeof line, "\n  %d %zu %d %zu ", fi, ii, fj, ij);
      put(&t, line);
      put_time(&t, rep, p, c, 1);
    }
    FZ_ASSERT(FZ_RC(pccd_report_contact, rep, p, nc, NULL, NULL, NULL, NULL) == PCCD_EINVAL);
  }
  FZ_ASSERT(FZ_RC(pccd_report_pair, rep, np, NULL, NULL, NULL) == PCCD_EINVAL);
  FZ_ASSERT(!collides || any_first);
  return t.s;
}

static void numbers(fz_in *in, size_t n, fz_num *x, double *d, const char **s)
{
  for (size_t i = 0; i < n; ++i) {
    fz_number(in, &x[i]);
    d[i] = x[i].d;
    s[i] = x[i].text;
  }
}

static pccd_body *read_body(fz_in *in, body_info *info)
{
  static fz_num x[4 * FZ_MAX_ELEMENTS];
  double d[4 * FZ_MAX_ELEMENTS];
  const char *s[4 * FZ_MAX_ELEMENTS];
  unsigned tris[3 * FZ_MAX_ELEMENTS];
  uint8_t type = fz_u8(in) % 4;
  pccd_body *b = NULL;
  info->mesh = type < 2;
  if (info->mesh) {
    size_t nv = fz_u8(in) % (FZ_MAX_ELEMENTS + 1), nt = fz_u8(in) % (FZ_MAX_ELEMENTS + 1);
    numbers(in, 3 * nv, x, d, s);
    for (size_t i = 0; i < 3 * nt; ++i) tris[i] = nv ? fz_u8(in) % nv : fz_u8(in);
    if (type == 0) FZ_RC(pccd_body_new_mesh_s, &b, s, nv, tris, nt);
    else FZ_RC(pccd_body_new_mesh_d, &b, d, nv, tris, nt);
  } else {
    size_t n = fz_u8(in) % (FZ_MAX_BALLS + 1);
    numbers(in, 4 * n, x, d, s);
    if (type == 2) FZ_RC(pccd_body_new_spheres_s, &b, s, s + 3 * n, n);
    else FZ_RC(pccd_body_new_spheres_d, &b, d, d + 3 * n, n);
  }
  if (b) FZ_ASSERT(FZ_RC(pccd_body_counts, b, &info->nv, &info->ne, &info->nt) == PCCD_OK);
  return b;
}

/* The motion of a body; *ok = 0 when a setter rejected it (the body is then left out). */
static pccd_motion *read_motion(fz_in *in, int *ok)
{
  static fz_num x[16];
  double d[16];
  const char *s[16];
  uint8_t kind = fz_u8(in) % 7;
  pccd_motion *m = NULL;
  *ok = 1;
  if (kind == 0) return NULL;
  FZ_ASSERT(FZ_RC(pccd_motion_new, &m) == PCCD_OK);
  int rc = PCCD_OK;
  switch (kind) {
  case 2:
    numbers(in, 6, x, d, s);
    rc = FZ_RC(pccd_motion_set_linear_translation_s, m, s, s + 3);
    break;
  case 3:
    numbers(in, 8, x, d, s);
    rc = FZ_RC(pccd_motion_set_axis_rotation_s, m, s, s + 3, s[6], s[7]);
    break;
  case 4:
    numbers(in, 9, x, d, s);
    rc = FZ_RC(pccd_motion_set_screw_s, m, s, s + 3, s[6], s[7], s[8]);
    break;
  case 5:
    for (size_t a = 0; a < 3 && rc == PCCD_OK; ++a) {
      size_t n = fz_u8(in) % 6 + 1;
      numbers(in, n, x, d, s);
      rc = FZ_RC(pccd_motion_set_translation_s, m, a, s, n);
    }
    for (size_t c = 0; c < 4 && rc == PCCD_OK; ++c) {
      size_t n = fz_u8(in) % 3 + 1;
      numbers(in, n, x, d, s);
      rc = FZ_RC(pccd_motion_set_rotation_s, m, c, s, n);
    }
    break;
  case 6:
    numbers(in, 12, x, d, s);
    rc = FZ_RC(pccd_motion_set_bezier_translation_s, m, s);
    numbers(in, 7, x, d, s);
    if (rc == PCCD_OK) rc = FZ_RC(pccd_motion_compose_pose_s, m, PCCD_POSE_BODY, s, s + 4);
    break;
  default: break; /* 1: the identity */
  }
  if (rc != PCCD_OK) *ok = 0;
  return m;
}

static char solve_error[512]; /* the message of the last failed pccd_scene_solve */

/* Solves bodies[idx[0..n-1]] as a scene; the report's text, or NULL on an error
 * (checked: the report is then unsolved; a rejected motion is named). */
static char *scene_text(const body_info *bodies, const size_t *idx, size_t n,
                        const pccd_config *cfg, const pccd_scene_options *opt, int *rc_out)
{
  pccd_scene *sc = NULL;
  pccd_report *rep = NULL;
  body_info sub[FZ_MAX_BODIES];
  char *out = NULL;
  FZ_ASSERT(FZ_RC(pccd_scene_new, &sc) == PCCD_OK && FZ_RC(pccd_report_new, &rep) == PCCD_OK);
  for (size_t k = 0; k < n; ++k) {
    size_t at = 99;
    sub[k] = bodies[idx[k]];
    FZ_ASSERT(FZ_RC(pccd_scene_add, sc, sub[k].b, sub[k].m, &at) == PCCD_OK && at == k);
  }
  size_t count = 0;
  FZ_ASSERT(FZ_RC(pccd_scene_body_count, sc, &count) == PCCD_OK && count == n);
  int rc = FZ_RC(pccd_scene_solve, sc, cfg, opt, rep);
  *rc_out = rc;
#ifdef FZ_REPORT_LIMIT
  if (rc == PCCD_ELIMIT) fprintf(stderr, "ELIMIT %s\n", pccd_last_error());
#endif
  if (rc == PCCD_OK) {
    out = report_text(rep, sub, n);
  } else {
    int c;
    snprintf(solve_error, sizeof solve_error, "%s", pccd_last_error());
    FZ_ASSERT(FZ_RC(pccd_report_collides, rep, &c) == PCCD_ESTATE);
  }
  pccd_report_free(rep);
  pccd_scene_free(sc);
  return out;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  fz_in in = {data, size, 0};
  uint8_t head = fz_u8(&in), bad = fz_u8(&in), cb = fz_u8(&in);
  static const int phases[4] = {PCCD_BROAD_BOXES, PCCD_BROAD_BRUTE, PCCD_BROAD_RANGE,
                                PCCD_BROAD_AUTO};
  pccd_config cfg;
  pccd_scene_options opt;
  fz_num tol;
  FZ_ASSERT(FZ_RC(pccd_config_init, &cfg) == PCCD_OK);
  FZ_ASSERT(FZ_RC(pccd_scene_options_init, &opt) == PCCD_OK);
  if (cb & 1) {
    fz_number(&in, &tol);
    cfg.time_tolerance = tol.text;
  }
  cfg.want_time = !(cb & 2);
  cfg.want_exact = !(cb & 4);
  cfg.max_work = FZ_MAX_WORK;
  opt.all_contacts = (head >> 2) & 1;
  opt.broad_phase = phases[(head >> 3) & 3];
  opt.threads = 1 + ((head >> 5) & 1);
  if (bad >= 0xF8) {
    switch (bad % 8) {
    case 0: opt.threads = 0; break;
    case 1: opt.threads = 1025; break;
    case 2: opt.all_contacts = 2; break;
    case 3: opt.broad_phase = -1; break;
    case 4: opt.broad_phase = 4; break;
    case 5: opt.struct_size = 0; break;
    case 6: cfg.struct_size = 1; break;
    default: cfg.time_tolerance = "0"; break;
    }
  }
  size_t want = 2 + fz_u8(&in) % 3, nb = 0;
  body_info bodies[FZ_MAX_BODIES];
  for (size_t k = 0; k < want; ++k) {
    body_info info = {NULL, NULL, 0, 0, 0, 0};
    int ok = 1;
    info.b = read_body(&in, &info);
    info.m = read_motion(&in, &ok);
    if (info.b && ok) {
      bodies[nb++] = info;
    } else {
      pccd_body_free(info.b);
      pccd_motion_free(info.m);
    }
  }
  fz_set_mode(head);
  if (nb >= 2 && !in.too_costly) {
    size_t all[FZ_MAX_BODIES] = {0, 1, 2, 3};
    int rc = 0, rc2 = 0;
    char *a = scene_text(bodies, all, nb, &cfg, &opt, &rc);
    /* a rejected solve names a motion, a config or an option field */
    if (rc != PCCD_OK)
      FZ_ASSERT(strstr(solve_error, ": bodies[") || strstr(solve_error, ": config.") ||
                strstr(solve_error, ": opt."));
    if (a && (head & 64)) {
      pccd_scene_options brute = opt;
      brute.threads = 1;
      brute.broad_phase = PCCD_BROAD_BRUTE;
      char *b = scene_text(bodies, all, nb, &cfg, &brute, &rc2);
      const int decide = !cfg.want_time && !opt.all_contacts;
      FZ_ASSERT(rc2 == PCCD_ELIMIT ||
                (rc2 == PCCD_OK && (decide ? same_decision(a, b) : strcmp(a, b) == 0)));
      free(b);
    }
    if (a && (head & 128)) {
      /* the index of body 0 against each other body: the two-body scene's report
       * (without the work limit: the pairs of a scene that answered within it) */
      pccd_config all_work = cfg;
      pccd_index *ix = NULL;
      all_work.max_work = 0;
      pccd_report *reps[FZ_MAX_BODIES];
      const pccd_body *qb[FZ_MAX_BODIES];
      const pccd_motion *qm[FZ_MAX_BODIES];
      char *single[FZ_MAX_BODIES];
      FZ_ASSERT(FZ_RC(pccd_index_new, &ix, bodies[0].b, bodies[0].m) == PCCD_OK);
      for (size_t k = 1; k < nb; ++k) {
        size_t pair[2] = {0, k};
        body_info two[2] = {bodies[0], bodies[k]};
        char *s = scene_text(bodies, pair, 2, &all_work, &opt, &rc2);
        FZ_ASSERT(rc2 == PCCD_OK);
        FZ_ASSERT(FZ_RC(pccd_report_new, &reps[k - 1]) == PCCD_OK);
        FZ_ASSERT(FZ_RC(pccd_index_query, ix, bodies[k].b, bodies[k].m, &all_work, &opt,
                        reps[k - 1]) == PCCD_OK);
        single[k - 1] = report_text(reps[k - 1], two, 2);
        FZ_ASSERT(strcmp(s, single[k - 1]) == 0);
        free(s);
        qb[k - 1] = bodies[k].b;
        qm[k - 1] = bodies[k].m;
      }
      FZ_ASSERT(FZ_RC(pccd_index_query_many, ix, qb, qm, nb - 1, &all_work, &opt,
                      (pccd_report *const *)reps) == PCCD_OK);
      for (size_t k = 1; k < nb; ++k) {
        body_info two[2] = {bodies[0], bodies[k]};
        char *s = report_text(reps[k - 1], two, 2);
        FZ_ASSERT(strcmp(s, single[k - 1]) == 0);
        free(s);
        free(single[k - 1]);
        pccd_report_free(reps[k - 1]);
      }
      pccd_index_free(ix);
    }
    free(a);
  }
  for (size_t k = 0; k < nb; ++k) {
    pccd_body_free(bodies[k].b);
    pccd_motion_free(bodies[k].m);
  }
  fz_restore_mode();
  return 0;
}
