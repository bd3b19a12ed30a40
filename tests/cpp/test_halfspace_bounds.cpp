// broad::upper_bound / lower_bound (lib/broad/halfspaces.h: plain doubles plus a derived
// error bound) against the exact extremes of a . x + a0 over interval coefficients and
// an interval box, computed in GMP rationals. Near-cancelling sums, wide magnitude
// ranges and all four rounding modes. Also checks the bound is not vacuous (tight to
// about 1e-12 relative on well-conditioned sums). Prints "N passed, N failed".
#include <gmpxx.h>

#include <cfenv>
#include <cmath>
#include <cstdio>
#include <random>

#include "broad/halfspaces.h"

using pccd::arith::Interval;
using pccd::broad::Halfspace;

constexpr int D = 12;
static long passed = 0, failed = 0;

static mpq_class q(double x) { return mpq_class(x); }

// Exact max (upper) or min of a . x + a0: each term's extreme is at a corner.
static mpq_class extreme(const Halfspace<D> &h, const Interval *x, bool upper) {
  mpq_class s = q(upper ? h.a0.hi : h.a0.lo);
  for (int k = 0; k < D; ++k) {
    const mpq_class c[4] = {q(h.a[k].lo) * q(x[k].lo), q(h.a[k].lo) * q(x[k].hi),
                            q(h.a[k].hi) * q(x[k].lo), q(h.a[k].hi) * q(x[k].hi)};
    mpq_class e = c[0];
    for (int i = 1; i < 4; ++i)
      if (upper ? c[i] > e : c[i] < e) e = c[i];
    s += e;
  }
  return s;
}

static void expect(bool ok, const char *what, int i) {
  if (ok) ++passed;
  else if (++failed <= 10) std::printf("FAIL case %d: %s\n", i, what);
}

int main() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> ex(-300, 300);
  const int modes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
  long tight = 0, tight_total = 0;
  for (int i = 0; i < 40000; ++i) {
    std::fesetround(modes[i % 4]);
    const int scale = i % 3 == 0 ? ex(rng) : 0;  // wide magnitudes in a third of the cases
    Halfspace<D> h;
    Interval x[D];
    for (int k = 0; k < D; ++k) {
      const double a = std::ldexp(u(rng), scale), w = i % 2 ? 0.0 : std::fabs(u(rng)) * 1e-9;
      h.a[k] = Interval(a - std::fabs(a) * w, a + std::fabs(a) * w);
      const double c = std::ldexp(u(rng), -scale / 2), r = i % 5 ? std::fabs(u(rng)) * 1e-3 : 0.0;
      x[k] = Interval(c - r, c + r);
    }
    // a0 cancels the rest (sums near zero are where rounding decides the sign).
    const mpq_class mid = (extreme(h, x, true) + extreme(h, x, false)) / 2;
    const double a0 = -mid.get_d();
    h.a0 = Interval(a0);
    const mpq_class hi = extreme(h, x, true), lo = extreme(h, x, false);
    const double ub = pccd::broad::upper_bound(h, x), lb = pccd::broad::lower_bound(h, x);
    expect(q(ub) >= hi, "upper_bound below the exact maximum", i);
    expect(q(lb) <= lo, "lower_bound above the exact minimum", i);
    if (scale == 0 && i % 5) {  // well-conditioned boxes: the margin is small
      ++tight_total;
      mpq_class slack = q(ub) - hi, width = hi - lo;
      if (slack <= width * mpq_class(1, 1000000) + mpq_class(1e-12)) ++tight;
    }
  }
  std::fesetround(FE_TONEAREST);
  expect(tight * 10 >= tight_total * 9, "upper_bound not tight on well-conditioned sums", -1);
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed ? 1 : 0;
}
