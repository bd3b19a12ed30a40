// The common rigid motions, built exactly (paper, section 2: constant or linearly
// changing position and orientation; appendix A: rotation about a fixed axis by
// linear interpolation of quaternions).
//
// Translations are paths of the body origin, each coordinate a polynomial of t of
// degree <= 3; setting one on a motion keeps its rotation (Rigid_motion::set_translation).
#pragma once
#include <array>
#include <string>

#include "motion/quaternion.h"
#include "motion/rigid_motion.h"

namespace pccd::motion {

// p0 + (p1 - p0) t: p0 at t = 0, p1 at t = 1.
Vec3p<arith::Rational> linear_path(const Vec3_q &p0, const Vec3_q &p1);

// The cubic Bezier curve of control points c[0..3]:
//   (1-t)^3 c0 + 3 (1-t)^2 t c1 + 3 (1-t) t^2 c2 + t^3 c3,
// in ascending powers c0 + 3 (c1 - c0) t + 3 (c0 - 2 c1 + c2) t^2 + (c3 - 3 c2 + 3 c1 - c0) t^3.
// Passes through c0 (t = 0) and c3 (t = 1) with tangents 3 (c1 - c0) and 3 (c3 - c2).
Vec3p<arith::Rational> bezier_path(const std::array<Vec3_q, 4> &c);

// The cubic Hermite curve with position p0 and velocity v0 at t = 0, p1 and v1 at t = 1:
//   p0 + v0 t + (3 (p1 - p0) - 2 v0 - v1) t^2 + (2 (p0 - p1) + v0 + v1) t^3.
Vec3p<arith::Rational> hermite_path(const Vec3_q &p0, const Vec3_q &v0, const Vec3_q &p1,
                                    const Vec3_q &v1);

// Rotation about the fixed axis through `center` with direction `axis` (nonzero, any
// length), by the linear quaternion interpolation r(t) = (1, tau(t) axis) with
// tau(t) = tau0 + (tau1 - tau0) t. At time t the body is turned by the angle theta(t)
// about the axis (right-handed) with tan(theta(t) / 2) = tau(t) |axis|: a rational tau
// gives an exact rational rotation even when |axis| is irrational. The body point at
// `center` (and every point of the axis line) stays fixed:
//   x(t) = R(r(t)) (p - c) + c,  i.e.  b = -Rn(r) c, o = c.
// r never vanishes (w = 1). Input_error when axis is zero.
Rigid_motion axis_rotation(const Vec3_q &axis, const Vec3_q &center, const arith::Rational &tau0,
                           const arith::Rational &tau1);

// axis_rotation plus the translation advance * t * axis along the axis: over [0, 1] the
// body moves by advance * axis, a distance |advance| |axis| (advance is the distance
// itself when axis is a unit vector).
Rigid_motion screw(const Vec3_q &axis, const Vec3_q &center, const arith::Rational &tau0,
                   const arith::Rational &tau1, const arith::Rational &advance);

// The motion between two poses: the body origin moves linearly, o(t) = (1 - t) p0 + t p1,
// and the rotation quaternion is interpolated linearly, r(t) = (1 - t) q0 + t q1', where
// q1' = q1 or -q1 (the same rotation), the one with q0 . q1' >= 0, so that r(t) never
// vanishes and the body turns the shorter way round (the rotation of r(t) / |r(t)| runs
// along the great arc from q0 to q1', not at a constant angular speed). At t = 0 the pose
// is exactly (R(q0), p0), at t = 1 exactly (R(q1), p1). Input_error "q0: ..." or "q1: ..."
// when a quaternion is zero.
Rigid_motion pose_between(const Vec3_q &p0, const Quat_q &q0, const Vec3_q &p1, const Quat_q &q1);

// The unit quaternion (w, x, y, z) of the 3x3 rotation block R (row-major) of a pose
// matrix, computed in doubles (Shepperd's method: the largest of w, x, y, z from the
// trace and the diagonal, the others from sums and differences of the off-diagonal
// entries), and the check that R is a rotation: Input_error naming `name` when an entry
// is not finite, when some entry of R^T R - I exceeds 1e-6 in magnitude, or when
// det R <= 0 (a reflection). The exact rotation R(q) of the returned doubles differs
// from R by about the rounding of this computation (1e-15 for an orthonormal R).
Quat_q quaternion_of_rotation(const double R[9], const std::string &name);

}  // namespace pccd::motion
