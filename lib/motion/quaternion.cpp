#include "motion/quaternion.h"

namespace pccd::motion {

using arith::Rational;

Quat_poly quat_constant(const Quat_q &q) {
  return {Poly_q::constant(q[0]), Poly_q::constant(q[1]), Poly_q::constant(q[2]),
          Poly_q::constant(q[3])};
}

Quat_poly quat_identity() {
  return quat_constant({Rational(1), Rational(0), Rational(0), Rational(0)});
}

Quat_poly quat_mul(const Quat_poly &a, const Quat_poly &b) {
  // (a0, a) (b0, b) = (a0 b0 - a.b, a0 b + b0 a + a x b), written out per component.
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] + a[2] * b[0] + a[3] * b[1] - a[1] * b[3],
          a[0] * b[3] + a[3] * b[0] + a[1] * b[2] - a[2] * b[1]};
}

Quat_poly quat_conj(const Quat_poly &q) { return {q[0], -q[1], -q[2], -q[3]}; }

Poly_q quat_norm2(const Quat_poly &q) {
  return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
}

bool quat_is_zero(const Quat_poly &q) {
  for (const Poly_q &c : q)
    if (!c.c.empty()) return false;  // Poly<Rational> is trimmed: empty = zero
  return true;
}

Mat3_poly rotation_numerator(const Quat_poly &q) {
  const Poly_q &w = q[0];
  const Poly_q two = Poly_q::constant(Rational(2));
  const Poly_q s = w * w - (q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);  // w^2 - |v|^2
  Mat3_poly m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = two * q[1 + i] * q[1 + j];  // 2 v v^T
  for (int i = 0; i < 3; ++i) m[i][i] = m[i][i] + s;
  // 2 w [v]x, with [v]x u = v x u:  [[0, -z, y], [z, 0, -x], [-y, x, 0]].
  const Poly_q wx = two * w * q[1], wy = two * w * q[2], wz = two * w * q[3];
  m[0][1] = m[0][1] - wz;
  m[0][2] = m[0][2] + wy;
  m[1][0] = m[1][0] + wz;
  m[1][2] = m[1][2] - wx;
  m[2][0] = m[2][0] - wy;
  m[2][1] = m[2][1] + wx;
  return m;
}

Vec3p<Rational> mat_vec(const Mat3_poly &m, const Vec3_q &v) {
  Vec3p<Rational> out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i] = out[i] + v[j] * m[i][j];
  return out;
}

Vec3p<Rational> mat_vec(const Mat3_poly &m, const Vec3p<Rational> &v) {
  Vec3p<Rational> out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i] = out[i] + m[i][j] * v[j];
  return out;
}

}  // namespace pccd::motion
