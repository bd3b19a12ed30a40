#include <array>

#include "pred/filters.h"

namespace pccd::pred {

using arith::Interval;

namespace {

// Which query points belong to the first primitive; the rest form the second.
int first_side_points(int kind) {
  switch (kind) {
    case EDGE_EDGE: return 2;
    default: return 1;
  }
}

bool boxes_separate(const Query_data<Interval> &q, bool bernstein) {
  const int split = first_side_points(q.kind);
  std::array<Interval, 3> box[2];
  bool init[2] = {false, false};
  for (size_t i = 0; i < q.p.size(); ++i) {
    int side = static_cast<int>(i) < split ? 0 : 1;
    for (int a = 0; a < 3; ++a) {
      Interval r;
      if (bernstein || !poly::horner_enclosure(q.p[i][a], Interval(0.0), Interval(1.0), r))
        r = poly::range_on_unit(q.p[i][a]);
      box[side][a] = init[side] ? arith::hull(box[side][a], r) : r;
    }
    init[side] = true;
  }
  // Radii and delta scale with D (query_systems.h): a side grows by r * max D (max D
  // found only for the kinds that grow: not on the path of the point kinds).
  double dmax = -1;
  auto grow = [&](int side, const Interval &r) {
    if (dmax < 0) dmax = q.scale.c.empty() ? 1.0 : poly::range_on_unit(q.scale).hi;
    const double g = (r * Interval(dmax)).hi;
    for (int a = 0; a < 3; ++a)
      box[side][a] = {arith::round_down(box[side][a].lo - g), arith::round_up(box[side][a].hi + g)};
  };
  if (q.kind == SPHERE_SPHERE || q.kind == SPHERE_TRIANGLE) grow(0, q.radius[0]);
  if (q.kind == SPHERE_SPHERE) grow(1, q.radius[1]);
  if (q.has_delta) grow(0, q.delta);  // within delta
  for (int a = 0; a < 3; ++a)
    if (box[0][a].hi < box[1][a].lo || box[1][a].hi < box[0][a].lo) return true;
  return false;
}

}  // namespace

// The boxes first from each coordinate's Horner enclosure on [0, 1] (O(n) each,
// poly/bernstein.h; on short windows nearly the Bernstein hull), and only when those do
// not separate, from the Bernstein hulls (O(n^2)): every box encloses the points' paths,
// so either separation is certain, and no separation the Bernstein boxes show is lost.
bool bounds_separate(const Query_data<Interval> &q) {
  return boxes_separate(q, false) || boxes_separate(q, true);
}

bool bernstein_excludes(const Query_data<Interval> &q) {
  const Interval zero(0.0), one(1.0);
  const auto &p = q.p;
  auto rootless = [&](const Poly<Interval> &f) { return poly::certainly_no_root(f, zero, one); };
  if (q.has_delta) {
    // The distance to the closed primitive is at least the distance to its plane
    // (vertex-face), to its line (vertex-edge) or between the lines (edge-edge; where they
    // are parallel the polynomial is h^2 = 0 and cannot be certainly positive). Squared
    // and multiplied by |n|^2 (|e|^2), each is above delta on all of [0, 1] when its
    // polynomial below is certainly positive there: then no contact within delta.
    const Poly<Interval> r2 = radius_squared(q.delta, q.scale);
    auto above = [&](const Poly<Interval> &f) {
      return !f.c.empty() && poly::certain_sign_on(f, zero, one) > 0;
    };
    switch (q.kind) {
      case VERTEX_VERTEX: {
        auto d = p[0] - p[1];
        return above(motion::dot(d, d) - r2);
      }
      case VERTEX_EDGE: {
        auto e = p[2] - p[1];
        auto u = motion::cross(e, p[0] - p[1]);
        return above(motion::dot(u, u) - r2 * motion::dot(e, e));
      }
      case VERTEX_FACE: {
        auto n = motion::cross(p[2] - p[1], p[3] - p[1]);
        Poly<Interval> h = motion::dot(n, p[0] - p[1]);
        return above(h * h - r2 * motion::dot(n, n));
      }
      case EDGE_EDGE: {
        auto n = motion::cross(p[1] - p[0], p[3] - p[2]);
        Poly<Interval> h = motion::dot(n, p[2] - p[0]);
        return above(h * h - r2 * motion::dot(n, n));
      }
    }
    return false;
  }
  switch (q.kind) {
    case VERTEX_FACE: {
      auto n = motion::cross(p[2] - p[1], p[3] - p[1]);
      return rootless(motion::dot(n, p[0] - p[1]));
    }
    case EDGE_EDGE:
      return rootless(motion::dot(motion::cross(p[1] - p[0], p[2] - p[0]), p[3] - p[0]));
    case VERTEX_EDGE: {
      auto u = motion::cross(p[2] - p[1], p[0] - p[1]);
      return rootless(u[0]) || rootless(u[1]) || rootless(u[2]);
    }
    case VERTEX_VERTEX: {
      auto d = p[0] - p[1];
      return rootless(d[0]) || rootless(d[1]) || rootless(d[2]);
    }
    case SPHERE_SPHERE: {
      auto d = p[0] - p[1];
      Poly<Interval> f = motion::dot(d, d) - radius_squared(Interval(q.radius[0] + q.radius[1]), q.scale);
      return !f.c.empty() && poly::certain_sign_on(f, zero, one) > 0;
    }
    case SPHERE_TRIANGLE: {
      // The ball stays strictly off the triangle's plane: (n.(c - f0))^2 > r^2 D^2 |n|^2
      // on [0, 1] (where n = 0 the left side is 0, so this cannot hold there).
      auto n = motion::cross(p[2] - p[1], p[3] - p[1]);
      Poly<Interval> h = motion::dot(n, p[0] - p[1]);
      Poly<Interval> f = h * h - radius_squared(q.radius[0], q.scale) * motion::dot(n, n);
      return !f.c.empty() && poly::certain_sign_on(f, zero, one) > 0;
    }
  }
  return false;
}

}  // namespace pccd::pred
