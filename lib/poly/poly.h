// Dense univariate polynomials over a number type NT (Rational or Interval),
// coefficients in ascending powers: c[0] + c[1] t + ... .
//
// Trailing coefficients that are exactly zero are trimmed. With NT = Interval a
// trailing coefficient that merely contains zero is kept (its degree is not certain);
// operations that need a certain leading coefficient call sign() and so throw
// Uncertain, which the filtered caller turns into an exact recomputation.
#pragma once
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include "arith/convert.h"
#include "arith/interval.h"
#include "arith/rational.h"
#include "util/work_budget.h"

namespace pccd::poly {

using arith::Interval;
using arith::Rational;

template <class NT>
struct Poly {
  std::vector<NT> c;

  Poly() = default;
  explicit Poly(std::vector<NT> coeffs) : c(std::move(coeffs)) { trim(); }
  static Poly constant(const NT &v) { return Poly(std::vector<NT>{v}); }
  // t - a
  static Poly linear_root(const NT &a) { return Poly(std::vector<NT>{-a, arith::from_int<NT>(1)}); }

  // Removes trailing coefficients that are exactly zero (certainly zero for Interval).
  void trim() {
    while (!c.empty() && exact_zero(c.back())) c.pop_back();
  }
  // Degree; -1 for the zero polynomial.
  int degree() const { return static_cast<int>(c.size()) - 1; }
  // True when every coefficient is exactly zero. For Interval: throws Uncertain when
  // no coefficient is certainly nonzero but some are not certainly zero.
  bool is_zero() const {
    bool certain = true;
    for (const NT &x : c) {
      if (arith::certainly_positive(x) || arith::certainly_negative(x)) return false;
      if (!exact_zero(x)) certain = false;
    }
    if (!certain) throw arith::Uncertain{};
    return true;
  }
  const NT &lc() const { return c.back(); }

  NT eval(const NT &t) const {
    NT r = arith::from_int<NT>(0);
    for (size_t i = c.size(); i-- > 0;) r = r * t + c[i];
    return r;
  }

  static bool exact_zero(const Rational &x) { return sgn(x) == 0; }
  static bool exact_zero(const Interval &x) { return x.is_point_zero(); }
};

// The size of exact numbers in limbs (machine words), the measure of the work steps
// counted by cost (util::work_cost): an operation on an n-limb and an m-limb number
// costs n * m. Intervals cost nothing (their operations take a bounded time).
inline std::uint64_t limbs(const arith::Integer &x) { return mpz_size(x.get_mpz_t()); }
inline std::uint64_t limbs(const Rational &x) {
  return mpz_size(x.get_num_mpz_t()) + mpz_size(x.get_den_mpz_t());
}
inline std::uint64_t limbs(const Interval &) { return 0; }
template <class NT>
std::uint64_t limbs(const Poly<NT> &p) {
  std::uint64_t n = 0;
  if constexpr (std::is_same<NT, Rational>::value)
    for (const Rational &x : p.c) n += limbs(x);
  return n;
}
// util::work_cost for exact number types only (cost_of is not called for intervals).
template <class NT, class F>
inline void exact_cost(F &&cost_of) {
  if constexpr (std::is_same<NT, Rational>::value || std::is_same<NT, arith::Integer>::value)
    util::work_cost(cost_of);
}

// One exact operation on x and y (a sum reduces to a common denominator, a product
// cancels common factors): counted per coefficient, as one coefficient of long numbers
// can take long (tens of milliseconds at a million bits).
template <class NT>
inline void op_cost(const NT &x, const NT &y) {
  exact_cost<NT>([&] { return limbs(x) * limbs(y); });
}

template <class NT>
Poly<NT> operator+(const Poly<NT> &a, const Poly<NT> &b) {
  std::vector<NT> r(std::max(a.c.size(), b.c.size()), arith::from_int<NT>(0));
  for (size_t i = 0; i < a.c.size(); ++i) r[i] = a.c[i];
  for (size_t i = 0; i < b.c.size(); ++i) {
    op_cost(r[i], b.c[i]);
    r[i] = r[i] + b.c[i];
  }
  return Poly<NT>(std::move(r));
}
template <class NT>
Poly<NT> operator-(const Poly<NT> &a) {
  std::vector<NT> r(a.c.size());
  for (size_t i = 0; i < a.c.size(); ++i) r[i] = -a.c[i];
  return Poly<NT>(std::move(r));
}
template <class NT>
Poly<NT> operator-(const Poly<NT> &a, const Poly<NT> &b) {
  std::vector<NT> r(std::max(a.c.size(), b.c.size()), arith::from_int<NT>(0));
  for (size_t i = 0; i < a.c.size(); ++i) r[i] = a.c[i];
  for (size_t i = 0; i < b.c.size(); ++i) {
    op_cost(r[i], b.c[i]);
    r[i] = r[i] - b.c[i];
  }
  return Poly<NT>(std::move(r));
}
template <class NT>
Poly<NT> operator*(const Poly<NT> &a, const Poly<NT> &b) {
  if (a.c.empty() || b.c.empty()) return Poly<NT>();
  std::vector<NT> r(a.c.size() + b.c.size() - 1, arith::from_int<NT>(0));
  for (size_t i = 0; i < a.c.size(); ++i)
    for (size_t j = 0; j < b.c.size(); ++j) r[i + j] = r[i + j] + a.c[i] * b.c[j];
  return Poly<NT>(std::move(r));
}
// Exact evaluation in integers (rational_product.cpp): Horner over Q reduces a fraction
// at every step; in integers one reduction at the end gives the same number.
template <>
Rational Poly<Rational>::eval(const Rational &t) const;
// The values at t of ps[0..count) over one common denominator, NOT reduced:
// ps[k](t) = (*num)[k] / *den exactly (den > 0; an empty polynomial gives 0). Counted
// by cost like eval (rational_product.cpp); the caller reduces once what it computes.
void eval_common(const Poly<Rational> *const *ps, size_t count, const Rational &t,
                 std::vector<arith::Integer> *num, arith::Integer *den);

// Exact products in integers (rational_product.cpp): the generic loop above reduces a
// fraction at every product and sum, and those gcds dominated the motion layer's work.
template <>
Poly<Rational> operator*(const Poly<Rational> &a, const Poly<Rational> &b);
// Sums and differences of integer polynomials on the numerators alone (the same values;
// rational_product.cpp); other rationals by the generic loop.
template <>
Poly<Rational> operator+(const Poly<Rational> &a, const Poly<Rational> &b);
template <>
Poly<Rational> operator-(const Poly<Rational> &a, const Poly<Rational> &b);

// sum_k sign[k] a[k] b[k] (sign +1 or -1) for n terms: the products and sums of the
// motion layer's cross and dot products in one pass. Generic: by the operators above.
template <class NT>
Poly<NT> signed_products_generic(const Poly<NT> *const *a, const Poly<NT> *const *b,
                                 const int *sign, size_t n) {
  if (n == 0) return Poly<NT>();
  Poly<NT> r = *a[0] * *b[0];  // the same operations as a0 b0 +- a1 b1 ... written out
  if (sign[0] < 0) r = -r;
  for (size_t k = 1; k < n; ++k) r = sign[k] > 0 ? r + *a[k] * *b[k] : r - *a[k] * *b[k];
  return r;
}
template <class NT>
Poly<NT> signed_products(const Poly<NT> *const *a, const Poly<NT> *const *b, const int *sign,
                         size_t n) {
  return signed_products_generic(a, b, sign, n);
}
// Integer inputs (the exact stage's normal form, rational_product.cpp): one integer
// convolution into the result's numerators (mpz_addmul / mpz_submul), without the
// temporaries of each product and sum (each Rational costs two allocations); other
// rationals by the generic loop.
template <>
Poly<Rational> signed_products(const Poly<Rational> *const *a, const Poly<Rational> *const *b,
                               const int *sign, size_t n);

template <class NT>
Poly<NT> operator*(const NT &s, const Poly<NT> &a) {
  std::vector<NT> r(a.c.size());
  for (size_t i = 0; i < a.c.size(); ++i) {
    op_cost(s, a.c[i]);
    r[i] = s * a.c[i];
  }
  return Poly<NT>(std::move(r));
}

// Remainder of a modulo b (deg b >= 0, leading coefficient certainly nonzero).
template <class NT>
Poly<NT> rem(Poly<NT> a, const Poly<NT> &b) {
  const int db = b.degree();
  if (db < 0) throw arith::Internal_error("polynomial remainder by zero");
  if (arith::sign(b.lc()) == 0) throw arith::Internal_error("untrimmed divisor");
  while (a.degree() >= db) {
    const int da = a.degree();
    NT q = a.lc() / b.lc();
    for (int i = 0; i <= db; ++i) {
      exact_cost<NT>([&] { return (limbs(q) + limbs(a.c[da - db + i])) * limbs(b.c[i]); });
      a.c[da - db + i] = a.c[da - db + i] - q * b.c[i];
    }
    a.c.pop_back();  // the leading term cancels by construction
    a.trim();
  }
  return a;
}

// p(a + (b - a) s) as a polynomial of s (Taylor shift then scaling).
template <class NT>
Poly<NT> reparametrize(const Poly<NT> &p, const NT &a, const NT &b) {
  // [0, 1] itself, exactly: p unchanged (the loops below would compute the same values).
  // Intervals take the loops, whose enclosures are what their callers were tuned on.
  if constexpr (std::is_same_v<NT, Rational>)
    if (sgn(a) == 0 && b == 1) return p;
  std::vector<NT> q = p.c;
  const size_t n = q.size();
  // Taylor shift by a: q(t + a), by repeated synthetic division (Horner scheme).
  for (size_t i = 0; i + 1 < n; ++i)
    for (size_t j = n - 1; j > i; --j) {
      exact_cost<NT>([&] { return (limbs(q[j - 1]) + limbs(q[j])) * limbs(a); });
      q[j - 1] = q[j - 1] + a * q[j];
    }
  NT w = b - a, scale = arith::from_int<NT>(1);
  for (size_t k = 0; k < n; ++k) {
    exact_cost<NT>([&] { return limbs(q[k]) * limbs(scale) + limbs(scale) * limbs(w); });
    q[k] = q[k] * scale;
    scale = scale * w;
  }
  return Poly<NT>(std::move(q));
}

template <class NT>
Poly<NT> derivative(const Poly<NT> &p) {
  if (p.c.size() <= 1) return Poly<NT>();
  std::vector<NT> r(p.c.size() - 1);
  for (size_t i = 1; i < p.c.size(); ++i) r[i - 1] = arith::from_int<NT>(static_cast<long>(i)) * p.c[i];
  return Poly<NT>(std::move(r));
}

// Converts coefficients Rational -> NT.
template <class NT>
Poly<NT> convert(const Poly<Rational> &p) {
  std::vector<NT> r;
  r.reserve(p.c.size());
  for (const Rational &x : p.c) r.push_back(arith::from_rational<NT>(x));
  return Poly<NT>(std::move(r));
}

}  // namespace pccd::poly
