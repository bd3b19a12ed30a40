#include "scene/solid_zero.h"

#include <memory>
#include <vector>

#include "arith/interval.h"
#include "motion/solid.h"

namespace pccd::scene {

namespace {

using arith::Interval;

// The points of a body tested for containment (narrow/containment.cpp keeps the same
// list to itself): a vertex of each surface component of a mesh, every ball's centre.
struct Zero_points final : narrow::Body_attachment {
  std::vector<uint32_t> ids;
};

const std::vector<uint32_t> &zero_points(const narrow::Body_data &d) {
  return d.attached<Zero_points>([&] {
           auto t = std::make_unique<Zero_points>();
           if (d.mesh) t->ids = motion::component_vertices(*d.mesh);
           else
             for (uint32_t k = 0; k < d.pts.size(); ++k) t->ids.push_back(k);
           return t;
         }).ids;
}

// Every point of Q tested is certainly outside solid S's body-frame box at the poses.
bool outside_box(const narrow::Body_data &S, const enclose::Pose_piece &ps, const narrow::Body_data &Q,
                 const enclose::Pose_piece &pq) {
  if (!ps.finite || !pq.finite) return false;
  Interval R[3][3], o[3], lo[3], hi[3];
  for (int i = 0; i < 3; ++i) {
    o[i] = Interval(ps.om[i]) + Interval(-ps.orad[i], ps.orad[i]);
    lo[i] = Interval(S.box_c[i]) - Interval(S.box_h[i]);
    hi[i] = Interval(S.box_c[i]) + Interval(S.box_h[i]);
    for (int j = 0; j < 3; ++j) R[i][j] = Interval(ps.Rm[i][j]) + Interval(-ps.Rr[i][j], ps.Rr[i][j]);
  }
  for (uint32_t k : zero_points(Q)) {
    const enclose::Box x = enclose::point_box(pq, Q.pts[k], Q.pt_err);
    Interval d[3];
    for (int i = 0; i < 3; ++i) d[i] = Interval(x.lo[i], x.hi[i]) - o[i];
    bool out = false;
    for (int j = 0; j < 3 && !out; ++j) {
      const Interval z = R[0][j] * d[0] + R[1][j] * d[1] + R[2][j] * d[2] + Interval(ps.q[j]);  // (R^T d + q)_j
      out = z.hi < lo[j].lo || z.lo > hi[j].hi;  // NaN compares false: not outside
    }
    if (!out) return false;
  }
  return true;
}

bool solid(const narrow::Body_data &d) { return d.mesh && d.mesh->solid(); }

}  // namespace

bool solids_apart_at_zero(const narrow::Body_data &A, const enclose::Pose_piece &pa, const narrow::Body_data &B,
                          const enclose::Pose_piece &pb) {
  return (!solid(A) || outside_box(A, pa, B, pb)) && (!solid(B) || outside_box(B, pb, A, pa));
}

}  // namespace pccd::scene
