#include "poly/rational_root.h"

#include "poly/gcd.h"

namespace pccd::poly {
namespace {

struct Candidate {
  bool rational = false;
  Rational r;                 // when rational
  Poly<Rational> F;           // otherwise: the only root of F in (a, b)
  Rational a, b;
};

int sign_at(const Poly<Rational> &F, const Rational &t) { return sgn(F.eval(t)); }

// Halves (a, b) keeping the only root of F inside; returns true and sets r when the
// midpoint is that root.
bool sign_bisect(const Poly<Rational> &F, Rational &a, Rational &b, Rational &r) {
  Rational m = (a + b) / 2;
  int sm = sign_at(F, m);
  if (sm == 0) {
    r = m;
    return true;
  }
  if (sm == sign_at(F, a)) a = m; else b = m;
  return false;
}

// The first contact of system s in (lo, hi) (s has one there and does not hit hi
// earlier than its interior contacts).
Candidate first_root(const System<Rational> &s, Rational a, Rational b) {
  Candidate c;
  c.F = squarefree_primitive(s.f);
  const std::vector<Poly<Rational>> none;
  // 1. Shrink until (a, b) holds only the first contact, as the only root of F, with
  //    F nonzero at both ends.
  while (!(count_roots(c.F, none, a, b) == 1 && sign_at(c.F, a) != 0 && sign_at(c.F, b) != 0)) {
    Rational m = (a + b) / 2;
    long left = s.count_open(a, m);
    if (left == 0 && s.hits(m)) {
      c.rational = true;
      c.r = m;
      return c;
    }
    if (left > 0) b = m; else a = m;
  }
  if (!may_have_rational_root(c.F)) {
    c.a = a;
    c.b = b;
    return c;  // irrational, and (a, b) isolates it
  }
  // 2. Narrow below 1/L, then test the only multiple of 1/L inside.
  const Rational L = abs(c.F.lc());
  while ((b - a) * L >= 1) {
    if (sign_bisect(c.F, a, b, c.r)) {
      c.rational = true;
      return c;
    }
  }
  Rational La = a * L;
  arith::Integer k = La.get_num() / La.get_den() + 1;  // floor(L a) + 1 (a >= 0)
  Rational cand = Rational(k) / L;
  cand.canonicalize();
  if (cand < b && sign_at(c.F, cand) == 0) {
    c.rational = true;
    c.r = cand;
    return c;
  }
  c.a = a;
  c.b = b;
  return c;
}

}  // namespace

Rational_root_result rational_first_contact(const std::vector<System<Rational>> &sys,
                                            const std::vector<size_t> &active,
                                            Rational lo, Rational hi) {
  std::vector<Candidate> cands(active.size());
  for (size_t k = 0; k < active.size(); ++k) {
    const System<Rational> &s = sys[active[k]];
    if (s.count_open(lo, hi) == 0) {  // its contact in (lo, hi] is hi itself
      cands[k].rational = true;
      cands[k].r = hi;
    } else {
      cands[k] = first_root(s, lo, hi);
    }
  }
  Rational_root_result out;
  bool any_rational = false;
  Rational best;
  for (const Candidate &c : cands)
    if (c.rational && (!any_rational || c.r < best)) {
      best = c.r;
      any_rational = true;
    }
  if (!any_rational) return out;
  // An irrational root below the best rational one makes t* irrational.
  for (Candidate &c : cands) {
    if (c.rational) continue;
    Rational unused;
    while (!(c.b < best || c.a > best)) sign_bisect(c.F, c.a, c.b, unused);
    if (c.b < best) return out;
  }
  out.exact = true;
  out.t = best;
  for (size_t k = 0; k < active.size(); ++k)
    if (cands[k].rational && cands[k].r == best) out.which.push_back(active[k]);
  return out;
}

// False only when F (integer coefficients) certainly has no rational root: a root
// p/q in lowest terms has q | lc(F), so for a prime P not dividing lc(F), q is
// invertible mod P and p q^-1 is a root of F mod P. A prime with no root mod P
// excludes rational roots. (A random polynomial has a root mod P with probability
// about 1 - 1/e, so 24 primes leave about 1.5e-5 of irrational cases undetected,
// which then take the complete path.)
bool may_have_rational_root(const Poly<Rational> &F) {
  for (unsigned long P : kModularPrimes) {
    if (mpz_fdiv_ui(F.lc().get_num_mpz_t(), P) == 0) continue;
    std::vector<unsigned long> c;
    for (const Rational &x : F.c) c.push_back(mpz_fdiv_ui(x.get_num_mpz_t(), P));
    bool root = false;
    for (unsigned long x = 0; x < P && !root; ++x) {
      unsigned long v = 0;
      for (size_t i = c.size(); i-- > 0;) v = (v * x + c[i]) % P;
      root = v == 0;
    }
    if (!root) return false;
  }
  return true;
}

}  // namespace pccd::poly
