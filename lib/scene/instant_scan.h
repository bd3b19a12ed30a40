// A robot check's witness scan at one instant (robot.cpp): every body pair, in the
// pairs' order, asked whether some triangle pair certainly touches (with a minimum
// distance: is certainly within delta_lo) at the dyadic instant i / 2^d, by touching_at
// from the roots with `tests` node pairs (link_filter.h). The first pair found gives a
// certain contact at that instant: a witness, which ends decide mode and bounds the
// first contact in first-contact mode. A pair not found says nothing (the budget may
// have run out before its leaves).
// Each body's root box at the instant is made once per pose (a link's is shared by
// each of its pairs), and a pair whose root boxes are not within reach is skipped, as
// touching_at would return at once; side A's node boxes are kept while its pairs follow
// one another at one pose (node_memo.h: one link against each obstacle).
#pragma once
#include <vector>

#include "bvh/hierarchy.h"
#include "scene/link_filter.h"
#include "scene/node_memo.h"
#include "scene/scene.h"

namespace pccd::scene {

class Instant_scan {
 public:
  // bodies: the check's body count (links, then obstacles: Pair_plan's i and j).
  explicit Instant_scan(size_t bodies) : root_pose_(bodies, nullptr), root_box_(bodies) {}

  // side(q, s): pair q's Filter_side of body i (s = 0) or j (s = 1); skip(q): pair q
  // needs no test (its root boxes over [0, 1] are apart). The index of the first pair
  // with a witness (w filled: found, d, i and its triangles), or plans.size() (w.found
  // false).
  template <class Side, class Skip>
  size_t find(const std::vector<Pair_plan> &plans, int d, long i, double reach, double delta_lo, size_t tests,
              Side &&side, Skip &&skip, Witness &w) {
    Node_memo &memo = memo_of_thread();
    w.found = false;
    for (size_t q = 0; q < plans.size(); ++q) {
      const Pair_plan &p = plans[q];
      const Filter_side a = side(q, 0), b = side(q, 1);
      if (!a.data->mesh || !b.data->mesh || !a.has_instant() || !b.has_instant() || skip(q)) continue;
      const enclose::Pose_piece &pa = a.instant(d, i), &pb = b.instant(d, i);
      if (!enclose::boxes_within(root_at(p.i, a, pa), root_at(p.j, b, pb), reach)) continue;
      if (memo_pose_ != &pa || memo_tree_ != a.tree) {
        memo_pose_ = &pa;
        memo_tree_ = a.tree;
        memo.start(a.tree->nodes.size(), a.tree->elems.size());
      }
      size_t budget = tests;
      if (touching_at(*a.data, pa, *b.data, pb, kRoots, budget, w.a, w.b, reach, delta_lo, a.tree, b.tree, &memo)) {
        w.found = true;
        w.depth = d;
        w.index = i;
        return q;
      }
    }
    return plans.size();
  }

 private:
  // Per thread: its slots are not reallocated per check; start() forgets every box.
  static Node_memo &memo_of_thread() {
    thread_local Node_memo memo;
    return memo;
  }
  const enclose::Box &root_at(size_t k, const Filter_side &s, const enclose::Pose_piece &pose) {
    if (root_pose_[k] != &pose) {
      root_pose_[k] = &pose;
      root_box_[k] = enclose::frame_box(pose, s.tree->nodes[0].c, s.tree->nodes[0].h);
    }
    return root_box_[k];
  }
  std::vector<const enclose::Pose_piece *> root_pose_;
  std::vector<enclose::Box> root_box_;
  const enclose::Pose_piece *memo_pose_ = nullptr;
  const bvh::Hierarchy *memo_tree_ = nullptr;
};

}  // namespace pccd::scene
