// The working memory of first_uncleared (link_filter.h), kept per thread so that a call
// allocates nothing once a call as large has run on its thread (issue 30: the stack's
// per-piece vectors were allocations per piece). It stores, it decides nothing.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/link_filter.h"
#include "scene/node_memo.h"
#include "scene/shared_memo.h"

namespace pccd::scene {

// The stack of pieces still to look at, each with its front in one of fronts (those not
// in use listed in unused), and the node memos. Reset at each call's start (a call
// ended by an exception leaves it as it was).
struct Scratch {
  struct Item {
    int d;
    long i;
    uint32_t f;  // its front: fronts[f]
  };
  std::vector<Item> stack;
  std::vector<Node_pairs> fronts;
  std::vector<uint32_t> unused;
  Node_pairs next, work;
  Node_memo memo_a, memo_b;
  Shared_memos shared_a;  // side A's memos across calls (Filter_side::share)
  void start() {
    stack.clear();
    unused.clear();
    for (uint32_t k = 0; k < fronts.size(); ++k) unused.push_back(k);
  }
  // A front holding a copy of f (its buffer reused).
  uint32_t take(const Node_pairs &f) {
    if (unused.empty()) {
      fronts.emplace_back();
      unused.push_back(static_cast<uint32_t>(fronts.size() - 1));
    }
    const uint32_t k = unused.back();
    unused.pop_back();
    fronts[k].assign(f.begin(), f.end());
    return k;
  }
  void give_back(uint32_t k) { unused.push_back(k); }
};

}  // namespace pccd::scene
