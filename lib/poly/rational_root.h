// Is the first contact time rational? (exact arithmetic only)
//
// Given exact systems and an enclosure lo < t* <= hi of their earliest contact,
// decides whether t* is rational and returns it. For a system whose first contact in
// (lo, hi) is a root r of f: let F be the primitive square-free integer part of f and
// L = |lc(F)|. If r = p/q in lowest terms then q | L (rational root theorem), so L r
// is an integer. Isolate r as the only root of F in an interval narrower than 1/L:
// that interval holds at most one multiple of 1/L, the only rational candidate. When f
// has opposite nonzero signs at lo and hi and f' one sign on [lo, hi], r is a simple
// root alone there and f made primitive serves as F (the theorem holds for any integer
// polynomial), with no gcd of f and f'; and f(hi) != 0 places the contact inside
// (lo, hi) without counting (rational_root.cpp).
#pragma once
#include <optional>
#include <vector>

#include "poly/system.h"

namespace pccd::poly {

struct Rational_root_result {
  bool exact = false;
  Rational t;                 // t* when exact
  std::vector<size_t> which;  // the systems whose contact set holds t* (when exact)
};

// False only when the integer polynomial F (Rational coefficients with denominator 1)
// certainly has no rational root (a root modulo small primes is missing); true means
// "may have one". Cheap: a few modular evaluations.
bool may_have_rational_root(const Poly<Rational> &F);

// The primes that test uses, in its order (a fast path reproducing it uses the same).
constexpr unsigned long kModularPrimes[] = {11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53,
                                            59, 61, 67, 71, 73, 79, 83, 89, 97, 101, 103, 107};

// active: the systems with a contact in (lo, hi]; none of them hits lo.
Rational_root_result rational_first_contact(const std::vector<System<Rational>> &sys,
                                            const std::vector<size_t> &active,
                                            Rational lo, Rational hi);

}  // namespace pccd::poly
