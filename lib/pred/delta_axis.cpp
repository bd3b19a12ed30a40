#include "pred/delta_axis.h"

#include <algorithm>
#include <cmath>

#include "poly/bernstein.h"
#include "pred/closest_axis.h"

namespace pccd::pred {

using arith::Interval;

namespace {

double mid(const Interval &x) { return 0.5 * x.lo + 0.5 * x.hi; }

}  // namespace

bool delta_axis_separated(const Query_data<Interval> &q) {
  if (!q.has_delta) return false;
  int na = 0, nb = 0;  // points of the first and the second primitive
  switch (q.kind) {
    case VERTEX_FACE: na = 1, nb = 3; break;
    case EDGE_EDGE: na = 2, nb = 2; break;
    case VERTEX_EDGE: na = 1, nb = 2; break;
    case VERTEX_VERTEX: na = 1, nb = 1; break;
    default: return false;
  }
  if (q.p.size() != static_cast<size_t>(na + nb)) return false;
  // The direction: the points at t = 1/2 in doubles (a heuristic, see the header).
  const Interval half(0.5);
  const double D = q.scale.c.empty() ? 1.0 : mid(q.scale.eval(half));
  double x[4][3];
  for (int i = 0; i < na + nb; ++i)
    for (int a = 0; a < 3; ++a) x[i][a] = mid(q.p[i][a].eval(half)) / D;
  double d[3];
  if (!closest_direction(x, na, x + na, nb, d)) return false;
  // N >= |d|: d . d enclosed, its square root one ulp up (sqrt errs by less than an ulp
  // in any rounding mode).
  Interval dd(0.0);
  for (int a = 0; a < 3; ++a) dd = dd + Interval(d[a]) * Interval(d[a]);
  if (!(dd.hi > 0) || !std::isfinite(dd.hi)) return false;
  const double N = arith::round_up(std::sqrt(dd.hi));
  const Interval dN = q.delta * Interval(N);
  const Poly<Interval> rhs = q.scale.c.empty() ? Poly<Interval>(std::vector<Interval>{dN}) : dN * q.scale;
  // g's coefficients summed in place, in the order of the polynomial operations (each
  // coefficient's value is the same as -rhs + sum_a d_a (p_j,a - p_i,a)); one buffer.
  size_t n = rhs.c.size();
  for (const auto &pt : q.p)
    for (int a = 0; a < 3; ++a) n = std::max(n, pt[a].c.size());
  const Interval zero(0.0);
  auto at = [&](const Poly<Interval> &p, size_t k) -> const Interval & { return k < p.c.size() ? p.c[k] : zero; };
  Poly<Interval> g;
  g.c.resize(n);
  for (int i = 0; i < na; ++i)
    for (int j = na; j < na + nb; ++j) {
      for (size_t k = 0; k < n; ++k) {
        Interval c = -at(rhs, k);
        for (int a = 0; a < 3; ++a) c = c + Interval(d[a]) * (at(q.p[j][a], k) - at(q.p[i][a], k));
        g.c[k] = c;
      }
      // certain_sign_on: Horner's O(n) enclosure first, then the Bernstein
      // coefficients, all certainly > 0 (the hull range_on_unit takes).
      if (poly::certain_sign_on(g, zero, Interval(1.0)) != 1) return false;
    }
  return true;
}

}  // namespace pccd::pred
