// range::upper_bound / lower_bound (lib/range/halfspaces.h: plain doubles plus a derived
// error bound) against the exact extremes of a . x + a0 over interval coefficients and
// an interval box, computed in GMP rationals. Near-cancelling sums, wide magnitude
// ranges and all four rounding modes. Also checks the bound is not vacuous (tight to
// about 1e-12 relative on well-conditioned sums). Then range::Quadratic clauses (the
// exact rotation linearization's root conditions) against the exact answer computed
// independently: the extremes of the quadratic on [0, 1] (ends and vertex) in GMP.
// Prints "N passed, N failed".
#include <gmpxx.h>

#include <cfenv>
#include <cmath>
#include <cstdio>
#include <random>

#include "range/halfspaces.h"

using pccd::arith::Interval;
using pccd::range::Halfspace;

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

// Exact min and max over s in [0, 1] of b0 (1 - s)^2 + 2 b1 s (1 - s) + b2 s^2, from the
// power form c0 + c1 s + c2 s^2 (the ends and, if inside, the vertex -c1 / (2 c2)).
static void exact_range(const mpq_class *b, mpq_class &mn, mpq_class &mx) {
  const mpq_class c0 = b[0], c1 = 2 * (b[1] - b[0]), c2 = b[0] - 2 * b[1] + b[2];
  auto at = [&](const mpq_class &s) { return mpq_class(c0 + c1 * s + c2 * s * s); };
  mn = mx = at(0);
  auto take = [&](const mpq_class &v) {
    if (v < mn) mn = v;
    if (v > mx) mx = v;
  };
  take(at(1));
  if (sgn(c2) != 0) {
    const mpq_class v = -c1 / (2 * c2);
    if (v >= 0 && v <= 1) take(at(v));
  }
}

// Quadratics k (s - r)^2 + e (double roots when e = 0, near misses and near double roots
// otherwise) and random ones, as clauses over a 1-D point or box: "may" must hold
// whenever the exact condition holds at the point (at some sampled point of a box),
// "certainly" only when it holds at every sampled point.
static void check_quadratics(std::mt19937_64 &rng) {
  using pccd::range::Quadratic;
  std::uniform_int_distribution<int> ri(-16, 80), ki(-8, 8), ei(-3, 3), coin(0, 3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 20000; ++i) {
    double b[3];
    if (coin(rng)) {
      const double r = ri(rng) / 64.0, k = ki(rng), e = ei(rng) * std::ldexp(1.0, -40 + 10 * (i % 4));
      b[0] = k * r * r + e;
      b[1] = k * r * (r - 1) + e;
      b[2] = k * (1 - r) * (1 - r) + e;
    } else {
      for (double &x : b) x = u(rng);
    }
    // b_j = g_j x + b_j with the point x = 0 (exact), or slopes g_j on the box [-w, w].
    const bool box = i % 2;
    const double w = box ? std::ldexp(1.0, -30 - (i % 7) * 3) : 0.0;
    Quadratic<1> qc;
    qc.kind = i % 3 ? Quadratic<1>::Root : Quadratic<1>::Nonpositive;
    double g[3];
    for (int j = 0; j < 3; ++j) {
      g[j] = box ? u(rng) : 0.0;
      qc.f[j].a[0] = Interval(g[j]);
      qc.f[j].a0 = Interval(b[j]);
    }
    const Interval x(-w, w);
    bool any = false, all = true;
    for (int p = 0; p <= (box ? 8 : 0); ++p) {
      const mpq_class xp = box ? q(-w) + q(w) * mpq_class(p, 4) : mpq_class(0);
      mpq_class e[3], mn, mx;
      for (int j = 0; j < 3; ++j) e[j] = q(g[j]) * xp + q(b[j]);
      exact_range(e, mn, mx);
      const bool holds = qc.kind == Quadratic<1>::Root ? (mn <= 0 && mx >= 0) : mn <= 0;
      any = any || holds;
      all = all && holds;
    }
    const bool may = pccd::range::quadratic_test(qc, &x, false);
    const bool certain = pccd::range::quadratic_test(qc, &x, true);
    expect(!any || may, "Quadratic: the condition holds but the clause says it cannot", i);
    expect(!certain || all, "Quadratic: 'certainly' where the condition fails", i);
    if (!box) expect(may == any, "Quadratic: not exact on a point", i);
  }
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
    const double ub = pccd::range::upper_bound(h, x), lb = pccd::range::lower_bound(h, x);
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
  check_quadratics(rng);
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed ? 1 : 0;
}
