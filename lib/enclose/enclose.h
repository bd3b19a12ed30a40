// Conservative space-time enclosures of a moving body (for the broad phases: boxes,
// bvh, and the driver's per-pair bounds in scene/pair_search.cpp).
//
// Over a time piece [a, b] the rotation R(t) = Rn(t) / W(t) and the translation
// o(t) = O(t) / W(t) of a body are enclosed entrywise (Bernstein hulls of the interval
// coefficient polynomials over [a, b], then certified interval division; rotation
// entries are also clipped to [-1, 1]). A body point p then stays, for every t in
// [a, b], inside the box  R(I) p + o(I), evaluated in midpoint-radius form.
//
// The midpoint-radius evaluation runs in plain double arithmetic and is made safe by a
// derived error bound (no rounding mode is assumed): each box coordinate is a sum of at
// most 8 products; in any IEEE rounding mode each operation errs by at most 2u = 2^-52
// relative, so the accumulated error is below 20u * M, where M is the sum of the
// magnitudes of all terms, plus 2^-1074 per operation for underflow. Every box is
// widened by M * 2^-48 (> 20u M) + 1e-300, which covers both.
#pragma once
#include <array>
#include <cstdint>

#include "narrow/pair_ctx.h"

namespace pccd::enclose {

using arith::Interval;
using narrow::Moving_body;
using narrow::Prim_pair;

struct Box {
  double lo[3], hi[3];
};

inline bool boxes_meet(const Box &a, const Box &b) {  // closed boxes
  for (int i = 0; i < 3; ++i)
    if (a.hi[i] < b.lo[i] || b.hi[i] < a.lo[i]) return false;
  return true;
}
inline Box hull(const Box &a, const Box &b) {
  Box h;
  for (int i = 0; i < 3; ++i) {
    h.lo[i] = a.lo[i] < b.lo[i] ? a.lo[i] : b.lo[i];
    h.hi[i] = a.hi[i] > b.hi[i] ? a.hi[i] : b.hi[i];
  }
  return h;
}
Box grow(const Box &a, double r);  // r >= 0 (+inf allowed), outward-safe
// Whether the closed boxes may be within Euclidean distance r >= 0 (+inf allowed): false
// only when their distance, sqrt of the sum of the squared gaps per axis, is certainly
// > r. A box pair that boxes_meet(grow(a, r), b) keeps may be up to sqrt(3) r apart (a
// cube's corner); this test keeps none farther than r: a pair of features at a distance
// in (delta, sqrt(3) delta] is separated (issue 33, near misses of a robot). r = 0:
// boxes_meet.
bool boxes_within(const Box &a, const Box &b, double r);
// n . x over the boxes b[0, count): lo <= n . x <= hi for every x in them (outward
// rounding bounds in enclose.cpp; unbounded boxes give [-inf, inf]).
void project(const double n[3], const Box *b, int count, double &lo, double &hi);
// Whether the axis n (any double vector) separates the boxes a[0, na) from b[0, nb) by
// more than reach |n| (reach >= 0; 0: disjoint projections): every point of the first
// boxes is then farther than reach from every point of the second (certified
// projections; the axis's doubles decide only how often it succeeds).
bool axis_separates(const double n[3], const Box *a, int na, const Box *b, int nb, double reach);
Box empty_box();                    // hull identity

// Minimum separation (pred::Solve_options::delta, pccd_config.min_distance): the growth
// of one side's boxes, a double >= delta (delta itself when it is a double, else the
// double just above it; +inf beyond DBL_MAX, which makes every box pair meet), 0 for
// delta = 0. Coverage: if two closed features are within Euclidean distance delta at t,
// they hold points x, y with |x - y|_2 <= delta, so |x_i - y_i| <= delta on each axis
// (L_inf <= L_2): the box of x's feature grown by reach >= delta on every side meets
// the box of y's feature. Growing one side suffices (broad phases grow side A's
// boxes: box_source.h, bvh_source.h, and the driver's per-pair bounds).
double reach_of(const arith::Rational &delta);

// The motion of one body over a time piece, in midpoint-radius form, about a pivot q
// (a body-frame point, doubles): x(t) = R(t) (p - q) + o_q(t), o_q(t) = o(t) + R(t) q,
// with R(t) in Rm +- Rr and o_q(t) in om +- orad. The pivot changes no bound's
// validity, only its width: enclosing R(t) and o(t) apart forgets that a rotation about
// an axis far from the body's origin moves the origin along an arc, so each box gains
// |R(I) - R(t)| |q_axis|. enclose_pose picks q near the piece's instantaneous screw axis
// (a least-squares estimate in doubles, pulled towards the body's box centre): for a
// rotation about a fixed axis, o_q is then nearly constant.
struct Pose_piece {
  double Rm[3][3], Rr[3][3];
  double q[3] = {0, 0, 0};
  double om[3] = {0, 0, 0}, orad[3] = {0, 0, 0};
  bool finite = true;  // false when W(I) was not certainly positive: boxes are unbounded
  // Half-width the motion adds to the box of a point of the body (bounded by `reach`).
  double spread = 0;
};

Pose_piece enclose_pose(const Moving_body &b, double a, double t1);
// enclose_pose(b, 0, 1), computed once per Moving_body (Moving_body::derived) and shared
// by every pair the body is in: a robot link against several obstacles enclosed its
// degree-14 pose once per pair and per candidate source.
Pose_piece whole_pose(const Moving_body &b);

// Halving a time piece no longer shrinks the boxes once the motion's spread stops
// shrinking with the width: its floor is then the rounding slack of large coordinates or
// an enclosure's overestimate, and below it further halving only multiplies pieces. Two
// fuzz findings ran 2^24 pieces that way (corpus/bodies/multi-body/
// fuzz-spread-floor-*.json: a body 10^4 or 10^36 times larger than the other's typical
// feature, so spread <= feature size never held). Past kFloor_depth, a piece whose spread
// is above 3/4 of its parent's is final. A final piece lists every element pair whose
// boxes meet on it, so stopping earlier never loses a candidate, only adds some.
constexpr int kFloor_depth = 8;
inline bool spread_stalled(int depth, double spread, double parent_spread) {
  return depth >= kFloor_depth && spread > 0.75 * parent_spread;
}

// The box of the body-frame point p (doubles) with coordinate uncertainty e (the same
// for each coordinate) over the piece.
Box point_box(const Pose_piece &pose, const std::array<double, 3> &p, double e);
// The box of the body-frame box (centre c, half sizes h) over the piece.
Box frame_box(const Pose_piece &pose, const std::array<double, 3> &c, const std::array<double, 3> &h);

// The box of side s's primitive of the feature pair p over the piece (s = 0: p.a of
// side A, a vertex for VF, an edge for EE, a triangle or a ball otherwise; s = 1: p.b).
Box feature_box(const Moving_body &b, int s, const Prim_pair &p, const Pose_piece &pose);

}  // namespace pccd::enclose
