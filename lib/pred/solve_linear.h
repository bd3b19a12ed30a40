// One query of points moving linearly, given as doubles (pccd_solve_linear_d and every
// entry of pccd_solve_linear_batch_d): the static filter (linear_filter.h) and its
// crossing half (linear_crossing.h), then the hit certificate (linear_crossing.h), then
// the staged solver (solve.h) only when neither decides. With a minimum distance those
// fast paths are skipped (they assume delta = 0); the staged solver's first test, the
// separating-direction filter (delta_filter.h), runs on the doubles before its interval
// query is built. The answer and stage are the staged solver's, except that its
// interval search may be skipped where it is predicted not to decide
// (solve_linear.cpp): the same answer, then from the exact stage.
#pragma once
#include <cstddef>

#include "pred/linear_crossing.h"
#include "pred/solve.h"

namespace pccd::pred {

// The static verdict: linear_filter, then crossing_misses on its cubic (misses). f gets
// the coplanarity cubic when one was computed (else f.ok is false).
Linear_verdict linear_verdict(int kind, const double *p0, const double *p1, Cubic_bernstein &f);

// kind: VERTEX_FACE, EDGE_EDGE, VERTEX_EDGE or VERTEX_VERTEX; n: its number of points;
// p0, p1: n points of 3 finite doubles each. The answer into out (any earlier content
// is replaced; reusing one out allocates nothing on the fast paths).
void solve_linear(int kind, size_t n, const double *p0, const double *p1, const Solve_options &opt,
                  Contact_result &out);

}  // namespace pccd::pred
