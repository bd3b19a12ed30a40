#include "arith/convert.h"

#include <cfloat>
#include <cmath>

namespace pccd::arith {

Interval enclose(const Rational &q) {
  double d = mpq_get_d(q.get_mpq_t());  // truncated toward zero: |d| <= |q|
  if (!std::isfinite(d))  // beyond DBL_MAX in magnitude
    return sgn(q) > 0 ? Interval(DBL_MAX, HUGE_VAL) : Interval(-HUGE_VAL, -DBL_MAX);
  Rational back;
  {
    mpq_set_d(back.get_mpq_t(), d);
    if (back == q) return Interval(d);
  }
  // q lies strictly between d and its neighbour away from zero (or beyond DBL_MAX).
  if (sgn(q) > 0) return {d, round_up(d)};
  return {round_down(d), d};
}

}  // namespace pccd::arith
