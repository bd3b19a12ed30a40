// The exact shortcuts of lib/poly on cases built so that the answer is known:
// - poly::gcd's coprimality test modulo 2^61 - 1: gcd(a c, b c) = monic c for a, b, c
//   products of distinct linear factors (t - r) with no root in common, so gcd(a, b) = 1;
//   a c and b c with leading coefficients that are multiples of the prime (the test
//   must not conclude there) and with a shared factor that vanishes modulo the prime;
// - poly::divide_out_positive: f = w^k g with g not divisible by w gives a positive
//   multiple of g; a w that does not divide f leaves f's multiple;
// - the integer product (poly/rational_product.cpp) against the schoolbook loop in
//   rationals written here, for rational and for integer coefficients; sums likewise;
// - poly::primitive_positive's integer shortcut: content 1, a positive multiple, and the
//   general route's answer.
// Prints "N passed, N failed".
#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "poly/gcd.h"
#include "poly/integer.h"

using pccd::arith::Integer;
using pccd::arith::Rational;
using pccd::poly::Poly;

#include "expect.h"

static Poly<Rational> linear(const Rational &root) {  // t - root
  return Poly<Rational>(std::vector<Rational>{-root, Rational(1)});
}

static Poly<Rational> product_of_roots(const std::vector<Rational> &roots, const Rational &lc) {
  Poly<Rational> p = Poly<Rational>::constant(lc);
  for (const Rational &r : roots) p = p * linear(r);
  return p;
}

// The same product by the schoolbook loop over Q (the generic code's way).
static Poly<Rational> schoolbook(const Poly<Rational> &a, const Poly<Rational> &b) {
  if (a.c.empty() || b.c.empty()) return Poly<Rational>();
  std::vector<Rational> r(a.c.size() + b.c.size() - 1, Rational(0));
  for (size_t i = 0; i < a.c.size(); ++i)
    for (size_t j = 0; j < b.c.size(); ++j) r[i + j] += a.c[i] * b.c[j];
  return Poly<Rational>(std::move(r));
}

static bool proportional_positive(const Poly<Rational> &p, const Poly<Rational> &q) {
  if (p.degree() != q.degree() || p.c.empty()) return false;
  const Rational k = p.lc() / q.lc();
  if (sgn(k) <= 0) return false;
  for (size_t i = 0; i < p.c.size(); ++i)
    if (p.c[i] != k * q.c[i]) return false;
  return true;
}

static Poly<Rational> monic(const Poly<Rational> &p) {
  Poly<Rational> q = p;
  const Rational lc = q.lc();
  for (Rational &x : q.c) x /= lc;
  return q;
}

int main() {
  std::mt19937_64 rng(20261125);
  auto rational = [&](int bits) {
    std::uniform_int_distribution<long> num(-(1L << bits), 1L << bits), den(1, 1L << bits);
    Rational r(num(rng), den(rng));
    r.canonicalize();
    return r;
  };
  const Integer P = (Integer(1) << 61) - 1;
  for (int round = 0; round < 300; ++round) {
    // Distinct roots for a, b, c: a pool drawn without repetition.
    std::vector<Rational> pool;
    while (pool.size() < 12) {
      Rational r = rational(4 + round % 40);  // 4 bits: more than 12 distinct values
      bool fresh = true;
      for (const Rational &x : pool) fresh = fresh && x != r;
      if (fresh) pool.push_back(r);
    }
    const int na = 1 + round % 4, nb = 1 + (round / 4) % 4, nc = round % 3;
    std::vector<Rational> ra(pool.begin(), pool.begin() + na),
        rb(pool.begin() + na, pool.begin() + na + nb),
        rc(pool.begin() + 8, pool.begin() + 8 + nc);
    // Leading coefficients: ordinary, or a multiple of the prime (reduction drops the degree).
    const Rational la = round % 5 == 0 ? Rational(P * 3) : rational(20);
    const Rational lb = round % 7 == 0 ? Rational(P) : rational(20);
    if (sgn(la) == 0 || sgn(lb) == 0) continue;
    const Poly<Rational> a = product_of_roots(ra, la), b = product_of_roots(rb, lb),
                         c = product_of_roots(rc, Rational(1));
    const Poly<Rational> g = pccd::poly::gcd(a * c, b * c);
    expect(g.c == c.c, "gcd(a c, b c) = c, round " + std::to_string(round));
    expect(pccd::poly::gcd(a, b).c == Poly<Rational>::constant(Rational(1)).c,
           "gcd(a, b) = 1, round " + std::to_string(round));
    // A common factor whose reduction modulo the prime is t (root P): must be found.
    const Poly<Rational> shared = linear(Rational(P));
    expect(pccd::poly::gcd(a * shared, b * shared).c == shared.c,
           "gcd with the factor t - P, round " + std::to_string(round));
    // Products: the integer convolution equals the rational schoolbook loop.
    expect((a * b).c == schoolbook(a, b).c, "a * b, round " + std::to_string(round));
    // divide_out_positive: w = t^2 + s (s > 0) never divides a product of linear factors.
    const Poly<Rational> w(std::vector<Rational>{abs(rational(10)) + Rational(1, 7), Rational(0), Rational(1)});
    const int k = round % 4;
    Poly<Rational> f = a;
    for (int i = 0; i < k; ++i) f = f * w;
    expect(proportional_positive(pccd::poly::divide_out_positive(f, w), a),
           "divide_out_positive(a w^k, w) ~ a, round " + std::to_string(round));
    expect(proportional_positive(pccd::poly::divide_out_positive(a, w), a),
           "divide_out_positive(a, w) ~ a, round " + std::to_string(round));
    expect(monic(pccd::poly::divide_out_positive(f, w)).c == monic(a).c,
           "monic quotient, round " + std::to_string(round));
  }
  // Integer products (the direct convolution): integer coefficients of up to 320 bits,
  // zeros among them, against the schoolbook loop; also mixed with a rational factor.
  for (int round = 0; round < 500; ++round) {
    auto integer_poly = [&](size_t n) {
      std::vector<Rational> c(n);
      for (Rational &x : c) {
        x = Rational(long(rng() % 2001) - 1000);
        mpq_mul_2exp(x.get_mpq_t(), x.get_mpq_t(), rng() % 320);
        if (rng() % 5 == 0) x = 0;
      }
      return Poly<Rational>(c);
    };
    const Poly<Rational> a = integer_poly(1 + rng() % 7), b = integer_poly(1 + rng() % 7);
    expect((a * b).c == schoolbook(a, b).c, "integer a * b, round " + std::to_string(round));
    const Poly<Rational> q = product_of_roots({rational(8)}, Rational(1, 3));
    expect((a * q).c == schoolbook(a, q).c, "integer a * rational q, round " + std::to_string(round));
    // Sums and differences (integer shortcut, and mixed) against coefficientwise sums
    // over Q; b - b cancels to the zero polynomial, trimmed.
    for (const Poly<Rational> *y : {&b, &q, &a}) {
      std::vector<Rational> s(std::max(a.c.size(), y->c.size()), Rational(0)), d = s;
      for (size_t i = 0; i < s.size(); ++i) {
        const Rational x = i < a.c.size() ? a.c[i] : Rational(0), z = i < y->c.size() ? y->c[i] : Rational(0);
        s[i] = x + z;
        d[i] = x - z;
      }
      expect((a + *y).c == Poly<Rational>(s).c && (a - *y).c == Poly<Rational>(d).c,
             "a + y, a - y, round " + std::to_string(round));
    }
    // primitive_positive of integer coefficients (its shortcut) with a common factor:
    // integers without a common factor, a positive multiple of a, and the same as the
    // general route's answer for a / 3 (a fraction).
    const Poly<Rational> ak = Poly<Rational>::constant(Rational(1 + long(rng() % 90))) * a;
    const Poly<Rational> pp = pccd::poly::primitive_positive(ak);
    Integer content = 0;
    bool integral = true;
    for (const Rational &x : pp.c) {
      integral = integral && x.get_den() == 1;
      mpz_gcd(content.get_mpz_t(), content.get_mpz_t(), x.get_num_mpz_t());
    }
    expect(a.c.empty() ? pp.c.empty() : integral && content == 1 && proportional_positive(pp, a),
           "primitive_positive(k a), round " + std::to_string(round));
    expect(pp.c == pccd::poly::primitive_positive(Poly<Rational>::constant(Rational(1, 3)) * ak).c,
           "primitive_positive(k a) = primitive_positive(k a / 3), round " + std::to_string(round));
  }
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
