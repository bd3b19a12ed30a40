// The driver of one body pair: all feature pairs of two moving bodies that touch, or the
// first ones. It asks a candidate source (broad_phase.h) for feature pairs, solves each
// distinct pair at most twice with the exact narrow phase (narrow/pair_ctx.h), and
// prunes by time:
//  - Meshes: the static test at t = 0 first (TT pairs of the source's static
//    candidates); a contact there is the first one.
//  - Solids (narrow/containment.h): a point of one body strictly inside the other's
//    solid at t = 0 (meshes: when the static pass found nothing) is a contact at t = 0
//    (IN_A / IN_B), which ends the search unless all_contacts.
//  - The source's candidates of a piece [a, b] get the start of the first of 8 equal
//    sub-pieces on which the two features' boxes meet (a lower bound of their contacts
//    in [a, b]; none: no contact in [a, b], so the pair is left for a later piece; with
//    a minimum separation delta, "meet" reads "within enclose::reach_of(delta)",
//    enclose::boxes_within, so that "contact" reads "within delta"). They
//    are solved in order of that bound, in batches of 4, 8, ..., 64 pairs; a batch
//    starts only with pairs whose bound is <= the best upper bound so far, and each pair
//    is asked only for contacts up to that bound and the piece's end b
//    (pred::Solve_options::until; with all_contacts or without times: all of [0, 1]).
//    A pair found apart up to b that a later piece reports again (it may touch there)
//    is solved again, then up to the best bound alone.
//  - Search_options::witness with a minimum separation delta: the candidates of a piece
//    starting at 0 are first tested at t = 0 alone (Pair_ctx::within_at_zero); once a
//    pair is within delta then, later pieces are pruned and only the pair of least key
//    within delta at t = 0 is solved (the same for every broad phase).
//  - A piece that starts after the best upper bound found so far is pruned: a pair
//    first met there can only touch later than that bound.
// The set of pairs solved, and so the answer, does not depend on the number of threads
// (the pairs of one batch are solved in parallel, results are merged in a fixed order).
#pragma once
#include <memory>
#include <vector>

#include "scene/broad_phase.h"

namespace pccd::scene {

using arith::Rational;
using narrow::Feature_ref;
using narrow::Moving_body;
using narrow::Pair_ctx;
using narrow::Prim_pair;
using narrow::Search_stats;
using util::Thread_pool;

struct Search_options {
  pred::Solve_options solve;
  bool all_contacts = false;  // solve every candidate (no time pruning)
  Broad_phase phase = Broad_phase::boxes;  // resolved (not automatic)
  double reach = 0;           // enclose::reach_of(solve.delta) (Scene_options::reach)
  int stored = -1;            // range: the side (0, 1) held in the trees; -1: the larger
  // A witness is enough where the first time is known or not wanted: without times
  // (solve.want_time false) or once a feature pair touches at t = 0 (the static pass),
  // candidates are solved in chunks of 64 and the search stops after the chunk that
  // found a contact, rather than reporting every touching feature pair (a robot's
  // overlapping links hold thousands). Not with all_contacts.
  bool witness = false;
  // The pair is known apart at t = 0 (a filter's lower bound > 0: scene/robot.h): the
  // static pass, which looks for contacts at t = 0 only, is skipped.
  bool apart_at_zero = false;
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

// A finer re-solve of a solved pair (for combine.h): tolerance / 2^(20 (round + 1)).
std::unique_ptr<Solved_pair> refine_pair(const Pair_ctx &ctx, const Solved_pair &s,
                                         const pred::Solve_options &opt, int round);

}  // namespace pccd::scene
