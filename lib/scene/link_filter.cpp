#include "scene/link_filter.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "bvh/hierarchy.h"
#include "pred/closest_axis.h"
#include "scene/delta_witness.h"
#include "scene/filter_scratch.h"
#include "scene/node_memo.h"
#include "pred/static_contact.h"
#include "util/work_budget.h"

namespace pccd::scene {

namespace {

using Front = Node_pairs;

constexpr double kSqrt3_up = 1.7320508075688774;  // > sqrt(3)

// A meeting node pair splits its larger node while that node is larger than this many
// times the piece's spread, else waits for the piece's halves (a heuristic: either way
// nothing is dropped unseparated). Measured (issue 30, check_many CPU ms per segment,
// 150 bench segments each, Panda / UR5 self-collision off): 1 (the earlier rule) 0.44 /
// 0.25, 2: 0.34 / 0.19, 4: 0.31 / 0.16, 8: 0.31 / 0.15, 16: 0.34 / 0.18; 0.5: 0.84 /
// 0.51. A node little larger than the spread mostly meets the other again as a whole
// on the halves, where the spread halves too: splitting it early doubles the pairs.
constexpr double kSplit_factor = 4;

// What the piece's motion adds to a box of the body (enclose::Pose_piece::spread's bound,
// recomputed here for poses made without it): |R(t) - Rm| |x| + orad over the body. A
// heuristic here (when to split a node rather than the piece), never a decision.
double spread_of(const enclose::Pose_piece &p, const narrow::Body_data &d) {
  if (!p.finite) return HUGE_VAL;
  double rr = 0, orad = 0;
  for (int i = 0; i < 3; ++i) {
    orad = std::max(orad, p.orad[i]);
    for (int j = 0; j < 3; ++j) rr = std::max(rr, p.Rr[i][j]);
  }
  return 3 * rr * d.reach + orad;
}

// With the piece's ends: what the motion adds across the chords (the chords themselves
// are thin across the motion, so nodes are split down to that).
double spread_of(const Side_piece &s, const narrow::Body_data &d) {
  if (s.identity) return 0;
  if (!s.at_a) return spread_of(*s.ball, d);
  return s.g_rot * kSqrt3_up * d.reach + s.g_off;
}

// The world box over the piece of the body-frame box (c, h) of a body whose points y all
// have |y|_2 <= yn (link_filter.h). The growth g_rot yn + g_off takes two roundings,
// each within 2^-52 relative in any mode: 2^-50 relative and 1e-300 cover them.
enclose::Box box_of(const Side_piece &s, const std::array<double, 3> &c, const std::array<double, 3> &h,
                    double yn) {
  if (s.identity) {
    enclose::Box b;
    for (int i = 0; i < 3; ++i) {
      b.lo[i] = arith::round_down(c[i] - h[i]);
      b.hi[i] = arith::round_up(c[i] + h[i]);
    }
    return b;
  }
  if (!s.at_a) return enclose::frame_box(*s.ball, c, h);
  const double g = (s.g_rot * yn + s.g_off) * (1 + 0x1p-50) + 1e-300;
  return enclose::grow(enclose::hull(enclose::frame_box(*s.at_a, c, h), enclose::frame_box(*s.at_b, c, h)), g);
}

double norm_bound(const narrow::Body_data &d) { return kSqrt3_up * d.reach * (1 + 0x1p-50); }

// Boxes whose convex hull holds the element at every t of the piece, side A's grown by
// reach: with the ball pose, the world boxes of its points (a triangle's three vertices;
// a ball's centre grown by its radius); with the piece's two ends, the boxes of its
// points at a and at b, each grown by the chords' growth g (a point at t is within g of
// its chord, so the element at t, a convex combination of its points, is within g of
// the hull of the end boxes: link_filter.h). Up to 6 boxes.
int element_boxes(const narrow::Body_data &d, const bvh::Hierarchy &h, uint32_t node, const Side_piece &p,
                  double reach, enclose::Box out[6]) {
  const uint32_t e = h.elems[h.nodes[node].first];
  const double er = d.pt_err;
  const bool ends = p.at_a && !p.identity;
  const double g = ends ? (p.g_rot * norm_bound(d) + p.g_off) * (1 + 0x1p-50) + 1e-300 : 0;
  auto boxes_of = [&](const std::array<double, 3> &x, double grow_by, enclose::Box *o) {
    if (!ends) {
      o[0] = enclose::grow(box_of(p, x, {er, er, er}, 0), grow_by);
      return 1;
    }
    o[0] = enclose::grow(enclose::frame_box(*p.at_a, x, {er, er, er}), grow_by + g);
    o[1] = enclose::grow(enclose::frame_box(*p.at_b, x, {er, er, er}), grow_by + g);
    return 2;
  };
  if (!d.mesh) return boxes_of(d.pts[e], d.radius_up[e] + reach, out);
  const auto &t = d.mesh->triangles()[e];
  int n = 0;
  for (int v = 0; v < 3; ++v) n += boxes_of(d.pts[t[v]], reach, out + n);
  return n;
}

// A separating axis test of two leaves' elements over the piece: the elements lie in
// the convex hulls of their point boxes, so an axis n on which the two sets of boxes
// project to disjoint intervals separates them at every t of the piece. Axes (any
// double vectors serve: the projections are certified): the difference of the two
// sets' box centres, each triangle's normal and, for two triangles, the cross products
// of their edges, directions taken at the piece's pose midpoints; reach > 0: also the
// direction of the elements' nearest points there (pred/closest_axis.h: the axis on
// which the gap is the distance). reach > 0: apart when the gap on an axis exceeds
// reach |n| (below).
// ba[0, na), bb[0, nb): the leaves' element_boxes on the piece (reach 0). First the
// boxes holding each side's boxes (a coordinate axis test: the element lies in the
// hull of its boxes, so boxes_within's "apart" holds for it, as for the nodes), then
// the axes in turn, each built only when the ones before it failed.
bool leaves_apart(const narrow::Body_data &A, const bvh::Hierarchy &ha, uint32_t ka, const Side_piece &pa,
                  const enclose::Box *ba, int na, const narrow::Body_data &B, const bvh::Hierarchy &hb, uint32_t kb,
                  const Side_piece &pb, const enclose::Box *bb, int nb, double reach) {
  enclose::Box hull_a = enclose::empty_box(), hull_b = enclose::empty_box();
  for (int k = 0; k < na; ++k) hull_a = enclose::hull(hull_a, ba[k]);
  for (int k = 0; k < nb; ++k) hull_b = enclose::hull(hull_b, bb[k]);
  if (!enclose::boxes_within(hull_a, hull_b, reach)) return true;
  // Whether the axis n separates the two sets of boxes (by more than reach |n|).
  auto separates = [&](const double n[3]) { return enclose::axis_separates(n, ba, na, bb, nb, reach); };
  double axis[3];
  double edges[2][3][3];  // world edge directions at the pose midpoints (triangles)
  double world[2][3][3];  // the elements' points at the pose midpoints (closest_axis.h)
  int n_world[2] = {1, 1};
  double ca[3] = {0, 0, 0}, cb[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < na; ++k) ca[i] += (ba[k].lo[i] + ba[k].hi[i]) / na;
    for (int k = 0; k < nb; ++k) cb[i] += (bb[k].lo[i] + bb[k].hi[i]) / nb;
    axis[i] = cb[i] - ca[i];
  }
  if (separates(axis)) return true;
  double normal[2][3];  // a triangle's (side s a mesh)
  for (int s = 0; s < 2; ++s) {
    const narrow::Body_data &d = s == 0 ? A : B;
    const bvh::Hierarchy &h = s == 0 ? ha : hb;
    const enclose::Pose_piece &p = *(s == 0 ? pa : pb).ball;
    const uint32_t e = h.elems[h.nodes[s == 0 ? ka : kb].first];
    auto place = [&](int k, const std::array<double, 3> &y) {
      const double z[3] = {y[0] - p.q[0], y[1] - p.q[1], y[2] - p.q[2]};  // about the pivot (enclose.h)
      for (int i = 0; i < 3; ++i) world[s][k][i] = p.Rm[i][0] * z[0] + p.Rm[i][1] * z[1] + p.Rm[i][2] * z[2] + p.om[i];
    };
    if (!d.mesh) {
      place(0, d.pts[e]);
      continue;
    }
    const auto &t = d.mesh->triangles()[e];
    n_world[s] = 3;
    for (int k = 0; k < 3; ++k) place(k, d.pts[t[k]]);
    const auto &x = d.pts[t[0]], &y = d.pts[t[1]], &z = d.pts[t[2]];
    const double u[3] = {y[0] - x[0], y[1] - x[1], y[2] - x[2]}, v[3] = {z[0] - x[0], z[1] - x[1], z[2] - x[2]};
    const double nb_[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    for (int i = 0; i < 3; ++i) normal[s][i] = p.Rm[i][0] * nb_[0] + p.Rm[i][1] * nb_[1] + p.Rm[i][2] * nb_[2];
    const double w[3] = {z[0] - y[0], z[1] - y[1], z[2] - y[2]};
    const double *e3[3] = {u, v, w};
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) edges[s][k][i] = p.Rm[i][0] * e3[k][0] + p.Rm[i][1] * e3[k][1] + p.Rm[i][2] * e3[k][2];
  }
  // With reach > 0, the nearest points' direction before the fixed axes: of the UR5's
  // leaf pairs near delta (firstmd bench, issue 33) it separated 342k, the normals and
  // edge crosses 216k, none 505k, and each it separated had failed the 11 fixed axes
  // first. Their distance there is a heuristic too: elements nearer than reach at the
  // pose midpoints (the ball's centre, inside the boxes) leave the hulls of their boxes
  // within reach, so no axis can separate them; the axes are then not tried (returning
  // "not apart" is always sound: the pair is kept).
  if (reach > 0 && pred::closest_direction(world[0], n_world[0], world[1], n_world[1], axis)) {
    const double d2 = axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2];
    if (d2 < reach * reach * (1 - 0x1p-20)) return false;
    if (separates(axis)) return true;
  }
  for (int s = 0; s < 2; ++s)
    if ((s == 0 ? A : B).mesh && separates(normal[s])) return true;
  if (A.mesh && B.mesh)  // edge-edge axes: the cross products of the two triangles' edges
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const double *a = edges[0][j], *b = edges[1][k];
        axis[0] = a[1] * b[2] - a[2] * b[1];
        axis[1] = a[2] * b[0] - a[0] * b[2];
        axis[2] = a[0] * b[1] - a[1] * b[0];
        if (separates(axis)) return true;
      }
  return false;
}

bool leaves_apart(const narrow::Body_data &A, const bvh::Hierarchy &ha, uint32_t ka, const Side_piece &pa,
                  const narrow::Body_data &B, const bvh::Hierarchy &hb, uint32_t kb, const Side_piece &pb,
                  double reach) {
  enclose::Box ba[6], bb[6];
  const int na = element_boxes(A, ha, ka, pa, 0, ba), nb = element_boxes(B, hb, kb, pb, 0, bb);
  return leaves_apart(A, ha, ka, pa, ba, na, B, hb, kb, pb, bb, nb, reach);
}

// The leaf pair's triangles share a point at the instant (touching_at): their vertex
// boxes at the instant's poses as interval points.
bool triangles_touch(const narrow::Body_data &A, uint32_t ea, const enclose::Pose_piece &pa,
                     const narrow::Body_data &B, uint32_t eb, const enclose::Pose_piece &pb) {
  std::array<pred::Vec3<arith::Interval>, 3> ta, tb;
  for (int s = 0; s < 2; ++s) {
    const narrow::Body_data &d = s == 0 ? A : B;
    const auto &t = d.mesh->triangles()[s == 0 ? ea : eb];
    auto &out = s == 0 ? ta : tb;
    for (int v = 0; v < 3; ++v) {
      const enclose::Box x = enclose::point_box(s == 0 ? pa : pb, d.pts[t[v]], d.pt_err);
      for (int i = 0; i < 3; ++i) out[v][i] = arith::Interval(x.lo[i], x.hi[i]);
    }
  }
  try {
    return pred::triangles_meet(ta, tb);
  } catch (const arith::Uncertain &) {
    return false;  // not certain: no witness
  }
}

}  // namespace

bool touching_at(const narrow::Body_data &A, const enclose::Pose_piece &pa, const narrow::Body_data &B,
                 const enclose::Pose_piece &pb, const Node_pairs &start, size_t &budget, uint32_t &ea, uint32_t &eb,
                 double reach, double delta_lo, const bvh::Hierarchy *pha, const bvh::Hierarchy *phb,
                 Node_memo *memo_a, bool *apart) {
  if (apart) *apart = false;
  if (!A.mesh || !B.mesh || !pa.finite || !pb.finite) return false;
  const bvh::Hierarchy &ha = pha ? *pha : bvh::hierarchy(A), &hb = phb ? *phb : bvh::hierarchy(B);
  thread_local Front tl_front;  // the node pairs left, reused (no allocation per call)
  Front &front = tl_front;
  front.assign(start.begin(), start.end());
  bool undecided = false;  // a leaf pair that is not certainly apart was met
  for (; !front.empty() && budget > 0; --budget) {
    // Not a structured binding: box_a captures ka (C++17 forbids capturing bindings).
    const uint32_t ka = front.back().first, kb = front.back().second;
    front.pop_back();
    auto box_a = [&] { return enclose::frame_box(pa, ha.nodes[ka].c, ha.nodes[ka].h); };
    if (!enclose::boxes_within(memo_a ? memo_a->node(ka, box_a) : box_a(),
                               enclose::frame_box(pb, hb.nodes[kb].c, hb.nodes[kb].h), reach))
      continue;
    const bool la = ha.nodes[ka].leaf(), lb = hb.nodes[kb].leaf();
    if (la && lb) {
      const Side_piece sa{&pa}, sb{&pb};
      if (leaves_apart(A, ha, ka, sa, B, hb, kb, sb, reach)) continue;
      const uint32_t a = ha.elems[ha.nodes[ka].first], b = hb.elems[hb.nodes[kb].first];
      if (triangles_touch(A, a, pa, B, b, pb) || (reach > 0 && triangles_within(A, a, pa, B, b, pb, delta_lo))) {
        ea = a;
        eb = b;
        return true;
      }
      undecided = true;  // neither apart nor certainly touching
    } else if (la || (!lb && hb.size(kb) > ha.size(ka))) {
      const uint32_t c = hb.nodes[kb].first;
      front.push_back({ka, c + 1});
      front.push_back({ka, c});
    } else {
      const uint32_t c = ha.nodes[ka].first;
      front.push_back({c + 1, kb});
      front.push_back({c, kb});
    }
  }
  if (apart) *apart = front.empty() && !undecided;
  return false;
}

double first_uncleared(const Filter_side &SA, const Filter_side &SB, double reach, const Filter_limits &lim,
                       Witness *w) {
  const double until = lim.until;
  const narrow::Body_data &A = *SA.data, &B = *SB.data;
  const bvh::Hierarchy &ha = SA.tree ? *SA.tree : bvh::hierarchy(A), &hb = SB.tree ? *SB.tree : bvh::hierarchy(B);
  const double yna = norm_bound(A), ynb = norm_bound(B);
  if ((reach > 0 && !(lim.delta_lo > 0)) || !A.mesh || !B.mesh || !SA.has_instant() || !SB.has_instant()) w = nullptr;
  size_t witness_spent = 0;  // node pairs tested at midpoints
  if (w && reach > 0 && until > 0) {
    // Minimum separation: a pair within delta at t = 0 (a start pose closer than delta,
    // common where the start is only checked for touching) has its first contact at 0;
    // a witness there ends the search at once (kWitness_tests node pairs).
    size_t budget = kWitness_tests;
    if (touching_at(A, SA.instant(0, 0), B, SB.instant(0, 0), kRoots, budget, w->a, w->b, reach, lim.delta_lo, &ha,
                    &hb)) {
      w->found = true;
      w->depth = 0;
      w->index = 0;
      return 0;
    }
  }
  // Each node's box and each leaf's element boxes once per piece and side (node_memo.h);
  // the pieces' fronts in buffers reused from call to call (no allocation per piece).
  thread_local Scratch tl_scratch;
  Scratch &S = tl_scratch;
  // Side A's boxes are kept across calls when it carries a share key (shared_memo.h).
  const bool share_a = SA.share != 0;
  Node_memo &memo_b = S.memo_b;
  if (!share_a) S.memo_a.start(ha.nodes.size(), ha.elems.size());
  memo_b.start(hb.nodes.size(), hb.elems.size());
  S.start();
  S.stack.push_back({0, 0, S.take(kRoots)});
  Front &next = S.next, &work = S.work;
  next.clear();
  size_t tests = 0;  // node pairs taken from fronts (kMax_tests)
  while (!S.stack.empty()) {
    const Scratch::Item it = S.stack.back();
    S.stack.pop_back();
    const double start = std::ldexp(static_cast<double>(it.i), -it.d);
    if (start >= until) return start;  // every earlier piece is separated
    if (std::ldexp(static_cast<double>(it.i + 1), -it.d) <= lim.from) {  // known separated
      S.give_back(it.f);
      continue;
    }
    const Side_piece pa = SA.piece(it.d, it.i), pb = SB.piece(it.d, it.i);
    const double spread = std::max(spread_of(pa, A), spread_of(pb, B));
    // Nodes up to kSplit_factor spreads wait for the halves (the finest piece has none:
    // there, down to one spread).
    const double wait_below = spread * (it.d == kMax_depth ? 1 : kSplit_factor);
    const size_t front_size = S.fronts[it.f].size();
    util::work_step(1 + front_size / 1024);
    tests += front_size;
    if (tests > lim.max_tests) return start;  // this piece's start
    next.clear();
    Node_memo &memo_a = share_a ? S.shared_a.at(SA, ha, it.d, it.i) : S.memo_a;
    if (!share_a) memo_a.next_piece();
    memo_b.next_piece();
    work.clear();
    work.swap(S.fronts[it.f]);
    S.give_back(it.f);
    while (!work.empty()) {
      // Not a structured binding: lambdas below capture these (C++17 forbids capturing
      // bindings; clang refuses, which broke the fuzz build).
      const uint32_t ka = work.back().first, kb = work.back().second;
      work.pop_back();
      if (!enclose::boxes_within(memo_a.node(ka, [&] { return box_of(pa, ha.nodes[ka].c, ha.nodes[ka].h, yna); }),
                                 memo_b.node(kb, [&] { return box_of(pb, hb.nodes[kb].c, hb.nodes[kb].h, ynb); }),
                                 reach))
        continue;
      const bool la = ha.nodes[ka].leaf(), lb = hb.nodes[kb].leaf();
      const double sa = la ? -1 : ha.size(ka), sb = lb ? -1 : hb.size(kb);
      if (la && lb) {
        int na = 0, nb = 0;
        const enclose::Box *ba = memo_a.elements(ha.nodes[ka].first, na, [&](enclose::Box *o) {
          return element_boxes(A, ha, ka, pa, 0, o);
        });
        const enclose::Box *bb = memo_b.elements(hb.nodes[kb].first, nb, [&](enclose::Box *o) {
          return element_boxes(B, hb, kb, pb, 0, o);
        });
        if (leaves_apart(A, ha, ka, pa, ba, na, B, hb, kb, pb, bb, nb, reach)) continue;
      }
      if (std::max(sa, sb) <= wait_below || (la && lb)) {
        next.push_back({ka, kb});  // waits for the halves of the piece
        if (next.size() > kMax_front) {  // the rest waits unrefined (kMax_front)
          if (next.size() + work.size() > 16 * kMax_front) return start;
          next.insert(next.end(), work.begin(), work.end());
          work.clear();
        }
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
    if (w && (it.d >= kWitness_depth || lim.frozen) && witness_spent < kWitness_tests + tests / 2) {
      size_t budget = kWitness_tests + tests / 2 - witness_spent;
      const size_t before = budget;
      const int md = it.d + 1;
      const long mi = 2 * it.i + 1;
      bool hit = touching_at(A, SA.instant(md, mi), B, SB.instant(md, mi), next, budget, w->a, w->b, reach,
                             lim.delta_lo, &ha, &hb);
      witness_spent += before - budget;
      if (hit) {
        w->found = true;
        w->depth = md;
        w->index = mi;
        return start;
      }
    }
    if (it.d == kMax_depth || lim.frozen) return start;  // exact; frozen: deeper pieces are equal
    S.stack.push_back({it.d + 1, 2 * it.i + 1, S.take(next)});
    S.stack.push_back({it.d + 1, 2 * it.i, S.take(next)});
  }
  return kNever;
}

enclose::Box whole_box(const Filter_side &S) {
  const narrow::Body_data &d = *S.data;
  const bvh::Hierarchy &h = S.tree ? *S.tree : bvh::hierarchy(d);
  return box_of(S.piece(0, 0), h.nodes[0].c, h.nodes[0].h, norm_bound(d));
}

bool roots_apart(const enclose::Box &a, const enclose::Box &b, double reach) {
  return !enclose::boxes_within(a, b, reach);
}

bool witness_after(const Filter_side &A, const Filter_side &B, double lower, Witness &w, double reach,
                   double delta_lo, size_t tests) {
  if (!A.data->mesh || !B.data->mesh || !A.has_instant() || !B.has_instant() || !(lower >= 0 && lower < 1)) return false;
  const long base = std::lround(std::ldexp(lower, kMax_depth));  // exact: lower is on the grid
  for (int k = kMax_depth; k >= 1; k -= 2) {
    const long i = base + (1L << (kMax_depth - k));
    if (i >= (1L << kMax_depth)) break;
    size_t budget = tests;
    if (touching_at(*A.data, A.instant(kMax_depth, i), *B.data, B.instant(kMax_depth, i), kRoots, budget, w.a,
                    w.b, reach, delta_lo, A.tree, B.tree)) {
      w.found = true;
      w.depth = kMax_depth;
      w.index = i;
      return true;
    }
  }
  return false;
}

}  // namespace pccd::scene
