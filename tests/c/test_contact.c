/*
 * test_contact.c -- pccd_contact_geometry_compute / _exact through the C API: cases built
 * so that the contact point and normal are known by hand (a vertex hitting a face at
 * t = 1/2, crossing edges, two balls, a ball on a triangle's face, edge and corner), the
 * report of a solve feeding the call, an enclosure over a time interval containing the
 * exact point, and each error with its place.
 */
#include "check.h"

static pccd_body *mesh(const char *const v[9])
{
  pccd_body *b = NULL;
  const unsigned tri[3] = {0, 1, 2};
  OK(pccd_body_new_mesh_s(&b, v, 3, tri, 1));
  return b;
}

static pccd_body *ball(const char *x, const char *y, const char *z, const char *r)
{
  pccd_body *b = NULL;
  const char *c[3] = {x, y, z}, *rr[1] = {r};
  OK(pccd_body_new_spheres_s(&b, c, rr, 1));
  return b;
}

/* A motion translating linearly by (dx, dy, dz) over [0, 1]. */
static pccd_motion *shift(double dx, double dy, double dz)
{
  pccd_motion *m = NULL;
  const double p0[3] = {0, 0, 0}, p1[3] = {dx, dy, dz};
  OK(pccd_motion_new(&m));
  OK(pccd_motion_set_linear_translation_d(m, p0, p1));
  return m;
}

/* The exact text (which 0: point, 1: normal) of the features at the exact time t. */
static void exact(const pccd_body *a, const pccd_motion *ma, int fa, size_t ia, const pccd_body *b,
                  const pccd_motion *mb, int fb, size_t ib, const char *t, int which, char *buf)
{
  buf[0] = 0;
  OK(pccd_contact_geometry_exact(a, ma, fa, ia, b, mb, fb, ib, t, t, which, buf, 256, NULL));
}

/* Feature kinds, short. */
enum {
  V = PCCD_FEATURE_VERTEX,
  E = PCCD_FEATURE_EDGE,
  T = PCCD_FEATURE_TRIANGLE,
  S = PCCD_FEATURE_SPHERE
};

/* Whether that text is `want`. */
static int exact_is(const pccd_body *a, const pccd_motion *ma, int fa, size_t ia,
                    const pccd_body *b, const pccd_motion *mb, int fb, size_t ib, const char *t,
                    int which, const char *want)
{
  char buf[256];
  exact(a, ma, fa, ia, b, mb, fb, ib, t, which, buf);
  return strcmp(buf, want) == 0;
}

static int encloses(const double lo[3], const double hi[3], double x, double y, double z)
{
  return lo[0] <= x && x <= hi[0] && lo[1] <= y && y <= hi[1] && lo[2] <= z && z <= hi[2];
}

static void vertex_face(void)
{
  /* Vertex (1, 1, 1) of b moves by (0, 0, -2): it meets the face z = 0 of a at t = 1/2,
   * at (1, 1, 0); the face's normal (4, 0, 0) x (0, 4, 0) = (0, 0, 16). The solve reports
   * the contact; its features and time go in. */
  const char *va[9] = {"0", "0", "0", "4", "0", "0", "0", "4", "0"};
  const char *vb[9] = {"1", "1", "1", "1", "1", "3", "2", "1", "3"};
  pccd_body *a, *b;
  pccd_motion *mb = shift(0, 0, -2);
  pccd_report *rep = NULL;
  pccd_contact_geometry g;
  int fi, fj;
  size_t ii, ij;
  char lo[64], hi[64], buf[256];
  g_case = "vertex_face";
  a = mesh(va);
  b = mesh(vb);
  OK(pccd_report_new(&rep));
  OK(pccd_pair_solve(a, NULL, b, mb, NULL, NULL, rep));
  OK(pccd_report_contact(rep, 0, 0, &fi, &ii, &fj, &ij));
  CHECK(fi == PCCD_FEATURE_TRIANGLE && fj == PCCD_FEATURE_VERTEX && ij == 0);
  OK(pccd_report_time(rep, 0, 0, 0, lo, sizeof lo, NULL));
  OK(pccd_report_time(rep, 0, 0, 1, hi, sizeof hi, NULL));
  CHECK(strcmp(lo, "1/2") == 0 && strcmp(hi, "1/2") == 0);
  memset(&g, 0, sizeof g);
  g.struct_size = sizeof g;
  OK(pccd_contact_geometry_compute(a, NULL, fi, ii, b, mb, fj, ij, lo, hi, &g));
  CHECK(g.exact == 1 && g.normal_state == PCCD_NORMAL_ENCLOSED);
  CHECK(encloses(g.point_lo, g.point_hi, 1, 1, 0));
  CHECK(encloses(g.normal_lo, g.normal_hi, 0, 0, 1));
  CHECK(exact_is(a, NULL, fi, ii, b, mb, fj, ij, lo, 0, "1 1 0"));
  CHECK(exact_is(a, NULL, fi, ii, b, mb, fj, ij, lo, 1, "0 0 16"));
  /* The same features over a time interval around 1/2: an enclosure containing the
   * point, no exact value. */
  OK(pccd_contact_geometry_compute(a, NULL, fi, ii, b, mb, fj, ij, "0.49", "0.51", &g));
  CHECK(g.exact == 0 && encloses(g.point_lo, g.point_hi, 1, 1, 0));
  CHECK(g.point_hi[2] - g.point_lo[2] <= 0x1.5p-5);  /* the vertex moves 2 * 0.02 */
  CHECK(g.normal_state == PCCD_NORMAL_ENCLOSED && encloses(g.normal_lo, g.normal_hi, 0, 0, 1));
  FAILS(pccd_contact_geometry_exact(a, NULL, fi, ii, b, mb, fj, ij, "0.49", "0.51", 0, buf, 256,
                                    NULL), PCCD_ESTATE, "not exact");
  /* At t = 1/4 the vertex is above the face: refused. */
  FAILS(pccd_contact_geometry_compute(a, NULL, fi, ii, b, mb, fj, ij, "1/4", "1/4", &g),
        PCCD_EINVAL, "do not touch at t = 1/4");
  FAILS(pccd_contact_geometry_compute(a, NULL, fi, ii, b, mb, fj, ij, "0", "1/8", &g),
        PCCD_EINVAL, "do not touch in [t_lo, t_hi]");
  pccd_report_free(rep);
  pccd_motion_free(mb);
  pccd_body_free(a);
  pccd_body_free(b);
}

static void edges(void)
{
  /* Edge 0 of a runs (-2, 1, 0) -> (2, 1, 0); edge 0 of b (1/2, -2, 1) -> (1/2, 2, 1),
   * moving by (0, 0, -2): at t = 1/2 they cross at (1/2, 1, 0); normal (4, 0, 0) x
   * (0, 4, 0) = (0, 0, 16). */
  const char *va[9] = {"-2", "1", "0", "2", "1", "0", "0", "1", "-5"};
  const char *vb[9] = {"1/2", "-2", "1", "1/2", "2", "1", "1/2", "0", "6"};
  pccd_body *a = mesh(va), *b = mesh(vb);
  pccd_motion *mb = shift(0, 0, -2);
  char buf[256];
  g_case = "edges";
  CHECK(exact_is(a, NULL, E, 0, b, mb, E, 0, "1/2", 0, "1/2 1 0"));
  CHECK(exact_is(a, NULL, E, 0, b, mb, E, 0, "1/2", 1, "0 0 16"));
  /* The triangles meet there too (edge-triangle and triangle-triangle: a point of both;
   * the edge of a crosses b's plane x = 1/2 at (1/2, 1, 0)); no normal. */
  CHECK(exact_is(a, NULL, E, 0, b, mb, T, 0, "1/2", 0, "1/2 1 0"));
  CHECK(exact_is(a, NULL, T, 0, b, mb, T, 0, "1/2", 0, "1/2 1 0"));
  FAILS(pccd_contact_geometry_exact(a, NULL, PCCD_FEATURE_TRIANGLE, 0, b, mb, PCCD_FEATURE_TRIANGLE,
                                    0, "1/2", "1/2", 1, buf, 256, NULL), PCCD_ESTATE, "no normal");
  pccd_motion_free(mb);
  pccd_body_free(a);
  pccd_body_free(b);
}

static void balls(void)
{
  /* Ball (0, 0, 0) r 1 and ball (5, 0, 0) r 2 moving by (-4, 0, 0): the centres are 3
   * apart at t = 1/2; point c_a + 1/3 (c_b - c_a) = (1, 0, 0), normal c_b - c_a. */
  pccd_body *a = ball("0", "0", "0", "1"), *b = ball("5", "0", "0", "2");
  pccd_motion *mb = shift(-4, 0, 0);
  g_case = "balls";
  CHECK(exact_is(a, NULL, S, 0, b, mb, S, 0, "1/2", 0, "1 0 0"));
  CHECK(exact_is(a, NULL, S, 0, b, mb, S, 0, "1/2", 1, "3 0 0"));
  pccd_motion_free(mb);
  pccd_body_free(a);
  pccd_body_free(b);
}

static void ball_triangle(void)
{
  /* Triangle (0,0,0), (4,0,0), (0,4,0); balls touching its face at (1, 1, 0) from
   * (1, 1, 1) r 1, its edge 0 (v0 -> v1) at (2, 0, 0) from (2, -1, 0) r 1, its corner
   * (0, 0, 0) from (-3, -4, 0) r 5. Normals from a's feature towards b's. */
  const char *vt[9] = {"0", "0", "0", "4", "0", "0", "0", "4", "0"};
  pccd_body *t = mesh(vt);
  pccd_body *face = ball("1", "1", "1", "1"), *edge = ball("2", "-1", "0", "1");
  pccd_body *corner = ball("-3", "-4", "0", "5");
  g_case = "ball_triangle";
  CHECK(exact_is(t, NULL, T, 0, face, NULL, S, 0, "0", 0, "1 1 0"));
  CHECK(exact_is(t, NULL, T, 0, face, NULL, S, 0, "0", 1, "0 0 1"));
  CHECK(exact_is(face, NULL, S, 0, t, NULL, T, 0, "0", 1, "0 0 -1"));
  CHECK(exact_is(t, NULL, T, 0, edge, NULL, S, 0, "0", 0, "2 0 0"));
  CHECK(exact_is(t, NULL, E, 0, edge, NULL, S, 0, "0", 0, "2 0 0"));
  CHECK(exact_is(t, NULL, E, 0, edge, NULL, S, 0, "0", 1, "0 -1 0"));
  CHECK(exact_is(t, NULL, T, 0, corner, NULL, S, 0, "0", 0, "0 0 0"));
  CHECK(exact_is(t, NULL, V, 0, corner, NULL, S, 0, "0", 1, "-3 -4 0"));
  pccd_body_free(t);
  pccd_body_free(face);
  pccd_body_free(edge);
  pccd_body_free(corner);
}

static void errors(void)
{
  const char *vt[9] = {"0", "0", "0", "4", "0", "0", "0", "4", "0"};
  pccd_body *t = mesh(vt), *s = ball("1", "1", "1", "1");
  pccd_motion *bad = NULL;
  pccd_contact_geometry g;
  char buf[8];
  size_t needed = 0;
  const double zero[1] = {0};
  g_case = "errors";
  memset(&g, 0, sizeof g);
  g.struct_size = sizeof g;
  {
    /* Each bad argument of mesh t against ball s, and the words its message must hold. */
    static const struct {
      int fa;
      size_t ia;
      int fb;
      size_t ib;
      const char *lo, *hi, *word;
    } bad_args[] = {
        {7, 0, S, 0, "0", "0", "feature_a: 7 is not a pccd_feature"},
        {T, 0, T, 0, "0", "0", "feature_b: triangle is not a feature of a sphere body"},
        {S, 0, S, 0, "0", "0", "feature_a: sphere is not a feature of a mesh body"},
        {V, 3, S, 0, "0", "0", "index_a: 3 out of range (3 vertices)"},
        {E, 3, S, 0, "0", "0", "index_a: 3 out of range (3 edges)"},
        {T, 0, S, 1, "0", "0", "index_b: 1 out of range (1 sphere)"},
        {T, 0, S, 0, "1/2", "1/4", "t_lo: 1/2 is above t_hi = 1/4"},
        {T, 0, S, 0, "0", "3/2", "t_hi: 3/2 is outside [0, 1]"},
        {T, 0, S, 0, "-1", "0", "t_lo: -1 is outside [0, 1]"},
        {T, 0, S, 0, "x", "0", "t_lo: "},
        {T, 0, S, 0, "0", NULL, "t_hi: is NULL"},
    };
    size_t k;
    for (k = 0; k < sizeof bad_args / sizeof bad_args[0]; ++k)
      FAILS(pccd_contact_geometry_compute(t, NULL, bad_args[k].fa, bad_args[k].ia, s, NULL,
                                          bad_args[k].fb, bad_args[k].ib, bad_args[k].lo,
                                          bad_args[k].hi, &g),
            PCCD_EINVAL, bad_args[k].word);
  }
  FAILS(pccd_contact_geometry_compute(NULL, NULL, V, 0, s, NULL, S, 0, "0", "0", &g), PCCD_EINVAL,
        "a: is NULL");
  FAILS(pccd_contact_geometry_compute(t, NULL, T, 0, s, NULL, S, 0, "0", "0", NULL), PCCD_EINVAL,
        "out: is NULL");
  g.struct_size = 3;
  FAILS(pccd_contact_geometry_compute(t, NULL, T, 0, s, NULL, S, 0, "0", "0", &g), PCCD_EINVAL,
        "out.struct_size");
  g.struct_size = sizeof g;
  /* A motion whose quaternion vanishes (r = 0): named. */
  OK(pccd_motion_new(&bad));
  OK(pccd_motion_set_rotation_d(bad, 0, zero, 1));
  FAILS(pccd_contact_geometry_compute(t, NULL, T, 0, s, bad, S, 0, "0", "0", &g), PCCD_EINVAL,
        "mb: ");
  FAILS(pccd_contact_geometry_exact(t, NULL, T, 0, s, NULL, S, 0, "0", "0", 2, buf, sizeof buf,
                                    NULL), PCCD_EINVAL, "which: 2");
  /* The buffer protocol: "1 1 0" needs 6 bytes. */
  CHECK(pccd_contact_geometry_exact(t, NULL, T, 0, s, NULL, S, 0, "0", "0", 0, buf, 3,
                                    &needed) == PCCD_ERANGE && needed == 6);
  pccd_motion_free(bad);
  pccd_body_free(t);
  pccd_body_free(s);
}

static void cases(void)
{
  vertex_face();
  edges();
  balls();
  ball_triangle();
  errors();
}

int main(void) { return run_in_every_mode(cases); }
