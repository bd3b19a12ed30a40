// Contact conditions of feature pairs as univariate systems (lib/poly/system.h).
//
// A query is decomposed into relatively open features so that every contact of the
// closed primitives is a contact of exactly the listed systems:
//   closed triangle = open face (when not degenerate) + 3 open edges + 3 vertices,
//   closed segment  = open segment (when not degenerate) + 2 endpoints.
// Vertex-face: v in open face | v in open edge (3) | v = vertex (3).
// Edge-edge: open segments cross at one point (not parallel) | endpoint in the other
//   open segment (4) | endpoints coincide (4). If closed segments meet and no
//   endpoint lies on the other one, they cross properly (parallel overlapping
//   segments always have an endpoint on the other).
// Each "open" system has strict inequalities only, so when its polynomial f is
// identically zero its contact set is open in [0, 1] and its first point is 0 or a
// contact of a lower feature listed too (lib/poly/earliest.h relies on this).
#pragma once
#include <array>
#include <vector>

#include "motion/trajectory.h"
#include "poly/bernstein.h"
#include "poly/gcd.h"
#include "poly/integer.h"
#include "poly/system.h"

namespace pccd::pred {

using motion::Point_traj;
using poly::Poly;
using poly::System;

// Query kinds 0..4 share the values of pccd_kind and are also the feature kinds of
// their systems. SPHERE_TRIANGLE (a closed ball against a closed triangle; points
// c, f0, f1, f2) is used by body queries; its features are the ball meeting the open
// face, an open edge or a vertex, and (kind SPHERE_TRIANGLE) the static test at t = 0.
enum Feature_kind {
  VERTEX_FACE = 0, EDGE_EDGE = 1, VERTEX_EDGE = 2, VERTEX_VERTEX = 3, SPHERE_SPHERE = 4,
  SPHERE_TRIANGLE = 5, SPHERE_FACE = 6, SPHERE_EDGE = 7, SPHERE_VERTEX = 8
};

struct Feature {
  int kind = 0;
  std::array<int, 4> points{{-1, -1, -1, -1}};  // query point indices, kind's order
};

inline bool operator==(const Feature &a, const Feature &b) { return a.kind == b.kind && a.points == b.points; }

template <class NT>
struct Feature_set {
  std::vector<Feature> features;  // all feature pairs of the query, by tag
  std::vector<System<NT>> systems;  // those not excluded; System::tag -> features
  // When set, only these features get a system (the others are listed, not built).
  const std::vector<Feature> *only = nullptr;
  // Polynomials > 0 on [0, 1] that may divide the query's polynomials
  // (Query_data::positive_factors); exact common zeros divide them out first.
  const std::vector<Poly<arith::Rational>> *positive = nullptr;
  bool wants(const Feature &f) const {
    if (!only) return true;
    for (const Feature &g : *only)
      if (g == f) return true;
    return false;
  }
};

// The common zero set of several polynomials as one polynomial f and whether all are
// identically zero. Exact: their gcd. Intervals: no certified gcd exists; when one
// polynomial certainly has no root on [0, 1] the set is empty (returns false), and
// otherwise the sum of squares (same real zeros) is used.
//
// Exact, with positive factors (Feature_set::positive): each polynomial is divided by them
// first. The common zeros on [0, 1] are the same, and a cross product of a moving point
// with a static edge (which carries the moving side's W) then has a constant gcd, which
// poly::gcd recognizes modulo a prime instead of running the remainder sequence.
inline bool common_zeros(const std::vector<Poly<arith::Rational>> &ps, Poly<arith::Rational> &f,
                         bool &all_zero,
                         const std::vector<Poly<arith::Rational>> *positive = nullptr) {
  f = Poly<arith::Rational>();
  for (const Poly<arith::Rational> &p : ps) {
    f = poly::gcd(std::move(f), positive ? poly::divide_out_positive(p, *positive) : p);
    if (f.degree() == 0) return false;  // a nonzero constant gcd: no common zero at all
  }
  all_zero = f.c.empty();
  return all_zero || f.degree() >= 1;  // a nonzero constant gcd: no common zero at all
}
inline bool common_zeros(const std::vector<Poly<arith::Interval>> &ps, Poly<arith::Interval> &f,
                         bool &all_zero, const std::vector<Poly<arith::Rational>> * = nullptr) {
  const arith::Interval zero(0.0), one(1.0);
  for (const auto &p : ps)
    if (poly::certainly_no_root(p, zero, one)) return false;
  f = Poly<arith::Interval>();
  for (const auto &p : ps) f = f + p * p;
  all_zero = f.is_zero();  // Uncertain unless certain
  return true;
}

template <class NT>
void add_system(Feature_set<NT> &set, Feature feat, typename System<NT>::Kind kind,
                Poly<NT> f, std::vector<Poly<NT>> g) {
  System<NT> s;
  s.kind = kind;
  s.f = std::move(f);
  s.g = std::move(g);
  s.tag = static_cast<int>(set.features.size());
  set.features.push_back(feat);
  set.systems.push_back(std::move(s));
}

// The pair is listed even when excluded, so tags are the same for every number type.
template <class NT>
void skip_feature(Feature_set<NT> &set, Feature feat) { set.features.push_back(feat); }

template <class NT>
void add_vertex_vertex(Feature_set<NT> &set, const Point_traj<NT> &a, const Point_traj<NT> &b,
                       int ia, int ib) {
  using K = typename System<NT>::Kind;
  Feature feat{VERTEX_VERTEX, {{ia, ib, -1, -1}}};
  if (!set.wants(feat)) return skip_feature(set, feat);
  auto d = a - b;
  Poly<NT> f;
  bool all_zero = false;
  std::vector<Poly<NT>> ds;  // moved, not copied (an initializer list copies)
  for (auto &x : d.v) ds.push_back(std::move(x));
  if (!common_zeros(ds, f, all_zero, set.positive)) return skip_feature(set, feat);
  add_system(set, feat, all_zero ? K::zero_f : K::roots, std::move(f), {});
}

// Own trajectories (Query_data::own): the points of one body may all carry one common
// factor c(t) > 0 (a body pair's side is multiplied by the other side's W). Differences
// of points of the same body are then taken between their own trajectories (p / c):
// every polynomial below is homogeneous in each such difference, so it changes by a
// positive factor (the same one for a system's f, and the same one for the two sides of
// each inequality), and its degree drops by deg c per difference (a static obstacle's
// face normal becomes a constant). `o...` arguments: the own trajectories of the points
// of that feature (null: the points themselves). `normal` (faces, with own
// trajectories): a positive multiple of their cross product, of lower degree (a moving
// face's rotated body-frame normal Rn n0 is that cross product divided by W).
template <class NT>
const Point_traj<NT> &own_or(const Point_traj<NT> *own, const Point_traj<NT> &p) {
  return own ? *own : p;
}

// v inside the open segment (e0, e1): v - e0 parallel to e1 - e0, strictly between.
template <class NT>
void add_vertex_edge(Feature_set<NT> &set, const Point_traj<NT> &v, const Point_traj<NT> &e0,
                     const Point_traj<NT> &e1, int iv, int i0, int i1,
                     const Point_traj<NT> *oe0 = nullptr, const Point_traj<NT> *oe1 = nullptr) {
  using K = typename System<NT>::Kind;
  Feature feat{VERTEX_EDGE, {{iv, i0, i1, -1}}};
  if (!set.wants(feat)) return skip_feature(set, feat);
  auto e = own_or(oe1, e1) - own_or(oe0, e0);
  auto u = motion::cross(e, v - e0);
  Poly<NT> f;
  bool all_zero = false;
  std::vector<Poly<NT>> us;  // moved, not copied (an initializer list copies)
  for (auto &x : u.v) us.push_back(std::move(x));
  if (!common_zeros(us, f, all_zero, set.positive)) return skip_feature(set, feat);
  add_system(set, feat, all_zero ? K::zero_f : K::roots, std::move(f),
             {motion::dot(v - e0, e), motion::dot(e1 - v, e)});
}

// The coplanarity polynomials every vertex-face / edge-edge contact is a root of:
// n . (v - f0) with n = (f1 - f0) x (f2 - f0), and ((a1 - a0) x (b0 - a0)) . (b1 - a0).
template <class NT>
Poly<NT> vertex_face_polynomial(const Point_traj<NT> &v, const std::array<const Point_traj<NT> *, 3> &fv) {
  return motion::dot(motion::cross(*fv[1] - *fv[0], *fv[2] - *fv[0]), v - *fv[0]);
}
template <class NT>
Poly<NT> edge_edge_polynomial(const Point_traj<NT> &a0, const Point_traj<NT> &a1, const Point_traj<NT> &b0,
                              const Point_traj<NT> &b1) {
  return motion::dot(motion::cross(a1 - a0, b0 - a0), b1 - a0);
}

// v inside the open triangle (f0, f1, f2): coplanar, strictly left of each edge seen
// along the normal n = (f1 - f0) x (f2 - f0) (n = 0 for a degenerate triangle makes
// every condition fail, as it must).
template <class NT>
void add_vertex_face(Feature_set<NT> &set, const Point_traj<NT> &v,
                     const std::array<const Point_traj<NT> *, 3> &fv, const std::array<int, 4> &idx,
                     const std::array<const Point_traj<NT> *, 3> *fo = nullptr,
                     const Point_traj<NT> *normal = nullptr) {
  using K = typename System<NT>::Kind;
  Feature feat{VERTEX_FACE, idx};
  if (!set.wants(feat)) return skip_feature(set, feat);
  const std::array<const Point_traj<NT> *, 3> &o = fo ? *fo : fv;
  auto n = normal ? *normal : motion::cross(*o[1] - *o[0], *o[2] - *o[0]);
  Poly<NT> f = fo ? motion::dot(n, v - *fv[0]) : vertex_face_polynomial(v, fv);
  std::vector<Poly<NT>> g;
  for (int i = 0; i < 3; ++i)
    g.push_back(motion::dot(n, motion::cross(*o[(i + 1) % 3] - *o[i], v - *fv[i])));
  const auto kind = f.is_zero() ? K::zero_f : K::roots;  // before f is moved
  add_system(set, feat, kind, std::move(f), std::move(g));
}

// Open segments (a0, a1) and (b0, b1) cross at one point: coplanar, not parallel, b0
// and b1 strictly on opposite sides of line a, a0 and a1 strictly on opposite sides
// of line b (sides measured along n = (a1 - a0) x (b1 - b0)).
// With own trajectories (o: a0, a1, b0, b1), f = ((a1 - a0) x (b0 - a0)) . (b1 - b0),
// the same determinant as edge_edge_polynomial's (b1 - a0 = (b1 - b0) + (b0 - a0)).
template <class NT>
void add_edge_edge(Feature_set<NT> &set, const Point_traj<NT> &a0, const Point_traj<NT> &a1,
                   const Point_traj<NT> &b0, const Point_traj<NT> &b1,
                   const std::array<const Point_traj<NT> *, 4> *o = nullptr) {
  using K = typename System<NT>::Kind;
  Feature feat{EDGE_EDGE, {{0, 1, 2, 3}}};
  if (!set.wants(feat)) return skip_feature(set, feat);
  auto ea = o ? *(*o)[1] - *(*o)[0] : a1 - a0, eb = o ? *(*o)[3] - *(*o)[2] : b1 - b0;
  Poly<NT> f = o ? motion::dot(motion::cross(ea, b0 - a0), eb) : edge_edge_polynomial(a0, a1, b0, b1);
  auto n = motion::cross(ea, eb);
  Poly<NT> sb0 = motion::dot(n, motion::cross(ea, b0 - a0));
  Poly<NT> sb1 = motion::dot(n, motion::cross(ea, b1 - a0));
  Poly<NT> sa0 = motion::dot(n, motion::cross(eb, a0 - b0));
  Poly<NT> sa1 = motion::dot(n, motion::cross(eb, a1 - b0));
  const auto kind = f.is_zero() ? K::zero_f : K::roots;  // before f is moved
  add_system(set, feat, kind, std::move(f),
             {-(sb0 * sb1), -(sa0 * sa1)});
}

// Balls against a triangle's features (kind SPHERE_TRIANGLE). Every point trajectory
// is D(t) times the true position, D > 0 on [0, 1] (D = 1 for primitive queries:
// `r2d2` = r^2 D^2), so every condition is homogeneous after multiplying the radius
// by D. The distance from the centre c to the closed triangle equals r exactly when
// the closest point lies in one relatively open feature: the open face (distance to
// the plane r, projection strictly inside), an open edge (distance to the line r,
// projection strictly inside) or a vertex. So every first contact after t = 0 is a
// hit of one of these systems and every hit is a contact (distance exactly r); the
// vertex systems are closed sublevel sets, which makes the union closed. A ball that
// already meets the triangle at t = 0 without touching a vertex is found by the
// static test (pred/static_contact.h). `label` (optional) names the system's feature
// otherwise (the minimum-separation queries of delta_systems.h reuse these systems with
// the ball at a vertex of radius delta).
template <class NT>
void add_ball_vertex(Feature_set<NT> &set, const Point_traj<NT> &c, const Point_traj<NT> &v,
                     const Poly<NT> &r2d2, int iv, const Feature *label = nullptr) {
  using K = typename System<NT>::Kind;
  const Feature feat = label ? *label : Feature{SPHERE_VERTEX, {{0, iv, -1, -1}}};
  if (!set.wants(feat)) return skip_feature(set, feat);
  auto d = c - v;
  add_system(set, feat, K::sublevel, motion::dot(d, d) - r2d2, {});
}

template <class NT>
void add_ball_edge(Feature_set<NT> &set, const Point_traj<NT> &c, const Point_traj<NT> &e0,
                   const Point_traj<NT> &e1, const Poly<NT> &r2d2, int i0, int i1,
                   const Feature *label = nullptr, const Point_traj<NT> *oe0 = nullptr,
                   const Point_traj<NT> *oe1 = nullptr) {
  using K = typename System<NT>::Kind;
  const Feature feat = label ? *label : Feature{SPHERE_EDGE, {{0, i0, i1, -1}}};
  if (!set.wants(feat)) return skip_feature(set, feat);
  auto e = own_or(oe1, e1) - own_or(oe0, e0);
  auto u = motion::cross(e, c - e0);
  Poly<NT> f = motion::dot(u, u) - r2d2 * motion::dot(e, e);
  const auto kind = f.is_zero() ? K::zero_f : K::roots;  // before f is moved
  add_system(set, feat, kind, std::move(f),
             {motion::dot(c - e0, e), motion::dot(e1 - c, e)});
}

template <class NT>
void add_ball_face(Feature_set<NT> &set, const Point_traj<NT> &c,
                   const std::array<const Point_traj<NT> *, 3> &fv, const Poly<NT> &r2d2,
                   const Feature *label = nullptr,
                   const std::array<const Point_traj<NT> *, 3> *fo = nullptr,
                   const Point_traj<NT> *normal = nullptr) {
  using K = typename System<NT>::Kind;
  const Feature feat = label ? *label : Feature{SPHERE_FACE, {{0, 1, 2, 3}}};
  if (!set.wants(feat)) return skip_feature(set, feat);
  const std::array<const Point_traj<NT> *, 3> &o = fo ? *fo : fv;
  auto n = normal ? *normal : motion::cross(*o[1] - *o[0], *o[2] - *o[0]);
  Poly<NT> h = motion::dot(n, c - *fv[0]);
  Poly<NT> f = h * h - r2d2 * motion::dot(n, n);
  std::vector<Poly<NT>> g;
  for (int i = 0; i < 3; ++i)
    g.push_back(motion::dot(n, motion::cross(*o[(i + 1) % 3] - *o[i], c - *fv[i])));
  const auto kind = f.is_zero() ? K::zero_f : K::roots;  // before f is moved
  add_system(set, feat, kind, std::move(f), std::move(g));
}

}  // namespace pccd::pred
