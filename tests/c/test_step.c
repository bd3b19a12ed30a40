/*
 * test_step.c -- whole steps of deforming meshes through the C API (pccd_step_*): a
 * vertex falling through a face at t = 1/2 (its exact time, step size, contact arrays,
 * all three modes), the same particle on a parabola (pccd_step_set_paths_d: z = 1 - 4 t^2,
 * also t = 1/2), a pair check that removes it, and the error paths with their places.
 * The exhaustive comparison with brute force is tests/test_step.py.
 *
 * Plain C99 (built with -std=c99 -Wall -Wextra -Werror). Every handle is freed.
 */
#include "polyccd.h"

#include <stdio.h>
#include <string.h>

#include "check.h"

/* Mesh 0: triangle (0, 1, 2) in z = 0 and particle 3 falling from z = 1 to z = -1. */
static const double kV0[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.25, 0.25, 1};
static const double kV1[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.25, 0.25, -1};
static const unsigned kF[] = {0, 1, 2};
static const unsigned kP[] = {3};

static void cases(void)
{
  pccd_step *s = NULL;
  pccd_step_report *rep = NULL;
  pccd_step_options opt;
  char buf[32];
  size_t n = 0, index[4] = {9, 9, 9, 9}, m = 9;
  int c = -1, kind = -1, mode;
  double lo = 0, hi = 0, step = 0;
  unsigned char exact = 0;
  const unsigned bad_face[] = {0, 1, 7}, flat[] = {0, 1, 1};

  g_case = "step";
  OK(pccd_step_new(&s));
  OK(pccd_step_report_new(&rep));
  OK(pccd_step_add_mesh_d(s, kV0, kV1, 4, kF, 1, NULL, 0, kP, 1, &m));
  CHECK(m == 0);
  OK(pccd_step_options_init(&opt));
  for (mode = PCCD_STEP_FIRST; mode <= PCCD_STEP_ALL; ++mode) {
    opt.mode = mode;
    opt.threads = mode == PCCD_STEP_ALL ? 2 : 1;
    OK(pccd_step_solve(s, NULL, &opt, rep));
    OK(pccd_step_report_collides(rep, &c));
    CHECK(c == 1);
    OK(pccd_step_report_contact_count(rep, &n));
    CHECK(n == 1);
    OK(pccd_step_report_contacts(rep, 0, 1, &kind, index, &lo, &hi, &exact));
    CHECK(kind == PCCD_VERTEX_FACE && index[0] == 0 && index[1] == 3 && index[2] == 0 && index[3] == 0);
    if (mode == PCCD_STEP_DECIDE) {
      FAILS(pccd_step_report_stepsize(rep, &step), PCCD_ESTATE, "DECIDE");
      CHECK(lo != lo && exact == 0);
      continue;
    }
    CHECK(lo == 0.5 && hi == 0.5 && exact == 1);
    OK(pccd_step_report_time(rep, 2, buf, sizeof buf, NULL));
    CHECK(strcmp(buf, "1/2") == 0);
    OK(pccd_step_report_stepsize(rep, &step));
    CHECK(step == 0.5);
  }
  /* Polynomial paths: particle 3 on z = 1 - 4 t^2 meets the face at t = 1/2. */
  {
    double coef[3 * 12] = {0};
    memcpy(coef, kV0, sizeof kV0);
    coef[2 * 12 + 3 * 3 + 2] = -4;
    g_case = "step paths";
    opt.mode = PCCD_STEP_FIRST;
    opt.threads = 1;
    OK(pccd_step_set_paths_d(s, 0, coef, 3, 4));
    OK(pccd_step_solve(s, NULL, &opt, rep));
    OK(pccd_step_report_stepsize(rep, &step));
    OK(pccd_step_report_time(rep, 2, buf, sizeof buf, NULL));
    CHECK(step == 0.5 && strcmp(buf, "1/2") == 0);
    FAILS(pccd_step_set_paths_d(s, 0, coef, 9, 4), PCCD_EINVAL, "ncoeffs: 9 is outside 1..8");
    FAILS(pccd_step_set_paths_d(s, 0, coef, 0, 4), PCCD_EINVAL, "ncoeffs: 0");
    FAILS(pccd_step_set_paths_d(s, 1, coef, 3, 4), PCCD_EINVAL, "mesh: 1 out of range (1 meshes)");
    FAILS(pccd_step_set_paths_d(s, 0, NULL, 3, 4), PCCD_EINVAL, "coeffs: is NULL");
    coef[1 * 12 + 2 * 3 + 1] = coef[1 * 12 + 2 * 3 + 1] / 0.0 * 0.0;  /* NaN */
    FAILS(pccd_step_set_paths_d(s, 0, coef, 3, 4), PCCD_EINVAL, "coeffs[1][2][1]");
    /* Straight again: the first answer. */
    OK(pccd_step_set_positions_d(s, 0, kV0, kV1, 4));
    OK(pccd_step_solve(s, NULL, &opt, rep));
    OK(pccd_step_report_stepsize(rep, &step));
    CHECK(step == 0.5);
  }
  /* The particle's self pair left out: nothing touches, the step size is 1. */
  OK(pccd_step_set_pair_check(s, 0, 0, 0));
  opt.mode = PCCD_STEP_FIRST;
  OK(pccd_step_solve(s, NULL, &opt, rep));
  OK(pccd_step_report_collides(rep, &c));
  OK(pccd_step_report_stepsize(rep, &step));
  CHECK(c == 0 && step == 1.0);
  FAILS(pccd_step_report_time(rep, 0, buf, sizeof buf, NULL), PCCD_ESTATE, "no contact");

  g_case = "step errors";
  FAILS(pccd_step_add_mesh_d(s, kV0, kV1, 4, bad_face, 1, NULL, 0, NULL, 0, NULL), PCCD_EINVAL,
        "faces[0][2]: index 7 out of range (4 vertices)");
  FAILS(pccd_step_add_mesh_d(s, kV0, kV1, 4, flat, 1, NULL, 0, NULL, 0, NULL), PCCD_EINVAL,
        "faces[0]: repeats vertex 1");
  FAILS(pccd_step_add_mesh_d(s, kV0, NULL, 4, kF, 1, NULL, 0, NULL, 0, NULL), PCCD_EINVAL, "v_t1: is NULL");
  FAILS(pccd_step_set_positions_d(s, 0, kV0, kV1, 3), PCCD_EINVAL, "nv: 3 vertices given, mesh 0 has 4");
  FAILS(pccd_step_set_pair_check(s, 0, 1, 1), PCCD_EINVAL, "j: 1 out of range (1 meshes)");
  opt.threads = 0;
  FAILS(pccd_step_solve(s, NULL, &opt, rep), PCCD_EINVAL, "opt.threads");
  FAILS(pccd_step_report_collides(rep, &c), PCCD_ESTATE, "rep");
  FAILS(pccd_step_report_contacts(rep, 0, 1, NULL, NULL, NULL, NULL, NULL), PCCD_ESTATE, "rep");
  pccd_step_report_free(rep);
  pccd_step_free(s);
  pccd_step_free(NULL);
  pccd_step_report_free(NULL);
}

int main(void) { return run_in_every_mode(cases); }
