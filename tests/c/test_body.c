/*
 * test_body.c -- the body part of the C API (pccd_body_*): construction of meshes and
 * sphere sets, the derived edge list of known meshes, and every error path of that
 * section of include/polyccd.h.
 *
 * Plain C99 (built with -std=c99 -Wall -Wextra -Werror). Prints every failed check,
 * then "N passed, N failed"; exit status 0 only when nothing failed. Every handle is
 * freed (valgrind-clean). No call may change the rounding mode (house style 21).
 */
#include "polyccd.h"

#include <fenv.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

/* The closed unit tetrahedron: V - E + F = 4 - 6 + 4 = 2. Sorted edges (a < b):
 * 01 02 03 12 13 23; each edge lies on exactly the two faces containing both ends. */
static const double kTetV[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
static const unsigned int kTetT[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

static void tetrahedron(void)
{
  pccd_body *b = NULL;
  size_t nv = 0, ne = 0, nt = 0, v[2], tris[4], count = 0;
  int kind = -1;
  static const size_t want[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  /* Faces (by index) containing both ends of each edge above. */
  static const size_t want_tris[6][2] = {{0, 1}, {0, 2}, {1, 2}, {0, 3}, {1, 3}, {2, 3}};
  size_t i;
  if (!OK(pccd_body_new_mesh_d(&b, kTetV, 4, kTetT, 4))) return;
  OK(pccd_body_kind(b, &kind));
  CHECK(kind == PCCD_BODY_MESH);
  OK(pccd_body_counts(b, &nv, &ne, &nt));
  CHECK(nv == 4 && ne == 6 && nt == 4);
  CHECK((long)nv - (long)ne + (long)nt == 2);
  OK(pccd_body_counts(b, NULL, NULL, NULL));
  for (i = 0; i < 6; ++i) {
    OK(pccd_body_edge(b, i, v));
    CHECK(v[0] == want[i][0] && v[1] == want[i][1]);
    OK(pccd_body_edge_triangles(b, i, tris, 4, &count));
    CHECK(count == 2 && tris[0] == want_tris[i][0] && tris[1] == want_tris[i][1]);
  }
  /* Size query: NULL buffer -> PCCD_ERANGE with the count; short buffer untouched. */
  count = 0;
  FAILS(pccd_body_edge_triangles(b, 0, NULL, 0, &count), PCCD_ERANGE, "needed");
  CHECK(count == 2);
  tris[0] = 99;
  FAILS(pccd_body_edge_triangles(b, 0, tris, 1, NULL), PCCD_ERANGE, "needed");
  CHECK(tris[0] == 99);
  FAILS(pccd_body_edge(b, 6, v), PCCD_EINVAL, "pccd_body_edge: i: edge 6 out of range (the body has 6 edges)");
  FAILS(pccd_body_edge(b, 0, NULL), PCCD_EINVAL, "pccd_body_edge: v: is NULL");
  pccd_body_free(b);
}

static void string_mesh_and_degenerate(void)
{
  /* Exact strings; triangle (0, 0, 1) has the single edge 01, triangle (2, 2, 2) none. */
  const char *verts[9] = {"1/3", "0.1", "-7", "2.5e-7", "0", "0", "0", "0", "0"};
  const unsigned int tris[6] = {0, 0, 1, 2, 2, 2};
  pccd_body *b = NULL;
  size_t ne = 0, nt = 0, v[2], t[2], count = 0;
  if (!OK(pccd_body_new_mesh_s(&b, verts, 3, tris, 2))) return;
  OK(pccd_body_counts(b, NULL, &ne, &nt));
  CHECK(ne == 1 && nt == 2);
  OK(pccd_body_edge(b, 0, v));
  CHECK(v[0] == 0 && v[1] == 1);
  OK(pccd_body_edge_triangles(b, 0, t, 2, &count));
  CHECK(count == 1 && t[0] == 0); /* listed once although the side appears twice */
  pccd_body_free(b);
}

static void spheres(void)
{
  const double c[6] = {0, 0, 0, 1, 2, 3};
  const double r[2] = {0.5, 1e-300};
  const char *cs[3] = {"1/3", "0", "-2"};
  const char *rs[1] = {"1/7"};
  pccd_body *b = NULL;
  size_t n = 0, ne = 9, nt = 9, v[2];
  int kind = -1;
  if (OK(pccd_body_new_spheres_d(&b, c, r, 2))) {
    OK(pccd_body_kind(b, &kind));
    CHECK(kind == PCCD_BODY_SPHERES);
    OK(pccd_body_counts(b, &n, &ne, &nt));
    CHECK(n == 2 && ne == 0 && nt == 0);
    FAILS(pccd_body_edge(b, 0, v), PCCD_EINVAL, "out of range (the body has 0 edges)");
    pccd_body_free(b);
  }
  b = NULL;
  if (OK(pccd_body_new_spheres_s(&b, cs, rs, 1))) {
    OK(pccd_body_counts(b, &n, NULL, NULL));
    CHECK(n == 1);
    pccd_body_free(b);
  }
}

static void errors(void)
{
  pccd_body *b = NULL;
  double bad[12];
  const unsigned int far[3] = {0, 12, 1};
  unsigned int tri10[12] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 12, 0};
  double ten[30];
  const double c[3] = {0, 0, 0};
  const double rneg[1] = {-0.5}, rzero[1] = {0.0}, rnan[1] = {NAN};
  const char *cs[3] = {"0", "0", "0"};
  const char *rs_neg[1] = {"-1/2"}, *rs_bad[1] = {"abc"}, *rs_null[1] = {NULL};
  const char *vs_bad[3] = {"0", "1/0", "0"};
  int kind;
  size_t n;
  memset(ten, 0, sizeof ten);
  memcpy(bad, kTetV, sizeof bad);

  FAILS(pccd_body_new_mesh_d(NULL, kTetV, 4, kTetT, 4), PCCD_EINVAL, "pccd_body_new_mesh_d: out: is NULL");
  b = (pccd_body *)&n; /* *out is reset to NULL on error */
  FAILS(pccd_body_new_mesh_d(&b, kTetV, 4, kTetT, 0), PCCD_EINVAL, "triangles: a mesh needs at least one triangle");
  CHECK(b == NULL);
  FAILS(pccd_body_new_mesh_d(&b, kTetV, 4, far, 1), PCCD_EINVAL,
        "triangles[0][1]: index 12 out of range (4 vertices)");
  tri10[3 * 3 + 1] = 12; /* the example: triangles[3][1] = 12 with 10 vertices */
  FAILS(pccd_body_new_mesh_d(&b, ten, 10, tri10, 4), PCCD_EINVAL,
        "triangles[3][1]: index 12 out of range (10 vertices)");
  bad[7] = NAN;
  FAILS(pccd_body_new_mesh_d(&b, bad, 4, kTetT, 4), PCCD_EINVAL, "pccd_body_new_mesh_d: vertices[2][1]: NaN");
  bad[7] = -INFINITY;
  FAILS(pccd_body_new_mesh_d(&b, bad, 4, kTetT, 4), PCCD_EINVAL, "vertices[2][1]: infinity");
  FAILS(pccd_body_new_mesh_d(&b, NULL, 4, kTetT, 4), PCCD_EINVAL, "vertices: is NULL");
  FAILS(pccd_body_new_mesh_d(&b, kTetV, 4, NULL, 4), PCCD_EINVAL, "triangles: is NULL");
  FAILS(pccd_body_new_mesh_d(&b, kTetV, (size_t)PCCD_MAX_BODY_ELEMENTS + 1, kTetT, 4),
        PCCD_ELIMIT, "vertices");
  FAILS(pccd_body_new_mesh_d(&b, kTetV, 4, kTetT, (size_t)PCCD_MAX_BODY_ELEMENTS + 1),
        PCCD_ELIMIT, "triangles");
  FAILS(pccd_body_new_mesh_s(&b, vs_bad, 1, far, 1), PCCD_EINVAL,
        "vertices[0][1]: \"1/0\" has a zero denominator");
  FAILS(pccd_body_new_mesh_s(&b, NULL, 1, far, 1), PCCD_EINVAL, "vertices: is NULL");
  CHECK(b == NULL);

  FAILS(pccd_body_new_spheres_d(&b, c, rneg, 1), PCCD_EINVAL, "radii[0]: -1/2 is not > 0");
  FAILS(pccd_body_new_spheres_d(&b, c, rzero, 1), PCCD_EINVAL, "radii[0]: 0 is not > 0");
  FAILS(pccd_body_new_spheres_d(&b, c, rnan, 1), PCCD_EINVAL, "radii[0]: NaN");
  FAILS(pccd_body_new_spheres_d(&b, c, rneg, 0), PCCD_EINVAL, "centers: a sphere body needs at least one ball");
  FAILS(pccd_body_new_spheres_d(&b, NULL, rneg, 1), PCCD_EINVAL, "centers: is NULL");
  FAILS(pccd_body_new_spheres_d(&b, c, NULL, 1), PCCD_EINVAL, "radii: is NULL");
  FAILS(pccd_body_new_spheres_d(&b, c, rneg, (size_t)PCCD_MAX_BODY_ELEMENTS + 1), PCCD_ELIMIT,
        "spheres");
  FAILS(pccd_body_new_spheres_s(&b, cs, rs_neg, 1), PCCD_EINVAL, "radii[0]: -1/2 is not > 0");
  FAILS(pccd_body_new_spheres_s(&b, cs, rs_bad, 1), PCCD_EINVAL, "radii[0]: \"abc\"");
  FAILS(pccd_body_new_spheres_s(&b, cs, rs_null, 1), PCCD_EINVAL, "pccd_body_new_spheres_s: radii[0]: is NULL");
  CHECK(b == NULL);

  FAILS(pccd_body_kind(NULL, &kind), PCCD_EINVAL, "b: is NULL");
  FAILS(pccd_body_counts(NULL, &n, NULL, NULL), PCCD_EINVAL, "b: is NULL");
  FAILS(pccd_body_edge(NULL, 0, NULL), PCCD_EINVAL, "b: is NULL");
  FAILS(pccd_body_edge_triangles(NULL, 0, NULL, 0, NULL), PCCD_EINVAL, "b: is NULL");
  pccd_body_free(NULL); /* does nothing */
}

int main(void)
{
  tetrahedron();
  string_mesh_and_degenerate();
  spheres();
  errors();
  printf("%d passed, %d failed\n", g_pass, g_fail);
  return g_fail == 0 ? 0 : 1;
}
