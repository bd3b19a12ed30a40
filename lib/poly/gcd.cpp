#include "poly/gcd.h"

#include <utility>

namespace pccd::poly {

static Poly<Rational> monic(Poly<Rational> p) {
  if (p.c.empty()) return p;
  Rational lc = p.lc();
  for (Rational &x : p.c) x /= lc;
  return p;
}

Poly<Rational> gcd(Poly<Rational> a, Poly<Rational> b) {
  while (!b.c.empty()) {
    Poly<Rational> r = rem(std::move(a), b);
    a = monic(std::move(b));  // keeps coefficient growth in check
    b = std::move(r);
  }
  return monic(std::move(a));
}

Poly<Rational> exact_quotient(Poly<Rational> a, const Poly<Rational> &b) {
  const int db = b.degree();
  if (a.degree() < db) return Poly<Rational>();
  std::vector<Rational> q(a.degree() - db + 1);
  while (a.degree() >= db) {
    const int da = a.degree();
    Rational c = a.lc() / b.lc();
    q[da - db] = c;
    for (int i = 0; i <= db; ++i) a.c[da - db + i] -= c * b.c[i];
    a.c.pop_back();
    a.trim();
  }
  return Poly<Rational>(std::move(q));
}

Poly<Rational> squarefree_primitive(const Poly<Rational> &f) {
  Poly<Rational> g = gcd(f, derivative(f));
  Poly<Rational> s = g.degree() > 0 ? exact_quotient(f, g) : f;
  // Clear denominators, then divide by the content.
  arith::Integer l = 1, content = 0;
  for (const Rational &x : s.c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  std::vector<Rational> out;
  for (const Rational &x : s.c) {
    Rational y = x * l;
    out.push_back(y);
    mpz_gcd(content.get_mpz_t(), content.get_mpz_t(), y.get_num_mpz_t());
  }
  if (sgn(out.back()) < 0) content = -content;
  for (Rational &x : out) x /= content;
  return Poly<Rational>(std::move(out));
}

}  // namespace pccd::poly
