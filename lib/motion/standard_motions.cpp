#include "motion/standard_motions.h"

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

}  // namespace pccd::motion
