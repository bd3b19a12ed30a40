// Exact polynomial gcd over Q and related normal forms (Rational only: a gcd is not
// continuous in the coefficients, so there is no certified interval version).
#pragma once
#include "poly/poly.h"

namespace pccd::poly {

// Monic gcd; gcd(0, 0) = 0.
Poly<Rational> gcd(Poly<Rational> a, Poly<Rational> b);

// The square-free part f / gcd(f, f'), scaled to a primitive integer polynomial with a
// positive leading coefficient. f must be nonzero.
Poly<Rational> squarefree_primitive(const Poly<Rational> &f);

// Exact quotient a / b (b divides a).
Poly<Rational> exact_quotient(Poly<Rational> a, const Poly<Rational> &b);

}  // namespace pccd::poly
