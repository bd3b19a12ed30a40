// The contract between the driver of a body pair (scene/pair_search.h) and the broad
// phases that feed it: a candidate source reports feature pairs (Prim_pair) that may
// touch; the driver solves each one exactly, once, and prunes by time. The driver does
// not know which source it talks to (brute force below, boxes/box_source.h,
// range/range_source.h).
//
// Why the feature pairs of pair_ctx.h cover every contact (formats.md: surfaces of
// meshes, balls of sphere sets):
//  - Meshes. If the surfaces share a point at t = 0, two closed triangles meet then:
//    the static test TT finds it. A first contact at t* > 0 is a vertex of one surface
//    in a closed triangle of the other (VF, FV) or two closed edges meeting (EE): at t*
//    some closed side of one triangle meets the other closed triangle; if no endpoint
//    lies in it and no edge-edge contact exists, the side crosses the open face
//    transversally, which persists for t slightly below t*, a contradiction.
//  - Sphere sets: ball pairs (SS, closed sublevel sets).
//  - Ball and mesh: ball against each closed triangle (ST / TS, with its own t = 0 test).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "narrow/pair_ctx.h"
#include "util/thread_pool.h"

namespace pccd::narrow {

// Counters of one search, summed over the body pairs of a scene (pccd_scene_stats).
// Sources count pieces, leaves and candidates; the driver counts the rest.
struct Search_stats {
  uint64_t pieces = 0;      // time pieces visited
  uint64_t leaves = 0;      // pieces whose candidates were collected (boxes: intersected)
  uint64_t candidates = 0;  // candidate pairs reported (with repeats over pieces)
  uint64_t solved = 0;      // distinct feature pairs solved exactly
  uint64_t static_tests = 0;
  uint64_t refined = 0;     // re-solves with a finer tolerance (scene/combine.h)
  uint64_t by_stage[5] = {0, 0, 0, 0, 0};  // solved pairs by deciding pccd_stage
  void add(const Search_stats &o);
};

// What a source hands its candidates to (the driver).
class Candidate_sink {
 public:
  virtual ~Candidate_sink() = default;
  // True when a contact that starts at time a or later cannot be the first one the
  // driver still needs: the source may skip a piece [a, b] and every later piece.
  virtual bool pruned(double a) const = 0;
  // Candidates found on the closed time piece [a, b] (any order, repeats allowed);
  // the driver solves them in the order of their earliest possible contact.
  virtual void piece(double a, double b, std::vector<Prim_pair> cand) = 0;
  // Candidates with no time piece (brute force): solved as one batch.
  virtual void whole(std::vector<Prim_pair> cand) = 0;
};

class Candidate_source {
 public:
  virtual ~Candidate_source() = default;
  // Two meshes: triangle pairs (type TT) among which is every pair of closed triangles
  // that share a point at t = 0.
  virtual std::vector<Prim_pair> static_candidates(util::Thread_pool &pool) = 0;
  // Hands the sink every feature pair (types VF, FV, EE, SS, ST, TS) that touches at
  // some t in [0, 1]: on a piece [a, b] containing such a t, or through whole(). Pieces
  // come in increasing time order; once sink.pruned(a) holds for a piece's start a,
  // that piece and every later one may be skipped. More pairs may be reported.
  virtual void run(Candidate_sink &sink, Search_stats &stats, util::Thread_pool &pool) = 0;
};

// Every feature pair of the two bodies' types: the reference source (quadratic).
std::unique_ptr<Candidate_source> brute_source(const Pair_ctx &ctx);

// True when a body of the pair has numbers beyond the double range, so its bounds
// (Motion_data::box_h, narrow/moving_body.h) are infinite: the box phases would compute
// inf - inf on them (and the hierarchies never separate a piece), so they hand such a
// pair to brute_source (the same answer: no non-finite double decides a candidate).
bool has_infinite_bounds(const Pair_ctx &ctx);

}  // namespace pccd::narrow
