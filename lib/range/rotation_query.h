// The exact linearization for a relative rotation about a fixed axis (Schömer and
// Thiel's case; derivation in range/LINEARIZATION.md, "Rotations about a fixed axis").
//
// On a time piece [ta, tb] the relative rotation E(t) = (alpha(t), t a)
// (range/axis_rotation.h) is linear in t, so with s = (t - ta) / (tb - ta) in [0, 1] and
// u0 = (alpha(ta), ta), u1 = (alpha(tb), tb) the pair (alpha, beta) is (1 - s) u0 + s u1
// and every quantity quadratic in (alpha, beta) has the degree-2 Bernstein coefficients
// (Q(u0, u0), Q(u0, u1), Q(u1, u1)) (Q's polar form in the middle). The rotation
// numerator Rn(alpha, beta) = alpha^2 I + 2 alpha beta [a]x + beta^2 (2 a a^T - |a|^2 I)
// and W = alpha^2 + beta^2 |a|^2 are such forms, so a query point q (relative to the
// fixed point c) is at Y(s) / W(s) with Y = W c + Rn q, and every contact polynomial
// (vertex-plane, plane-vertex, line-line, ball-ball) is W(s) times a QUADRATIC in s
// whose three Bernstein coefficients are linear in the stored primitive's lifted point.
// Its "has a root in the piece" (balls: "is <= 0 somewhere") is then decided exactly by
// a Quadratic clause (range/halfspaces.h) instead of the conservative Bernstein hull.
//
// The "inside the primitive at that root" part is a second level, tested on each
// candidate the tree reports (Root_sides): the quadratic's roots in the piece are
// enclosed (quadratic formula in interval arithmetic; a 64-cell scan when the leading
// coefficient may vanish), and side functions, also quadratics in s linear in a lifted
// point, are evaluated there. The stored triangle's and the edges' sides use lines
// parallel to a coordinate axis e_k: a point y in a plane not parallel to e_k lies in a
// convex polygon of that plane iff the line (e_k, y x e_k) through it meets the polygon,
// i.e. its side products with the polygon's boundary have one sign; two coplanar segments
// cross iff each one's endpoints lie on both sides of the other's line, seen along e_k.
// When the plane is parallel to e_k every such product vanishes and the test passes, so
// each k gives a necessary condition, and the three together are exact: no plane is
// parallel to all three axes.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "range/axis_rotation.h"
#include "range/halfspaces.h"
#include "range/linearize.h"

namespace pccd::range {

// A stored edge's endpoints (a0, a1): the second level of edge-edge under a rotation.
constexpr int kDimEnds = 6;
std::vector<std::array<Interval, kDimEnds>> lift_edge_ends(const Body_data &b);

// "The quadratic f (Bernstein coefficients linear in x1) has a root in [0, 1] at which
// the side conditions may hold": group 1 sides linear in x1, group 2 in x2.
// Side functions (each a quadratic in s, Bernstein coefficients linear in a lifted
// point) and how their values must be signed: Same_sign: all >= 0 or all <= 0;
// All_nonneg: all >= 0; Opposite: two values whose product is <= 0.
enum class Side_mode : uint8_t { Same_sign, All_nonneg, Opposite };
template <int D>
struct Side_set {
  std::vector<std::array<Halfspace<D>, 3>> sides;
  Side_mode mode = Side_mode::Same_sign;
};

template <int D1, int D2>
struct Root_sides {
  std::array<Halfspace<D1>, 3> f;
  std::vector<Side_set<D1>> sets1;  // every set must hold at one root (sets1 on x1,
  std::vector<Side_set<D2>> sets2;  // sets2 on x2)
  // The tree's clause: f has a root in [0, 1].
  Quadratic<D1> clause() const { return {f, Quadratic<D1>::Root}; }
  bool possible(const Interval *x1, const Interval *x2) const;
};

class Rotation_piece {
 public:
  Rotation_piece(const Axis_rotation &ax, const Moving_body &query, double ta, double tb);

  // Ball pairs: the exact clause "|y - c_S|^2 <= (r + rho)^2 somewhere in the piece".
  void add_ball_vs_balls(uint32_t k, Cnf<kDimBall> &q) const;

  // Mesh pairs: clause() goes into the tree query (with Piece_query's box clauses);
  // possible() is the second level on each reported candidate, with x1 = its lifted
  // point and x2 = its triangle sides (kDimSides) / itself / its edge ends (kDimEnds).
  Root_sides<kDimTriangle, kDimSides> vertex_vs_triangle_sides(uint32_t v) const;
  Root_sides<kDimVertex, kDimVertex> triangle_vs_vertex_sides(uint32_t tri) const;
  Root_sides<kDimEdge, kDimEnds> edge_vs_edge_sides(uint32_t e) const;

 private:
  using I3 = std::array<Interval, 3>;
  const Moving_body &q_;
  I3 c_;
  std::array<std::array<I3, 3>, 3> R_;  // R_[j][row]: Bernstein coefficients of Rn
  std::array<Interval, 3> W_;
  std::vector<I3> q_pts_;                // q = y(0) - c of every query point
  std::vector<std::array<I3, 3>> Y_;     // Bernstein coefficients of Y per point

  I3 rot(int j, const I3 &v) const;  // R_j v
};

}  // namespace pccd::range
