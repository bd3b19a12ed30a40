// One joint-space segment of a chain, enclosed piece by piece in interval arithmetic
// straight from the joint values: no exact motion is built. A robot check (scene/robot.h)
// tests these enclosures against the obstacles' hierarchies and builds the exact link
// motions (Chain::segment_motions) only for the body pairs they cannot separate.
//
// Contract: for every t in [a, b] and every link k, the rotation R_k(t) (the unit rotation
// of the quaternion of link k's motion from Chain::segment_motions on the same q0, q1) and
// its translation o_k(t) satisfy ||R_k(t) - Rm||_2 <= eps and |o_k(t) - om|_2 <= rho
// for the out[k] = {Rm, eps, om, rho} of enclose (a ball in the operator norm: its
// radius grows additively along the chain, where entrywise intervals would wrap by up
// to sqrt(3) per joint).
//
// Where the bounds come from: every number the exact motions take is a double
// (Joint_doubles, the origin quaternion and translation, the axis), and so is every
// number here. Each joint's own factor is first enclosed entrywise over the piece
// T = [a, b] in outward-rounded intervals (arith/interval.h), then as a ball (its
// midpoints, and the Frobenius norm of its radii, >= the operator norm):
//  - revolute: c(T) = c0 + T (c1 - c0), s(T) likewise; the joint quaternion (c, s a)
//    rotates by R = I + alpha [a]x + beta (a a^T - |a|^2 I) with alpha = 2 c s / n,
//    beta = 2 s^2 / n, n = c^2 + s^2 |a|^2 (the unit quaternion's R = I + 2 w [v]x +
//    2 [v]x^2 with v = s a, divided through by n). For an exactly unit axis alpha =
//    sin(theta) and beta = 1 - cos(theta) are clipped to [-1, 1] and [0, 2].
//  - prismatic: the translation e(T) a, e(T) = e0 + T (e1 - e0);
//  - origin: R of the origin quaternion (w, x, y, z) by the textbook numerator / n.
// Balls compose as in Chain (R_k = R_parent R_origin R_joint, o_k = o_parent +
// R_parent (p_origin + R_origin e a)): with ||Rm|| <= 1 + eps (Rm is within eps of a
// rotation), (Rm_A + E_A)(Rm_B + E_B) is within eps_A + eps_B + 3 eps_A eps_B of
// fl(Rm_A Rm_B) plus its rounding error, and R (v + d) within (1 + eps_R) |d| + eps_R
// |v| of fl(Rm v). Rounding: an IEEE operation in any rounding mode errs by at most
// 2u = 2^-52 relative, so a 3-term dot product errs by at most 10u times the sum of its
// terms' magnitudes; every such sum is bounded by norms ((1 + eps_A)(1 + eps_B) for a
// row-column pair, |o| + (1 + eps) |v| for a translation), and the bounds add
// kSlack = 2^-40 (> 30 u, covering also the norms' own rounding) times them, plus
// 1e-300 for underflow. A divisor n that is not certainly positive (a piece so wide
// that c and s may both vanish) gives the joint the ball {0, 1} (||R - 0|| = 1).
//
// Second-order enclosures (derivatives): for every link k, bounds over t in [a, b] of
// ||R_k'(t)||_2 <= d1, ||R_k''(t)||_2 <= d2 and |o_k''(t)|_2 <= o2 (derivatives in t).
// Then for f = R_k or o_k and every t in [a, b], |f(t) - ((1 - s) f(a) + s f(b))| <=
// (t - a)(b - t) / 2 max |f''| <= (b - a)^2 / 8 max |f''| (s = (t - a) / (b - a); the
// interpolation error of a C^2 function, f - L = -int G f'' with the Green's function
// G >= 0 of integral (t - a)(b - t) / 2, for any norm): a link's points over [a, b]
// lie within that of the chords between their poses at a and at b, which is far
// tighter than the ball of enclose once the piece is short (scene/link_filter.h).
// Where they come from: a revolute joint turns by theta(t) = 2 atan2(A s(t), c(t)) about
// its unit axis (A = |a|), so theta' = 2 A K / n with K = c0 s1 - s0 c1 (constant: c, s
// are linear) and n = c^2 + A^2 s^2, and theta'' = -2 A K n' / n^2, n' = 2 (c (c1 - c0)
// + A^2 s (s1 - s0)); its factor J(t) = exp(theta [u]x) has ||J'|| = |theta'| and
// ||J''|| <= theta'^2 + |theta''| (||[u]x|| = ||[u]x^2|| = 1). R_k = R_p O J (the parent's
// rotation, the constant origin rotation, norm 1 each) gives d1_k = d1_p + |theta'| and
// d2_k = d2_p + 2 d1_p |theta'| + theta'^2 + |theta''|; o_k = o_p + R_p v(t), v = p_origin
// (+ O e(t) a for a prismatic joint: v' = O a (e1 - e0), v'' = 0) gives o2_k = o2_p +
// d2_p max|v| + 2 d1_p |v'|. All in outward-rounded intervals (upper ends taken); a piece
// on which n may vanish gives infinite bounds (then only the ball serves).
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "arith/interval.h"
#include "motion/chain.h"

namespace pccd::motion {

struct Pose_bounds {
  double Rm[3][3];
  double eps = 0;  // ||R(t) - Rm||_2 <= eps
  double om[3];
  double rho = 0;  // |o(t) - om|_2 <= rho
};

struct Path_derivs {
  double d1 = 0, d2 = 0, o2 = 0;  // bounds of ||R'||, ||R''||, |o''| over the piece
};

class Chain_path {
 public:
  // Input_error as Chain::segment_motions for a segment it rejects ("q1[k]: ...").
  Chain_path(const Chain &c, const double *q0, const double *q1);
  // The pose bounds (enclose_link) and derivative bounds (derivatives_link) over [a, b],
  // 0 <= a <= b <= 1 (doubles), of link k and its ancestors below base alone, those not
  // yet marked in have (arrays of size() entries, one flag per link, kept by the caller
  // per piece; an unmarked entry's value is never read), relative to link base: base an
  // ancestor of k, or -1 (the world frame).
  // Relative to base, the poses are those of the chain below base with base's pose
  // taken as the identity: the motion of the ancestors that move both links of a
  // self-collision pair alike drops out (scene/robot.h).
  void enclose_link(double a, double b, size_t k, long base, Pose_bounds *out, char *have) const;
  void derivatives_link(double a, double b, size_t k, long base, Path_derivs *out, char *have) const;
  // The lowest link that is i or an ancestor of i and j or an ancestor of j; -1: none.
  long common_ancestor(size_t i, size_t j) const;
  size_t size() const { return ends_.size(); }

 private:
  // Link k over T, its parent's entry of out already made.
  void ball_of_link(size_t k, const arith::Interval &T, Pose_bounds *out, long base) const;
  void derivs_of_link(size_t k, const arith::Interval &T, Path_derivs *out, long base) const;
  const Chain &c_;
  std::vector<Joint_doubles> ends_;
  // Per link, the segment-independent parts, made from the link's doubles alone: its
  // origin pose (R of origin_q, p: rho = 0), axis (doubles, exact), |a|^2, a a^T - |a|^2 I
  // of the revolute factor and |a| enclosed. Shared by the segments of a chain: the
  // thread keeps the last set made (fixed_parts) and hands it out again when every link's
  // doubles (key) and the rounding mode match, so the intervals are the ones a remake
  // would give (remade per segment they were ~3% of a free Panda segment, issue 30).
  struct Link_fixed {
    Pose_bounds origin;
    arith::Interval axis2;
    std::array<double, 3> axis;
    arith::Interval B[3][3];
    arith::Interval A;
    std::array<double, 10> key;  // axis_d, origin_p_d, origin_q_d
  };
  struct Fixed {
    bool nearest;  // made in round-to-nearest (arith/interval.h: exact points then)
    std::vector<Link_fixed> links;
  };
  static std::shared_ptr<const Fixed> fixed_parts(const Chain &c);
  const Link_fixed &fx(size_t k) const { return fixed_->links[k]; }
  std::shared_ptr<const Fixed> fixed_;
  // Per link and segment, made once by the constructor with the same interval operations
  // the per-piece formulas would apply (so the same intervals): the slopes c1 - c0,
  // s1 - s0, and |2 A K| (its upper end), K = c0 (s1 - s0) - s0 (c1 - c0).
  struct Link_consts {
    arith::Interval dc, ds, akt;
  };
  std::vector<Link_consts> consts_;
};

}  // namespace pccd::motion
