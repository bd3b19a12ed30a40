// Vertices on polynomial paths in a step (Step_set::coef, set_paths): their swept boxes
// and the exact solve of a primitive pair with at least one such vertex.
//
// Box: coordinate a of x(t) - u t over [0, 1] (u: the broad phase's frame velocity,
// step.h) lies in the hull of its Bernstein coefficients on [0, 1] (convex hull
// property), computed in outward-rounded intervals (poly::range_on_unit) from the exact
// double coefficients, so the box holds the exact path. One piece over [0, 1].
//
// Solve: the pair's points as exact polynomial trajectories (a straight vertex of
// another mesh as x0 + (x1 - x0) t), the general staged solver (pred::solve, as
// pccd_query_solve: the same answers as a single primitive query of those paths).
#pragma once
#include <cstdint>

#include "enclose/enclose.h"
#include "pred/solve.h"
#include "step/step_set.h"

namespace pccd::step {

// Whether global vertex v moves on a polynomial path.
inline bool on_path(const Step_set &s, uint32_t v) { return s.ncoef[s.vmesh[v]] != 0; }

// The outward box of vertex v's path minus u t over [0, 1] (v on a path).
enclose::Box path_box(const Step_set &s, uint32_t v, const double u[3]);

// The pair of `kind` on the global vertices pts[0..n) solved exactly into out.
void solve_paths(const Step_set &s, int kind, const uint32_t *pts, int n, const pred::Solve_options &opt,
                 pred::Contact_result &out);

}  // namespace pccd::step
