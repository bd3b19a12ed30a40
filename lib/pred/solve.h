// The staged, exact primitive contact solver.
//
// Stages, cheapest first (pccd_stage): space-time bounds; Bernstein enclosure of the
// polynomial every contact is a root of; the whole algorithm in certified interval
// arithmetic; the whole algorithm in exact rationals. A stage either decides with
// certainty or hands over to the next (arith::Uncertain), so every answer is exact.
#pragma once
#include <functional>
#include <vector>

#include "arith/convert.h"
#include "pred/query_systems.h"

namespace pccd::pred {

// Which stage decided (the values of pccd_stage in polyccd.h; lib/api/constants.cpp
// checks that the two agree). STAGE_EXACT also when the interval stage enclosed the
// first time and the exact search for a rational one (poly/rational_root.h) had to run.
enum Stage : int { STAGE_NONE = 0, STAGE_BOUNDS = 1, STAGE_BERNSTEIN = 2, STAGE_INTERVAL = 3, STAGE_EXACT = 4 };

struct Solve_options {
  arith::Rational tol = arith::Rational(1, 1000000000000);  // 1e-12
  bool want_time = true;
  bool want_exact = true;
  // Only a first contact at a time <= until is wanted: a later one may be reported as
  // no contact. A contact that is reported is the same as with until = 1
  // (poly/earliest.h), so answers never depend on it. Body queries set it from the
  // best contact found so far.
  arith::Rational until = 1;
  // Minimum separation delta >= 0 (pccd_config.min_distance): a contact is a time when
  // the closed primitives are within distance delta (0: they touch). solve() applies
  // it to the query: ball radii grow by delta, point kinds get the systems of
  // pred/delta_systems.h. Set it with set_delta (below), never alone: the filters
  // read delta_box, which must enclose it.
  arith::Rational delta = 0;
  // delta enclosed in doubles, for the filters (delta_filter.h): set with delta, only
  // through set_delta.
  arith::Interval delta_box = 0.0;
  void set_delta(const arith::Rational &d) {
    delta = d;
    delta_box = arith::enclose(d);
  }
  // Run the interval search (build_systems on intervals, poly/earliest.h) before the
  // exact one. Off only where a caller predicts the interval search cannot decide
  // (solve_linear.cpp): then the exact search starts from [0, 1] instead of the
  // interval one's last state, with the same answer (the midpoint bisection's steps do
  // not depend on the stage taking them); only the stage reported may differ. Never
  // changes whether or when a contact is found.
  bool interval_search = true;
  // The one test of "a minimum distance is set" (config.min_distance > 0).
  bool min_distance() const { return sgn(delta) > 0; }
};

struct Contact_result {
  bool collides = false;
  arith::Rational lo, hi;  // lo <= t* <= hi when collides
  bool exact = false;      // lo == hi == t*
  std::vector<Feature> features;
  int stage = STAGE_NONE;  // Stage
};

// An unsolved, empty result, in place: no allocation when r held an answer before.
inline void reset(Contact_result &r) {
  r.collides = r.exact = false;
  r.lo = 0;
  r.hi = 0;
  r.features.clear();
  r.stage = STAGE_NONE;
}

// Features of a query whose first-touch polynomial is known to have no rational root
// (narrow/irrational_memo.h: a body pair's memo across its feature pairs). has(f): f's
// polynomial, or one with the same roots on [0, 1], was proven so before; add(f):
// record f, proven now. Asked only after the interval stage enclosed a first time
// whose features are all known: then the time is irrational (it is a root on [0, 1] of
// each), and its enclosure stands without the exact query (solve.cpp).
class Irrational_features {
 public:
  virtual ~Irrational_features() = default;
  virtual bool has(const Feature &f) const = 0;
  virtual void add(const Feature &f) = 0;
};

// exact_points builds the exact trajectories on demand (only when the interval stages
// cannot decide); interval.p must enclose them coefficient by coefficient. known: null,
// or the memo above for this query's features.
Contact_result solve(const Query_data<arith::Interval> &interval,
                     const std::function<Query_data<arith::Rational>()> &exact_points,
                     const Solve_options &opt, Irrational_features *known = nullptr);
// The same, taking over the interval query (with a minimum distance it is not copied).
Contact_result solve(Query_data<arith::Interval> &&interval,
                     const std::function<Query_data<arith::Rational>()> &exact_points,
                     const Solve_options &opt, Irrational_features *known = nullptr);

}  // namespace pccd::pred
