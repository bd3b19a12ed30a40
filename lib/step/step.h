// The whole-step query: every primitive pair of a Step_set (step_set.h) that touches
// during t in [0, 1], found by a swept-box broad phase (tree.h) and decided exactly by
// the library's linear solver (pred/solve_linear.h, as pccd_solve_linear_d).
//
// Broad phase. Each vertex's straight path lies in the box of its two end positions
// (doubles, exact); a polynomial path (paths.h) in the hull of its Bernstein
// coefficients, and its pairs are solved by the general solver (pred::solve). The boxes are taken in a frame translating with a common velocity
// u (the mean displacement, rounded to doubles): x(t) - u t. Contact depends only on
// the distances between points at the same time, which such a frame keeps, so any u
// is valid, and a mesh falling or sliding as a whole gets boxes of its deformation
// only. x1 - u is rounded, so each such box is widened by one ulp on each side. A
// primitive's box is the hull of its vertices' boxes; with a minimum separation delta
// the query side's boxes grow by enclose::reach_of(delta) (enclose.h: why one side
// suffices). Queries (every used vertex against the face tree, every edge against the
// edge tree, every point against the edge and point trees) run in fixed chunks on the
// thread pool, each candidate solved as it is found (first by the separating-direction
// filter, separate.h; in FIRST mode with the chunk's earliest contact so far as the
// solver's `until`), chunk results kept by index.
//
// Answers (none depends on the broad phase or on the thread count: the broad phase
// only drops pairs whose boxes are apart, which cannot touch):
//   FIRST  the exact first contact time over all pairs (scene/combine.h: the usual
//          enclosure, exact when rational), the pairs touching first, and the step
//          size: the largest double <= t* (enclosures refined until no double lies
//          inside), 1 when nothing touches;
//   DECIDE whether anything touches: chunks run in rounds of kRound and the call stops
//          after the first round with a contact; a chunk stops at its first contact.
//          The contacts reported are those found (no times: want_time = 0);
//   ALL    FIRST plus every touching pair with its own first time.
// Contacts are sorted by (kind, a, b). Work steps: one per chunk, plus the solver's.
#pragma once
#include <cstdint>
#include <vector>

#include "pred/solve.h"
#include "step/step_set.h"

namespace pccd::step {

enum Mode : int { FIRST = 0, DECIDE = 1, ALL = 2 };

struct Step_options {
  pred::Solve_options solve;
  Mode mode = FIRST;
  unsigned threads = 1;
};

// A touching pair: VERTEX_FACE (a vertex, b face), EDGE_EDGE (edges a < b), VERTEX_EDGE
// (a point's vertex, b edge), VERTEX_VERTEX (vertices a < b); global indices.
struct Step_contact {
  int kind = 0;
  uint32_t a = 0, b = 0;
  pred::Contact_result r;
};

struct Step_stats {
  uint64_t queries = 0, candidates = 0, refined = 0;
  uint64_t by_stage[5] = {0, 0, 0, 0, 0};
};

struct Step_report {
  bool collides = false;
  arith::Rational lo, hi;  // FIRST, ALL: lo <= t* <= hi
  bool exact = false;
  double stepsize = 1.0;   // FIRST, ALL: the largest double <= t*; 1 when free
  std::vector<Step_contact> contacts;
  Step_stats stats;
};

constexpr size_t kChunk = 256;  // queries per task
constexpr size_t kRound = 32;   // chunks per round (DECIDE)

Step_report solve_step(const Step_set &s, const Step_options &opt);

// The largest double <= q, for q >= 0.
double double_below(const arith::Rational &q);

}  // namespace pccd::step
