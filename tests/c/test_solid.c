/*
 * test_solid.c -- solids in the C API: pccd_body_new_solid and pccd_body_solid, the
 * errors naming the first open or flipped edge, and a small box inside a big one, which
 * touches it at t = 0 (PCCD_FEATURE_SOLID with a vertex) as a solid and never as a
 * surface (docs/design.md, "Solids"). Answers known by construction: every vertex of the
 * small box [-1/2, 1/2]^3 moving by at most 1/2 stays inside [-2, 2]^3.
 *
 * Plain C99 (built with -std=c99 -Wall -Wextra -Werror). Prints every failed check, then
 * "N passed, N failed"; exit status 0 only when nothing failed. Every handle is freed.
 */
#include "polyccd.h"

#include <stdio.h>

#include "check.h"

/* A box's 12 outward triangles; corner i has the signs of the bits of i. */
static const unsigned int kBoxT[36] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                       2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};

static void box(double h, double v[24])
{
  int i;
  for (i = 0; i < 8; ++i) {
    v[3 * i] = (i & 1) ? h : -h;
    v[3 * i + 1] = (i & 2) ? h : -h;
    v[3 * i + 2] = (i & 4) ? h : -h;
  }
}

static void box_in_box(void)
{
  double big_v[24], small_v[24];
  const double from[3] = {0, 0, 0}, to[3] = {0.5, 0.25, 0};
  pccd_body *big = NULL, *solid = NULL, *small = NULL;
  pccd_motion *m = NULL;
  pccd_report *rep = NULL;
  int collides = -1, flag = -1, fi = -1, fj = -1;
  size_t n = 0, ii = 99, ij = 99;
  char t[32];
  g_case = "box_in_box";
  box(2, big_v);
  box(0.5, small_v);
  if (!OK(pccd_body_new_mesh_d(&big, big_v, 8, kBoxT, 12)) ||
      !OK(pccd_body_new_mesh_d(&small, small_v, 8, kBoxT, 12)) || !OK(pccd_body_new_solid(&solid, big)) ||
      !OK(pccd_motion_new(&m)) || !OK(pccd_motion_set_linear_translation_d(m, from, to)) ||
      !OK(pccd_report_new(&rep)))
    goto done;
  OK(pccd_body_solid(big, &flag));
  CHECK(flag == 0);
  OK(pccd_body_solid(solid, &flag));
  CHECK(flag == 1);
  /* As a surface: no contact. */
  OK(pccd_pair_solve(big, NULL, small, m, NULL, NULL, rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 0);
  /* As a solid: at t = 0 exactly, the solid with a vertex of the small box. */
  OK(pccd_pair_solve(solid, NULL, small, m, NULL, NULL, rep));
  OK(pccd_report_collides(rep, &collides));
  CHECK(collides == 1);
  if (OK(pccd_report_time(rep, PCCD_WHOLE, 0, 2, t, sizeof t, NULL))) CHECK(strcmp(t, "0") == 0);
  OK(pccd_report_contact_count(rep, 0, &n));
  CHECK(n == 1);
  OK(pccd_report_contact(rep, 0, 0, &fi, &ii, &fj, &ij));
  CHECK(fi == PCCD_FEATURE_SOLID && ii == 0 && fj == PCCD_FEATURE_VERTEX && ij < 8);
  /* The other order: the solid is body j. */
  OK(pccd_pair_solve(small, m, solid, NULL, NULL, NULL, rep));
  OK(pccd_report_contact(rep, 0, 0, &fi, &ii, &fj, &ij));
  CHECK(fi == PCCD_FEATURE_VERTEX && fj == PCCD_FEATURE_SOLID);
done:
  pccd_report_free(rep);
  pccd_motion_free(m);
  pccd_body_free(small);
  pccd_body_free(solid);
  pccd_body_free(big);
}

static void errors(void)
{
  static const double tet_v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  static const unsigned int open_t[9] = {0, 2, 1, 0, 1, 3, 0, 3, 2};
  static const unsigned int flipped_t[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 3, 2};
  static const double c[3] = {0, 0, 0}, r[1] = {1};
  pccd_body *b = NULL, *s = (pccd_body *)&b;
  int flag = 0;
  g_case = "errors";
  /* Triangle 0 = (0, 2, 1): its side 1-2 has no other triangle. */
  if (OK(pccd_body_new_mesh_d(&b, tet_v, 4, open_t, 3))) {
    FAILS(pccd_body_new_solid(&s, b), PCCD_EINVAL,
          "pccd_body_new_solid: triangles: edge (1, 2) of triangle 0 is open");
    CHECK(s == NULL);
    pccd_body_free(b);
  }
  /* Triangle 3 = (1, 3, 2) runs 2 -> 1 as triangle 0 does. */
  if (OK(pccd_body_new_mesh_d(&b, tet_v, 4, flipped_t, 4))) {
    FAILS(pccd_body_new_solid(&s, b), PCCD_EINVAL,
          "triangles: edge (1, 2) of triangle 0 runs the same way (2 -> 1) in triangles 0 and 3");
    pccd_body_free(b);
  }
  if (OK(pccd_body_new_spheres_d(&b, c, r, 1))) {
    FAILS(pccd_body_new_solid(&s, b), PCCD_EINVAL, "mesh: a sphere body is not a mesh");
    OK(pccd_body_solid(b, &flag));
    CHECK(flag == 1);
    pccd_body_free(b);
  }
  FAILS(pccd_body_new_solid(NULL, NULL), PCCD_EINVAL, "out: is NULL");
  FAILS(pccd_body_new_solid(&s, NULL), PCCD_EINVAL, "mesh: is NULL");
  FAILS(pccd_body_solid(NULL, &flag), PCCD_EINVAL, "b: is NULL");
}

int main(void)
{
  box_in_box();
  errors();
  printf("%d passed, %d failed\n", g_pass, g_fail);
  return g_fail == 0 ? 0 : 1;
}
