// The certified filter of a minimum distance delta > 0 for points moving linearly: one
// fixed direction d that keeps the two primitives more than delta apart over [0, 1].
//
// Why it is sound: for a fixed d, g(t) = d . (a(t) - b(t)) is linear in t when the points
// a and b move linearly, so g > delta |d| at t = 0 and at t = 1, for every point a of
// one primitive and b of the other, holds on all of [0, 1]. Then the projections onto d
// of the two closed convex hulls are more than delta |d| apart, so are the hulls by more
// than delta, at every time: no contact within delta. Any d is valid. The candidates
// (the axes; vertex-face: the face normal and its in-plane edge normals; edge-edge: the
// common normal and the in-plane normals of each edge, also in the plane of edge a and
// b's start for nearly parallel edges; vertex-edge: the perpendicular from the vertex to
// the line; vertex-vertex: the difference; each at t = 0 and t = 1) are scored in plain
// doubles (the approximate gap), in this order, and the first clear of delta (the axes
// first) is certified with outward rounding (arith/interval.h): the point differences
// at both ends as intervals from the enclosures c0 and c0 + c1 of the endpoints, g's
// lower bound over them with every product and sum stepped one ulp down (valid in any
// rounding mode), its least value L over the pairs, then L > 0 and L * L > delta^2
// (d . d) with the left side rounded down and the right side up. A derived bound, no
// tolerance.
//
// Same decision on every path: the filter reads only the points' coefficient
// enclosures (x(t) = c0 + c1 t, Linear_points) and delta's enclosure. The single call
// and the batch (solve_linear.h) build them from the doubles exactly as the staged
// solver's interval query holds them (linear_points_from), the staged solver reads them
// from that query (linear_points_of; pccd_query_solve gets there with the exact
// coefficients, whose enclosures are the same doubles: c1 = x1 - x0 enclosed tightly by
// both point_sum and arith::enclose), so a query is decided and staged alike whichever
// entry point asks it. The stage reported is STAGE_BOUNDS (a space-time bound: a plane
// between the primitives' swept hulls).
#pragma once
#include <cstddef>

#include "pred/query_systems.h"

namespace pccd::pred {

// Up to 4 points moving linearly: coordinate a of point i is c0[i][a] + c1[i][a] t.
struct Linear_points {
  int n = 0;
  arith::Interval c0[4][3], c1[4][3];
};

// The coefficients of the interval query q when it is a plain linear query of a point
// kind (no scale, no own trajectories, every coordinate of degree <= 1); false otherwise.
bool linear_points_of(const Query_data<arith::Interval> &q, Linear_points &out);

// The coefficients of n points moving from p0 to p1 (3 finite doubles each) as the
// staged solver encloses them: c0 = x0, c1 = x1 - x0 (a point or its tightest enclosure
// under round-to-nearest: the C call's rounding scope, util/rounding.h).
void linear_points_from(size_t n, const double *p0, const double *p1, Linear_points &out);

// True when the query (kind VERTEX_FACE, EDGE_EDGE, VERTEX_EDGE or VERTEX_VERTEX; false
// for other kinds) is certainly more than delta apart at every t in [0, 1] (delta
// encloses the minimum distance, lo >= 0).
bool delta_separated(int kind, const Linear_points &pts, const arith::Interval &delta);

}  // namespace pccd::pred
