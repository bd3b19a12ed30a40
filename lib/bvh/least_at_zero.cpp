#include "bvh/least_at_zero.h"

#include <algorithm>
#include <unordered_set>
#include <vector>

#include "bvh/hierarchy.h"
#include "enclose/enclose.h"
#include "util/work_budget.h"

namespace pccd::bvh {

using enclose::Box;
using narrow::Prim_pair;

namespace {

// A heap entry: a node pair (x, y) keyed by a lower bound of its feature pairs' keys,
// or a feature pair (its own key; x, y unused).
struct Entry {
  uint64_t key;
  uint32_t x, y;
  bool feature;
};
// std heaps put the greatest first: "greater" puts the least key first (a feature pair
// before a node pair of the same bound; either order is correct: least_at_zero.h).
bool after(const Entry &p, const Entry &q) {
  return p.key != q.key ? p.key > q.key : (!p.feature && q.feature);
}

// Pops, and exact tests, handled per work step (util/work_budget.h; 256 tests: as the
// driver's pass, scene/pair_search.cpp, within_at_zero, did per chunk).
constexpr size_t kStepPops = 4096, kStepTests = 256;

class Search {
 public:
  Search(const narrow::Pair_ctx &ctx, double reach)
      : ctx_(ctx), H_{&hierarchy(*ctx.side(0).data), &hierarchy(*ctx.side(1).data)}, reach_(reach) {
    for (int s = 0; s < 2; ++s) pose_[s] = enclose::enclose_pose(ctx.side(s), 0.0, 0.0);
  }

  std::optional<Prim_pair> run(const pred::Solve_options &opt, uint64_t &tests) {
    if (H_[0]->least.empty() || H_[1]->least.empty() || H_[0]->elems.empty() || H_[1]->elems.empty())
      return std::nullopt;
    push_nodes(0, 0);
    std::unordered_set<uint64_t> tested;  // a vertex or edge is in several triangles
    for (size_t pops = 0; !heap_.empty(); ++pops) {
      if (pops % kStepPops == 0) util::work_step();
      std::pop_heap(heap_.begin(), heap_.end(), after);
      const Entry e = heap_.back();
      heap_.pop_back();
      if (e.feature) {
        const Prim_pair p = of_key(e.key);
        if (!tested.insert(e.key).second) continue;
        if (tested.size() % kStepTests == 0) util::work_step();
        ++tests;
        if (ctx_.within_at_zero(p, opt)) return p;
        continue;
      }
      const Node &nx = H_[0]->nodes[e.x], &ny = H_[1]->nodes[e.y];
      if (nx.leaf() && ny.leaf()) {
        for (uint32_t i = nx.first; i < nx.first + nx.count; ++i)
          for (uint32_t j = ny.first; j < ny.first + ny.count; ++j) features(H_[0]->elems[i], H_[1]->elems[j]);
        continue;
      }
      // The larger node (by body-frame size) is split, as the swept traversal does.
      const bool split_x = !nx.leaf() && (ny.leaf() || H_[0]->size(e.x) >= H_[1]->size(e.y));
      for (uint32_t c = 0; c < 2; ++c)
        split_x ? push_nodes(nx.first + c, e.y) : push_nodes(e.x, ny.first + c);
    }
    return std::nullopt;
  }

 private:
  const narrow::Pair_ctx &ctx_;
  const Hierarchy *H_[2];
  const double reach_;
  enclose::Pose_piece pose_[2];
  std::vector<Entry> heap_;

  static Prim_pair of_key(uint64_t key) {
    constexpr uint64_t kMask = (uint64_t(1) << 29) - 1;
    return {static_cast<uint8_t>(key >> 58), static_cast<uint32_t>((key >> 29) & kMask),
            static_cast<uint32_t>(key & kMask)};
  }

  void push(uint64_t key, uint32_t x, uint32_t y, bool feature) {
    heap_.push_back({key, x, y, feature});
    std::push_heap(heap_.begin(), heap_.end(), after);
  }

  // The node pair when its world boxes at t = 0 are within reach, keyed by the VF key of
  // the least vertex below x and the least triangle below y (least_at_zero.h).
  void push_nodes(uint32_t x, uint32_t y) {
    const Node &nx = H_[0]->nodes[x], &ny = H_[1]->nodes[y];
    if (!enclose::boxes_within(enclose::frame_box(pose_[0], nx.c, nx.h), enclose::frame_box(pose_[1], ny.c, ny.h),
                               reach_))
      return;
    push(Prim_pair{narrow::VF, H_[0]->least[x][0], H_[1]->least[y][2]}.key(), x, y, false);
  }

  // The feature pairs of triangles ea (A) and eb (B) whose boxes at t = 0 are within
  // reach (bvh_source.cpp, features, on the piece [0, 0]).
  void features(uint32_t ea, uint32_t eb) {
    const narrow::Moving_body *side[2] = {&ctx_.side(0), &ctx_.side(1)};
    const uint32_t tri[2] = {ea, eb};
    Box vb[2][3], tb[2];
    for (int s = 0; s < 2; ++s) {
      const auto &t = side[s]->mesh->triangles()[tri[s]];
      for (int k = 0; k < 3; ++k) vb[s][k] = enclose::point_box(pose_[s], side[s]->data->pts[t[k]], side[s]->data->pt_err);
      tb[s] = enclose::hull(enclose::hull(vb[s][0], vb[s][1]), vb[s][2]);
    }
    const auto &TA = side[0]->mesh->triangles()[ea], &TB = side[1]->mesh->triangles()[eb];
    for (int k = 0; k < 3; ++k) {
      if (enclose::boxes_within(vb[0][k], tb[1], reach_)) push(Prim_pair{narrow::VF, TA[k], eb}.key(), 0, 0, true);
      if (enclose::boxes_within(tb[0], vb[1][k], reach_)) push(Prim_pair{narrow::FV, ea, TB[k]}.key(), 0, 0, true);
    }
    const auto &EA = side[0]->data->tri_edges[ea], &EB = side[1]->data->tri_edges[eb];
    for (int i = 0; i < 3; ++i) {
      if (EA[i] < 0) continue;
      const Box ba = enclose::hull(vb[0][i], vb[0][(i + 1) % 3]);
      for (int j = 0; j < 3; ++j)
        if (EB[j] >= 0 && enclose::boxes_within(ba, enclose::hull(vb[1][j], vb[1][(j + 1) % 3]), reach_))
          push(Prim_pair{narrow::EE, uint32_t(EA[i]), uint32_t(EB[j])}.key(), 0, 0, true);
    }
  }
};

}  // namespace

std::optional<Prim_pair> least_within_at_zero(const narrow::Pair_ctx &ctx, const pred::Solve_options &opt,
                                              double reach, uint64_t &tests) {
  return Search(ctx, reach).run(opt, tests);
}

}  // namespace pccd::bvh
