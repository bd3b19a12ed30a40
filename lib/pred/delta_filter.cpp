#include "pred/delta_filter.h"

#include <cmath>

namespace pccd::pred {

using arith::Interval;

namespace {

// The points of the first primitive (the rest form the second).
int first_side(int kind) { return kind == EDGE_EDGE ? 2 : 1; }
int points_of(int kind) { return kind == VERTEX_EDGE ? 3 : kind == VERTEX_VERTEX ? 2 : 4; }

struct V3 {
  double x[3];
};
V3 sub(const V3 &a, const V3 &b) { return {{a.x[0] - b.x[0], a.x[1] - b.x[1], a.x[2] - b.x[2]}}; }
V3 cross(const V3 &a, const V3 &b) {
  return {{a.x[1] * b.x[2] - a.x[2] * b.x[1], a.x[2] * b.x[0] - a.x[0] * b.x[2],
           a.x[0] * b.x[1] - a.x[1] * b.x[0]}};
}
double dot(const V3 &a, const V3 &b) { return a.x[0] * b.x[0] + a.x[1] * b.x[1] + a.x[2] * b.x[2]; }

constexpr int kMaxDirs = 13;
constexpr int kMaxPairs = 8;  // point pairs across the primitives times both ends

double least(double a, double b) { return b < a ? b : a; }  // no libm call on the hot path

// The query at both ends: the differences a - b of every pair (a of the first primitive,
// b of the second) at t = 0 and t = 1, enclosed, and their lower ends as approximations
// (for choosing directions only); the approximate positions for the candidates.
struct Ends {
  int n = 0, pairs = 0;
  V3 p[2][4];
  Interval diff[kMaxPairs][3];
  V3 approx[kMaxPairs];
};

void ends_of(int kind, const Linear_points &pts, Ends &q) {
  q.n = points_of(kind);
  const int split = first_side(kind);
  Interval e[2][4][3];
  for (int i = 0; i < q.n; ++i)
    for (int a = 0; a < 3; ++a) {
      e[0][i][a] = pts.c0[i][a];
      e[1][i][a] = pts.c0[i][a] + pts.c1[i][a];
      q.p[0][i].x[a] = e[0][i][a].lo;
      q.p[1][i].x[a] = e[1][i][a].lo;
    }
  q.pairs = 0;
  for (int t = 0; t < 2; ++t)
    for (int i = 0; i < split; ++i)
      for (int j = split; j < q.n; ++j) {
        for (int a = 0; a < 3; ++a) {
          q.diff[q.pairs][a] = e[t][i][a] - e[t][j][a];
          q.approx[q.pairs].x[a] = q.diff[q.pairs][a].lo;
        }
        ++q.pairs;
      }
}

// An axis: the gap is a coordinate difference, no product to round. Certified when
// every pair's difference along it (or along its opposite) is above delta.hi.
bool axis_separates(int a, const Ends &q, const Interval &delta) {
  double up = HUGE_VAL, down = HUGE_VAL;  // least a-gap with the first primitive above / below
  for (int k = 0; k < q.pairs; ++k) {
    up = least(up, q.diff[k][a].lo);
    down = least(down, -q.diff[k][a].hi);
  }
  return up > delta.hi || down > delta.hi;  // false on NaN
}

// The other candidate directions of the header, from the approximate positions.
int candidates(int kind, const Ends &q, V3 *d) {
  int k = 0;
  for (int t = 0; t < 2; ++t) {
    const V3 *p = q.p[t];
    switch (kind) {
      case VERTEX_FACE: {
        const V3 e[3] = {sub(p[2], p[1]), sub(p[3], p[2]), sub(p[1], p[3])};
        const V3 n = cross(e[0], e[2]);
        d[k++] = n;
        for (const V3 &ei : e) d[k++] = cross(n, ei);
        break;
      }
      case EDGE_EDGE: {
        const V3 ea = sub(p[1], p[0]), eb = sub(p[3], p[2]);
        const V3 n = cross(ea, eb), m = cross(ea, sub(p[2], p[0]));
        d[k++] = n;
        for (const V3 &plane : {n, m}) {
          d[k++] = cross(plane, ea);
          d[k++] = cross(plane, eb);
        }
        break;
      }
      case VERTEX_EDGE: {
        const V3 e = sub(p[2], p[1]);
        d[k++] = cross(cross(e, sub(p[0], p[1])), e);
        break;
      }
      default: d[k++] = sub(p[0], p[1]); break;
    }
  }
  return k;
}

// The approximate gap along d over every pair and both ends, in its better orientation
// (sign: +1 when the first primitive lies on d's positive side); -inf when d is unusable.
double approx_gap(const V3 &d, const Ends &q, double &sign) {
  const double dd = dot(d, d);
  if (!(dd > 0) || !(dd < HUGE_VAL)) return -HUGE_VAL;
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int k = 0; k < q.pairs; ++k) {
    const double g = dot(d, q.approx[k]);
    lo = least(lo, g);
    hi = -least(-hi, -g);
  }
  sign = lo >= -hi ? 1 : -1;
  return (lo >= -hi ? lo : -hi) / std::sqrt(dd);
}

// A lower bound of the exact d . x over the intervals x (d exact doubles): each product
// and sum rounded, then stepped one ulp down (arith::round_down, valid in any rounding
// mode), the lower end of arith's interval product and sum without their point tests.
double dot_low(const double *d, const Interval *x) {
  double s = 0;
  for (int a = 0; a < 3; ++a) {
    const double p = d[a] >= 0 ? d[a] * x[a].lo : d[a] * x[a].hi;
    s = arith::round_down(s + arith::round_down(p));
  }
  return s;  // NaN when an end is infinite against a zero or opposite infinity
}

// The certificate of the header for the direction s d (s = +-1, exact).
bool certified(const V3 &d, double s, const Ends &q, const Interval &delta) {
  const double sd[3] = {s * d.x[0], s * d.x[1], s * d.x[2]};
  double low = HUGE_VAL;
  for (int k = 0; k < q.pairs; ++k) {
    const double g = dot_low(sd, q.diff[k]);
    if (!(g > 0)) return false;  // also NaN
    low = least(low, g);
  }
  // delta^2 (d . d) rounded up, low^2 rounded down (each operation then one ulp outward).
  double dd = 0;
  for (double x : sd) dd = arith::round_up(dd + arith::round_up(x * x));
  const double need = arith::round_up(arith::round_up(delta.hi * delta.hi) * dd);
  const double have = arith::round_down(low * low);
  return need < HUGE_VAL && have > need;
}

}  // namespace

bool linear_points_of(const Query_data<Interval> &q, Linear_points &out) {
  if (q.kind != VERTEX_FACE && q.kind != EDGE_EDGE && q.kind != VERTEX_EDGE && q.kind != VERTEX_VERTEX)
    return false;
  if (!q.scale.c.empty() || !q.own.empty() || q.p.size() != static_cast<size_t>(points_of(q.kind)))
    return false;
  out.n = static_cast<int>(q.p.size());
  for (int i = 0; i < out.n; ++i)
    for (int a = 0; a < 3; ++a) {
      const auto &c = q.p[i][a].c;
      if (c.size() > 2) return false;
      out.c0[i][a] = c.empty() ? Interval(0.0) : c[0];
      out.c1[i][a] = c.size() < 2 ? Interval(0.0) : c[1];
    }
  return true;
}

void linear_points_from(size_t n, const double *p0, const double *p1, Linear_points &out) {
  out.n = static_cast<int>(n);
  for (size_t i = 0; i < n && i < 4; ++i)
    for (int a = 0; a < 3; ++a) {
      const double x0 = p0[3 * i + a], x1 = p1[3 * i + a];
      out.c0[i][a] = Interval(x0);
      out.c1[i][a] = Interval(x1) - Interval(x0);  // as solve_linear's staged solver builds it
    }
}

bool delta_separated(int kind, const Linear_points &pts, const Interval &delta) {
  if (kind != VERTEX_FACE && kind != EDGE_EDGE && kind != VERTEX_EDGE && kind != VERTEX_VERTEX) return false;
  if (pts.n != points_of(kind) || !(delta.lo >= 0) || !std::isfinite(delta.hi)) return false;
  Ends q;
  ends_of(kind, pts, q);
  for (int a = 0; a < 3; ++a)
    if (axis_separates(a, q, delta)) return true;
  V3 d[kMaxDirs];
  const int nd = candidates(kind, q, d);
  // The first direction that looks clear of delta in doubles and is certified.
  for (int k = 0; k < nd; ++k) {
    double s = 1;
    if (approx_gap(d[k], q, s) > delta.hi && certified(d[k], s, q, delta)) return true;
  }
  return false;
}

}  // namespace pccd::pred
