// The static filter of a linear query given as doubles (pccd_solve_linear_d): every point
// moves on the segment from its position p0 at t = 0 to p1 at t = 1. Allocation-free,
// raw doubles, no rounding-mode assumption; it either proves "no contact" or says
// nothing, and then the staged solver (solve.h) decides as before. It proves:
//  - boxes_apart: the closed boxes of the two primitives' points at t = 0 and t = 1 are
//    disjoint. A point moving linearly stays in the box of its two positions, so the
//    primitives (convex hulls of their points) never meet. No arithmetic: exact.
//  - no_root: the polynomial every contact is a root of (solve.h's Bernstein stage:
//    the coplanarity cubic of vertex-face and edge-edge, a component of the cross
//    product for vertex-edge, a coordinate difference for vertex-vertex) has Bernstein
//    coefficients on [0, 1] of one strict sign, so it has no root in [0, 1]. The
//    coefficients are sums of determinants of point differences, evaluated in doubles
//    with the error bound derived in linear_filter.cpp.
// Its second half, a single crossing where the primitives miss (misses), is in
// linear_crossing.h, which builds on this file (never the other way round);
// solve_linear.h runs both.
#pragma once

namespace pccd::pred {

// misses: vertex-face or edge-edge whose coplanarity cubic has one simple root in (0, 1),
// where the primitives are certainly apart (linear_crossing.h, crossing_misses; given by
// solve_linear.h's linear_verdict, never by linear_filter).
enum class Linear_verdict { unknown = 0, boxes_apart = 1, no_root = 2, misses = 3 };

struct Cubic_bernstein;

// kind: VERTEX_FACE, EDGE_EDGE, VERTEX_EDGE or VERTEX_VERTEX (features.h); p0 and p1 hold
// the kind's points (polyccd.h order), 3 finite doubles each. Other kinds: unknown.
// boxes_apart, no_root or unknown; f gets the coplanarity cubic (below) of a vertex-face
// or edge-edge query whose boxes meet (otherwise f.ok is false).
Linear_verdict linear_filter(int kind, const double *p0, const double *p1, Cubic_bernstein &f);

// The Bernstein coefficients on [0, 1] of the cubic f(t) = det(a(t), b(t), c(t)) with
// a(t) = A(t) - O(t), b(t) = B(t) - O(t), c(t) = C(t) - O(t) and each point X(t) moving
// linearly from X[0] to X[1] (3 doubles each), the middle two times 3:
// |value[k] - exact[k]| <= bound[k] for each k when ok; ok is false when a point
// difference is outside the filter's range (linear_filter.cpp), and then nothing holds.
struct Cubic_bernstein {
  double value[4], bound[4];
  bool ok;
};
Cubic_bernstein cubic_bernstein(const double *const O[2], const double *const A[2],
                                const double *const B[2], const double *const C[2]);

// The cubic of a query of `kind` (VERTEX_FACE: det(f1 - f0, f2 - f0, v - f0); EDGE_EDGE:
// det(a1 - a0, b0 - a0, b1 - a0), the polynomials of features.h); ok is false for other
// kinds.
Cubic_bernstein coplanarity_cubic(int kind, const double *p0, const double *p1);

// The same for the quadratic cross-product component k (0, 1, 2) of
// (A(t) - O(t)) x (B(t) - O(t)); the middle coefficient times 2.
struct Quadratic_bernstein {
  double value[3], bound[3];
  bool ok;
};
Quadratic_bernstein cross_bernstein(int k, const double *const O[2], const double *const A[2],
                                    const double *const B[2]);

}  // namespace pccd::pred
