// The minimum-distance axis filter of a query whose points move on polynomials of any
// degree (robot links, rational motions; issue 33): one direction d, the nearest-point
// direction of the two primitives at t = 1/2 (closest_axis.h), that keeps them more than
// delta apart on all of [0, 1].
//
// Why it is sound: the true positions are x_i(t) = p_i(t) / D(t), D > 0 the query's
// scale (query_systems.h; D = 1 when empty). For every point a_i of the first primitive
// and b_j of the second, g_ij(t) = d . (p_bj(t) - p_ai(t)) - delta N D(t) with N >= |d|
// (a double rounded up) is a polynomial in interval coefficients; when its Bernstein
// range on [0, 1] (poly::range_on_unit, an enclosure of every value) is certainly > 0,
// d . (b_j - a_i) > delta |d| at every t. Every point of the closed primitives is a
// convex combination of its points, so d . (b - a) > delta |d| for all of them, and by
// Cauchy-Schwarz |b - a| > delta: no contact within delta on [0, 1]. Any d is valid;
// the doubles choosing it decide only how often the test succeeds.
//
// Why it is needed: the other cheap filters take the per-coordinate boxes grown by delta
// (bounds_separate) or the distance to a primitive's plane or line (bernstein_excludes),
// so a vertex 0.06 from a plate's face triangle but beside it, near the plane, went to
// the interval stage: a UR5 segment with min_distance 0.05 solved 691 feature pairs,
// 580 of them in intervals (about 1 ms each), where this test clears most of them.
// Used only for queries that are not plain linear (the linear filter of delta_filter.h
// decides those, alike on every path), reported as STAGE_BOUNDS.
#pragma once

#include "pred/query_systems.h"

namespace pccd::pred {

// q: with has_delta (kinds VERTEX_FACE, EDGE_EDGE, VERTEX_EDGE, VERTEX_VERTEX; false
// for any other query), delta its enclosure.
bool delta_axis_separated(const Query_data<arith::Interval> &q);

}  // namespace pccd::pred
