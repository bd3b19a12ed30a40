/*
 * test_robot_many.c -- robot batches (pccd_robot_check_many, pccd_robot_check_states)
 * on a chain whose answers are known by construction: every entry equals the
 * one-segment pccd_robot_check (with one and two threads, with reports), a bad segment
 * keeps its status and message at its index while the others are answered, the call
 * without a status array fails at the first bad segment, the work limits and a set
 * cancel flag end the whole batch with nothing readable, and the argument errors.
 * Plain C99; every handle is freed.
 */
#include "polyccd.h"

#include <math.h>
#include <string.h>

#include "check.h"
#include "scene_fixtures.h"

/* One link, prismatic along x, carrying the unit cube [0, 1]^3; the obstacle: the unit
 * cube at x = 3/2. Segment q0 -> q1 touches it exactly when max(q0, q1) >= 1/2, first
 * at t = (1/2 - q0) / (q1 - q0) when q0 < 1/2 (at 0 when q0 >= 1/2). */
enum { N = 6 };
static const double Q0[N] = {0, 0, 0.75, 0, -1, 0};
static const double Q1[N] = {1, 0.25, 1, 0.5, 0, 2};
static const int HIT[N] = {1, 0, 1, 1, 0, 1};
static const double FIRST[N] = {0.5, NAN, 0, 1, NAN, 0.25};

static void batch_out(pccd_robot_batch_out *o, int *status, char *msgs, size_t cap,
                      unsigned char *coll, double *lo, double *hi, double *fu)
{
  memset(o, 0, sizeof *o);
  o->struct_size = sizeof *o;
  o->status = status;
  o->messages = msgs;
  o->message_cap = cap;
  o->collides = coll;
  o->lo = lo;
  o->hi = hi;
  o->free_until = fu;
}

static void cases(void)
{
  pccd_chain *c = NULL;
  pccd_robot *r = NULL;
  pccd_body *cube = NULL;
  pccd_report *one = NULL, *reps[N] = {NULL};
  pccd_motion *near = slide_x(1.5, 1.5);
  pccd_cancel *cancel = NULL;
  pccd_config cfg;
  pccd_scene_options so;
  pccd_robot_batch_out out;
  const double ex[3] = {1, 0, 0}, zero[3] = {0, 0, 0};
  const pccd_body *obst[1];
  const pccd_motion *mot[1];
  int status[N], hit = -1, k, mode, threads;
  char msgs[N][160];
  unsigned char coll[N];
  double lo[N], hi[N], fu[N], below = -1;

  CHECK(near != NULL);
  OK(pccd_chain_new(&c));
  OK(pccd_chain_add_link(c, -1, PCCD_JOINT_PRISMATIC, ex, zero, zero, NULL));
  OK(pccd_body_new_mesh_d(&cube, kCubeV, 8, kCubeT, 12));
  OK(pccd_robot_new(&r, c));
  OK(pccd_robot_add_body(r, 0, 0, cube, NULL));
  OK(pccd_report_new(&one));
  for (k = 0; k < N; ++k) OK(pccd_report_new(&reps[k]));
  OK(pccd_config_init(&cfg));
  OK(pccd_scene_options_init(&so));
  obst[0] = cube;
  mot[0] = near;

  for (mode = 0; mode <= 1; ++mode)
    for (threads = 1; threads <= 2; ++threads) {
      g_case = mode ? "entries equal one-by-one checks, first contact" : "entries equal one-by-one checks, decide";
      cfg.want_time = mode;
      so.threads = (unsigned)threads;
      batch_out(&out, status, &msgs[0][0], sizeof msgs[0], coll, lo, hi, fu);
      out.reports = reps;
      OK(pccd_robot_check_many(r, Q0, Q1, N, 1, obst, mot, 1, &cfg, &so, NULL, &out));
      for (k = 0; k < N; ++k) {
        CHECK(status[k] == PCCD_OK && msgs[k][0] == '\0');
        CHECK(coll[k] == HIT[k]);
        OK(pccd_robot_check(r, &Q0[k], &Q1[k], 1, obst, mot, 1, &cfg, NULL, NULL, one));
        OK(pccd_report_collides(one, &hit));
        CHECK(hit == HIT[k]);
        OK(pccd_report_collides(reps[k], &hit));
        CHECK(hit == HIT[k]);
        OK(pccd_report_free_until(one, NULL, 0, NULL, &below));
        CHECK(fu[k] == below);
        if (HIT[k] && mode == 1)
          CHECK(lo[k] <= FIRST[k] && FIRST[k] <= hi[k] && hi[k] - lo[k] < 1e-9);
        if (HIT[k])
          CHECK(lo[k] <= hi[k] && lo[k] >= 0 && hi[k] <= 1);
        else
          CHECK(isnan(lo[k]) && isnan(hi[k]) && fu[k] == 1);
      }
    }

  g_case = "states: the zero-length segments";
  {
    const double q[3] = {0, 0.5, 0.25};
    batch_out(&out, status, &msgs[0][0], sizeof msgs[0], coll, lo, hi, fu);
    OK(pccd_robot_check_states(r, q, 3, 1, obst, mot, 1, NULL, NULL, NULL, &out));
    CHECK(status[0] == PCCD_OK && status[1] == PCCD_OK && status[2] == PCCD_OK);
    CHECK(coll[0] == 0 && coll[1] == 1 && coll[2] == 0); /* the cubes touch at q = 1/2 */
  }

  g_case = "a bad segment keeps its index, the others are answered";
  {
    const double b0[3] = {0, NAN, 0}, b1[3] = {1, 1, 0.25};
    batch_out(&out, status, &msgs[0][0], sizeof msgs[0], coll, lo, hi, fu);
    OK(pccd_robot_check_many(r, b0, b1, 3, 1, obst, mot, 1, NULL, NULL, NULL, &out));
    CHECK(status[0] == PCCD_OK && coll[0] == 1);
    CHECK(status[1] == PCCD_EINVAL && coll[1] == 0 && isnan(fu[1]));
    CHECK(strstr(msgs[1], "pccd_robot_check_many: segments[1]: q0[0]") == msgs[1]);
    CHECK(status[2] == PCCD_OK && coll[2] == 0 && msgs[2][0] == '\0');
    batch_out(&out, NULL, NULL, 0, coll, NULL, NULL, NULL);
    FAILS(pccd_robot_check_many(r, b0, b1, 3, 1, obst, mot, 1, NULL, NULL, NULL, &out), PCCD_EINVAL,
          "segments[1]: q0[0]");
    CHECK(coll[0] == 1 && coll[2] == 0); /* written before the call failed */
    batch_out(&out, status, &msgs[0][0], 8, coll, lo, hi, fu);
    OK(pccd_robot_check_states(r, b0, 3, 1, obst, mot, 1, NULL, NULL, NULL, &out));
    CHECK(status[1] == PCCD_EINVAL && strlen(&msgs[0][0] + 8) == 7); /* cut to message_cap - 1 */
    CHECK(strncmp(&msgs[0][0] + 8, "pccd_ro", 7) == 0 && msgs[0][0] == '\0');
  }

  g_case = "limits end the whole batch";
  batch_out(&out, status, &msgs[0][0], sizeof msgs[0], coll, lo, hi, fu);
  out.reports = reps;
  cfg.want_time = 1;
  cfg.max_work = 1;
  FAILS(pccd_robot_check_many(r, Q0, Q1, N, 1, obst, mot, 1, &cfg, NULL, NULL, &out), PCCD_ELIMIT,
        "config.max_work");
  for (k = 0; k < N; ++k) {
    CHECK(status[k] == PCCD_ESTATE && coll[k] == 0 && isnan(fu[k]));
    CHECK(pccd_report_collides(reps[k], &hit) == PCCD_ESTATE);
  }
  cfg.max_work = 0;
  OK(pccd_cancel_new(&cancel));
  OK(pccd_cancel_set(cancel));
  cfg.cancel = cancel;
  so.threads = 2;
  FAILS(pccd_robot_check_many(r, Q0, Q1, N, 1, obst, mot, 1, &cfg, &so, NULL, &out), PCCD_ELIMIT,
        "config.cancel");
  FAILS(pccd_robot_check_states(r, Q0, N, 1, obst, mot, 1, &cfg, &so, NULL, &out), PCCD_ELIMIT,
        "config.cancel");
  cfg.cancel = NULL;

  g_case = "argument errors";
  batch_out(&out, status, &msgs[0][0], sizeof msgs[0], coll, lo, hi, fu);
  FAILS(pccd_robot_check_many(NULL, Q0, Q1, N, 1, obst, mot, 1, NULL, NULL, NULL, &out), PCCD_EINVAL,
        "r: is NULL");
  FAILS(pccd_robot_check_many(r, Q0, Q1, N, 1, obst, mot, 1, NULL, NULL, NULL, NULL), PCCD_EINVAL,
        "out: is NULL");
  FAILS(pccd_robot_check_many(r, Q0, Q1, N, 2, obst, mot, 1, NULL, NULL, NULL, &out), PCCD_EINVAL,
        "n: 2 joint values given, the chain has 1 links");
  FAILS(pccd_robot_check_many(r, NULL, Q1, N, 1, obst, mot, 1, NULL, NULL, NULL, &out), PCCD_EINVAL,
        "q0: is NULL");
  FAILS(pccd_robot_check_states(r, Q0, N, 1, NULL, NULL, 1, NULL, NULL, NULL, &out), PCCD_EINVAL,
        "obstacles: is NULL");
  out.message_cap = 0;
  FAILS(pccd_robot_check_many(r, Q0, Q1, N, 1, obst, mot, 1, NULL, NULL, NULL, &out), PCCD_EINVAL,
        "out.message_cap: is 0");
  out.struct_size = 3;
  FAILS(pccd_robot_check_many(r, Q0, Q1, N, 1, obst, mot, 1, NULL, NULL, NULL, &out), PCCD_EINVAL,
        "out.struct_size: 3");
  batch_out(&out, status, NULL, 0, coll, NULL, NULL, NULL);
  OK(pccd_robot_check_many(r, NULL, NULL, 0, 1, obst, mot, 1, NULL, NULL, NULL, &out)); /* nothing */

  for (k = 0; k < N; ++k) pccd_report_free(reps[k]);
  pccd_report_free(one);
  pccd_cancel_free(cancel);
  pccd_robot_free(r);
  pccd_chain_free(c);
  pccd_body_free(cube);
  pccd_motion_free(near);
}

int main(void) { return run_in_every_mode(cases); }
