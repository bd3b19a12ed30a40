// enclose::boxes_within (lib/enclose/enclose.h, issue 33) against the exact Euclidean
// distance of the two boxes in GMP rationals: it may keep a pair a few ulps farther than
// r (its slack), but never drops one at distance <= r. Cases: gaps on one, two and three
// axes at exactly r, r (1 -+ 2^-40), the diagonal gap a per axis with 3 a^2 just above
// r^2 (kept by grow + boxes_meet, dropped here), overlapping and infinite boxes, r = 0
// (boxes_meet exactly), and random boxes in all four rounding modes. Prints "N passed,
// N failed".
#include <gmpxx.h>

#include <cfenv>
#include <cmath>
#include <cstdio>
#include <random>

#include "enclose/enclose.h"

using pccd::enclose::Box;
using pccd::enclose::boxes_within;

static long passed = 0, failed = 0;

static void expect(bool ok, const char *what, double r) {
  if (ok) {
    ++passed;
  } else if (++failed <= 10) {
    std::printf("FAIL %s (r = %a)\n", what, r);
  }
}

// The squared Euclidean distance of the boxes, exact.
static mpq_class dist2(const Box &a, const Box &b) {
  mpq_class s = 0;
  for (int i = 0; i < 3; ++i) {
    mpq_class g = 0, lo_b = b.lo[i], hi_a = a.hi[i], lo_a = a.lo[i], hi_b = b.hi[i];
    if (lo_b - hi_a > g) g = lo_b - hi_a;
    if (lo_a - hi_b > g) g = lo_a - hi_b;
    s += g * g;
  }
  return s;
}

static Box unit_at(double x, double y, double z) {  // [x, x + 1] x [y, y + 1] x [z, z + 1]
  return Box{{x, y, z}, {x + 1, y + 1, z + 1}};
}

// Within r exactly: must be kept. Farther than r by more than the slack: must be dropped.
static void exact_case(const Box &a, const Box &b, double r, const char *what) {
  const mpq_class d2 = dist2(a, b), r2 = mpq_class(r) * mpq_class(r);
  const bool kept = boxes_within(a, b, r);
  if (d2 <= r2) expect(kept, what, r);
  else if (d2 > r2 * mpq_class(1 + 0x1p-40)) expect(!kept, what, r);
  else ++passed;  // in the slack: either answer is sound
}

int main() {
  const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
  for (int mode : modes) {
    std::fesetround(mode);
    for (double r : {0.05, 1.0 / 3, 1e-9, 0x1p-20, 3.0}) {
      const double lo = r * (1 - 0x1p-40), hi = r * (1 + 0x1p-40);
      for (double g : {r, lo, hi}) {  // one axis: the box distance is the gap
        exact_case(unit_at(0, 0, 0), unit_at(1 + g, 0, 0), r, "one axis");
        exact_case(unit_at(0, 0, 0), unit_at(0, 0, -1 - g), r, "one axis, below");
      }
      // Diagonal: a per axis with a < r but sqrt(3) a > r (grow + boxes_meet keeps it).
      const double a = r * 0.6;
      exact_case(unit_at(0, 0, 0), unit_at(1 + a, 1 + a, 1 + a), r, "diagonal");
      expect(!boxes_within(unit_at(0, 0, 0), unit_at(1 + a, 1 + a, 1 + a), r), "diagonal dropped", r);
      expect(pccd::enclose::boxes_meet(pccd::enclose::grow(unit_at(0, 0, 0), r), unit_at(1 + a, 1 + a, 1 + a)),
             "diagonal met by grown boxes", r);
      // Two axes at exactly 3 r / 5 and 4 r / 5: distance r (a double when r is dyadic).
      exact_case(unit_at(0, 0, 0), unit_at(1 + 0.6 * r, 1 + 0.8 * r, 0), r, "3-4-5");
      expect(boxes_within(unit_at(0, 0, 0), unit_at(0.5, 0.5, 0.5), r), "overlap", r);
      const double inf = HUGE_VAL;
      expect(boxes_within(Box{{-inf, -inf, -inf}, {inf, inf, inf}}, unit_at(1e300, 0, 0), r), "infinite", r);
      expect(boxes_within(unit_at(0, 0, 0), unit_at(1e300, 0, 0), inf), "r infinite", r);
    }
    // r = 0: boxes_meet exactly (touching boxes kept, a one-ulp gap dropped).
    expect(boxes_within(unit_at(0, 0, 0), unit_at(1, 0, 0), 0), "r = 0 touching", 0);
    expect(!boxes_within(unit_at(0, 0, 0), unit_at(std::nextafter(1.0, 2.0), 0, 0), 0), "r = 0 apart", 0);
    std::mt19937_64 rng(3300 + mode);
    std::uniform_real_distribution<double> u(-2, 2), w(0, 1), rr(0, 0.5);
    for (int k = 0; k < 20000; ++k) {
      Box a, b;
      for (int i = 0; i < 3; ++i) {
        a.lo[i] = u(rng);
        a.hi[i] = a.lo[i] + w(rng);
        b.lo[i] = u(rng);
        b.hi[i] = b.lo[i] + w(rng);
      }
      exact_case(a, b, rr(rng), "random");
    }
  }
  std::fesetround(FE_TONEAREST);
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
