#include "poly/gcd.h"

#include "poly/integer.h"
#include "util/work_budget.h"

#include <utility>

namespace pccd::poly {

static Poly<Rational> monic(Poly<Rational> p) {
  if (p.c.empty()) return p;
  Rational lc = p.lc();
  for (Rational &x : p.c) x /= lc;
  return p;
}

// The primitive remainder sequence: every polynomial is kept a primitive integer
// polynomial with a positive leading coefficient (poly/integer.h), so the remainders
// are positive multiples of the Euclidean ones and end in a multiple of the gcd.
// Euclid over Q instead canonicalizes a fraction at every coefficient operation, and
// its numbers grow far beyond the primitive ones (a gcd of two degree-8 polynomials of
// 20,000-bit coefficients took seconds that way, and the root counts ask for many).
Poly<Rational> gcd(Poly<Rational> a, Poly<Rational> b) {
  if (a.c.empty()) return monic(std::move(b));
  if (b.c.empty()) return monic(std::move(a));
  a = primitive_monic_sign(a);
  b = primitive_monic_sign(b);
  if (a.degree() < b.degree()) std::swap(a, b);
  while (!b.c.empty()) {
    util::work_step();  // a remainder of long numbers can take long (util/work_budget.h)
    Poly<Rational> r = prem_positive(std::move(a), b);  // primitive, c * (a mod b)
    a = std::move(b);
    b = primitive_monic_sign(r);
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
