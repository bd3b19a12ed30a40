#include "poly/rational_root.h"

#include <algorithm>
#include <cmath>

#include "arith/errors.h"
#include "arith/convert.h"
#include "poly/bernstein.h"
#include "poly/gcd.h"
#include "poly/integer.h"
#include "util/work_budget.h"

namespace pccd::poly {
namespace {

struct Candidate {
  bool rational = false;
  Rational r;                 // when rational
  Poly<Rational> F;           // otherwise: the only root of F in (a, b)
  Rational a, b;
};

// |F(t)| scaled by the positive factor q_a^n q_b^n / q_t^n... that is: for the two
// ends of an interval, |F(a)| : |F(b)| = |v_a| q_b^n : |v_b| q_a^n with v = q^n F
// (poly::scaled_value), all integers.
arith::Integer cross_scaled(const arith::Integer &v, const Rational &other, int n) {
  arith::Integer qn;
  mpz_pow_ui(qn.get_mpz_t(), other.get_den_mpz_t(), static_cast<unsigned long>(n));
  return abs(v) * qn;
}

// Refines an interval (a, b) holding exactly one root r of F, a simple one, with
// F(a), F(b) nonzero (so of opposite signs), by quadratic interval refinement
// (J. Abbott, "Quadratic interval refinement for real roots", 2006): split (a, b) into
// N = 2^k equal pieces, guess the piece holding r from the secant through (a, F(a)) and
// (b, F(b)), and test the guess by the exact signs of F at the piece's ends. A right
// guess makes the piece the new interval and squares N (near a simple root the secant's
// error shrinks quadratically, so the bits gained per step double); a wrong one still
// keeps the side of the piece that holds r and halves k. Each step at least halves the
// width, so it is never slower than bisection, and it needs about log log (1 / width)
// steps instead of log (1 / width) once the secant is accurate. Every decision is an
// exact sign, so the result does not depend on the doubles that make the guesses.
class Refiner {
 public:
  Refiner(const Poly<Rational> &F, Rational a, Rational b)
      : F_(F), a_(std::move(a)), b_(std::move(b)) {
    va_ = scaled_value(F_, a_);
    vb_ = scaled_value(F_, b_);
    sa_ = sgn(va_);
    if (sa_ == 0 || sgn(vb_) == 0 || sgn(vb_) == sa_)
      throw arith::Internal_error("Refiner: F must have opposite nonzero signs at a and b");
  }
  const Rational &a() const { return a_; }
  const Rational &b() const { return b_; }

  // One step; true when an evaluation point is the root itself (then *root is it and the
  // interval is left as it was).
  bool step(Rational *root) {
    util::work_step();
    // The secant meets zero at a + lambda (b - a), lambda = |F(a)| / (|F(a)| + |F(b)|);
    // the guess is piece j = floor(lambda N), computed in integers (doubles would cap
    // the guesses at 53 bits, and the refinement at linear speed beyond them).
    const int n = F_.degree();
    const arith::Integer A = cross_scaled(va_, b_, n), B = cross_scaled(vb_, a_, n);
    const arith::Integer pieces = arith::Integer(1) << k_;
    arith::Integer j = A << k_;
    mpz_fdiv_q(j.get_mpz_t(), j.get_mpz_t(), arith::Integer(A + B).get_mpz_t());
    if (j >= pieces) j = pieces - 1;
    const Rational w = (b_ - a_) / Rational(pieces);
    Rational left = a_ + Rational(j) * w, right = left + w;
    arith::Integer vl = sgn(j) == 0 ? va_ : scaled_value(F_, left);
    arith::Integer vr = j + 1 == pieces ? vb_ : scaled_value(F_, right);
    if (sgn(vl) == 0 || sgn(vr) == 0) {
      *root = sgn(vl) == 0 ? left : right;
      return true;
    }
    if (sgn(vl) == sa_ && sgn(vr) != sa_) {  // the guess holds r
      a_ = std::move(left), va_ = std::move(vl);
      b_ = std::move(right), vb_ = std::move(vr);
      k_ = std::min<unsigned long>(2 * k_, kMaxLog2Pieces);
      return false;
    }
    if (sgn(vl) != sa_) b_ = std::move(left), vb_ = std::move(vl);  // r < left
    else a_ = std::move(right), va_ = std::move(vr);                 // r > right
    k_ = std::max<unsigned long>(k_ / 2, 1);
    return false;
  }

 private:
  // N never needs more bits than the interval's end points will get; 2^20 pieces per
  // step is far beyond the million bits a step could then gain.
  static constexpr unsigned long kMaxLog2Pieces = 1ul << 20;
  const Poly<Rational> &F_;
  Rational a_, b_;
  arith::Integer va_, vb_;
  int sa_ = 0;
  unsigned long k_ = 2;  // N = 2^k pieces
};

// F (integer coefficients) has exactly one root in (a, b), a simple one, shown without
// its square-free part: nonzero values of opposite signs at a and b, and F' of one
// strict sign on [a, b] (F strictly monotone there), in intervals first, then in
// rationals (Bernstein).
bool simple_root_alone(const Poly<Rational> &f, const Rational &a, const Rational &b) {
  if (f.degree() < 1) return false;
  const int sa = sign_at(f, a), sb = sign_at(f, b);
  if (sa == 0 || sb == 0 || sa == sb) return false;
  const Poly<Rational> d = derivative(f);
  Poly<arith::Interval> di;
  for (const Rational &x : d.c) di.c.push_back(arith::enclose(x));
  return certainly_no_root(di, arith::enclose(a), arith::enclose(b)) || certainly_no_root(d, a, b);
}

// The first contact of system s in (lo, hi) (s has one there and does not hit hi
// earlier than its interior contacts). F0: primitive_positive(s.f).
Candidate first_root(const System<Rational> &s, const Poly<Rational> &F0, Rational a, Rational b) {
  Candidate c;
  // f's only root in (a, b) is then that contact: F = f made primitive isolates it as
  // step 1 below would, and serves the rationality test as its square-free part does (the
  // rational root theorem and the refinement hold for any integer F with one simple
  // root there). The gcd of f and f' behind the square-free part was nearly all of a
  // Panda segment's 880 ms with min_distance 0.05 (a hand vertex against a box face on a
  // window of 2^-14: one feature pair in this stage; issue 33).
  const bool simple = simple_root_alone(F0, a, b);
  c.F = simple ? F0 : squarefree_primitive(s.f);
  const std::vector<Poly<Rational>> none;
  // 1. Shrink until (a, b) holds only the first contact, as the only root of F, with
  //    F nonzero at both ends (so it does already when simple).
  while (!simple && !(count_roots(c.F, none, a, b) == 1 && sign_at(c.F, a) != 0 && sign_at(c.F, b) != 0)) {
    util::work_step();
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
  Refiner ref(c.F, a, b);
  while ((ref.b() - ref.a()) * L >= 1) {
    if (ref.step(&c.r)) {
      c.rational = true;
      return c;
    }
  }
  a = ref.a();
  b = ref.b();
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
    const bool zero = s.kind == System<Rational>::Kind::zero_f;
    const Poly<Rational> F0 = zero ? s.f : primitive_positive(s.f);  // integers, f's roots
    // f(hi) != 0: the contact is not hi itself (a contact of kind roots has f = 0 there;
    // one of kind sublevel with f(hi) < 0 is preceded by f <= 0 inside, f(lo) > 0 as
    // none hits lo), so it is inside, and count_open's Sturm count (the square-free
    // part: a gcd of f and f') need not say so.
    if (!zero && sign_at(F0, hi) != 0) {
      cands[k] = first_root(s, F0, lo, hi);
    } else if (s.count_open(lo, hi) == 0) {  // its contact in (lo, hi] is hi itself
      cands[k].rational = true;
      cands[k].r = hi;
    } else {
      cands[k] = first_root(s, F0, lo, hi);
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
    Rational unused;  // F has no rational root in (a, b): no step lands on it
    Refiner ref(c.F, c.a, c.b);
    while (!(ref.b() < best || ref.a() > best))
      if (ref.step(&unused)) throw arith::Internal_error("rational_first_contact: a rational root of F");
    if (ref.b() < best) return out;
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
