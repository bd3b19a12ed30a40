// arith::round_up / round_down (bit-pattern ulp steps, lib/arith/interval.h) against
// std::nextafter, the reference they replace: special values, every binade boundary,
// and random bit patterns, in all four rounding modes. Prints "N passed, N failed".
#include <cfenv>
#include <cfloat>
#include <cstdio>
#include <cstring>
#include <random>

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

int main() {
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
