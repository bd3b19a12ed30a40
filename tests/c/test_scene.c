/*
 * test_scene.c -- the scene part of the C API (pccd_scene_*, pccd_pair_solve,
 * pccd_report_*): known answers of small scenes (hand-derived below), identical answers
 * for any thread count and both broad phases, and every error path of that section of
 * include/polyccd.h.
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

/* Cube B slides from x = 3 to x = 0 against the fixed cube A: faces x = 1 (A) and
 * x = 3 - 3t (B) meet when 3 - 3t = 1, at t = 2/3 exactly. The fixed ball (centre
 * (5, 1/2, 1/2), radius 1/2) spans x in [4.5, 5.5]; B spans [3 - 3t, 4 - 3t], at most
 * x = 4, so the ball touches nothing. The scene's only contact is A-B, first at 2/3. */
static void two_cubes(unsigned threads, int broad)
{
  pccd_body *cube = NULL, *ball = NULL;
  pccd_motion *m = slide_x(3, 0);
  pccd_scene *s = NULL;
  pccd_report *rep = NULL;
  pccd_scene_options opt;
  size_t index = 99, count = 0, bi = 9, bj = 9, fi_idx = 0, fj_idx = 0;
  int collides = -1, exact = -1, first = -1, fi = -1, fj = -1;
  double approx = 0;
  const double centre[3] = {5, 0.5, 0.5}, radius = 0.5;
  pccd_scene_stats st;
  if (!CHECK(m != NULL)) return;
  OK(pccd_body_new_mesh_d(&cube, kCubeV, 8, kCubeT, 12));
  OK(pccd_body_new_spheres_d(&ball, centre, &radius, 1));
  OK(pccd_scene_new(&s));
  OK(pccd_scene_add(s, cube, NULL, &index));
  CHECK(index == 0);
  OK(pccd_scene_add(s, cube, m, &index));
  CHECK(index == 1);
  OK(pccd_scene_add(s, ball, NULL, NULL));
  pccd_body_free(cube); /* the scene keeps its own references and copies */
  pccd_body_free(ball);
  pccd_motion_free(m);
  OK(pccd_scene_body_count(s, &count));
  CHECK(count == 3);
  OK(pccd_scene_options_init(&opt));
  opt.threads = threads;
  opt.broad_phase = broad;
  OK(pccd_report_new(&rep));
  OK(pccd_scene_solve(s, NULL, &opt, rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 1);
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 0, "2/3"));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "2/3"));
  OK(pccd_report_time_info(rep, PCCD_WHOLE, PCCD_WHOLE, &exact, &approx));
  CHECK(exact == 1 && approx == 2.0 / 3.0);
  OK(pccd_report_pair_count(rep, &count));
  CHECK(count == 1);
  OK(pccd_report_pair(rep, 0, &bi, &bj, &first));
  CHECK(bi == 0 && bj == 1 && first == 1);
  CHECK(time_is(rep, 0, PCCD_WHOLE, 1, "2/3"));
  OK(pccd_report_contact_count(rep, 0, &count));
  CHECK(count > 0);
  /* Every contact at 2/3 involves A's face x = 1 side: vertex 1, 3, 5, 7 or triangles
   * 10, 11 (x = 1) against B's features on x = 3 - 3t. */
  OK(pccd_report_contact(rep, 0, 0, &fi, &fi_idx, &fj, &fj_idx));
  CHECK(fi >= PCCD_FEATURE_VERTEX && fi <= PCCD_FEATURE_TRIANGLE);
  CHECK(time_is(rep, 0, 0, 2, "2/3"));
  OK(pccd_report_stats(rep, &st));
  CHECK(st.solved > 0);
  /* Errors on a solved report. */
  FAILS(pccd_report_pair(rep, 1, NULL, NULL, NULL), PCCD_EINVAL, "pccd_report_pair: pair: 1 out of range");
  FAILS(pccd_report_contact(rep, 0, 100000, NULL, NULL, NULL, NULL), PCCD_EINVAL, "pccd_report_contact: contact: 100000 out of range");
  FAILS(pccd_report_time(rep, PCCD_WHOLE, PCCD_WHOLE, 3, NULL, 0, NULL), PCCD_EINVAL, "pccd_report_time: which: 3 is not 0");
  {
    char small[2];
    size_t needed = 0;
    CHECK(pccd_report_time(rep, PCCD_WHOLE, PCCD_WHOLE, 0, small, sizeof small, &needed) == PCCD_ERANGE &&
          needed == 4);
  }
  /* The only pair in contact, skipped (given in either order): no contact at all; the
   * other pairs are still checked (none touches); checked again: the same answer. */
  OK(pccd_scene_set_pair_check(s, 1, 0, 0));
  OK(pccd_scene_solve(s, NULL, &opt, rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 0);
  OK(pccd_report_pair_count(rep, &count));
  CHECK(count == 0);
  OK(pccd_scene_set_pair_check(s, 0, 2, 0));
  OK(pccd_scene_set_pair_check(s, 0, 1, 1));
  OK(pccd_scene_solve(s, NULL, &opt, rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 1);
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "2/3"));
  pccd_report_free(rep);
  pccd_scene_free(s);
}

/* A rotation quaternion (1 - 2t, 0, 0, 0) vanishes at t = 1/2: rejected by solve with
 * the body's place. A fresh report cannot be read. Bad options are named. */
static void errors(void)
{
  pccd_body *cube = NULL;
  pccd_motion *m = NULL;
  pccd_scene *s = NULL;
  pccd_report *rep = NULL;
  pccd_scene_options opt;
  const char *w[2] = {"1", "-2"};
  int v = 0;
  size_t n = 0;
  OK(pccd_body_new_mesh_d(&cube, kCubeV, 8, kCubeT, 12));
  OK(pccd_motion_new(&m));
  OK(pccd_motion_set_rotation_s(m, 0, w, 2));
  OK(pccd_scene_new(&s));
  OK(pccd_report_new(&rep));
  FAILS(pccd_report_collides(rep, &v), PCCD_ESTATE, "rep: holds no answer");
  FAILS(pccd_report_pair_count(rep, &n), PCCD_ESTATE, "rep: holds no answer");
  OK(pccd_scene_add(s, cube, NULL, NULL));
  FAILS(pccd_scene_solve(s, NULL, NULL, rep), PCCD_EINVAL, "at least 2 bodies");
  OK(pccd_scene_add(s, cube, m, NULL));
  FAILS(pccd_scene_solve(s, NULL, NULL, rep), PCCD_EINVAL, "bodies[1].motion");
  CHECK(strstr(pccd_last_error(), "1/2") != NULL);
  FAILS(pccd_report_collides(rep, &v), PCCD_ESTATE, "rep: holds no answer");
  OK(pccd_scene_options_init(&opt));
  opt.threads = 0;
  FAILS(pccd_scene_solve(s, NULL, &opt, rep), PCCD_EINVAL, "pccd_scene_solve: opt.threads: 0 is outside 1..1024");
  OK(pccd_scene_options_init(&opt));
  opt.broad_phase = 7;
  FAILS(pccd_scene_solve(s, NULL, &opt, rep), PCCD_EINVAL, "opt.broad_phase: 7 is not");
  OK(pccd_scene_options_init(&opt));
  opt.struct_size = 3;
  FAILS(pccd_scene_solve(s, NULL, &opt, rep), PCCD_EINVAL, "opt.struct_size: ");
  FAILS(pccd_scene_new(NULL), PCCD_EINVAL, "pccd_scene_new: out: is NULL");
  FAILS(pccd_scene_add(NULL, cube, NULL, NULL), PCCD_EINVAL, "pccd_scene_add: s: is NULL");
  FAILS(pccd_scene_add(s, NULL, NULL, NULL), PCCD_EINVAL, "body: is NULL");
  FAILS(pccd_scene_solve(s, NULL, NULL, NULL), PCCD_EINVAL, "pccd_scene_solve: rep: is NULL");
  FAILS(pccd_scene_options_init(NULL), PCCD_EINVAL, "pccd_scene_options_init: opt: is NULL");
  FAILS(pccd_report_stats(rep, NULL), PCCD_ESTATE, "pccd_report_stats: rep: holds no answer");
  FAILS(pccd_scene_set_pair_check(NULL, 0, 1, 0), PCCD_EINVAL, "pccd_scene_set_pair_check: s: is NULL");
  FAILS(pccd_scene_set_pair_check(s, 0, 2, 0), PCCD_EINVAL, "pccd_scene_set_pair_check: j: 2 out of range (2 bodies)");
  FAILS(pccd_scene_set_pair_check(s, 5, 1, 0), PCCD_EINVAL, "i: 5 out of range (2 bodies)");
  FAILS(pccd_scene_set_pair_check(s, 1, 1, 0), PCCD_EINVAL, "j: 1 equals i");
  FAILS(pccd_scene_set_pair_check(s, 0, 1, 2), PCCD_EINVAL, "check: 2 is not 0 (skip) or 1 (check)");
  pccd_scene_free(NULL);
  pccd_report_free(NULL);
  pccd_report_free(rep);
  pccd_scene_free(s);
  pccd_motion_free(m);
  pccd_body_free(cube);
}

/* pccd_pair_solve: the two-body scene without a pccd_scene. Cube B slides from x = 3 to
 * x = 0 against cube A (first contact 2/3, as two_cubes): the same answer and the same
 * work counters as the scene of (A, NULL), (B, m). The motion handle keeps its derived
 * data from the first solve; every setter drops it: changing m to x = 3 -> -1 moves the
 * contact to 3 - 4t = 1, t = 1/2, and a world-side shift by -1 to 2 - 4t = 1, t = 1/4,
 * while the scene built before keeps the motion it copied (2/3). A motion made invalid
 * after a valid solve fails the next solve; fixed again, it solves. */
static void pair_solve(unsigned threads, int broad)
{
  pccd_body *cube = NULL;
  pccd_motion *m = slide_x(3, 0);
  pccd_scene *s = NULL;
  pccd_report *rep = NULL, *rep2 = NULL;
  pccd_scene_options opt;
  pccd_scene_stats st, st2;
  size_t n = 0, n2 = 0;
  int v = -1;
  const double p0[3] = {3, 0, 0}, p1[3] = {-1, 0, 0};
  const char *q[4] = {"1", "0", "0", "0"}, *shift[3] = {"-1", "0", "0"};
  const char *w_bad[2] = {"1", "-2"}, *w_one[1] = {"1"};
  if (!CHECK(m != NULL)) return;
  OK(pccd_body_new_mesh_d(&cube, kCubeV, 8, kCubeT, 12));
  OK(pccd_scene_new(&s));
  OK(pccd_scene_add(s, cube, NULL, NULL));
  OK(pccd_scene_add(s, cube, m, NULL));
  OK(pccd_scene_options_init(&opt));
  opt.threads = threads;
  opt.broad_phase = broad;
  OK(pccd_report_new(&rep));
  OK(pccd_report_new(&rep2));
  OK(pccd_pair_solve(cube, NULL, cube, m, NULL, &opt, rep));
  OK(pccd_scene_solve(s, NULL, &opt, rep2));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "2/3") && time_is(rep2, PCCD_WHOLE, PCCD_WHOLE, 2, "2/3"));
  OK(pccd_report_contact_count(rep, 0, &n));
  OK(pccd_report_contact_count(rep2, 0, &n2));
  CHECK(n > 0 && n == n2);
  OK(pccd_report_stats(rep, &st));
  OK(pccd_report_stats(rep2, &st2));
  CHECK(memcmp(&st, &st2, sizeof st) == 0);
  OK(pccd_motion_set_linear_translation_d(m, p0, p1));
  OK(pccd_pair_solve(cube, NULL, cube, m, NULL, &opt, rep));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "1/2"));
  OK(pccd_scene_solve(s, NULL, &opt, rep2));
  CHECK(time_is(rep2, PCCD_WHOLE, PCCD_WHOLE, 2, "2/3"));
  OK(pccd_motion_compose_pose_s(m, PCCD_POSE_WORLD, q, shift));
  OK(pccd_pair_solve(cube, NULL, cube, m, NULL, &opt, rep));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "1/4"));
  OK(pccd_pair_solve(cube, m, cube, NULL, NULL, &opt, rep)); /* the moving body first */
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "1/4"));
  OK(pccd_motion_set_rotation_s(m, 0, w_bad, 2));
  FAILS(pccd_pair_solve(cube, NULL, cube, m, NULL, &opt, rep), PCCD_EINVAL, "pccd_pair_solve: bodies[1].motion");
  CHECK(strstr(pccd_last_error(), "1/2") != NULL);
  FAILS(pccd_report_collides(rep, &v), PCCD_ESTATE, "rep: holds no answer");
  FAILS(pccd_pair_solve(cube, m, cube, NULL, NULL, &opt, rep), PCCD_EINVAL, "bodies[0].motion");
  OK(pccd_motion_set_rotation_s(m, 0, w_one, 1));
  OK(pccd_pair_solve(cube, NULL, cube, m, NULL, &opt, rep));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "1/4"));
  FAILS(pccd_pair_solve(NULL, NULL, cube, m, NULL, &opt, rep), PCCD_EINVAL, "pccd_pair_solve: a: is NULL");
  FAILS(pccd_pair_solve(cube, NULL, NULL, m, NULL, &opt, rep), PCCD_EINVAL, "pccd_pair_solve: b: is NULL");
  FAILS(pccd_pair_solve(cube, NULL, cube, m, NULL, &opt, NULL), PCCD_EINVAL, "pccd_pair_solve: rep: is NULL");
  opt.threads = 0;
  FAILS(pccd_pair_solve(cube, NULL, cube, m, NULL, &opt, rep), PCCD_EINVAL, "pccd_pair_solve: opt.threads: 0 is outside");
  FAILS(pccd_report_collides(rep, &v), PCCD_ESTATE, "rep: holds no answer");
  pccd_report_free(rep);
  pccd_report_free(rep2);
  pccd_scene_free(s);
  pccd_motion_free(m);
  pccd_body_free(cube);
}

int main(void)
{
  unsigned t;
  for (t = 1; t <= 3; ++t) {
    two_cubes(t, PCCD_BROAD_BOXES);
    two_cubes(t, PCCD_BROAD_BRUTE);
    two_cubes(t, PCCD_BROAD_RANGE);
    two_cubes(t, PCCD_BROAD_BVH);
    pair_solve(t, PCCD_BROAD_AUTO);
    pair_solve(t, PCCD_BROAD_BOXES);
  }
  errors();
  printf("%d passed, %d failed\n", g_pass, g_fail);
  return g_fail == 0 ? 0 : 1;
}
