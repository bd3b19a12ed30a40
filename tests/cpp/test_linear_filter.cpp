// pred::linear_verdict (linear_filter and its crossing half, lib/pred/solve_linear.h)
// and its Bernstein enclosures (lib/pred/linear_filter.h) against
// exact rational arithmetic (GMP, independent of the filter's floating point):
//  - every certified coefficient: |value - exact| <= bound, whenever ok;
//  - every verdict: boxes_apart only when the exact closed boxes are disjoint, no_root
//    only when the exact Bernstein coefficients of the kind's polynomial have one strict
//    sign (so that polynomial has no root in [0, 1]);
// on random, nearly degenerate (coplanar / collinear up to an ulp), huge (2^290), tiny
// (2^-290), mixed-scale, subnormal and small-integer (touching, tied) inputs, under every rounding mode (the bound must
// hold in all of them). Prints "N passed, N failed"; exit status 0 only when none failed.
#include <fenv.h>
#include <gmpxx.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "pred/features.h"
#include "pred/solve_linear.h"

using pccd::pred::Linear_verdict;

static long g_pass, g_fail;
static void expect(bool ok, const char *what, int round) {
  if (ok) {
    ++g_pass;
  } else if (++g_fail <= 20) {
    std::printf("FAIL: %s (case %d)\n", what, round);
  }
}

static mpq_class q(double x) {
  mpq_class r;
  mpq_set_d(r.get_mpq_t(), x);
  return r;
}

using Q3 = std::array<mpq_class, 3>;
static Q3 qsub(const double *a, const double *b) { return {q(a[0]) - q(b[0]), q(a[1]) - q(b[1]), q(a[2]) - q(b[2])}; }
static mpq_class det(const Q3 &a, const Q3 &b, const Q3 &c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}
static mpq_class cross_k(int k, const Q3 &a, const Q3 &b) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  return a[i] * b[j] - a[j] * b[i];
}

// The exact coefficients (middle ones times 3 / times 2, as the filter's).
static std::array<mpq_class, 4> exact_cubic(const double *const O[2], const double *const A[2],
                                            const double *const B[2], const double *const C[2]) {
  Q3 a[2], b[2], c[2];
  for (int s = 0; s < 2; ++s) {
    a[s] = qsub(A[s], O[s]);
    b[s] = qsub(B[s], O[s]);
    c[s] = qsub(C[s], O[s]);
  }
  return {det(a[0], b[0], c[0]), det(a[1], b[0], c[0]) + det(a[0], b[1], c[0]) + det(a[0], b[0], c[1]),
          det(a[1], b[1], c[0]) + det(a[1], b[0], c[1]) + det(a[0], b[1], c[1]), det(a[1], b[1], c[1])};
}
static std::array<mpq_class, 3> exact_cross(int k, const double *const O[2], const double *const A[2],
                                            const double *const B[2]) {
  Q3 a[2], b[2];
  for (int s = 0; s < 2; ++s) {
    a[s] = qsub(A[s], O[s]);
    b[s] = qsub(B[s], O[s]);
  }
  return {cross_k(k, a[0], b[0]), cross_k(k, a[1], b[0]) + cross_k(k, a[0], b[1]), cross_k(k, a[1], b[1])};
}

template <size_t N>
static bool one_sign(const std::array<mpq_class, N> &v) {
  bool pos = true, neg = true;
  for (const auto &x : v) {
    pos = pos && sgn(x) > 0;
    neg = neg && sgn(x) < 0;
  }
  return pos || neg;
}

template <class R, size_t N>
static void check_enclosure(const R &r, const std::array<mpq_class, N> &ex, int round, long &rounded) {
  if (!r.ok) return;
  for (size_t k = 0; k < N; ++k) {
    const mpq_class err = abs(q(r.value[k]) - ex[k]);
    if (err != 0) ++rounded;
    expect(std::isfinite(r.bound[k]) && err <= q(r.bound[k]), "|value - exact| <= bound", round);
  }
}

static bool exact_boxes_apart(int n, int split, const double *p0, const double *p1) {
  for (int a = 0; a < 3; ++a) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < n; ++i)
      for (const double *p : {p0, p1}) {
        const int s = i < split ? 0 : 1;
        lo[s] = std::fmin(lo[s], p[3 * i + a]);
        hi[s] = std::fmax(hi[s], p[3 * i + a]);
      }
    if (hi[0] < lo[1] || hi[1] < lo[0]) return true;
  }
  return false;
}

// One query of `kind`: the verdict against exact facts, and the enclosures.
static void check_query(int kind, const double *p0, const double *p1, int round, long &rounded,
                        long verdicts[4]) {
  auto pt = [&](int i) { return std::array<const double *, 2>{p0 + 3 * i, p1 + 3 * i}; };
  pccd::pred::Cubic_bernstein f;
  const Linear_verdict v = pccd::pred::linear_verdict(kind, p0, p1, f);
  ++verdicts[static_cast<int>(v)];
  const int n = kind == pccd::pred::VERTEX_FACE || kind == pccd::pred::EDGE_EDGE ? 4
                : kind == pccd::pred::VERTEX_EDGE                                 ? 3
                                                                                  : 2;
  const int split = kind == pccd::pred::EDGE_EDGE ? 2 : 1;
  if (v == Linear_verdict::boxes_apart) expect(exact_boxes_apart(n, split, p0, p1), "boxes apart", round);
  if (kind == pccd::pred::VERTEX_FACE || kind == pccd::pred::EDGE_EDGE) {
    const auto o = kind == pccd::pred::VERTEX_FACE ? pt(1) : pt(0);
    const auto a = kind == pccd::pred::VERTEX_FACE ? pt(2) : pt(1);
    const auto b = kind == pccd::pred::VERTEX_FACE ? pt(3) : pt(2);
    const auto c = kind == pccd::pred::VERTEX_FACE ? pt(0) : pt(3);
    const auto ex = exact_cubic(o.data(), a.data(), b.data(), c.data());
    check_enclosure(pccd::pred::cubic_bernstein(o.data(), a.data(), b.data(), c.data()), ex, round, rounded);
    if (v == Linear_verdict::no_root) expect(one_sign(ex), "cubic without root", round);
    if (v == Linear_verdict::misses) {  // the Descartes part of the certificate, exactly
      int changes = 0;
      bool zero = false;
      for (int k = 0; k < 4; ++k) {
        zero = zero || sgn(ex[k]) == 0;
        if (k > 0 && sgn(ex[k]) != sgn(ex[k - 1])) ++changes;
      }
      expect(!zero && changes == 1, "misses: one simple root in (0, 1)", round);
    }
  } else if (kind == pccd::pred::VERTEX_EDGE) {
    bool some = false;
    for (int k = 0; k < 3; ++k) {
      const auto ex = exact_cross(k, pt(1).data(), pt(2).data(), pt(0).data());
      check_enclosure(pccd::pred::cross_bernstein(k, pt(1).data(), pt(2).data(), pt(0).data()), ex, round,
                      rounded);
      some = some || one_sign(ex);
    }
    if (v == Linear_verdict::no_root) expect(some, "cross component without root", round);
  } else if (v == Linear_verdict::no_root) {
    bool some = false;
    for (int k = 0; k < 3; ++k) {
      const mpq_class d0 = q(p0[k]) - q(p0[3 + k]), d1 = q(p1[k]) - q(p1[3 + k]);
      some = some || (sgn(d0) * sgn(d1) > 0);
    }
    expect(some, "coordinate difference without root", round);
  }
}

int main() {
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> unit(-1, 1);
  const int kinds[4] = {pccd::pred::VERTEX_FACE, pccd::pred::EDGE_EDGE, pccd::pred::VERTEX_EDGE,
                        pccd::pred::VERTEX_VERTEX};
  const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
  long rounded = 0, verdicts[4] = {0, 0, 0, 0};
  int round = 0;
  for (int family = 0; family < 10; ++family) {
    for (int rep = 0; rep < 3000; ++rep, ++round) {
      double p0[12], p1[12];
      // Scales: 1, huge, tiny, mixed, near the filter's range limits, subnormal.
      const int e = family == 1 ? 290 : family == 2 ? -290 : family == 6 ? 299 : family == 7 ? -1060 : 0;
      for (int i = 0; i < 12; ++i) {
        const int ei = family == 3 ? static_cast<int>(rng() % 121) - 60 : e;
        p0[i] = std::ldexp(unit(rng), ei);
        p1[i] = p0[i] + std::ldexp(unit(rng), ei - static_cast<int>(rng() % 8));
      }
      if (family == 8)  // small integers: touching boxes, equal coordinates, exact zeros
        for (int i = 0; i < 12; ++i) {
          p0[i] = static_cast<double>(static_cast<int>(rng() % 3) - 1);
          p1[i] = static_cast<double>(static_cast<int>(rng() % 3) - 1);
        }
      if (family == 9) {
        // A crossing near miss (the "misses" verdict): a triangle (points 1-3) near the
        // plane z = 0 and a vertex (point 0) crossing it at a time tc just outside the
        // edge x = 0, by a relative margin 2^-3 to 2^-43; every point moves linearly.
        const double size = std::ldexp(1.0, -static_cast<int>(rng() % 7));
        const double tc = 0.05 + 0.9 * (unit(rng) + 1) / 2;
        const double at_tc[12] = {-size * std::ldexp(1.0, -3 - static_cast<int>(rng() % 41)), size * 0.3, 0,
                                  0, 0, 0, 0, size, 0, size, 0, 0};
        for (int i = 0; i < 4; ++i) {
          const double speed = size * std::ldexp(1.0, -2 - static_cast<int>(rng() % 8));
          for (int a = 0; a < 3; ++a) {
            double vel = speed * unit(rng);
            if (a == 2) vel = i == 0 ? -speed * (1.5 + unit(rng)) : 0.1 * vel;
            p0[3 * i + a] = at_tc[3 * i + a] - tc * vel;
            p1[3 * i + a] = at_tc[3 * i + a] + (1 - tc) * vel;
          }
        }
      }
      if (family == 4 || family == 5) {
        // Nearly degenerate: the last point made coplanar with (collinear to) the others
        // at both times, then moved by an ulp or so on one coordinate.
        for (double *p : {p0, p1}) {
          const double s = unit(rng), t = unit(rng);
          for (int a = 0; a < 3; ++a)
            p[9 + a] = p[a] + s * (p[3 + a] - p[a]) + (family == 4 ? t * (p[6 + a] - p[a]) : 0.0);
          const int k = 9 + static_cast<int>(rng() % 3);
          p[k] = std::nextafter(p[k], rng() % 2 ? 1e300 : -1e300);
          if (family == 5)
            for (int a = 0; a < 3; ++a) p[6 + a] = p[a] + s * (p[3 + a] - p[a]);  // v on line e0 e1
        }
      }
      if (rep % 5 == 0)  // a collision-like query: both primitives near the origin, crossing
        for (int i = 0; i < 3; ++i) std::swap(p0[i], p1[i]);
      fesetround(modes[rep % 4]);
      for (int kind : kinds) check_query(kind, p0, p1, round, rounded, verdicts);
      fesetround(FE_TONEAREST);
    }
  }
  std::printf("verdicts: %ld unknown, %ld boxes apart, %ld no root, %ld misses; %ld coefficients rounded\n",
              verdicts[0], verdicts[1], verdicts[2], verdicts[3], rounded);
  // The enclosures must be tested where rounding happens, or they prove nothing.
  expect(rounded > 10000, "enough coefficients carried rounding errors", -1);
  expect(verdicts[3] > 1000 && verdicts[2] > 1000 && verdicts[0] > 1000 && verdicts[1] > 1000,
         "every verdict occurred", -1);
  std::printf("%ld passed, %ld failed\n", g_pass, g_fail);
  return g_fail == 0 ? 0 : 1;
}
