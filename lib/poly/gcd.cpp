#include "poly/gcd.h"

#include "poly/integer.h"
#include "util/work_budget.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace pccd::poly {

static Poly<Rational> monic(Poly<Rational> p) {
  if (p.c.empty()) return p;
  Rational lc = p.lc();
  for (Rational &x : p.c) x /= lc;
  return p;
}

namespace {

// Arithmetic modulo the Mersenne prime 2^61 - 1 (products in 128 bits).
constexpr uint64_t kP = (uint64_t(1) << 61) - 1;
uint64_t mul_mod(uint64_t a, uint64_t b) { return uint64_t((unsigned __int128)a * b % kP); }
uint64_t pow_mod(uint64_t a, uint64_t e) {
  uint64_t r = 1;
  for (; e; e >>= 1, a = mul_mod(a, a))
    if (e & 1) r = mul_mod(r, a);
  return r;
}

// Coefficients of an integer polynomial modulo kP, trimmed.
std::vector<uint64_t> reduce(const Poly<Rational> &p) {
  std::vector<uint64_t> out;
  for (const Rational &x : p.c) out.push_back(mpz_fdiv_ui(x.get_num_mpz_t(), kP));
  while (!out.empty() && out.back() == 0) out.pop_back();
  return out;
}

// True when the integer polynomials a and b (a of degree >= 1) certainly have a constant
// gcd: kP does not divide lc(a), and a mod kP, b mod kP have a constant gcd. Then
// deg gcd(a, b) = 0, because with a = g a' the prime does not divide lc(g) either, so
// g mod kP keeps its degree and divides both reductions. False means "not shown" (the
// remainder sequence decides), never "not coprime".
bool coprime_mod_p(const Poly<Rational> &a, const Poly<Rational> &b) {
  std::vector<uint64_t> x = reduce(a), y = reduce(b);
  if (x.size() != a.c.size() || y.empty()) return false;
  if (x.size() < y.size()) std::swap(x, y);
  while (y.size() > 1) {  // Euclid while y has degree >= 1
    const uint64_t inv = pow_mod(y.back(), kP - 2);
    while (x.size() >= y.size()) {
      const uint64_t q = mul_mod(x.back(), inv);
      const size_t shift = x.size() - y.size();
      for (size_t i = 0; i < y.size(); ++i) x[shift + i] = (x[shift + i] + kP - mul_mod(q, y[i])) % kP;
      while (!x.empty() && x.back() == 0) x.pop_back();
    }
    std::swap(x, y);
  }
  return y.size() == 1;  // a nonzero constant remainder: coprime modulo kP
}

}  // namespace

// The primitive remainder sequence: every polynomial is kept a primitive integer
// polynomial with a positive leading coefficient (poly/integer.h), so the remainders
// are positive multiples of the Euclidean ones and end in a multiple of the gcd.
// Euclid over Q instead canonicalizes a fraction at every coefficient operation, and
// its numbers grow far beyond the primitive ones (a gcd of two degree-8 polynomials of
// 20,000-bit coefficients took seconds that way, and the root counts ask for many).
Poly<Rational> gcd(Poly<Rational> a, Poly<Rational> b) {
  if (a.c.empty()) return monic(std::move(b));
  if (b.c.empty()) return monic(std::move(a));
  a = primitive_monic_sign(std::move(a));
  b = primitive_monic_sign(std::move(b));
  if (a.degree() < b.degree()) std::swap(a, b);
  // Coprime polynomials (most pairs the feature systems ask about) are recognized
  // modulo one prime at a negligible cost; the sequence below is for the rest.
  if (a.degree() < 1 || b.degree() < 1 || coprime_mod_p(a, b)) return Poly<Rational>::constant(Rational(1));
  while (!b.c.empty()) {
    util::work_step();  // a remainder of long numbers can take long (util/work_budget.h)
    Poly<Rational> r = prem_positive(std::move(a), b);  // primitive, c * (a mod b)
    a = std::move(b);
    b = primitive_monic_sign(std::move(r));
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
