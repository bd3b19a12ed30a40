#include "pred/linear_crossing.h"

#include <cmath>

#include "arith/interval.h"
#include "pred/features.h"

namespace pccd::pred {

namespace {

using arith::Interval;

int certain_sign(const Interval &x) { return x.lo > 0 ? 1 : x.hi < 0 ? -1 : 0; }

struct I3 {
  Interval x, y, z;
};
I3 operator-(const I3 &a, const I3 &b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
I3 cross(const I3 &a, const I3 &b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Interval dot(const I3 &a, const I3 &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Point i's positions over T: x0 + T (x1 - x0), enclosed.
I3 position(const double *p0, const double *p1, int i, const Interval &T) {
  const double *a = p0 + 3 * i, *b = p1 + 3 * i;
  auto at = [&](int k) { return Interval(a[k]) + T * (Interval(b[k]) - Interval(a[k])); };
  return {at(0), at(1), at(2)};
}

// The cubic's true Bernstein coefficients as intervals (the middle ones were times 3).
void coefficients(const Cubic_bernstein &f, Interval c[4]) {
  for (int k = 0; k < 4; ++k) {
    c[k] = Interval(arith::round_down(f.value[k] - f.bound[k]), arith::round_up(f.value[k] + f.bound[k]));
    if (k == 1 || k == 2) c[k] = c[k] / Interval(3.0);
  }
}

// f(t) by de Casteljau on the enclosed coefficients (t a double in [0, 1]).
Interval eval(const Interval c[4], double t) {
  const Interval T(t), U = Interval(1.0) - T;
  Interval b[4] = {c[0], c[1], c[2], c[3]};
  for (int r = 1; r < 4; ++r)
    for (int k = 0; k + r < 4; ++k) b[k] = U * b[k] + T * b[k + 1];
  return b[0];
}

// A floating-point estimate of the root (bisection on the approximate coefficients);
// any value in [0, 1] is safe: it only chooses where the certificate is tried.
double estimate_root(const Cubic_bernstein &f) {
  const double v[4] = {f.value[0], f.value[1] / 3, f.value[2] / 3, f.value[3]};
  auto at = [&](double t) {
    double b[4] = {v[0], v[1], v[2], v[3]};
    for (int r = 1; r < 4; ++r)
      for (int k = 0; k + r < 4; ++k) b[k] = (1 - t) * b[k] + t * b[k + 1];
    return b[0];
  };
  double lo = 0, hi = 1;
  const bool neg_at_lo = v[0] < 0;
  for (int i = 0; i < 60 && hi - lo > 0x1p-50; ++i) {
    const double m = 0.5 * (lo + hi);
    if ((at(m) < 0) == neg_at_lo) lo = m; else hi = m;
  }
  return 0.5 * (lo + hi);
}

// The side conditions over T, each as a certain sign (0: not certain): vertex-face g_0,
// g_1, g_2; edge-edge s(b0), s(b1), s(a0), s(a1) (linear_crossing.h).
struct Sides {
  int s[4] = {0, 0, 0, 0};
};
Sides sides_on(int kind, const double *p0, const double *p1, const Interval &T) {
  const I3 x0 = position(p0, p1, 0, T), x1 = position(p0, p1, 1, T), x2 = position(p0, p1, 2, T),
           x3 = position(p0, p1, 3, T);
  Sides out;
  if (kind == VERTEX_FACE) {  // v = x0, triangle x1 x2 x3
    const I3 f[3] = {x1, x2, x3};
    const I3 n = cross(x2 - x1, x3 - x1);
    for (int i = 0; i < 3; ++i) out.s[i] = certain_sign(dot(n, cross(f[(i + 1) % 3] - f[i], x0 - f[i])));
    return out;
  }
  // edge-edge: a0 = x0, a1 = x1, b0 = x2, b1 = x3
  const I3 ea = x1 - x0, eb = x3 - x2, n = cross(ea, eb);
  out.s[0] = certain_sign(dot(n, cross(ea, x2 - x0)));
  out.s[1] = certain_sign(dot(n, cross(ea, x3 - x0)));
  out.s[2] = certain_sign(dot(n, cross(eb, x0 - x2)));
  out.s[3] = certain_sign(dot(n, cross(eb, x1 - x2)));
  return out;
}

// Some side condition certainly says "apart" on all of T.
bool apart(int kind, const Sides &d) {
  if (kind == VERTEX_FACE) return d.s[0] < 0 || d.s[1] < 0 || d.s[2] < 0;
  return d.s[0] * d.s[1] > 0 || d.s[2] * d.s[3] > 0;
}

// Every side condition certainly says "inside" on all of T.
bool inside(int kind, const Sides &d) {
  if (kind == VERTEX_FACE) return d.s[0] > 0 && d.s[1] > 0 && d.s[2] > 0;
  return d.s[0] * d.s[1] < 0 && d.s[2] * d.s[3] < 0;
}

// f's only root in [0, 1] and a bracket [ta, tb] of it with certainly opposite signs of
// f at its ends (c: the enclosed coefficients); false when the Descartes part fails or no
// bracket certifies.
bool single_root_bracket(const Cubic_bernstein &f, Interval c[4], double &ta, double &tb) {
  coefficients(f, c);
  int changes = 0;
  for (int k = 0; k < 4; ++k) {
    if (certain_sign(c[k]) == 0) return false;
    if (k > 0 && certain_sign(c[k]) != certain_sign(c[k - 1])) ++changes;
  }
  if (changes != 1) return false;
  const double r = estimate_root(f);
  // The narrowest bracket whose ends certainly differ in sign (f's enclosure error
  // sets how narrow it can be).
  for (double h : {0x1p-40, 0x1p-28, 0x1p-16, 0x1p-6}) {
    ta = r - h > 0 ? r - h : 0.0;
    tb = r + h < 1 ? r + h : 1.0;
    if (certain_sign(eval(c, ta)) * certain_sign(eval(c, tb)) < 0) return true;
  }
  return false;
}

}  // namespace

bool crossing_misses(int kind, const double *p0, const double *p1, const Cubic_bernstein &f) {
  if (!f.ok || (kind != VERTEX_FACE && kind != EDGE_EDGE)) return false;
  Interval c[4];
  double ta, tb;
  return single_root_bracket(f, c, ta, tb) && apart(kind, sides_on(kind, p0, p1, Interval(ta, tb)));
}

bool crossing_hit(int kind, const double *p0, const double *p1, Contact_result &out) {
  const Cubic_bernstein f = coplanarity_cubic(kind, p0, p1);  // not ok for other kinds
  Interval c[4];
  double ta, tb;
  if (!f.ok || !single_root_bracket(f, c, ta, tb) || !inside(kind, sides_on(kind, p0, p1, Interval(ta, tb))))
    return false;
  out.collides = true;
  out.exact = false;
  out.lo = 0;
  out.hi = 1;
  out.features.assign(1, Feature{kind, {{0, 1, 2, 3}}});
  out.stage = STAGE_INTERVAL;
  return true;
}

}  // namespace pccd::pred
