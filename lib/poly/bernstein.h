// Bernstein enclosures: the range of p over [a, b] lies in the convex hull of its
// Bernstein coefficients on [a, b]. Used as conservative filters: a polynomial whose
// coefficients all have one strict sign has no root on the CLOSED interval [a, b].
#pragma once
#include <algorithm>
#include <type_traits>
#include <vector>

#include "poly/poly.h"

namespace pccd::poly {

// Bernstein coefficients of p (degree <= n, n >= deg p) on [a, b].
// b_k = sum_{i <= k} C(k, i) / C(n, i) * q_i, where q(s) = p(a + (b - a) s).
template <class NT>
std::vector<NT> bernstein_coefficients(const Poly<NT> &p, const NT &a, const NT &b) {
  Poly<NT> q = reparametrize(p, a, b);
  const size_t n = q.c.empty() ? 0 : q.c.size() - 1;
  std::vector<NT> out(n + 1, arith::from_int<NT>(0));
  if (q.c.empty()) return out;
  // Closed form: scale q_i by 1 / C(n, i), then sum with the weights C(k, i).
  std::vector<NT> scaled(n + 1);
  NT binom = arith::from_int<NT>(1);  // C(n, i)
  for (size_t i = 0; i <= n; ++i) {
    scaled[i] = q.c[i] / binom;
    binom = binom * arith::from_int<NT>(static_cast<long>(n - i)) /
            arith::from_int<NT>(static_cast<long>(i + 1));
  }
  for (size_t k = 0; k <= n; ++k) {
    NT ck = arith::from_int<NT>(1);  // C(k, i)
    NT sum = arith::from_int<NT>(0);
    for (size_t i = 0; i <= k; ++i) {
      sum = sum + ck * scaled[i];
      ck = ck * arith::from_int<NT>(static_cast<long>(k - i)) /
           arith::from_int<NT>(static_cast<long>(i + 1));
    }
    out[k] = sum;
  }
  return out;
}

// Tests on coefficient vectors, true only when certain (never throw Uncertain).
template <class NT>
bool all_positive(const std::vector<NT> &b) {
  for (const NT &x : b)
    if (!arith::certainly_positive(x)) return false;
  return true;
}
template <class NT>
bool all_negative(const std::vector<NT> &b) {
  for (const NT &x : b)
    if (!arith::certainly_negative(x)) return false;
  return true;
}
template <class NT>
bool all_nonpositive(const std::vector<NT> &b) {
  for (const NT &x : b)
    if (!arith::certainly_nonpos(x)) return false;
  return true;
}

// Intervals: p's natural interval extension on [a, b] (Horner on the interval hull of a
// and b), O(deg p) where the Bernstein coefficients take O(deg p ^ 2) operations with
// divisions. It encloses every value of p on [a, b] (each operation outward-rounded,
// arith/interval.h), so one strict sign of it is one of p. On the short windows of a
// robot's exact solve (2^-14 of the segment, degree-16 point paths) the terms of degree
// k shrink like width^k, and this enclosure settles most queries the Bernstein test
// would (a certain answer of either is sound; an undecided one falls back to the
// Bernstein test, so no answer certain before is lost). Other NT: false, undecided.
template <class NT>
bool horner_enclosure(const Poly<NT> &p, const NT &a, const NT &b, arith::Interval &out) {
  if constexpr (std::is_same_v<NT, arith::Interval>) {
    if (p.c.empty()) return false;
    const arith::Interval t(std::min(a.lo, b.lo), std::max(a.hi, b.hi));
    arith::Interval r = p.c.back();
    for (size_t k = p.c.size() - 1; k-- > 0;) r = r * t + p.c[k];
    out = r;
    return true;
  } else {
    (void)p, (void)a, (void)b, (void)out;
    return false;
  }
}

// True only when p certainly has no root on [a, b] (all Bernstein coefficients of one
// strict sign). Never throws Uncertain: an undecided filter answers false.
template <class NT>
bool certainly_no_root(const Poly<NT> &p, const NT &a, const NT &b) {
  try {
    if (p.c.empty()) return false;  // the zero polynomial vanishes everywhere
    arith::Interval h;
    if (horner_enclosure(p, a, b, h) && (h.lo > 0 || h.hi < 0)) return true;
    std::vector<NT> bc = bernstein_coefficients(p, a, b);
    return all_positive(bc) || all_negative(bc);
  } catch (const arith::Uncertain &) {
    return false;
  }
}

// +1 when p > 0 on all of [a, b] certainly, -1 when p <= 0 on all of [a, b] certainly,
// 0 when undecided.
template <class NT>
int certain_sign_on(const Poly<NT> &p, const NT &a, const NT &b) {
  try {
    if (p.c.empty()) return -1;  // identically zero: never > 0
    arith::Interval h;
    if (horner_enclosure(p, a, b, h)) {
      if (h.lo > 0) return 1;
      if (h.hi <= 0) return -1;
    }
    std::vector<NT> bc = bernstein_coefficients(p, a, b);
    return all_positive(bc) ? 1 : all_nonpositive(bc) ? -1 : 0;
  } catch (const arith::Uncertain &) {
    return 0;
  }
}

// An interval enclosing p over [0, 1] (hull of its Bernstein coefficients).
Interval range_on_unit(const Poly<Interval> &p);

}  // namespace pccd::poly
