// range::detect_axis_rotation (lib/range/axis_rotation.h): which relative motions are
// detected as a rotation about a fixed axis, and, when one is, that its parametrization
// reproduces the exact positions: for body points p and rational times t,
//   c + Rn(E(t)) (M0 p + v0) / W(E(t)),   E(t) = (alpha0 + alpha1 t, t a),
// (interval arithmetic) must contain the exact relative position R_S(t)^T (x_Q - o_S)
// computed from Rigid_motion::position in rationals. Also: a is parallel to the axis the
// motion was built with, and c lies on that axis. Prints "N passed, N failed".
#include <cstdio>
#include <vector>

#include "arith/convert.h"
#include "range/axis_rotation.h"
#include "motion/standard_motions.h"

using namespace pccd;
using arith::Interval;
using arith::Rational;
using motion::Rigid_motion;
using motion::Vec3_q;

static long passed = 0, failed = 0;
static void expect(bool ok, const char *what) {
  if (ok) ++passed;
  else if (++failed <= 20) std::printf("FAIL: %s\n", what);
}

using I3 = std::array<Interval, 3>;
static bool meets(const Interval &a, const Interval &b) { return a.lo <= b.hi && b.lo <= a.hi; }
static bool has_zero(const Interval &a) { return a.lo <= 0 && a.hi >= 0; }
static I3 enc(const Vec3_q &v) { return {arith::enclose(v[0]), arith::enclose(v[1]), arith::enclose(v[2])}; }
static I3 cross(const I3 &a, const I3 &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

static const std::vector<motion::Point3_q> kPts = {
    {Rational(0), Rational(0), Rational(0)}, {Rational(1), Rational(0), Rational(0)},
    {Rational(0), Rational(1), Rational(0)}, {Rational(3, 7), Rational(-2, 3), Rational(5, 4)}};

static narrow::Moving_body body(const Rigid_motion &m) {
  auto mesh = std::make_shared<const motion::Mesh_body>(
      kPts, std::vector<motion::Triangle>{{0, 1, 2}, {1, 2, 3}});
  return narrow::prepare_body(narrow::make_body_data(mesh, nullptr), m);
}

// The exact relative position of query point p at t: R_S^T (x_Q - o_S), o_S = x_S(0).
static Vec3_q relative(const Rigid_motion &S, const Rigid_motion &Q, const motion::Point3_q &p,
                       const Rational &t) {
  const Vec3_q x = Q.position(p, t), o = S.position({Rational(0), Rational(0), Rational(0)}, t);
  Vec3_q out;
  // columns of R_S: images of the unit vectors minus the origin's image
  Vec3_q col[3];
  for (int k = 0; k < 3; ++k) {
    Vec3_q u = {Rational(0), Rational(0), Rational(0)};
    u[k] = 1;
    const Vec3_q y = S.position(u, t);
    for (int i = 0; i < 3; ++i) col[k][i] = y[i] - o[i];
  }
  for (int k = 0; k < 3; ++k) out[k] = col[k][0] * (x[0] - o[0]) + col[k][1] * (x[1] - o[1]) + col[k][2] * (x[2] - o[2]);
  return out;
}

static void check_detected(const char *name, const Rigid_motion &S, const Rigid_motion &Q,
                           const Vec3_q *axis, const Vec3_q *point_on_axis) {
  const auto r = range::detect_axis_rotation(body(S), body(Q));
  expect(r.has_value(), name);
  if (!r) return;
  if (axis) {
    const I3 x = cross(r->a, enc(*axis));
    expect(has_zero(x[0]) && has_zero(x[1]) && has_zero(x[2]), "a parallel to the axis");
  }
  if (point_on_axis) {
    const I3 pc = enc(*point_on_axis);
    const I3 d = {r->c[0] - pc[0], r->c[1] - pc[1], r->c[2] - pc[2]};
    const I3 x = cross(d, r->a);
    expect(has_zero(x[0]) && has_zero(x[1]) && has_zero(x[2]), "c on the axis");
  }
  for (int i = 0; i <= 8; ++i) {
    const Rational t(i, 8);
    const Interval ti = arith::enclose(t), al = r->alpha0 + r->alpha1 * ti;
    const I3 v = {ti * r->a[0], ti * r->a[1], ti * r->a[2]};
    const Interval W = al * al + ti * ti * r->a2;
    for (const auto &p : kPts) {
      const I3 pi = enc(p);
      I3 q;
      for (int k = 0; k < 3; ++k) q[k] = r->M0[k][0] * pi[0] + r->M0[k][1] * pi[1] + r->M0[k][2] * pi[2] + r->v0[k];
      // Rn q = (al^2 - |v|^2) q + 2 (v . q) v + 2 al (v x q)
      const Interval vq = v[0] * q[0] + v[1] * q[1] + v[2] * q[2], v2 = ti * ti * r->a2;
      const I3 vx = cross(v, q);
      const Vec3_q exact = relative(S, Q, p, t);
      bool ok = true;
      for (int k = 0; k < 3; ++k) {
        const Interval rn = (al * al - v2) * q[k] + Interval(2.0) * vq * v[k] + Interval(2.0) * al * vx[k];
        ok = ok && meets(r->c[k] + rn / W, arith::enclose(exact[k]));
      }
      expect(ok, name);
    }
  }
}

static void check_not(const char *name, const Rigid_motion &S, const Rigid_motion &Q) {
  expect(!range::detect_axis_rotation(body(S), body(Q)).has_value(), name);
}

int main() {
  const Vec3_q axis = {Rational(1), Rational(2), Rational(2)}, center = {Rational(1, 2), Rational(-1), Rational(3)};
  const Rigid_motion rest;
  const Rigid_motion turn = motion::axis_rotation(axis, center, Rational(-1, 3), Rational(2, 5));
  check_detected("axis rotation against a body at rest", rest, turn, &axis, &center);
  check_detected("body at rest against an axis rotation (stored body turning)", turn, rest, &axis, &center);
  // Constant poses on both sides of both bodies keep it a rotation about a fixed line.
  Rigid_motion posed = turn, stored = rest;
  posed.compose_body({Rational(1), Rational(2), Rational(0), Rational(-1)}, {Rational(1), Rational(0), Rational(2)});
  posed.compose_world({Rational(3), Rational(0), Rational(1), Rational(1)}, {Rational(-2), Rational(1, 3), Rational(0)});
  stored.compose_world({Rational(2), Rational(-1), Rational(1), Rational(0)}, {Rational(5), Rational(1), Rational(-1)});
  check_detected("posed axis rotation against a posed body", stored, posed, nullptr, nullptr);
  // A large turn (tau |axis| up to 6, about 160 degrees).
  check_detected("large turn", rest, motion::axis_rotation(axis, center, Rational(-2), Rational(2)), &axis, &center);

  check_not("screw", rest, motion::screw(axis, center, Rational(0), Rational(1), Rational(1, 2)));
  Rigid_motion rolling;  // r = (1, tau(t) axis) about the body origin while it translates
  rolling.set_rotation(0, motion::Poly_q::constant(Rational(1)));
  for (int k = 0; k < 3; ++k)
    rolling.set_rotation(1 + k, motion::Poly_q(std::vector<Rational>{Rational(0), axis[k]}));
  rolling.set_translation(0, motion::Poly_q(std::vector<Rational>{Rational(0), Rational(1)}));
  check_not("rotation plus a translation", rest, rolling);
  Rigid_motion slide;
  slide.set_translation(1, motion::Poly_q(std::vector<Rational>{Rational(1), Rational(-3)}));
  check_not("linear translation (no rotation)", rest, slide);
  check_not("both at rest", rest, rest);
  check_not("the same turn on both bodies (no relative motion)", turn, turn);
  // The same rotations written with a degree-2 quaternion (r times 1 + t): not detected
  // (the documented rule is degree <= 1); the general clauses handle it.
  Rigid_motion deg2;
  for (int c = 0; c < 4; ++c)
    deg2.set_rotation(c, turn.r[c] * motion::Poly_q(std::vector<Rational>{Rational(1), Rational(1)}));
  check_not("degree-2 quaternion", rest, deg2);
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed ? 1 : 0;
}
