// Node memos (node_memo.h) kept from one first_uncleared call to the next for one side:
// the robot check runs a link's pairs one after the other (the link against each
// obstacle, against each later link), and each pair's traversal made the link's node
// and element boxes again on the same pieces (issue 30, round two). A side that carries
// a share key (Filter_side::share, nonzero) names poses that stay fixed while the key
// does: the same key, data, hierarchy, base and link give the same Side_piece on every
// piece, so a box made by the same function from it is the same box. The set keeps the
// memos of the last kSlots pieces seen for the last such side (round robin); any other
// side forgets them all. It stores what the caller computed: it decides nothing.
#pragma once
#include <array>
#include <cstdint>

#include "bvh/hierarchy.h"
#include "scene/link_filter.h"
#include "scene/node_memo.h"

namespace pccd::scene {

class Shared_memos {
 public:
  // Slots per side. A free Panda segment's pairs mostly end on the first few pieces of
  // the depth-first order ([0, 1], its halves, quarters); 8 hold those.
  static constexpr int kSlots = 8;

  // The memo of piece (depth, index) for side s, its boxes kept when the last call's
  // side was the same one and the piece is still held; else an emptied slot.
  Node_memo &at(const Filter_side &s, const bvh::Hierarchy &h, int depth, long index) {
    const Owner o{s.share, s.data, &h, s.src, s.base, s.k};
    if (!(o == owner_)) {
      owner_ = o;
      for (Slot &x : slot_) x.depth = -1;
    }
    for (Slot &x : slot_)
      if (x.depth == depth && x.index == index) return x.memo;
    Slot &x = slot_[next_];
    next_ = (next_ + 1) % kSlots;
    x.depth = -1;  // until start() returns (a throw leaves the slot empty)
    x.memo.start(h.nodes.size(), h.elems.size());
    x.depth = depth;
    x.index = index;
    return x.memo;
  }
  // Forget every piece (a call whose side has no share key).
  void forget() { owner_ = Owner{}; }

 private:
  struct Owner {
    uint64_t share = 0;
    const void *data = nullptr, *tree = nullptr, *src = nullptr;
    long base = -1;
    size_t k = 0;
    bool operator==(const Owner &o) const {
      return share == o.share && data == o.data && tree == o.tree && src == o.src && base == o.base && k == o.k;
    }
  };
  struct Slot {
    int depth = -1;
    long index = 0;
    Node_memo memo;
  };
  Owner owner_;
  std::array<Slot, kSlots> slot_;
  int next_ = 0;
};

}  // namespace pccd::scene
