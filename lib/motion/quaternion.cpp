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
  // The ten distinct products q_a q_b once (the entries share them; the products of
  // long polynomials are the whole cost), then their combinations.
  Poly_q p[4][4];
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) p[a][b] = q[a] * q[b];
  const Rational two(2);
  auto twice = [&](const Poly_q &x) { return two * x; };
  const Poly_q &ww = p[0][0], &xx = p[1][1], &yy = p[2][2], &zz = p[3][3];
  Mat3_poly m;
  // Rn = (w^2 - |v|^2) I + 2 v v^T + 2 w [v]x, [v]x = [[0, -z, y], [z, 0, -x], [-y, x, 0]].
  m[0][0] = ww + xx - yy - zz;
  m[1][1] = ww - xx + yy - zz;
  m[2][2] = ww - xx - yy + zz;
  m[0][1] = twice(p[1][2] - p[0][3]);
  m[1][0] = twice(p[1][2] + p[0][3]);
  m[0][2] = twice(p[1][3] + p[0][2]);
  m[2][0] = twice(p[1][3] - p[0][2]);
  m[1][2] = twice(p[2][3] - p[0][1]);
  m[2][1] = twice(p[2][3] + p[0][1]);
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
