// The robot filter's containment test at t = 0 (robot.h, step 2): a certified "no" that
// spares the exact solve a pair with a solid mesh whose bodies' boxes meet at t = 0.
//
// Why it is enough. The filter bounds surface contacts only; a solid (narrow/
// containment.h) may hold the other body with no surface near. containment.h proves
// that when the surfaces do not meet at t = 0, the solids share a point only if one of
// the containment points (a vertex of each surface component, each ball centre) of one
// side lies inside the other side's solid, and that without a surface contact the status
// of t = 0 holds until the first surface contact. So a pair whose filter bound is > 0
// (no surface contact on [0, bound)) and for which no containment point of either side
// is in the other's solid at t = 0 has no contact before its bound.
//
// How a point is certainly outside: its world box at t = 0 (enclose::point_box of the
// side's pose enclosure at the instant 0) is mapped into the solid's body frame through
// the solid's pose enclosure at t = 0 in outward-rounded intervals (arith/interval.h):
// x = R (p - q) + o_q (enclose::Pose_piece, R in Rm +- Rr, o_q in om +- orad) gives
// p = q + R^T (x - o_q), R being a rotation (the unit rotation of a rigid motion, whose
// inverse is its transpose); a point whose interval box misses the solid's body-frame
// box (Body_data::box_c, box_h, which holds every exact point, so the solid) on some
// axis is outside. Any doubt (an unbounded pose, a box that meets) answers false; then
// contained_exactly_at_zero decides on the exact poses at t = 0 alone (a point in a link's
// box but outside its solid, as a wrist link near a concave forearm), and only a pair
// in containment keeps bound 0 and goes to the exact solve.
#pragma once
#include "scene/link_filter.h"

namespace pccd::scene {

// True only when certainly no containment point of A is in B's solid and none of B's is
// in A's at t = 0 (sides as first_uncleared's, with instant). A side that is no solid
// mesh holds nothing.
bool solids_apart_at_zero(const Filter_side &A, const Filter_side &B);

// The exact test where the one above is in doubt: narrow::contained_at_zero of the two
// bodies on motions whose t = 0 poses are theirs (a robot link on the segment q0 -> q0),
// exactly; its contract holds when their surfaces do not meet at t = 0 (a pair whose
// filter bound is > 0). True: some containment point is inside the other's solid.
bool contained_exactly_at_zero(const narrow::Moving_body &a, const narrow::Moving_body &b);

}  // namespace pccd::scene
