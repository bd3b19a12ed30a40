// Certified "within delta" at an instant, for the witnesses of the robot filter with a
// minimum separation (link_filter.h; issue 33: without them a robot segment with
// min_distance solved every pair the filter left, > 100 s where 1 s sufficed).
//
// triangles_within: whether triangle ea of A and triangle eb of B are certainly within
// distance delta at the instant whose poses pa, pb enclose the exact poses. Each
// vertex's world position is an interval box (enclose::point_box); for each vertex q
// of one triangle a point p of the other is chosen in doubles (q's projection on its
// plane, clamped into it by barycentric weights b1, b2 >= 0 with b1 + b2 <= 1 certified)
// and p is enclosed with interval arithmetic as (1 - b1 - b2) V0 + b1 V1 + b2 V2: it
// holds a point of the exact triangle. If the squared distance of the two enclosures
// is certainly <= delta_lo^2 (delta_lo <= delta, a double) the triangles are within
// delta: a contact in the min_distance sense at that instant. Then each edge of one
// against each edge of the other the same way: the edges' nearest parameters s, u in
// doubles, clamped to [0, 1], the points (1 - s) V0 + s V1 enclosed (edge to edge is
// how a link first comes within delta of a plate's edge: no vertex is that close). A
// choice of p made in doubles only costs witnesses missed, never a wrong one.
#pragma once
#include <cstdint>

#include "enclose/enclose.h"
#include "narrow/moving_body.h"

namespace pccd::scene {

bool triangles_within(const narrow::Body_data &A, uint32_t ea, const enclose::Pose_piece &pa,
                      const narrow::Body_data &B, uint32_t eb, const enclose::Pose_piece &pb, double delta_lo);

}  // namespace pccd::scene
