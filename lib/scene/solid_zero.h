// Containment at t = 0 ruled out from the filter's poses, for the robot filter's solid
// pairs (robot.cpp; issue 33).
//
// The filter bounds surface contacts only. A solid (narrow/containment.h) may hold a
// point of the other body with no surface near, so a pair with a solid whose bounds did
// not rule that out went to the exact solve with no bound (its containment test at
// t = 0), and with a minimum separation that solve is costly (a UR5 link 0.053 from a
// plate: 60 ms, where the filter had cleared the pair on all of [0, 1]).
//
// solids_apart_at_zero: true when, for each side S that is a solid mesh, every point of
// the other side Q that narrow::contained_at_zero would test (a vertex of each surface
// component, or each ball's centre: motion::component_vertices) lies certainly outside
// S's body-frame box (Body_data::box_c, box_h, holding S's exact points, so S's solid,
// their convex hull's subset) at t = 0. The point is enclosed in the world (enclose::
// point_box at Q's pose enclosure at t = 0) and taken to S's frame as R^T (x - o) in
// interval arithmetic over S's pose enclosure (R a rotation: its inverse is R^T); a
// coordinate certainly beyond the box puts the point outside. Then no point tested is
// inside, so no solid holds a point of the other at t = 0 (containment.h, why one point
// per component decides), and with the surfaces apart on [0, lower) (the filter's bound,
// within delta read as touching) the pair has no contact, none within delta, before
// lower (a solid's distance to a disjoint body is that of its surface). False when not
// certain (then the caller solves the pair with no bound, as before).
#pragma once

#include "enclose/enclose.h"
#include "narrow/moving_body.h"

namespace pccd::scene {

bool solids_apart_at_zero(const narrow::Body_data &A, const enclose::Pose_piece &pa, const narrow::Body_data &B,
                          const enclose::Pose_piece &pb);

}  // namespace pccd::scene
