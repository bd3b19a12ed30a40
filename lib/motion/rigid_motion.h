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
// body-side pose with a nonzero offset was composed in; it is always a combination of
// entries of Rn(r), so deg b <= deg W.
//
// Composition with constant poses (q a nonzero rational quaternion, R_q = R(q), n_q = |q|^2):
//   body side  x'(t) = M(R_q0 p + p0):   r' = r q0,  b' = n_q0 (Rn(r) p0 + b),  o' = o
//     because Rn(r) R_q0 = Rn(r q0) / n_q0 and W(r q0) = W(r) n_q0;
//   world side x'(t) = R_q1 M(p) + p1:   r' = q1 r,  b' = Rn(q1) b,  o' = R_q1 o + p1
//     because Rn(q1) Rn(r) = Rn(q1 r) and W(q1 r) = n_q1 W(r).
// Degrees never grow: deg r' = deg r, deg o' = deg o, deg b' <= deg W.
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

// "t = 1/2" or "an irrational time t with lo < t < hi" (for messages).
std::string describe_vanishing(const Vanishing &v);

}  // namespace pccd::motion
