// The robot filter's containment test at t = 0 (scene/solid_start.h).
#include "scene/solid_start.h"

#include "arith/interval.h"
#include "narrow/containment.h"

namespace pccd::scene {

namespace {

using arith::Interval;

// Whether every containment point of Q is certainly outside S's solid at t = 0
// (solid_start.h: the world box of the point, through the inverse of S's pose).
bool points_outside(const narrow::Body_data &S, const enclose::Pose_piece &ps, const narrow::Body_data &Q,
                    const enclose::Pose_piece &pq) {
  if (!ps.finite || !pq.finite) return false;
  double lo[3], hi[3];  // S's body-frame box, outward
  for (int i = 0; i < 3; ++i) {
    lo[i] = arith::round_down(S.box_c[i] - S.box_h[i]);
    hi[i] = arith::round_up(S.box_c[i] + S.box_h[i]);
  }
  Interval R[3][3], O[3];
  for (int i = 0; i < 3; ++i) {
    O[i] = Interval(arith::round_down(ps.om[i] - ps.orad[i]), arith::round_up(ps.om[i] + ps.orad[i]));
    for (int j = 0; j < 3; ++j)
      R[i][j] = Interval(arith::round_down(ps.Rm[i][j] - ps.Rr[i][j]), arith::round_up(ps.Rm[i][j] + ps.Rr[i][j]));
  }
  for (uint32_t k : narrow::containment_points(Q)) {
    const enclose::Box x = enclose::point_box(pq, Q.pts[k], Q.pt_err);
    Interval d[3];
    for (int j = 0; j < 3; ++j) d[j] = Interval(x.lo[j], x.hi[j]) - O[j];
    bool outside = false;
    for (int i = 0; i < 3 && !outside; ++i) {
      Interval y = Interval(ps.q[i]);
      for (int j = 0; j < 3; ++j) y += R[j][i] * d[j];  // (R^T d)_i
      outside = y.hi < lo[i] || hi[i] < y.lo;  // false for NaN: no claim
    }
    if (!outside) return false;
  }
  return true;
}

bool solid(const narrow::Body_data &d) { return d.mesh && d.mesh->solid(); }

}  // namespace

bool solids_apart_at_zero(const Filter_side &A, const Filter_side &B) {
  if (!A.has_instant() || !B.has_instant()) return false;
  const enclose::Pose_piece &pa = A.instant(0, 0), &pb = B.instant(0, 0);
  if (solid(*A.data) && !points_outside(*A.data, pa, *B.data, pb)) return false;
  if (solid(*B.data) && !points_outside(*B.data, pb, *A.data, pa)) return false;
  return true;
}

bool contained_exactly_at_zero(const narrow::Moving_body &a, const narrow::Moving_body &b) {
  return narrow::contained_at_zero(narrow::Pair_ctx(a, b)).has_value();
}

}  // namespace pccd::scene
