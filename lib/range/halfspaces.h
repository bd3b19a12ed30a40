// Conjunctions of clauses of closed halfspaces over lifted points (the query side of the
// range structure, range/range_tree.h; what is lifted: range/LINEARIZATION.md).
//
// A halfspace is  a . s + a0 >= 0  for a lifted point s in R^D, with interval
// coefficients a, a0 (they enclose the exact coefficients of the query). A clause is a
// disjunction of halfspaces; a query (Cnf) is a conjunction of clauses. Every test
// answers "possibly": true unless the interval evaluation proves the inequality false
// for every coefficient and every point in the (interval) argument. So a stored
// primitive that satisfies the exact condition is never filtered out, touching (= 0)
// included: the halfspaces are closed.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "arith/interval.h"

namespace pccd::range {

using arith::Interval;

template <int D>
struct Halfspace {
  std::array<Interval, D> a;
  Interval a0;
};

// A bound on one coordinate, s_k <= v (upper) or s_k >= v: a one-halfspace clause with a
// unit normal, kept apart because it costs one comparison (the box conditions).
struct Bound {
  uint8_t k = 0;
  bool upper = false;
  double v = 0;
};

// A condition on a quadratic q(s) = b0 (1 - s)^2 + 2 b1 s (1 - s) + b2 s^2 over s in
// [0, 1] whose Bernstein coefficients b_j = f[j] . x + f[j]_0 are linear in the lifted
// point x (the exact rotation linearization, range/LINEARIZATION.md):
//   Root:        q has a root in [0, 1]  <=>  b0 b2 <= 0  or  (b0 b1 <= 0 and b1^2 >= b0 b2);
//   Nonpositive: q <= 0 somewhere        <=>  b0 <= 0 or b2 <= 0 or (b1 <= 0 and b1^2 >= b0 b2).
// (If b0, b2 have one strict sign, substitute s = x / (1 + x), x in [0, inf): the roots
// are those of b0 + 2 b1 x + b2 x^2, positive iff b1 has the other sign and the
// discriminant 4 (b1^2 - b0 b2) is >= 0.) These are linear in the Veronese lift of x
// (its degree-2 monomials); they are evaluated here on the interval box of x directly.
template <int D>
struct Quadratic {
  enum Kind : uint8_t { Root, Nonpositive };
  std::array<Halfspace<D>, 3> f;
  Kind kind = Root;
};

template <int D>
struct Cnf {
  std::vector<Bound> bounds;
  std::vector<Halfspace<D>> hs;
  std::vector<uint32_t> clause_end;  // clause c is hs[clause_end[c-1] .. clause_end[c])
  std::vector<Quadratic<D>> quads;   // each one clause of its own

  void end_clause() { clause_end.push_back(static_cast<uint32_t>(hs.size())); }
  bool empty() const { return clause_end.empty() && bounds.empty() && quads.empty(); }
};

// Bounds of a . x + a0 over every coefficient in h and every point in the box x, for
// the tree search (the hot loop): plain double arithmetic plus a derived error bound
// instead of a rounded interval operation per term.
//
// Error bound: the exact maximum of a_k x_k over the two intervals is one of the four
// corner products; every rounding mode is monotone, so the largest rounded product is
// the rounded largest one, within 2u |t_k| + eta of it (u = 2^-53: one ulp in any
// rounding mode; eta = 2^-1074 for underflow). The D additions of the D + 1 terms add
// at most D * 2u * (1 + D 2u) * sum |t_k| (Higham, Accuracy and Stability, 2nd ed.,
// (3.4), with 2u for directed rounding). So |computed - exact| <= (D + 1) 2u (1 + 2D u)
// sum |t_k| + (D + 1) eta; the margin below, (D + 2) 2^-50 m + 2^-1000 with m the
// computed sum |t_k| (m >= (1 - 2(D+1)u) sum |t_k|), exceeds it by a factor over 3, so
// the two additions that apply it, each off by at most 2u of their result, keep it a
// bound. Overflow gives inf or NaN; NaN answers "possible" and never "certain".
template <int D, bool Upper>
double bound(const Halfspace<D> &h, const Interval *x) {
  double s = Upper ? h.a0.hi : h.a0.lo, m = std::fabs(s);
  for (int k = 0; k < D; ++k) {
    const Interval &a = h.a[k];
    const double p0 = a.lo * x[k].lo, p1 = a.lo * x[k].hi, p2 = a.hi * x[k].lo, p3 = a.hi * x[k].hi;
    const double t = Upper ? std::max(std::max(p0, p1), std::max(p2, p3))
                           : std::min(std::min(p0, p1), std::min(p2, p3));
    s += t;
    m += std::fabs(t);
  }
  const double margin = m * ((D + 2) * 0x1p-50) + 0x1p-1000;
  return Upper ? s + margin : s - margin;
}
template <int D>
double upper_bound(const Halfspace<D> &h, const Interval *x) { return bound<D, true>(h, x); }
template <int D>
double lower_bound(const Halfspace<D> &h, const Interval *x) { return bound<D, false>(h, x); }

// Whether the quadratic condition may hold (certainly holds, when certain = true) for
// some (every) point of the box x. NaN bounds answer "may" and never "certainly".
template <int D>
bool quadratic_test(const Quadratic<D> &q, const Interval *x, bool certain) {
  Interval b[3];
  for (int j = 0; j < 3; ++j) {
    b[j] = Interval(lower_bound(q.f[j], x), upper_bound(q.f[j], x));
    if (!(std::fabs(b[j].lo) < HUGE_VAL && std::fabs(b[j].hi) < HUGE_VAL)) return !certain;
  }
  // Products of finite bounds are not NaN; a NaN from inf - inf in disc answers "may".
  const Interval disc = b[1] * b[1] - b[0] * b[2];
  if (q.kind == Quadratic<D>::Root) {
    const Interval p02 = b[0] * b[2], p01 = b[0] * b[1];
    if (certain) return p02.hi <= 0 || (p01.hi <= 0 && disc.lo >= 0);
    return !(p02.lo > 0) || (!(p01.lo > 0) && !(disc.hi < 0));
  }
  if (certain) return b[0].hi <= 0 || b[2].hi <= 0 || (b[1].hi <= 0 && disc.lo >= 0);
  return !(b[0].lo > 0) || !(b[2].lo > 0) || (!(b[1].lo > 0) && !(disc.hi < 0));
}

// Whether some point of the interval box x may satisfy every clause (a necessary test:
// each clause separately has a halfspace that meets the box).
template <int D>
bool cnf_possible(const Cnf<D> &q, const Interval *x) {
  for (const Bound &b : q.bounds)
    if (b.upper ? !(x[b.k].lo <= b.v) : !(x[b.k].hi >= b.v)) return false;
  uint32_t start = 0;
  for (uint32_t end : q.clause_end) {
    bool any = false;
    for (uint32_t i = start; i < end && !any; ++i) any = !(upper_bound(q.hs[i], x) < 0);
    if (!any) return false;
    start = end;
  }
  for (const Quadratic<D> &c : q.quads)
    if (!quadratic_test(c, x, false)) return false;
  return true;
}

// Whether every point of the box certainly satisfies every clause (then a whole subtree
// is reported without testing its points; only a shortcut, reporting more is safe).
template <int D>
bool cnf_certain(const Cnf<D> &q, const Interval *x) {
  for (const Bound &b : q.bounds)
    if (b.upper ? !(x[b.k].hi <= b.v) : !(x[b.k].lo >= b.v)) return false;
  uint32_t start = 0;
  for (uint32_t end : q.clause_end) {
    bool any = false;
    for (uint32_t i = start; i < end && !any; ++i) any = lower_bound(q.hs[i], x) >= 0;
    if (!any) return false;
    start = end;
  }
  for (const Quadratic<D> &c : q.quads)
    if (!quadratic_test(c, x, true)) return false;
  return true;
}

}  // namespace pccd::range
