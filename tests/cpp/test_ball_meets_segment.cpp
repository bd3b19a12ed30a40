// pred::ball_meets_segment and segments_within (lib/pred/static_contact.h, issue 33):
//  - in rationals ball_meets_segment(c, r2d2, a, b) is ball_meets_triangle(c, r2d2,
//    {a, b, b}), the test it replaced, on random cases and on built ones at exactly the
//    radius (an end on the sphere, the open segment tangent to it, the projection at an
//    end), degenerate segments (a = b) included;
//  - with intervals of nonzero width around the same points (the enclosures a robot's
//    poses give) it decides the cases away from the boundary, which the degenerate
//    triangle never did (b - b straddles zero), and agrees with the exact answer
//    whenever it decides; segments_within likewise against its rational answer.
// Prints "N passed, N failed".
#include <cstdio>
#include <random>
#include <string>

#include "arith/convert.h"
#include "expect.h"
#include "pred/static_contact.h"

using namespace pccd;
using arith::Interval;
using arith::Rational;
using pred::Vec3;

static Vec3<Rational> q3(const double *x) { return {Rational(x[0]), Rational(x[1]), Rational(x[2])}; }
// An enclosure of width about 2 w around each coordinate (never a point interval).
static Vec3<Interval> i3(const double *x, double w) {
  Vec3<Interval> v;
  for (int i = 0; i < 3; ++i) v[i] = Interval(x[i] - w - 1e-300, x[i] + w + 1e-300);
  return v;
}

// Returns 1 / 0 for a decided interval test, -1 when it threw Uncertain.
template <class F>
static int decided(F f) {
  try {
    return f() ? 1 : 0;
  } catch (const arith::Uncertain &) {
    return -1;
  }
}

int main() {
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> u(-1, 1);
  long interval_decided = 0, interval_cases = 0;
  for (int k = 0; k < 4000; ++k) {
    double c[3], a[3], b[3], p[3], q[3];
    for (double *x : {c, a, b, p, q})
      for (int i = 0; i < 3; ++i) x[i] = u(rng);
    if (k % 10 == 0)
      for (int i = 0; i < 3; ++i) b[i] = a[i];  // degenerate segment
    const double r = 0.05 + 0.5 * (u(rng) + 1);
    const Rational r2(Rational(r) * Rational(r));
    const Vec3<Rational> C = q3(c), A = q3(a), B = q3(b), P = q3(p), Q = q3(q);
    const bool exact = pred::ball_meets_segment(C, r2, A, B);
    expect(exact == pred::ball_meets_triangle(C, r2, {{A, B, B}}), "rational: as the degenerate triangle");
    const bool within = pred::segments_within(P, Q, A, B, r2);
    // Intervals 1e-12 wide: the robot filter's pose enclosures are of that order.
    const Interval ri(r);
    const Interval r2i = ri * ri;
    const int got = decided([&] { return pred::ball_meets_segment(i3(c, 1e-12), r2i, i3(a, 1e-12), i3(b, 1e-12)); });
    ++interval_cases;
    if (got >= 0) {
      ++interval_decided;
      expect((got == 1) == exact, "interval ball_meets_segment agrees with rationals (case " + std::to_string(k) + ")");
    }
    const int gw = decided([&] {
      return pred::segments_within(i3(p, 1e-12), i3(q, 1e-12), i3(a, 1e-12), i3(b, 1e-12), r2i);
    });
    if (gw >= 0) expect((gw == 1) == within, "interval segments_within agrees with rationals");
    if (k % 10 != 0) expect(gw >= 0, "interval segments_within decides a proper random case");
  }
  // Every proper random case is far from the boundary at this width (a few degenerate
  // ones stay undecided: the direction of a zero-length segment is no certain sign).
  expect(interval_decided >= interval_cases * 9 / 10, "intervals decide nearly every random case");

  // Built cases on the boundary, exact: the segment from (-1, 0, 0) to (1, 0, 0).
  const double a[3] = {-1, 0, 0}, b[3] = {1, 0, 0};
  const Vec3<Rational> A = q3(a), B = q3(b);
  struct Case {
    double c[3];
    double r;
    bool meets;
    const char *what;
  } cases[] = {
      {{0, 0.5, 0}, 0.5, true, "tangent to the open segment"},
      {{0, 0.5, 0}, 0.4999999999999999, false, "just short of the open segment"},
      {{2, 0, 0}, 1, true, "an end on the sphere"},
      {{2, 0, 0}, 0.9999999999999999, false, "just short of an end"},
      {{1, 0.25, 0}, 0.25, true, "projection exactly at an end"},
      {{-1.5, 0, 0.5}, 0.5, false, "beyond an end, near the line"},
  };
  for (const Case &cs : cases) {
    const Rational r2 = Rational(cs.r) * Rational(cs.r);
    const Vec3<Rational> C = q3(cs.c);
    expect(pred::ball_meets_segment(C, r2, A, B) == cs.meets, cs.what);
    expect(pred::ball_meets_triangle(C, r2, {{A, B, B}}) == cs.meets, std::string(cs.what) + " (triangle)");
    expect(pred::ball_meets_segment(C, r2, A, A) == pred::ball_meets_triangle(C, r2, {{A, A, A}}),
           std::string(cs.what) + " (a = b)");
  }
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed != 0;
}
