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
#pragma once
#include <array>
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

class Chain_path {
 public:
  // Input_error as Chain::segment_motions for a segment it rejects ("q1[k]: ...").
  Chain_path(const Chain &c, const double *q0, const double *q1);
  // The bounds of every link over [a, b], 0 <= a <= b <= 1 (doubles), into out (resized).
  void enclose(double a, double b, std::vector<Pose_bounds> &out) const;
  size_t size() const { return ends_.size(); }

 private:
  const Chain &c_;
  std::vector<Joint_doubles> ends_;
  std::vector<Pose_bounds> origin_;  // each link's origin pose (R of origin_q, p: rho = 0)
  std::vector<arith::Interval> axis2_;  // |a|^2 of each joint axis
  std::vector<std::array<double, 3>> axis_;  // each joint axis (doubles, exact)
};

}  // namespace pccd::motion
