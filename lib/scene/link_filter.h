// The certified filter of a robot check (robot.h): which body pairs may touch over a
// segment, and from when, decided on pose enclosures alone, before any exact motion is
// built.
//
// A body on a time piece [a, b] is given by a enclose::Pose_piece: for a robot link the
// interval pose of motion/chain_path.h (straight from the joint path) in midpoint-radius
// form, for an obstacle enclose::enclose_pose of its exact motion. A node's world box over
// the piece is enclose::frame_box of its body-frame box (hierarchy.h): it holds the node's
// elements at every t of the piece.
//
// first_uncleared: a swept traversal of the two hierarchies over dyadic pieces of
// [0, 1], earlier half first, carrying a front of node pairs from a piece to its halves
// (as bvh/bvh_source.h does with exact-motion enclosures): a node pair whose world boxes
// miss is dropped with both subtrees for the piece and its sub-pieces; a meeting pair
// splits its larger node while that node is larger than the piece's spread (what the
// motion adds to a box), else waits for the halves. A piece whose front empties is
// separated: no element pair touches at any t of it (a touching pair of elements lies
// in leaves whose boxes, and whose ancestors' boxes, all meet on every piece holding
// that t). A front that outgrows kMax_front on a piece hands its unprocessed pairs to
// the halves as they are (each may still meet: nothing is dropped unseparated). The
// first piece that is still not separated at depth kMax_depth, or whose front outgrows
// 16 kMax_front, or that starts after kMax_tests front pairs were taken for the body
// pair (overlapping links hold a front of thousands at t = 0 on every depth), gives its
// start: a certified lower bound of the pair's
// contact times (every earlier time lies in a separated piece). kNever (> 1) when every
// piece is separated: the pair never touches on [0, 1].
// Minimum separation: side A's boxes grow by reach (enclose::reach_of), so "touch" reads
// "come within delta" throughout.
#pragma once
#include <functional>

#include "enclose/enclose.h"

namespace pccd::scene {

constexpr int kMax_depth = 14;         // pieces of 1/16384 at the finest
constexpr size_t kMax_front = 4096;    // node pairs per piece (then: not separated)
constexpr size_t kMax_tests = 1 << 16;  // front pairs per body pair (then: the piece's start)
constexpr double kNever = 2.0;         // first_uncleared: no contact on [0, 1]

// The pose of one side on the dyadic piece (depth, index): [index / 2^depth,
// (index + 1) / 2^depth].
using Pose_of = std::function<const enclose::Pose_piece &(int depth, long index)>;

double first_uncleared(const narrow::Body_data &A, const Pose_of &pose_a, const narrow::Body_data &B,
                       const Pose_of &pose_b, double reach);

}  // namespace pccd::scene
