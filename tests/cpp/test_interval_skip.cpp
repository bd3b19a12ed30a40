// Skipping the interval search (Solve_options::interval_search, and solve_linear's
// prediction of when it cannot decide, lib/pred/solve_linear.cpp) changes no answer:
//  - near-grazing linear queries built so the answer is known: a vertex crossing the
//    plane of a triangle at t = 1/2 at distance d from an edge's line (it touches iff it
//    is on the closed triangle's side, d >= 0), an edge endpoint crossing another edge
//    at t = 1/2 (touches iff d <= 0); d from 0 to a few ulps and beyond, so the double
//    filters cannot tell and the prediction fires. Checked: collides against the known
//    answer, the contact time 1/2 inside the enclosure (exact 1/2 when asked), and the
//    staged solver with and without the interval search agree exactly (collides,
//    enclosure, exactness, features), also with solve_linear;
//  - queries of the public query set (../shared/data/ccd-queries) on which the
//    interval search decides but the prediction fires (vertex-face, without and with a
//    time): solve_linear now answers from the exact stage, with the staged solver's
//    answer.
// Prints "N passed, N failed"; exit status 0 only when none failed.
#include <cstdio>
#include <functional>
#include <vector>

#include "arith/convert.h"
#include "pred/solve_linear.h"

using namespace pccd;
using arith::Interval;
using arith::Rational;
using pred::Contact_result;
using pred::Solve_options;

static long passed = 0, failed = 0;
static void expect(bool ok, const char *what, double d) {
  if (ok) {
    ++passed;
  } else if (++failed <= 20) {
    std::printf("FAIL: %s (d = %a)\n", what, d);
  }
}

// The staged solver on the linear query, as solve_linear builds it.
static Contact_result staged(int kind, size_t n, const double *p0, const double *p1, const Solve_options &opt) {
  pred::Query_data<Interval> iq;
  iq.kind = kind;
  iq.p.resize(n);
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const double x0 = p0[3 * i + a], x1 = p1[3 * i + a];
      iq.p[i][a] = poly::Poly<Interval>(std::vector<Interval>{Interval(x0), Interval(x1) - Interval(x0)});
    }
  auto exact = [&] {
    pred::Query_data<Rational> eq;
    eq.kind = kind;
    eq.p.resize(n);
    for (size_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) {
        Rational x0 = arith::rational_from_double(p0[3 * i + a], "p_t0");
        Rational x1 = arith::rational_from_double(p1[3 * i + a], "p_t1");
        eq.p[i][a] = poly::Poly<Rational>(std::vector<Rational>{x0, x1 - x0});
      }
    return eq;
  };
  return pred::solve(iq, exact, opt);
}

static bool same(const Contact_result &a, const Contact_result &b) {
  return a.collides == b.collides && (!a.collides || (a.lo == b.lo && a.hi == b.hi && a.exact == b.exact &&
                                                      a.features == b.features));
}

// One query with known answer `touches` at t = 1/2 (when it touches), both modes.
static void check(int kind, const double *p0, const double *p1, bool touches, double d) {
  const Rational half(1, 2);
  for (bool want_time : {false, true}) {
    Solve_options opt;
    opt.want_time = want_time;
    Contact_result lin;
    pred::solve_linear(kind, 4, p0, p1, opt, lin);
    const Contact_result with = staged(kind, 4, p0, p1, opt);
    Solve_options skip = opt;
    skip.interval_search = false;
    const Contact_result without = staged(kind, 4, p0, p1, skip);
    expect(lin.collides == touches, "solve_linear: collides as known", d);
    expect(same(with, without), "staged solver with and without the interval search", d);
    expect(lin.collides == with.collides && (!lin.collides || lin.features == with.features),
           "solve_linear: the staged solver's answer", d);
    if (want_time && touches) {
      expect(lin.lo <= half && half <= lin.hi, "contact time 1/2 inside the enclosure", d);
      expect(lin.exact && lin.lo == half, "rational contact time 1/2 found exactly", d);
      expect(same(lin, with), "solve_linear: the staged solver's enclosure", d);
    }
  }
}

int main() {
  // d: multiples of 2^-54 (so d +- 1/2 is an exact double), 0 and up to 2^-40.
  std::vector<double> ds = {0.0};
  for (double m : {1.0, 3.0, 5.0, 1024.0, 16384.0 * 64})
    for (double s : {1.0, -1.0}) ds.push_back(s * m * 0x1p-54);
  for (double d : ds) {
    // Vertex-face: the face z = 0 with corners (0,0,0), (1,0,0), (0,1,0); the vertex
    // from (1/4, d - 1/2, 1) to (1/4, d + 1/2, -1), at (1/4, d, 0) at t = 1/2.
    const double vf0[12] = {0.25, d - 0.5, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
    const double vf1[12] = {0.25, d + 0.5, -1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
    check(pred::VERTEX_FACE, vf0, vf1, d >= 0, d);
    // Edge-edge: edge a from (0,0,0) to (1,0,0), still; edge b from (1/2, d - 1/2, 1)
    // - (1/2, 1, 1) to (1/2, d + 1/2, -1) - (1/2, 1, -1): in the plane z = 0 only at
    // t = 1/2, then from (1/2, d, 0) to (1/2, 1, 0), meeting a iff d <= 0.
    const double ee0[12] = {0, 0, 0, 1, 0, 0, 0.5, d - 0.5, 1, 0.5, 1, 1};
    const double ee1[12] = {0, 0, 0, 1, 0, 0, 0.5, d + 0.5, -1, 0.5, 1, -1};
    check(pred::EDGE_EDGE, ee0, ee1, d <= 0, d);
  }
  // From ../shared/data/ccd-queries (erleben-cube-cliff-edges/vertex-face/data_0_1.csv,
  // colliding by the truth column): every coefficient of the contact cubic has a certain sign and
  // the crossing filter cannot decide, yet the interval search decides. Without a time
  // the prediction skips it: the exact stage answers, with the same answer.
  const double p0[12] = {-0x1.4fe50cd52fc2ap-57, 0x1.017893189eecdp-1, 0x1.7bda1225661edp-54, 0, 0x1p-1, 0x1p+0,
                         0, 0x1p-1, 0, -0x1p-2, -0x1p-1, -0x1p-2};
  const double p1[12] = {-0x1.0dfca19aa5f85p-54, 0x1.1c4a18930a7fbp-2, -0x1.01b718706618cp-56, 0, 0x1p-1, 0x1p+0,
                         0, 0x1p-1, 0, -0x1p-2, -0x1p-1, -0x1p-2};
  Solve_options decide;
  decide.want_time = false;
  Contact_result lin;
  pred::solve_linear(pred::VERTEX_FACE, 4, p0, p1, decide, lin);
  const Contact_result with = staged(pred::VERTEX_FACE, 4, p0, p1, decide);
  expect(with.stage == pred::STAGE_INTERVAL && with.collides, "public case: the interval search decides it", 0);
  expect(lin.stage == pred::STAGE_EXACT, "public case: predicted, decided by the exact stage", 0);
  expect(lin.collides && lin.features == with.features, "public case: the staged solver's answer", 0);
  // From ../shared/data/ccd-queries (unit-tests/vertex-face/data_0_0.csv): the same with
  // a time (the prediction is used with a time for vertex-face): the same enclosure.
  const double u0[12] = {0, 1, 0, -1, 0, 1, 1, 0, 1, 0, 0, -1};
  const double u1[12] = {0, 0, -0x1p-23, -1, 1, 1, 1, 1, 1, 0, 1, -1};
  Solve_options timed;
  pred::solve_linear(pred::VERTEX_FACE, 4, u0, u1, timed, lin);
  const Contact_result with_t = staged(pred::VERTEX_FACE, 4, u0, u1, timed);
  expect(with_t.stage == pred::STAGE_INTERVAL, "public case with a time: the interval search decides it", 0);
  expect(lin.stage == pred::STAGE_EXACT, "public case with a time: predicted, decided by the exact stage", 0);
  expect(same(lin, with_t), "public case with a time: the staged solver's answer", 0);
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed ? 1 : 0;
}
