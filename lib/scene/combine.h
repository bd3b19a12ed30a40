// The first contact of a set of solved primitive pairs: exact when it is rational.
//
// Each solved pair i that collides has lo_i <= t_i <= hi_i, hi_i - lo_i <= tol, and is
// exact when t_i is rational (pred/solve.h with want_exact; then lo_i = hi_i = t_i).
// So a pair that is not exact has an irrational t_i in the open (lo_i, hi_i).
// The minimum t* = min t_i lies in [min lo, min hi] (width <= tol: the pair owning
// min lo has hi - lo <= tol). It is the rational E = min exact t_i exactly when no
// inexact pair can be below E: every inexact pair with lo_i < E < hi_i is re-solved
// with a finer tolerance until its enclosure falls on one side of E (t_i != E since
// t_i is irrational, so this ends). Without want_exact an inexact t_i may be rational;
// refinement then stops after a bounded number of rounds and the enclosure is reported.
#pragma once
#include <functional>
#include <vector>

#include "pred/solve.h"

namespace pccd::scene {

struct First_contact {
  bool collides = false;
  arith::Rational lo, hi;
  bool exact = false;
  std::vector<size_t> which;  // the results touching first (exact) or possibly first
};

// results[i] may be replaced by refine(i, E): a finer re-solve of the same pair, which
// may also answer "no contact up to E" (then t_i > E, and the pair drops out).
First_contact first_contact(
    std::vector<const pred::Contact_result *> results,
    const std::function<const pred::Contact_result *(size_t, const arith::Rational &)> &refine);

}  // namespace pccd::scene
