// A body on its motion, prepared once per scene solve: the exact homogeneous motion
// (x(t) = (Rn(t) p + O(t)) / W(t), motion/rigid_motion.h), its interval enclosure for
// the broad phase, and per-point double data for fast conservative boxes.
#pragma once
#include <array>
#include <memory>
#include <mutex>
#include <vector>

#include "motion/body.h"
#include "motion/rigid_motion.h"

namespace pccd::broad {

using arith::Interval;
using arith::Rational;
using motion::Poly_q;

struct Stored_trees;  // broad/range_index.h

// Motion-independent data of a body, derived once per body (pccd_body keeps it).
struct Body_data {
  std::shared_ptr<const motion::Mesh_body> mesh;     // exactly one of mesh / spheres
  std::shared_ptr<const motion::Sphere_body> spheres;
  // Points: mesh vertices or ball centres. pts[k] is the nearest double of each
  // coordinate; |exact - pts| <= pt_err (an upper bound, for every coordinate).
  std::vector<std::array<double, 3>> pts;
  double pt_err = 0;
  std::vector<double> radius_up;  // radii rounded up (spheres)
  // Mesh only: the three edge indices of each triangle (edge (a, b) of mesh->edges();
  // -1 for a side with a repeated index) and the vertices used by some triangle.
  std::vector<std::array<int64_t, 3>> tri_edges;
  std::vector<uint32_t> surface_vertices;
  double reach = 0;    // upper bound of max_k |pts_k|_inf (+ radius): for the spread
  double feature = 0;  // typical feature size (median triangle box diagonal / diameter)
  std::array<double, 3> box_c{}, box_h{};  // body-frame box of all points (+ radii)
  // The range structure of this body as a stored side (lifted points in kd-trees), built
  // on first use by stored_trees() (broad/range_index.h) and kept with the body: lifted
  // points live in the body frame, so any motion and any number of queries share it.
  mutable std::once_flag trees_once;
  mutable std::shared_ptr<const Stored_trees> trees;
};

std::shared_ptr<const Body_data> make_body_data(std::shared_ptr<const motion::Mesh_body> mesh,
                                                std::shared_ptr<const motion::Sphere_body> spheres);

struct Moving_body {
  std::shared_ptr<const Body_data> data;
  std::shared_ptr<const motion::Mesh_body> mesh;     // = data->mesh, data->spheres
  std::shared_ptr<const motion::Sphere_body> spheres;
  motion::Rigid_motion motion;

  // Exact homogeneous motion.
  motion::Mat3_poly Rn;
  motion::Vec3p<Rational> O;
  Poly_q W;
  // Coefficient enclosures of the same polynomials (for time-piece bounds).
  std::array<std::array<poly::Poly<Interval>, 3>, 3> Rn_i;
  std::array<poly::Poly<Interval>, 3> O_i;
  poly::Poly<Interval> W_i;

  bool is_mesh() const { return static_cast<bool>(mesh); }
  size_t n_points() const { return data->pts.size(); }
  // The exact body-frame coordinates of point k.
  const motion::Point3_q &point(size_t k) const {
    return mesh ? mesh->vertices()[k] : spheres->centers()[k];
  }
};

// Validates the motion (Input_error when r(t) vanishes on [0, 1]) and derives the data.
Moving_body prepare_body(std::shared_ptr<const Body_data> data, const motion::Rigid_motion &m);

}  // namespace pccd::broad
