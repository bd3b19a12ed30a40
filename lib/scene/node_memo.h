// The boxes first_uncleared (link_filter.h) computes for one side on one piece, each
// computed once per piece and kept until the next: a node's world box and a leaf's
// element boxes. A node appears in many node pairs of a front (each of its partners on
// the other side), and recomputing its box per pair was most of a robot check's filter
// time (issue 30: enclose::frame_box and the element boxes, per pair). The memo only
// stores what the caller computed for this piece: it decides nothing.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "enclose/enclose.h"

namespace pccd::scene {

class Node_memo {
 public:
  // Slots for a hierarchy of nodes nodes and elems leaf elements; forgets every box.
  // Memory: 8 bytes per node and per element (an eighth of the hierarchy's own), plus
  // the boxes made on one piece (kept in pools that only grow to a piece's demand).
  void start(size_t nodes, size_t elems) {
    if (node_at_.size() < nodes) node_at_.resize(nodes, {0, 0});
    if (elem_at_.size() < elems) elem_at_.resize(elems, {0, 0});
    next_piece();
  }
  // A new piece: every stored box is forgotten (an O(1) stamp; a full clear on wrap).
  void next_piece() {
    node_pool_.clear();
    elem_pool_.clear();
    if (++gen_ == 0) {
      std::fill(node_at_.begin(), node_at_.end(), Slot{0, 0});
      std::fill(elem_at_.begin(), elem_at_.end(), Slot{0, 0});
      gen_ = 1;
    }
  }
  // Node k's box on this piece: make() on the first demand.
  template <class Make>
  const enclose::Box &node(uint32_t k, Make &&make) {
    Slot &s = node_at_[k];
    if (s.gen != gen_) {  // the slot is set after make(): a throw leaves no stale slot
      node_pool_.push_back(make());
      s = {gen_, static_cast<uint32_t>(node_pool_.size() - 1)};
    }
    return node_pool_[s.at];
  }
  // The element boxes of the leaf whose element sits at slot e (its first index into
  // Hierarchy::elems): make(out) fills up to 6 and returns how many, on the first demand.
  template <class Make>
  const enclose::Box *elements(uint32_t e, int &count, Make &&make) {
    Slot &s = elem_at_[e];
    if (s.gen != gen_) {
      Elements x;
      x.n = make(x.box.data());
      elem_pool_.push_back(x);
      s = {gen_, static_cast<uint32_t>(elem_pool_.size() - 1)};
    }
    count = elem_pool_[s.at].n;
    return elem_pool_[s.at].box.data();
  }

 private:
  struct Slot {
    uint32_t gen, at;  // valid on the piece of generation gen: the pool's entry at
  };
  struct Elements {
    std::array<enclose::Box, 6> box;
    int n = 0;
  };
  uint32_t gen_ = 0;
  std::vector<Slot> node_at_, elem_at_;
  std::vector<enclose::Box> node_pool_;
  std::vector<Elements> elem_pool_;
};

}  // namespace pccd::scene
