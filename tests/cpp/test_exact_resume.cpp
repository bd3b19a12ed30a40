// The exact stage resumed from the interval search's last state builds only the systems
// that state holds active (lib/pred/solve.cpp; poly/earliest.h: a resumed bisection looks
// at no other). Checked on minimum-distance queries built so the answer is known, where
// the interval search cannot finish: a vertex passing a triangle's corner at distance r
// at t = 1/2, with delta = 1/8 (the ball-vertex system then touches first; r = delta is
// a double root at 1/2, r = delta (1 +- 2^-k) roots at or near it). Each configuration
// is turned by a rational rotation and moved, in exact rationals, so that the interval
// enclosures are not points. Required: collides exactly when r <= delta, the time 1/2
// exact when r = delta and the enclosure at or before 1/2 otherwise, and the same answer
// (collides, enclosure, exactness, features) without the interval search (every system
// built in rationals, the bisection from [0, 1]); and that some queries did resume (the
// exact stage reported with the interval search on). The same with `until` just past 1/2,
// where the early answer of poly/earliest.h cannot tell in intervals.
// Prints "N passed, N failed"; exit status 0 only when none failed.
#include <cstdio>
#include <vector>

#include "arith/convert.h"
#include "pred/solve.h"
#include "expect.h"

using namespace pccd;
using arith::Interval;
using arith::Rational;
using pred::Contact_result;
using pred::Solve_options;

// A check of case k (expect.h's counter).
static void expect(bool ok, const char *what, int k) { expect(ok, std::string(what) + " (case " + std::to_string(k) + ")"); }

using Vec = std::array<Rational, 3>;
using Traj = std::array<poly::Poly<Rational>, 3>;  // x(t) per axis

static bool same(const Contact_result &a, const Contact_result &b) {
  return a.collides == b.collides && (!a.collides || (a.lo == b.lo && a.hi == b.hi && a.exact == b.exact &&
                                                      a.features == b.features));
}

// R v for the rotation of the Pythagorean triple (p, q, h) about z, then (P, Q, H) about x.
static Vec turn(const Vec &v, const int *t) {
  const Rational c(t[0], t[2]), s(t[1], t[2]), c2(t[3], t[5]), s2(t[4], t[5]);
  const Vec a{c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]};
  return {a[0], c2 * a[1] - s2 * a[2], s2 * a[1] + c2 * a[2]};
}

static Contact_result solve(const std::vector<Traj> &p, const Solve_options &opt) {
  pred::Query_data<Interval> iq;
  iq.kind = pred::VERTEX_FACE;
  for (const Traj &x : p) {
    motion::Point_traj<Interval> y;
    for (int a = 0; a < 3; ++a) y[a] = poly::convert<Interval>(x[a]);
    iq.p.push_back(y);
  }
  auto exact = [&] {
    pred::Query_data<Rational> eq;
    eq.kind = pred::VERTEX_FACE;
    for (const Traj &x : p) eq.p.push_back({x[0], x[1], x[2]});
    return eq;
  };
  return pred::solve(iq, exact, opt);
}

int main() {
  const Rational delta(1, 8), half(1, 2);
  const int turns[3][6] = {{3, 4, 5, 5, 12, 13}, {8, 15, 17, 7, 24, 25}, {20, 21, 29, 12, 35, 37}};
  const Vec moves[2] = {{Rational(1, 3), Rational(-2, 7), Rational(5, 11)}, {Rational(0), Rational(0), Rational(0)}};
  int k = 0, resumed = 0;
  for (int e : {0, 1, -1, 2, -2}) {
    for (int bits : {20, 40, 60}) {
      if (e == 0 && bits != 20) continue;
      // r = delta (1 + e 2^-bits)
      Rational r = delta;
      if (e != 0) r += delta * Rational(e) / Rational(mpz_class(1) << bits);
      for (const auto &t : turns)
        for (const Vec &o : moves) {
          ++k;
          // The corner a = (0, 0, 0) of the triangle a, (1, 0, 0), (0, 1, 0); the vertex at
          // (-3r/5, -4r/5, t - 1/2): its nearest point of the triangle is a, at distance
          // sqrt(r^2 + (t - 1/2)^2).
          auto place = [&](const Vec &at, const Vec &vel) {
            const Vec a = turn(at, t), b = turn(vel, t);
            Traj x;
            for (int i = 0; i < 3; ++i) x[i] = poly::Poly<Rational>(std::vector<Rational>{a[i] + o[i], b[i]});
            return x;
          };
          const Rational z(0), one(1);
          const std::vector<Traj> p = {place({-r * Rational(3, 5), -r * Rational(4, 5), -half}, {z, z, one}),
                                       place({z, z, z}, {z, z, z}), place({one, z, z}, {z, z, z}),
                                       place({z, one, z}, {z, z, z})};
          for (bool want_time : {true, false}) {
            Solve_options opt;
            opt.want_time = want_time;
            opt.set_delta(delta);
            const Contact_result with = solve(p, opt);
            Solve_options scratch = opt;
            scratch.interval_search = false;
            const Contact_result without = solve(p, scratch);
            expect(with.collides == (r <= delta), "collides exactly when r <= delta", k);
            expect(same(with, without), "the same answer without the interval search", k);
            if (want_time && with.collides) {
              expect(with.lo <= half, "first time at or before 1/2", k);
              if (r == delta) expect(with.exact && with.lo == half, "r = delta: exactly 1/2", k);
            }
            resumed += with.stage == pred::STAGE_EXACT;
            if (!want_time) continue;
            // Contacts up to `until` alone, until just past 1/2 (a feature pair tied with
            // the one that set it: poly/earliest.h's early answer cannot tell in
            // intervals): a contact reported is the one of until = 1, with and without
            // the interval search.
            Solve_options bounded = opt;
            bounded.until = half + Rational(1, 1) / Rational(mpz_class(1) << 45);
            const Contact_result b_with = solve(p, bounded);
            Solve_options b_scratch = bounded;
            b_scratch.interval_search = false;
            expect(same(b_with, solve(p, b_scratch)), "bounded: the same answer without the interval search", k);
            expect(b_with.collides == with.collides, "bounded: a contact by 1/2 is found", k);
            expect(!b_with.collides || same(b_with, with), "bounded: the answer of until = 1", k);
          }
        }
    }
  }
  expect(resumed > 0, "some queries ended in the exact stage with the interval search on", resumed);
  std::printf("%d of %d queries in the exact stage\n", resumed, 2 * k);
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed ? 1 : 0;
}
