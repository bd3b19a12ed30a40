// Piece_query's exact conditions for a linear translation (LINEARIZATION.md, "Linear
// translations") and the same side conditions at one instant (the static test); the
// rest of Piece_query is in linearize.cpp.
//
// On the piece every query point moves on the segment start(k) -> end(k) (homogeneous,
// weight w = w_[0] > 0, constant), all by the same vector d = end - start. In
// homogeneous form the line through X with direction D has the Plücker coordinates
// (w D, X x D) (positive multiples of the affine ones), and the closed segment or
// convex polygon met by a line makes the side products u1 . v2 + u2 . v1 with its
// consistently oriented boundary edges all >= 0 or all <= 0 (all 0 when the line lies
// in its plane or the polygon is degenerate): necessary, so nothing is filtered wrongly.
#include "range/ivec.h"
#include "range/linearize.h"

namespace pccd::range {

std::array<Interval, 3> Piece_query::start(uint32_t point) const {
  const auto &h = H(point);
  return {h[0][0], h[1][0], h[2][0]};
}

std::array<Interval, 3> Piece_query::end(uint32_t point) const {
  const auto &h = H(point);  // A_n = beta_n = the value at s = 1 (C(n, n) = 1)
  return {h[0].back(), h[1].back(), h[2].back()};
}

namespace {

// Clauses "side_i >= 0 or side_j <= 0" for every i != j: all sides have one sign.
template <int D>
void same_sign(Cnf<D> &q, const std::vector<Halfspace<D>> &side) {
  for (size_t i = 0; i < side.size(); ++i)
    for (size_t j = 0; j < side.size(); ++j) {
      if (i == j) continue;
      q.hs.push_back(side[i]);
      Halfspace<D> neg = side[j];
      for (auto &x : neg.a) x = -x;
      neg.a0 = -neg.a0;
      q.hs.push_back(neg);
      q.end_clause();
    }
}

}  // namespace

void Piece_query::add_translation_sides_vs_vertices(uint32_t tri, Cnf<kDimVertex> &q) const {
  // Stored vertex p moves by -d relative to the triangle (taken at the piece's start):
  // the line through p with direction d against the sides X_i -> X_{i+1}:
  // (w (X_{i+1} - X_i)) . (p x d) + d . (X_i x X_{i+1}) = p . (d x u_i) + d . v_i.
  const auto &t = q_.mesh->triangles()[tri];
  const Interval w = w_[0];
  const I3 d = sub(end(t[0]), start(t[0]));
  std::vector<Halfspace<kDimVertex>> side(3);
  for (int i = 0; i < 3; ++i) {
    const I3 x0 = start(t[i]), x1 = start(t[(i + 1) % 3]);
    const I3 a = cross(d, scale3(w, sub(x1, x0)));
    for (int k = 0; k < 3; ++k) side[i].a[k] = a[k];
    side[i].a0 = dot(d, cross(x0, x1));
  }
  same_sign(q, side);
}

Cnf<kDimSides> Piece_query::translation_sides_vs_triangles(uint32_t v) const {
  // The query vertex's line (w d, X0 x d) against the stored sides (u_i, v_i):
  // w d . v_i + u_i . (X0 x d).
  const Interval w = w_[0];
  const I3 x0 = start(v), d = sub(end(v), x0);
  const I3 m = cross(x0, d), wd = scale3(w, d);
  std::vector<Halfspace<kDimSides>> side(3);  // coefficients start at 0
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      side[i].a[6 * i + k] = m[k];
      side[i].a[6 * i + 3 + k] = wd[k];
    }
  Cnf<kDimSides> q;
  same_sign(q, side);
  return q;
}

void Piece_query::add_translation_sides_vs_edges(uint32_t e, Cnf<kDimEdge> &q) const {
  // The query edge sweeps the parallelogram A B C D (A, B the endpoints at the start, C,
  // D at the end); the stored edge's line (u, v) meets it only if its sides with
  // A->B, B->C, C->D, D->A, (w (Y - X), X x Y), have one sign: v . w (Y - X) + u . (X x Y).
  const auto &E = q_.mesh->edges()[e];
  const Interval w = w_[0];
  const I3 c[4] = {start(E[0]), start(E[1]), end(E[1]), end(E[0])};
  std::vector<Halfspace<kDimEdge>> side(4);  // coefficients start at 0
  for (int i = 0; i < 4; ++i) {
    const I3 &x = c[i], &y = c[(i + 1) % 4];
    const I3 mom = cross(x, y), dir = scale3(w, sub(y, x));
    for (int k = 0; k < 3; ++k) {
      side[i].a[k] = mom[k];
      side[i].a[3 + k] = dir[k];
    }
  }
  same_sign(q, side);
}

void Piece_query::add_triangle_vs_edge_sides(uint32_t tri, Cnf<kDimEdge> &q) const {
  // The stored edge's line (u, v) against the sides X -> Y of the triangle at the
  // instant: (w (Y - X)) . v + (X x Y) . u, as in add_translation_sides_vs_edges.
  const auto &t = q_.mesh->triangles()[tri];
  const Interval w = w_[0];
  std::vector<Halfspace<kDimEdge>> side(3);  // coefficients start at 0
  for (int i = 0; i < 3; ++i) {
    const I3 x = start(t[i]), y = start(t[(i + 1) % 3]);
    const I3 mom = cross(x, y), dir = scale3(w, sub(y, x));
    for (int k = 0; k < 3; ++k) {
      side[i].a[k] = mom[k];
      side[i].a[3 + k] = dir[k];
    }
  }
  same_sign(q, side);
}

}  // namespace pccd::range
