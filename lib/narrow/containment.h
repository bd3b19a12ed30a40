// Containment at t = 0: two bodies whose solids share a point without their surfaces
// touching (docs/design.md, "Solids"). A solid mesh (motion/solid.h) stands for the
// solid it bounds, a non-solid mesh for its surface, a set of balls for its balls.
//
// Why one point per surface component (or per ball) decides it. Take bodies A and B
// whose surfaces (a mesh's closed triangles, a ball's sphere) do not meet at t = 0, and
// whose solids share a point x. The bounded nonempty set S = solid A and solid B has a
// boundary point y, and y lies on the surface of A or of B, say on a connected
// component C of A's surface. C does not meet B's surface, so C lies entirely in the
// interior of solid B or entirely outside it (the winding number of B is constant on
// C); as y is in the closure of solid B, C lies inside, and so does each of its
// vertices (a ball: its centre). So testing one vertex of each component of each
// body's surface against the other's solid finds every such pair; a body inside
// another with no vertex inside is impossible unless the surfaces meet, which the
// surface contacts report. Balls need the test only against solid meshes: a ball
// holding part of a mesh's surface meets a closed triangle, a surface contact.
//
// Afterwards (continuity): the winding number of a moving point changes only when the
// point crosses the other surface, a surface contact, so without any surface contact on
// [0, 1] the containment status of t = 0 holds on all of [0, 1], and with one, the pair
// touches at t = 0 anyway: the first contact is t = 0 whenever a point is inside.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "narrow/pair_ctx.h"

namespace pccd::narrow {

// The points of a body tested against the other's solid (the argument above): a vertex
// of each surface component of a mesh, every ball centre (indices into pts). Kept with
// the body. Also behind the robot filter's certified test at t = 0 (scene/solid_start.h).
const std::vector<uint32_t> &containment_points(const Body_data &d);

// Whether either side is a solid mesh (the only pairs contained_at_zero looks at).
bool has_solid(const Pair_ctx &ctx);

// The first point strictly inside the other side's solid at t = 0, exactly: the points
// of side B (a vertex of each surface component, or each ball's centre) against solid A
// first ({IN_A, 0, point}), then those of side A against solid B ({IN_B, point, 0});
// nothing when no tested point is inside. A tested point on the other's surface at
// t = 0 (a surface contact, which the caller reports) may count as inside or not.
std::optional<Prim_pair> contained_at_zero(const Pair_ctx &ctx);

}  // namespace pccd::narrow
