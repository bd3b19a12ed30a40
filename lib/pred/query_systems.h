// The feature systems of each primitive query kind (see features.h for why the list
// is complete), and the cheap exclusion tests that run before them.
#pragma once
#include <vector>

#include "pred/delta_systems.h"
#include "pred/features.h"

namespace pccd::pred {

// The primitive query: kind, point trajectories, ball radii (SPHERE_SPHERE: both;
// SPHERE_TRIANGLE: radius[0], the ball at point 0).
//
// `scale`: every trajectory in p may be D(t) times the true position, with one common
// polynomial D > 0 on [0, 1] (body queries clear the denominators of rational motions
// this way). Contact conditions between points are homogeneous in point differences
// and unchanged; radii are multiplied by D. Empty means D = 1.
//
// `has_delta`: a minimum separation delta > 0 (pccd_config.min_distance) for the kinds
// VERTEX_FACE, EDGE_EDGE, VERTEX_EDGE, VERTEX_VERTEX: a contact is then a time when the
// closed primitives are within distance delta (delta_systems.h). Scaled by D like radii.
// (Ball kinds take delta into their radii instead.)
//
// `own`: empty, or one trajectory per point with p[i] = c_i(t) own[i], c_i > 0 on
// [0, 1] common to all the points of one body (a body pair multiplies each side by the
// other side's W; own is the side's own homogeneous trajectory). Differences of points
// of the same body use own (features.h): the systems change by positive factors only,
// and a static body's edges and normals become constants. The kinds' point order puts
// one body's points before the other's (VERTEX_FACE: vertex | face; EDGE_EDGE: edge a |
// edge b; SPHERE_TRIANGLE: ball | triangle), and only same-body differences use own.
//
// `positive_factors`: exact polynomials > 0 on [0, 1] that may divide the systems'
// polynomials (a body query's motion denominators W_A, W_B: the side that does not
// move is multiplied by the other's W, so a static face's normal carries W^2). The
// exact stage divides them out (poly::divide_out_positive), keeping roots and signs on
// [0, 1]; only a hint: empty changes no answer, only the cost.
template <class NT>
struct Query_data {
  int kind = 0;
  std::vector<Point_traj<NT>> p;
  NT radius[2];
  Poly<NT> scale;
  bool has_delta = false;
  NT delta = arith::from_int<NT>(0);
  std::vector<Poly<arith::Rational>> positive_factors;
  std::vector<Point_traj<NT>> own;
  // With own, for VERTEX_FACE and SPHERE_TRIANGLE: empty, or the face's normal as a
  // positive multiple of (own[2] - own[1]) x (own[3] - own[1]) (features.h, `normal`).
  std::vector<Point_traj<NT>> face_normal;
};

// r^2 D^2 as a polynomial.
template <class NT>
Poly<NT> radius_squared(const NT &r, const Poly<NT> &scale) {
  Poly<NT> r2 = Poly<NT>::constant(r * r);
  return scale.c.empty() ? r2 : r2 * scale * scale;
}

// only: when given, systems are built for these features alone (the others are listed
// without a system, so tags stay the same).
template <class NT>
Feature_set<NT> build_systems(const Query_data<NT> &q, const std::vector<Feature> *only = nullptr) {
  using K = typename System<NT>::Kind;
  Feature_set<NT> s;
  s.only = only;
  if (!q.positive_factors.empty()) s.positive = &q.positive_factors;
  const auto &p = q.p;
  // Own trajectories of point i (null without them).
  const bool has_own = q.own.size() == p.size();
  auto o = [&](int i) { return has_own ? &q.own[i] : nullptr; };
  const std::array<const Point_traj<NT> *, 3> face_own{{o(1), o(2), o(3)}};
  const std::array<const Point_traj<NT> *, 4> edges_own{{o(0), o(1), o(2), o(3)}};
  const Point_traj<NT> *normal = has_own && q.face_normal.size() == 1 ? &q.face_normal[0] : nullptr;
  if (q.has_delta) {
    add_delta_systems(s, q.kind, p, radius_squared(q.delta, q.scale), has_own ? &q.own : nullptr, normal);
    return s;
  }
  auto vertex_edge = [&](int v, int e0, int e1) {
    add_vertex_edge(s, p[v], p[e0], p[e1], v, e0, e1, o(e0), o(e1));
  };
  switch (q.kind) {
    case VERTEX_FACE:
      add_vertex_face(s, p[0], {{&p[1], &p[2], &p[3]}}, {{0, 1, 2, 3}}, has_own ? &face_own : nullptr,
                      normal);
      for (int i = 0; i < 3; ++i) vertex_edge(0, 1 + i, 1 + (i + 1) % 3);
      for (int i = 1; i <= 3; ++i) add_vertex_vertex(s, p[0], p[i], 0, i);
      break;
    case EDGE_EDGE:
      add_edge_edge(s, p[0], p[1], p[2], p[3], has_own ? &edges_own : nullptr);
      vertex_edge(0, 2, 3);
      vertex_edge(1, 2, 3);
      vertex_edge(2, 0, 1);
      vertex_edge(3, 0, 1);
      for (int i = 0; i < 2; ++i)
        for (int j = 2; j < 4; ++j) add_vertex_vertex(s, p[i], p[j], i, j);
      break;
    case VERTEX_EDGE:
      vertex_edge(0, 1, 2);
      add_vertex_vertex(s, p[0], p[1], 0, 1);
      add_vertex_vertex(s, p[0], p[2], 0, 2);
      break;
    case VERTEX_VERTEX:
      add_vertex_vertex(s, p[0], p[1], 0, 1);
      break;
    case SPHERE_SPHERE: {
      // Closed balls meet iff |ca - cb|^2 - (ra + rb)^2 <= 0.
      const Feature feat{SPHERE_SPHERE, {{0, 1, -1, -1}}};
      if (!s.wants(feat)) {
        skip_feature(s, feat);
        break;
      }
      auto d = p[0] - p[1];
      Poly<NT> f = motion::dot(d, d) - radius_squared(NT(q.radius[0] + q.radius[1]), q.scale);
      add_system(s, feat, K::sublevel, f, {});
      break;
    }
    case SPHERE_TRIANGLE: {
      Poly<NT> r2d2 = radius_squared(q.radius[0], q.scale);
      add_ball_face(s, p[0], {{&p[1], &p[2], &p[3]}}, r2d2, nullptr, has_own ? &face_own : nullptr, normal);
      for (int i = 0; i < 3; ++i) {
        const int e0 = 1 + i, e1 = 1 + (i + 1) % 3;
        add_ball_edge(s, p[0], p[e0], p[e1], r2d2, e0, e1, nullptr, o(e0), o(e1));
      }
      for (int i = 1; i <= 3; ++i) add_ball_vertex(s, p[0], p[i], r2d2, i);
      break;
    }
    default:
      throw arith::Internal_error("build_systems: unknown kind");
  }
  return s;
}

}  // namespace pccd::pred
