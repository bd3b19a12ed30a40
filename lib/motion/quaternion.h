// Quaternions with polynomial components (paper, appendix A), exact over Q.
//
// A quaternion q = w + x i + y j + z k is stored as {w, x, y, z}. Products follow the
// paper's rule  q p = (q0 p0 - q.p,  q0 p + p0 q + q x p); it is associative and
// |q p|^2 = |q|^2 |p|^2 (both as polynomial identities).
//
// The rotation of a nonzero q is R(q) = Rn(q) / W(q) with the numerator matrix
//   Rn(q) = (w^2 - |v|^2) I + 2 v v^T + 2 w [v]x,   v = (x, y, z),
// and W(q) = w^2 + |v|^2 (formats.md; paper, equation (3)). Rn is quadratic in q, so
// for polynomial q(t) every entry is a polynomial of degree <= 2 max deg q_i, and
// R(q) R(p) = R(q p) gives the numerator identity Rn(q) Rn(p) = Rn(q p) exactly.
// R(q) is the rotation by the angle 2 atan(|v| / w) about v (right-handed).
#pragma once
#include <array>

#include "motion/trajectory.h"
#include "poly/poly.h"

namespace pccd::motion {

using Poly_q = poly::Poly<arith::Rational>;
using Vec3_q = std::array<arith::Rational, 3>;

// Components {w, x, y, z}, each a polynomial of t.
using Quat_poly = std::array<Poly_q, 4>;
// Constant quaternion {w, x, y, z}.
using Quat_q = std::array<arith::Rational, 4>;
// 3x3 matrix of polynomials, row-major: m[row][col].
using Mat3_poly = std::array<std::array<Poly_q, 3>, 3>;

// The quaternion with constant components q.
Quat_poly quat_constant(const Quat_q &q);

// The identity rotation 1 + 0 i + 0 j + 0 k.
Quat_poly quat_identity();

// Product a b (not commutative).
Quat_poly quat_mul(const Quat_poly &a, const Quat_poly &b);

// Conjugate w - x i - y j - z k.
Quat_poly quat_conj(const Quat_poly &q);

// Squared norm W = w^2 + x^2 + y^2 + z^2 (= q q*). Zero only for the zero quaternion;
// deg W = 2 max deg q_i exactly (the leading coefficient is a sum of squares).
Poly_q quat_norm2(const Quat_poly &q);

// True when every component is the zero polynomial.
bool quat_is_zero(const Quat_poly &q);

// The rotation numerator Rn(q): R(q) = Rn(q) / quat_norm2(q).
Mat3_poly rotation_numerator(const Quat_poly &q);

// m v for a constant vector v.
Vec3p<arith::Rational> mat_vec(const Mat3_poly &m, const Vec3_q &v);
// m v for a polynomial vector v.
Vec3p<arith::Rational> mat_vec(const Mat3_poly &m, const Vec3p<arith::Rational> &v);

}  // namespace pccd::motion
