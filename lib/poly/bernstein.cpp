#include "poly/bernstein.h"

#include <cmath>

namespace pccd::poly {

Interval range_on_unit(const Poly<Interval> &p) {
  if (p.c.empty()) return Interval(0.0);
  std::vector<Interval> bc = bernstein_coefficients(p, Interval(0.0), Interval(1.0));
  Interval r = bc[0];
  for (const Interval &x : bc) r = arith::hull(r, x);
  return r;
}

}  // namespace pccd::poly
