// A body on its motion, prepared once per scene solve: the exact homogeneous motion
// (x(t) = (Rn(t) p + O(t)) / W(t), motion/rigid_motion.h), its interval enclosure for
// the broad phase, and per-point double data for fast conservative boxes.
#pragma once
#include <array>
#include <memory>
#include <mutex>
#include <typeindex>
#include <utility>
#include <vector>

#include "motion/body.h"
#include "motion/rigid_motion.h"

namespace pccd::narrow {

using arith::Interval;
using arith::Rational;
using motion::Poly_q;

// A structure derived from a body alone that a candidate source builds on first use and
// keeps with the body for every later check (the range phase's stored trees,
// range/range_index.h): Body_data::attached<T>().
struct Body_attachment {
  virtual ~Body_attachment() = default;
};

// Structures of types derived from Body_attachment, each built on first use and then
// shared by every caller: one build per holder and type, thread-safe (a concurrent
// caller waits for the build). make() returns a std::unique_ptr<T> or
// std::shared_ptr<T>; if it throws, nothing is kept.
class Attachments {
 public:
  template <class T, class Make>
  const T &attached(Make &&make) const {
    std::lock_guard<std::mutex> lock(mu_);
    for (const auto &a : items_)
      if (a.first == std::type_index(typeid(T))) return static_cast<const T &>(*a.second);
    std::shared_ptr<const Body_attachment> built(make());
    items_.emplace_back(std::type_index(typeid(T)), built);
    return static_cast<const T &>(*built);
  }

 private:
  mutable std::mutex mu_;
  mutable std::vector<std::pair<std::type_index, std::shared_ptr<const Body_attachment>>> items_;
};

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

  // The attachment of type T, built by make() on the first call for this body and T
  // (Attachments).
  template <class T, class Make>
  const T &attached(Make &&make) const {
    return attachments_->attached<T>(std::forward<Make>(make));
  }

 private:
  // Shared by the copies of same_geometry (every attachment is derived from the points
  // and elements alone).
  std::shared_ptr<Attachments> attachments_ = std::make_shared<Attachments>();
};

std::shared_ptr<const Body_data> make_body_data(std::shared_ptr<const motion::Mesh_body> mesh,
                                                std::shared_ptr<const motion::Sphere_body> spheres);
// The data of d for mesh, a Mesh_body with d's vertices and triangles (a solid made of
// a surface: motion/solid.h): the same derived data and attachments (the hierarchy is
// not built again).
std::shared_ptr<const Body_data> same_geometry(const Body_data &d, std::shared_ptr<const motion::Mesh_body> mesh);

// The motion-dependent part of a Moving_body, derived from a valid motion alone and
// shared: a pccd_motion keeps the one of its current value (api/motion_handle.h), so a
// check that reuses a motion handle does not rebuild (or revalidate) it.
struct Motion_data {
  motion::Rigid_motion motion;
  // Exact homogeneous motion.
  motion::Mat3_poly Rn;
  motion::Vec3p<Rational> O;
  Poly_q W;
  // Coefficient enclosures of the same polynomials (for time-piece bounds).
  std::array<std::array<poly::Poly<Interval>, 3>, 3> Rn_i;
  std::array<poly::Poly<Interval>, 3> O_i;
  poly::Poly<Interval> W_i;
};

// Validates the motion (Input_error when r(t) vanishes on [0, 1]) and derives its data.
// known_valid: the caller has proven r(t) != 0 on [0, 1] (a kinematic chain's link
// motions, motion::Chain::segment_motions), and the exact test is skipped.
// Rn: rotation_numerator(m.r) when the caller has it.
std::shared_ptr<const Motion_data> prepare_motion(const motion::Rigid_motion &m,
                                                  bool known_valid = false,
                                                  const motion::Mat3_poly *Rn = nullptr);
// The data of the stationary (identity) motion: built once per process.
const std::shared_ptr<const Motion_data> &identity_motion();

struct Moving_body {
  std::shared_ptr<const Body_data> data;
  std::shared_ptr<const motion::Mesh_body> mesh;     // = data->mesh, data->spheres
  std::shared_ptr<const motion::Sphere_body> spheres;
  std::shared_ptr<const Motion_data> mo;             // never null
  // What later layers derive from the body on this motion, once for all the pairs it
  // is in (the broad phases' enclosure of its pose over [0, 1], enclose::whole_pose);
  // made by prepare_body, shared by copies (same body, same motion).
  std::shared_ptr<const Attachments> derived;

  bool is_mesh() const { return static_cast<bool>(mesh); }
  size_t n_points() const { return data->pts.size(); }
  // The exact body-frame coordinates of point k.
  const motion::Point3_q &point(size_t k) const {
    return mesh ? mesh->vertices()[k] : spheres->centers()[k];
  }
};

// A body on a prepared motion (no work that scales with the body: shared pointers only).
Moving_body prepare_body(std::shared_ptr<const Body_data> data, std::shared_ptr<const Motion_data> mo);
// Validates the motion (Input_error when r(t) vanishes on [0, 1]) and derives the data.
Moving_body prepare_body(std::shared_ptr<const Body_data> data, const motion::Rigid_motion &m);

// The query body's homogeneous motion in the stored body's frame (range/linearize.h):
// a query point p is at y(t) = (M(t) p + u(t)) / w(t) with
//   M = Rn_S^T W_S Rn_Q,   u = Rn_S^T (W_S O_Q - W_Q O_S),   w = W_S^2 W_Q,
// from the exact polynomials (Rn, O, W) or their enclosures (Rn_i, O_i, W_i).
template <class P>
struct Relative_pose {
  std::array<std::array<P, 3>, 3> M;
  std::array<P, 3> u;
  P w;
};
template <class Mat, class Vec, class P>
Relative_pose<P> relative_pose(const Mat &RnS, const Vec &OS, const P &WS, const Mat &RnQ, const Vec &OQ,
                               const P &WQ) {
  Relative_pose<P> r;
  std::array<std::array<P, 3>, 3> A;  // Rn_S^T W_S, then M = A Rn_Q
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A[i][j] = RnS[j][i] * WS;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.M[i][j] = A[i][0] * RnQ[0][j] + A[i][1] * RnQ[1][j] + A[i][2] * RnQ[2][j];
  std::array<P, 3> d;
  for (int k = 0; k < 3; ++k) d[k] = WS * OQ[k] - WQ * OS[k];
  for (int i = 0; i < 3; ++i) r.u[i] = RnS[0][i] * d[0] + RnS[1][i] * d[1] + RnS[2][i] * d[2];
  r.w = WS * WS * WQ;
  return r;
}

}  // namespace pccd::narrow
