// The certified filter of a robot check (robot.h): which body pairs may touch over a
// segment, and from when, decided on pose enclosures alone, before any exact motion is
// built; in decide mode also a certified contact found on the way (a witness).
//
// A body on a time piece [a, b] is given by a Side_piece: a ball pose (enclose::
// Pose_piece: for a robot link the interval pose of motion/chain_path.h straight from
// the joint path in midpoint-radius form, for an obstacle enclose::enclose_pose of its
// exact motion), and for a robot link on a short piece the second-order enclosure of
// motion/chain_path.h ("Second-order enclosures"): its poses at a and at b (enclosures
// of the exact poses at those instants) and the chords' growth g_rot |y| + g_off. A node's
// world box over the piece is then the hull of its boxes at a and at b (enclose::
// frame_box of its body-frame box) grown by g_rot |y|max + g_off, |y|max <= sqrt(3)
// reach over the body (every point y of the node: R(t) y + o(t) is within that of the
// chord between R(a) y + o(a) and R(b) y + o(b), whose points lie in the hull); without
// the ends, frame_box of the ball pose. Either holds the node's elements at every t of
// the piece.
//
// first_uncleared: a swept traversal of the two hierarchies over dyadic pieces of
// [0, 1], earlier half first, carrying a front of node pairs from a piece to its halves
// (as bvh/bvh_source.h does with exact-motion enclosures): a node pair whose world boxes
// miss is dropped with both subtrees for the piece and its sub-pieces; a meeting pair
// splits its larger node while that node is larger than kSplit_factor (link_filter.cpp)
// times the piece's spread (what the motion adds to a box; on the finest piece, which
// has no halves, than the spread), else waits for the halves. A piece whose front empties is
// separated: no element pair touches at any t of it (a touching pair of elements lies
// in leaves whose boxes, and whose ancestors' boxes, all meet on every piece holding
// that t). A front that outgrows kMax_front on a piece hands its unprocessed pairs to
// the halves as they are (each may still meet: nothing is dropped unseparated). The
// first piece that is still not separated at depth kMax_depth, or whose front outgrows
// 16 kMax_front, or that starts after kMax_tests front pairs were taken for the body
// pair (overlapping links hold a front of thousands at t = 0 on every depth; or
// Filter_limits::max_tests), or that starts at or after Filter_limits::until, gives its start: a certified lower bound of the pair's
// contact times (every earlier time lies in a separated piece). kNever (> 1) when every
// piece is separated: the pair never touches on [0, 1].
// Witness (decide mode, when asked): on a piece of depth >= kWitness_depth that is not
// separated, while the body pair's witness budget lasts (kWitness_tests), the front is
// tested at the piece's midpoint, an instant m = (2i + 1) /
// 2^(d + 1) (touching_at); a triangle pair found touching there ends the traversal (the
// pair touches at m, exactly: the answer is certain) and the piece's start is returned.
// Minimum separation: boxes are kept when within reach (enclose::boxes_within, reach_of;
// the leaves' separating axes take a margin reach |n|), so "touch" reads "come within
// delta" throughout; a witness is then a triangle pair certainly within
// delta at the midpoint (delta_witness.h; Filter_limits::delta_lo, issue 33).
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "enclose/enclose.h"

namespace pccd::bvh {
struct Hierarchy;
}

namespace pccd::scene {

class Node_memo;  // node_memo.h

constexpr int kMax_depth = 14;         // pieces of 1/16384 at the finest
constexpr size_t kMax_front = 4096;    // node pairs per piece (then: not separated)
constexpr size_t kMax_tests = 1 << 16;  // front pairs per body pair (then: the piece's start)
constexpr double kNever = 2.0;         // first_uncleared: no contact on [0, 1]
constexpr int kWitness_depth = 3;      // witnesses are looked for from pieces of 1/8
// Node pairs tested at midpoints, per body pair: at most kWitness_tests plus half the
// front pairs taken so far (a near miss that is never a contact costs at most half again).
constexpr size_t kWitness_tests = 256;

struct Side_piece {
  const enclose::Pose_piece *ball = nullptr;                    // always
  bool identity = false;  // the body does not move: world boxes are body-frame boxes
  const enclose::Pose_piece *at_a = nullptr, *at_b = nullptr;  // both, or neither
  double g_rot = 0, g_off = 0;  // (b - a)^2 / 8 times d2, o2 (rounded up)
};

// A body pair's side: its data, and its poses from a source the caller keeps alive
// while the side is used (piece_poses.h for a robot check): piece_of(src, base, k, d, i)
// over the dyadic piece [i, i + 1] / 2^d, instant_of(...) at the instant i / 2^d (an
// enclosure of the exact pose then; null: none). Plain function pointers, not
// std::function: a check makes two sides per pair and asks for a pose per piece, and
// std::function's copies and calls were about 3% of a free Panda segment (issue 30).
struct Filter_side {
  const narrow::Body_data *data = nullptr;
  const bvh::Hierarchy *tree = nullptr;  // bvh::hierarchy(*data) when the caller has it
  void *src = nullptr;
  long base = -1;
  size_t k = 0;
  // Nonzero: piece_of gives the same poses for as long as this key, data, tree, src, base
  // and k stay the same (first_uncleared then keeps side A's boxes from call to call:
  // shared_memo.h). Zero: no such promise.
  uint64_t share = 0;
  const Side_piece &(*piece_of)(void *src, long base, size_t k, int depth, long index) = nullptr;
  const enclose::Pose_piece &(*instant_of)(void *src, long base, size_t k, int depth, long index) = nullptr;
  const Side_piece &piece(int depth, long index) const { return piece_of(src, base, k, depth, index); }
  const enclose::Pose_piece &instant(int depth, long index) const { return instant_of(src, base, k, depth, index); }
  bool has_instant() const { return instant_of != nullptr; }
};

// A certified contact: elements a (of A) and b (of B) share a point at t = index / 2^depth.
struct Witness {
  bool found = false;
  int depth = 0;
  long index = 0;
  uint32_t a = 0, b = 0;
};

using Node_pairs = std::vector<std::pair<uint32_t, uint32_t>>;
inline const Node_pairs kRoots{{0, 0}};  // the front of the two roots

struct Filter_limits {
  double until = 1;               // pieces starting at or after it are not looked at
  size_t max_tests = kMax_tests;  // front pairs per body pair
  double delta_lo = 0;            // with reach > 0: delta rounded down (witnesses within it)
  // Both sides stand still over [0, 1] (a robot state: q0 = q1, obstacles fixed): every
  // piece holds the same poses, so a halving separates nothing the whole piece did not.
  // The first piece that is not separated gives its start (0) at once, after a witness
  // try at its midpoint (decide mode): no descent to kMax_depth over equal pieces.
  bool frozen = false;
  // The caller knows [0, from] separated (the start an earlier call on the same sides
  // and reach returned, on the dyadic grid): pieces ending at or before it are skipped
  // as separated, unexamined (a witness pair's second traversal, robot.cpp).
  double from = 0;
};

// w: when not null (both bodies meshes; with reach > 0 only when lim.delta_lo > 0),
// witnesses are looked for.
double first_uncleared(const Filter_side &A, const Filter_side &B, double reach, const Filter_limits &lim = {},
                       Witness *w = nullptr);

// A side's root node's world box over the whole of [0, 1] (piece 0): what
// first_uncleared's first piece tests. A caller keeps it per body (a link against each
// obstacle).
enclose::Box whole_box(const Filter_side &S);
// Whether two sides' whole_box are apart by more than reach: then no element pair comes
// within reach at any t, so first_uncleared's first piece is separated, no witness
// exists, and neither body can hold a point of the other (nothing of either leaves its
// root box). A robot check's decide scan skips such pairs (robot.cpp: the same answers,
// without their instants).
bool roots_apart(const enclose::Box &a, const enclose::Box &b, double reach);

// A witness at the instants lower + 2^-k, k = kMax_depth, kMax_depth - 2, ..., while
// below 1 (lower: a pair's first_uncleared, on the dyadic grid of kMax_depth): after
// the first uncleared piece, where a contact that first_uncleared's midpoints missed
// most likely overlaps. touching_at from the roots, kWitness_tests node pairs each.
// reach, delta_lo: as first_uncleared's (0: touching witnesses only).
// tests: node pairs per instant (kWitness_tests; more where an exact solve follows anyway).
bool witness_after(const Filter_side &A, const Filter_side &B, double lower, Witness &w, double reach = 0,
                   double delta_lo = 0, size_t tests = kWitness_tests);

// Whether some element pair under the node pairs of front (e.g. {{0, 0}}: the roots)
// certainly shares a point at the instant of the poses pa, pb (enclosures of the exact
// poses then): a traversal with frame_box at the instant, then pred::triangles_meet in
// interval arithmetic on the element boxes (a certain answer holds for every point of
// the boxes, so for the exact one; an uncertain one is not a witness). Triangles of two
// meshes only; each node pair tested takes one from budget, and none is tested once it
// is 0 (then: none found). reach > 0: A's boxes grow by reach and a leaf pair certainly
// within delta_lo (delta_witness.h) is found too.
// ha, hb: bvh::hierarchy(A), (B) when the caller has them (else looked up: a lock).
// memo_a: A's node boxes at pa (node_memo.h), kept by the caller while pa and ha stay the
// same (a link at one instant against each obstacle); null: made per node pair.
// apart (when not null): set when none is found and every node pair under the front
// was separated, leaves by the filter's certified leaf test (first_uncleared's; with
// reach > 0: farther than delta): no element pair is within delta at the instant.
bool touching_at(const narrow::Body_data &A, const enclose::Pose_piece &pa, const narrow::Body_data &B,
                 const enclose::Pose_piece &pb, const Node_pairs &front, size_t &budget, uint32_t &ea, uint32_t &eb,
                 double reach = 0, double delta_lo = 0, const bvh::Hierarchy *ha = nullptr,
                 const bvh::Hierarchy *hb = nullptr, Node_memo *memo_a = nullptr, bool *apart = nullptr);

}  // namespace pccd::scene
