// The cheap certified filters of the staged solver (solve.h: the bounds and Bernstein
// stages), on the interval form of a query (filters.cpp).
#pragma once
#include "pred/query_systems.h"

namespace pccd::pred {

// Conservative space-time bounds: the box of each point over t in [0, 1] (hull of the
// Bernstein coefficients of its coordinates); segments and triangles lie in the hull
// of their vertices, balls within radius of their centres. True when the two sides'
// boxes are certainly disjoint, so no contact is possible.
bool bounds_separate(const Query_data<arith::Interval> &q);

// True when the polynomial every contact must be a root of certainly has no root on
// [0, 1] (orientation determinant, cross product or coordinate difference components,
// distance polynomial of balls).
bool bernstein_excludes(const Query_data<arith::Interval> &q);

}  // namespace pccd::pred
