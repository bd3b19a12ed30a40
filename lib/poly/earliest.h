// The earliest time in [0, 1] at which any of several feature systems is in contact,
// enclosed by bisection on exact (or certified) root counts.
//
// Contract: given systems whose contact sets C_k have a closed union C, returns
// whether C is empty and, if not, lo <= min C <= hi with hi - lo <= tol, and the
// systems whose contact sets meet [lo, hi]. Systems of kind zero_f contribute only
// t = 0: when f is identically zero, inf C_k is either 0 (then 0 is in C) or a
// point of C outside C_k, i.e. a contact of another, lower-dimensional feature pair,
// which lib/pred always includes (see lib/pred/features.h).
#pragma once
#include <vector>

#include "poly/system.h"

namespace pccd::poly {

struct Search_options {
  Rational tol = Rational(1, 1000000000000);  // 1e-12
  bool want_time = true;
  // Only contacts at times <= until matter: the search may answer "none" when the first
  // contact is later. When it does find one, the answer (enclosure, exactness, systems)
  // is exactly the one of until = 1: the bisection still runs on [0, 1] and only stops
  // early once its lower end passes `until` (so results never depend on until).
  Rational until = 1;
};

// lo is certainly beyond `until`.
inline bool past(const Rational &lo, const Rational &until) { return lo > until; }
inline bool past(const Interval &lo, const Rational &until) {
  return arith::enclose(until).hi < lo.lo;
}

template <class NT>
struct Search_result {
  bool found = false;
  NT lo, hi;                  // lo <= t* <= hi
  bool exact = false;         // t* == hi == lo
  std::vector<size_t> which;  // indices of the systems touching within [lo, hi]
};

// Split points inside (lo, hi) tried in order; with intervals a step may be uncertain
// at one point (a root too close to it) and certain at another.
template <class NT> std::vector<NT> split_points(const NT &lo, const NT &hi);
template <> inline std::vector<Rational> split_points(const Rational &lo, const Rational &hi) {
  return {(lo + hi) / 2};
}
template <> inline std::vector<Interval> split_points(const Interval &lo, const Interval &hi) {
  std::vector<Interval> out;
  const double w = hi.lo - lo.lo;
  for (double f : {0.5, 0.4375, 0.5625, 0.375, 0.625}) {
    double m = lo.lo + w * f;  // any double strictly inside is a valid split point
    if (m > lo.lo && m < hi.lo) out.push_back(Interval(m));
  }
  return out;
}

template <class NT> bool wider_than(const NT &lo, const NT &hi, const Rational &tol);
template <> inline bool wider_than(const Rational &lo, const Rational &hi, const Rational &tol) {
  return hi - lo > tol;
}
template <> inline bool wider_than(const Interval &lo, const Interval &hi, const Rational &tol) {
  Interval w = hi - lo;
  return !(w.hi <= arith::enclose(tol).lo);  // stops only when certainly <= tol
}

template <class NT>
Search_result<NT> earliest_contact(const std::vector<System<NT>> &sys,
                                   const Search_options &opt) {
  using K = typename System<NT>::Kind;
  Search_result<NT> res;
  const NT zero = arith::from_int<NT>(0), one = arith::from_int<NT>(1);
  for (size_t i = 0; i < sys.size(); ++i)
    if (sys[i].contains(zero)) res.which.push_back(i);
  if (!res.which.empty()) {
    res.found = res.exact = true;
    res.lo = res.hi = zero;
    return res;
  }
  std::vector<size_t> active;
  for (size_t i = 0; i < sys.size(); ++i)
    if (sys[i].kind != K::zero_f && sys[i].meets(zero, one)) active.push_back(i);
  if (active.empty()) return res;
  res.found = true;
  res.lo = zero;
  res.hi = one;
  if (!opt.want_time) {
    res.which = active;
    return res;
  }
  NT lo = zero, hi = one;
  const bool bounded = opt.until < 1;
  if (bounded) {
    // No contact in (0, u] with u >= until: none that matters (cheap early answer).
    const NT u = arith::from_rational_up<NT>(opt.until);
    bool any = false;
    for (size_t i : active)
      if (sys[i].meets(zero, u)) {
        any = true;
        break;
      }
    if (!any) {
      res = Search_result<NT>();
      return res;
    }
  }
  {
    while (wider_than(lo, hi, opt.tol)) {
      if (bounded && past(lo, opt.until)) {
        res = Search_result<NT>();  // the first contact is after `until`
        return res;
      }
      bool stepped = false;
      for (const NT &m : split_points(lo, hi)) {
        try {
          std::vector<size_t> left;
          for (size_t i : active)
            if (sys[i].meets(lo, m)) left.push_back(i);
          if (left.empty()) {
            lo = m;
          } else {
            hi = m;
            active = std::move(left);
          }
          stepped = true;
          break;
        } catch (const arith::Uncertain &) {
          // try the next split point
        }
      }
      if (!stepped) throw arith::Uncertain{};
    }
  }
  // t* in (lo, hi]. It is exactly hi when some system hits hi and none has a contact
  // in the open (lo, hi).
  res.lo = lo;
  res.hi = hi;
  res.which = active;
  std::vector<size_t> at_hi, inside;
  try {
    for (size_t i : active) {
      if (sys[i].hits(hi)) at_hi.push_back(i);
      if (sys[i].count_open(lo, hi) > 0) inside.push_back(i);
    }
  } catch (const arith::Uncertain &) {
    return res;  // [lo, hi] stays a valid enclosure; exactness is left undecided
  }
  if (!at_hi.empty() && inside.empty()) {
    res.exact = true;
    res.lo = hi;
    res.which = at_hi;
  }
  return res;
}

}  // namespace pccd::poly
