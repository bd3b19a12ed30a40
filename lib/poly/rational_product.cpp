// The product of two exact polynomials through integers: a = A / la and b = B / lb with
// A, B integer polynomials and la, lb the lcms of the denominators, so
// a b = (A B) / (la lb). A B is an integer convolution (mpz_addmul, no fraction), and
// each coefficient of the result is reduced once; integer inputs convolve directly. The generic loop (poly.h) instead
// canonicalizes a fraction at every one of its deg a * deg b products and sums: a
// kinematic chain's motions (dyadic coefficients of 50-400 bits, degrees up to 14) spent
// most of their time in those gcds. Integer inputs (la = lb = 1, the exact stage's
// normal form) skip the reduction altogether.
//
// Both count their work by cost (util::work_cost: a row of the convolution, a Horner
// step, a reduction), so a limit is checked between any two of them whatever the sizes.
#include <algorithm>

#include "poly/lowest_terms.h"
#include "poly/poly.h"

namespace pccd::poly {

namespace {

// p = num / l with integer num and l the lcm of p's denominators.
void split(const Poly<Rational> &p, std::vector<arith::Integer> *num, arith::Integer *l) {
  *l = 1;
  for (const Rational &x : p.c) {
    util::work_cost([&] { return limbs(*l) * limbs(x); });
    mpz_lcm(l->get_mpz_t(), l->get_mpz_t(), x.get_den_mpz_t());
  }
  num->resize(p.c.size());
  for (size_t i = 0; i < p.c.size(); ++i) {
    util::work_cost([&] { return limbs(*l) * limbs(p.c[i]); });
    arith::Integer &n = (*num)[i];
    mpz_divexact(n.get_mpz_t(), l->get_mpz_t(), p.c[i].get_den_mpz_t());
    n *= p.c[i].get_num();
  }
}

}  // namespace

namespace {

bool integral(const Poly<Rational> &p) {
  for (const Rational &x : p.c)
    if (mpz_cmp_ui(mpq_denref(x.get_mpq_t()), 1) != 0) return false;
  return true;
}

// a b for integer a and b (the exact stage's normal form): the convolution of the
// numerators straight into the result's numerators (denominators stay 1, a canonical
// fraction), without split's copies and lcms.
Poly<Rational> integer_product(const Poly<Rational> &a, const Poly<Rational> &b) {
  std::vector<Rational> r(a.c.size() + b.c.size() - 1);  // each 0 / 1
  std::uint64_t size_b = 0;
  if (util::current_budget())
    for (const Rational &x : b.c) size_b += limbs(x);
  for (size_t i = 0; i < a.c.size(); ++i) {
    const mpz_srcptr ai = mpq_numref(a.c[i].get_mpq_t());
    if (mpz_sgn(ai) == 0) continue;
    util::work_cost([&] { return limbs(a.c[i]) * size_b + limbs(r[i]) * b.c.size(); });
    for (size_t j = 0; j < b.c.size(); ++j)
      mpz_addmul(mpq_numref(r[i + j].get_mpq_t()), ai, mpq_numref(b.c[j].get_mpq_t()));
  }
  return Poly<Rational>(std::move(r));
}

// a + sign b for integer a and b, sign = +1 or -1.
Poly<Rational> integer_sum(const Poly<Rational> &a, const Poly<Rational> &b, int sign) {
  std::vector<Rational> r(std::max(a.c.size(), b.c.size()));  // each 0 / 1
  for (size_t i = 0; i < r.size(); ++i) {
    const mpz_ptr ri = mpq_numref(r[i].get_mpq_t());
    const bool in_a = i < a.c.size(), in_b = i < b.c.size();
    if (in_a && in_b) {
      op_cost(a.c[i], b.c[i]);
      (sign > 0 ? mpz_add : mpz_sub)(ri, mpq_numref(a.c[i].get_mpq_t()), mpq_numref(b.c[i].get_mpq_t()));
    } else if (in_a) {
      mpz_set(ri, mpq_numref(a.c[i].get_mpq_t()));
    } else if (sign > 0) {
      mpz_set(ri, mpq_numref(b.c[i].get_mpq_t()));
    } else {
      mpz_neg(ri, mpq_numref(b.c[i].get_mpq_t()));
    }
  }
  return Poly<Rational>(std::move(r));
}

// The generic loop of poly.h for rationals that are not all integers.
Poly<Rational> rational_sum(const Poly<Rational> &a, const Poly<Rational> &b, int sign) {
  std::vector<Rational> r(std::max(a.c.size(), b.c.size()), Rational(0));
  for (size_t i = 0; i < a.c.size(); ++i) r[i] = a.c[i];
  for (size_t i = 0; i < b.c.size(); ++i) {
    op_cost(r[i], b.c[i]);
    if (sign > 0) r[i] += b.c[i]; else r[i] -= b.c[i];
  }
  return Poly<Rational>(std::move(r));
}

}  // namespace

template <>
Poly<Rational> operator+(const Poly<Rational> &a, const Poly<Rational> &b) {
  return integral(a) && integral(b) ? integer_sum(a, b, 1) : rational_sum(a, b, 1);
}

template <>
Poly<Rational> operator-(const Poly<Rational> &a, const Poly<Rational> &b) {
  return integral(a) && integral(b) ? integer_sum(a, b, -1) : rational_sum(a, b, -1);
}

template <>
Poly<Rational> operator*(const Poly<Rational> &a, const Poly<Rational> &b) {
  if (a.c.empty() || b.c.empty()) return Poly<Rational>();
  if (integral(a) && integral(b)) return integer_product(a, b);
  std::vector<arith::Integer> A, B;
  arith::Integer la, lb;
  split(a, &A, &la);
  split(b, &B, &lb);
  std::vector<arith::Integer> r(A.size() + B.size() - 1);
  std::uint64_t size_B = 0;
  if (util::current_budget())
    for (const arith::Integer &x : B) size_B += limbs(x);
  for (size_t i = 0; i < A.size(); ++i) {
    if (sgn(A[i]) == 0) continue;
    util::work_cost([&] { return limbs(A[i]) * size_B + limbs(r[i]) * B.size(); });
    for (size_t j = 0; j < B.size(); ++j)
      mpz_addmul(r[i + j].get_mpz_t(), A[i].get_mpz_t(), B[j].get_mpz_t());
  }
  const arith::Integer l = la * lb;
  std::vector<Rational> out(r.size());
  for (size_t k = 0; k < r.size(); ++k) {
    out[k] = Rational(r[k], l);
    if (l != 1) lowest_terms(out[k]);  // the gcd, counted and within the time limit
  }
  return Poly<Rational>(std::move(out));
}

template <>
Poly<Rational> signed_products(const Poly<Rational> *const *a, const Poly<Rational> *const *b,
                               const int *sign, size_t n) {
  size_t size = 0;
  for (size_t k = 0; k < n; ++k) {
    if (!integral(*a[k]) || !integral(*b[k])) return signed_products_generic(a, b, sign, n);
    if (!a[k]->c.empty() && !b[k]->c.empty()) size = std::max(size, a[k]->c.size() + b[k]->c.size() - 1);
  }
  std::vector<Rational> r(size);  // each 0 / 1; numerators accumulate, denominators stay 1
  for (size_t k = 0; k < n; ++k) {
    const std::vector<Rational> &x = a[k]->c, &y = b[k]->c;
    if (x.empty() || y.empty()) continue;  // a zero product (r may be shorter than x)
    std::uint64_t size_y = 0;
    if (util::current_budget())
      for (const Rational &v : y) size_y += limbs(v);
    const auto op = sign[k] > 0 ? mpz_addmul : mpz_submul;
    for (size_t i = 0; i < x.size(); ++i) {
      const mpz_srcptr xi = mpq_numref(x[i].get_mpq_t());
      if (mpz_sgn(xi) == 0) continue;
      util::work_cost([&] { return limbs(x[i]) * size_y + limbs(r[i]) * y.size(); });  // as integer_product
      for (size_t j = 0; j < y.size(); ++j) op(mpq_numref(r[i + j].get_mpq_t()), xi, mpq_numref(y[j].get_mpq_t()));
    }
  }
  return Poly<Rational>(std::move(r));  // trimmed: the sum may cancel leading terms
}

template <>
Rational Poly<Rational>::eval(const Rational &t) const {
  // c_i = C_i / L (L the lcm of the denominators) and t = p / q:
  // f(t) = (sum C_i p^i q^(n-i)) / (L q^n), the sum by Horner's rule in integers.
  if (c.empty()) return Rational(0);
  std::vector<arith::Integer> C;
  arith::Integer L;
  split(*this, &C, &L);
  const size_t n = C.size() - 1;
  const arith::Integer &p = t.get_num(), &q = t.get_den();
  arith::Integer v = C[n], qpow = 1;
  for (size_t i = n; i-- > 0;) {
    util::work_cost([&] { return limbs(v) * limbs(p) + (limbs(C[i]) + limbs(q)) * limbs(qpow); });
    qpow *= q;
    v *= p;
    v += C[i] * qpow;
  }
  util::work_cost([&] { return limbs(L) * limbs(qpow); });
  return lowest_terms(v, L * qpow);  // the gcd, counted and within the time limit
}

void eval_common(const Poly<Rational> *const *ps, size_t count, const Rational &t,
                 std::vector<arith::Integer> *num, arith::Integer *den) {
  // L the lcm of every denominator, n the largest degree, t = p / q: each value is
  // (sum C_i p^i q^(n-i)) / (L q^n) with C_i = c_i L, the sum by Horner's rule in p
  // over the powers of q.
  arith::Integer L = 1;
  size_t n = 0;
  for (size_t k = 0; k < count; ++k) {
    for (const Rational &x : ps[k]->c) {
      util::work_cost([&] { return limbs(L) * limbs(x); });
      mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), x.get_den_mpz_t());
    }
    if (!ps[k]->c.empty()) n = std::max(n, ps[k]->c.size() - 1);
  }
  const arith::Integer &p = t.get_num(), &q = t.get_den();
  std::vector<arith::Integer> qpow(n + 1);
  qpow[0] = 1;
  for (size_t i = 1; i <= n; ++i) {
    util::work_cost([&] { return limbs(qpow[i - 1]) * limbs(q); });
    qpow[i] = qpow[i - 1] * q;
  }
  num->assign(count, arith::Integer(0));
  for (size_t k = 0; k < count; ++k) {
    const std::vector<Rational> &c = ps[k]->c;
    if (c.empty()) continue;
    const size_t d = c.size() - 1;
    arith::Integer &v = (*num)[k], C;
    for (size_t i = d + 1; i-- > 0;) {
      util::work_cost([&] { return limbs(v) * limbs(p) + (limbs(L) + limbs(c[i])) * limbs(qpow[d - i]); });
      mpz_divexact(C.get_mpz_t(), L.get_mpz_t(), c[i].get_den_mpz_t());
      C *= c[i].get_num();
      v *= p;
      v += C * qpow[d - i];
    }
    util::work_cost([&] { return limbs(v) * limbs(qpow[n - d]); });
    v *= qpow[n - d];
  }
  util::work_cost([&] { return limbs(L) * limbs(qpow[n]); });
  *den = L * qpow[n];
}

}  // namespace pccd::poly
