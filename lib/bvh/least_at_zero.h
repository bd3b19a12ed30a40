// The feature pair of least key within the minimum separation at t = 0: a search of two
// meshes' hierarchies (hierarchy.h) at the poses of t = 0, in key order.
//
// What it finds: among the feature pairs the hierarchy source lists (bvh_source.h: VF
// of a vertex of some triangle of A and a triangle of B, FV likewise, EE of two
// triangles' edges; the brute source's surface vertices and edges are the same sets),
// the one of least narrow::Prim_pair::key (type, then a, then b) that
// narrow::Pair_ctx::within_at_zero certifies within delta at t = 0 (exact), or none.
// That is the pair the driver solves as a body pair's contact at t = 0 with a minimum
// separation (scene/pair_search.cpp, within_at_zero); before this search it listed every
// candidate of the piece holding 0, sorted them by key and tested them in that order
// (issue 33: 180k-320k feature pairs within 5 cm of a UR5 self pair, most of a segment
// within delta at t = 0).
//
// How: best first over node pairs whose world boxes at t = 0 (enclose::enclose_pose on
// [0, 0], frame_box) are within reach (enclose::boxes_within, a double >= delta), each
// keyed by a lower bound of the keys below it: the VF key of the least vertex of A's node
// and least triangle of B's node (Hierarchy::least; VF is the least type, and a
// descendant's least indices are never smaller). A leaf pair pushes its feature pairs
// whose boxes are within reach (the tests of bvh_source.cpp's features), each keyed by
// its own key; a feature pair popped is tested exactly. When one is certified within
// delta, every entry left has a key at least its own, so it is the least.
// Coverage: a feature pair within delta at t = 0 has points at most delta apart then,
// so its boxes and those of its elements' ancestors at t = 0 are within reach (as
// bvh_source.h, "Coverage", on a piece holding 0): the search reaches it.
//
// Sequential: its answer is unique (a minimum), so it does not depend on threads.
#pragma once
#include <cstdint>
#include <optional>

#include "narrow/pair_ctx.h"

namespace pccd::bvh {

// Two meshes with finite bounds (not narrow::has_infinite_bounds); reach: enclose::
// reach_of(opt.delta) > 0. tests: incremented per exact test (Search_stats::static_tests).
std::optional<narrow::Prim_pair> least_within_at_zero(const narrow::Pair_ctx &ctx, const pred::Solve_options &opt,
                                                      double reach, uint64_t &tests);

}  // namespace pccd::bvh
