// A certified filter in front of the exact solver: a separating direction over the
// whole step.
//
// For points moving linearly, d . x(t) is linear in t for any fixed direction d. If for
// every vertex a of one primitive and b of the other, g(t) = d . (a(t) - b(t)) > 0 at
// t = 0 and at t = 1, then g > 0 on [0, 1], so the projections of the two closed convex
// hulls onto d are apart at every time and the primitives never touch; with a minimum
// separation delta, g > delta |d| at both ends keeps them more than delta apart (the
// distance is at least min g / |d|). The directions are tried in doubles (any d is
// valid): the face normal and its in-plane edge normals (vertex-face), the edges' cross
// product and each edge's normal in their common plane (edge-edge), each at t = 0 and
// t = 1, in both orientations. They decide the flat and nearly flat configurations of
// cloth (every pair coplanar while a flat sheet falls), where the polynomial filters
// see a volume that vanishes identically.
//
// Rounding: each g(t) is evaluated in doubles as sum_a d_a (p_a - q_a), four roundings
// deep, so its error is below 8u sum_a |d_a| (|p_a| + |q_a|) (u = 2^-53; the bound
// doubles the standard gamma_4), plus 2^-1070 for underflow; a test passes only when g
// exceeds that bound (plus delta |d|, |d| rounded up). No rounding mode is assumed.
#pragma once

namespace pccd::step {

// True when the query (a pccd_kind of points moving from p0 to p1: VERTEX_FACE or
// EDGE_EDGE; false for other kinds) is certainly free of contact (within reach >= delta,
// a double; 0 for touching).
bool separated(int kind, const double *p0, const double *p1, double reach);

}  // namespace pccd::step
