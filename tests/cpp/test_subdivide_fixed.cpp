// The exact root counter on fixed-width integers (arith::Fixed_int, poly/subdivide_fixed.h)
// against the same counter on GMP integers only (set_fixed_limbs(0)): the same decision,
// the same count and the same budget left, for every width cap (4 to 32 limbs), on
// random integer Bernstein vectors of mixed signs and on polynomials with known close
// roots (deep subdivisions), scaled so that their entries sit just below, at and above
// the bounds of each width (inputs that must run on a wider type or on GMP from the
// start, and inputs that fit at first and outgrow their width during the subdivision).
// Then the fixed-width integers themselves against GMP: conversions both ways, sums,
// shifts, the lowest set bit, sig_bits, and the halving (poly::halve_fixed) entry for
// entry, at the bound of its guard (halving_fits) and one bit past it.
// Prints "N passed, N failed".
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "poly/bernstein.h"
#include "poly/subdivide.h"

using pccd::arith::Integer;
using pccd::arith::Rational;
using pccd::poly::Poly;
using Vec = std::vector<Integer>;

#include "expect.h"

static std::mt19937_64 rng(20261129);

// A random integer of about `bits` bits (exactly `bits` when exact), random sign.
static Integer random_int(unsigned bits, bool exact = false) {
  Integer z = 0;
  for (unsigned b = 0; b < bits; b += 32) z = (z << 32) + Integer(static_cast<unsigned long>(rng() & 0xffffffffu));
  z >>= (bits + 31) / 32 * 32 - bits;
  if (exact) mpz_setbit(z.get_mpz_t(), bits - 1);
  return rng() % 2 ? z : Integer(-z);
}

struct Outcome {
  bool ok;
  long count;
  int budget;
};

static Outcome run(int limbs, const Vec &f, const std::vector<Vec> &g, const std::vector<Vec> &h) {
  pccd::poly::Subdivision_counter<Integer> c(256);
  c.set_fixed_limbs(limbs);
  long n = 0;
  const bool ok = c.count(f, g, n, h);
  return {ok, n, c.budget_left()};
}

static void compare(const Vec &f, const std::vector<Vec> &g, const std::vector<Vec> &h, const std::string &name) {
  const Outcome ref = run(0, f, g, h);
  for (int limbs : {4, 6, 8, 12, 16, 24, 32}) {
    const Outcome o = run(limbs, f, g, h);
    expect(o.ok == ref.ok && o.count == ref.count && o.budget == ref.budget,
           name + " limbs " + std::to_string(limbs) + ": " + std::to_string(o.ok) + "/" +
               std::to_string(o.count) + "/" + std::to_string(o.budget) + " vs GMP " +
               std::to_string(ref.ok) + "/" + std::to_string(ref.count) + "/" + std::to_string(ref.budget));
  }
}

// Bernstein vector (integers) of prod (t - r_i), times 2^shift, sign flipped when neg.
static Vec with_roots(const std::vector<Rational> &roots, unsigned shift, bool neg) {
  Poly<Rational> p(std::vector<Rational>{Rational(1)});
  for (const Rational &r : roots) p = p * Poly<Rational>(std::vector<Rational>{-r, Rational(1)});
  Vec b = pccd::poly::bernstein_integer(p);
  for (Integer &x : b) {
    x <<= shift;
    if (neg) x = -x;
  }
  return b;
}

static void fixed_ops() {
  for (int k = 0; k < 2000; ++k) {
    const unsigned bits = 1 + rng() % 250;
    const Integer a = random_int(bits), b = random_int(1 + rng() % 250);
    pccd::arith::Fixed_int<4> fa, fb;
    expect(pccd::arith::to_fixed(a, fa) && pccd::arith::to_fixed(b, fb), "to_fixed fits");
    expect(pccd::arith::from_fixed(fa) == a, "round trip " + a.get_str());
    expect(fa.sig_bits() == pccd::arith::sig_bits(a), "sig_bits " + a.get_str());
    pccd::arith::Fixed_int<4> s = fa;
    s.add(fb);
    expect(pccd::arith::from_fixed(s) == a + b, "sum");
    const unsigned sh = rng() % 4;
    pccd::arith::Fixed_int<4> l = fa;
    l.shl(sh);
    expect(pccd::arith::from_fixed(l) == Integer(a << sh), "shl");
    if (sgn(a) != 0) {
      const unsigned low = fa.low_bit();
      expect(low == mpz_scan1(a.get_mpz_t(), 0), "low bit");
      pccd::arith::Fixed_int<4> r = fa;
      r.sar(low);
      Integer q;
      mpz_fdiv_q_2exp(q.get_mpz_t(), a.get_mpz_t(), low);
      expect(pccd::arith::from_fixed(r) == q, "sar");
    }
    expect(pccd::arith::sign(fa) == sgn(a), "sign");
  }
  // The edges of Fixed_int<4>: -2^255 fits, 2^255 and -2^255 - 1 do not.
  pccd::arith::Fixed_int<4> x;
  const Integer p255 = Integer(1) << 255;
  expect(pccd::arith::to_fixed(Integer(-p255), x) && pccd::arith::from_fixed(x) == -p255, "-2^255 fits");
  expect(!pccd::arith::to_fixed(p255, x), "2^255 does not fit");
  expect(!pccd::arith::to_fixed(Integer(-p255 - 1), x), "-2^255 - 1 does not fit");
  expect(pccd::arith::to_fixed(Integer(p255 - 1), x) && pccd::arith::from_fixed(x) == p255 - 1, "2^255 - 1 fits");
  // The halving entry for entry, rows at the width's bound (halving_bits = 256).
  for (int k = 0; k < 500; ++k) {
    const size_t n = 1 + rng() % 6;
    Vec w(n);
    for (Integer &z : w) z = random_int(256 - n, rng() % 2);
    if (rng() % 4 == 0) w[rng() % n] = -(Integer(1) << (256 - n));  // the most negative
    Vec gl, gr;
    pccd::poly::de_casteljau_halves_scaled(w, gl, gr);
    pccd::arith::Fixed_int<4> fw[8], fl[8], fr[8];
    for (size_t i = 0; i < n; ++i) pccd::arith::to_fixed(w[i], fw[i]);
    expect(pccd::poly::halving_fits(fw, static_cast<int>(n)), "row at the bound fits");
    pccd::poly::halve_fixed<4, 8>(fw, static_cast<int>(n), fl, fr);
    bool same = true;
    for (size_t i = 0; i < n; ++i)
      same = same && pccd::arith::from_fixed(fl[i]) == gl[i] && pccd::arith::from_fixed(fr[i]) == gr[i];
    expect(same, "halves equal");
    pccd::poly::halve_fixed<4, 8>(fw, static_cast<int>(n), fl, fw);  // right over its input
    same = true;
    for (size_t i = 0; i < n; ++i) same = same && pccd::arith::from_fixed(fw[i]) == gr[i];
    expect(same, "right half over its input");
    w[0] = Integer(1) << (256 - n);  // one bit past the bound
    if (n > 1) {
      pccd::arith::to_fixed(w[0], fw[0]);
      expect(!pccd::poly::halving_fits(fw, static_cast<int>(n)), "row past the bound");
    }
  }
}

int main() {
  fixed_ops();
  // Random vectors of mixed signs: sizes 1-7, 0-3 conditions with or without h.
  for (int k = 0; k < 3000; ++k) {
    const unsigned bits = 1 + rng() % 1300;
    auto vec = [&](size_t n) {
      Vec v(n);
      for (Integer &z : v) z = random_int(1 + rng() % bits);
      return v;
    };
    const Vec f = vec(1 + rng() % 7);
    std::vector<Vec> g, h;
    const size_t m = rng() % 4;
    for (size_t i = 0; i < m; ++i) {
      g.push_back(vec(1 + rng() % 5));
      h.push_back(rng() % 2 ? vec(2 + rng() % 2) : Vec{});
    }
    compare(f, g, h, "random " + std::to_string(k));
  }
  // Close roots (deep subdivisions), scaled to each width's bound: entries of s + n bits
  // for s + n = 64 N - 2 .. 64 N + 1, so the run starts at N and outgrows it, or starts
  // wider; conditions with a root between and beside F's roots.
  const std::vector<Rational> roots = {Rational(1, 3), Rational(1, 3) + Rational(1, 1 << 20),
                                       Rational(5, 7)};
  const Vec base = with_roots(roots, 0, false);
  unsigned base_bits = 0;
  for (const Integer &x : base) base_bits = std::max<unsigned>(base_bits, mpz_sizeinbase(x.get_mpz_t(), 2));
  for (int N : {4, 6, 8, 12, 16, 24, 32}) {
    for (int d = -3; d <= 1; ++d) {
      const int target = 64 * N + d - static_cast<int>(base.size());  // sig bits wanted
      const unsigned shift = target > static_cast<int>(base_bits) ? target - base_bits : 0;
      for (bool neg : {false, true}) {
        const Vec f = with_roots(roots, shift, neg);
        const std::vector<Vec> g = {with_roots({Rational(1, 3) + Rational(1, 1 << 21)}, shift / 2, false),
                                    with_roots({Rational(2, 3)}, 0, true)};
        const std::vector<Vec> h = {Vec{}, with_roots({Rational(5, 7)}, 3, false)};
        const std::string name = "close roots N " + std::to_string(N) + " d " + std::to_string(d);
        compare(f, {}, {}, name + " alone");
        compare(f, g, h, name + " with conditions");
      }
    }
  }
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
