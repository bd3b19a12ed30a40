// Exact rigid motions over t in [0, 1] (paper, section 2 and appendix A).
//
// A body point p (body coordinates) is at x(t) = R(r(t)) p + o(t): r(t) is a quaternion
// polynomial that need not have unit length and R = Rn / W (motion/quaternion.h).
// Composing with constant poses keeps every coordinate a rational function with the
// common denominator W(t) = |r(t)|^2, so a motion is kept in the HOMOGENEOUS form
//
//   x(t) = (Rn(r(t)) p + b(t)) / W(t) + o(t)  =  (Rn(r(t)) p + O(t)) / W(t),
//   O(t) = b(t) + W(t) o(t),
//
// with polynomials r (4), o (3) and b (3). The homogeneous offset O is split in two
// parts so that the polynomial translation o keeps its meaning (the path of the body
// origin when b = 0) while r is edited component by component, and so that o never
// has to be multiplied by W before a point trajectory is asked for. b is zero unless a
// body-side pose with a nonzero offset or another motion was composed in. The invariant
// is only that r, o and b are polynomials (W > 0 on [0, 1] once validated): after
// constant poses deg b <= deg W still holds (b is then a combination of entries of
// Rn(r)), but a composition of motions puts the inner motion's translation into b, so
// deg b may exceed deg W (e.g. deg b = deg O_inner + 2 deg r_outer). Every consumer
// reads the homogeneous pair (O, W) (point_trajectory, narrow::prepare_body, the boxes,
// bvh and range broad phases), whatever the degrees; only set_rotation needs b = 0.
//
// Composition with constant poses (q a nonzero rational quaternion, R_q = R(q), n_q = |q|^2):
//   body side  x'(t) = M(R_q0 p + p0):   r' = r q0,  b' = n_q0 (Rn(r) p0 + b),  o' = o
//     because Rn(r) R_q0 = Rn(r q0) / n_q0 and W(r q0) = W(r) n_q0;
//   world side x'(t) = R_q1 M(p) + p1:   r' = q1 r,  b' = Rn(q1) b,  o' = R_q1 o + p1
//     because Rn(q1) Rn(r) = Rn(q1 r) and W(q1 r) = n_q1 W(r).
// Degrees never grow: deg r' = deg r, deg o' = deg o, deg b' <= max(deg b, deg W).
//
// Composition of two motions (compose_motions), x(t) = M_outer(M_inner(p)) at the same t:
//   M_inner(p) = (Rn_i p + O_i) / W_i, so
//   M_outer(M_inner(p)) = (Rn_o (Rn_i p + O_i) / W_i + O_o) / W_o
//                       = (Rn(r_o r_i) p + Rn_o O_i + W_i O_o) / (W_o W_i)
//   because Rn(r_o) Rn(r_i) = Rn(r_o r_i) and W(r_o r_i) = W_o W_i. Hence
//   r = r_o r_i,  W = W_o W_i,  O = Rn(r_o) O_i + W_i O_o,
// kept as o = o_o and b = Rn(r_o) O_i + W_i b_o (then b + W o = O). When r_o is a
// constant q, o = R(q) o_i + o_o and b = Rn(q) b_i + W_i b_o instead (the same O; the
// translation stays polynomial and b stays zero when both b are zero). r(t) = 0 iff
// r_o(t) = 0 or r_i(t) = 0 (|r_o r_i| = |r_o| |r_i|), so the composite is valid iff
// both factors are; compose_motions checks each and names it.
#pragma once
#include <array>
#include <string>

#include "motion/quaternion.h"

namespace pccd::motion {

// x(t) = X(t) / W(t), W > 0 on [0, 1] for a valid motion.
struct Homogeneous_traj {
  Vec3p<arith::Rational> X;
  Poly_q W;
};

// Where r(t) first vanishes on [0, 1].
struct Vanishing {
  bool vanishes = false;      // r(t) = 0 for some t in [0, 1] (or r is identically 0)
  bool identically = false;   // r is the zero polynomial
  bool exact = false;         // the first such time is t = lo = hi
  arith::Rational lo, hi;     // else lo < t < hi, hi - lo <= 1e-12, t irrational
};

struct Rigid_motion {
  Quat_poly r = quat_identity();  // rotation quaternion {w, x, y, z}
  Vec3p<arith::Rational> o;       // polynomial part of the translation
  Vec3p<arith::Rational> b;       // body-side offsets, numerator over W (see above)

  // Sets o[axis] := f and b[axis] := 0: afterwards coordinate `axis` of the body
  // origin's path is f(t). The rotation is kept. axis in 0..2.
  void set_translation(int axis, Poly_q f);
  // Sets the whole translation (b := 0), keeping the rotation.
  void set_translation(const Vec3p<arith::Rational> &path);
  // Sets component `c` (0 = w, 1 = x, 2 = y, 3 = z) of r, keeping o. Precondition:
  // has_body_offset() is false (b is tied to the old r); Internal_error otherwise.
  void set_rotation(int c, Poly_q f);
  bool has_body_offset() const;

  // W = |r|^2 and O = b + W o: x(t) = (Rn(r(t)) p + O(t)) / W(t).
  Poly_q denominator() const;
  Vec3p<arith::Rational> offset_numerator() const;

  // The trajectory of body point p as X(t) / W(t).
  Homogeneous_traj point_trajectory(const Vec3_q &p) const;

  // The exact position of body point p at time t. Input_error when t is outside
  // [0, 1] or r(t) = 0.
  Vec3_q position(const Vec3_q &p, const arith::Rational &t) const;

  // Where r(t) vanishes first on the closed [0, 1] (exact decision; see the .cpp).
  Vanishing vanishing() const;
  // Input_error when r vanishes somewhere on [0, 1] (or is identically zero); the
  // message gives the first such time, exactly or enclosed.
  void validate() const;

  // Composition with constant poses (formulas above). Input_error when q is zero.
  void compose_body(const Quat_q &q0, const Vec3_q &p0);
  void compose_world(const Quat_q &q1, const Vec3_q &p1);
};

// outer o inner (formulas above): x(t) = outer(inner(p, t), t). Input_error
// "outer: ..." / "inner: ..." when that factor's r vanishes on [0, 1] (checked first:
// outer, then inner).
Rigid_motion compose_motions(const Rigid_motion &outer, const Rigid_motion &inner);
// The same without the vanishing checks, for factors known to be valid (motion/chain.h).
// Rn_outer: rotation_numerator(outer.r) when the caller has it (a chain reuses each
// link's for its children and its data), else computed here.
Rigid_motion compose_valid(const Rigid_motion &outer, const Rigid_motion &inner,
                           const Mat3_poly *Rn_outer = nullptr);

// "t = 1/2" or "an irrational time t with lo < t < hi" (for messages).
std::string describe_vanishing(const Vanishing &v);

}  // namespace pccd::motion
