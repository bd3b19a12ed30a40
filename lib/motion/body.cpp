// Validation and edge extraction of rigid bodies (motion/body.h).
#include "motion/body.h"

#include <algorithm>
#include <string>

#include "arith/errors.h"
#include "motion/solid.h"
#include "util/work_budget.h"

namespace pccd::motion {

void check_body_size(size_t count, const char *what) {
  if (count > kMax_body_elements)
    throw arith::Limit_error(std::string(what) + ": " + std::to_string(count) +
                             " elements exceed the limit of " +
                             std::to_string(kMax_body_elements));
}

Mesh_body::Mesh_body(std::vector<Point3_q> vertices, std::vector<Triangle> triangles, bool solid)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)), solid_(solid) {
  check_body_size(vertices_.size(), "vertices");
  check_body_size(triangles_.size(), "triangles");
  if (triangles_.empty()) throw arith::Input_error("triangles: a mesh needs at least one triangle");
  const size_t nv = vertices_.size();
  for (size_t t = 0; t < triangles_.size(); ++t)
    for (size_t k = 0; k < 3; ++k)
      if (triangles_[t][k] >= nv)
        throw arith::Input_error("triangles[" + std::to_string(t) + "][" + std::to_string(k) +
                                 "]: index " + std::to_string(triangles_[t][k]) +
                                 " out of range (" + std::to_string(nv) + " vertices)");

  // Every side (a < b) of every triangle, tagged with the triangle; sorting groups the
  // copies of one edge and orders its triangles ascending. Sides with a == b are points.
  struct Side {
    uint32_t a, b, tri;
    bool operator<(const Side &o) const {
      return a != o.a ? a < o.a : b != o.b ? b < o.b : tri < o.tri;
    }
  };
  std::vector<Side> sides;
  sides.reserve(3 * triangles_.size());
  for (size_t t = 0; t < triangles_.size(); ++t)
    for (size_t k = 0; k < 3; ++k) {
      uint32_t a = triangles_[t][k], b = triangles_[t][(k + 1) % 3];
      if (a == b) continue;
      if (a > b) std::swap(a, b);
      sides.push_back({a, b, static_cast<uint32_t>(t)});
    }
  // A work step per 4,096 sides before the sort (util/work_budget.h: a body built under
  // limits, pccd_body_new_mesh_cfg_d, ends here rather than after the sort).
  util::work_step(1 + sides.size() / 4096);
  std::sort(sides.begin(), sides.end());

  edge_tri_start_.push_back(0);
  for (size_t i = 0; i < sides.size(); ++i) {
    const Side &s = sides[i];
    const bool new_edge = i == 0 || s.a != sides[i - 1].a || s.b != sides[i - 1].b;
    if (new_edge) {
      if (i > 0) edge_tri_start_.push_back(edge_tris_.size());
      edges_.push_back({s.a, s.b});
    }
    // A triangle with a repeated index has the same side twice: list it once.
    if (new_edge || s.tri != sides[i - 1].tri) edge_tris_.push_back(s.tri);
  }
  if (!edges_.empty()) edge_tri_start_.push_back(edge_tris_.size());
  if (solid_) check_solid(*this);
}

Sphere_body::Sphere_body(std::vector<Point3_q> centers, std::vector<arith::Rational> radii)
    : centers_(std::move(centers)), radii_(std::move(radii)) {
  check_body_size(centers_.size(), "centers");
  if (centers_.size() != radii_.size())
    throw arith::Internal_error("Sphere_body: " + std::to_string(centers_.size()) +
                                " centers but " + std::to_string(radii_.size()) + " radii");
  if (centers_.empty()) throw arith::Input_error("centers: a sphere body needs at least one ball");
  for (size_t i = 0; i < radii_.size(); ++i)
    if (sgn(radii_[i]) <= 0)
      throw arith::Input_error("radii[" + std::to_string(i) + "]: " + arith::to_string(radii_[i]) +
                               " is not > 0");
}

}  // namespace pccd::motion
