#include "bvh/bvh_source.h"

#include <cmath>

#include <algorithm>

#include "enclose/enclose.h"
#include "bvh/hierarchy.h"

namespace pccd::bvh {

using enclose::Box;
using enclose::Pose_piece;
using narrow::Candidate_sink;
using narrow::Moving_body;
using narrow::Pair_ctx;
using narrow::Prim_pair;
using narrow::Search_stats;

namespace {

constexpr int kMax_depth = 24;       // pieces of width 2^-24 at most (as boxes/box_source.h)
constexpr size_t kLeaf_pairs = 64;   // a front of at most this many leaf pairs is final
constexpr size_t kChunk = 2048;      // node pairs per parallel task (fixed: determinism)

struct Node_pair {
  uint32_t x, y;  // node of side A's hierarchy, node of side B's
};

// What one level of the traversal makes of a chunk of node pairs.
struct Step_out {
  std::vector<Node_pair> open;    // children pairs, for the next level
  std::vector<Node_pair> wait;    // pairs left for the halves of the piece
  std::vector<Node_pair> leaves;  // pairs of leaves whose boxes meet
};

class Bvh_source final : public narrow::Candidate_source {
 public:
  Bvh_source(const Pair_ctx &ctx, double reach)
      : ctx_(ctx), H_{&hierarchy(*ctx.side(0).data), &hierarchy(*ctx.side(1).data)}, reach_(reach) {}

  // The triangle pairs whose boxes meet at t = 0. None when the root boxes miss over
  // all of [0, 1] (they hold the bodies at t = 0 too): a far-apart pair costs the two
  // enclosures of the whole piece (enclose::whole_pose: once per body, for all its pairs
  // and for run()) and one box test. The static
  // test asks for triangles sharing a point whatever the minimum separation, so its
  // boxes are not grown (pairs within delta at t = 0 are run()'s, solved with delta).
  std::vector<Prim_pair> static_candidates(util::Thread_pool &pool) override {
    const Pose_piece whole[2] = {enclose::whole_pose(ctx_.side(0)), enclose::whole_pose(ctx_.side(1))};
    if (!roots_meet(whole, 0.0)) return {};
    const Pose_piece pose[2] = {enclose::enclose_pose(ctx_.side(0), 0.0, 0.0),
                                enclose::enclose_pose(ctx_.side(1), 0.0, 0.0)};
    std::vector<Node_pair> leaves, wait;
    traverse(pose, true, 0.0, 0.0, {{0, 0}}, leaves, wait, pool);
    std::vector<Prim_pair> cand;
    for (const Node_pair &p : leaves) elements(p, [&](uint32_t ea, uint32_t eb) {
      cand.push_back({narrow::TT, ea, eb});
    });
    return cand;
  }

  void run(Candidate_sink &sink, Search_stats &stats, util::Thread_pool &pool) override {
    sink_ = &sink;
    stats_ = &stats;
    pool_ = &pool;
    feature_ = std::min(ctx_.side(0).data->feature, ctx_.side(1).data->feature);
    piece(0.0, 1.0, 0, {{0, 0}}, HUGE_VAL);
  }

 private:
  const Pair_ctx &ctx_;
  const Hierarchy *H_[2];
  Candidate_sink *sink_ = nullptr;
  Search_stats *stats_ = nullptr;
  util::Thread_pool *pool_ = nullptr;
  // Node, triangle, vertex and edge boxes are kept when within reach_ (enclose::boxes_within;
  // reach_of: a double >= the minimum separation delta, 0 without one) in run(), so
  // every feature pair within delta at t keeps them, with its ancestors', on every
  // piece holding t (bvh_source.h, "Coverage").
  const double reach_;
  double feature_ = 0;  // the bodies' typical feature size (final-piece test)

  bool roots_meet(const Pose_piece pose[2], double reach) const {
    return enclose::boxes_meet(node_box(0, pose[0], 0, reach), node_box(1, pose[1], 0, 0.0));
  }

  // The world box of node k of side s over the piece, grown by reach.
  Box node_box(int s, const Pose_piece &pose, uint32_t k, double reach) const {
    const Node &n = H_[s]->nodes[k];
    const Box b = enclose::frame_box(pose, n.c, n.h);
    return reach > 0 ? enclose::grow(b, reach) : b;
  }

  // Calls f(ea, eb) for each element pair of the leaf pair p.
  template <class F>
  void elements(const Node_pair &p, F &&f) const {
    const Node &x = H_[0]->nodes[p.x], &y = H_[1]->nodes[p.y];
    for (uint32_t i = x.first; i < x.first + x.count; ++i)
      for (uint32_t j = y.first; j < y.first + y.count; ++j) f(H_[0]->elems[i], H_[1]->elems[j]);
  }

  // One level on pairs p[0 .. n): final pieces split every pair down to leaves; other
  // pieces only split nodes larger than thresh (the motion's spread). Node pairs are
  // kept when within reach (enclose::boxes_within).
  void step(const Pose_piece pose[2], bool final, double thresh, double reach, const Node_pair *p,
            size_t n, Step_out &out) const {
    for (size_t i = 0; i < n; ++i) {
      const uint32_t x = p[i].x, y = p[i].y;
      if (!enclose::boxes_within(node_box(0, pose[0], x, 0.0), node_box(1, pose[1], y, 0.0), reach)) continue;
      const Node &nx = H_[0]->nodes[x], &ny = H_[1]->nodes[y];
      if (nx.leaf() && ny.leaf()) {
        out.leaves.push_back(p[i]);
        continue;
      }
      const double sx = H_[0]->size(x), sy = H_[1]->size(y);
      const bool split_x = !nx.leaf() && (ny.leaf() || sx >= sy);
      if (!final && (split_x ? sx : sy) <= thresh) {
        out.wait.push_back(p[i]);
        continue;
      }
      if (split_x) {
        out.open.push_back({nx.first, y});
        out.open.push_back({nx.first + 1, y});
      } else {
        out.open.push_back({x, ny.first});
        out.open.push_back({x, ny.first + 1});
      }
    }
  }

  // The traversal of a front on one piece, level by level (bvh_source.h, "Threads").
  void traverse(const Pose_piece pose[2], bool final, double thresh, double reach,
                std::vector<Node_pair> front,
                std::vector<Node_pair> &leaves, std::vector<Node_pair> &wait,
                util::Thread_pool &pool) const {
    while (!front.empty()) {
      const size_t chunks = (front.size() + kChunk - 1) / kChunk;
      std::vector<Step_out> out(chunks);
      auto run_chunk = [&](size_t c) {
        util::work_step();  // one chunk of node pairs (util/work_budget.h)
        const size_t b = c * kChunk, e = std::min(front.size(), b + kChunk);
        step(pose, final, thresh, reach, front.data() + b, e - b, out[c]);
      };
      if (chunks == 1) run_chunk(0);
      else pool.parallel_for(chunks, run_chunk);
      front.clear();
      for (Step_out &o : out) {
        front.insert(front.end(), o.open.begin(), o.open.end());
        wait.insert(wait.end(), o.wait.begin(), o.wait.end());
        leaves.insert(leaves.end(), o.leaves.begin(), o.leaves.end());
      }
    }
  }

  void piece(double a, double b, int depth, std::vector<Node_pair> front, double parent_spread) {
    util::work_step();  // one time piece (util/work_budget.h)
    if (sink_->pruned(a)) return;
    ++stats_->pieces;
    Pose_piece pose[2];
    for (int s = 0; s < 2; ++s)
      pose[s] = depth == 0 ? enclose::whole_pose(ctx_.side(s)) : enclose::enclose_pose(ctx_.side(s), a, b);
    const double spread = std::max(pose[0].spread, pose[1].spread);
    bool final = depth >= kMax_depth || spread <= feature_ || enclose::spread_stalled(depth, spread, parent_spread);
    if (!final && front.size() <= kLeaf_pairs) {
      final = true;
      for (const Node_pair &p : front) final = final && H_[0]->nodes[p.x].leaf() && H_[1]->nodes[p.y].leaf();
    }
    std::vector<Node_pair> leaves, wait;
    traverse(pose, final, spread, reach_, std::move(front), leaves, wait, *pool_);
    if (wait.empty() && (final || leaves.size() <= kLeaf_pairs)) {
      if (!leaves.empty()) emit(a, b, pose, leaves);
      return;
    }
    wait.insert(wait.end(), leaves.begin(), leaves.end());
    const double m = 0.5 * (a + b);  // exact: dyadic pieces
    piece(a, m, depth + 1, wait, spread);
    piece(m, b, depth + 1, std::move(wait), spread);
  }

  // The candidates of a final piece: the feature pairs of its element pairs.
  void emit(double a, double b, const Pose_piece pose[2], const std::vector<Node_pair> &leaves) {
    ++stats_->leaves;
    const size_t chunks = (leaves.size() + kChunk - 1) / kChunk;
    std::vector<std::vector<Prim_pair>> out(chunks);
    auto run_chunk = [&](size_t c) {
      util::work_step();  // one chunk of leaf pairs
      const size_t e = std::min(leaves.size(), (c + 1) * kChunk);
      for (size_t i = c * kChunk; i < e; ++i)
        elements(leaves[i], [&](uint32_t ea, uint32_t eb) { features(pose, ea, eb, out[c]); });
    };
    if (chunks == 1) run_chunk(0);
    else pool_->parallel_for(chunks, run_chunk);
    std::vector<Prim_pair> cand;
    for (auto &o : out) cand.insert(cand.end(), o.begin(), o.end());
    stats_->candidates += cand.size();
    sink_->piece(a, b, std::move(cand));
  }

  // The feature pairs of elements ea (side A) and eb (side B) on a piece.
  void features(const Pose_piece pose[2], uint32_t ea, uint32_t eb, std::vector<Prim_pair> &out) const {
    const Moving_body &A = ctx_.side(0), &B = ctx_.side(1);
    if (!A.is_mesh() || !B.is_mesh()) {
      out.push_back({!A.is_mesh() && !B.is_mesh() ? narrow::SS : !A.is_mesh() ? narrow::ST : narrow::TS,
                     ea, eb});
      return;
    }
    const Moving_body *side[2] = {&A, &B};
    const uint32_t tri[2] = {ea, eb};
    Box vb[2][3], tb[2];
    for (int s = 0; s < 2; ++s) {
      const auto &t = side[s]->mesh->triangles()[tri[s]];
      for (int k = 0; k < 3; ++k) {
        vb[s][k] = enclose::point_box(pose[s], side[s]->data->pts[t[k]], side[s]->data->pt_err);
      }
      tb[s] = enclose::hull(enclose::hull(vb[s][0], vb[s][1]), vb[s][2]);
    }
    const auto &TA = A.mesh->triangles()[ea], &TB = B.mesh->triangles()[eb];
    for (int k = 0; k < 3; ++k) {
      if (enclose::boxes_within(vb[0][k], tb[1], reach_)) out.push_back({narrow::VF, TA[k], eb});
      if (enclose::boxes_within(tb[0], vb[1][k], reach_)) out.push_back({narrow::FV, ea, TB[k]});
    }
    const auto &EA = A.data->tri_edges[ea], &EB = B.data->tri_edges[eb];
    for (int i = 0; i < 3; ++i) {
      if (EA[i] < 0) continue;
      const Box ba = enclose::hull(vb[0][i], vb[0][(i + 1) % 3]);
      for (int j = 0; j < 3; ++j)
        if (EB[j] >= 0 && enclose::boxes_within(ba, enclose::hull(vb[1][j], vb[1][(j + 1) % 3]), reach_))
          out.push_back({narrow::EE, uint32_t(EA[i]), uint32_t(EB[j])});
    }
  }
};

}  // namespace

std::unique_ptr<narrow::Candidate_source> bvh_source(const Pair_ctx &ctx, double reach) {
  if (narrow::has_infinite_bounds(ctx)) return narrow::brute_source(ctx);  // candidate_source.h
  return std::make_unique<Bvh_source>(ctx, reach);
}

}  // namespace pccd::bvh
