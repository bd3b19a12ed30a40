/*
 * test_robot.c -- the robot part of the C API (pccd_robot_*, pccd_report_free_until): a
 * chain whose contacts are known by construction, in both modes, with and without the
 * filter and self-collision, and the error paths of that section of include/polyccd.h.
 * Plain C99; every handle is freed.
 */
#include "polyccd.h"

#include <string.h>

#include "check.h"
#include "scene_fixtures.h"

/* Link 0: prismatic along x, q 0 -> 1, carrying the unit cube [0, 1]^3 (group 0): the
 * cube spans x in [t, 1 + t]. Link 1: fixed under link 0 at (0, 0, 1/2), another unit
 * cube (group 1): it overlaps the first at every t. Obstacles: the unit cube slid to
 * x = 3/2 (touched at t = 1/2 exactly: 1 + t = 3/2) or to x = 5/2 (never touched). */
static int free_is(const pccd_report *rep, const char *want, double *below)
{
  char buf[64];
  size_t needed = 0;
  return pccd_report_free_until(rep, buf, sizeof buf, &needed, below) == PCCD_OK && strcmp(buf, want) == 0;
}

/* Two revolute links about z (the second hanging 2 along x from the first), a unit cube
 * on each, and a stationary cube beside their sweep: the filtered check (links enclosed
 * from the joint path, self pairs relative to their common ancestor, witnesses, the
 * exact solve on a witness's window) must give the unfiltered exact check's answers in
 * both modes, with and without self-collision, on segments that hit and that miss. */
static void filtered_equals_unfiltered(const pccd_body *cube)
{
  static const double shifted[24] = {0.5, 2.5, 0, 1.5, 2.5, 0, 0.5, 3.5, 0, 1.5, 3.5, 0,
                                     0.5, 2.5, 1, 1.5, 2.5, 1, 0.5, 3.5, 1, 1.5, 3.5, 1};
  const double ez[3] = {0, 0, 1}, zero[3] = {0, 0, 0}, out[3] = {2, 0, 0};
  const double ends[4][4] = {{0, 0, 1.2, -2.0}, {0, 0, 0.3, 0.2}, {-0.4, 1, 1.6, 2.5}, {0.1, 2.9, 0.9, 2.0}};
  pccd_chain *c = NULL;
  pccd_robot *r = NULL;
  pccd_body *wall = NULL;
  pccd_report *a = NULL, *b = NULL;
  pccd_config cfg;
  pccd_robot_options ro;
  const pccd_body *obst[1];
  int k, mode, self, ca = -1, cb = -1, ea = -1, eb = -1, seen[2] = {0, 0};
  double ta = -1, tb = -1;
  OK(pccd_chain_new(&c));
  OK(pccd_chain_add_link(c, -1, PCCD_JOINT_REVOLUTE, ez, zero, zero, NULL));
  OK(pccd_chain_add_link(c, 0, PCCD_JOINT_REVOLUTE, ez, out, zero, NULL));
  OK(pccd_robot_new(&r, c));
  pccd_chain_free(c);
  OK(pccd_robot_add_body(r, 0, 0, cube, NULL));
  OK(pccd_robot_add_body(r, 1, 1, cube, NULL));
  OK(pccd_body_new_mesh_d(&wall, shifted, 8, kCubeT, 12));
  obst[0] = wall;
  OK(pccd_report_new(&a));
  OK(pccd_report_new(&b));
  OK(pccd_config_init(&cfg));
  OK(pccd_robot_options_init(&ro));
  g_case = "filtered equals unfiltered, revolute links";
  for (k = 0; k < 4; ++k)
    for (mode = 0; mode <= 1; ++mode)
      for (self = 0; self <= 1; ++self) {
        const double q0[2] = {ends[k][0], ends[k][1]}, q1[2] = {ends[k][2], ends[k][3]};
        cfg.want_time = mode;
        ro.self_collision = self;
        ro.filter = 1;
        OK(pccd_robot_check(r, q0, q1, 2, obst, NULL, 1, &cfg, NULL, &ro, a));
        ro.filter = 0;
        OK(pccd_robot_check(r, q0, q1, 2, obst, NULL, 1, &cfg, NULL, &ro, b));
        OK(pccd_report_collides(a, &ca));
        OK(pccd_report_collides(b, &cb));
        CHECK(ca == cb);
        seen[ca == 1] += 1;
        if (ca == 1 && mode == 1) {
          OK(pccd_report_time_info(a, PCCD_WHOLE, PCCD_WHOLE, &ea, &ta));
          OK(pccd_report_time_info(b, PCCD_WHOLE, PCCD_WHOLE, &eb, &tb));
          CHECK(ea == eb && ta - tb < 1e-9 && tb - ta < 1e-9);
        }
      }
  CHECK(seen[0] > 0 && seen[1] > 0); /* hits and misses both checked */
  pccd_report_free(a);
  pccd_report_free(b);
  pccd_body_free(wall);
  pccd_robot_free(r);
}

static void cases(void)
{
  pccd_chain *c = NULL;
  pccd_robot *r = NULL;
  pccd_body *cube = NULL;
  pccd_report *rep = NULL;
  pccd_config cfg;
  pccd_robot_options ro;
  pccd_motion *near = slide_x(1.5, 1.5), *far = slide_x(2.5, 2.5);
  const double ex[3] = {1, 0, 0}, zero[3] = {0, 0, 0}, up[3] = {0, 0, 0.5};
  const double q0[2] = {0, 0}, q1[2] = {1, 0};
  const size_t both[2] = {0, 1};
  size_t index = 9, bi = 9, bj = 9, count = 9;
  int collides = -1, first = -1, filter;
  double below = -1;
  const pccd_body *obst[1];
  const pccd_motion *mot_near[1], *mot_far[1];

  CHECK(near && far);
  OK(pccd_chain_new(&c));
  OK(pccd_chain_add_link(c, -1, PCCD_JOINT_PRISMATIC, ex, zero, zero, NULL));
  OK(pccd_chain_add_link(c, 0, PCCD_JOINT_FIXED, NULL, up, zero, NULL));
  OK(pccd_body_new_mesh_d(&cube, kCubeV, 8, kCubeT, 12));
  OK(pccd_robot_new(&r, c));
  pccd_chain_free(c); /* the robot has its own copy */
  OK(pccd_robot_add_body(r, 0, 0, cube, &index));
  CHECK(index == 0);
  OK(pccd_report_new(&rep));
  OK(pccd_config_init(&cfg));
  OK(pccd_robot_options_init(&ro));
  obst[0] = cube;
  mot_near[0] = near;
  mot_far[0] = far;

  for (filter = 0; filter <= 1; ++filter) {
    g_case = filter ? "known answers, filtered" : "known answers, unfiltered";
    ro.filter = filter;
    ro.self_collision = 0;
    cfg.want_time = 1;
    OK(pccd_robot_check(r, q0, q1, 2, obst, mot_near, 1, &cfg, NULL, &ro, rep));
    OK(pccd_report_collides(rep, &collides));
    CHECK(collides == 1);
    CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "1/2"));
    CHECK(free_is(rep, "1/2", &below) && below == 0.5);
    OK(pccd_report_pair(rep, 0, &bi, &bj, &first));
    CHECK(bi == 0 && bj == 1 && first == 1);
    cfg.want_time = 0; /* decide mode: a witness, and a prefix no later than the contact */
    OK(pccd_robot_check(r, q0, q1, 2, obst, mot_near, 1, &cfg, NULL, &ro, rep));
    OK(pccd_report_collides(rep, &collides));
    CHECK(collides == 1);
    OK(pccd_report_pair_count(rep, &count));
    CHECK(count == 1);
    OK(pccd_report_free_until(rep, NULL, 0, NULL, &below));
    CHECK(below >= 0 && below <= 0.5);
    OK(pccd_robot_check(r, q0, q1, 2, obst, mot_far, 1, &cfg, NULL, &ro, rep));
    OK(pccd_report_collides(rep, &collides));
    CHECK(collides == 0);
    CHECK(free_is(rep, "1", &below) && below == 1);
  }

  g_case = "self-collision, allowed pairs";
  OK(pccd_robot_add_body(r, 1, 1, cube, &index));
  CHECK(index == 1);
  OK(pccd_robot_options_init(&ro));
  cfg.want_time = 1;
  OK(pccd_robot_check(r, q0, q1, 2, obst, mot_far, 1, &cfg, NULL, &ro, rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 1);
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "0"));
  OK(pccd_report_pair(rep, 0, &bi, &bj, &first));
  CHECK(bi == 0 && bj == 1);
  OK(pccd_report_contact_count(rep, 0, &count));
  CHECK(count == 1); /* one touching triangle pair at t = 0, not every one */
  OK(pccd_robot_set_allowed(r, both, 1));
  OK(pccd_robot_check(r, q0, q1, 2, obst, mot_far, 1, &cfg, NULL, &ro, rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 0);
  OK(pccd_robot_set_allowed(r, NULL, 0));
  ro.self_collision = 0;
  OK(pccd_robot_check(r, q0, q1, 2, obst, mot_far, 1, &cfg, NULL, &ro, rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 0);

  g_case = "errors";
  FAILS(pccd_robot_new(NULL, NULL), PCCD_EINVAL, "out: is NULL");
  FAILS(pccd_robot_add_body(r, 2, 0, cube, NULL), PCCD_EINVAL,
        "pccd_robot_add_body: link: 2 out of range (2 chain links)");
  FAILS(pccd_robot_add_body(r, 0, 0, NULL, NULL), PCCD_EINVAL, "body: is NULL");
  FAILS(pccd_robot_set_allowed(r, NULL, 1), PCCD_EINVAL, "groups: is NULL");
  FAILS(pccd_robot_check(r, q0, q1, 3, obst, NULL, 1, NULL, NULL, NULL, rep), PCCD_EINVAL,
        "n: 3 joint values given, the chain has 2 links");
  FAILS(pccd_robot_check(r, q0, q1, 2, NULL, NULL, 1, NULL, NULL, NULL, rep), PCCD_EINVAL,
        "obstacles: is NULL");
  CHECK(pccd_report_collides(rep, &collides) == PCCD_ESTATE); /* no answer after an error */
  ro.filter = 2;
  FAILS(pccd_robot_check(r, q0, q1, 2, obst, NULL, 1, NULL, NULL, &ro, rep), PCCD_EINVAL,
        "ropt.filter: 2 is not 0 or 1");
  ro.struct_size = 1;
  FAILS(pccd_robot_check(r, q0, q1, 2, obst, NULL, 1, NULL, NULL, &ro, rep), PCCD_EINVAL,
        "ropt.struct_size: 1 is not sizeof(pccd_robot_options)");
  {
    const double turn[2] = {1, 0};
    pccd_chain *rc = NULL;
    pccd_robot *rr = NULL;
    OK(pccd_chain_new(&rc));
    OK(pccd_chain_add_link(rc, -1, PCCD_JOINT_REVOLUTE, ex, zero, zero, NULL));
    OK(pccd_robot_new(&rr, rc));
    OK(pccd_robot_add_body(rr, 0, 0, cube, NULL));
    const double t0[1] = {0}, t1[1] = {7};
    FAILS(pccd_robot_check(rr, t0, t1, 1, obst, NULL, 1, NULL, NULL, NULL, rep), PCCD_EINVAL,
          "q1[0]: the revolute segment from 0 to 7 turns by 2 pi or more");
    /* One body and no obstacle: no pair, so no contact (issue 33: was an error). */
    int hit = -1;
    OK(pccd_robot_check(rr, t0, t0, 1, NULL, NULL, 0, NULL, NULL, NULL, rep));
    OK(pccd_report_collides(rep, &hit));
    CHECK(hit == 0);
    (void)turn;
    pccd_robot_free(rr);
    pccd_chain_free(rc);
  }
  FAILS(pccd_report_free_until(NULL, NULL, 0, NULL, NULL), PCCD_EINVAL, "rep: is NULL");
  filtered_equals_unfiltered(cube);
  pccd_report_free(rep);
  pccd_robot_free(r);
  pccd_robot_free(NULL);
  pccd_body_free(cube);
  pccd_motion_free(near);
  pccd_motion_free(far);
}

int main(void) { return run_in_every_mode(cases); }
