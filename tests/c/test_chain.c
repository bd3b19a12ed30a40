/*
 * test_chain.c -- the kinematic-chain part of the C API (pccd_chain_*): a small chain
 * whose link positions are known by construction, the joint values, and every error
 * path of that section of include/polyccd.h. Plain C99; every handle is freed.
 */
#include "polyccd.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

#include "motion_check.h"


/* Link 0: prismatic along (0, 0, 2) (|axis| = 2 exactly, so q moves by q along z), origin
 *         (1, 0, 0), q 0 -> 1: its origin is at (1, 0, t).
 * Link 1: revolute about z under link 0, q 0 -> 0 (no turn): a point (1, 0, 0) of it is
 *         at (2, 0, t).
 * Link 2: fixed under link 1 at (0, 1, 0): its origin at (1, 1, t).
 * Joint values at t = 1/2: 1/2 (prismatic), 0, 0. */
static void cases(void)
{
  pccd_chain *c = NULL;
  pccd_motion *m[3] = {NULL, NULL, NULL};
  const double z2[3] = {0, 0, 2}, ez[3] = {0, 0, 1}, zero[3] = {0, 0, 0}, ex[3] = {1, 0, 0};
  const double ey[3] = {0, 1, 0}, bad[3] = {0, NAN, 0};
  const double q0[3] = {0, 0, 0}, q1[3] = {1, 0, 0}, full[3] = {0, 7, 0};
  double v[3] = {9, 9, 9};
  size_t index = 99, n = 0;
  int k;

  g_case = "known answers";
  OK(pccd_chain_new(&c));
  OK(pccd_chain_add_link(c, -1, PCCD_JOINT_PRISMATIC, z2, ex, zero, &index));
  CHECK(index == 0);
  OK(pccd_chain_add_link(c, 0, PCCD_JOINT_REVOLUTE, ez, zero, zero, &index));
  CHECK(index == 1);
  OK(pccd_chain_add_link(c, 1, PCCD_JOINT_FIXED, NULL, ey, zero, NULL));
  OK(pccd_chain_size(c, &n));
  CHECK(n == 3);
  OK(pccd_chain_segment_motions(c, q0, q1, 3, m));
  CHECK(position_is(m[0], "0", "0", "0", "1/2", "1 0 1/2"));
  CHECK(position_is(m[1], "1", "0", "0", "1/3", "2 0 1/3"));
  CHECK(position_is(m[2], "0", "0", "0", "1", "1 1 1"));
  OK(pccd_chain_joint_values_s(c, q0, q1, 3, "1/2", v));
  CHECK(v[0] == 0.5 && v[1] == 0 && v[2] == 0);
  for (k = 0; k < 3; ++k) pccd_motion_free(m[k]);

  g_case = "limits";
  {
    pccd_config cfg;
    OK(pccd_config_init(&cfg));
    cfg.max_work = 1000000;
    OK(pccd_chain_segment_motions_cfg(c, q0, q1, 3, &cfg, m)); /* within them: the same */
    CHECK(position_is(m[1], "1", "0", "0", "1/3", "2 0 1/3"));
    for (k = 0; k < 3; ++k) pccd_motion_free(m[k]);
    OK(pccd_chain_segment_motions_cfg(c, q0, q1, 3, NULL, m));
    CHECK(position_is(m[2], "0", "0", "0", "1", "1 1 1"));
    for (k = 0; k < 3; ++k) pccd_motion_free(m[k]);
    cfg.max_number_bits = 1; /* every number has 2 bits or more */
    FAILS(pccd_chain_segment_motions_cfg(c, q0, q1, 3, &cfg, m), PCCD_ELIMIT,
          "pccd_chain_segment_motions_cfg: motions[0].");
    CHECK(m[0] == NULL && m[1] == NULL && m[2] == NULL);
    cfg.struct_size = 3;
    FAILS(pccd_chain_segment_motions_cfg(c, q0, q1, 3, &cfg, m), PCCD_EINVAL,
          "pccd_chain_segment_motions_cfg: config");
  }

  g_case = "errors";
  FAILS(pccd_chain_new(NULL), PCCD_EINVAL, "pccd_chain_new: out: is NULL");
  FAILS(pccd_chain_add_link(NULL, -1, 0, NULL, zero, zero, NULL), PCCD_EINVAL, "c: is NULL");
  FAILS(pccd_chain_add_link(c, 3, 0, NULL, zero, zero, NULL), PCCD_EINVAL,
        "pccd_chain_add_link: parent: 3 is not -1 (the world) or an earlier link (0..2)");
  FAILS(pccd_chain_add_link(c, -2, 0, NULL, zero, zero, NULL), PCCD_EINVAL, "parent: -2");
  FAILS(pccd_chain_add_link(c, 0, 4, ez, zero, zero, NULL), PCCD_EINVAL, "joint: 4 is not a pccd_joint_type");
  FAILS(pccd_chain_add_link(c, 0, PCCD_JOINT_REVOLUTE, NULL, zero, zero, NULL), PCCD_EINVAL, "axis: is NULL");
  FAILS(pccd_chain_add_link(c, 0, PCCD_JOINT_PRISMATIC, zero, zero, zero, NULL), PCCD_EINVAL,
        "axis: the direction is the zero vector");
  FAILS(pccd_chain_add_link(c, 0, PCCD_JOINT_CONTINUOUS, bad, zero, zero, NULL), PCCD_EINVAL, "axis[1]: NaN");
  FAILS(pccd_chain_add_link(c, 0, PCCD_JOINT_FIXED, NULL, bad, zero, NULL), PCCD_EINVAL, "xyz[1]: NaN");
  FAILS(pccd_chain_add_link(c, 0, PCCD_JOINT_FIXED, NULL, zero, bad, NULL), PCCD_EINVAL, "rpy[1]: NaN");
  FAILS(pccd_chain_add_link(c, 0, PCCD_JOINT_FIXED, NULL, NULL, zero, NULL), PCCD_EINVAL, "xyz: is NULL");
  OK(pccd_chain_size(c, &n));
  CHECK(n == 3); /* unchanged by the failed calls */
  FAILS(pccd_chain_size(c, NULL), PCCD_EINVAL, "n: is NULL");
  m[0] = m[1] = m[2] = (pccd_motion *)c; /* must be reset to NULL on error */
  FAILS(pccd_chain_segment_motions(c, q0, full, 3, m), PCCD_EINVAL,
        "pccd_chain_segment_motions: q1[1]: the revolute segment from 0 to 7 turns by 2 pi or more");
  CHECK(m[0] == NULL && m[1] == NULL && m[2] == NULL);
  FAILS(pccd_chain_segment_motions(c, q0, q1, 2, m), PCCD_EINVAL, "n: 2 joint values given, the chain has 3 links");
  FAILS(pccd_chain_segment_motions(c, NULL, q1, 3, m), PCCD_EINVAL, "q0: is NULL");
  FAILS(pccd_chain_segment_motions(c, q0, q1, 3, NULL), PCCD_EINVAL, "motions: is NULL");
  {
    const double nan1[3] = {NAN, 0, 0};
    FAILS(pccd_chain_segment_motions(c, nan1, q1, 3, m), PCCD_EINVAL, "q0[0]: NaN");
  }
  FAILS(pccd_chain_joint_values_s(c, q0, q1, 3, "3/2", v), PCCD_EINVAL, "t: 3/2 is outside [0, 1]");
  FAILS(pccd_chain_joint_values_s(c, q0, q1, 3, "x", v), PCCD_EINVAL, "pccd_chain_joint_values_s: t: ");
  FAILS(pccd_chain_joint_values_s(c, q0, q1, 3, NULL, v), PCCD_EINVAL, "t: is NULL");
  pccd_chain_free(c);
  pccd_chain_free(NULL);
}

int main(void) { return run_in_every_mode(cases); }
