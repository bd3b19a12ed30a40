// Static contact tests at one instant (bodies that already touch or intersect at t = 0).
//
// Points are exact positions, possibly all multiplied by one common factor D > 0 (as
// the point trajectories of body queries are, see query_systems.h); every test below
// is homogeneous in point differences, and radii enter as r^2 D^2.
//
// NT = Rational decides exactly. NT = Interval is the filter: arith::sign throws
// Uncertain when an interval straddles zero, and the caller recomputes exactly.
#pragma once
#include <array>

#include "arith/convert.h"
#include "arith/interval.h"
#include "arith/rational.h"

namespace pccd::pred {

template <class NT>
using Vec3 = std::array<NT, 3>;

template <class NT>
Vec3<NT> sub(const Vec3<NT> &a, const Vec3<NT> &b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class NT>
Vec3<NT> cross3(const Vec3<NT> &a, const Vec3<NT> &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class NT>
NT dot3(const Vec3<NT> &a, const Vec3<NT> &b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The closed segment [p, q] and the closed triangle (a, b, c) share a point. Either
// triangle or segment may be degenerate. Cases (relatively open features, so the
// list is complete): an endpoint lies in the closed triangle; the open segment meets
// a closed side of the triangle; the open segment crosses the open face transversally
// (endpoints strictly on opposite sides of the plane, line strictly inside the three
// sides). A segment in the plane meeting the open face but no side has an endpoint
// inside.
template <class NT> bool point_in_triangle(const Vec3<NT> &p, const std::array<Vec3<NT>, 3> &t);
template <class NT> bool segments_meet(const Vec3<NT> &p, const Vec3<NT> &q, const Vec3<NT> &a,
                                       const Vec3<NT> &b);
template <class NT> bool segment_meets_triangle(const Vec3<NT> &p, const Vec3<NT> &q,
                                                const std::array<Vec3<NT>, 3> &t);

// Closed triangles share a point: some side of one meets the other closed triangle
// (the intersection of two convex sets has its extreme points on their boundaries).
template <class NT> bool triangles_meet(const std::array<Vec3<NT>, 3> &a,
                                        const std::array<Vec3<NT>, 3> &b);

// The closed ball (c, radius with r2d2 = r^2 D^2) meets the closed triangle: a vertex
// inside the ball, or an open edge / the open face within distance r with the
// projection of c strictly inside it (the closest point of a triangle lies in exactly
// one relatively open feature).
template <class NT> bool ball_meets_triangle(const Vec3<NT> &c, const NT &r2d2,
                                             const std::array<Vec3<NT>, 3> &t);

// The closed ball (c, r2d2 as above) meets the closed segment [a, b]: an end inside
// the ball, or the open segment within distance r with the projection of c strictly
// inside it. The same answer as ball_meets_triangle(c, r2d2, {a, b, b}) (whose
// degenerate side b - b and normal are exact zeros only in rationals: with intervals
// they straddle zero, so that filter never decided and every such test was exact).
template <class NT> bool ball_meets_segment(const Vec3<NT> &c, const NT &r2d2, const Vec3<NT> &a,
                                            const Vec3<NT> &b);

// The closed segments [p, q] and [a, b] are within distance r (r2d2 = r^2 D^2): an
// endpoint's ball meets the other closed segment, or the lines' closest points lie
// strictly inside both segments at distance <= r (delta_systems.h: the closest pair
// lies in relatively open features).
template <class NT> bool segments_within(const Vec3<NT> &p, const Vec3<NT> &q, const Vec3<NT> &a,
                                         const Vec3<NT> &b, const NT &r2d2);

extern template bool triangles_meet(const std::array<Vec3<arith::Rational>, 3> &,
                                    const std::array<Vec3<arith::Rational>, 3> &);
extern template bool triangles_meet(const std::array<Vec3<arith::Interval>, 3> &,
                                    const std::array<Vec3<arith::Interval>, 3> &);
extern template bool segment_meets_triangle(const Vec3<arith::Rational> &, const Vec3<arith::Rational> &,
                                            const std::array<Vec3<arith::Rational>, 3> &);
extern template bool segment_meets_triangle(const Vec3<arith::Interval> &, const Vec3<arith::Interval> &,
                                            const std::array<Vec3<arith::Interval>, 3> &);
extern template bool ball_meets_triangle(const Vec3<arith::Rational> &, const arith::Rational &,
                                         const std::array<Vec3<arith::Rational>, 3> &);
extern template bool ball_meets_triangle(const Vec3<arith::Interval> &, const arith::Interval &,
                                         const std::array<Vec3<arith::Interval>, 3> &);
extern template bool ball_meets_segment(const Vec3<arith::Rational> &, const arith::Rational &,
                                        const Vec3<arith::Rational> &, const Vec3<arith::Rational> &);
extern template bool ball_meets_segment(const Vec3<arith::Interval> &, const arith::Interval &,
                                        const Vec3<arith::Interval> &, const Vec3<arith::Interval> &);
extern template bool segments_within(const Vec3<arith::Rational> &, const Vec3<arith::Rational> &,
                                     const Vec3<arith::Rational> &, const Vec3<arith::Rational> &,
                                     const arith::Rational &);
extern template bool segments_within(const Vec3<arith::Interval> &, const Vec3<arith::Interval> &,
                                     const Vec3<arith::Interval> &, const Vec3<arith::Interval> &,
                                     const arith::Interval &);

}  // namespace pccd::pred
