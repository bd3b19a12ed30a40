// Minimum separation (pccd_config.min_distance = delta > 0): the first time t in [0, 1]
// at which the closed primitives are within distance delta, dist(A(t), B(t)) <= delta.
//
// Why these systems are complete. The distance is continuous in t, so either it is
// <= delta at t = 0 (the static test, static_contact.h: segments_within and
// ball_meets_triangle) or the first such time t* > 0 has dist = delta exactly. At t*
// take a closest pair (p, q); p and q lie in relatively open features of the closed
// primitives (a vertex, an open edge, the open face), and (p, q) is a closest pair of
// those two features' closures. Then:
//   - point vs open face: the point's distance to the plane is delta and its
//     projection lies strictly inside (ball-face system with the ball at the vertex);
//   - point vs open segment: distance to the line delta, projection strictly inside
//     (ball-edge system);
//   - point vs point: |p - q| <= delta, a closed sublevel set (ball-vertex system);
//   - open segment vs open segment: if the lines are not parallel, p and q are the
//     lines' closest points, strictly inside both segments, at distance delta
//     (add_segments_at_delta below); if they are parallel, an endpoint of one segment
//     is at the same distance from the other closed segment, so a system above holds.
// Conversely every system measures the distance between points of the two closed
// primitives, so any of its hits is a time with dist <= delta. Hence the earliest hit
// of the systems listed, or 0, is t*. Features are reported with the public kinds: a
// vertex-face system as VERTEX_FACE (0, 1, 2, 3), a point and an open segment as
// VERTEX_EDGE, two points as VERTEX_VERTEX, the two open segments as EDGE_EDGE.
//
// All conditions are homogeneous in point differences and delta (delta^2 D^2 enters
// as the ball systems' r^2 D^2; query_systems.h), so scaled trajectories keep them.
#pragma once
#include <array>
#include <vector>

#include "pred/features.h"

namespace pccd::pred {

// The open segments (a0, a1), (b0, b1) at distance delta through their lines' closest
// points, strictly inside both: with n = ea x eb, w = b0 - a0, the line distance is
// |n . w| / |n| and the closest points are at s = ((w x eb) . n) / |n|^2 on a and
// u = ((w x ea) . n) / |n|^2 on b. f = (n . w)^2 - delta^2 D^2 |n|^2, conditions
// 0 < s |n|^2 < |n|^2 and 0 < u |n|^2 < |n|^2 (all false where n = 0).
template <class NT>
void add_segments_at_delta(Feature_set<NT> &set, const Point_traj<NT> &a0, const Point_traj<NT> &a1,
                           const Point_traj<NT> &b0, const Point_traj<NT> &b1, const Poly<NT> &r2d2) {
  using K = typename System<NT>::Kind;
  const Feature feat{EDGE_EDGE, {{0, 1, 2, 3}}};
  if (!set.wants(feat)) return skip_feature(set, feat);
  auto ea = a1 - a0, eb = b1 - b0, w = b0 - a0;
  auto n = motion::cross(ea, eb);
  Poly<NT> nn = motion::dot(n, n), h = motion::dot(n, w);
  Poly<NT> f = h * h - r2d2 * nn;
  Poly<NT> s = motion::dot(motion::cross(w, eb), n), u = motion::dot(motion::cross(w, ea), n);
  add_system(set, feat, f.is_zero() ? K::zero_f : K::roots, f, {s, nn - s, u, nn - u});
}

// The systems of a VERTEX_FACE, EDGE_EDGE, VERTEX_EDGE or VERTEX_VERTEX query at
// minimum separation delta (r2d2 = delta^2 D^2), in the order of the kind's features.
// own: the own trajectories (query_systems.h, Query_data::own) or null; used by the
// ball systems' same-body differences (the segment system's conditions compare s and
// u with |n|^2, which would change by different factors: it takes the points).
template <class NT>
void add_delta_systems(Feature_set<NT> &s, int kind, const std::vector<Point_traj<NT>> &p,
                       const Poly<NT> &r2d2, const std::vector<Point_traj<NT>> *own = nullptr,
                       const Point_traj<NT> *normal = nullptr) {
  auto o = [&](int i) { return own ? &(*own)[i] : nullptr; };
  auto ball_vertex = [&](int c, int v) {
    const Feature f{VERTEX_VERTEX, {{c, v, -1, -1}}};
    add_ball_vertex(s, p[c], p[v], r2d2, v, &f);
  };
  auto ball_edge = [&](int c, int e0, int e1) {
    const Feature f{VERTEX_EDGE, {{c, e0, e1, -1}}};
    add_ball_edge(s, p[c], p[e0], p[e1], r2d2, e0, e1, &f, o(e0), o(e1));
  };
  switch (kind) {
    case VERTEX_FACE: {
      const Feature f{VERTEX_FACE, {{0, 1, 2, 3}}};
      const std::array<const Point_traj<NT> *, 3> fo{{o(1), o(2), o(3)}};
      add_ball_face(s, p[0], {{&p[1], &p[2], &p[3]}}, r2d2, &f, own ? &fo : nullptr, normal);
      for (int i = 0; i < 3; ++i) ball_edge(0, 1 + i, 1 + (i + 1) % 3);
      for (int i = 1; i <= 3; ++i) ball_vertex(0, i);
      break;
    }
    case EDGE_EDGE:
      add_segments_at_delta(s, p[0], p[1], p[2], p[3], r2d2);
      ball_edge(0, 2, 3);
      ball_edge(1, 2, 3);
      ball_edge(2, 0, 1);
      ball_edge(3, 0, 1);
      for (int i = 0; i < 2; ++i)
        for (int j = 2; j < 4; ++j) ball_vertex(i, j);
      break;
    case VERTEX_EDGE:
      ball_edge(0, 1, 2);
      ball_vertex(0, 1);
      ball_vertex(0, 2);
      break;
    case VERTEX_VERTEX:
      ball_vertex(0, 1);
      break;
    default:
      throw arith::Internal_error("add_delta_systems: not a point-feature kind");
  }
}

}  // namespace pccd::pred
