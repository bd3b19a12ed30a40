// Linearizations of the contact conditions (paper section 3; derivations in
// range/LINEARIZATION.md): a stored body's primitives become lifted points, a query
// primitive over a time piece becomes a conjunction of clauses of closed halfspaces
// (range/halfspaces.h) that every lifted point of a stored primitive it may touch
// during the piece satisfies.
//
// The query body moves relative to the stored body's frame:
//   y(t) = R_S(t)^T (x_Q(t) - o_S(t)) = (M(t) p + u(t)) / w(t),
//   M = Rn_S^T W_S Rn_Q,  u = Rn_S^T (W_S O_Q - W_Q O_S),  w = W_S^2 W_Q > 0,
// (x = (Rn p + O) / W for both bodies, Rn = W R). Stored primitives are constant in
// that frame. Each contact condition is a polynomial in t that is LINEAR in the lifted
// point s of the stored primitive, f(t) = sum_k s_k c_k(t) + c_0(t); on a piece its
// Bernstein coefficients beta_j = sum_k s_k B(c_k)_j + B(c_0)_j are linear in s too,
// and f can vanish (be >= 0, <= 0) somewhere on the piece only if
// min_j beta_j <= 0 <= max_j beta_j (some beta_j >= 0, <= 0): clauses of halfspaces.
//
// Lifted points (body frame of the stored body; D = dimension):
//   vertex p                   (p)                                      D = 3
//   triangle a0 a1 a2          (n, n . a0, lo, hi)                      D = 10
//   edge a0 a1                 (a1 - a0, a0 x a1, lo, hi)               D = 12
//   ball c, r                  (c, |c|^2 - r^2, r)                      D = 5
// with n = (a1 - a0) x (a2 - a0) and lo, hi the corners of the primitive's box.
#pragma once
#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <vector>

#include "range/axis_rotation.h"
#include "range/halfspaces.h"
#include "narrow/moving_body.h"

namespace pccd::range {

constexpr int kDimVertex = 3, kDimTriangle = 10, kDimEdge = 12, kDimBall = 5;
// Plücker coordinates (direction, moment) of a triangle's three sides a0a1, a1a2, a2a0:
// the second level of the stored triangles under a linear translation (not in the tree).
constexpr int kDimSides = 18;

using IPoly = poly::Poly<Interval>;

// Interval boxes of the exact lifted points, indexed like the body's primitives
// (vertices: only those listed in `ids`, in that order).
std::vector<std::array<Interval, kDimVertex>> lift_vertices(const Body_data &b,
                                                           const std::vector<uint32_t> &ids);
std::vector<std::array<Interval, kDimTriangle>> lift_triangles(const Body_data &b);
std::vector<std::array<Interval, kDimEdge>> lift_edges(const Body_data &b);
std::vector<std::array<Interval, kDimBall>> lift_balls(const Body_data &b);
std::vector<std::array<Interval, kDimSides>> lift_triangle_sides(const Body_data &b);

// The body's rotation (hence W) constant and its translation of degree <= 1, exactly.
bool is_linear_translation(const Moving_body &b);

// The query body's homogeneous motion in the stored body's frame, in t.
struct Relative_motion {
  std::array<std::array<IPoly, 3>, 3> M;
  std::array<IPoly, 3> u;
  IPoly w;
  // Exactly (from the rational motions): both rotations and W constant, both
  // translations of degree <= 1. Then every query point moves on a segment relative to
  // the stored body, all by the same vector, and Piece_query adds the exact conditions
  // of the translation linearization (LINEARIZATION.md, "Linear translations").
  bool linear_translation = false;
  // Exactly: a rotation about a fixed axis (range/axis_rotation.h); then Range_index adds
  // the exact conditions of range/rotation_query.h.
  std::optional<Axis_rotation> axis_rotation;
  Relative_motion(const Moving_body &stored, const Moving_body &query);
  // Float estimate of the relative pose at t (for choosing pieces only).
  struct Pose {
    double M[3][3], u[3], w;
    std::array<double, 3> apply(const std::array<double, 3> &p) const {
      std::array<double, 3> y;
      for (int i = 0; i < 3; ++i) y[i] = (M[i][0] * p[0] + M[i][1] * p[1] + M[i][2] * p[2] + u[i]) / w;
      return y;
    }
  };
  Pose approx(double t) const;
};

// The query primitives of one body over one time piece [a, b] (reparametrized to
// s in [0, 1]). Each query has two stages: *_boxes gives the cheap clauses (the stored
// primitive's box meets the query primitive's, at the same time); add_* appends the
// contact conditions (the costly polynomial products) to them. The caller may test the
// cheap clauses against the whole tree first (Range_tree::may_hit).
class Piece_query {
 public:
  // only: when not null, the query points prepared (the others are left empty, and
  // the queries may use only primitives whose points are all in it); null: every point.
  using Ids = std::vector<uint32_t>;
  Piece_query(const Relative_motion &rel, const Moving_body &query, double a, double b, const Ids *only = nullptr);

  // query triangle, stored vertices
  Cnf<kDimVertex> triangle_vs_vertices_boxes(uint32_t tri) const;
  void add_triangle_vs_vertices(uint32_t tri, Cnf<kDimVertex> &q) const;
  // query vertex, stored triangles
  Cnf<kDimTriangle> vertex_vs_triangles_boxes(uint32_t v) const;
  void add_vertex_vs_triangles(uint32_t v, Cnf<kDimTriangle> &q) const;
  // query edge, stored edges
  Cnf<kDimEdge> edge_vs_edges_boxes(uint32_t e) const;
  void add_edge_vs_edges(uint32_t e, Cnf<kDimEdge> &q) const;
  // query ball, stored balls
  Cnf<kDimBall> ball_vs_balls_boxes(uint32_t k) const;
  void add_ball_vs_balls(uint32_t k, Cnf<kDimBall> &q) const;
  // Linear translations only (Relative_motion::linear_translation): the Plücker side
  // conditions, "the line of the relative motion meets the closed triangle /
  // parallelogram", as clauses "all sides >= 0 or all sides <= 0".
  // query triangle, stored vertices (3-D, appended to q):
  void add_translation_sides_vs_vertices(uint32_t tri, Cnf<kDimVertex> &q) const;
  // query vertex, stored triangles' sides (lift_triangle_sides; a second level):
  Cnf<kDimSides> translation_sides_vs_triangles(uint32_t v) const;
  // query edge, stored edges (Plücker coordinates 0..5 of the edge lift, appended to q):
  void add_translation_sides_vs_edges(uint32_t e, Cnf<kDimEdge> &q) const;
  bool linear_translation() const { return translation_; }

  // A piece of one instant (a = b; the static test at t = 0, Range_index): query
  // triangle, stored triangles whose boxes meet its box; then (add_) the query
  // triangle's corners are not all strictly on one side of the stored triangle's plane,
  // "some n . H_i - (n . a0) w >= 0" and "some <= 0" (linear in the lifted n, n . a0;
  // necessary for two closed triangles to meet).
  Cnf<kDimTriangle> triangle_vs_triangles_boxes(uint32_t tri) const;
  void add_triangle_vs_triangle_planes(uint32_t tri, Cnf<kDimTriangle> &q) const;
  // The same instant: query triangle, stored edges whose boxes meet its box; then (add_) the stored edge's line
  // meets the closed triangle: its side products with the triangle's three sides (from
  // the corners at the instant) are all >= 0 or all <= 0 (all 0 when the line lies in
  // the triangle's plane or the triangle is degenerate; linear in the Plücker
  // coordinates 0..5 of the edge lift; necessary for the closed edge to meet it).
  Cnf<kDimEdge> triangle_vs_edges_boxes(uint32_t tri) const;
  void add_triangle_vs_edge_sides(uint32_t tri, Cnf<kDimEdge> &q) const;

  // ball and triangle: boxes only (the distance to a plane is not linear in it)
  Cnf<kDimBall> triangle_vs_balls_boxes(uint32_t tri) const;
  Cnf<kDimTriangle> ball_vs_triangles_boxes(uint32_t k) const;

 private:
  const Moving_body &q_;
  bool translation_ = false;
  std::vector<Interval> w_, w2_;  // scaled Bernstein forms (range/scaled_bernstein.h)
  std::vector<std::array<std::vector<Interval>, 3>> H_;  // homogeneous trajectory of every query point

  // Per query point, an enclosure of each coordinate of its position over the piece
  // (empty when some Bernstein coefficient of w is not certainly > 0).
  std::vector<std::array<Interval, 3>> ybox_;

  const std::array<std::vector<Interval>, 3> &H(uint32_t point) const { return H_[point]; }
  template <int D>
  void box_conditions(Cnf<D> &q, std::initializer_list<uint32_t> pts, int lo_at, int hi_at,
                      const Interval *rho = nullptr) const;
  // Homogeneous position (weight w_[0]) of a query point at the piece's start (end).
  std::array<Interval, 3> start(uint32_t point) const;
  std::array<Interval, 3> end(uint32_t point) const;
};

}  // namespace pccd::range
