// estimate_costs (auto_cost.h): the cost model of the automatic broad phase.
#include "scene/auto_cost.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "bvh/hierarchy.h"
#include "enclose/enclose.h"

namespace pccd::scene {

namespace {

using narrow::Moving_body;
using V3 = std::array<double, 3>;

// Measured constants (seconds of CPU time, auto_cost.h): bvh per element pair whose boxes
// meet on a piece and per call; range per query primitive and piece and per call, for
// two meshes (with the static pass at t = 0) and otherwise (balls: 5-D trees, no
// static pass). Fitted on 2,000 stored elements, 40 queries: range 113-129 us per
// query on shells (7 primitives x 1 piece), 824 us on translated needles (7 x 16),
// 53 us on the molecule slab (1 ball x 4); bvh 45-88 us on the slab (about 3 pairs per
// piece), 57-74 us on the terrain (about 14), 106 ms on translated needles (32,000).
constexpr double kPair = 4.0e-6, kBvh_call = 4.0e-5;
constexpr double kItem_meshes = 8.0e-6, kRange_call_meshes = 8.0e-5;
constexpr double kItem_other = 4.0e-6, kRange_call_other = 2.5e-5;
constexpr size_t kSamples = 16;
constexpr size_t kCap = 4096;

// A body's pose at t in doubles (the midpoints of its motion's coefficient enclosures):
// x = (Rn p + O) / W.
struct Pose {
  double Rn[3][3], O[3], W;
};

double mid_eval(const poly::Poly<arith::Interval> &f, double t) {
  double v = 0;
  for (size_t k = f.c.size(); k-- > 0;) v = v * t + (0.5 * f.c[k].lo + 0.5 * f.c[k].hi);
  return v;
}

Pose pose_at(const Moving_body &b, double t) {
  Pose p;
  p.W = mid_eval(b.mo->W_i, t);
  for (int i = 0; i < 3; ++i) {
    p.O[i] = mid_eval(b.mo->O_i[i], t);
    for (int j = 0; j < 3; ++j) p.Rn[i][j] = mid_eval(b.mo->Rn_i[i][j], t);
  }
  return p;
}

// Point p of body Q at pose q, in the frame of body S at pose s: R_S^T (x - o_S) with
// R_S = Rn_S / W_S, o_S = O_S / W_S.
V3 in_frame(const Pose &s, const Pose &q, const V3 &p) {
  V3 x, y;
  for (int i = 0; i < 3; ++i)
    x[i] = (q.Rn[i][0] * p[0] + q.Rn[i][1] * p[1] + q.Rn[i][2] * p[2] + q.O[i]) / q.W - s.O[i] / s.W;
  for (int i = 0; i < 3; ++i) y[i] = (s.Rn[0][i] * x[0] + s.Rn[1][i] * x[1] + s.Rn[2][i] * x[2]) / s.W;
  return y;
}

size_t elements(const Moving_body &b) { return b.is_mesh() ? b.mesh->triangles().size() : b.n_points(); }

// Query primitives the range phase searches for side b (range_index.cpp, query_items).
size_t items(const Moving_body &b) {
  if (!b.is_mesh()) return b.n_points();
  return b.data->surface_vertices.size() + b.mesh->triangles().size() + b.mesh->edges().size();
}

// The points (and the radius) of element e of body b, body frame.
void element_points(const Moving_body &b, size_t e, std::vector<V3> &pts, double &radius) {
  pts.clear();
  if (b.is_mesh()) {
    for (uint32_t v : b.mesh->triangles()[e]) pts.push_back(b.data->pts[v]);
    radius = b.data->pt_err;
  } else {
    pts.push_back(b.data->pts[e]);
    radius = b.data->radius_up[e] + b.data->pt_err;
  }
}

// Appends the elements of S whose hierarchy boxes meet [lo, hi] (at most cap in all).
void meeting(const bvh::Hierarchy &h, const V3 &lo, const V3 &hi, std::vector<uint32_t> &out, size_t cap) {
  uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0 && out.size() < cap) {
    const bvh::Node &nd = h.nodes[stack[--top]];
    bool meets = true;
    for (int a = 0; a < 3; ++a) meets = meets && nd.c[a] - nd.h[a] <= hi[a] && lo[a] <= nd.c[a] + nd.h[a];
    if (!meets) continue;
    if (nd.leaf()) {
      for (uint32_t i = 0; i < nd.count; ++i) out.push_back(h.elems[nd.first + i]);
    } else if (top + 2 <= 128) {
      stack[top++] = nd.first + 1;
      stack[top++] = nd.first;
    }
  }
}

}  // namespace

Auto_costs estimate_costs(const narrow::Pair_ctx &ctx) {
  const int s = elements(ctx.side(0)) >= elements(ctx.side(1)) ? 0 : 1;
  const Moving_body &S = ctx.side(s), &Q = ctx.side(1 - s);
  Auto_costs out;
  // Pieces as Range_index: the longest path of Q's box corners in S's frame (17 times).
  std::array<Pose, 17> ps, pq;
  for (int i = 0; i <= 16; ++i) ps[i] = pose_at(S, i / 16.0), pq[i] = pose_at(Q, i / 16.0);
  double path = 0;
  for (int c = 0; c < 8; ++c) {
    V3 p, prev{};
    for (int a = 0; a < 3; ++a) p[a] = Q.data->box_c[a] + ((c >> a) & 1 ? Q.data->box_h[a] : -Q.data->box_h[a]);
    double len = 0;
    for (int i = 0; i <= 16; ++i) {
      const V3 y = in_frame(ps[i], pq[i], p);
      if (i > 0) len += std::sqrt((y[0] - prev[0]) * (y[0] - prev[0]) + (y[1] - prev[1]) * (y[1] - prev[1]) +
                                  (y[2] - prev[2]) * (y[2] - prev[2]));
      prev = y;
    }
    path = std::max(path, len);
  }
  const double feature = std::min(S.data->feature, Q.data->feature);
  int k = 0;
  while (k < 6 && path > feature * double(1 << k)) ++k;
  if (!std::isfinite(path)) k = 6;
  out.pieces = 1 << k;
  const bool meshes = S.is_mesh() && Q.is_mesh();
  out.range = (meshes ? kRange_call_meshes : kRange_call_other) +
              (meshes ? kItem_meshes : kItem_other) * double(items(Q)) * out.pieces;
  // bvh halves its pieces until the certified motion spread (enclose::whole_pose, kept
  // with each body) is below the feature size, so it takes about spread / feature
  // pieces where the sums below take `pieces`: under rotations many more (blades
  // turned about one axis: 7 to 140 against 4 to 16), each with its own pairs.
  const double spread = std::max(enclose::whole_pose(Q).spread, enclose::whole_pose(S).spread);
  const double ratio = spread / (feature * out.pieces);
  const double refine = ratio > 1 ? (std::isfinite(ratio) ? ratio : HUGE_VAL) : 1.0;
  // bvh: the elements of S meeting each sampled element of Q, summed over the pieces;
  // the count stops once it alone makes bvh the dearer (the choice is then made: kCap
  // elements against every one of 8,000 needles cost a third of a range query).
  const bvh::Hierarchy &h = bvh::hierarchy(*S.data);
  const size_t nq = elements(Q), m = std::min(nq, kSamples);
  const double enough = (out.range - kBvh_call) / kPair / refine * double(m) / double(std::max<size_t>(nq, 1));
  const size_t cap = std::min<double>(kCap, std::max(0.0, enough) + 1);
  std::vector<Pose> es(out.pieces + 1), eq(out.pieces + 1);
  for (int i = 0; i <= out.pieces; ++i) es[i] = pose_at(S, double(i) / out.pieces), eq[i] = pose_at(Q, double(i) / out.pieces);
  std::vector<V3> pts, prev, now;
  std::vector<uint32_t> met;
  for (size_t j = 0; j < m && met.size() < cap; ++j) {
    double r = 0;
    element_points(Q, j * nq / m, pts, r);
    for (int i = 0; i <= out.pieces && met.size() < cap; ++i) {
      now.clear();
      for (const V3 &p : pts) now.push_back(in_frame(es[i], eq[i], p));
      if (i > 0) {
        V3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
        for (const auto *set : {&prev, &now})
          for (const V3 &y : *set)
            for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], y[a] - r), hi[a] = std::max(hi[a], y[a] + r);
        meeting(h, lo, hi, met, cap);
      }
      std::swap(prev, now);
    }
  }
  out.pairs = m ? double(met.size()) * double(nq) / double(m) * refine : 0.0;
  out.bvh = kBvh_call + kPair * out.pairs;
  return out;
}

}  // namespace pccd::scene
