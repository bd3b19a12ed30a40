// arith::round_up / round_down (bit-pattern ulp steps, lib/arith/interval.h) against
// std::nextafter, the reference they replace: special values, every binade boundary,
// and random bit patterns, in all four rounding modes; and arith::exact_midpoint, the
// bisections' midpoint, against exact dyadic arithmetic. Prints "N passed, N failed".
#include <cfenv>
#include <cmath>
#include <cfloat>
#include <cstdio>
#include <cstring>
#include <random>
#include <utility>

#include "arith/interval.h"

using pccd::arith::round_down;
using pccd::arith::round_up;

static long passed = 0, failed = 0;

static bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0 || (a != a && b != b); }

static void check(double x) {
  const double up = std::nextafter(x, HUGE_VAL), down = std::nextafter(x, -HUGE_VAL);
  if (same(round_up(x), up) && same(round_down(x), down)) {
    ++passed;
  } else {
    if (++failed <= 10) std::printf("FAIL x = %a: up %a (want %a), down %a (want %a)\n", x, round_up(x), up, round_down(x), down);
  }
}

// Every dyadic piece [j 2^-k, (j + 1) 2^-k] of the bisection of [0, 1] near t = 0, 1/3,
// 1/2 and 1: exact_midpoint must give the true midpoint exactly when it is a double
// (2j + 1 fits the spacing at hi) and refuse otherwise (it never rounds to lo or hi).
static void check_midpoints() {
  using pccd::arith::exact_midpoint;
  for (int k = 1; k <= 80; ++k)
    for (double t : {0.0, 1.0 / 3, 0.5, 0.75, 1.0 - 0x1p-40}) {
      const double w = std::ldexp(1.0, -k);
      const double lo = std::floor(t / w) * w, hi = lo + w;  // exact: multiples of w
      if (hi > 1 || hi - lo != w) continue;  // w below the spacing at lo: no such piece
      // The true midpoint lo + w / 2 is a double exactly when the sum rounds the same
      // upward and downward.
      volatile double vlo = lo, vhalf = w * 0.5;  // volatile: one sum per mode, not one CSE
      std::fesetround(FE_UPWARD);
      const double up = vlo + vhalf;
      std::fesetround(FE_DOWNWARD);
      const double down = vlo + vhalf;
      std::fesetround(FE_TONEAREST);
      const bool representable = up == down;
      double m = -1;
      const bool ok = exact_midpoint(lo, hi, m);
      if (ok == representable && (!ok || (m == up && lo < m && m < hi))) {
        ++passed;
      } else {
        if (++failed <= 10) std::printf("FAIL midpoint of [%a, %a]: %d %a (representable %d)\n", lo, hi, ok, m, representable);
      }
    }
  double m;
  for (auto bad : {std::pair<double, double>{0.0, 0.75}, {0.25, 0.25}, {-0.5, 0.0}, {0.5, 1.5}}) {
    if (!exact_midpoint(bad.first, bad.second, m)) ++passed;
    else if (++failed <= 10) std::printf("FAIL midpoint of [%a, %a] accepted\n", bad.first, bad.second);
  }
}

int main() {
  check_midpoints();
  const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
  std::mt19937_64 rng(20261123);
  for (int mode : modes) {
    std::fesetround(mode);
    const double special[] = {0.0, -0.0, 0x1p-1074, -0x1p-1074, DBL_MIN, -DBL_MIN, DBL_MAX, -DBL_MAX,
                              HUGE_VAL, -HUGE_VAL, NAN, 1.0, -1.0, 0x1.fffffffffffffp-1023};
    for (double x : special) check(x);
    for (int e = -1074; e <= 1023; ++e)
      for (double s : {1.0, -1.0}) {
        const double x = s * std::ldexp(1.0, e);
        check(x);
        check(std::nextafter(x, 0.0));
      }
    for (int i = 0; i < 200000; ++i) {
      const uint64_t bits = rng();
      double x;
      std::memcpy(&x, &bits, sizeof x);
      check(x);
    }
  }
  std::fesetround(FE_TONEAREST);
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed ? 1 : 0;
}
