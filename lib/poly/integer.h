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

}  // namespace pccd::poly
