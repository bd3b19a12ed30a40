// Polynomials on s in [0, 1] in SCALED Bernstein form, with interval coefficients: a
// polynomial of degree n is p(s) = sum_i a_i C(n, i) s^i (1 - s)^(n - i) and the vector
// holds the scaled coefficients  A_i = C(n, i) a_i.
//
// Why scaled: products become plain convolutions, because
//   (sum_i A_i s^i (1-s)^(m-i)) (sum_j B_j s^j (1-s)^(n-j)) = sum_k (sum_{i+j=k} A_i B_j) s^k (1-s)^(m+n-k),
// and degree elevation by r is the product with 1 = ((1 - s) + s)^r, scaled form
// (C(r, 0), ..., C(r, r)). The true Bernstein coefficient is a_k = A_k / C(n, k) with
// C(n, k) > 0, so sign conditions on Bernstein coefficients (the range of p on [0, 1]
// lies in [min a_k, max a_k]) are sign conditions on the A_k: no division is needed.
// The empty vector is the zero polynomial (of any degree).
#pragma once
#include <vector>

#include "arith/interval.h"
#include "poly/poly.h"

namespace pccd::range {

using arith::Interval;
using Sb = std::vector<Interval>;

inline size_t sb_degree(const Sb &a) { return a.empty() ? 0 : a.size() - 1; }

// Product (convolution of the scaled coefficients).
inline Sb sb_mul(const Sb &a, const Sb &b) {
  if (a.empty() || b.empty()) return {};
  Sb c(a.size() + b.size() - 1, Interval(0.0));
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j) c[i + j] = c[i + j] + a[i] * b[j];
  return c;
}

// The same polynomial at degree n >= sb_degree(a).
inline Sb sb_elevate(const Sb &a, size_t n) {
  if (a.empty() || sb_degree(a) == n) return a;
  const size_t r = n - sb_degree(a);
  Sb ones(r + 1);
  Interval c(1.0);  // C(r, i), certified for any r
  for (size_t i = 0; i <= r; ++i) {
    ones[i] = c;
    c = c * Interval(double(r - i)) / Interval(double(i + 1));
  }
  return sb_mul(a, ones);
}

inline Sb sb_add(const Sb &a, const Sb &b, double sb = 1.0) {
  if (b.empty()) return a;
  if (a.empty()) {
    Sb c = b;
    if (sb != 1.0)
      for (Interval &x : c) x = Interval(sb) * x;
    return c;
  }
  const size_t n = std::max(sb_degree(a), sb_degree(b));
  Sb x = sb_elevate(a, n), y = sb_elevate(b, n);
  for (size_t i = 0; i <= n; ++i) x[i] = x[i] + (sb == 1.0 ? y[i] : Interval(sb) * y[i]);
  return x;
}
inline Sb sb_sub(const Sb &a, const Sb &b) { return sb_add(a, b, -1.0); }
inline Sb sb_scale(const Interval &s, const Sb &a) {
  Sb c(a.size());
  for (size_t i = 0; i < a.size(); ++i) c[i] = s * a[i];
  return c;
}
inline Sb sb_neg(const Sb &a) {
  Sb c(a.size());
  for (size_t i = 0; i < a.size(); ++i) c[i] = -a[i];
  return c;
}

// Scaled Bernstein form at degree n >= deg p of a power-basis polynomial on [0, 1]:
// A_k = C(n, k) sum_{i <= k} C(k, i) / C(n, i) p_i = sum_{i <= k} C(n - i, k - i) p_i.
inline Sb sb_from_power(const poly::Poly<Interval> &p, size_t n) {
  if (p.c.empty()) return {};
  Sb out(n + 1, Interval(0.0));
  for (size_t i = 0; i < p.c.size(); ++i) {
    Interval c(1.0);  // C(n - i, k - i) for k = i, i + 1, ... (certified)
    for (size_t k = i; k <= n; ++k) {
      out[k] = out[k] + c * p.c[i];
      c = c * Interval(double(n - k)) / Interval(double(k - i + 1));
    }
  }
  return out;
}

}  // namespace pccd::range
