// Integer normal forms for the exact path. Root counts under sign conditions do not
// change when f or a g_i is multiplied by a positive constant, so the exact path keeps
// every polynomial primitive with integer coefficients (Rational values with
// denominator 1): GMP then never has to canonicalize large fractions.
#pragma once
#include "poly/poly.h"

namespace pccd::poly {

// c * p with c > 0 chosen so the result has coprime integer coefficients.
Poly<Rational> primitive_positive(const Poly<Rational> &p);

// The same, and also multiplied by -1 if needed for a positive leading coefficient
// (for an f whose roots, not signs, matter).
Poly<Rational> primitive_monic_sign(const Poly<Rational> &p);

// c * (a mod b) with c > 0, for integer a and b with lc(b) > 0: pseudo-division
// multiplying by lc(b) (positive) at each step, then made primitive.
Poly<Rational> prem_positive(Poly<Rational> a, const Poly<Rational> &b);

// The value of F (integer coefficients, degree n >= 0) at t = p / q (q > 0) scaled to an
// integer: q^n F(t) = sum c_i p^i q^(n - i), by Horner on the homogenized polynomial.
// GMP never reduces a fraction on the way (the rational Horner scheme canonicalizes
// at every step, a gcd of numbers as long as the result). For dyadic t = k / 2^j the
// powers of q are shifts. Same sign as F(t).
arith::Integer scaled_value(const Poly<Rational> &F, const Rational &t);

// sign F(t) for F with integer coefficients (scaled_value's sign).
inline int sign_at(const Poly<Rational> &F, const Rational &t) { return sgn(scaled_value(F, t)); }

}  // namespace pccd::poly
