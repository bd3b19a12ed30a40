// The range broad phase of one body pair (paper section 3): the stored side's
// primitives as lifted points in range trees (range/range_tree.h), queried with each
// primitive of the other side per time piece (range/linearize.h).
//
// Contract of candidates(a, b): every feature pair (Prim_pair, narrow.h) that touches at
// some time in the closed piece [a, b] is reported (the linearized conditions are
// necessary, evaluated conservatively); more may be. Pairs of meshes: vertex-triangle
// both ways and edge-edge (the static test at t = 0 is the caller's); sphere sets:
// ball pairs; ball-mesh: ball-triangle by box conditions only (the distance to a plane
// is not linear in the plane's coordinates).
//
// Pieces: [0, 1] is cut into 2^k equal pieces (k <= 6), k chosen so that the query body
// moves (relative to the stored one, float estimate at 17 times) about one feature size
// per piece at most; that choice affects speed only.
#pragma once
#include <memory>
#include <vector>

#include "range/linearize.h"
#include "narrow/pair_ctx.h"
#include "range/range_tree.h"
#include "range/rotation_query.h"
#include "util/thread_pool.h"

namespace pccd::range {

using narrow::Pair_ctx;
using narrow::Prim_pair;
using util::Thread_pool;

// A body's primitives as lifted points (range/linearize.h) in range trees: vertices,
// triangles and edges of a mesh, or the balls of a sphere set. Depends on the body
// only (lifted points are in the body frame), so it is built once per body.
struct Stored_trees : narrow::Body_attachment {
  std::unique_ptr<Range_tree<kDimVertex>> vertices;
  std::unique_ptr<Range_tree<kDimTriangle>> triangles;
  std::unique_ptr<Range_tree<kDimEdge>> edges;
  std::unique_ptr<Range_tree<kDimBall>> balls;
  // Meshes: the Plücker coordinates of each triangle's sides, tested on the triangles the
  // tree reports for a query vertex under a linear translation (a second level).
  std::vector<std::array<Interval, kDimSides>> triangle_sides;
  // Meshes: the endpoints of each edge (the second level of edge-edge under a rotation
  // about a fixed axis, range/rotation_query.h).
  std::vector<std::array<Interval, kDimEnds>> edge_ends;
  explicit Stored_trees(const Body_data &d);
};

// The trees of a body: built on the first call (thread-safe), then shared
// (Body_data::attached).
const Stored_trees &stored_trees(const Body_data &d);

class Range_index {
 public:
  // stored: 0 or 1, the side whose primitives go into the trees.
  Range_index(const Pair_ctx &ctx, int stored);

  // Number of equal time pieces to use.
  int pieces() const { return pieces_; }
  // The candidates of piece [a, b], sorted and unique.
  std::vector<Prim_pair> candidates(double a, double b, Thread_pool &pool) const;
  // Two meshes: every triangle pair (TT) that meets at t = 0, and perhaps more (for
  // the static test), sorted and unique. By edges: two closed triangles meet iff an
  // edge of one meets the other (the extreme points of the intersection of two convex
  // sets lie on their boundaries; a degenerate triangle is the union of its edges). Each
  // triangle of one side is searched in the other side's edge tree (boxes, the line
  // meets the closed triangle: Piece_query::add_triangle_vs_edge_sides), each candidate
  // edge decided exactly (Pair_ctx::edge_meets_triangle_at_zero), and every triangle on
  // a meeting edge is paired with the triangle (a triangle whose three indices are
  // equal, a point, has no edge: it is paired with every triangle its plane clause
  // leaves). So triangles sharing one edge (a fan) cost one exact test each, not one
  // per pair of triangles.
  std::vector<Prim_pair> static_candidates(Thread_pool &pool) const;

 private:
  const Pair_ctx &ctx_;
  int s_;  // stored side
  Relative_motion rel_;
  const Stored_trees &trees_;
  int pieces_ = 1;

  Prim_pair pair(uint8_t stored_is_a_type, uint8_t stored_is_b_type, uint32_t stored,
                 uint32_t query) const;
  // rp: the exact rotation conditions of the piece (nullptr unless rel_.axis_rotation).
  void query_one(const Piece_query &pq, const Rotation_piece *rp, size_t item,
                 std::vector<Prim_pair> &out, std::vector<uint32_t> &scratch) const;
  size_t query_items() const;
  std::vector<uint32_t> near_at_zero(Thread_pool &pool) const;
};

}  // namespace pccd::range
