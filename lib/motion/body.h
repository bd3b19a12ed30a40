// Rigid bodies in body coordinates (formats.md, BODY): a triangle mesh or a set of balls,
// with exact rational coordinates. A body never changes after construction; the motion
// that moves it is separate (motion/rigid_motion.h).
//
// Mesh contract:
//  - at least one triangle; every index < the number of vertices (else Input_error
//    "triangles[3][1]: index 12 out of range (10 vertices)");
//  - degenerate triangles are ALLOWED and kept as given: repeated indices ((0, 0, 1)),
//    collinear or coincident vertices. Under the closed-set contract a triangle is the
//    closed set it spans, so nothing is dropped or perturbed;
//  - vertices need not be used by any triangle.
// The derived edge list holds every unordered pair {a, b}, a != b, that is a side of
// some triangle, once, as (a, b) with a < b, sorted lexicographically. A side whose two
// indices are equal (a repeated index) is a point, not an edge, and is not listed.
// Each edge knows its incident triangles (ascending triangle indices, each once; a
// triangle (0, 0, 1) is incident to {0, 1} once).
//
// Spheres contract: at least one ball; every radius > 0 (else Input_error
// "radii[2]: -1/2 is not > 0"). Balls may overlap or coincide.
//
// Solid (motion/solid.h): a mesh made with solid = true must be closed and consistently
// oriented (Input_error naming the first open or flipped edge); it then stands for the
// solid it bounds, not only its surface.
//
// Size: at most kMax_body_elements vertices, triangles or balls (Limit_error).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "arith/rational.h"

namespace pccd::motion {

// PCCD_MAX_BODY_ELEMENTS (polyccd.h; lib/api/constants.cpp checks that the two agree).
constexpr size_t kMax_body_elements = 50000000;

using Point3_q = std::array<arith::Rational, 3>;
using Triangle = std::array<uint32_t, 3>;
using Edge = std::array<uint32_t, 2>;  // (a, b) with a < b

// Limit_error when count > kMax_body_elements; `what` names it ("vertices").
void check_body_size(size_t count, const char *what);

class Mesh_body {
 public:
  // Validates (see the contract above) and derives the edges. Input_error / Limit_error.
  Mesh_body(std::vector<Point3_q> vertices, std::vector<Triangle> triangles, bool solid = false);

  const std::vector<Point3_q> &vertices() const { return vertices_; }
  const std::vector<Triangle> &triangles() const { return triangles_; }
  const std::vector<Edge> &edges() const { return edges_; }
  bool solid() const { return solid_; }

  // The triangles incident to edge e (e < edges().size()), ascending: a pointer to the
  // first and the count.
  const uint32_t *edge_triangles(size_t e, size_t *count) const {
    *count = edge_tri_start_[e + 1] - edge_tri_start_[e];
    return edge_tris_.data() + edge_tri_start_[e];
  }

 private:
  std::vector<Point3_q> vertices_;
  std::vector<Triangle> triangles_;
  std::vector<Edge> edges_;
  bool solid_ = false;
  // Incident triangles of edge e: edge_tris_[edge_tri_start_[e] .. edge_tri_start_[e+1]).
  std::vector<size_t> edge_tri_start_;
  std::vector<uint32_t> edge_tris_;
};

class Sphere_body {
 public:
  // centers.size() == radii.size() >= 1, every radius > 0. Input_error / Limit_error.
  Sphere_body(std::vector<Point3_q> centers, std::vector<arith::Rational> radii);

  const std::vector<Point3_q> &centers() const { return centers_; }
  const std::vector<arith::Rational> &radii() const { return radii_; }

 private:
  std::vector<Point3_q> centers_;
  std::vector<arith::Rational> radii_;
};

}  // namespace pccd::motion
