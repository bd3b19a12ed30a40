/*
 * test_limits_build.c -- building under a call's limits (issue 33): a mesh body
 * (pccd_body_new_mesh_cfg_d / _s) and a step's mesh (pccd_step_add_mesh_cfg_d) end with
 * PCCD_ELIMIT at max_work = 1 on a grid of 20,000 triangles, leave *out NULL and the
 * step unchanged, and build the same thing as without limits when the limit is
 * generous or cfg is NULL. A step's solve counts the building of its trees too: a work
 * limit below the steps the trees take ends it before any pair is solved.
 *
 * Plain C99 (built with -std=c99 -Wall -Wextra -Werror). Every handle is freed.
 */
#include "polyccd.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

enum { kSide = 101, kNv = kSide * kSide, kNt = 2 * (kSide - 1) * (kSide - 1) };

/* A flat grid of kNt triangles in z = z0 (the vertices at integer x, y). */
static void grid(double *v, unsigned *t, double z0)
{
  size_t n = 0;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      v[3 * (i * kSide + j)] = i;
      v[3 * (i * kSide + j) + 1] = j;
      v[3 * (i * kSide + j) + 2] = z0;
    }
  for (int i = 0; i + 1 < kSide; ++i)
    for (int j = 0; j + 1 < kSide; ++j) {
      const unsigned a = i * kSide + j, b = a + 1, c = a + kSide, d = c + 1;
      const unsigned tri[6] = {a, b, c, b, d, c};
      memcpy(t + 3 * n, tri, sizeof tri);
      n += 2;
    }
}

static void body_under_limits(const double *v, const unsigned *t)
{
  pccd_config cfg;
  pccd_body *b = NULL, *free_b = NULL;
  size_t ne = 0, ne_free = 0;
  OK(pccd_config_init(&cfg));
  cfg.max_work = 1;
  g_case = "body: max_work = 1 ends the building";
  b = (pccd_body *)1;
  FAILS(pccd_body_new_mesh_cfg_d(&b, v, kNv, t, kNt, &cfg), PCCD_ELIMIT,
        "config.max_work: the limit of 1 work steps was reached");
  CHECK(b == NULL);
  g_case = "body: a generous limit and cfg NULL build the body of pccd_body_new_mesh_d";
  cfg.max_work = 1000000;
  OK(pccd_body_new_mesh_cfg_d(&b, v, kNv, t, kNt, &cfg));
  OK(pccd_body_new_mesh_d(&free_b, v, kNv, t, kNt));
  OK(pccd_body_counts(b, NULL, &ne, NULL));
  OK(pccd_body_counts(free_b, NULL, &ne_free, NULL));
  CHECK(ne == ne_free && ne == 3 * (kSide - 1) * (kSide - 1) + 2 * (kSide - 1));
  pccd_body_free(b);
  OK(pccd_body_new_mesh_cfg_d(&b, v, kNv, t, kNt, NULL));
  pccd_body_free(b);
  g_case = "body: the input limit names the vertex";
  cfg.max_work = 0;
  cfg.max_number_bits = 4;
  FAILS(pccd_body_new_mesh_cfg_d(&b, v, kNv, t, kNt, &cfg), PCCD_ELIMIT, "vertices[");
  CHECK(b == NULL);
  {
    const char *sv[9] = {"0", "0", "0", "1", "0", "0", "0", "1", "0"};
    const unsigned one[3] = {0, 1, 2};
    cfg.max_number_bits = PCCD_DEFAULT_MAX_NUMBER_BITS;
    cfg.max_work = 1000;
    OK(pccd_body_new_mesh_cfg_s(&b, sv, 3, one, 1, &cfg));
    pccd_body_free(b);
  }
  pccd_body_free(free_b);
}

static void step_under_limits(const double *v, const double *v1, const unsigned *t)
{
  pccd_config cfg;
  pccd_step *s = NULL;
  pccd_step_report *rep = NULL;
  pccd_step_options opt;
  size_t nm = 9, m = 9;
  int hit = -1;
  OK(pccd_config_init(&cfg));
  OK(pccd_step_new(&s));
  OK(pccd_step_report_new(&rep));
  OK(pccd_step_options_init(&opt));
  g_case = "step: max_work = 1 ends add_mesh, the step unchanged";
  cfg.max_work = 1;
  FAILS(pccd_step_add_mesh_cfg_d(s, v, v1, kNv, t, kNt, NULL, 0, NULL, 0, &m, &cfg), PCCD_ELIMIT,
        "config.max_work: the limit of 1 work steps was reached");
  FAILS(pccd_step_mesh_counts(s, 0, &nm, NULL, NULL, NULL), PCCD_EINVAL, "mesh: 0 out of range (0 meshes)");
  g_case = "step: a generous limit adds the mesh";
  cfg.max_work = 1000000;
  OK(pccd_step_add_mesh_cfg_d(s, v, v1, kNv, t, kNt, NULL, 0, NULL, 0, &m, &cfg));
  CHECK(m == 0);
  g_case = "step: the solve counts its trees (max_work = 10: no pair is solved)";
  cfg.max_work = 10;
  FAILS(pccd_step_solve(s, &cfg, &opt, rep), PCCD_ELIMIT, "config.max_work: the limit of 10 work steps");
  CHECK(strstr(pccd_last_error(), "primitive pairs solved") == NULL); /* ended in the trees */
  cfg.max_work = 0;
  OK(pccd_step_solve(s, &cfg, &opt, rep));
  OK(pccd_step_report_collides(rep, &hit));
  CHECK(hit == 0);
  pccd_step_report_free(rep);
  pccd_step_free(s);
}

static void cases(void)
{
  double *v = malloc(3 * sizeof(double) * kNv), *v1 = malloc(3 * sizeof(double) * kNv);
  unsigned *t = malloc(3 * sizeof(unsigned) * kNt);
  CHECK(v && v1 && t);
  grid(v, t, 0);
  grid(v1, t, 1);
  body_under_limits(v, t);
  step_under_limits(v, v1, t);
  free(v);
  free(v1);
  free(t);
}

int main(void) { return run_in_every_mode(cases); }
