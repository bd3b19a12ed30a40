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
  void start(size_t nodes, size_t elems) {
    if (node_gen_.size() < nodes) {
      node_.resize(nodes);
      node_gen_.resize(nodes, 0);
    }
    if (elem_gen_.size() < elems) {
      elem_.resize(elems);
      elem_n_.resize(elems, 0);
      elem_gen_.resize(elems, 0);
    }
    next_piece();
  }
  // A new piece: every stored box is forgotten (an O(1) stamp; a full clear on wrap).
  void next_piece() {
    if (++gen_ == 0) {
      std::fill(node_gen_.begin(), node_gen_.end(), 0);
      std::fill(elem_gen_.begin(), elem_gen_.end(), 0);
      gen_ = 1;
    }
  }
  // Node k's box on this piece: make() on the first demand.
  template <class Make>
  const enclose::Box &node(uint32_t k, Make &&make) {
    if (node_gen_[k] != gen_) {
      node_[k] = make();
      node_gen_[k] = gen_;
    }
    return node_[k];
  }
  // The element boxes of the leaf whose element sits at slot s (its first index into
  // Hierarchy::elems): make(out) fills up to 6 and returns how many, on the first demand.
  template <class Make>
  const enclose::Box *elements(uint32_t s, int &count, Make &&make) {
    if (elem_gen_[s] != gen_) {
      elem_n_[s] = static_cast<uint8_t>(make(elem_[s].data()));
      elem_gen_[s] = gen_;
    }
    count = elem_n_[s];
    return elem_[s].data();
  }

 private:
  uint32_t gen_ = 0;
  std::vector<enclose::Box> node_;
  std::vector<uint32_t> node_gen_;
  std::vector<std::array<enclose::Box, 6>> elem_;
  std::vector<uint8_t> elem_n_;
  std::vector<uint32_t> elem_gen_;
};

}  // namespace pccd::scene
