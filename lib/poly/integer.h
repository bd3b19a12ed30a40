// Integer normal forms for the exact path. Root counts under sign conditions do not
// change when f or a g_i is multiplied by a positive constant, so the exact path keeps
// every polynomial primitive with integer coefficients (Rational values with
// denominator 1): GMP then never has to canonicalize large fractions.
#pragma once
#include "poly/poly.h"

namespace pccd::poly {

// c * p with c > 0 chosen so the result has coprime integer coefficients.
// (By value: pass a temporary to have it reduced in place.)
Poly<Rational> primitive_positive(Poly<Rational> p);

// The same, and also multiplied by -1 if needed for a positive leading coefficient
// (for an f whose roots, not signs, matter).
Poly<Rational> primitive_monic_sign(Poly<Rational> p);

// c * (a mod b) with c > 0, for integer a and b with lc(b) > 0: pseudo-division
// multiplying by lc(b) (positive) at each step, then made primitive.
Poly<Rational> prem_positive(Poly<Rational> a, const Poly<Rational> &b);

// f divided by w as many times as w divides it exactly, times a positive constant (the
// result is primitive with integer coefficients; f itself when w does not divide it).
// For w > 0 on [0, 1] (a motion's denominator W = |r|^2) the result has the roots and
// signs of f on [0, 1], at a lower degree: the narrow phase multiplies a static side by
// the moving side's W, so its systems carry powers of W (pred/solve.cpp). A division
// that fails stops at the first leading coefficient lc(w) does not divide (Gauss: a
// divisor w with integer coefficients, primitive, leaves an integer quotient), so a
// trial costs little when w is not a factor.
Poly<Rational> divide_out_positive(const Poly<Rational> &f, const Poly<Rational> &w);
// The same for each of ws in turn (f itself, unchanged, when ws is empty).
Poly<Rational> divide_out_positive(Poly<Rational> f, const std::vector<Poly<Rational>> &ws);

// The value of F (integer coefficients, degree n >= 0) at t = p / q (q > 0) scaled to an
// integer: q^n F(t) = sum c_i p^i q^(n - i), by Horner on the homogenized polynomial.
// GMP never reduces a fraction on the way (the rational Horner scheme canonicalizes
// at every step, a gcd of numbers as long as the result). For dyadic t = k / 2^j the
// powers of q are shifts. Same sign as F(t).
arith::Integer scaled_value(const Poly<Rational> &F, const Rational &t);

// sign F(t) for F with integer coefficients (scaled_value's sign).
inline int sign_at(const Poly<Rational> &F, const Rational &t) { return sgn(scaled_value(F, t)); }

}  // namespace pccd::poly
