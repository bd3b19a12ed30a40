// Closed intervals of doubles with outward rounding, for certified filters.
//
// Contract: for every operation, the exact result of the operation applied to any
// values inside the operands lies inside the returned interval.
//
// Where the certainty comes from: an IEEE-754 operation in ANY rounding mode returns
// one of the two doubles that bracket the exact result (or +-inf / DBL_MAX on
// overflow). Stepping one ulp outward with nextafter therefore yields a valid bound
// whatever rounding mode the caller left active, so no mode switch is needed and the
// FP environment is never touched. NaN (inf - inf) makes every sign query uncertain.
//
// Exact points stay exact: when the thread's rounding mode is round-to-nearest
// (util/rounding.h: set once per C call, default: not assumed), a sum or product
// of two point intervals is checked with an error-free transformation (TwoSum, exact
// for round-to-nearest without overflow [Knuth, TAOCP 4.2.2]; the FMA residual
// a*b - p, exact when no underflow occurs [Boldo-Muller 2011], guarded by |p| >= 2^-960).
// A zero error makes the result an exact point, so structural zeros (coplanar input,
// t = 1/2 hitting a rational root) are certified without falling back to rationals;
// a nonzero error gives a one-ulp interval on the side it points to.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>

#include "arith/errors.h"
#include "util/rounding.h"

// The hot operations are always inlined: at -O2 GCC kept operator+ and operator* as
// calls in the robot filter's pose enclosures (motion/chain_path.cpp), about 9% of a
// free segment's samples (perf, issue 30). Inlining changes no result: every operation
// is still one IEEE operation in the same order (-ffp-contract=off, lib/flags.mk).
#if defined(__GNUC__)
#define PCCD_INTERVAL_INLINE inline __attribute__((always_inline))
#else
#define PCCD_INTERVAL_INLINE inline
#endif

namespace pccd::arith {

struct Interval {
  double lo = 0, hi = 0;
  Interval() = default;
  Interval(double x) : lo(x), hi(x) {}  // NOLINT: exact point (x must be finite)
  Interval(double l, double h) : lo(l), hi(h) {}
  bool is_point_zero() const { return lo == 0 && hi == 0; }
};

// One ulp up / down: std::nextafter(x, +-HUGE_VAL) without the library call (the hot
// path of every interval operation). Stepping the bit pattern by one moves a finite
// nonzero double one ulp away from / towards zero (IEEE-754 binary64 orders the
// magnitudes of same-signed doubles like their bit patterns); -inf steps to -DBL_MAX,
// +inf and NaN stay, +-0 steps to +-DBL_TRUE_MIN. Independent of the rounding mode.
PCCD_INTERVAL_INLINE double round_up(double x) {
  if (!(x < HUGE_VAL)) return x;  // +inf, NaN
  if (x == 0) return 0x1p-1074;
  uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  b = x > 0 ? b + 1 : b - 1;
  std::memcpy(&x, &b, sizeof b);
  return x;
}
PCCD_INTERVAL_INLINE double round_down(double x) { return -round_up(-x); }

// The midpoint m of [lo, hi] when it is a double, in any rounding mode; false otherwise.
// For the bisections of [0, 1]: lo and hi are consecutive multiples of w = hi - lo, a
// power of two (a computed width that is no power of two is refused; then hi - lo and
// w / 2 are exact). The true midpoint lo + w / 2 is a multiple of w / 2: if w / 2 is at
// least the spacing of the doubles there, it is a
// double and the sum is exact; otherwise lo and hi are adjacent doubles, and the sum
// rounds to one of them in every mode. So a sum strictly between them is the midpoint
// (widths under about 2^-53 near t = 1 have none).
inline bool exact_midpoint(double lo, double hi, double &m) {
  if (!(0 <= lo && lo < hi && hi <= 1)) return false;
  int e;
  if (std::frexp(hi - lo, &e) != 0.5) return false;  // not a power of two
  m = lo + (hi - lo) * 0.5;
  return lo < m && m < hi;
}

// Whether this thread computes in round-to-nearest: one scope per C call
// (util/rounding.h), carried to the pool's workers.
using util::nearest_mode;

// The point sum s = fl(a + b) with its exact rounding error (round-to-nearest only).
PCCD_INTERVAL_INLINE Interval point_sum(double a, double b) {
  double s = a + b;
  if (nearest_mode() && std::isfinite(s)) {
    double bb = s - a, aa = s - bb;  // TwoSum
    double err = (a - aa) + (b - bb);
    if (err == 0) return Interval(s);
    return err > 0 ? Interval(s, round_up(s)) : Interval(round_down(s), s);
  }
  return {round_down(s), round_up(s)};
}

PCCD_INTERVAL_INLINE Interval operator+(const Interval &a, const Interval &b) {
  if (a.is_point_zero()) return b;
  if (b.is_point_zero()) return a;
  if (a.lo == a.hi && b.lo == b.hi) return point_sum(a.lo, b.lo);
  return {round_down(a.lo + b.lo), round_up(a.hi + b.hi)};
}
PCCD_INTERVAL_INLINE Interval operator-(const Interval &a) { return {-a.hi, -a.lo}; }
PCCD_INTERVAL_INLINE Interval operator-(const Interval &a, const Interval &b) {
  if (b.is_point_zero()) return a;
  if (a.is_point_zero()) return -b;
  if (a.lo == a.hi && b.lo == b.hi) return point_sum(a.lo, -b.lo);
  return {round_down(a.lo - b.hi), round_up(a.hi - b.lo)};
}
PCCD_INTERVAL_INLINE Interval operator*(const Interval &a, const Interval &b) {
  if (a.is_point_zero() || b.is_point_zero()) return Interval(0.0);
  if (a.lo == a.hi && b.lo == b.hi && nearest_mode()) {
    double p = a.lo * b.lo;
    if (std::isfinite(p) && std::fabs(p) >= 0x1p-960) {
      double err = std::fma(a.lo, b.lo, -p);  // exact residual a*b - p
      if (err == 0) return Interval(p);
      return err > 0 ? Interval(p, round_up(p)) : Interval(round_down(p), p);
    }
  }
  double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
  if (std::isnan(p1) || std::isnan(p2) || std::isnan(p3) || std::isnan(p4))
    return {-HUGE_VAL, HUGE_VAL};
  // No NaN: plain comparisons (one instruction each; std::fmin is a libm call, and its
  // only other difference, the sign of a zero, is lost in round_down / round_up).
  auto mn = [](double x, double y) { return y < x ? y : x; };
  auto mx = [](double x, double y) { return x < y ? y : x; };
  return {round_down(mn(mn(p1, p2), mn(p3, p4))), round_up(mx(mx(p1, p2), mx(p3, p4)))};
}
// Division needs a divisor that certainly excludes zero; otherwise Uncertain.
inline Interval operator/(const Interval &a, const Interval &b) {
  if (!(b.lo > 0 || b.hi < 0)) throw Uncertain{};
  if (a.is_point_zero()) return Interval(0.0);
  if (a.lo == a.hi && b.lo == b.hi && nearest_mode()) {
    double q = a.lo / b.lo;
    if (std::isfinite(q) && std::fabs(q) >= 0x1p-960 && std::fabs(a.lo) >= 0x1p-900) {
      // The residual q*b - a of a round-to-nearest quotient is a double, so the FMA
      // computes it exactly; its sign over the divisor's tells the side of a/b.
      double r = std::fma(q, b.lo, -a.lo);
      if (r == 0) return Interval(q);
      bool above = (r > 0) == (b.lo > 0);  // q > a/b
      return above ? Interval(round_down(q), q) : Interval(q, round_up(q));
    }
  }
  double q1 = a.lo / b.lo, q2 = a.lo / b.hi, q3 = a.hi / b.lo, q4 = a.hi / b.hi;
  double lo = std::fmin(std::fmin(q1, q2), std::fmin(q3, q4));
  double hi = std::fmax(std::fmax(q1, q2), std::fmax(q3, q4));
  return {round_down(lo), round_up(hi)};
}
inline Interval &operator+=(Interval &a, const Interval &b) { return a = a + b; }
inline Interval &operator-=(Interval &a, const Interval &b) { return a = a - b; }
inline Interval &operator*=(Interval &a, const Interval &b) { return a = a * b; }

// Sign if certain; throws Uncertain otherwise (the filter failed).
inline int sign(const Interval &x) {
  if (x.lo > 0) return 1;
  if (x.hi < 0) return -1;
  if (x.is_point_zero()) return 0;
  throw Uncertain{};
}
// Non-throwing one-sided tests: true only when certain.
inline bool certainly_positive(const Interval &x) { return x.lo > 0; }
inline bool certainly_negative(const Interval &x) { return x.hi < 0; }
inline bool certainly_nonneg(const Interval &x) { return x.lo >= 0; }
inline bool certainly_nonpos(const Interval &x) { return x.hi <= 0; }
inline bool certainly_nonzero(const Interval &x) { return x.lo > 0 || x.hi < 0; }
// Exact zero test: true/false when certain, Uncertain otherwise.
inline bool is_zero(const Interval &x) { return sign(x) == 0; }

// Hull of two intervals.
inline Interval hull(const Interval &a, const Interval &b) {
  return {std::fmin(a.lo, b.lo), std::fmax(a.hi, b.hi)};
}

}  // namespace pccd::arith
