// The exact narrow phase of two moving bodies: one feature pair ("primitive pair") at a
// time, through the staged primitive solver (pred/solve.h).
//
// Both bodies' motions are rational, x(t) = X(t) / W(t) with W > 0 on [0, 1]. The pair
// works with the common denominator D = W_A W_B: side A's point trajectories are
// X_A W_B, side B's are X_B W_A, each D times the true position, which every contact
// condition tolerates (pred/query_systems.h: homogeneous in point differences, radii
// times D). Feature pairs (why they cover every first contact: see pair_search.h):
//   VF  surface vertex of A / closed triangle of B     FV  triangle of A / vertex of B
//   EE  closed edge of A / closed edge of B            TT  triangles of A and B at t = 0
//   SS  ball of A / ball of B                          ST  ball of A / closed triangle of B
//   TS  closed triangle of A / ball of B
//   IN_A  point b of B strictly inside solid A at t = 0 (a = 0; narrow/containment.h)
//   IN_B  point a of A strictly inside solid B at t = 0 (b = 0)
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "narrow/irrational_memo.h"
#include "narrow/moving_body.h"
#include "narrow/point_memo.h"
#include "pred/solve.h"
#include "pred/static_contact.h"

namespace pccd::narrow {

enum Prim_type : uint8_t { VF = 0, FV = 1, EE = 2, SS = 3, ST = 4, TS = 5, TT = 6, IN_A = 7, IN_B = 8 };

// a and b index side A's and side B's elements of the types the Prim_type names
// (vertex, edge, triangle or ball).
struct Prim_pair {
  uint8_t type = 0;
  uint32_t a = 0, b = 0;
  uint64_t key() const { return (uint64_t(type) << 58) | (uint64_t(a) << 29) | uint64_t(b); }
  bool operator<(const Prim_pair &o) const { return key() < o.key(); }
  bool operator==(const Prim_pair &o) const { return key() == o.key(); }
};

// Feature of one body in a reported contact (values of pccd_feature in polyccd.h).
// F_SOLID: the whole solid of a solid mesh (index 0), holding the other body's point.
enum Feature_type : uint8_t { F_VERTEX = 0, F_EDGE = 1, F_TRIANGLE = 2, F_SPHERE = 3, F_SOLID = 4 };
struct Feature_ref {
  uint8_t type = 0;
  uint32_t index = 0;
  bool operator<(const Feature_ref &o) const {
    return type != o.type ? type < o.type : index < o.index;
  }
  bool operator==(const Feature_ref &o) const { return type == o.type && index == o.index; }
};

class Pair_ctx {
 public:
  Pair_ctx(const Moving_body &a, const Moving_body &b);
  const Moving_body &side(int s) const { return s == 0 ? A_ : B_; }

  // The scaled trajectory of point k of side s (exact, and coefficient enclosures).
  motion::Point_traj<Rational> traj_q(int s, uint32_t k) const;
  motion::Point_traj<Interval> traj_i(int s, uint32_t k) const;

  // Solves one primitive pair (not TT, IN_A, IN_B).
  pred::Contact_result solve(const Prim_pair &p, const pred::Solve_options &opt) const;
  // TT: the closed triangles a (of A) and b (of B) share a point at t = 0 (exact).
  bool triangles_meet_at_zero(uint32_t a, uint32_t b) const;
  // The closed edge e of side s (a mesh) and the closed triangle t of side 1 - s share a
  // point at t = 0 (exact; the static pass of the range phase, range/range_index.h).
  bool edge_meets_triangle_at_zero(int s, uint32_t e, uint32_t t) const;
  // VF, FV, EE (other types: false): the closed primitives are within distance
  // opt.delta at t = 0, decided exactly (interval filter, then rationals): the static
  // test pred::solve makes of such a pair with a minimum separation, without building
  // the pair's trajectories (the witness pass of scene/pair_search.h).
  bool within_at_zero(const Prim_pair &p, const pred::Solve_options &opt) const;

  // The (side, index of that side's points) of p's query points, in the order of its
  // query (the vertex or edge of A first), for VF, FV and EE; their count, 0 for others.
  int query_points(const Prim_pair &p, Query_irrational::Points &out) const;

  // The feature pairs a result reports, as features of the two bodies (deduplicated).
  std::vector<std::pair<Feature_ref, Feature_ref>> contacts(const Prim_pair &p,
                                                           const pred::Contact_result &r) const;

 private:
  // The same point on its side's own homogeneous motion, Rn_s p + O_s: the scaled
  // trajectory divided by the other side's W (pred::Query_data::own; NT = Rational or
  // Interval, exact or coefficient enclosures).
  template <class NT> motion::Point_traj<NT> own(int s, uint32_t k) const;
  // x + Rn_s v: a body-frame direction v on side s's motion (times W_s) added to x.
  template <class NT> void add_rotated(motion::Point_traj<NT> &x, int s, const motion::Point3_q &v) const;

  const Moving_body &A_, &B_;
  // The common-denominator trajectories' polynomials, made once by init() (lazily; a
  // pair with no candidate, such as a far-apart one, never makes or frees them).
  struct Common {
    std::array<motion::Mat3_poly, 2> M;  // Rn_s W_other
    std::array<motion::Vec3p<Rational>, 2> N;  // O_s W_other
    std::array<std::array<std::array<poly::Poly<Interval>, 3>, 3>, 2> Mi;
    std::array<motion::Vec3p<Interval>, 2> Ni;
    Poly_q D;
    poly::Poly<Interval> Di;
  };
  mutable std::once_flag once_;
  mutable std::unique_ptr<const Common> c_;
  // traj_q, traj_i and own per point, made once (point_memo.h).
  mutable Point_memo<motion::Point_traj<Rational>> traj_q_, own_q_;
  mutable Point_memo<motion::Point_traj<Interval>> traj_i_, own_i_;
  // Features proven to touch at irrational times only (irrational_memo.h).
  mutable Irrational_memo irrational_;

  const Common &init() const;
  std::unique_ptr<const Common> compute() const;

  // scaled: set the query's scale D for every kind (balls always have it; point kinds
  // need it with a minimum separation).
  template <class NT> pred::Query_data<NT> query(const Prim_pair &p, bool scaled) const;
  std::array<uint32_t, 3> triangle(int s, uint32_t t) const;
  // Points ids of side s at t = 0 times D(0) > 0 (exact, or enclosures for Interval).
  template <class NT, size_t K>
  std::array<pred::Vec3<NT>, K> at_zero(int s, const std::array<uint32_t, K> &ids) const;
};

}  // namespace pccd::narrow
