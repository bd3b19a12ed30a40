// A separating direction for two primitives that may be close but apart: the direction
// from the nearest point of one to the nearest point of the other, computed in doubles
// (issue 33). Two certified tests try it as a projection axis: the robot filter's leaf
// test (scene/link_filter.cpp, leaves_apart) and the minimum-distance axis filter of
// polynomial queries (delta_filter.h, delta_axis_separated). Both certify the
// projections themselves, so a direction made inexact by rounding only weakens a test,
// never makes it wrong; its value is a heuristic.
//
// Why it is needed: with a minimum separation delta, two primitives at distance d >
// delta are apart by d |n| on the axis n of their nearest points, but by less on the
// fixed axes (box centres, normals, cross products of edges) when the nearest points
// are a vertex and an edge, or two vertices, and a per-coordinate box test loses up to
// a factor sqrt(3). A UR5 link passing 0.052 from a plate edge with delta 0.05 stayed
// unseparated by the filter down to pieces of 2^-14 (about 60 ms a segment, solved
// exactly), and hundreds of feature pairs near a plate went to the interval stage.
#pragma once

namespace pccd::pred {

// p: the primitive's points, 1 (a point), 2 (a segment) or 3 (a triangle); np its
// count, the same for q. out: the nearest point of q minus the nearest point of p (the
// minimum over each vertex of one against the other primitive and each edge of one
// against each edge of the other: the distance of two disjoint primitives in real
// arithmetic). False when a point is not finite or the direction is zero.
bool closest_direction(const double p[][3], int np, const double q[][3], int nq, double out[3]);

}  // namespace pccd::pred
