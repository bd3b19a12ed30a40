// Exact detection of a relative rotation about a fixed axis (the case of Schömer and
// Thiel's rotation linearization; range/LINEARIZATION.md, "Rotations about a fixed
// axis").
//
// In the stored body's frame a query point p is at y_p(t) = R_rel(t) p + v(t) with the
// relative rotation quaternion rho(t) = conj(r_S(t)) r_Q(t) (R(conj q) = R(q)^T, and
// R(q1) R(q2) = R(q1 q2)). When rho has degree <= 1 exactly, rho(t) = rho0 + t rho1,
//   E(t) := rho(t) conj(rho0) = |rho0|^2 + t e,   e = rho1 conj(rho0),
// is (alpha(t), t a) with alpha(t) = |rho0|^2 + t e_w and the fixed vector a = vec(e):
// R_rel(t) = R(E(t)) R(rho0), a rotation about the fixed direction a after the
// constant rotation R(rho0) (E(0) is a positive scalar). When moreover some point c of
// the stored frame is fixed by the relative motion,
//   y_p(t) - c = R(E(t)) (y_p(0) - c)   for every p,
// the query body turns about the line through c with direction a, with the half-angle
// tangent t |a| / alpha(t). This holds iff v(t) - c = R(E(t)) (v(0) - c) for all t, a
// polynomial identity that is linear in c; it is solved exactly over the rationals.
// Screws, general polynomial motions and constant relative rotations (a = 0) are not
// this case.
#pragma once
#include <array>
#include <optional>

#include "narrow/moving_body.h"

namespace pccd::range {

using arith::Interval;
using arith::Rational;
using motion::Poly_q;
using narrow::Body_data;
using narrow::Moving_body;
using narrow::Relative_pose;
using narrow::relative_pose;

// Enclosures of the exact quantities above (stored-body frame).
struct Axis_rotation {
  using I3 = std::array<Interval, 3>;
  I3 a;                     // axis direction (not normalised)
  Interval a2;              // |a|^2
  Interval alpha0, alpha1;  // alpha(t) = alpha0 + alpha1 t; E(t) = (alpha(t), t a)
  I3 c;                     // a fixed point on the axis
  // y_p(0) - c = M0 p + v0 for a query body point p (body coordinates).
  std::array<I3, 3> M0;
  I3 v0;
};

// The relative motion of `query` in `stored`'s frame, when it is a rotation about a fixed
// axis as described above (decided exactly); nullopt otherwise.
std::optional<Axis_rotation> detect_axis_rotation(const Moving_body &stored, const Moving_body &query);

}  // namespace pccd::range
