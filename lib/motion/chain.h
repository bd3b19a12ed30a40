// Kinematic chains (trees) of links with fixed, revolute, continuous and prismatic
// joints (URDF's conventions), and the exact rigid motion of every link over one
// joint-space segment q0 -> q1.
//
// Link k hangs from its parent (or from the world frame, parent -1) by its joint:
//   X_parent = T_origin J_k(q) X_k,
// T_origin the constant origin pose (translation xyz, rotation from roll-pitch-yaw
// R = Rz(yaw) Ry(pitch) Rx(roll), URDF's convention), J_k the joint's own motion along
// or about the axis a (a nonzero vector of the joint frame, any length). A link's world
// motion is the composition of the joints above it (compose_motions), so its rotation
// quaternion has degree = the number of revolute or continuous joints above it.
//
// Where the numbers come from (every input is a double, taken as its exact binary value):
//  - origin rotation: the quaternion qz(yaw) qy(pitch) qx(roll) of the half-angle
//    cosines and sines, evaluated in doubles (round-to-nearest, lib/api's guard) and
//    then taken EXACTLY: any nonzero rational quaternion is an exact rotation, within
//    about 1e-16 of the roll-pitch-yaw one.
//  - revolute / continuous joint over theta0 -> theta1: the joint quaternion
//    r_j(t) = (c(t), s(t) a), c and s linear in t, interpolating the exact doubles
//    (c_i, s_i) = (cos(theta_i / 2), sin(theta_i / 2) / |a|) (|a| = 1 exactly for a unit
//    axis; else the double nearest sqrt(|a|^2)). Then tan(theta(t) / 2) = s(t) |a| / c(t)
//    interpolates the half-angle tangent as the paper's appendix A does, the motion is
//    an exact rotation about a, and it turns the short way between the two half-angle
//    directions, which is the requested way as long as |theta1 - theta0| < 2 pi.
//    Policy (revolute and continuous alike; limits are not checked here): a segment with
//    |theta1 - theta0| >= 2 pi is rejected (split it); so is one with
//    |theta1 - theta0| > pi whose rounded endpoints would be interpolated the other way
//    round (within rounding of 2 pi; decided exactly on (c_i, s_i)). r_j never vanishes
//    otherwise: c(t), s(t) vanish together only for antipodal endpoints.
//  - prismatic joint over d0 -> d1: the translation e(t) a, e linear between the doubles
//    e_i = d_i / |a| (exactly d_i for a unit axis).
//  - joint values at a time t (outputs, never decisions): revolute theta0 plus twice
//    the angle from (c0, s0 |a|) to (c(t), s(t) |a|), prismatic e(t) |a|, in doubles.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "motion/rigid_motion.h"

namespace pccd::motion {

enum class Joint_type { fixed = 0, revolute = 1, continuous = 2, prismatic = 3 };

struct Chain_link {
  long parent = -1;                  // an earlier link, or -1 for the world frame
  Joint_type joint = Joint_type::fixed;
  Vec3_q axis{};                     // nonzero unless fixed
  double axis_norm = 1;              // the double nearest |axis| (exactly 1 for a unit axis)
  Quat_q origin_q{};                 // exact, from the roll-pitch-yaw doubles
  Vec3_q origin_p{};
  // The nearest doubles of axis, origin_q and origin_p (the interval path of
  // motion/chain_path.h takes them on every segment), converted once, by add_link.
  std::array<double, 3> axis_d{}, origin_p_d{};
  std::array<double, 4> origin_q_d{};
  std::string value_place;           // errors name the joint value "q0" + this ("": "[k]")
};

// The doubles a joint's exact motion interpolates (taken exactly by segment_motions; the
// interval path of motion/chain_path.h encloses the same): revolute and continuous
// (c_i, s_i) = (cos(q_i / 2), sin(q_i / 2) / |a|); prismatic e_i = q_i / |a|.
struct Joint_doubles {
  double c0 = 1, s0 = 0, c1 = 1, s1 = 0;
  double e0 = 0, e1 = 0;
};
Joint_doubles joint_doubles(const Chain_link &L, double q0, double q1);

// Called with (k, link k's world motion) as soon as segment_motions has built it: a
// caller's limit on the motions' numbers (api: config.max_number_bits) stops the
// segment at the first link beyond it, before its children are composed.
using Link_check = std::function<void(size_t, const Rigid_motion &)>;

class Chain {
 public:
  // Appends a link; returns its index. Input_error naming "parent", "joint",
  // "axis" / "axis[i]", "xyz[i]", "rpy[i]" (non-finite, zero axis, parent not earlier).
  size_t add_link(long parent, int joint, const double *axis, const double xyz[3],
                  const double rpy[3]);
  size_t size() const { return links_.size(); }
  // How errors about link k's joint value name it after "q0" / "q1" (default "[k]"): a
  // caller whose values are numbered otherwise says so, e.g. "[2] (elbow)".
  void set_value_place(size_t k, std::string place) { links_.at(k).value_place = std::move(place); }
  const Chain_link &link(size_t k) const { return links_[k]; }

  // The world motion of every link over the segment q0 -> q1 (q[k]: the value of link
  // k's joint; ignored for fixed joints). Input_error "q0[k]" / "q1[k]" for a
  // non-finite value, "q1[k]" for a revolute segment the policy above rejects.
  // rn: when given, also rotation_numerator(r) of every link's motion (computed once
  // per link: each serves its children's compositions and the link's own data).
  // needed: when given (one flag per link), only the needed links' motions and their
  // ancestors' are built; the others are left as the identity (a robot check builds
  // the motions of the links its filter cannot clear: scene/robot.h).
  // check: when given, called on every link built (Link_check). The products are
  // counted by cost (poly.h), so the calling thread's work limits hold inside.
  // base >= 0: the motions in link base's frame instead of the world's: base is the
  // identity, a link below it the composition of the joints between them, and the links
  // not below base are left as the identity. Two links at or below base have the same
  // relative pose at every t in either frame (each world motion is base's world motion
  // composed with these, exactly), so every distance and contact time between them is
  // the same; the polynomials are of far lower degree (scene/robot.cpp: self pairs).
  std::vector<Rigid_motion> segment_motions(const double *q0, const double *q1,
                                            std::vector<Mat3_poly> *rn = nullptr,
                                            const std::vector<bool> *needed = nullptr,
                                            const Link_check *check = nullptr, long base = -1) const;
  // Input_error as segment_motions for a segment it would reject, without building.
  void check_segment(const double *q0, const double *q1) const;
  // The joint values at time t in [0, 1] of the same segment (as above; fixed: 0).
  std::vector<double> joint_values(const double *q0, const double *q1, const arith::Rational &t) const;

 private:
  // The joint's motion in its parent's frame: T_origin J_k(t).
  Rigid_motion joint_motion(size_t k, double q0, double q1) const;
  std::vector<Chain_link> links_;
};

}  // namespace pccd::motion
