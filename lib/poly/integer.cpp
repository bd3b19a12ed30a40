#include "poly/integer.h"

#include "arith/errors.h"

namespace pccd::poly {

// p by value: a caller that passes a temporary (std::move) gets its coefficients
// divided in place, without a copy of each Rational (two allocations apiece).
Poly<Rational> primitive_positive(Poly<Rational> p) {
  if (p.c.empty()) return p;
  // Integer coefficients (the exact stage's normal form): the gcd of the numerators
  // alone (the general route below with l = 1, without its divisions and copies).
  bool integral = true;
  for (const Rational &x : p.c) integral = integral && mpz_cmp_ui(mpq_denref(x.get_mpq_t()), 1) == 0;
  if (integral) {
    arith::Integer g = 0;
    for (const Rational &x : p.c) {
      util::work_cost([&] { return limbs(g) * limbs(x); });
      mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), mpq_numref(x.get_mpq_t()));
    }
    if (g == 1 || g == 0) return p;  // primitive already (0: all zero, untrimmed)
    for (Rational &x : p.c)  // denominators stay 1: still canonical
      mpz_divexact(mpq_numref(x.get_mpq_t()), mpq_numref(x.get_mpq_t()), g.get_mpz_t());
    return p;
  }
  arith::Integer l = 1, g = 0;
  for (const Rational &x : p.c) {
    util::work_cost([&] { return limbs(l) * limbs(x); });  // util/work_budget.h
    mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  }
  std::vector<arith::Integer> num(p.c.size());
  for (size_t i = 0; i < p.c.size(); ++i) {
    util::work_cost([&] { return (limbs(l) + limbs(g)) * limbs(p.c[i]); });
    num[i] = p.c[i].get_num() * (l / p.c[i].get_den());
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), num[i].get_mpz_t());
  }
  std::vector<Rational> out(p.c.size());
  for (size_t i = 0; i < p.c.size(); ++i) {
    mpz_divexact(num[i].get_mpz_t(), num[i].get_mpz_t(), g.get_mpz_t());
    out[i] = Rational(num[i]);
  }
  return Poly<Rational>(std::move(out));
}

Poly<Rational> primitive_monic_sign(Poly<Rational> p) {
  Poly<Rational> q = primitive_positive(std::move(p));
  if (!q.c.empty() && sgn(q.lc()) < 0)
    for (Rational &x : q.c) mpq_neg(x.get_mpq_t(), x.get_mpq_t());  // in place, canonical
  return q;
}

Poly<Rational> prem_positive(Poly<Rational> a, const Poly<Rational> &b) {
  const int db = b.degree();
  if (db < 0 || sgn(b.lc()) <= 0) throw arith::Internal_error("prem_positive: bad divisor");
  const mpz_srcptr lb = mpq_numref(b.lc().get_mpq_t());
  arith::Integer la;  // one buffer for every step's leading coefficient
  while (a.degree() >= db) {
    const int da = a.degree();
    // a <- lb * a - la * t^(da-db) * b: the leading term cancels, so it is not computed;
    // it is swapped out into la (its slot is popped below). Integer coefficients
    // (denominators 1) are updated in place on their numerators: no temporaries.
    util::work_cost([&] { return limbs(a) * mpz_size(lb) + limbs(a.c[da]) * limbs(b); });
    mpz_swap(la.get_mpz_t(), mpq_numref(a.c[da].get_mpq_t()));
    for (int i = 0; i < da - db; ++i) {
      const mpz_ptr x = mpq_numref(a.c[i].get_mpq_t());
      mpz_mul(x, x, lb);
    }
    for (int i = 0; i < db; ++i) {
      const mpz_ptr x = mpq_numref(a.c[da - db + i].get_mpq_t());
      mpz_mul(x, x, lb);
      mpz_submul(x, la.get_mpz_t(), mpq_numref(b.c[i].get_mpq_t()));
    }
    a.c.pop_back();
    a.trim();
  }
  return primitive_positive(std::move(a));
}

arith::Integer scaled_value(const Poly<Rational> &F, const Rational &t) {
  const int n = F.degree();
  if (n < 0) return 0;
  arith::Integer v = F.c[n].get_num(), term;
  const arith::Integer &p = t.get_num();
  const mpz_srcptr den = t.get_den_mpz_t();
  if (mpz_popcount(den) == 1) {  // q = 2^j: q^(n - i) is a shift by j (n - i)
    const mp_bitcnt_t j = mpz_scan1(den, 0);
    for (int i = n - 1; i >= 0; --i) {
      util::work_cost([&] { return limbs(v) * limbs(p) + limbs(F.c[i]) + j * (n - i) / 64; });
      v *= p;
      mpz_mul_2exp(term.get_mpz_t(), F.c[i].get_num_mpz_t(), j * mp_bitcnt_t(n - i));
      v += term;
    }
    return v;
  }
  arith::Integer qpow = 1;
  const arith::Integer q = t.get_den();
  for (int i = n - 1; i >= 0; --i) {
    util::work_cost([&] { return limbs(v) * limbs(p) + (limbs(F.c[i]) + limbs(q)) * limbs(qpow); });
    qpow *= q;
    v *= p;
    term = F.c[i].get_num() * qpow;
    v += term;
  }
  return v;
}

namespace {

// f / w with integer coefficients when w divides f (w primitive), else false. Long
// division in integers: each quotient coefficient must be an integer.
bool exact_integer_quotient(std::vector<arith::Integer> f, const std::vector<arith::Integer> &w,
                            std::vector<arith::Integer> *q) {
  const size_t dw = w.size() - 1;
  if (f.size() < w.size()) return false;
  q->assign(f.size() - dw, arith::Integer(0));
  for (size_t k = f.size(); k-- > dw;) {
    if (sgn(f[k]) == 0) continue;
    if (!mpz_divisible_p(f[k].get_mpz_t(), w[dw].get_mpz_t())) return false;
    arith::Integer c;
    util::work_cost([&] {
      std::uint64_t s = 0;
      for (const arith::Integer &x : w) s += limbs(x);
      return limbs(f[k]) * limbs(w[dw]) + (limbs(f[k]) + 1) * s;
    });
    mpz_divexact(c.get_mpz_t(), f[k].get_mpz_t(), w[dw].get_mpz_t());
    for (size_t i = 0; i <= dw; ++i) f[k - dw + i] -= c * w[i];
    (*q)[k - dw] = std::move(c);
  }
  for (size_t i = 0; i < dw; ++i)
    if (sgn(f[i]) != 0) return false;
  return true;
}

std::vector<arith::Integer> integer_coefficients(const Poly<Rational> &p) {
  std::vector<arith::Integer> out;
  for (const Rational &x : primitive_positive(p).c) out.push_back(x.get_num());
  return out;
}

}  // namespace

Poly<Rational> divide_out_positive(const Poly<Rational> &f, const Poly<Rational> &w) {
  if (f.c.empty() || w.degree() < 1) return f.c.empty() ? f : primitive_positive(f);
  std::vector<arith::Integer> F = integer_coefficients(f), q;
  const std::vector<arith::Integer> W = integer_coefficients(w);
  while (exact_integer_quotient(F, W, &q)) F = std::move(q);
  std::vector<Rational> out(F.size());
  for (size_t i = 0; i < F.size(); ++i) out[i] = Rational(F[i]);
  return primitive_positive(Poly<Rational>(std::move(out)));
}

Poly<Rational> divide_out_positive(Poly<Rational> f, const std::vector<Poly<Rational>> &ws) {
  for (const Poly<Rational> &w : ws) f = divide_out_positive(f, w);
  return f;
}

}  // namespace pccd::poly
