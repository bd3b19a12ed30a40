/*
 * test_index.c -- the on-line index of the C API (pccd_index_new / _query / _free):
 * known answers of a stored body queried with bodies on motions (hand-derived below)
 * with every broad phase (PCCD_BROAD_AUTO, _RANGE, _BOXES, _BRUTE, _BVH and NULL options) and
 * thread count, and the index outliving (or not) the bodies and motions it was made of
 * (the error paths of pccd_index_new / pccd_index_query: test_index_errors.c).
 *
 * pccd_index_query_many is checked against single queries and on its error paths.
 *
 * Plain C99 (built with -std=c99 -Wall -Wextra -Werror). Prints every failed check,
 * then "N passed, N failed"; exit status 0 only when nothing failed. Every handle is
 * freed (valgrind-clean). No call may change the rounding mode.
 */
#include "polyccd.h"

#include <fenv.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "scene_fixtures.h"

/* Feature (kind, index) of a cube has a point on its face x = x_face: a vertex of it
 * (it is convex and the cube lies in x in [0, 1]) is on that face. */
static int meets_face(const pccd_body *cube, int kind, size_t k, int x_face)
{
  size_t v[2];
  if (kind == PCCD_FEATURE_VERTEX) return k < 8 && (int)(k & 1) == x_face;
  if (kind == PCCD_FEATURE_TRIANGLE)
    return k < 12 && ((int)(kCubeT[3 * k] & 1) == x_face || (int)(kCubeT[3 * k + 1] & 1) == x_face ||
                      (int)(kCubeT[3 * k + 2] & 1) == x_face);
  if (kind == PCCD_FEATURE_EDGE)
    return pccd_body_edge(cube, k, v) == PCCD_OK &&
           ((int)(v[0] & 1) == x_face || (int)(v[1] & 1) == x_face);
  return 0;
}

/* opt: NULL (defaults) or options with the broad phase and thread count. */
static const pccd_scene_options *options(pccd_scene_options *opt, int broad, unsigned threads,
                                         int all_contacts)
{
  if (broad < 0) return NULL;
  pccd_scene_options_init(opt);
  opt->broad_phase = broad;
  opt->threads = threads;
  opt->all_contacts = all_contacts;
  return opt;
}

/* The stored cube A slides from x = 0 to x = 1 (its face x = 1 is at 1 + t); the query
 * cube B slides from x = 3 to x = 0 (its face x = 0 is at 3 - 3t). They meet when
 * 1 + t = 3 - 3t: t = 1/2 exactly (before, the cubes are apart in x). Then A spans
 * x in [1/2, 3/2] and B [3/2, 5/2], so every touching feature pair meets in the plane
 * x = 3/2: a feature of A with a vertex on its face x = 1 and one of B with a vertex on
 * its face x = 0 (the faces coincide as a unit square). With all_contacts, the cubes
 * pass through each other afterwards, so more contacts follow, all at times >= 1/2.
 *
 * A ball of radius 1/2 at (5, 1/4, 1/2) sliding x = 5 - 5t (one-ball query) touches A's
 * face x = 1 + t when 5 - 5t - 1/2 = 1 + t: t = 7/12, at (19/12, 1/4, 1/2), inside
 * triangle 10 = (1, 3, 5) of that face (y + z = 3/4 < 1, y, z > 0): the only contact.
 *
 * A one-triangle query (0, 1/8, 1/8), (0, 1/2, 1/8), (0, 1/8, 1/2) in the plane x = 0,
 * sliding x = 4 - 4t, reaches A's face x = 1 + t when 4 - 4t = 1 + t: t = 3/5. It then
 * lies strictly inside A's triangle 10 (y, z >= 1/8, y + z <= 5/8 < 1), away from every
 * edge and vertex of A, so the contacts are exactly its three vertices in triangle 10. */
static void known_answers(int broad, unsigned threads)
{
  pccd_body *cube = NULL, *ball = NULL, *tri = NULL;
  pccd_motion *ma = slide_x(0, 1), *mb = slide_x(3, 0), *mball = slide_x(0, -5),
              *mtri = slide_x(4, 0), *mfar = slide_x(3, 3);
  pccd_index *ix = NULL;
  pccd_report *rep = NULL;
  pccd_scene_options opt;
  const double centre[3] = {5, 0.25, 0.5}, radius = 0.5;
  const double tv[9] = {0, 0.125, 0.125, 0, 0.5, 0.125, 0, 0.125, 0.5};
  const unsigned int tt[3] = {0, 1, 2};
  size_t count = 0, ncontacts = 0, bi = 9, bj = 9, ki = 0, kj = 0, c;
  int collides = -1, first = -1, fi = -1, fj = -1, exact = -1, all_on_faces = 1;
  double approx = 0;
  if (!CHECK(ma && mb && mball && mtri && mfar)) goto done;
  OK(pccd_body_new_mesh_d(&cube, kCubeV, 8, kCubeT, 12));
  OK(pccd_body_new_spheres_d(&ball, centre, &radius, 1));
  OK(pccd_body_new_mesh_d(&tri, tv, 3, tt, 1));
  OK(pccd_index_new(&ix, cube, ma));
  pccd_motion_free(ma); /* the index keeps a copy of the motion */
  ma = NULL;
  OK(pccd_report_new(&rep));

  /* Cube against cube: first contact exactly 1/2 on the faces. */
  OK(pccd_index_query(ix, cube, mb, NULL, options(&opt, broad, threads, 0), rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 1);
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 0, "1/2"));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 1, "1/2"));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "1/2"));
  OK(pccd_report_time_info(rep, PCCD_WHOLE, PCCD_WHOLE, &exact, &approx));
  CHECK(exact == 1 && approx == 0.5);
  OK(pccd_report_pair_count(rep, &count));
  CHECK(count == 1);
  OK(pccd_report_pair(rep, 0, &bi, &bj, &first));
  CHECK(bi == 0 && bj == 1 && first == 1);
  CHECK(time_is(rep, 0, PCCD_WHOLE, 2, "1/2"));
  OK(pccd_report_contact_count(rep, 0, &ncontacts));
  CHECK(ncontacts >= 4); /* at least the four vertex pairs of the coinciding squares */
  for (c = 0; c < ncontacts; ++c) {
    OK(pccd_report_contact(rep, 0, c, &fi, &ki, &fj, &kj));
    /* feature_i belongs to the indexed body A (face x = 1), feature_j to B (x = 0) */
    all_on_faces &= meets_face(cube, fi, ki, 1) && meets_face(cube, fj, kj, 0) &&
                    time_is(rep, 0, c, 2, "1/2");
  }
  CHECK(all_on_faces);
  FAILS(pccd_report_pair(rep, 1, NULL, NULL, NULL), PCCD_EINVAL, "pair: 1 out of range");

  /* All contacts: the first ones above again, then later ones, ordered by time (one
   * thread count only: the slowest query here, run under valgrind too). */
  if (broad >= 0 && threads == 1) {
    size_t n_all = 0, at_half = 0;
    double prev = 0;
    int ordered = 1;
    OK(pccd_index_query(ix, cube, mb, NULL, options(&opt, broad, threads, 1), rep));
    OK(pccd_report_contact_count(rep, 0, &n_all));
    CHECK(n_all > ncontacts);
    for (c = 0; c < n_all; ++c) {
      OK(pccd_report_time_info(rep, 0, c, &exact, &approx));
      ordered &= approx >= prev && approx >= 0.5;
      prev = approx;
      at_half += time_is(rep, 0, c, 0, "1/2");
    }
    CHECK(ordered && at_half == ncontacts);
  }

  /* One ball: t = 7/12, ball 0 against triangle 10. */
  OK(pccd_index_query(ix, ball, mball, NULL, options(&opt, broad, threads, 0), rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 1);
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "7/12"));
  OK(pccd_report_contact_count(rep, 0, &count));
  CHECK(count == 1);
  OK(pccd_report_contact(rep, 0, 0, &fi, &ki, &fj, &kj));
  CHECK(fi == PCCD_FEATURE_TRIANGLE && ki == 10 && fj == PCCD_FEATURE_SPHERE && kj == 0);

  /* One triangle: t = 3/5, its vertices 0, 1, 2 (in some order) in triangle 10. */
  OK(pccd_index_query(ix, tri, mtri, NULL, options(&opt, broad, threads, 0), rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 1);
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "3/5"));
  OK(pccd_report_contact_count(rep, 0, &count));
  CHECK(count == 3);
  {
    int seen = 0;
    for (c = 0; c < count && c < 3; ++c) {
      OK(pccd_report_contact(rep, 0, c, &fi, &ki, &fj, &kj));
      if (fi == PCCD_FEATURE_TRIANGLE && ki == 10 && fj == PCCD_FEATURE_VERTEX && kj < 3)
        seen |= 1 << kj;
    }
    CHECK(seen == 7);
  }

  /* B standing at x in [3, 4] never meets A (x <= 2). */
  OK(pccd_index_query(ix, cube, mfar, NULL, options(&opt, broad, threads, 0), rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 0);
  OK(pccd_report_pair_count(rep, &count));
  CHECK(count == 0);
  FAILS(pccd_report_time(rep, PCCD_WHOLE, PCCD_WHOLE, 0, NULL, 0, NULL), PCCD_ESTATE, "");

done:
  pccd_report_free(rep);
  pccd_index_free(ix);
  pccd_body_free(cube);
  pccd_body_free(ball);
  pccd_body_free(tri);
  pccd_motion_free(ma);
  pccd_motion_free(mb);
  pccd_motion_free(mball);
  pccd_motion_free(mtri);
  pccd_motion_free(mfar);
}

/* A swing about a fixed axis (the range phase's exact rotation linearization): the unit
 * cube at rest is indexed; a triangle with vertices (1/3, 2, 1/2), (1, 2, 1/2),
 * (1, 2, 3/4) turns about the vertical axis through (2, 2, 0) with tau from 0 to 1.
 * Vertex 0 is at distance 5/3 from the axis, at (2 - 5/3 cos th, 2 - 5/3 sin th, 1/2);
 * it reaches the face y = 1 when sin th = 3/5 (cos th = 4/5: x = 2/3, inside the face),
 * i.e. tan(th / 2) = (3/5) / (1 + 4/5) = 1/3 = tau: t = 1/3 exactly. The other vertices
 * (distance 1) and the edges (distances 1 to 5/3, reaching y = 1 at sin th = 1/rho, later
 * for smaller rho) come later. */
static void swing(int broad, unsigned threads)
{
  pccd_body *cube = NULL, *tri = NULL;
  pccd_motion *m = NULL;
  pccd_index *ix = NULL;
  pccd_report *rep = NULL;
  pccd_scene_options opt;
  const char *sv[9] = {"1/3", "2", "1/2", "1", "2", "1/2", "1", "2", "3/4"};
  const unsigned int tt[3] = {0, 1, 2};
  const char *axis[3] = {"0", "0", "1"}, *center[3] = {"2", "2", "0"};
  size_t count = 0, c, ki = 0, kj = 0;
  int collides = -1, fi = -1, fj = -1, vertex0 = 0;
  OK(pccd_body_new_mesh_d(&cube, kCubeV, 8, kCubeT, 12));
  OK(pccd_body_new_mesh_s(&tri, sv, 3, tt, 1));
  OK(pccd_motion_new(&m));
  OK(pccd_motion_set_axis_rotation_s(m, axis, center, "0", "1"));
  OK(pccd_index_new(&ix, cube, NULL));
  OK(pccd_report_new(&rep));
  OK(pccd_index_query(ix, tri, m, NULL, options(&opt, broad, threads, 0), rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 1);
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "1/3"));
  OK(pccd_report_contact_count(rep, 0, &count));
  CHECK(count >= 1);
  for (c = 0; c < count; ++c) {
    OK(pccd_report_contact(rep, 0, c, &fi, &ki, &fj, &kj));
    vertex0 |= fi == PCCD_FEATURE_TRIANGLE && fj == PCCD_FEATURE_VERTEX && kj == 0;
  }
  CHECK(vertex0);
  /* tau only to 1/4 (t = 1 is tau = 1/4 < 1/3): no contact */
  OK(pccd_motion_set_axis_rotation_s(m, axis, center, "0", "1/4"));
  OK(pccd_index_query(ix, tri, m, NULL, options(&opt, broad, threads, 0), rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 0);
  pccd_report_free(rep);
  pccd_index_free(ix);
  pccd_motion_free(m);
  pccd_body_free(cube);
  pccd_body_free(tri);
}

/* The index keeps its own reference to the body: it answers after the body (and the
 * motion) were freed; and freeing the index first leaves the bodies usable. The query
 * cube on slide_x(3, 0) meets the stationary cube when 3 - 3t = 1: t = 2/3. */
static void lifetimes(void)
{
  pccd_body *a = NULL, *b = NULL;
  pccd_motion *m = slide_x(3, 0);
  pccd_index *ix = NULL, *ix2 = NULL;
  pccd_report *rep = NULL;
  int collides = 0;
  if (!CHECK(m != NULL)) return;
  OK(pccd_report_new(&rep));
  /* Index made, then its body freed before any query. */
  OK(pccd_body_new_mesh_d(&a, kCubeV, 8, kCubeT, 12));
  OK(pccd_index_new(&ix, a, NULL));
  pccd_body_free(a);
  OK(pccd_body_new_mesh_d(&b, kCubeV, 8, kCubeT, 12));
  OK(pccd_index_query(ix, b, m, NULL, NULL, rep));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "2/3"));
  /* The query body may be freed after a query; the report stays readable. */
  pccd_body_free(b);
  pccd_motion_free(m);
  m = NULL;
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 1);
  /* An index of the same body as a query of itself (a body is a shape: sharing is fine). */
  OK(pccd_body_new_mesh_d(&a, kCubeV, 8, kCubeT, 12));
  m = slide_x(3, 0);
  OK(pccd_index_new(&ix2, a, NULL));
  OK(pccd_index_query(ix2, a, m, NULL, NULL, rep));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "2/3"));
  /* The index freed first: the body still works (in another index and in a query). */
  pccd_index_free(ix2);
  ix2 = NULL;
  OK(pccd_index_query(ix, a, m, NULL, NULL, rep));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "2/3"));
  OK(pccd_index_new(&ix2, a, m));
  OK(pccd_index_query(ix2, a, NULL, NULL, NULL, rep)); /* the same answer, roles exchanged */
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "2/3"));
  pccd_index_free(ix2);
  pccd_index_free(ix);
  pccd_body_free(a);
  pccd_motion_free(m);
  pccd_report_free(rep);
  pccd_index_free(NULL); /* does nothing */
}

/* pccd_index_query_many: three queries (the moving cube at t = 2/3, a cube standing at
 * x = 3 that never touches, the cube again on a NULL motion entry -- the unit cube
 * itself, touching the stored one from t = 0) answer as single queries do. */
static void many(unsigned threads)
{
  pccd_body *cube = NULL;
  pccd_motion *m = slide_x(3, 0), *far = slide_x(3, 3), *bad = vanishing();
  pccd_index *ix = NULL;
  pccd_report *reps[3] = {NULL, NULL, NULL}, *one = NULL;
  pccd_scene_options opt;
  const pccd_body *bodies[3];
  const pccd_motion *motions[3];
  int collides = -1, k;
  if (!CHECK(m && far && bad)) goto done;
  OK(pccd_body_new_mesh_d(&cube, kCubeV, 8, kCubeT, 12));
  OK(pccd_index_new(&ix, cube, NULL));
  for (k = 0; k < 3; ++k) OK(pccd_report_new(&reps[k]));
  OK(pccd_report_new(&one));
  bodies[0] = bodies[1] = bodies[2] = cube;
  motions[0] = m;
  motions[1] = far;
  motions[2] = NULL;
  OK(pccd_scene_options_init(&opt));
  opt.threads = threads;
  OK(pccd_index_query_many(ix, bodies, motions, 3, NULL, &opt, reps));
  CHECK(time_is(reps[0], PCCD_WHOLE, PCCD_WHOLE, 2, "2/3"));
  OK(pccd_report_collides(reps[1], &collides));
  CHECK(collides == 0);
  CHECK(time_is(reps[2], PCCD_WHOLE, PCCD_WHOLE, 2, "0"));
  OK(pccd_index_query(ix, cube, NULL, NULL, NULL, one));
  CHECK(time_is(one, PCCD_WHOLE, PCCD_WHOLE, 2, "0"));
  /* motions == NULL: every query stationary (all touch at t = 0). */
  OK(pccd_index_query_many(ix, bodies, NULL, 3, NULL, &opt, reps));
  for (k = 0; k < 3; ++k) CHECK(time_is(reps[k], PCCD_WHOLE, PCCD_WHOLE, 2, "0"));
  /* n = 0 does nothing, even with NULL arrays. */
  OK(pccd_index_query_many(ix, NULL, NULL, 0, NULL, NULL, NULL));
  /* Errors: every report is left unsolved. */
  motions[1] = bad;
  FAILS(pccd_index_query_many(ix, bodies, motions, 3, NULL, &opt, reps), PCCD_EINVAL,
        "bodies[1].motion: ");
  CHECK(strstr(pccd_last_error(), "vanishes at t = 1/2") != NULL);
  for (k = 0; k < 3; ++k)
    FAILS(pccd_report_collides(reps[k], &collides), PCCD_ESTATE, "rep: holds no answer");
  motions[1] = far;
  FAILS(pccd_index_query_many(NULL, bodies, motions, 3, NULL, NULL, reps), PCCD_EINVAL, "ix: is NULL");
  FAILS(pccd_index_query_many(ix, NULL, motions, 3, NULL, NULL, reps), PCCD_EINVAL, "bodies: is NULL");
  FAILS(pccd_index_query_many(ix, bodies, motions, 3, NULL, NULL, NULL), PCCD_EINVAL, "reports: is NULL");
  bodies[2] = NULL;
  FAILS(pccd_index_query_many(ix, bodies, motions, 3, NULL, NULL, reps), PCCD_EINVAL,
        "pccd_index_query_many: bodies[2]: is NULL");
  bodies[2] = cube;
  {
    pccd_report *const with_null[3] = {reps[0], NULL, reps[2]};
    FAILS(pccd_index_query_many(ix, bodies, motions, 3, NULL, NULL, with_null), PCCD_EINVAL,
          "reports[1]: is NULL");
  }
  opt.threads = 0;
  FAILS(pccd_index_query_many(ix, bodies, motions, 3, NULL, &opt, reps), PCCD_EINVAL,
        "opt.threads: 0 is outside");
done:
  for (k = 0; k < 3; ++k) pccd_report_free(reps[k]);
  pccd_report_free(one);
  pccd_index_free(ix);
  pccd_body_free(cube);
  pccd_motion_free(m);
  pccd_motion_free(far);
  pccd_motion_free(bad);
}

int main(void)
{
  /* Every broad phase (and NULL options); thread counts 1 to 3 for the index's own
   * phases (boxes and brute force: one thread, to keep the valgrind run short). */
  const int broads[6] = {-1 /* NULL options */, PCCD_BROAD_AUTO, PCCD_BROAD_RANGE,
                         PCCD_BROAD_BOXES, PCCD_BROAD_BRUTE, PCCD_BROAD_BVH};
  const unsigned max_threads[6] = {1, 3, 3, 1, 1, 3};
  int b;
  unsigned t;
  for (b = 0; b < 6; ++b)
    for (t = 1; t <= max_threads[b]; ++t) {
      known_answers(broads[b], t);
      swing(broads[b], t);
    }
  lifetimes();
  for (t = 1; t <= 3; ++t) many(t);
  printf("%d passed, %d failed\n", g_pass, g_fail);
  return g_fail == 0 ? 0 : 1;
}
