#include "motion/standard_motions.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>


namespace pccd::motion {

using arith::Input_error;
using arith::Rational;
using V3 = Vec3p<Rational>;

namespace {

// The polynomial c[0] + c[1] t + ... of each coordinate: coordinate i of power k is c[k][i].
V3 path(const std::vector<Vec3_q> &c) {
  V3 out;
  for (int i = 0; i < 3; ++i) {
    std::vector<Rational> coeffs;
    for (const Vec3_q &ck : c) coeffs.push_back(ck[i]);
    out[i] = Poly_q(std::move(coeffs));
  }
  return out;
}

Vec3_q lin(const Rational &a, const Vec3_q &x, const Rational &b, const Vec3_q &y) {
  return {a * x[0] + b * y[0], a * x[1] + b * y[1], a * x[2] + b * y[2]};
}

}  // namespace

V3 linear_path(const Vec3_q &p0, const Vec3_q &p1) { return path({p0, lin(1, p1, -1, p0)}); }

V3 bezier_path(const std::array<Vec3_q, 4> &c) {
  return path({c[0], lin(3, c[1], -3, c[0]), lin(3, lin(1, c[0], -2, c[1]), 3, c[2]),
               lin(1, lin(1, c[3], -3, c[2]), 1, lin(3, c[1], -1, c[0]))});
}

V3 hermite_path(const Vec3_q &p0, const Vec3_q &v0, const Vec3_q &p1, const Vec3_q &v1) {
  const Vec3_q c2 = lin(1, lin(3, p1, -3, p0), 1, lin(-2, v0, -1, v1));
  const Vec3_q c3 = lin(1, lin(2, p0, -2, p1), 1, lin(1, v0, 1, v1));
  return path({p0, v0, c2, c3});
}

Rigid_motion axis_rotation(const Vec3_q &axis, const Vec3_q &center, const Rational &tau0,
                           const Rational &tau1) {
  if (sgn(axis[0]) == 0 && sgn(axis[1]) == 0 && sgn(axis[2]) == 0)
    throw Input_error("axis: the direction is the zero vector");
  Rigid_motion m;
  m.r[0] = Poly_q::constant(Rational(1));
  const Rational dtau = tau1 - tau0;
  for (int i = 0; i < 3; ++i)
    m.r[1 + i] = Poly_q(std::vector<Rational>{tau0 * axis[i], dtau * axis[i]});
  // x = R (p - c) + c = (Rn p - Rn c) / W + c.
  const Vec3p<Rational> rc = mat_vec(rotation_numerator(m.r), center);
  for (int i = 0; i < 3; ++i) {
    m.b[i] = -rc[i];
    m.o[i] = Poly_q::constant(center[i]);
  }
  return m;
}

Rigid_motion screw(const Vec3_q &axis, const Vec3_q &center, const Rational &tau0,
                   const Rational &tau1, const Rational &advance) {
  Rigid_motion m = axis_rotation(axis, center, tau0, tau1);
  for (int i = 0; i < 3; ++i)
    m.o[i] = m.o[i] + Poly_q(std::vector<Rational>{Rational(0), advance * axis[i]});
  return m;
}

Rigid_motion pose_between(const Vec3_q &p0, const Quat_q &q0, const Vec3_q &p1, const Quat_q &q1) {
  for (const auto &[q, name] : {std::pair<const Quat_q &, const char *>{q0, "q0"}, {q1, "q1"}})
    if (std::all_of(q.begin(), q.end(), [](const Rational &c) { return sgn(c) == 0; }))
      throw Input_error(std::string(name) + ": the zero quaternion is no rotation");
  Rational dot = 0;
  for (int i = 0; i < 4; ++i) dot += q0[i] * q1[i];
  const Rational sign = sgn(dot) < 0 ? Rational(-1) : Rational(1);
  Rigid_motion m;
  for (int i = 0; i < 4; ++i)
    m.r[i] = Poly_q(std::vector<Rational>{q0[i], sign * q1[i] - q0[i]});
  const V3 o = linear_path(p0, p1);
  for (int i = 0; i < 3; ++i) m.o[i] = o[i];
  return m;
}

Quat_q quaternion_of_rotation(const double R[9], const std::string &name) {
  for (int i = 0; i < 9; ++i)
    if (!std::isfinite(R[i]))
      throw Input_error(name + "[" + std::to_string(i / 3) + "][" + std::to_string(i % 3) +
                        "]: " + std::to_string(R[i]) + " is not a finite number");
  auto at = [&](int r, int c) { return R[3 * r + c]; };
  double worst = 0;  // max |R^T R - I|
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double d = a == b ? -1.0 : 0.0;
      for (int k = 0; k < 3; ++k) d += at(k, a) * at(k, b);
      worst = std::max(worst, std::fabs(d));
    }
  const double det = at(0, 0) * (at(1, 1) * at(2, 2) - at(1, 2) * at(2, 1)) -
                     at(0, 1) * (at(1, 0) * at(2, 2) - at(1, 2) * at(2, 0)) +
                     at(0, 2) * (at(1, 0) * at(2, 1) - at(1, 1) * at(2, 0));
  if (!(worst <= 1e-6) || !(det > 0))
    throw Input_error(name + ": the upper-left 3x3 block is not a rotation (max |R^T R - I| = " +
                      std::to_string(worst) + ", det = " + std::to_string(det) +
                      "; a rotation matrix is orthonormal to 1e-6 with det 1)");
  // Shepperd: 4 w^2 = 1 + tr, 4 x^2 = 1 + R00 - R11 - R22, ...; the largest is computed
  // from its square root, the others from off-diagonal sums and differences.
  const double tr = at(0, 0) + at(1, 1) + at(2, 2);
  const double s[4] = {1 + tr, 1 + at(0, 0) - at(1, 1) - at(2, 2),
                       1 - at(0, 0) + at(1, 1) - at(2, 2), 1 - at(0, 0) - at(1, 1) + at(2, 2)};
  const int k = static_cast<int>(std::max_element(s, s + 4) - s);
  const double big = 0.5 * std::sqrt(s[k]), f = 0.25 / big;
  double q[4];
  const double wx = at(2, 1) - at(1, 2), wy = at(0, 2) - at(2, 0), wz = at(1, 0) - at(0, 1);
  const double xy = at(0, 1) + at(1, 0), xz = at(0, 2) + at(2, 0), yz = at(1, 2) + at(2, 1);
  if (k == 0) { q[0] = big; q[1] = wx * f; q[2] = wy * f; q[3] = wz * f; }
  if (k == 1) { q[0] = wx * f; q[1] = big; q[2] = xy * f; q[3] = xz * f; }
  if (k == 2) { q[0] = wy * f; q[1] = xy * f; q[2] = big; q[3] = yz * f; }
  if (k == 3) { q[0] = wz * f; q[1] = xz * f; q[2] = yz * f; q[3] = big; }
  Quat_q out;
  for (int i = 0; i < 4; ++i) out[i] = arith::rational_from_double(q[i], name);
  return out;
}

}  // namespace pccd::motion
