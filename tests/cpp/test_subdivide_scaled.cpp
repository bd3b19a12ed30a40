// poly::integer_multiple and poly::de_casteljau_halves_scaled (the exact root counter's
// halving on integers) against the rational halving poly::de_casteljau_halves, which
// divides by 2 at every step: integer_multiple(b) must be L b (L the lcm of b's
// denominators); each scaled half must be c times the rational half of b with ONE c > 0
// for all of its entries (the counter reads signs within a vector only, which such a c
// keeps), be integers, and have no power of two common to all its entries left. Inputs:
// random rationals of mixed signs, sizes 1 to 8, with zeros, big and tiny magnitudes,
// and a case whose midpoint value is exactly 0. Then the counter itself: exact root
// counts of products of distinct linear factors with known roots. And
// poly::bernstein_integer, the counter's integer Bernstein vectors, against
// bernstein_coefficients: one positive factor for the whole vector. And the interval
// halving (poly::half_of) against exact rational halves, in every rounding mode.
// Prints "N passed, N failed".
#include <algorithm>
#include <cfenv>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "poly/bernstein.h"
#include "poly/subdivide.h"

using pccd::arith::Integer;
using pccd::arith::Interval;
using pccd::arith::Rational;
using pccd::poly::Poly;

#include "expect.h"

static std::string show(const std::vector<Rational> &v) {
  std::string s;
  for (const Rational &x : v) s += x.get_str() + " ";
  return s;
}

// Whether s = c r for one rational c > 0 (both all zero counts), s of integers with no
// common factor 2.
static bool positive_multiple(const std::vector<Integer> &s, const std::vector<Rational> &r) {
  if (s.size() != r.size()) return false;
  Rational c = 0;
  bool odd = false;
  for (size_t i = 0; i < r.size(); ++i) {
    if (sgn(r[i]) != 0 && sgn(c) == 0) c = Rational(s[i]) / r[i];
    odd = odd || mpz_odd_p(s[i].get_mpz_t());
  }
  if (sgn(c) == 0) return std::all_of(s.begin(), s.end(), [](const Integer &x) { return sgn(x) == 0; });
  if (sgn(c) < 0 || !odd) return false;
  for (size_t i = 0; i < r.size(); ++i)
    if (Rational(s[i]) != c * r[i]) return false;
  return true;
}

static void check(const std::vector<Rational> &b, const std::string &name) {
  std::vector<Rational> l, r;
  std::vector<Integer> sl, sr;
  pccd::poly::de_casteljau_halves(b, l, r);
  const std::vector<Integer> z = pccd::poly::integer_multiple(b);
  Integer L = 1;
  for (const Rational &x : b) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), x.get_den_mpz_t());
  bool ok = z.size() == b.size();
  for (size_t i = 0; ok && i < b.size(); ++i) ok = Rational(z[i]) == Rational(L) * b[i];
  expect(ok, name + ": integer_multiple of " + show(b));
  pccd::poly::de_casteljau_halves_scaled(z, sl, sr);
  expect(positive_multiple(sl, l) && positive_multiple(sr, r), name + ": halves of " + show(b));
}

// The Bernstein coefficients on [0, 1] of prod (t - roots[k]).
static std::vector<Rational> product_bernstein(const std::vector<Rational> &roots) {
  Poly<Rational> p = Poly<Rational>::constant(Rational(1));
  for (const Rational &x : roots) p = p * Poly<Rational>(std::vector<Rational>{-x, Rational(1)});
  return pccd::poly::bernstein_coefficients(p, Rational(0), Rational(1));
}

int main() {
  std::mt19937_64 rng(34);
  std::uniform_int_distribution<long> num(-1000000, 1000000), den(1, 4096), size(1, 8), shift(0, 120);
  for (int k = 0; k < 2000; ++k) {
    std::vector<Rational> b(size(rng));
    for (Rational &x : b) {
      x = Rational(num(rng), den(rng));
      if (k % 3 == 0) mpq_mul_2exp(x.get_mpq_t(), x.get_mpq_t(), shift(rng));
      if (k % 3 == 1) mpq_div_2exp(x.get_mpq_t(), x.get_mpq_t(), shift(rng));
      if (k % 7 == 0 && rng() % 2) x = 0;
      x.canonicalize();
    }
    check(b, "random #" + std::to_string(k));
  }
  // bernstein_integer(p): a positive multiple of bernstein_coefficients(p, 0, 1), as
  // integers; the sign test built on it agrees with certain_sign_on.
  for (int k = 0; k < 2000; ++k) {
    std::vector<Rational> c(size(rng));
    for (Rational &x : c) {
      x = Rational(num(rng), k % 2 ? den(rng) : 1);
      if (k % 3 == 0) mpq_mul_2exp(x.get_mpq_t(), x.get_mpq_t(), shift(rng));
      if (k % 5 == 0 && rng() % 2) x = 0;
      x.canonicalize();
    }
    const Poly<Rational> p(c);
    const std::vector<Rational> ref = pccd::poly::bernstein_coefficients(p, Rational(0), Rational(1));
    std::vector<Integer> z = pccd::poly::bernstein_integer(p);
    Rational c0 = 0;  // the factor; positive_multiple above also wants no common 2
    for (size_t i = 0; i < ref.size() && i < z.size(); ++i)
      if (sgn(ref[i]) != 0 && sgn(c0) == 0) c0 = Rational(z[i]) / ref[i];
    bool ok = z.size() == ref.size() && sgn(c0) >= 0;
    for (size_t i = 0; ok && i < ref.size(); ++i) ok = Rational(z[i]) == c0 * ref[i];
    ok = ok && (sgn(c0) > 0 || std::all_of(ref.begin(), ref.end(), [](const Rational &x) { return sgn(x) == 0; }));
    expect(ok, "bernstein_integer of " + show(p.c));
    expect(pccd::poly::certain_sign_on_integers(p) ==
               pccd::poly::certain_sign_on(p, Rational(0), Rational(1)),
           "certain_sign_on_integers of " + show(p.c));
  }
  // Interval halving (half_of, de_casteljau_halves on intervals) under every rounding
  // mode: each half's entries enclose the rational halves of the doubles (exact
  // oracle), and an interval whose ends halve without loss halves to exactly them.
  const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> expo(-1080, 60);
  auto encloses = [](const Interval &x, const Rational &v) {
    return Rational(x.lo) <= v && v <= Rational(x.hi);
  };
  for (int mode : modes) {
    std::fesetround(mode);
    for (int k = 0; k < 500; ++k) {
      std::vector<Rational> b(size(rng));
      std::vector<Interval> bi(b.size());
      for (size_t i = 0; i < b.size(); ++i) {
        const double x = std::ldexp(unit(rng), k % 4 == 0 ? expo(rng) : int(rng() % 40) - 20);
        bi[i] = Interval(x);
        b[i] = Rational(x);
      }
      std::vector<Rational> l, r;
      std::vector<Interval> li, ri;
      pccd::poly::de_casteljau_halves(b, l, r);
      pccd::poly::de_casteljau_halves(bi, li, ri);
      bool ok = li.size() == l.size() && ri.size() == r.size();
      for (size_t i = 0; ok && i < l.size(); ++i) ok = encloses(li[i], l[i]) && encloses(ri[i], r[i]);
      expect(ok, "interval halves enclose the rational ones, mode " + std::to_string(mode));
      const double lo = std::ldexp(unit(rng), expo(rng)), hi = lo + std::fabs(std::ldexp(unit(rng), expo(rng)));
      const Interval h = pccd::poly::half_of(Interval(lo, hi));
      const bool lossless = std::ldexp(lo, -1) * 2 == lo && std::ldexp(hi, -1) * 2 == hi;
      expect(encloses(h, Rational(lo) / 2) && encloses(h, Rational(hi) / 2) &&
                 (!lossless || (h.lo == std::ldexp(lo, -1) && h.hi == std::ldexp(hi, -1))),
             "half_of [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
  }
  std::fesetround(FE_TONEAREST);
  check({Rational(0)}, "one zero");
  check({Rational(-3, 7)}, "one entry");
  check(product_bernstein({Rational(1, 2), Rational(1, 3), Rational(5, 4)}), "midpoint root");

  // The counter: roots in the open (0, 1), none with conditions. A count is never wrong;
  // "undecided" (false: the caller then counts with Hermite's method) is allowed only
  // where marked: a root at a midpoint beside others leaves pieces with a zero end,
  // which the rational halving did not decide either (checked before this change).
  struct Case {
    std::vector<Rational> roots;
    long expected;
    bool must_decide;
  };
  const std::vector<Case> cases = {
      {{Rational(1, 3)}, 1, true},
      {{Rational(1, 2)}, 1, true},
      {{Rational(1, 3), Rational(2, 3), Rational(5, 4)}, 2, true},
      {{Rational(1, 2), Rational(1, 1000), Rational(999, 1000)}, 3, false},
      {{Rational(-1, 2), Rational(3, 2)}, 0, true},
      {{Rational(1, 7), Rational(1, 7) + Rational(1, 1 << 20)}, 2, true},
      {{Rational(1, 1 << 30), Rational(3, 5), Rational(4, 5), Rational(2)}, 3, true},
  };
  for (const Case &c : cases) {
    pccd::poly::Subdivision_counter<Rational> counter(256);
    long n = 0;
    const bool ok = counter.count(product_bernstein(c.roots), {}, n);
    expect(ok ? n == c.expected : !c.must_decide, "count of " + show(c.roots) + "= " + std::to_string(n) + (ok ? "" : " (undecided)"));
  }
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
