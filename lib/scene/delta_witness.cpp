#include "scene/delta_witness.h"

#include <array>
#include <cmath>

#include "arith/interval.h"

namespace pccd::scene {
namespace {

using arith::Interval;
using IPoint = std::array<Interval, 3>;
using ITriangle = std::array<IPoint, 3>;

ITriangle world_triangle(const narrow::Body_data &d, uint32_t e, const enclose::Pose_piece &p) {
  const auto &t = d.mesh->triangles()[e];
  ITriangle out;
  for (int v = 0; v < 3; ++v) {
    const enclose::Box x = enclose::point_box(p, d.pts[t[v]], d.pt_err);
    for (int i = 0; i < 3; ++i) out[v][i] = Interval(x.lo[i], x.hi[i]);
  }
  return out;
}

double mid(const Interval &x) { return 0.5 * x.lo + 0.5 * x.hi; }

// An enclosure of the squared distance of two enclosed points.
Interval dist2(const IPoint &a, const IPoint &b) {
  Interval s(0.0);
  for (int i = 0; i < 3; ++i) {
    const Interval d = a[i] - b[i];
    s += d * d;
  }
  return s;
}

// A point of triangle T near q (see the header), enclosed; false when no weights could
// be certified (a degenerate triangle, a non-finite box).
bool near_point(const ITriangle &T, const IPoint &q, IPoint &out) {
  double v0[3], e1[3], e2[3], w[3];
  for (int i = 0; i < 3; ++i) {
    v0[i] = mid(T[0][i]);
    e1[i] = mid(T[1][i]) - v0[i];
    e2[i] = mid(T[2][i]) - v0[i];
    w[i] = mid(q[i]) - v0[i];
  }
  const double d11 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
  const double d12 = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
  const double d22 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
  const double dw1 = w[0] * e1[0] + w[1] * e1[1] + w[2] * e1[2];
  const double dw2 = w[0] * e2[0] + w[1] * e2[1] + w[2] * e2[2];
  const double det = d11 * d22 - d12 * d12;
  if (!(det > 0) || !std::isfinite(det)) return false;
  double b1 = (d22 * dw1 - d12 * dw2) / det, b2 = (d11 * dw2 - d12 * dw1) / det;
  if (!(b1 >= 0)) b1 = 0;  // also NaN
  if (!(b2 >= 0)) b2 = 0;
  if (b1 + b2 > 1) {
    const double s = b1 + b2;
    b1 /= s;
    b2 /= s;
  }
  const Interval b0 = Interval(1.0) - Interval(b1) - Interval(b2);
  if (!(b0.lo >= 0)) return false;  // 1 - b1 - b2 >= 0 not certain: no point
  for (int i = 0; i < 3; ++i) out[i] = b0 * T[0][i] + Interval(b1) * T[1][i] + Interval(b2) * T[2][i];
  return true;
}

// The points of edges [a0, a1] and [b0, b1] nearest in doubles (parameters clamped to
// [0, 1], each in turn), enclosed as (1 - s) a0 + s a1 and (1 - u) b0 + u b1: points of
// the exact edges (s, u in [0, 1] exactly, so 1 - s >= 0 certainly). Edge pairs are
// where two triangles approach edge to edge, when no vertex is as close as the edges.
void nearest_of_edges(const IPoint &a0, const IPoint &a1, const IPoint &b0, const IPoint &b1, IPoint &p, IPoint &q) {
  double d1[3], d2[3], r[3];
  for (int i = 0; i < 3; ++i) {
    d1[i] = mid(a1[i]) - mid(a0[i]);
    d2[i] = mid(b1[i]) - mid(b0[i]);
    r[i] = mid(a0[i]) - mid(b0[i]);
  }
  auto dot = [](const double *x, const double *y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  auto clamp = [](double x) { return x > 0 ? (x < 1 ? x : 1.0) : 0.0; };  // NaN: 0
  const double a = dot(d1, d1), e = dot(d2, d2), b = dot(d1, d2), c = dot(d1, r), f = dot(d2, r);
  const double den = a * e - b * b;
  double s = den > 0 ? clamp((b * f - c * e) / den) : 0;
  double u = e > 0 ? (b * s + f) / e : 0;
  if (!(u >= 0)) {
    u = 0;
    s = a > 0 ? clamp(-c / a) : 0;
  } else if (u > 1) {
    u = 1;
    s = a > 0 ? clamp((b - c) / a) : 0;
  }
  const Interval s1 = Interval(1.0) - Interval(s), u1 = Interval(1.0) - Interval(u);
  for (int i = 0; i < 3; ++i) {
    p[i] = s1 * a0[i] + Interval(s) * a1[i];
    q[i] = u1 * b0[i] + Interval(u) * b1[i];
  }
}

}  // namespace

bool triangles_within(const narrow::Body_data &A, uint32_t ea, const enclose::Pose_piece &pa,
                      const narrow::Body_data &B, uint32_t eb, const enclose::Pose_piece &pb, double delta_lo) {
  if (!(delta_lo > 0) || !std::isfinite(delta_lo) || !A.mesh || !B.mesh) return false;
  const ITriangle ta = world_triangle(A, ea, pa), tb = world_triangle(B, eb, pb);
  const Interval d = Interval(delta_lo) * Interval(delta_lo);
  for (int side = 0; side < 2; ++side) {
    const ITriangle &from = side ? tb : ta, &onto = side ? ta : tb;
    for (int v = 0; v < 3; ++v) {
      IPoint p;
      if (near_point(onto, from[v], p) && dist2(p, from[v]).hi <= d.lo) return true;
    }
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      IPoint p, q;
      nearest_of_edges(ta[i], ta[(i + 1) % 3], tb[j], tb[(j + 1) % 3], p, q);
      if (dist2(p, q).hi <= d.lo) return true;
    }
  return false;
}

}  // namespace pccd::scene
