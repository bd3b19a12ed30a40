// Conjunctions of clauses of closed halfspaces over lifted points (the query side of the
// range structure, broad/range_tree.h; what is lifted: broad/LINEARIZATION.md).
//
// A halfspace is  a . s + a0 >= 0  for a lifted point s in R^D, with interval
// coefficients a, a0 (they enclose the exact coefficients of the query). A clause is a
// disjunction of halfspaces; a query (Cnf) is a conjunction of clauses. Every test
// answers "possibly": true unless the interval evaluation proves the inequality false
// for every coefficient and every point in the (interval) argument. So a stored
// primitive that satisfies the exact condition is never filtered out, touching (= 0)
// included: the halfspaces are closed.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "arith/interval.h"

namespace pccd::broad {

using arith::Interval;

template <int D>
struct Halfspace {
  std::array<Interval, D> a;
  Interval a0;
};

template <int D>
struct Cnf {
  std::vector<Halfspace<D>> hs;
  std::vector<uint32_t> clause_end;  // clause c is hs[clause_end[c-1] .. clause_end[c])

  void end_clause() { clause_end.push_back(static_cast<uint32_t>(hs.size())); }
  bool empty() const { return clause_end.empty(); }
};

// An enclosure of a . x + a0 over the intervals x (outward rounded).
template <int D>
Interval evaluate(const Halfspace<D> &h, const Interval *x) {
  Interval s = h.a0;
  for (int k = 0; k < D; ++k) s = s + h.a[k] * x[k];
  return s;
}

// Whether some point of the interval box x may satisfy every clause (a necessary test:
// each clause separately has a halfspace that meets the box).
template <int D>
bool cnf_possible(const Cnf<D> &q, const Interval *x) {
  uint32_t start = 0;
  for (uint32_t end : q.clause_end) {
    bool any = false;
    for (uint32_t i = start; i < end && !any; ++i) any = evaluate(q.hs[i], x).hi >= 0;
    if (!any) return false;
    start = end;
  }
  return true;
}

// Whether every point of the box certainly satisfies every clause (then a whole subtree
// is reported without testing its points; only a shortcut, reporting more is safe).
template <int D>
bool cnf_certain(const Cnf<D> &q, const Interval *x) {
  uint32_t start = 0;
  for (uint32_t end : q.clause_end) {
    bool any = false;
    for (uint32_t i = start; i < end && !any; ++i) any = evaluate(q.hs[i], x).lo >= 0;
    if (!any) return false;
    start = end;
  }
  return true;
}

}  // namespace pccd::broad
