/*
 * fuzz_body.c -- libFuzzer harness of the bodies: pccd_body_new_mesh_d/_s,
 * pccd_body_new_spheres_d/_s (numbers from raw bytes, indices in and out of range, NULL
 * arrays, counts above PCCD_MAX_BODY_ELEMENTS) and every pccd_body_* getter, in any of
 * the four rounding modes.
 *
 * Input (fuzz_input.h for u8, number, ...):
 *   u8 head     rounding mode = head % 4; what = (head / 4) % 4: mesh_d, mesh_s,
 *               spheres_d, spheres_s; bit 4: a NULL array (the first one whose count
 *               is not 0); bit 5: a count above PCCD_MAX_BODY_ELEMENTS
 *   u8 n1, n2   mesh: nv = n1 % (FZ_MAX_ELEMENTS + 1), nt = n2 % (FZ_MAX_ELEMENTS + 1);
 *               spheres: n = n1 % (FZ_MAX_ELEMENTS + 1)
 *   numbers     mesh: nv * 3 vertex coordinates; spheres: n * 3 centre coordinates
 *               then n radii
 *   indices     mesh: nt * 3 of u8 each (>= 0xF0: a u32 follows, the raw index)
 *
 * Checks beyond fuzz_input.h's: a failed call leaves *out NULL; the edges of a mesh
 * equal the ones this harness derives from the triangles itself (every unordered pair
 * of distinct indices of a triangle side, sorted), and each edge's triangles are
 * exactly the triangles having that side, ascending; the counts agree; an index past
 * the end is rejected.
 */
#include "fuzz_input.h"

#define FZ_MAX_ELEMENTS 24

typedef struct edge {
  size_t a, b;
} edge;

static int edge_cmp(const void *x, const void *y)
{
  const edge *e = (const edge *)x, *f = (const edge *)y;
  if (e->a != f->a) return e->a < f->a ? -1 : 1;
  if (e->b != f->b) return e->b < f->b ? -1 : 1;
  return 0;
}

/* The oracle: the sorted distinct edges of the triangles (formats.md, BODY). */
static size_t derive_edges(const unsigned *tris, size_t nt, edge *out)
{
  size_t n = 0;
  for (size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      size_t a = tris[3 * t + k], b = tris[3 * t + (k + 1) % 3];
      if (a == b) continue;
      out[n].a = a < b ? a : b;
      out[n].b = a < b ? b : a;
      ++n;
    }
  qsort(out, n, sizeof *out, edge_cmp);
  size_t m = 0;
  for (size_t i = 0; i < n; ++i)
    if (m == 0 || edge_cmp(&out[m - 1], &out[i]) != 0) out[m++] = out[i];
  return m;
}

static int has_side(const unsigned *tri, edge e)
{
  for (int k = 0; k < 3; ++k) {
    size_t a = tri[k], b = tri[(k + 1) % 3];
    if ((a == e.a && b == e.b) || (a == e.b && b == e.a)) return 1;
  }
  return 0;
}

static void check_mesh(const pccd_body *b, size_t nv, const unsigned *tris, size_t nt)
{
  edge want[3 * FZ_MAX_ELEMENTS];
  size_t ne = derive_edges(tris, nt, want), n0 = 0, n1 = 0, n2 = 0, v[2], got[FZ_MAX_ELEMENTS];
  int kind = -1;
  FZ_ASSERT(FZ_RC(pccd_body_kind, b, &kind) == PCCD_OK && kind == PCCD_BODY_MESH);
  FZ_ASSERT(FZ_RC(pccd_body_counts, b, &n0, &n1, &n2) == PCCD_OK);
  FZ_ASSERT(n0 == nv && n1 == ne && n2 == nt);
  FZ_ASSERT(FZ_RC(pccd_body_counts, b, NULL, NULL, NULL) == PCCD_OK);
  for (size_t i = 0; i < ne; ++i) {
    FZ_ASSERT(FZ_RC(pccd_body_edge, b, i, v) == PCCD_OK);
    FZ_ASSERT(v[0] == want[i].a && v[1] == want[i].b);
    size_t count = 0, k = 0;
    FZ_ASSERT(FZ_RC(pccd_body_edge_triangles, b, i, NULL, 0, &count) == PCCD_ERANGE);
    FZ_ASSERT(count >= 1 && count <= nt);
    if (count > 1)
      FZ_ASSERT(FZ_RC(pccd_body_edge_triangles, b, i, got, count - 1, NULL) == PCCD_ERANGE);
    FZ_ASSERT(FZ_RC(pccd_body_edge_triangles, b, i, got, FZ_MAX_ELEMENTS, &count) == PCCD_OK);
    for (size_t t = 0; t < nt; ++t)
      if (has_side(tris + 3 * t, want[i])) {
        FZ_ASSERT(k < count && got[k] == t);
        ++k;
      }
    FZ_ASSERT(k == count);
  }
  FZ_ASSERT(FZ_RC(pccd_body_edge, b, ne, v) == PCCD_EINVAL);
  FZ_ASSERT(FZ_RC(pccd_body_edge_triangles, b, ne, got, 1, NULL) == PCCD_EINVAL);
  if (ne > 0) FZ_ASSERT(FZ_RC(pccd_body_edge, b, 0, NULL) == PCCD_EINVAL);
}

static void check_spheres(const pccd_body *b, size_t n)
{
  size_t n0 = 0, n1 = 9, n2 = 9, v[2];
  int kind = -1;
  FZ_ASSERT(FZ_RC(pccd_body_kind, b, &kind) == PCCD_OK && kind == PCCD_BODY_SPHERES);
  FZ_ASSERT(FZ_RC(pccd_body_counts, b, &n0, &n1, &n2) == PCCD_OK);
  FZ_ASSERT(n0 == n && n1 == 0 && n2 == 0);
  FZ_ASSERT(FZ_RC(pccd_body_edge, b, 0, v) == PCCD_EINVAL);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  fz_in in = {data, size, 0};
  uint8_t head = fz_u8(&in);
  int what = (head / 4) % 4, null_array = (head >> 4) & 1, too_many = (head >> 5) & 1;
  size_t n1 = fz_u8(&in) % (FZ_MAX_ELEMENTS + 1), n2 = fz_u8(&in) % (FZ_MAX_ELEMENTS + 1);
  static fz_num x[4 * FZ_MAX_ELEMENTS];
  double d[4 * FZ_MAX_ELEMENTS];
  const char *s[4 * FZ_MAX_ELEMENTS];
  unsigned tris[3 * FZ_MAX_ELEMENTS];
  size_t nnum = what < 2 ? 3 * n1 : 4 * n1;
  for (size_t i = 0; i < nnum; ++i) {
    fz_number(&in, &x[i]);
    d[i] = x[i].d;
    s[i] = x[i].text;
  }
  if (what < 2)
    for (size_t i = 0; i < 3 * n2; ++i) {
      uint8_t b = fz_u8(&in);
      tris[i] = b >= 0xF0 ? fz_u32(&in) : b;
    }
  fz_set_mode(head);
  pccd_body *b = (pccd_body *)&head; /* not NULL: a failed call must write NULL */
  int rc;
  /* A count above the limit is rejected before any array is read. */
  const size_t big = (size_t)PCCD_MAX_BODY_ELEMENTS + 1;
  if (what < 2) {
    size_t nv = too_many && !(head & 64) ? big : n1, nt = too_many && (head & 64) ? big : n2;
    const double *vd = null_array && nv > 0 ? NULL : d;
    const char *const *vs = null_array && nv > 0 ? NULL : s;
    const unsigned *ti = null_array && nv == 0 && nt > 0 ? NULL : tris;
    rc = what == 0 ? FZ_RC(pccd_body_new_mesh_d, &b, vd, nv, ti, nt)
                   : FZ_RC(pccd_body_new_mesh_s, &b, vs, nv, ti, nt);
    if (too_many) FZ_ASSERT(rc == PCCD_ELIMIT);
    if (null_array && (nv > 0 || nt > 0)) FZ_ASSERT(rc != PCCD_OK);
    /* no triangle: an error (PCCD_EINVAL, or PCCD_ELIMIT for a vertex number beyond the
     * text limits, which is read first: crashes/fuzz_body-no-triangle-long-exponent) */
    if (nt == 0) FZ_ASSERT(rc != PCCD_OK);
    if (rc == PCCD_OK) {
      for (size_t i = 0; i < 3 * nt; ++i) FZ_ASSERT(tris[i] < nv);
      check_mesh(b, nv, tris, nt);
    }
  } else {
    size_t n = too_many ? big : n1;
    const double *cd = null_array && n > 0 ? NULL : d, *rd = d + 3 * n1;
    const char *const *cs = null_array && n > 0 ? NULL : s, *const *rs = s + 3 * n1;
    rc = what == 2 ? FZ_RC(pccd_body_new_spheres_d, &b, cd, rd, n)
                   : FZ_RC(pccd_body_new_spheres_s, &b, cs, rs, n);
    if (too_many) FZ_ASSERT(rc == PCCD_ELIMIT);
    if (n == 0) FZ_ASSERT(rc != PCCD_OK);
    if (rc == PCCD_OK) check_spheres(b, n);
  }
  if (rc != PCCD_OK) FZ_ASSERT(b == NULL);
  pccd_body_free(b);
  fz_restore_mode();
  return 0;
}
