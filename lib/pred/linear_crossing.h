// The second half of the static filter of linear double queries (linear_filter.h): a
// vertex-face or edge-edge query whose contact cubic f (the coplanarity determinant)
// crosses zero exactly once in [0, 1], at a time the primitives miss each other.
//
// Proof it gives of "no contact": the certified Bernstein coefficients of f on [0, 1]
// (linear_filter.h) all have a certain sign with exactly one sign change, so f has
// exactly one root r in (0, 1), a simple one, and none at 0 or 1 (Descartes' rule of
// signs in Bernstein form: the number of roots in (0, 1) is at most the number of sign
// changes and has its parity). f evaluated in interval arithmetic at two times ta < tb
// (found around a floating-point estimate of r) has certain opposite signs, so r is in
// (ta, tb). On T = [ta, tb] the side conditions are enclosed in interval arithmetic
// (positions x0 + T (x1 - x0)); one of them certainly says "apart" on all of T:
//  - vertex-face: v strictly outside an edge line of the triangle within the plane,
//    g_i = n . ((f_(i+1) - f_i) x (v - f_i)) < 0, n = (f1 - f0) x (f2 - f0) (the closed
//    triangle lies where every g_i >= 0; a degenerate triangle has n = 0, g_i = 0);
//  - edge-edge: both ends of one segment strictly on one side of the other's line,
//    measured along n = (a1 - a0) x (b1 - b0): s(b0) s(b1) > 0 or s(a0) s(a1) > 0 (the
//    side s is affine and vanishes on the line, so a crossing point forces s(x0) and
//    s(x1) not to have one strict sign).
// The only time the primitives are coplanar is r, and there they are apart: no contact.
// Anything else (several roots, tangency, uncertain signs) is left to the solver.
//
// The hit half: the same single crossing r, where the primitives certainly touch
// transversally, answered without the staged solver. With the same bracket T of r, the
// side conditions are certainly "inside" on all of T:
//  - vertex-face: g_i > 0 for i = 0, 1, 2 (v in the open face; then not on an edge or
//    a vertex, so the vertex-face feature alone touches);
//  - edge-edge: s(b0) s(b1) < 0 and s(a0) s(a1) < 0 (the open edges cross at one point;
//    no endpoint is on the other segment's line, so edge-edge alone touches).
// So the query collides, only at r, with the one feature (points 0, 1, 2, 3): the
// staged solver's decide-only answer (solve.h, poly/earliest.h without a time: the
// enclosure [0, 1] and the features that touch somewhere), or with a time the same
// enclosure as the solver's canonical midpoint bisection (see crossing_hit).
#pragma once

#include "pred/linear_filter.h"
#include "pred/solve.h"

namespace pccd::pred {

// kind: VERTEX_FACE or EDGE_EDGE; f: the query's coplanarity_cubic (linear_filter.h). True only when the proof above holds.
bool crossing_misses(int kind, const double *p0, const double *p1, const Cubic_bernstein &f);

// kind: VERTEX_FACE or EDGE_EDGE; p0, p1: finite doubles (linear_filter.h); f: the
// query's coplanarity_cubic (not ok: false). True and the
// staged solver's answer in out (collides, the feature, stage interval, exact false) when
// the certificate holds and, with a time, when every step below certainly decides:
//  - without a time: the enclosure [0, 1];
//  - with a time: the solver's midpoint bisection (poly/earliest.h) by the sign of f at
//    each midpoint, so the same enclosure; with want_exact, only when r is proved
//    irrational by the solver's modular test run on f mod small primes from the doubles
//    (linear_crossing.cpp), so the solver would stop there too.
bool crossing_hit(int kind, const double *p0, const double *p1, const Cubic_bernstein &f,
                  const Solve_options &opt, Contact_result &out);

}  // namespace pccd::pred
