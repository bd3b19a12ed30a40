// Contact point and normal of two features (contact_geometry.h has the definitions).
//
// One set of formulas, templated on the number type: NT = Rational at an exact time,
// NT = Interval over a time interval, where arith::sign and division throw Uncertain
// when undecided and the caller falls back to the features' boxes.
#include "narrow/contact_geometry.h"

#include <cfloat>
#include <cmath>
#include <string>
#include <type_traits>

#include "arith/convert.h"
#include "arith/errors.h"
#include "narrow/pair_ctx.h"
#include "poly/bernstein.h"
#include "pred/static_contact.h"

namespace pccd::narrow {
namespace {

using arith::Input_error;
using arith::Interval;
using arith::Rational;
using arith::sign;
using pred::cross3;
using pred::dot3;
using pred::sub;
template <class NT>
using V = pred::Vec3<NT>;

// A feature as world points: a vertex (n = 1), an edge (2), a triangle (3) or a ball
// (1: its centre, radius r).
template <class NT>
struct Shape {
  int kind = F_VERTEX;
  int n = 1;
  std::array<V<NT>, 3> p;
  std::array<V<NT>, 2> e;  // p[1] - p[0], p[2] - p[0] (the sides an edge or triangle has)
  NT r{};
};

template <class NT>
V<NT> add(const V<NT> &a, const V<NT> &b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
template <class NT>
V<NT> scaled(const V<NT> &a, const NT &s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
template <class NT>
NT dist2(const V<NT> &a, const V<NT> &b) {
  const V<NT> d = sub(a, b);
  return dot3(d, d);
}

// Thrown (exact times only) when the computed point is not on both features.
struct Not_touching {};

// The closest point of the closed segment [a, b] to c.
template <class NT>
V<NT> closest_on_segment(const V<NT> &c, const V<NT> &a, const V<NT> &b) {
  const V<NT> d = sub(b, a);
  const NT dd = dot3(d, d);
  if (sign(dd) == 0) return a;
  const NT s = dot3(sub(c, a), d);
  if (sign(s) <= 0) return a;
  if (sign(NT(s - dd)) >= 0) return b;
  return add(a, scaled(d, NT(s / dd)));
}

// The closest point of the closed triangle t to c: Ericson, Real-Time Collision
// Detection, 5.1.5 (Voronoi regions of the vertices, edges and face); a degenerate
// triangle (collinear corners) is the union of its sides.
template <class NT>
V<NT> closest_on_triangle(const V<NT> &p, const std::array<V<NT>, 3> &t) {
  const V<NT> &a = t[0], &b = t[1], &c = t[2];
  const V<NT> ab = sub(b, a), ac = sub(c, a);
  const V<NT> n = cross3(ab, ac);
  if (sign(dot3(n, n)) == 0) {
    V<NT> best = closest_on_segment(p, a, b);
    for (int k = 1; k < 3; ++k) {
      const V<NT> q = closest_on_segment(p, t[k], t[(k + 1) % 3]);
      if (sign(NT(dist2(p, q) - dist2(p, best))) < 0) best = q;
    }
    return best;
  }
  const V<NT> ap = sub(p, a);
  const NT d1 = dot3(ab, ap), d2 = dot3(ac, ap);
  if (sign(d1) <= 0 && sign(d2) <= 0) return a;
  const V<NT> bp = sub(p, b);
  const NT d3 = dot3(ab, bp), d4 = dot3(ac, bp);
  if (sign(d3) >= 0 && sign(NT(d4 - d3)) <= 0) return b;
  const NT vc = d1 * d4 - d3 * d2;
  if (sign(vc) <= 0 && sign(d1) >= 0 && sign(d3) <= 0) return add(a, scaled(ab, NT(d1 / (d1 - d3))));
  const V<NT> cp = sub(p, c);
  const NT d5 = dot3(ab, cp), d6 = dot3(ac, cp);
  if (sign(d6) >= 0 && sign(NT(d5 - d6)) <= 0) return c;
  const NT vb = d5 * d2 - d1 * d6;
  if (sign(vb) <= 0 && sign(d2) >= 0 && sign(d6) <= 0) return add(a, scaled(ac, NT(d2 / (d2 - d6))));
  const NT va = d3 * d6 - d5 * d4;
  const NT e1 = d4 - d3, e2 = d5 - d6;
  if (sign(va) <= 0 && sign(e1) >= 0 && sign(e2) >= 0)
    return add(b, scaled(sub(c, b), NT(e1 / (e1 + e2))));
  const NT denom = va + vb + vc;  // = |n|^2 > 0
  return add(a, add(scaled(ab, NT(vb / denom)), scaled(ac, NT(vc / denom))));
}

// Exact membership in the closed features (Rational only).
bool on_segment(const V<Rational> &p, const V<Rational> &a, const V<Rational> &b) {
  const V<Rational> d = sub(b, a), w = sub(p, a);
  const Rational dd = dot3(d, d);
  if (sgn(dd) == 0) return w == V<Rational>{};
  const V<Rational> c = cross3(w, d);
  if (sgn(dot3(c, c)) != 0) return false;
  const Rational s = dot3(w, d);
  return sgn(s) >= 0 && s <= dd;
}
bool on_triangle(const V<Rational> &p, const std::array<V<Rational>, 3> &t) {
  const V<Rational> n = cross3(sub(t[1], t[0]), sub(t[2], t[0]));
  if (sgn(dot3(n, n)) == 0)
    return on_segment(p, t[0], t[1]) || on_segment(p, t[1], t[2]) || on_segment(p, t[2], t[0]);
  if (sgn(dot3(n, sub(p, t[0]))) != 0) return false;
  for (int k = 0; k < 3; ++k)
    if (sgn(dot3(cross3(sub(t[(k + 1) % 3], t[k]), sub(p, t[k])), n)) < 0) return false;
  return true;
}
bool on_shape(const V<Rational> &p, const Shape<Rational> &s) {
  switch (s.kind) {
    case F_VERTEX: return p == s.p[0];
    case F_EDGE: return on_segment(p, s.p[0], s.p[1]);
    case F_TRIANGLE: return on_triangle(p, s.p);
    default: return dist2(p, s.p[0]) <= s.r * s.r;
  }
}

// The segments of a shape: an edge, or a triangle's three sides.
template <class NT>
int segments(const Shape<NT> &s, std::array<std::array<V<NT>, 2>, 3> &out) {
  if (s.kind == F_EDGE) {
    out[0] = {s.p[0], s.p[1]};
    return 1;
  }
  for (int k = 0; k < 3; ++k) out[k] = {s.p[k], s.p[(k + 1) % 3]};
  return 3;
}

// A point of two closed features (edges or triangles) that meet, by the candidates of
// contact_geometry.h; Not_touching when none lies on both.
V<Rational> meet_point(const Shape<Rational> &A, const Shape<Rational> &B) {
  std::vector<V<Rational>> cand(A.p.begin(), A.p.begin() + A.n);
  cand.insert(cand.end(), B.p.begin(), B.p.begin() + B.n);
  std::array<std::array<V<Rational>, 2>, 3> sa, sb;
  const int na = segments(A, sa), nb = segments(B, sb);
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j) {  // crossings of non-parallel segment lines
      const V<Rational> da = sub(sa[i][1], sa[i][0]), db = sub(sb[j][1], sb[j][0]);
      const V<Rational> n = cross3(da, db);
      const Rational nn = dot3(n, n);
      if (sgn(nn) == 0) continue;
      const Rational s = dot3(cross3(sub(sb[j][0], sa[i][0]), db), n) / nn;
      cand.push_back(add(sa[i][0], scaled(da, s)));
    }
  auto plane = [&](const Shape<Rational> &T, const std::array<std::array<V<Rational>, 2>, 3> &ss,
                   int ns) {  // crossings of segments ss with T's plane
    if (T.kind != F_TRIANGLE) return;
    const V<Rational> n = cross3(sub(T.p[1], T.p[0]), sub(T.p[2], T.p[0]));
    for (int i = 0; i < ns; ++i) {
      const V<Rational> d = sub(ss[i][1], ss[i][0]);
      const Rational den = dot3(n, d);
      if (sgn(den) == 0) continue;
      cand.push_back(add(ss[i][0], scaled(d, Rational(dot3(n, sub(T.p[0], ss[i][0])) / den))));
    }
  };
  plane(B, sa, na);
  plane(A, sb, nb);
  for (const V<Rational> &c : cand)
    if (on_shape(c, A) && on_shape(c, B)) return c;
  throw Not_touching{};
}

// The contact point (contact_geometry.h). Rational: exact; Interval: Uncertain when a
// decision is not certain.
template <class NT>
V<NT> contact_point(const Shape<NT> &A, const Shape<NT> &B) {
  if (A.kind == F_VERTEX) return A.p[0];
  if (B.kind == F_VERTEX) return B.p[0];
  if (A.kind == F_SPHERE && B.kind == F_SPHERE) {
    const NT f = A.r / (A.r + B.r);
    return add(A.p[0], scaled(sub(B.p[0], A.p[0]), f));
  }
  if (A.kind == F_SPHERE || B.kind == F_SPHERE) {
    const Shape<NT> &ball = A.kind == F_SPHERE ? A : B, &x = A.kind == F_SPHERE ? B : A;
    if (x.kind == F_EDGE) return closest_on_segment(ball.p[0], x.p[0], x.p[1]);
    return closest_on_triangle(ball.p[0], x.p);
  }
  if (A.kind == F_EDGE && B.kind == F_EDGE) {
    const V<NT> &da = A.e[0], &db = B.e[0];
    const V<NT> n = cross3(da, db);
    const NT nn = dot3(n, n);
    if (sign(nn) != 0) {
      const NT s = dot3(cross3(sub(B.p[0], A.p[0]), db), n) / nn;
      return add(A.p[0], scaled(da, s));
    }
    if constexpr (std::is_same_v<NT, Rational>) {  // parallel: the first endpoint on the other
      for (int k = 0; k < 2; ++k)
        if (on_segment(A.p[k], B.p[0], B.p[1])) return A.p[k];
      for (int k = 0; k < 2; ++k)
        if (on_segment(B.p[k], A.p[0], A.p[1])) return B.p[k];
      throw Not_touching{};
    }
    throw arith::Uncertain{};  // (intervals: nn certainly zero only for point data)
  }
  if constexpr (std::is_same_v<NT, Rational>) return meet_point(A, B);
  throw arith::Uncertain{};
}

// The unnormalized normal (contact_geometry.h); false when the pair has none.
template <class NT>
bool contact_normal(const Shape<NT> &A, const Shape<NT> &B, const V<NT> &point, V<NT> &n) {
  const int ka = A.kind, kb = B.kind;
  if ((ka == F_VERTEX && kb == F_TRIANGLE) || (ka == F_TRIANGLE && kb == F_VERTEX)) {
    const Shape<NT> &t = ka == F_TRIANGLE ? A : B;
    n = cross3(t.e[0], t.e[1]);
    return true;
  }
  if (ka == F_EDGE && kb == F_EDGE) {
    n = cross3(A.e[0], B.e[0]);
    return true;
  }
  if (ka == F_SPHERE && kb == F_SPHERE) {
    n = sub(B.p[0], A.p[0]);
    return true;
  }
  if (ka == F_SPHERE) {
    n = sub(point, A.p[0]);
    return true;
  }
  if (kb == F_SPHERE) {
    n = sub(B.p[0], point);
    return true;
  }
  return false;
}

// The unit vector of n enclosed by interval normalization (outward rounding: sqrt is
// correctly rounded under round-to-nearest, the mode every C entry point runs in, and
// one ulp outward covers it in any mode); false when |n|^2 is not certainly positive.
bool unit_enclosure(const V<Interval> &n, std::array<Interval, 3> &u) {
  const Interval nn = dot3(n, n);
  if (!(nn.lo > 0) || !std::isfinite(nn.hi)) return false;
  const Interval len(arith::round_down(std::sqrt(nn.lo)), arith::round_up(std::sqrt(nn.hi)));
  for (int k = 0; k < 3; ++k) {
    const Interval q = n[k] / len;
    u[k] = Interval(std::fmax(q.lo, -1.0), std::fmin(q.hi, 1.0));
  }
  return true;
}

// An enclosure of p over [a, b] (doubles, 0 <= a < b <= 1): the Bernstein hull of the
// exact polynomial reparametrized exactly to [a, b].
Interval range_over(const poly::Poly<Rational> &p, double a, double b) {
  if (p.c.empty()) return Interval(0.0);
  return poly::range_on_unit(poly::convert<Interval>(poly::reparametrize(p, Rational(a), Rational(b))));
}

// The world position of body point p over [a, b]: (Rn p + O) / W (moving_body.h); with
// offset = false the world vector R(t) p of a body vector p (an edge's direction: tighter
// than the difference of its ends' enclosures, and exact for a translation).
V<Interval> position_over(const Motion_data &mo, const motion::Point3_q &p, double a, double b,
                          bool offset = true) {
  const Interval w = range_over(mo.W, a, b);
  if (!(w.lo > 0)) return {Interval(-HUGE_VAL, HUGE_VAL), Interval(-HUGE_VAL, HUGE_VAL),
                           Interval(-HUGE_VAL, HUGE_VAL)};
  V<Interval> x;
  for (int k = 0; k < 3; ++k) {
    poly::Poly<Rational> num = offset ? mo.O[k] : poly::Poly<Rational>();
    for (int j = 0; j < 3; ++j)
      if (sgn(p[j]) != 0) num = num + p[j] * mo.Rn[k][j];
    x[k] = range_over(num, a, b) / w;
  }
  return x;
}

const char *kind_word(int kind) {
  static const char *const words[] = {"vertex", "edge", "triangle", "sphere"};
  return words[kind];
}
const char *kind_plural(int kind) {
  static const char *const words[] = {"vertices", "edges", "triangles", "spheres"};
  return words[kind];
}

// The body points of feature f (checked), as indices into the body's points.
int feature_points(const Moving_body &b, const Feature_arg &f, std::array<size_t, 3> &idx) {
  if (f.kind == F_SOLID)
    throw Input_error(std::string(f.kind_name) + ": a solid (a containment at t = 0) has no contact point or normal");
  if (f.kind < F_VERTEX || f.kind > F_SPHERE)
    throw Input_error(std::string(f.kind_name) + ": " + std::to_string(f.kind) +
                      " is not a pccd_feature (0 vertex, 1 edge, 2 triangle, 3 sphere, 4 solid)");
  if (b.is_mesh() == (f.kind == F_SPHERE))
    throw Input_error(std::string(f.kind_name) + ": " + kind_word(f.kind) + " is not a feature of a " +
                      (b.is_mesh() ? "mesh body (vertex, edge or triangle)" : "sphere body (sphere)"));
  size_t count = f.kind == F_EDGE ? b.mesh->edges().size()
                 : f.kind == F_TRIANGLE ? b.mesh->triangles().size() : b.n_points();
  if (f.index >= count)
    throw Input_error(std::string(f.index_name) + ": " + std::to_string(f.index) + " out of range (" +
                      std::to_string(count) + " " + (count == 1 ? kind_word(f.kind) : kind_plural(f.kind)) + ")");
  switch (f.kind) {
    case F_EDGE: idx = {b.mesh->edges()[f.index][0], b.mesh->edges()[f.index][1], 0}; return 2;
    case F_TRIANGLE: {
      const auto &t = b.mesh->triangles()[f.index];
      idx = {t[0], t[1], t[2]};
      return 3;
    }
    default: idx = {f.index, 0, 0}; return 1;
  }
}

// The shape of feature f: pos(p) the world position of body point p, dir(v) the world
// vector of body vector v.
template <class NT, class Pos, class Dir>
Shape<NT> shape_of(const Moving_body &b, const Feature_arg &f, Pos &&pos, Dir &&dir) {
  std::array<size_t, 3> idx;
  Shape<NT> s;
  s.kind = f.kind;
  s.n = feature_points(b, f, idx);
  for (int k = 0; k < s.n; ++k) s.p[k] = pos(b.point(idx[k]));
  for (int k = 1; k < s.n; ++k) {
    const motion::Point3_q &p0 = b.point(idx[0]), &pk = b.point(idx[k]);
    s.e[k - 1] = dir(motion::Point3_q{pk[0] - p0[0], pk[1] - p0[1], pk[2] - p0[2]});
  }
  if (f.kind == F_SPHERE) s.r = arith::from_rational<NT>(b.spheres->radii()[f.index]);
  return s;
}

// The shape at the exact time t (sides: differences of exact positions).
Shape<Rational> exact_shape(const Moving_body &b, const Feature_arg &f, const Rational &t) {
  Shape<Rational> s = shape_of<Rational>(
      b, f, [&](const motion::Point3_q &p) { return b.mo->motion.position(p, t); },
      [](const motion::Point3_q &) { return V<Rational>{}; });
  for (int k = 1; k < s.n; ++k) s.e[k - 1] = sub(s.p[k], s.p[0]);
  return s;
}

// The shape enclosed over [lo, hi].
Shape<Interval> shape_over(const Moving_body &b, const Feature_arg &f, double lo, double hi) {
  return shape_of<Interval>(
      b, f, [&](const motion::Point3_q &p) { return position_over(*b.mo, p, lo, hi); },
      [&](const motion::Point3_q &v) { return position_over(*b.mo, v, lo, hi, false); });
}

// The box of a shape over the time interval: its points' hull, a ball's grown by r.
std::array<Interval, 3> box_of(const Shape<Interval> &s) {
  std::array<Interval, 3> box;
  for (int k = 0; k < 3; ++k) {
    box[k] = s.p[0][k];
    for (int i = 1; i < s.n; ++i) box[k] = arith::hull(box[k], s.p[i][k]);
    if (s.kind == F_SPHERE) box[k] = box[k] + Interval(-s.r.hi, s.r.hi);
  }
  return box;
}

// a meet b per coordinate; false when empty in some coordinate.
bool meet(std::array<Interval, 3> &a, const std::array<Interval, 3> &b) {
  for (int k = 0; k < 3; ++k) {
    a[k] = Interval(std::fmax(a[k].lo, b[k].lo), std::fmin(a[k].hi, b[k].hi));
    if (a[k].lo > a[k].hi) return false;
  }
  return true;
}

}  // namespace

Contact_geometry contact_geometry(const Moving_body &a, const Feature_arg &fa, const Moving_body &b,
                                  const Feature_arg &fb, const Rational &t_lo, const Rational &t_hi) {
  for (const auto &[t, name] : {std::pair<const Rational &, const char *>{t_lo, "t_lo"}, {t_hi, "t_hi"}})
    if (sgn(t) < 0 || t > 1) throw Input_error(std::string(name) + ": " + arith::to_string(t) + " is outside [0, 1]");
  if (t_lo > t_hi)
    throw Input_error("t_lo: " + arith::to_string(t_lo) + " is above t_hi = " + arith::to_string(t_hi));
  Contact_geometry g;
  if (t_lo == t_hi) {
    g.exact = true;
    const Shape<Rational> A = exact_shape(a, fa, t_lo), B = exact_shape(b, fb, t_lo);
    auto apart = [&] {
      return Input_error(std::string("the features do not touch at t = ") + arith::to_string(t_lo) +
                         " (a " + kind_word(fa.kind) + " of a and a " + kind_word(fb.kind) +
                         " of b; features reported with config.min_distance > 0 may be apart)");
    };
    try {
      g.point_q = contact_point(A, B);
    } catch (const Not_touching &) {
      throw apart();
    }
    if (!on_shape(g.point_q, A) || !on_shape(g.point_q, B)) throw apart();
    for (int k = 0; k < 3; ++k) g.point[k] = arith::enclose(g.point_q[k]);
    V<Rational> n;
    if (contact_normal(A, B, g.point_q, n) && sgn(dot3(n, n)) != 0) {
      g.normal_state = Normal_state::enclosed;
      g.normal_q = n;
      const V<Interval> ni{arith::enclose(n[0]), arith::enclose(n[1]), arith::enclose(n[2])};
      if (!unit_enclosure(ni, g.normal))  // tiny components: still a valid enclosure
        g.normal = {Interval(-1, 1), Interval(-1, 1), Interval(-1, 1)};
    }
    return g;
  }
  const double lo = std::fmax(arith::enclose(t_lo).lo, 0.0), hi = std::fmin(arith::enclose(t_hi).hi, 1.0);
  const Shape<Interval> A = shape_over(a, fa, lo, hi), B = shape_over(b, fb, lo, hi);
  std::array<Interval, 3> box = box_of(A);
  if (!meet(box, box_of(B)))
    throw Input_error("the features do not touch in [t_lo, t_hi] = [" + arith::to_string(t_lo) + ", " +
                      arith::to_string(t_hi) + "] (their boxes over it are apart)");
  g.point = box;
  bool formula = false;
  try {
    std::array<Interval, 3> p = contact_point(A, B);
    if (!meet(p, box))
      throw Input_error("the features do not touch in [t_lo, t_hi] = [" + arith::to_string(t_lo) + ", " +
                        arith::to_string(t_hi) + "]");
    g.point = p;
    formula = true;
  } catch (const arith::Uncertain &) {
  }
  V<Interval> n;
  const bool has = contact_normal(A, B, g.point, n);
  const bool needs_point = A.kind == F_SPHERE ? B.kind != F_SPHERE : B.kind == F_SPHERE;
  // Point intervals are exact values (positions that stay put over [t_lo, t_hi]).
  const bool zero = has && n[0].is_point_zero() && n[1].is_point_zero() && n[2].is_point_zero();
  if (!has || (zero && (!needs_point || formula))) {
    g.normal_state = Normal_state::none;
  } else if ((!needs_point || formula) && unit_enclosure(n, g.normal)) {
    g.normal_state = Normal_state::enclosed;
  } else {
    g.normal_state = Normal_state::unknown;
    g.normal = {Interval(-1, 1), Interval(-1, 1), Interval(-1, 1)};
  }
  return g;
}

}  // namespace pccd::narrow
