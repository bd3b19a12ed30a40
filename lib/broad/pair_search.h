// All feature pairs of two moving bodies that touch, or the first ones: broad phase
// (time pieces and CGAL box intersection) or brute force, then the exact narrow phase.
//
// Why these feature pairs cover every contact (formats.md: surfaces of meshes, balls of
// sphere sets):
//  - Meshes. If the surfaces share a point at t = 0, two closed triangles meet then:
//    the static test TT finds it. A first contact at t* > 0 is a vertex of one surface
//    in a closed triangle of the other (VF, FV) or two closed edges meeting (EE): at t*
//    some closed side of one triangle meets the other closed triangle; if no endpoint
//    lies in it and no edge-edge contact exists, the side crosses the open face
//    transversally, which persists for t slightly below t*, a contradiction.
//  - Sphere sets: ball pairs (SS, closed sublevel sets).
//  - Ball and mesh: ball against each closed triangle (ST / TS, with its own t = 0 test).
//
// Broad phase. [0, 1] is split recursively into dyadic pieces. On each piece every
// element (triangle or ball) gets a conservative box (broad/boxes.h); elements whose box
// misses the other body's active elements' hull are dropped for that piece and its
// sub-pieces. When the motion's spread over a piece is at most the bodies' typical
// feature size (or the piece is small), CGAL's box_intersection_d pairs the boxes of
// vertices, edges, triangles and balls; each pair met for the first time is solved
// exactly over all of [0, 1]. A pair whose boxes never meet on any piece has no contact.
// Pieces are visited in time order; for the first contact, a piece that starts after
// the best upper bound found so far is skipped: a pair first met there can only touch
// later than that bound. The set of pairs solved up to each piece, and so the answer,
// does not depend on the number of threads (pairs of one piece are solved in parallel,
// results are merged in a fixed order).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "broad/combine.h"
#include "broad/narrow.h"
#include "broad/thread_pool.h"

namespace pccd::broad {

struct Search_options {
  pred::Solve_options solve;
  bool all_contacts = false;  // solve every candidate (no time pruning)
  bool brute = false;         // every feature pair, no boxes
  bool range = false;         // the range structure (broad/range_index.h) instead of boxes
  int stored = -1;            // range: the side (0, 1) held in the trees; -1: the larger
};

struct Search_stats {
  uint64_t pieces = 0;      // time pieces visited
  uint64_t leaves = 0;      // pieces where boxes were intersected
  uint64_t candidates = 0;  // box pairs reported (with repeats over pieces)
  uint64_t solved = 0;      // distinct feature pairs solved exactly
  uint64_t static_tests = 0;
  uint64_t refined = 0;     // re-solves with a finer tolerance (combine.h)
  uint64_t by_stage[5] = {0, 0, 0, 0, 0};  // solved pairs by deciding pccd_stage
  void add(const Search_stats &o);
};

struct Solved_pair {
  Prim_pair prim;
  pred::Contact_result result;
};

struct Pair_outcome {
  std::vector<std::unique_ptr<Solved_pair>> solved;  // the solved pairs that touch, in a fixed order
  Search_stats stats;
};

Pair_outcome search_pair(const Pair_ctx &ctx, const Search_options &opt, Thread_pool &pool);

// A finer re-solve of a solved pair (for combine.h): tolerance / 2^20.
std::unique_ptr<Solved_pair> refine_pair(const Pair_ctx &ctx, const Solved_pair &s,
                                         const pred::Solve_options &opt, int round);

}  // namespace pccd::broad
