#include "boxes/box_source.h"

#include <cmath>

#include <algorithm>

#include "boxes/boxes.h"

namespace pccd::boxes {

using enclose::boxes_meet;
using enclose::empty_box;
using enclose::enclose_pose;
using enclose::frame_box;
using enclose::grow;
using enclose::hull;
using enclose::point_box;
using enclose::Pose_piece;
using enclose::spread_stalled;
using enclose::whole_pose;
using narrow::Candidate_sink;
using narrow::Moving_body;
using narrow::Prim_pair;
using narrow::Pair_ctx;
using narrow::Search_stats;

namespace {

constexpr int kMax_depth = 24;       // pieces of width 2^-24 at most
constexpr double kLeaf_pairs = 64;   // |active A| * |active B| at most: intersect now

// Boxes of one side's points, cached per piece by a stamp (meshes: each vertex is
// shared by several triangles and edges; a ball's box is used once per piece, so sphere
// sets keep no cache and allocate nothing per query). Side A's point boxes are grown by
// the minimum separation's reach (enclose/enclose.h, reach_of; 0 without one), and so are its
// edge, triangle and ball boxes, which are hulls of them or grow them further.
struct Side {
  const Moving_body *b = nullptr;
  double reach = 0;
  std::vector<Box> vbox;
  std::vector<uint32_t> vstamp, vlisted, elisted;
  uint32_t stamp = 0;

  // The caches are allocated on first use: a source built but not run (an on-line
  // query answered by the static test) must not pay for the stored body's size.
  Side(const Moving_body &body, double r) : b(&body), reach(r) {}

  void allocate() {
    if (!b->is_mesh() || !vstamp.empty()) return;
    vbox.resize(b->n_points());
    vstamp.assign(b->n_points(), 0);
    vlisted.assign(b->n_points(), 0);
    elisted.assign(b->mesh->edges().size(), 0);
  }

  Box point(const Pose_piece &pose, uint32_t k) {
    if (!b->is_mesh()) return grown(point_box(pose, b->data->pts[k], b->data->pt_err));
    allocate();
    if (vstamp[k] != stamp) {
      vbox[k] = grown(point_box(pose, b->data->pts[k], b->data->pt_err));
      vstamp[k] = stamp;
    }
    return vbox[k];
  }
  Box grown(const Box &x) const { return reach > 0 ? grow(x, reach) : x; }
  // Box of element e: triangle (mesh) or ball.
  Box element(const Pose_piece &pose, uint32_t e) {
    if (b->is_mesh()) {
      const auto &t = b->mesh->triangles()[e];
      return hull(hull(point(pose, t[0]), point(pose, t[1])), point(pose, t[2]));
    }
    return grow(point(pose, e), b->data->radius_up[e]);
  }
  size_t n_elements() const {
    return b->is_mesh() ? b->mesh->triangles().size() : b->spheres->centers().size();
  }

  // Vertices and edges of the active triangles tris (each once).
  void parts(const std::vector<uint32_t> &tris, std::vector<uint32_t> &verts,
             std::vector<uint32_t> &edges) {
    allocate();
    const auto &T = b->mesh->triangles();
    for (uint32_t t : tris)
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = T[t][k];
        if (vlisted[v] != stamp) {
          vlisted[v] = stamp;
          verts.push_back(v);
        }
        const int64_t e = b->data->tri_edges[t][k];
        if (e >= 0 && elisted[e] != stamp) {
          elisted[e] = stamp;
          edges.push_back(static_cast<uint32_t>(e));
        }
      }
  }
};

class Box_source final : public narrow::Candidate_source {
 public:
  Box_source(const Pair_ctx &ctx, double reach)
      : ctx_(ctx), side_{Side(ctx.side(0), reach), Side(ctx.side(1), 0.0)} {}

  // The triangle pairs whose boxes meet at t = 0. The static test asks for triangles
  // sharing a point (candidate_source.h), whatever the minimum separation: boxes are
  // not grown here (pairs within delta at t = 0 are run()'s, solved with delta).
  std::vector<Prim_pair> static_candidates(util::Thread_pool &) override {
    std::vector<Box> boxes[2];
    const double reach = side_[0].reach;
    side_[0].reach = 0;
    for (int s = 0; s < 2; ++s) {
      const Pose_piece pose = enclose_pose(*side_[s].b, 0.0, 0.0);
      ++side_[s].stamp;
      for (uint32_t e = 0; e < side_[s].n_elements(); ++e) boxes[s].push_back(side_[s].element(pose, e));
    }
    side_[0].reach = reach;
    ++side_[0].stamp;  // no ungrown box stays cached
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    box_pairs(boxes[0], boxes[1], pairs);
    std::vector<Prim_pair> cand;
    for (auto &p : pairs) cand.push_back({narrow::TT, p.first, p.second});
    return cand;
  }

  void run(Candidate_sink &sink, Search_stats &stats, util::Thread_pool &) override {
    sink_ = &sink;
    stats_ = &stats;
    std::vector<uint32_t> all[2];
    for (int s = 0; s < 2; ++s) {
      all[s].resize(side_[s].n_elements());
      for (size_t e = 0; e < all[s].size(); ++e) all[s][e] = static_cast<uint32_t>(e);
    }
    feature_ = std::min(ctx_.side(0).data->feature, ctx_.side(1).data->feature);
    piece(0.0, 1.0, 0, all[0], all[1], HUGE_VAL);
  }

 private:
  const Pair_ctx &ctx_;
  Side side_[2];
  Candidate_sink *sink_ = nullptr;
  Search_stats *stats_ = nullptr;
  double feature_ = 0;  // the bodies' typical feature size (leaf test)

  // Keeps the elements of `act` (side s) whose box meets `other`; returns their hull.
  Box filter(int s, const Pose_piece &pose, std::vector<uint32_t> &act, const Box &other) {
    Box h = empty_box();
    size_t kept = 0;
    for (uint32_t e : act) {
      Box b = side_[s].element(pose, e);
      if (!boxes_meet(b, other)) continue;
      act[kept++] = e;
      h = hull(h, b);
    }
    act.resize(kept);
    return h;
  }

  void piece(double a, double b, int depth, std::vector<uint32_t> actA, std::vector<uint32_t> actB,
             double parent_spread) {
    util::work_step();  // one time piece (util/work_budget.h)
    if (sink_->pruned(a)) return;
    ++stats_->pieces;
    auto pose_on = [&](int s) {
      return a == 0 && b == 1 ? whole_pose(ctx_.side(s)) : enclose_pose(ctx_.side(s), a, b);
    };
    Pose_piece pose[2] = {pose_on(0), pose_on(1)};
    for (int s = 0; s < 2; ++s) ++side_[s].stamp;
    Box bodyB = frame_box(pose[1], ctx_.side(1).data->box_c, ctx_.side(1).data->box_h);
    Box hullA = filter(0, pose[0], actA, bodyB);
    if (actA.empty()) return;
    Box hullB = filter(1, pose[1], actB, hullA);
    if (actB.empty()) return;
    hullA = filter(0, pose[0], actA, hullB);
    if (actA.empty()) return;
    const double spread = std::max(pose[0].spread, pose[1].spread);
    const bool leaf = depth >= kMax_depth || spread <= feature_ ||
                      double(actA.size()) * double(actB.size()) <= kLeaf_pairs ||
                      spread_stalled(depth, spread, parent_spread);
    if (leaf) return sink_->piece(a, b, intersect(pose, actA, actB));
    const double m = 0.5 * (a + b);  // exact: dyadic pieces
    piece(a, m, depth + 1, actA, actB, spread);
    piece(m, b, depth + 1, std::move(actA), std::move(actB), spread);
  }

  // The candidates of a leaf: feature pairs of the active elements whose boxes meet.
  std::vector<Prim_pair> intersect(const Pose_piece pose[2], const std::vector<uint32_t> &actA,
                                   const std::vector<uint32_t> &actB) {
    ++stats_->leaves;
    const std::vector<uint32_t> *act[2] = {&actA, &actB};
    std::vector<Box> elem[2];
    for (int s = 0; s < 2; ++s)
      for (uint32_t e : *act[s]) elem[s].push_back(side_[s].element(pose[s], e));
    std::vector<Prim_pair> cand;
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    auto emit = [&](uint8_t type, const std::vector<uint32_t> &ia, const std::vector<uint32_t> &ib) {
      for (auto &p : pairs) cand.push_back({type, ia[p.first], ib[p.second]});
      stats_->candidates += pairs.size();
      pairs.clear();
    };
    const bool mA = ctx_.side(0).is_mesh(), mB = ctx_.side(1).is_mesh();
    if (mA && mB) {
      std::vector<uint32_t> verts[2], edges[2];
      std::vector<Box> vb[2], eb[2];
      for (int s = 0; s < 2; ++s) {
        side_[s].parts(*act[s], verts[s], edges[s]);
        const auto &E = side_[s].b->mesh->edges();
        for (uint32_t v : verts[s]) vb[s].push_back(side_[s].point(pose[s], v));
        for (uint32_t e : edges[s])
          eb[s].push_back(hull(side_[s].point(pose[s], E[e][0]), side_[s].point(pose[s], E[e][1])));
      }
      box_pairs(vb[0], elem[1], pairs);
      emit(narrow::VF, verts[0], actB);
      box_pairs(elem[0], vb[1], pairs);
      emit(narrow::FV, actA, verts[1]);
      box_pairs(eb[0], eb[1], pairs);
      emit(narrow::EE, edges[0], edges[1]);
    } else {
      box_pairs(elem[0], elem[1], pairs);
      emit(!mA && !mB ? narrow::SS : !mA ? narrow::ST : narrow::TS, actA, actB);
    }
    return cand;
  }
};

}  // namespace

std::unique_ptr<narrow::Candidate_source> box_source(const Pair_ctx &ctx, double reach) {
  if (narrow::has_infinite_bounds(ctx)) return narrow::brute_source(ctx);  // candidate_source.h
  return std::make_unique<Box_source>(ctx, reach);
}

}  // namespace pccd::boxes
