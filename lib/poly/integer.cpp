#include "poly/integer.h"

#include "arith/errors.h"

namespace pccd::poly {

Poly<Rational> primitive_positive(const Poly<Rational> &p) {
  if (p.c.empty()) return p;
  arith::Integer l = 1, g = 0;
  for (const Rational &x : p.c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  std::vector<arith::Integer> num(p.c.size());
  for (size_t i = 0; i < p.c.size(); ++i) {
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

Poly<Rational> primitive_monic_sign(const Poly<Rational> &p) {
  Poly<Rational> q = primitive_positive(p);
  if (!q.c.empty() && sgn(q.lc()) < 0)
    for (Rational &x : q.c) x = -x;
  return q;
}

Poly<Rational> prem_positive(Poly<Rational> a, const Poly<Rational> &b) {
  const int db = b.degree();
  if (db < 0 || sgn(b.lc()) <= 0) throw arith::Internal_error("prem_positive: bad divisor");
  const arith::Integer lb = b.lc().get_num();
  while (a.degree() >= db) {
    const int da = a.degree();
    const arith::Integer la = a.lc().get_num();
    // a <- lb * a - la * t^(da-db) * b: the leading term cancels.
    for (int i = 0; i < da - db; ++i) a.c[i] = Rational(a.c[i].get_num() * lb);
    for (int i = 0; i <= db; ++i)
      a.c[da - db + i] = Rational(a.c[da - db + i].get_num() * lb - la * b.c[i].get_num());
    a.c.pop_back();
    a.trim();
  }
  return primitive_positive(a);
}

}  // namespace pccd::poly
