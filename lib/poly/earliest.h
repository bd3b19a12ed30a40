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
#include <algorithm>
#include <vector>

#include "poly/isolated_root.h"
#include "util/work_budget.h"
#include "poly/system.h"

namespace pccd::poly {

struct Earliest_options {
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

// The bisection always splits at the midpoint, so where it ends is a function of t*
// and tol alone: every stage (intervals, exact rationals, the isolated-root sign test,
// the linear fast path of lib/pred) that decides each step with certainty reaches the
// same enclosure, whatever the rounding mode or the order of stages. With intervals a
// midpoint that is no double (widths below about 2^-53, for tolerances that small) is
// Uncertain: the exact stage takes the bisection over from there.
template <class NT> NT midpoint(const NT &lo, const NT &hi);
template <> inline Rational midpoint(const Rational &lo, const Rational &hi) { return (lo + hi) / 2; }
template <> inline Interval midpoint(const Interval &lo, const Interval &hi) {
  double m;
  if (!arith::exact_midpoint(lo.lo, hi.lo, m)) throw arith::Uncertain{};
  return Interval(m);
}

// Where a bisection stands after its last certain step: lo < t* <= hi and `active`
// are the systems meeting (lo, hi]. A search stopped by arith::Uncertain leaves it in
// `progress`, and another search over the same systems (same order, exact numbers) can
// resume from it: the steps it would have taken from scratch are the same.
template <class NT>
struct Search_state {
  bool valid = false;
  NT lo, hi;
  std::vector<size_t> active;
};

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
                                   const Earliest_options &opt,
                                   Search_state<NT> *progress = nullptr,
                                   const Search_state<NT> *resume = nullptr) {
  using K = typename System<NT>::Kind;
  Search_result<NT> res;
  const NT zero = arith::from_int<NT>(0), one = arith::from_int<NT>(1);
  NT lo = zero, hi = one;
  std::vector<size_t> active;
  const bool bounded = opt.until < 1;
  if (resume && resume->valid) {
    lo = resume->lo;
    hi = resume->hi;
    active = resume->active;
  } else {
    for (size_t i = 0; i < sys.size(); ++i)
      if (sys[i].contains(zero)) res.which.push_back(i);
    if (!res.which.empty()) {
      res.found = res.exact = true;
      res.lo = res.hi = zero;
      return res;
    }
    for (size_t i = 0; i < sys.size(); ++i)
      if (sys[i].kind != K::zero_f && sys[i].meets(zero, one)) active.push_back(i);
    if (active.empty()) return res;
    if (!opt.want_time) {
      res.found = true;
      res.lo = zero;
      res.hi = one;
      res.which = active;
      return res;
    }
    if (bounded) {
      // No contact in (0, u] with u >= until: none that matters (cheap early answer).
      // Undecided in intervals (a root at or near u: the feature pairs tied with the
      // contact that set `until`, a robot's vertex-vertex approach within delta): the
      // bisection below decides, as with no early answer. That exception sent every
      // such pair to the exact stage from scratch, each of its systems built and
      // stripped in rationals (issue 33).
      const NT u = arith::from_rational_up<NT>(opt.until);
      bool any = false;
      for (size_t i : active) {
        try {
          any = sys[i].meets(zero, u);
        } catch (const arith::Uncertain &) {
          any = true;
        }
        if (any) break;
      }
      if (!any) return res;
    }
  }
  res.found = true;
  // Bisection at midpoints. A system whose first contact in (lo, hi] has become the only
  // root of its f there is stepped by one sign of f (poly/isolated_root.h), the others by
  // root counts; both give the same decisions.
  std::vector<Isolated_root<NT>> iso(sys.size());
  std::vector<char> isolated(sys.size(), 0);
  auto save = [&] {
    if (!progress) return;
    progress->valid = true;
    progress->lo = lo;
    progress->hi = hi;
    progress->active = active;
  };
  save();
  // t* = hi exactly: some system hits hi and none has a contact in the open (lo, hi)
  // (at_hi: those hitting hi). An isolated system's only candidate r is in (lo, hi]: it
  // hits hi exactly when f(hi) = 0 (r qualifies), and has a contact inside otherwise.
  // The hits are asked first (signs at one point); the root counts of the open interval
  // only when one system hits hi.
  auto exact_at_hi = [&](std::vector<size_t> &at_hi) {
    at_hi.clear();
    for (size_t i : active)
      if (isolated[i] ? iso[i].sign_at(hi) == 0 : sys[i].hits(hi)) at_hi.push_back(i);
    if (at_hi.empty()) return false;
    for (size_t i : active) {
      const bool hit = std::find(at_hi.begin(), at_hi.end(), i) != at_hi.end();
      if (isolated[i] ? !hit : sys[i].count_open(lo, hi) > 0) return false;
    }
    return true;
  };
  std::vector<size_t> at_hi;
  while (wider_than(lo, hi, opt.tol)) {
    util::work_step();  // one bisection step (util/work_budget.h)
    if (bounded && past(lo, opt.until)) return Search_result<NT>();  // first contact after `until`
    for (size_t i : active)
      if (!isolated[i] && sys[i].kind != K::zero_f) isolated[i] = iso[i].isolate(sys[i].f, lo, hi);
    const NT m = midpoint(lo, hi);
    std::vector<size_t> left;
    for (size_t i : active)
      if (isolated[i] ? iso[i].at_or_before(m) : sys[i].meets(lo, m)) left.push_back(i);
    if (left.empty()) {
      lo = m;
    } else {
      hi = m;
      active = std::move(left);
      // A contact exactly at the midpoint (a dyadic t*, e.g. 1/2) ends the search here:
      // the remaining steps would only move lo up to hi and then find the same exact
      // answer below (unless `until` < hi, where they return no contact: left to them).
      // An undecided sign in intervals only skips this shortcut.
      bool done = false;
      if (!bounded || !past(hi, opt.until)) {
        try {
          done = exact_at_hi(at_hi);
        } catch (const arith::Uncertain &) {
          done = false;
        }
      }
      if (done) {
        save();
        res.lo = res.hi = hi;
        res.exact = true;
        res.which = at_hi;
        return res;
      }
    }
    save();
  }
  // t* in (lo, hi], and exactly hi when exact_at_hi says so.
  res.lo = lo;
  res.hi = hi;
  res.which = active;
  try {
    if (exact_at_hi(at_hi)) {
      res.exact = true;
      res.lo = hi;
      res.which = at_hi;
    }
  } catch (const arith::Uncertain &) {
    // [lo, hi] stays a valid enclosure; exactness is left undecided
  }
  return res;
}

}  // namespace pccd::poly
