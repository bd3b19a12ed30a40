// Contact point and normal of two features at their first contact time.
//
// Given feature fa of body a and feature fb of body b (vertex, edge, triangle or ball:
// narrow::Feature_type, the values of pccd_feature) that touch at some time t* in
// [t_lo, t_hi] (a report's contact and its time), a contact point and a normal, by these
// definitions (positions are world positions at t*; an edge (v0, v1) runs from v0 to v1,
// v0 < v1 as motion::Mesh_body::edges lists it; a triangle (v0, v1, v2) as given):
//   vertex-X, X-vertex   the point is the vertex (of a when both are vertices).
//   edge-edge            d = v1 - v0 on each side, n = d_a x d_b. n != 0: the crossing
//                        a0 + s d_a, s = ((b0 - a0) x d_b) . n / |n|^2. n = 0 (parallel,
//                        overlapping on a line): the first of a0, a1, b0, b1 that lies on
//                        the other closed segment.
//   edge-triangle, triangle-triangle (the static test at t = 0 reports the latter): the
//                        first point, in a fixed order, of: the vertices of a, those of b,
//                        the crossings of an edge of one with an edge of the other, the
//                        crossings of an edge of one with the plane of the other, that lies
//                        in both closed features (the extreme points of the intersection
//                        of two convex sets are among these).
//   sphere-sphere        c_a + r_a / (r_a + r_b) (c_b - c_a): in both balls whenever they
//                        touch or overlap.
//   sphere-X, X-sphere   the closest point of the closed feature X to the centre (exact
//                        region tests and projections, Ericson's closest point on a
//                        triangle; a degenerate triangle: the closest of its sides').
// Normals (not normalized; Normal_state::none when the vector is zero or undefined):
//   vertex-triangle (either order): (v1 - v0) x (v2 - v0) of the triangle, by its
//   winding; edge-edge: d_a x d_b (none when parallel); sphere-sphere: c_b - c_a;
//   sphere-X: from body a's feature towards body b's: point - c_a when the ball is a's,
//   c_b - point when it is b's; every other pair (vertex-vertex, vertex-edge,
//   edge-triangle, triangle-triangle): none.
//
// t_lo == t_hi: every value is computed exactly (rationals) and checked: the point must
// lie on both closed features (Input_error "the features do not touch at t = ..."
// otherwise; so features reported with config.min_distance > 0, which are within the
// distance but apart, are refused). t_lo < t_hi (t* irrational): the same formulas in
// interval arithmetic over the feature points' position enclosures on [t_lo, t_hi]
// (Bernstein hulls of the exact motion polynomials over the time interval, divided by
// W's; the sides of edges and triangles, for the normals and the crossing of edges, as
// R(t) times the body-frame side, exact for translations); when a decision or division
// is uncertain the point falls back to the intersection of the two features' boxes over
// [t_lo, t_hi], which contains every point of both features at t* (Input_error when it
// is empty: the features cannot touch in [t_lo, t_hi]); the normal is
// Normal_state::unknown when |n|^2 is not certainly positive, or when it depends on a
// point that fell back (sphere-X). Every enclosure contains the true value whenever the
// features do touch at some t* in [t_lo, t_hi]; its width shrinks with t_hi - t_lo.
// (lib/narrow precedes lib/enclose in the layer order, so the enclosures are made here
// from poly::range_on_unit, the Bernstein hull enclose::enclose_pose builds on.)
#pragma once
#include <array>
#include <cstddef>

#include "arith/interval.h"
#include "arith/rational.h"
#include "narrow/moving_body.h"

namespace pccd::narrow {

enum class Normal_state { none = 0, enclosed = 1, unknown = 2 };

struct Contact_geometry {
  std::array<arith::Interval, 3> point;   // encloses the contact point
  Normal_state normal_state = Normal_state::none;
  std::array<arith::Interval, 3> normal;  // encloses the unit normal (enclosed); [-1, 1]
                                          // (unknown: valid whenever a normal is defined)
  bool exact = false;                     // t_lo == t_hi: the next two are set
  std::array<arith::Rational, 3> point_q;
  std::array<arith::Rational, 3> normal_q;  // unnormalized; when normal_state == enclosed
};

struct Feature_arg {
  int kind = 0;       // a Feature_type value (checked)
  size_t index = 0;   // checked against the body
  const char *kind_name = "feature";   // argument names for messages
  const char *index_name = "index";
};

// Input_error naming the argument: kind not a Feature_type or not one of the body's
// kinds, index out of range, a time outside [0, 1] or t_lo > t_hi, features that do
// not touch (above).
Contact_geometry contact_geometry(const Moving_body &a, const Feature_arg &fa, const Moving_body &b,
                                  const Feature_arg &fb, const arith::Rational &t_lo,
                                  const arith::Rational &t_hi);

}  // namespace pccd::narrow
