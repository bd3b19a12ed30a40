// The static filter of linear double queries (linear_filter.h) and its error bound.
//
// Error bound. Let eps = 2^-52. In ANY IEEE-754 rounding mode, an operation (+, -, *)
// whose exact result x is a normal double or zero returns x (1 + d) with |d| <= eps
// (directed rounding errs by less than one ulp, ulp(x) <= eps |x|); a sum or difference
// whose exact result is subnormal is exact; only a product can underflow, and then it
// errs by less than 2^-1074 in absolute value. The filter works on point differences
// e = fl(X - Y) and declines (ok = false) unless every one is zero or has
// 2^-300 <= |e| <= 2^300. Then:
//  - no overflow: products of two or three differences stay below 2^900;
//  - a product of two nonzero differences is >= 2^-600, normal: relative error only;
//  - a 2x2 minor (difference of two such products) is exact if subnormal;
//  - only the product of a difference with a minor can underflow (a cubic's monomials).
// A value V = sum over monomials +-(e1 e2 [e3]) evaluated in that way carries, per
// monomial, at most K factors (1 + d): one per difference, one per product, one per
// sum or difference on the monomial's path. Hence
//     |fl(V) - V| <= ((1 + eps)^K - 1) P + U,   P = sum over monomials |e1 e2 [e3]|,
// with U the underflow part (at most 3 underflowing products per determinant, each
// < 2^-1074, then carried through at most 4 additions: U < 2^-1070 for a sum of three
// determinants). The permanent P is evaluated in the same order with |e|'s, all terms
// >= 0, so its computed value P^ >= (1 - eps)^K P, and
//     |fl(V) - V| <= ((1 + eps)^K - 1) / (1 - eps)^K P^ + U < (K + 0.01) eps P^ + U
// for K <= 16. The bound used is fl((K + 1) eps P^) >= (K + 1) eps P^ (1 - eps)
// > (K + 0.01) eps P^ + 0.98 eps P^. If P^ > 0, some monomial is a product of nonzero
// differences, so P^ >= 2^-901 and 0.98 eps P^ > 2^-954 > U. If P^ = 0, every
// monomial has a zero factor, V = fl(V) = 0 exactly, and the bound 0 certifies no sign
// (the tests below are strict). So |fl(V) - V| <= bound in every case.
//
// K per value: a 3x3 determinant a . (b x c) has 8 on its longest path (3 differences,
// the product and the difference of the minor, the product with a, 2 sums); a sum of
// three determinants adds 2 (K = 10); a 2x2 minor has 4, a sum of two minors 5.
#include "pred/linear_filter.h"

#include <cmath>

#include "pred/features.h"

namespace pccd::pred {

namespace {

constexpr double kEps = 0x1p-52;
constexpr double kMax = 0x1p300, kMin = 0x1p-300;

struct V3 {
  double x, y, z;
};

// A point difference; false when it is outside the filter's range.
inline bool diff(const double *p, const double *q, V3 &out) {
  out = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
  for (double e : {out.x, out.y, out.z}) {
    const double m = std::fabs(e);
    if (!(m <= kMax) || (m != 0 && m < kMin)) return false;  // also NaN, inf
  }
  return true;
}

// det(a, b, c) = a . (b x c) and its permanent, in the order the bound assumes.
inline void det3(const V3 &a, const V3 &b, const V3 &c, double &d, double &p) {
  const double m0 = b.y * c.z - b.z * c.y, m1 = b.z * c.x - b.x * c.z, m2 = b.x * c.y - b.y * c.x;
  d = a.x * m0 + a.y * m1 + a.z * m2;
  const double q0 = std::fabs(b.y * c.z) + std::fabs(b.z * c.y);
  const double q1 = std::fabs(b.z * c.x) + std::fabs(b.x * c.z);
  const double q2 = std::fabs(b.x * c.y) + std::fabs(b.y * c.x);
  p = std::fabs(a.x) * q0 + std::fabs(a.y) * q1 + std::fabs(a.z) * q2;
}

// Component k of a x b and its permanent.
inline void minor2(int k, const V3 &a, const V3 &b, double &d, double &p) {
  const double u[3] = {a.x, a.y, a.z}, v[3] = {b.x, b.y, b.z};
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  d = u[i] * v[j] - u[j] * v[i];
  p = std::fabs(u[i] * v[j]) + std::fabs(u[j] * v[i]);
}

template <int N>
bool all_certain(const double (&v)[N], const double (&b)[N], int sign) {
  for (int k = 0; k < N; ++k)
    if (!(sign > 0 ? v[k] > b[k] : v[k] < -b[k])) return false;
  return true;
}

template <class R>
bool one_strict_sign(const R &r) {
  return r.ok && (all_certain(r.value, r.bound, 1) || all_certain(r.value, r.bound, -1));
}

// Disjoint closed boxes of points [0, split) and [split, n) over their positions at
// t = 0 and t = 1 (exact: only comparisons).
bool boxes_apart(int n, int split, const double *p0, const double *p1) {
  for (int a = 0; a < 3; ++a) {
    double lo[2], hi[2];
    for (int s = 0; s < 2; ++s) {
      const int first = s == 0 ? 0 : split, last = s == 0 ? split : n;
      lo[s] = hi[s] = p0[3 * first + a];
      for (int i = first; i < last; ++i)
        for (const double *p : {p0, p1}) {
          const double x = p[3 * i + a];
          lo[s] = x < lo[s] ? x : lo[s];
          hi[s] = x > hi[s] ? x : hi[s];
        }
    }
    if (hi[0] < lo[1] || hi[1] < lo[0]) return true;
  }
  return false;
}

}  // namespace

Cubic_bernstein cubic_bernstein(const double *const O[2], const double *const A[2],
                                const double *const B[2], const double *const C[2]) {
  Cubic_bernstein r{};
  V3 a[2], b[2], c[2];
  for (int s = 0; s < 2; ++s)
    if (!diff(A[s], O[s], a[s]) || !diff(B[s], O[s], b[s]) || !diff(C[s], O[s], c[s])) return r;
  // The blossom of the trilinear det: coefficient k is the mean of det(a_i, b_j, c_l)
  // over i + j + l = k (i, j, l in {0, 1}).
  double d[2][2][2], p[2][2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int l = 0; l < 2; ++l) det3(a[i], b[j], c[l], d[i][j][l], p[i][j][l]);
  r.value[0] = d[0][0][0];
  r.value[1] = d[1][0][0] + d[0][1][0] + d[0][0][1];
  r.value[2] = d[1][1][0] + d[1][0][1] + d[0][1][1];
  r.value[3] = d[1][1][1];
  const double perm[4] = {p[0][0][0], p[1][0][0] + p[0][1][0] + p[0][0][1],
                          p[1][1][0] + p[1][0][1] + p[0][1][1], p[1][1][1]};
  for (int k = 0; k < 4; ++k) r.bound[k] = 11 * kEps * perm[k];  // K = 10
  r.ok = true;
  return r;
}

Quadratic_bernstein cross_bernstein(int k, const double *const O[2], const double *const A[2],
                                    const double *const B[2]) {
  Quadratic_bernstein r{};
  V3 a[2], b[2];
  for (int s = 0; s < 2; ++s)
    if (!diff(A[s], O[s], a[s]) || !diff(B[s], O[s], b[s])) return r;
  double d[2][2], p[2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) minor2(k, a[i], b[j], d[i][j], p[i][j]);
  r.value[0] = d[0][0];
  r.value[1] = d[1][0] + d[0][1];
  r.value[2] = d[1][1];
  const double perm[3] = {p[0][0], p[1][0] + p[0][1], p[1][1]};
  for (int m = 0; m < 3; ++m) r.bound[m] = 6 * kEps * perm[m];  // K = 5
  r.ok = true;
  return r;
}

Cubic_bernstein coplanarity_cubic(int kind, const double *p0, const double *p1) {
  const double *P[4][2];
  for (int i = 0; i < 4; ++i) {
    P[i][0] = p0 + 3 * i;
    P[i][1] = p1 + 3 * i;
  }
  if (kind == VERTEX_FACE) return cubic_bernstein(P[1], P[2], P[3], P[0]);  // v, f0, f1, f2
  if (kind == EDGE_EDGE) return cubic_bernstein(P[0], P[1], P[2], P[3]);    // a0, a1, b0, b1
  return Cubic_bernstein{};
}

Linear_verdict linear_filter(int kind, const double *p0, const double *p1, Cubic_bernstein &f) {
  f.ok = false;  // nothing else of f is read unless ok
  auto at = [&](int i) {
    struct Pair {
      const double *x[2];
    };
    return Pair{{p0 + 3 * i, p1 + 3 * i}};
  };
  switch (kind) {
    case VERTEX_FACE:  // v, f0, f1, f2
    case EDGE_EDGE:    // a0, a1, b0, b1
      if (boxes_apart(4, kind == VERTEX_FACE ? 1 : 2, p0, p1)) return Linear_verdict::boxes_apart;
      f = coplanarity_cubic(kind, p0, p1);
      return one_strict_sign(f) ? Linear_verdict::no_root : Linear_verdict::unknown;
    case VERTEX_EDGE: {  // v, e0, e1: a component of (e1 - e0) x (v - e0) never vanishes
      if (boxes_apart(3, 1, p0, p1)) return Linear_verdict::boxes_apart;
      const auto v = at(0), e0 = at(1), e1 = at(2);
      for (int k = 0; k < 3; ++k)
        if (one_strict_sign(cross_bernstein(k, e0.x, e1.x, v.x))) return Linear_verdict::no_root;
      return Linear_verdict::unknown;
    }
    case VERTEX_VERTEX: {  // a, b: a coordinate of a - b is linear; same strict sign at
      // both ends means no root (the sign of a difference of doubles is exact)
      if (boxes_apart(2, 1, p0, p1)) return Linear_verdict::boxes_apart;
      for (int k = 0; k < 3; ++k) {
        const double d0 = p0[k] - p0[3 + k], d1 = p1[k] - p1[3 + k];
        if ((d0 > 0 && d1 > 0) || (d0 < 0 && d1 < 0)) return Linear_verdict::no_root;
      }
      return Linear_verdict::unknown;
    }
  }
  return Linear_verdict::unknown;
}

}  // namespace pccd::pred
