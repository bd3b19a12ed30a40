// A bounding-volume hierarchy over boxes, rebuilt for every step (the boxes move).
//
// Build: the boxes are ordered along a Morton curve of their centres (30-bit codes,
// 10 bits per axis over the centres' bounding cube, a stable radix sort, so equal codes
// keep index order), cut into leaves of kLeaf consecutive boxes, and a complete binary
// tree in array form above them (node k's children 2k + 1, 2k + 2; the leaves last, in
// curve order, padded with empty boxes to a power of two): O(n) after the sort, no
// pointers. The order only changes how fast a query runs, never what it finds: a
// query visits exactly the boxes that meet it (closed boxes), whatever the order.
#pragma once
#include <cstdint>
#include <vector>

#include "enclose/enclose.h"

namespace pccd::step {

using enclose::Box;

class Box_tree {
 public:
  static constexpr uint32_t kLeaf = 4;

  explicit Box_tree(const std::vector<Box> &boxes);

  // Calls visit(i) for every index i whose box meets q, in a fixed order (a function
  // of the boxes alone).
  template <class F>
  void query(const Box &q, F &&visit) const {
    query_after(q, 0, visit);
  }

  // query, restricted to the boxes at curve positions >= from (a self-join visits each
  // pair once: box i at position p queries with from = p + 1).
  template <class F>
  void query_after(const Box &q, uint32_t from, F &&visit) const {
    if (order_.empty()) return;
    struct Item { uint32_t node, first, end; };  // node and its leaves [first, end)
    Item stack[64];
    int top = 0;
    stack[top++] = {0, 0, first_leaf_ + 1};
    const uint32_t from_leaf = from / kLeaf;
    while (top) {
      const Item it = stack[--top];
      if (it.end <= from_leaf || !enclose::boxes_meet(nodes_[it.node], q)) continue;
      if (it.node >= first_leaf_) {
        const uint32_t leaf = it.node - first_leaf_;
        const uint32_t end = std::min<uint32_t>(static_cast<uint32_t>(order_.size()), (leaf + 1) * kLeaf);
        for (uint32_t j = std::max(leaf * kLeaf, from); j < end; ++j)
          if (enclose::boxes_meet(sorted_[j], q)) visit(order_[j]);
        continue;
      }
      const uint32_t mid = it.first + (it.end - it.first) / 2;
      stack[top++] = {2 * it.node + 2, mid, it.end};
      stack[top++] = {2 * it.node + 1, it.first, mid};
    }
  }

  size_t size() const { return order_.size(); }
  uint32_t at(uint32_t position) const { return order_[position]; }  // index at a curve position

 private:
  std::vector<uint32_t> order_;  // box indices along the curve
  std::vector<Box> sorted_;      // the boxes in that order
  std::vector<Box> nodes_;       // a complete binary tree in array form; leaves last
  uint32_t first_leaf_ = 0;      // nodes_[first_leaf_ + i]: hull of leaf i's boxes
};

}  // namespace pccd::step
