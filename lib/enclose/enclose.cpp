#include "enclose/enclose.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "arith/convert.h"
#include "poly/bernstein.h"

namespace pccd::enclose {

namespace {

constexpr double kSlack = 1.0 / (1ull << 48);  // > 20 u, see enclose.h
constexpr double kTiny = 1e-300;
constexpr double kInf = std::numeric_limits<double>::infinity();

// p(t) by interval Horner evaluation: an enclosure of p'(t) for every p' with
// coefficients in p's.
Interval value_at(const poly::Poly<Interval> &p, double t) {
  Interval r = p.c.back();
  for (size_t i = p.c.size() - 1; i-- > 0;) r = r * Interval(t) + p.c[i];
  return r;
}

// An enclosure of p over [a, b]. Shortcuts (each an enclosure by itself; they matter
// for a far-apart pair, which costs two calls of enclose_pose): a constant is its
// coefficient; at a point a = b, interval Horner evaluation; a line (translations)
// takes its values between those at a and b, so the hull of their enclosures; on
// [0, 1] the Bernstein hull needs no change of variable.
Interval range_on(const poly::Poly<Interval> &p, double a, double b) {
  if (p.c.empty()) return Interval(0.0);
  if (p.c.size() == 1) return p.c[0];
  if (a == b) return value_at(p, a);
  if (p.c.size() == 2) return arith::hull(value_at(p, a), value_at(p, b));
  if (a == 0 && b == 1) return poly::range_on_unit(p);
  return poly::range_on_unit(poly::reparametrize(p, Interval(a), Interval(b)));
}

// Midpoint and a radius covering [x.lo, x.hi] (with the slack of enclose.h).
void mid_rad(const Interval &x, double &m, double &r) {
  m = 0.5 * x.lo + 0.5 * x.hi;
  r = (std::fmax(x.hi - m, m - x.lo) + std::fabs(m) * kSlack) * (1 + kSlack) + kTiny;
}

}  // namespace

Box grow(const Box &a, double r) {
  Box g;
  for (int i = 0; i < 3; ++i) {
    const double s = (std::fabs(a.lo[i]) + std::fabs(a.hi[i]) + r) * kSlack + kTiny;
    g.lo[i] = a.lo[i] - r - s;
    g.hi[i] = a.hi[i] + r + s;
  }
  return g;
}

bool boxes_within(const Box &a, const Box &b, double r) {
  // Each gap is a difference of doubles (relative error <= 2^-53 rounding to nearest,
  // <= 2^-52 in a directed mode: e = 2^-52 serves every mode), squared and summed in
  // three more operations: the computed sum is within a factor (1 + e)^5 of the exact
  // one, and the computed r^2 within (1 + e)^2 of its own; 2^-48 > 5e covers both, and
  // 1e-300 underflow. A NaN gap counts as 0 (std::max keeps 0): kept.
  if (!(r > 0)) return boxes_meet(a, b);  // r = 0: exactly boxes_meet
  double d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double g = std::max({0.0, b.lo[i] - a.hi[i], a.lo[i] - b.hi[i]});
    d2 += g * g;
  }
  return !(d2 * (1 - 0x1p-48) - 1e-300 > r * r * (1 + 0x1p-48));
}

double reach_of(const arith::Rational &delta) {
  if (sgn(delta) <= 0) return 0.0;
  return arith::enclose(delta).hi;  // exact comparison with delta: arith/convert.h
}

Box empty_box() {
  Box e;
  for (int i = 0; i < 3; ++i) {
    e.lo[i] = kInf;
    e.hi[i] = -kInf;
  }
  return e;
}

namespace {

// A double estimate of R(t) = Rn(t) / W(t) and o(t) = O(t) / W(t) (midpoints of the
// coefficient enclosures; a heuristic input only, never a bound).
void approx_pose(const Moving_body &b, double t, double R[3][3], double o[3]) {
  auto ev = [t](const poly::Poly<Interval> &p) {
    double r = 0;
    for (size_t i = p.c.size(); i-- > 0;) r = r * t + 0.5 * (p.c[i].lo + p.c[i].hi);
    return r;
  };
  const double w = ev(b.mo->W_i);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) R[i][j] = ev(b.mo->Rn_i[i][j]) / w;
    o[i] = ev(b.mo->O_i[i]) / w;
  }
}

// The pivot of a piece (enclose.h, Pose_piece): q minimising |dR q + do|^2 + lam |q - c|^2,
// dR = R(b) - R(a), do = o(b) - o(a) (so q moves least over the piece), c the body's box
// centre, lam = |dR|^2 / 1000 (q = c for a translation). Any finite q is valid (the
// bounds hold for every q); a non-finite estimate falls back to c.
void choose_pivot(const Moving_body &b, double a, double t1, double q[3]) {
  const auto &c = b.data->box_c;
  for (int i = 0; i < 3; ++i) q[i] = c[i];
  if (!(t1 > a)) return;
  double Ra[3][3], Rb[3][3], oa[3], ob[3], D[3][3], d[3];
  approx_pose(b, a, Ra, oa);
  approx_pose(b, t1, Rb, ob);
  double n2 = 0;
  for (int i = 0; i < 3; ++i) {
    d[i] = ob[i] - oa[i];
    for (int j = 0; j < 3; ++j) {
      D[i][j] = Rb[i][j] - Ra[i][j];
      n2 += D[i][j] * D[i][j];
    }
  }
  if (!(n2 > 1e-24) || !std::isfinite(n2)) return;
  const double lam = 1e-3 * n2;
  double M[3][4];  // (D^T D + lam I) q = lam c - D^T d
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      M[i][j] = (i == j) ? lam : 0.0;
      for (int k = 0; k < 3; ++k) M[i][j] += D[k][i] * D[k][j];
    }
    M[i][3] = lam * c[i];
    for (int k = 0; k < 3; ++k) M[i][3] -= D[k][i] * d[k];
  }
  for (int i = 0; i < 3; ++i)  // Gaussian elimination (symmetric positive definite)
    for (int r = i + 1; r < 3; ++r) {
      const double f = M[r][i] / M[i][i];
      for (int k = i; k < 4; ++k) M[r][k] -= f * M[i][k];
    }
  double x[3];
  for (int i = 3; i-- > 0;) {
    double v = M[i][3];
    for (int k = i + 1; k < 3; ++k) v -= M[i][k] * x[k];
    x[i] = v / M[i][i];
  }
  if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))
    for (int i = 0; i < 3; ++i) q[i] = x[i];
}

}  // namespace

namespace {
struct Whole_pose : narrow::Body_attachment {
  Pose_piece pose;
};
}  // namespace

Pose_piece whole_pose(const Moving_body &b) {
  if (!b.derived) return enclose_pose(b, 0.0, 1.0);
  return b.derived
      ->attached<Whole_pose>([&] {
        auto w = std::make_unique<Whole_pose>();
        w->pose = enclose_pose(b, 0.0, 1.0);
        return w;
      })
      .pose;
}

Pose_piece enclose_pose(const Moving_body &b, double a, double t1) {
  Pose_piece p;
  choose_pivot(b, a, t1, p.q);
  const Interval W = range_on(b.mo->W_i, a, t1);
  const bool w_pos = W.lo > 0;
  double max_rr = 0, max_or = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Interval r(-1.0, 1.0);  // rotation entries lie in [-1, 1]
      if (w_pos) {
        Interval q = range_on(b.mo->Rn_i[i][j], a, t1);
        if (!(W.lo == 1 && W.hi == 1)) q = q / W;  // W = 1: translations, the identity
        r = Interval(std::fmax(q.lo, -1.0), std::fmin(q.hi, 1.0));
      }
      mid_rad(r, p.Rm[i][j], p.Rr[i][j]);
      max_rr = std::fmax(max_rr, p.Rr[i][j]);
    }
    if (w_pos) {
      // O_q = O + Rn q, coefficient by coefficient in interval arithmetic (q is exact).
      // (A per-thread buffer: no allocation per call once it has grown.)
      thread_local poly::Poly<Interval> Oq;
      Oq.c.assign(b.mo->O_i[i].c.begin(), b.mo->O_i[i].c.end());
      for (int j = 0; j < 3; ++j) {
        const auto &r = b.mo->Rn_i[i][j];
        if (r.c.size() > Oq.c.size()) Oq.c.resize(r.c.size(), Interval(0.0));
        for (size_t k = 0; k < r.c.size(); ++k) Oq.c[k] = Oq.c[k] + r.c[k] * Interval(p.q[j]);
      }
      Interval o = range_on(Oq, a, t1);
      if (!(W.lo == 1 && W.hi == 1)) o = o / W;
      mid_rad(o, p.om[i], p.orad[i]);
      p.finite = p.finite && std::isfinite(p.om[i]) && std::isfinite(p.orad[i]);
      max_or = std::fmax(max_or, p.orad[i]);
    } else {
      p.finite = false;  // om, orad stay 0 and unused (spread and boxes are unbounded)
    }
  }
  // |p - q|_inf <= reach + |q|_inf for every body point (reach covers radii too).
  const double qn = std::fmax(std::fabs(p.q[0]), std::fmax(std::fabs(p.q[1]), std::fabs(p.q[2])));
  p.spread = p.finite ? 3 * max_rr * (b.data->reach + qn) + max_or : kInf;
  return p;
}

Box frame_box(const Pose_piece &pose, const std::array<double, 3> &c, const std::array<double, 3> &h) {
  Box out;
  if (!pose.finite) {
    for (int i = 0; i < 3; ++i) {
      out.lo[i] = -kInf;
      out.hi[i] = kInf;
    }
    return out;
  }
  // The box about the pivot: (cq, hq) holds the exact box [c - h, c + h] - q, since
  // fl(c - q) errs by at most 2u |c - q| <= (|c| + |q|) kSlack / 16; the sum below then
  // treats (cq, hq) as exact.
  double cq[3], hq[3];
  for (int j = 0; j < 3; ++j) {
    cq[j] = c[j] - pose.q[j];
    hq[j] = (h[j] + (std::fabs(c[j]) + std::fabs(pose.q[j])) * kSlack) * (1 + kSlack) + kTiny;
  }
  for (int i = 0; i < 3; ++i) {
    double m = pose.om[i], r = pose.orad[i], mag = std::fabs(pose.om[i]) + pose.orad[i];
    for (int j = 0; j < 3; ++j) {
      const double ac = std::fabs(cq[j]);
      m += pose.Rm[i][j] * cq[j];
      const double t = pose.Rr[i][j] * (ac + hq[j]) + std::fabs(pose.Rm[i][j]) * hq[j];
      r += t;
      mag += std::fabs(pose.Rm[i][j]) * ac + t;
    }
    const double s = (mag + std::fabs(m) + r) * kSlack + kTiny;
    out.lo[i] = m - r - s;
    out.hi[i] = m + r + s;
  }
  return out;
}

Box point_box(const Pose_piece &pose, const std::array<double, 3> &p, double e) {
  return frame_box(pose, p, {e, e, e});
}

Box feature_box(const Moving_body &b, int s, const Prim_pair &p, const Pose_piece &pose) {
  const uint32_t k = s == 0 ? p.a : p.b;
  const auto &pts = b.data->pts;
  const double e = b.data->pt_err;
  const bool vertex = (s == 0 && p.type == narrow::VF) || (s == 1 && p.type == narrow::FV);
  if (vertex) return point_box(pose, pts[k], e);
  if (p.type == narrow::EE) {
    const auto &ed = b.mesh->edges()[k];
    return hull(point_box(pose, pts[ed[0]], e), point_box(pose, pts[ed[1]], e));
  }
  if (!b.is_mesh()) return grow(point_box(pose, pts[k], e), b.data->radius_up[k]);
  const auto &t = b.mesh->triangles()[k];
  Box h = point_box(pose, pts[t[0]], e);
  for (int v = 1; v < 3; ++v) h = hull(h, point_box(pose, pts[t[v]], e));
  return h;
}

// n . x over the boxes: an interval holding every value. Each bound is a sum of three
// products in doubles; in any rounding mode each operation errs by at most 2u = 2^-52
// relative, so the sum errs by at most 10u times the sum M of the products' magnitudes;
// both bounds move out by M 2^-48 (> 10u M) + 1e-300 (underflow), as boxes.h does.
void project(const double n[3], const Box *b, int count, double &lo, double &hi) {
  lo = HUGE_VAL;
  hi = -HUGE_VAL;
  for (int k = 0; k < count; ++k) {
    double l = 0, h = 0, m = 0;
    for (int i = 0; i < 3; ++i) {
      const double x = n[i] * b[k].lo[i], y = n[i] * b[k].hi[i];
      l += x < y ? x : y;
      h += x < y ? y : x;
      m += std::fabs(x) > std::fabs(y) ? std::fabs(x) : std::fabs(y);
    }
    const double e = m * 0x1p-48 + 1e-300;
    if (std::isnan(l) || std::isnan(h) || std::isnan(e)) {  // unbounded boxes: no claim
      lo = -HUGE_VAL;
      hi = HUGE_VAL;
      return;
    }
    lo = std::min(lo, l - e);
    hi = std::max(hi, h + e);
  }
}

bool axis_separates(const double n[3], const Box *a, int na, const Box *b, int nb, double reach) {
  double xl, xh, yl, yh;
  project(n, a, na, xl, xh);
  project(n, b, nb, yl, yh);
  if (reach == 0) return xh < yl || yh < xl;
  // Within reach: points x, y with |x - y| <= reach project within reach |n| of each
  // other, so a gap > reach |n| separates (sharper than A's boxes grown by reach on
  // every axis, which adds reach |n|_1). Each gap, a difference of doubles, errs by at
  // most u of itself; |n| and the product by a few u: 2^-48 covers them.
  const double m = reach * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * (1 + 0x1p-48) + 1e-300;
  return (yl - xh) * (1 - 0x1p-48) > m || (xl - yh) * (1 - 0x1p-48) > m;
}

}  // namespace pccd::enclose
