// A system's first contact isolated as the only root of f, refined by signs.
//
// Contract: once f's Bernstein coefficients on [lo, hi] have nonzero ends of certain
// sign and exactly one sign variation, f has exactly one root r in (lo, hi), a simple
// one (Descartes' rule in the Bernstein basis: the number of roots in the open interval,
// with multiplicity, is at most the number of variations and has its parity), and none
// at lo or hi. If the system's contact set meets (lo, hi], that contact is r, the only
// candidate. Then for any m in (lo, hi):
//     the system meets (lo, m]  <=>  r <= m  <=>  sign f(m) != sign f(lo)
// (0 included: f(m) = 0 means m = r). One evaluation of f replaces a root count, and
// the decisions are the same as System::meets', so the bisection of poly/earliest.h takes
// the same steps either way. The interval shrinks around r in the bisection, so r stays
// the only root in it, and sign f(lo) never changes (lo only moves to points below r).
//
// Exact path: f is kept as a positive integer multiple (same signs), evaluated at the
// bisection's dyadic points k / 2^j as the integer sum of c_i k^i 2^(j (n - i)), so GMP
// never reduces a fraction (poly::scaled_value).
#pragma once
#include <type_traits>

#include "poly/bernstein.h"
#include "poly/integer.h"

namespace pccd::poly {

template <class NT>
class Isolated_root {
 public:
  // True when the test above holds for f on [lo, hi]; then sign_lo() is sign f(lo).
  bool isolate(const Poly<NT> &f, const NT &lo, const NT &hi) {
    if (f.degree() < 1) return false;
    std::vector<NT> b;
    try {
      b = bernstein_coefficients(f, lo, hi);
      int v = 0, last = 0;
      for (const NT &x : b) {
        const int s = arith::sign(x);  // Uncertain with intervals: not isolated (yet)
        if (s == 0) {
          if (&x == &b.front() || &x == &b.back()) return false;
          continue;
        }
        if (last != 0 && s != last) ++v;
        last = s;
      }
      if (v != 1) return false;
      sign_lo_ = arith::sign(b.front());
    } catch (const arith::Uncertain &) {
      return false;
    }
    if constexpr (std::is_same<NT, Rational>::value) f_ = primitive_positive(f); else f_ = f;
    return true;
  }

  int sign_lo() const { return sign_lo_; }

  // r <= m for m in (lo, hi) of the isolating interval or any later one.
  bool at_or_before(const NT &m) const {
    const int s = sign_at(m);
    return s == 0 || s != sign_lo_;
  }

  // sign f(t); throws arith::Uncertain when an interval cannot tell.
  int sign_at(const NT &t) const {
    if constexpr (std::is_same<NT, Rational>::value) return poly::sign_at(f_, t);
    else return arith::sign(f_.eval(t));
  }

 private:
  Poly<NT> f_;
  int sign_lo_ = 0;
};

}  // namespace pccd::poly
