#include "pred/closest_axis.h"

#include <cmath>

namespace pccd::pred {

namespace {

struct V {
  double x[3];
};

V sub(const double a[3], const double b[3]) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
double dot(const V &a, const V &b) { return a.x[0] * b.x[0] + a.x[1] * b.x[1] + a.x[2] * b.x[2]; }
V at(const double a[3], const V &d, double s) { return {{a[0] + s * d.x[0], a[1] + s * d.x[1], a[2] + s * d.x[2]}}; }
double clamp01(double s) { return s < 0 ? 0 : (s > 1 ? 1 : s); }

// The point of triangle t nearest to x: the region of x among the triangle's vertices,
// edges and face, by the signs of the dot products with the edges (the Voronoi regions).
V nearest_on_triangle(const double t[][3], const double x[3]) {
  const V ab = sub(t[1], t[0]), ac = sub(t[2], t[0]), ax = sub(x, t[0]);
  const double d1 = dot(ab, ax), d2 = dot(ac, ax);
  if (d1 <= 0 && d2 <= 0) return at(t[0], ab, 0);
  const V bx = sub(x, t[1]);
  const double d3 = dot(ab, bx), d4 = dot(ac, bx);
  if (d3 >= 0 && d4 <= d3) return at(t[1], ab, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return at(t[0], ab, d1 / (d1 - d3));
  const V cx = sub(x, t[2]);
  const double d5 = dot(ab, cx), d6 = dot(ac, cx);
  if (d6 >= 0 && d5 <= d6) return at(t[2], ab, 0);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return at(t[0], ac, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return at(t[1], sub(t[2], t[1]), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double den = va + vb + vc, v = vb / den, w = vc / den;
  return {{t[0][0] + ab.x[0] * v + ac.x[0] * w, t[0][1] + ab.x[1] * v + ac.x[1] * w,
           t[0][2] + ab.x[2] * v + ac.x[2] * w}};
}

// The nearest points of segments [p0, p1] and [q0, q1]: the minimum of the squared
// distance over the parameters s, t in [0, 1], each clamped in turn.
void nearest_of_segments(const double p0[3], const double p1[3], const double q0[3], const double q1[3], V &cp,
                         V &cq) {
  const V d1 = sub(p1, p0), d2 = sub(q1, q0), r = sub(p0, q0);
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a <= 0 && e <= 0) {
  } else if (a <= 0) {
    t = clamp01(f / e);
  } else {
    const double c = dot(d1, r);
    if (e <= 0) {
      s = clamp01(-c / a);
    } else {
      const double b = dot(d1, d2), den = a * e - b * b;
      s = den > 0 ? clamp01((b * f - c * e) / den) : 0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = clamp01(-c / a);
      } else if (t > 1) {
        t = 1;
        s = clamp01((b - c) / a);
      }
    }
  }
  cp = at(p0, d1, s);
  cq = at(q0, d2, t);
}

// The point of primitive t (n points) nearest to x.
V nearest_on(const double t[][3], int n, const double x[3]) {
  if (n == 3) return nearest_on_triangle(t, x);
  if (n == 1) return at(t[0], V{{0, 0, 0}}, 0);
  const V d = sub(t[1], t[0]), w = sub(x, t[0]);
  const double dd = dot(d, d);
  return at(t[0], d, dd > 0 ? clamp01(dot(w, d) / dd) : 0);
}

}  // namespace

bool closest_direction(const double p[][3], int np, const double q[][3], int nq, double out[3]) {
  double best = HUGE_VAL;
  auto consider = [&](const V &a, const V &b) {
    const V d = sub(b.x, a.x);
    const double n = dot(d, d);
    if (n < best) {
      best = n;
      for (int i = 0; i < 3; ++i) out[i] = d.x[i];
    }
  };
  for (int k = 0; k < np; ++k) consider(V{{p[k][0], p[k][1], p[k][2]}}, nearest_on(q, nq, p[k]));
  for (int k = 0; k < nq; ++k) consider(nearest_on(p, np, q[k]), V{{q[k][0], q[k][1], q[k][2]}});
  const int ep = np == 3 ? 3 : np - 1, eq = nq == 3 ? 3 : nq - 1;  // edges: segment 1, triangle 3
  for (int i = 0; i < ep; ++i)
    for (int j = 0; j < eq; ++j) {
      V a, b;
      nearest_of_segments(p[i], p[(i + 1) % np], q[j], q[(j + 1) % nq], a, b);
      consider(a, b);
    }
  return std::isfinite(best) && best > 0;
}

}  // namespace pccd::pred
