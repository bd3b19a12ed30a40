#include "pred/solve_linear.h"

#include "arith/convert.h"
#include "arith/interval.h"
#include "pred/delta_filter.h"

#include <cmath>

namespace pccd::pred {

using arith::Interval;
using arith::Rational;

namespace {

// True when the certified Bernstein coefficients of the contact cubic f all have a
// certain sign (linear_filter.h) and yet the filters could not decide: f certainly
// changes sign in (0, 1), and the crossing filter (linear_crossing.h) could not tell
// the side conditions there in interval arithmetic. The interval search then mostly
// meets the same uncertain side conditions: of the distinct queries bench_linear
// --workloads public ran (../shared/data/ccd-queries and its warm-up) that reached the
// staged solver this way, 52 of 56 vertex-face and 83 of 95 edge-edge without a time,
// and 130 of 142 vertex-face with a time, ended in the exact stage anyway
// (docs/benchmarks-tail.md). Not used for edge-edge with a time: there the exact search
// resumes the interval search's bisection (solve.cpp), which skipping loses, and 50 of
// 138 such queries were decided by intervals; skipping measured slower there. A
// prediction only: it picks which stage runs first, never an answer
// (Solve_options::interval_search).
bool interval_search_predicted_to_fail(const Cubic_bernstein &f) {
  if (!f.ok) return false;
  for (int k = 0; k < 4; ++k)
    if (!(std::fabs(f.value[k]) > f.bound[k])) return false;
  return true;
}

// The staged solver on n points with finite coordinates.
Contact_result solve_staged(int kind, size_t n, const double *p0, const double *p1,
                            const Solve_options &opt) {
  // The interval stages see the doubles as exact points; the exact trajectories are
  // built only if those stages cannot decide.
  Query_data<Interval> iq;
  iq.kind = kind;
  iq.p.resize(n);
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const double x0 = p0[3 * i + a], x1 = p1[3 * i + a];
      // x(t) = x0 + (x1 - x0) t: the slope is enclosed, not rounded.
      iq.p[i][a] = poly::Poly<Interval>(std::vector<Interval>{Interval(x0), Interval(x1) - Interval(x0)});
    }
  auto exact = [&] {
    Query_data<Rational> eq;
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
  return solve(iq, exact, opt);
}

}  // namespace

Linear_verdict linear_verdict(int kind, const double *p0, const double *p1, Cubic_bernstein &f) {
  const Linear_verdict v = linear_filter(kind, p0, p1, f);
  if (v == Linear_verdict::unknown && crossing_misses(kind, p0, p1, f)) return Linear_verdict::misses;
  return v;
}

void solve_linear(int kind, size_t n, const double *p0, const double *p1, const Solve_options &opt,
                  Contact_result &out) {
  reset(out);
  if (!opt.min_distance()) {
    // The stage each proof stands for: the staged solver decides there too (solve.h).
    Cubic_bernstein f;
    switch (linear_verdict(kind, p0, p1, f)) {
      case Linear_verdict::boxes_apart: out.stage = STAGE_BOUNDS; return;
      case Linear_verdict::no_root: out.stage = STAGE_BERNSTEIN; return;
      case Linear_verdict::misses: out.stage = STAGE_INTERVAL; return;
      case Linear_verdict::unknown: break;
    }
    if (crossing_hit(kind, p0, p1, f, opt, out)) return;
    if ((!opt.want_time || kind == VERTEX_FACE) && interval_search_predicted_to_fail(f)) {
      Solve_options exact_only = opt;
      exact_only.interval_search = false;
      out = solve_staged(kind, n, p0, p1, exact_only);
      return;
    }
  } else {
    // The staged solver's first test with a minimum distance (delta_filter.h), on the
    // same enclosures, before its interval query is built.
    Linear_points lp;
    linear_points_from(n, p0, p1, lp);
    if (delta_separated(kind, lp, opt.delta_box)) {
      out.stage = STAGE_BOUNDS;
      return;
    }
  }
  out = solve_staged(kind, n, p0, p1, opt);
}

}  // namespace pccd::pred
