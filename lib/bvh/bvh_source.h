// The hierarchy candidate source (PCCD_BROAD_BVH): a swept traversal of the two bodies'
// hierarchies (hierarchy.h) under their polynomial motions.
//
// [0, 1] is split recursively into dyadic pieces, earlier half first (so pieces come in
// time order; a piece whose start the sink prunes is skipped with all later ones). On a
// piece [a, b] each body's motion is enclosed (enclose/enclose.h: certified interval bounds
// of R(t) and o(t) over [a, b], Bernstein hulls, a derived rounding-error bound), and a
// node's box [c - h, c + h] is mapped through it to a world box that holds the node's
// elements at every t in [a, b] (enclose::frame_box). A front of node pairs is carried
// from a piece to its halves, starting with the two roots on [0, 1]:
//  - a pair whose world boxes miss is dropped, with both subtrees, for this piece and
//    every sub-piece (no element pair below it meets on [a, b]);
//  - otherwise the larger node (by body-frame size) is split while it is larger than the
//    motion's spread on the piece (enclose::Pose_piece::spread: what the motion adds to
//    a box); a pair of smaller nodes waits in the front for the halves of the piece,
//    on which the spread is smaller;
//  - two leaves stay in the front too, until the piece is final: its spread is at most
//    the bodies' typical feature size, or the front holds at most kLeaf_pairs pairs of
//    leaves and nothing else, or the depth is 24. On a final piece every pair is
//    descended to leaves, and each pair of elements becomes the piece's candidates: a
//    ball pair (SS), ball-triangle (ST, TS), or for two triangles the vertex-triangle
//    (VF, FV) and edge-edge (EE) pairs of their features whose world boxes meet.
// Coverage: a feature pair touching at t lies in a pair of elements (a vertex or edge
// is part of some triangle that has it) whose world boxes meet on every piece holding
// t, and so do the boxes of all their ancestors; so that element pair reaches a final
// piece holding t unless the sink pruned it. A far-apart pair ends with the two roots:
// their boxes over [0, 1] miss, which also holds at t = 0, so the static candidates
// (the triangle pairs meeting at t = 0) are none without a traversal.
// Minimum separation delta > 0 (pccd_config.min_distance): in run() "boxes meet" reads
// "boxes within reach" (enclose::boxes_within: Euclidean box distance <= reach, a double
// >= delta, enclose/enclose.h, reach_of) for nodes, triangles, vertices and edges; a
// feature pair within distance delta at t has points at most delta apart, so its
// boxes, and those of its elements and their ancestors, are within reach on every
// piece holding t, and the argument above holds for "within delta" in place of
// "touching". (Growing A's boxes by reach on every axis, as before issue 33, also kept
// pairs up to sqrt(3) delta apart: a robot's near misses solved 3x the pairs.) The static test (triangles sharing a point at t = 0)
// keeps ungrown boxes: with delta, pairs within delta at t = 0 come from run() (the
// driver solves them with delta from t = 0). A far-apart pair still ends with the
// roots (grown): one box test when the bodies stay more than delta apart per axis.
//
// Threads: a front is processed one level at a time in chunks of a fixed size
// (kChunk), in parallel, and the chunks' outputs are concatenated in chunk order: the
// fronts, the candidates and so the answers do not depend on the number of threads.
#pragma once
#include <memory>

#include "narrow/candidate_source.h"

namespace pccd::bvh {

// reach: the growth of side A's boxes for a minimum separation (enclose::reach_of), 0
// without one.
std::unique_ptr<narrow::Candidate_source> bvh_source(const narrow::Pair_ctx &ctx, double reach = 0);

}  // namespace pccd::bvh
