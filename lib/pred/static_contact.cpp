#include "pred/static_contact.h"

namespace pccd::pred {

using arith::sign;

namespace {

// arith::certainly_nonzero / _positive / _negative (interval.h, rational.h) and the
// exact twin of the first.
bool certainly_nonzero(const arith::Rational &x) { return sgn(x) != 0; }
using arith::certainly_negative;
using arith::certainly_nonzero;
using arith::certainly_positive;

// Every point of p certainly strictly on one side of the plane of t (false when unsure,
// never Uncertain: a cheap first test that settles most static pairs, e.g. triangles on
// parallel planes, before the side tests below could meet a zero they cannot certify).
template <class NT>
bool strictly_one_side(const std::array<Vec3<NT>, 3> &t, const std::array<Vec3<NT>, 3> &p) {
  const Vec3<NT> n = cross3(sub(t[1], t[0]), sub(t[2], t[0]));
  bool pos = true, neg = true;
  for (const Vec3<NT> &x : p) {
    const NT h = dot3(n, sub(x, t[0]));
    pos = pos && certainly_positive(h);
    neg = neg && certainly_negative(h);
  }
  return pos || neg;
}

// The two triangles' boxes certainly miss each other on some axis.
template <class NT>
bool boxes_apart(const std::array<Vec3<NT>, 3> &a, const std::array<Vec3<NT>, 3> &b) {
  for (int k = 0; k < 3; ++k) {
    bool a_below = true, b_below = true;  // every corner of a below every corner of b, and back
    for (const Vec3<NT> &x : a)
      for (const Vec3<NT> &y : b) {
        const NT d = y[k] - x[k];
        a_below = a_below && certainly_positive(d);
        b_below = b_below && certainly_negative(d);
      }
    if (a_below || b_below) return true;
  }
  return false;
}

// v = 0. One component certainly nonzero settles it before any sign is asked of the
// others: the filter then decides "distinct" even when another component's interval
// straddles zero (equal coordinates, e.g. an axis-aligned edge, scaled by an inexact
// D(0) in a body query), which would throw Uncertain and send the test to rationals.
template <class NT>
bool is_zero_vec(const Vec3<NT> &v) {
  for (int i = 0; i < 3; ++i)
    if (certainly_nonzero(v[i])) return false;
  return sign(v[0]) == 0 && sign(v[1]) == 0 && sign(v[2]) == 0;
}

template <class NT>
bool equal(const Vec3<NT> &a, const Vec3<NT> &b) {
  return is_zero_vec(sub(a, b));
}

// p in the open segment (a, b).
template <class NT>
bool in_open_segment(const Vec3<NT> &p, const Vec3<NT> &a, const Vec3<NT> &b) {
  Vec3<NT> e = sub(b, a);
  if (!is_zero_vec(cross3(e, sub(p, a)))) return false;
  return sign(dot3(sub(p, a), e)) > 0 && sign(dot3(sub(b, p), e)) > 0;
}

// p in the closed segment [a, b].
template <class NT>
bool in_segment(const Vec3<NT> &p, const Vec3<NT> &a, const Vec3<NT> &b) {
  return equal(p, a) || equal(p, b) || in_open_segment(p, a, b);
}

// The side conditions n . ((t[i+1] - t[i]) x (p - t[i])) of a point in the plane.
template <class NT>
bool strictly_inside_sides(const Vec3<NT> &p, const std::array<Vec3<NT>, 3> &t, const Vec3<NT> &n) {
  for (int i = 0; i < 3; ++i)
    if (sign(dot3(n, cross3(sub(t[(i + 1) % 3], t[i]), sub(p, t[i])))) <= 0) return false;
  return true;
}

}  // namespace

template <class NT>
bool point_in_triangle(const Vec3<NT> &p, const std::array<Vec3<NT>, 3> &t) {
  for (int i = 0; i < 3; ++i)
    if (in_segment(p, t[i], t[(i + 1) % 3])) return true;
  Vec3<NT> n = cross3(sub(t[1], t[0]), sub(t[2], t[0]));
  return sign(dot3(n, sub(p, t[0]))) == 0 && strictly_inside_sides(p, t, n);
}

template <class NT>
bool segments_meet(const Vec3<NT> &p, const Vec3<NT> &q, const Vec3<NT> &a, const Vec3<NT> &b) {
  if (in_segment(p, a, b) || in_segment(q, a, b) || in_segment(a, p, q) || in_segment(b, p, q))
    return true;
  // Proper crossing of the open segments (see pred/features.h, add_edge_edge).
  Vec3<NT> ep = sub(q, p), ea = sub(b, a);
  if (sign(dot3(cross3(ep, sub(a, p)), sub(b, p))) != 0) return false;
  Vec3<NT> n = cross3(ep, ea);
  int sa = sign(dot3(n, cross3(ep, sub(a, p)))), sb = sign(dot3(n, cross3(ep, sub(b, p))));
  int sp = sign(dot3(n, cross3(ea, sub(p, a)))), sq = sign(dot3(n, cross3(ea, sub(q, a))));
  return sa * sb < 0 && sp * sq < 0;
}

template <class NT>
bool segment_meets_triangle(const Vec3<NT> &p, const Vec3<NT> &q, const std::array<Vec3<NT>, 3> &t) {
  if (point_in_triangle(p, t) || point_in_triangle(q, t)) return true;
  for (int i = 0; i < 3; ++i)
    if (segments_meet(p, q, t[i], t[(i + 1) % 3])) return true;
  // Transversal crossing of the open face.
  Vec3<NT> n = cross3(sub(t[1], t[0]), sub(t[2], t[0]));
  int sp = sign(dot3(n, sub(p, t[0]))), sq = sign(dot3(n, sub(q, t[0])));
  if (sp * sq >= 0) return false;  // also n = 0 (degenerate triangle)
  Vec3<NT> d = sub(q, p);
  int first = 0;
  for (int i = 0; i < 3; ++i) {
    int s = sign(dot3(d, cross3(sub(t[i], p), sub(t[(i + 1) % 3], p))));
    if (s == 0 || (first != 0 && s != first)) return false;
    first = s;
  }
  return true;
}

template <class NT>
bool triangles_meet(const std::array<Vec3<NT>, 3> &a, const std::array<Vec3<NT>, 3> &b) {
  // Separated by an axis or by either triangle's plane: apart (each test is exact for
  // Rational and certified for Interval; unsure goes on to the full test).
  if (boxes_apart(a, b) || strictly_one_side(a, b) || strictly_one_side(b, a)) return false;
  for (int i = 0; i < 3; ++i)
    if (segment_meets_triangle(a[i], a[(i + 1) % 3], b)) return true;
  for (int i = 0; i < 3; ++i)
    if (segment_meets_triangle(b[i], b[(i + 1) % 3], a)) return true;
  return false;
}

namespace {

// The closed ball (c, r2d2) holds the point v.
template <class NT>
bool ball_holds(const Vec3<NT> &c, const NT &r2d2, const Vec3<NT> &v) {
  const Vec3<NT> d = sub(c, v);
  return sign(dot3(d, d) - r2d2) <= 0;
}

// The open segment (a, b) comes within r of c with the projection of c strictly inside
// it (never for a = b).
template <class NT>
bool ball_meets_open_segment(const Vec3<NT> &c, const NT &r2d2, const Vec3<NT> &a, const Vec3<NT> &b) {
  const Vec3<NT> e = sub(b, a);
  if (sign(dot3(sub(c, a), e)) <= 0 || sign(dot3(sub(b, c), e)) <= 0) return false;
  const Vec3<NT> u = cross3(e, sub(c, a));
  return sign(dot3(u, u) - r2d2 * dot3(e, e)) <= 0;
}

}  // namespace

template <class NT>
bool ball_meets_triangle(const Vec3<NT> &c, const NT &r2d2, const std::array<Vec3<NT>, 3> &t) {
  for (int i = 0; i < 3; ++i)
    if (ball_holds(c, r2d2, t[i])) return true;
  for (int i = 0; i < 3; ++i)
    if (ball_meets_open_segment(c, r2d2, t[i], t[(i + 1) % 3])) return true;
  Vec3<NT> n = cross3(sub(t[1], t[0]), sub(t[2], t[0]));
  if (!strictly_inside_sides(c, t, n)) return false;  // also n = 0
  NT h = dot3(n, sub(c, t[0]));
  return sign(h * h - r2d2 * dot3(n, n)) <= 0;
}

template <class NT>
bool ball_meets_segment(const Vec3<NT> &c, const NT &r2d2, const Vec3<NT> &a, const Vec3<NT> &b) {
  return ball_holds(c, r2d2, a) || ball_holds(c, r2d2, b) || ball_meets_open_segment(c, r2d2, a, b);
}

template <class NT>
bool segments_within(const Vec3<NT> &p, const Vec3<NT> &q, const Vec3<NT> &a, const Vec3<NT> &b,
                     const NT &r2d2) {
  if (ball_meets_segment(p, r2d2, a, b) || ball_meets_segment(q, r2d2, a, b) ||
      ball_meets_segment(a, r2d2, p, q) || ball_meets_segment(b, r2d2, p, q))
    return true;
  const Vec3<NT> ea = sub(q, p), eb = sub(b, a), w = sub(a, p);
  const Vec3<NT> n = cross3(ea, eb);
  const NT nn = dot3(n, n);
  if (sign(nn) <= 0) return false;  // parallel: an endpoint pair above is as close
  const NT s = dot3(cross3(w, eb), n), u = dot3(cross3(w, ea), n);
  if (sign(s) <= 0 || sign(nn - s) <= 0 || sign(u) <= 0 || sign(nn - u) <= 0) return false;
  const NT h = dot3(n, w);
  return sign(h * h - r2d2 * nn) <= 0;
}

template bool triangles_meet(const std::array<Vec3<arith::Rational>, 3> &,
                             const std::array<Vec3<arith::Rational>, 3> &);
template bool triangles_meet(const std::array<Vec3<arith::Interval>, 3> &,
                             const std::array<Vec3<arith::Interval>, 3> &);
template bool segment_meets_triangle(const Vec3<arith::Rational> &, const Vec3<arith::Rational> &,
                                     const std::array<Vec3<arith::Rational>, 3> &);
template bool segment_meets_triangle(const Vec3<arith::Interval> &, const Vec3<arith::Interval> &,
                                     const std::array<Vec3<arith::Interval>, 3> &);
template bool ball_meets_triangle(const Vec3<arith::Rational> &, const arith::Rational &,
                                  const std::array<Vec3<arith::Rational>, 3> &);
template bool ball_meets_triangle(const Vec3<arith::Interval> &, const arith::Interval &,
                                  const std::array<Vec3<arith::Interval>, 3> &);
template bool ball_meets_segment(const Vec3<arith::Rational> &, const arith::Rational &,
                                 const Vec3<arith::Rational> &, const Vec3<arith::Rational> &);
template bool ball_meets_segment(const Vec3<arith::Interval> &, const arith::Interval &,
                                 const Vec3<arith::Interval> &, const Vec3<arith::Interval> &);
template bool segments_within(const Vec3<arith::Rational> &, const Vec3<arith::Rational> &,
                              const Vec3<arith::Rational> &, const Vec3<arith::Rational> &,
                              const arith::Rational &);
template bool segments_within(const Vec3<arith::Interval> &, const Vec3<arith::Interval> &,
                              const Vec3<arith::Interval> &, const Vec3<arith::Interval> &,
                              const arith::Interval &);

}  // namespace pccd::pred
