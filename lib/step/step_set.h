// The meshes of one simulator step: vertices each on its own straight trajectory from
// its position at t = 0 to its position at t = 1 (doubles taken at their exact values),
// with triangles, edges and isolated points over them.
//
// The meshes are stored flat: one global vertex array for all of them, and faces,
// edges and points holding global vertex indices, each tagged with its mesh, so the
// broad phase (tree.h) and the driver (step.h) see one set of primitives. A mesh's own
// index of a vertex, face, edge or point is its global index minus the mesh's first.
//
// Primitives and the pairs a step checks (step.h):
//   - every vertex used by a face, an edge or a point, against every face not holding
//     it (VERTEX_FACE),
//   - every edge against every edge with no common vertex (EDGE_EDGE),
//   - every isolated point against every edge not ending at it (VERTEX_EDGE) and every
//     other point (VERTEX_VERTEX),
// within a mesh when its self-collision is checked and between two meshes when that
// mesh pair is checked (both by default). For closed triangles these pairs are
// exactly the ones whose first contact can be the first contact of two faces that
// share no vertex; pairs sharing a vertex touch from the start and are left out, as
// every simulator's CCD does.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pccd::step {

struct Mesh_range {
  uint32_t v0 = 0, nv = 0, f0 = 0, nf = 0, e0 = 0, ne = 0, p0 = 0, np = 0;
};

struct Step_set {
  std::vector<double> x0, x1;                  // 3 per vertex: positions at t = 0 and 1
  std::vector<uint32_t> vmesh;                 // mesh of each vertex
  std::vector<std::array<uint32_t, 3>> faces;  // global vertex indices
  std::vector<std::array<uint32_t, 2>> edges;  // a < b
  std::vector<uint32_t> points;                // isolated points (vertices)
  std::vector<uint32_t> fmesh, emesh, pmesh;   // mesh of each face, edge, point
  std::vector<uint32_t> used;                  // vertices of some face, edge or point
  std::vector<Mesh_range> meshes;
  std::vector<uint8_t> skip;                   // skip[i * n + j]: pair (i, j) unchecked
  // Polynomial paths (set_paths): mesh m's vertex i (its own index) at t is
  // sum_k coef[m][(k * nv + i) * 3 + a] t^k, ncoef[m] coefficients (power basis, doubles
  // at their exact values); ncoef[m] == 0: straight paths x0 -> x1. For a mesh with
  // paths, x0 holds x(0) and x1 x(1) rounded to doubles (the broad phase's frame only).
  std::vector<uint32_t> ncoef;
  std::vector<std::vector<double>> coef;
  bool has_paths() const {
    for (uint32_t n : ncoef)
      if (n) return true;
    return false;
  }

  bool checked(uint32_t i, uint32_t j) const { return !skip[size_t(i) * meshes.size() + j]; }
};

// Appends a mesh (nv vertices x0, x1 of 3 doubles each; nf faces of 3 indices; edges:
// nullptr derives them from the faces, every side {a, b} once, a < b, sorted; else ne
// given edges, each stored as (min, max), duplicates kept once; np isolated points).
// Input_error naming the place: a non-finite coordinate ("v_t0[4][2]"), an index out
// of range ("faces[3][1]: index 12 out of range (10 vertices)"), a degenerate face or
// edge ("faces[3]: repeats vertex 5 (a degenerate face)"). Limit_error above
// motion::kMax_body_elements of any kind. The set is unchanged on error. Returns the
// mesh's index.
size_t add_mesh(Step_set &s, const double *x0, const double *x1, size_t nv,
                const unsigned *faces, size_t nf, const unsigned *edges, size_t ne,
                const unsigned *points, size_t np);

// Replaces the positions of mesh m (nv must be its vertex count), checked as add_mesh.
void set_positions(Step_set &s, size_t m, const double *x0, const double *x1, size_t nv);

// Gives mesh m polynomial paths: coef holds ncoef coefficients of its nv vertices
// (layout of Step_set::coef, (ncoef, nv, 3)), 1 <= ncoef <= kMax_path_coefficients.
// Input_error naming the place ("coeffs[2][4][1]: NaN ...", "ncoeffs", "nv", "mesh");
// the set is unchanged on error. set_positions makes the paths straight again.
constexpr size_t kMax_path_coefficients = 8;
void set_paths(Step_set &s, size_t m, const double *coef, size_t ncoef, size_t nv);

// Sets whether the mesh pair (i, j) is checked (i == j: self-collision of mesh i).
void set_pair_check(Step_set &s, size_t i, size_t j, bool check);

}  // namespace pccd::step
