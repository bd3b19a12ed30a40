// A bounding-volume hierarchy over boxes, rebuilt for every step (the boxes move).
//
// Build: the boxes are ordered along a Morton curve of their centres (30-bit codes,
// 10 bits per axis over the centres' bounding box, a stable radix sort, so equal codes
// keep index order), cut into leaves of kLeaf consecutive boxes, and the levels above
// are hulls of adjacent pairs: an implicit balanced tree, O(n) after the sort, with no
// pointers. The order only changes how fast a query runs, never what it finds: a
// query visits exactly the boxes that meet it (closed boxes), whatever the order.
#pragma once
#include <cstdint>
#include <vector>

#include "boxes/boxes.h"

namespace pccd::step {

using boxes::Box;

class Box_tree {
 public:
  static constexpr uint32_t kLeaf = 4;

  explicit Box_tree(const std::vector<Box> &boxes);

  // Calls visit(i) for every index i whose box meets q, in a fixed order (a function
  // of the boxes alone).
  template <class F>
  void query(const Box &q, F &&visit) const {
    if (order_.empty()) return;
    struct Item { uint32_t level, index; };
    Item stack[64];
    int top = 0;
    stack[top++] = {static_cast<uint32_t>(levels_.size() - 1), 0};
    while (top) {
      const Item it = stack[--top];
      if (!boxes::boxes_meet(levels_[it.level][it.index], q)) continue;
      if (it.level == 0) {
        const uint32_t end = std::min<uint32_t>(static_cast<uint32_t>(order_.size()), (it.index + 1) * kLeaf);
        for (uint32_t k = it.index * kLeaf; k < end; ++k)
          if (boxes::boxes_meet(sorted_[k], q)) visit(order_[k]);
        continue;
      }
      const uint32_t c = 2 * it.index, below = it.level - 1;
      if (c + 1 < levels_[below].size()) stack[top++] = {below, c + 1};
      stack[top++] = {below, c};
    }
  }

 private:
  std::vector<uint32_t> order_;          // box indices along the curve
  std::vector<Box> sorted_;              // the boxes in that order
  std::vector<std::vector<Box>> levels_; // levels_[0][i]: hull of leaf i; top: the root
};

}  // namespace pccd::step
