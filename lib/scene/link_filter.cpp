#include "scene/link_filter.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "bvh/hierarchy.h"
#include "util/work_budget.h"

namespace pccd::scene {

namespace {

using Front = std::vector<std::pair<uint32_t, uint32_t>>;

// What the piece's motion adds to a box of the body (boxes::Pose_piece::spread's bound,
// recomputed here for poses made without it): |R(t) - Rm| |x| + orad over the body.
double spread_of(const boxes::Pose_piece &p, const narrow::Body_data &d) {
  if (!p.finite) return HUGE_VAL;
  double rr = 0, orad = 0;
  for (int i = 0; i < 3; ++i) {
    orad = std::max(orad, p.orad[i]);
    for (int j = 0; j < 3; ++j) rr = std::max(rr, p.Rr[i][j]);
  }
  return 3 * rr * d.reach + orad;
}

}  // namespace

double first_uncleared(const narrow::Body_data &A, const Pose_of &pose_a, const narrow::Body_data &B,
                       const Pose_of &pose_b, double reach) {
  const bvh::Hierarchy &ha = bvh::hierarchy(A), &hb = bvh::hierarchy(B);
  struct Item {
    int d;
    long i;
    Front front;
  };
  std::vector<Item> stack;
  stack.push_back({0, 0, Front{{0, 0}}});
  Front next, work;
  while (!stack.empty()) {
    Item it = std::move(stack.back());
    stack.pop_back();
    const boxes::Pose_piece &pa = pose_a(it.d, it.i), &pb = pose_b(it.d, it.i);
    const double spread = std::max(spread_of(pa, A), spread_of(pb, B));
    util::work_step(1 + it.front.size() / 1024);
    next.clear();
    work = std::move(it.front);
    while (!work.empty()) {
      const auto [ka, kb] = work.back();
      work.pop_back();
      boxes::Box x = boxes::frame_box(pa, ha.nodes[ka].c, ha.nodes[ka].h);
      if (reach > 0) x = boxes::grow(x, reach);
      if (!boxes::boxes_meet(x, boxes::frame_box(pb, hb.nodes[kb].c, hb.nodes[kb].h))) continue;
      const bool la = ha.nodes[ka].leaf(), lb = hb.nodes[kb].leaf();
      const double sa = la ? -1 : ha.size(ka), sb = lb ? -1 : hb.size(kb);
      if (std::max(sa, sb) <= spread || (la && lb)) {
        next.push_back({ka, kb});  // waits for the halves of the piece
        if (next.size() > kMax_front) return std::ldexp(static_cast<double>(it.i), -it.d);
      } else if (sb > sa) {
        const uint32_t c = hb.nodes[kb].first;
        work.push_back({ka, c + 1});
        work.push_back({ka, c});
      } else {
        const uint32_t c = ha.nodes[ka].first;
        work.push_back({c + 1, kb});
        work.push_back({c, kb});
      }
    }
    if (next.empty()) continue;  // separated on this piece
    if (it.d == kMax_depth) return std::ldexp(static_cast<double>(it.i), -it.d);  // exact
    stack.push_back({it.d + 1, 2 * it.i + 1, next});
    stack.push_back({it.d + 1, 2 * it.i, std::move(next)});
    next = Front();
  }
  return kNever;
}

}  // namespace pccd::scene
