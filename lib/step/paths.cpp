#include "step/paths.h"

#include "arith/convert.h"
#include "arith/interval.h"
#include "poly/bernstein.h"

namespace pccd::step {

using arith::Interval;
using arith::Rational;

namespace {

// Coefficient k of axis a of vertex v (on a path).
double coefficient(const Step_set &s, uint32_t v, size_t k, int a) {
  const uint32_t m = s.vmesh[v];
  const size_t nv = s.meshes[m].nv, i = v - s.meshes[m].v0;
  return s.coef[m][(k * nv + i) * 3 + a];
}

// The pair's trajectories: a path's coefficients, a straight vertex as x0 + (x1 - x0) t
// (NT = Interval: points, the slope enclosed; NT = Rational: exact).
template <class NT>
pred::Query_data<NT> query_of(const Step_set &s, int kind, const uint32_t *pts, int n) {
  pred::Query_data<NT> q;
  q.kind = kind;
  q.p.resize(n);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const uint32_t v = pts[i];
      std::vector<NT> c;
      if (on_path(s, v)) {
        for (size_t k = 0; k < s.ncoef[s.vmesh[v]]; ++k) c.push_back(NT(coefficient(s, v, k, a)));
      } else {
        const NT x0(s.x0[3 * size_t(v) + a]), x1(s.x1[3 * size_t(v) + a]);
        c = {x0, x1 - x0};
      }
      q.p[i][a] = poly::Poly<NT>(std::move(c));
    }
  return q;
}

}  // namespace

enclose::Box path_box(const Step_set &s, uint32_t v, const double u[3]) {
  const size_t n = s.ncoef[s.vmesh[v]];
  enclose::Box b;
  for (int a = 0; a < 3; ++a) {
    std::vector<Interval> c(std::max<size_t>(n, 2), Interval(0.0));
    for (size_t k = 0; k < n; ++k) c[k] = Interval(coefficient(s, v, k, a));
    c[1] = c[1] - Interval(u[a]);  // the frame: x(t) - u t
    const Interval r = poly::range_on_unit(poly::Poly<Interval>(std::move(c)));
    b.lo[a] = r.lo;
    b.hi[a] = r.hi;
  }
  return b;
}

void solve_paths(const Step_set &s, int kind, const uint32_t *pts, int n, const pred::Solve_options &opt,
                 pred::Contact_result &out) {
  const pred::Query_data<Interval> iq = query_of<Interval>(s, kind, pts, n);
  out = pred::solve(iq, [&] { return query_of<Rational>(s, kind, pts, n); }, opt);
}

}  // namespace pccd::step
