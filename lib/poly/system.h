// A contact condition of one feature pair, as a univariate semialgebraic system:
// the feature pair touches at time t exactly when t is in its contact set.
#pragma once
#include <vector>

#include "poly/count.h"

namespace pccd::poly {

template <class NT>
struct System {
  enum class Kind {
    roots,      // {t : f(t) = 0 and g_i(t) > 0 for all i}, f not identically zero
    zero_f,     // f is identically zero: {t : g_i(t) > 0 for all i}
    sublevel    // {t : f(t) <= 0} (closed balls); g unused
  };
  Kind kind = Kind::roots;
  Poly<NT> f;
  std::vector<Poly<NT>> g;
  int tag = 0;  // which feature pair this is (meaning defined by lib/pred)

  // t is in the contact set.
  bool contains(const NT &t) const {
    switch (kind) {
      case Kind::zero_f: return satisfies(Poly<NT>(), g, t);
      case Kind::sublevel: return arith::sign(f.eval(t)) <= 0;
      default: return satisfies(f, g, t);
    }
  }
  // t > 0 is a first-entry point candidate: a root of f meeting the conditions (for
  // sublevel: a root of f).
  bool hits(const NT &t) const {
    const std::vector<Poly<NT>> none;
    return satisfies(f, kind == Kind::sublevel ? none : g, t);
  }
  // The contact set meets (a, b]. Only for kind roots, and for sublevel when f(a) > 0
  // (then its first point after a is a root of f).
  bool meets(const NT &a, const NT &b) const {
    const std::vector<Poly<NT>> none;
    const std::vector<Poly<NT>> &conds = kind == Kind::sublevel ? none : g;
    return count_roots(f, conds, a, b) > 0 || satisfies(f, conds, b);
  }
  // Number of points of the contact set in the open (a, b) (roots kinds only).
  long count_open(const NT &a, const NT &b) const {
    const std::vector<Poly<NT>> none;
    return count_roots(f, kind == Kind::sublevel ? none : g, a, b);
  }
};

}  // namespace pccd::poly
