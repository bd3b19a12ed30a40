#include "motion/chain.h"

#include <climits>
#include <cmath>
#include <cstdio>

namespace pccd::motion {

using arith::Input_error;
using arith::Rational;

namespace {

// pi and 2 pi rounded to nearest: 3.141592653589793116 < pi and 6.283185307179586232 <
// 2 pi, so "|d| >= kTwo_pi" rejects every segment of a full turn or more (and the few
// doubles within 2.5e-16 below it).
const double kPi = 3.141592653589793;
const double kTwo_pi = 6.283185307179586;

std::string text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string where(const char *name, size_t k) { return std::string(name) + "[" + std::to_string(k) + "]"; }

// The place of link k's joint value q0 / q1 in errors (Chain::set_value_place).
std::string where(const char *name, const Chain_link &L, size_t k) {
  return L.value_place.empty() ? where(name, k) : name + L.value_place;
}

Rational exact(double x, const std::string &place) { return arith::rational_from_double(x, place); }

Poly_q line(const Rational &a, const Rational &b) { return Poly_q(std::vector<Rational>{a, b - a}); }

// The endpoints (c, s) = (cos(theta / 2), sin(theta / 2) / |a|) of a revolute joint, and
// the scaled translation e = d / |a| of a prismatic one (chain.h).
struct Ends {
  Rational c0, s0, c1, s1;  // revolute
  Rational e0, e1;          // prismatic
};

Ends joint_ends(const Chain_link &L, size_t k, double q0, double q1) {
  const Rational a = exact(q0, where("q0", L, k)), b = exact(q1, where("q1", L, k));
  const Joint_doubles d = joint_doubles(L, q0, q1);
  Ends e;
  if (L.joint == Joint_type::prismatic) {
    e.e0 = exact(d.e0, where("q0", L, k));
    e.e1 = exact(d.e1, where("q1", L, k));
    return e;
  }
  e.c0 = exact(d.c0, where("q0", k));  // finite: q0, q1 are, and |a| ~ 1 (add_link)
  e.s0 = exact(d.s0, where("q0", k));
  e.c1 = exact(d.c1, where("q1", k));
  e.s1 = exact(d.s1, where("q1", k));
  const Rational dq = b - a;
  const int sd = sgn(dq);
  const Rational ad = sd < 0 ? Rational(-dq) : dq;
  if (!(ad < Rational(kTwo_pi)))
    throw Input_error(where("q1", L, k) + ": the revolute segment from " + text(q0) + " to " + text(q1) +
                      " turns by 2 pi or more; split it into shorter segments");
  // The sign of sin of the swept half-angle is that of c0 s1 - s0 c1 (|a| > 0).
  const Rational cross = e.c0 * e.s1 - e.s0 * e.c1;
  if (Rational(kPi) < ad && sgn(cross) != sd)
    throw Input_error(where("q1", L, k) + ": the revolute segment from " + text(q0) + " to " + text(q1) +
                      " is so close to a full turn that its rounded half-angle endpoints "
                      "would be interpolated the other way round; split it");
  const Rational dot = e.c0 * e.c1 + e.s0 * e.s1 * L.axis[0] * L.axis[0] +
                       e.s0 * e.s1 * L.axis[1] * L.axis[1] + e.s0 * e.s1 * L.axis[2] * L.axis[2];
  if (sgn(cross) == 0 && sgn(dot) < 0)
    throw arith::Internal_error("antipodal joint quaternions passed the segment check");
  return e;
}

}  // namespace

Joint_doubles joint_doubles(const Chain_link &L, double q0, double q1) {
  Joint_doubles d;
  if (L.joint == Joint_type::prismatic) {
    d.e0 = q0 / L.axis_norm;
    d.e1 = q1 / L.axis_norm;
  } else if (L.joint != Joint_type::fixed) {
    d.c0 = std::cos(q0 / 2);
    d.s0 = std::sin(q0 / 2) / L.axis_norm;
    d.c1 = std::cos(q1 / 2);
    d.s1 = std::sin(q1 / 2) / L.axis_norm;
  }
  return d;
}

// A revolute or continuous joint with finite q0, q1 whose double difference is at most 3
// passes joint_ends without any rational (the per-segment check of every robot check
// spent tens of us on them): every value is finite (cos, sin over |a| ~ 1); the exact
// |q1 - q0| is within 2^-53 relative of the double's, so below pi: no turn of 2 pi or
// more, no near-full turn; and the dot of the rounded half-angle endpoints is cos((q1 -
// q0) / 2) >= cos(1.5) > 0.07 up to libm's and the axis norm's errors (< 1e-14), so it is
// positive and the antipodal check cannot fire. Anything else takes joint_ends.
void Chain::check_segment(const double *q0, const double *q1) const {
  for (size_t k = 0; k < links_.size(); ++k) {
    const Joint_type j = links_[k].joint;
    if (j == Joint_type::fixed) continue;
    const bool turning = j == Joint_type::revolute || j == Joint_type::continuous;
    if (turning && std::isfinite(q0[k]) && std::isfinite(q1[k]) && std::fabs(q1[k] - q0[k]) <= 3.0) continue;
    joint_ends(links_[k], k, q0[k], q1[k]);
  }
}

size_t Chain::add_link(long parent, int joint, const double *axis, const double xyz[3],
                       const double rpy[3]) {
  Chain_link L;
  if (parent < -1 || parent >= static_cast<long>(links_.size()))
    throw Input_error("parent: " + std::to_string(parent) + " is not -1 (the world) or an earlier link (0.." +
                      std::to_string(static_cast<long>(links_.size()) - 1) + ")");
  L.parent = parent;
  if (joint < 0 || joint > 3)
    throw Input_error("joint: " + std::to_string(joint) + " is not a pccd_joint_type (0..3)");
  L.joint = static_cast<Joint_type>(joint);
  if (L.joint != Joint_type::fixed) {
    if (!axis) throw Input_error("axis: is NULL");
    // The direction scaled exactly by a power of two to a largest component in [1/2, 1):
    // the joint's motion depends on the direction alone (chain.h), and |a| is then a
    // double near 1 whatever the axis (1e300 or 1e-200 overflowed or underflowed it,
    // and the link never turned). For an axis of ordinary size nothing changes: the
    // doubles derived from it scale by the same power of two, exactly.
    int top = INT_MIN;
    for (int i = 0; i < 3; ++i) {
      L.axis[i] = exact(axis[i], where("axis", i));
      int e = 0;
      if (axis[i] != 0) std::frexp(axis[i], &e);  // |axis[i]| < 2^e
      if (axis[i] != 0 && e > top) top = e;
    }
    if (top == INT_MIN) throw Input_error("axis: the direction is the zero vector");
    if (top < -64 || top > 64)  // ordinary axes keep their exact value
      for (int i = 0; i < 3; ++i) {
        if (top > 0) mpq_div_2exp(L.axis[i].get_mpq_t(), L.axis[i].get_mpq_t(), top);
        else mpq_mul_2exp(L.axis[i].get_mpq_t(), L.axis[i].get_mpq_t(), -top);
      }
    const Rational n2 = L.axis[0] * L.axis[0] + L.axis[1] * L.axis[1] + L.axis[2] * L.axis[2];
    L.axis_norm = n2 == Rational(1) ? 1.0 : std::sqrt(arith::nearest_double(n2));
    if (!(std::isfinite(L.axis_norm) && L.axis_norm > 0))
      throw arith::Internal_error("axis: |axis| is not a positive double after scaling");
  }
  double h[3][2];  // cos, sin of the half angles of roll, pitch, yaw
  for (int i = 0; i < 3; ++i) {
    L.origin_p[i] = exact(xyz[i], where("xyz", i));
    exact(rpy[i], where("rpy", i));  // checks finiteness
    h[i][0] = std::cos(rpy[i] / 2);
    h[i][1] = std::sin(rpy[i] / 2);
  }
  // q = qz(yaw) qy(pitch) qx(roll), qx = (cr, sr, 0, 0), qy = (cp, 0, sp, 0), qz = (cy, 0, 0, sy).
  const double cr = h[0][0], sr = h[0][1], cp = h[1][0], sp = h[1][1], cy = h[2][0], sy = h[2][1];
  const double q[4] = {cy * cp * cr + sy * sp * sr, cy * cp * sr - sy * sp * cr,
                       cy * sp * cr + sy * cp * sr, sy * cp * cr - cy * sp * sr};
  for (int i = 0; i < 4; ++i) L.origin_q[i] = exact(q[i], "rpy");
  if (sgn(L.origin_q[0]) == 0 && sgn(L.origin_q[1]) == 0 && sgn(L.origin_q[2]) == 0 &&
      sgn(L.origin_q[3]) == 0)
    throw arith::Internal_error("the roll-pitch-yaw quaternion rounded to zero");
  for (int i = 0; i < 3; ++i) {
    L.axis_d[i] = arith::nearest_double(L.axis[i]);
    L.origin_p_d[i] = arith::nearest_double(L.origin_p[i]);
  }
  for (int i = 0; i < 4; ++i) L.origin_q_d[i] = arith::nearest_double(L.origin_q[i]);
  links_.push_back(L);
  return links_.size() - 1;
}

Rigid_motion Chain::joint_motion(size_t k, double q0, double q1) const {
  const Chain_link &L = links_[k];
  Rigid_motion m;
  if (L.joint != Joint_type::fixed) {
    const Ends e = joint_ends(L, k, q0, q1);
    if (L.joint == Joint_type::prismatic) {
      const Poly_q f = line(e.e0, e.e1);
      for (int i = 0; i < 3; ++i) m.o[i] = Poly_q::constant(L.axis[i]) * f;
    } else {
      m.r[0] = line(e.c0, e.c1);
      const Poly_q s = line(e.s0, e.s1);
      for (int i = 0; i < 3; ++i) m.r[1 + i] = Poly_q::constant(L.axis[i]) * s;
    }
  }
  m.compose_world(L.origin_q, L.origin_p);
  return m;
}

std::vector<Rigid_motion> Chain::segment_motions(const double *q0, const double *q1,
                                                std::vector<Mat3_poly> *rn,
                                                const std::vector<bool> *needed,
                                                const Link_check *check, long base) const {
  if (base >= static_cast<long>(links_.size())) throw arith::Internal_error("segment_motions: no such base link");
  std::vector<Rigid_motion> out;
  out.reserve(links_.size());
  std::vector<Mat3_poly> local;
  std::vector<Mat3_poly> &R = rn ? *rn : local;
  R.clear();
  R.reserve(links_.size());
  std::vector<bool> need(links_.size(), true);
  if (needed) {  // the needed links and their ancestors (parents come first)
    need = *needed;
    for (size_t k = links_.size(); k-- > 0;)
      if (need[k] && links_[k].parent >= 0) need[links_[k].parent] = true;
  }
  std::vector<char> in_frame(links_.size(), 1);  // at or below base (parents come first)
  if (base >= 0)
    for (size_t k = 0; k < links_.size(); ++k) {
      const long p = links_[k].parent;
      in_frame[k] = static_cast<long>(k) == base || (p >= 0 && in_frame[p]);
    }
  for (size_t k = 0; k < links_.size(); ++k) {
    if (!need[k] || !in_frame[k] || static_cast<long>(k) == base) {
      out.emplace_back();
      R.emplace_back();
      if (static_cast<long>(k) == base && need[k]) R.back() = rotation_numerator(out.back().r);
      continue;
    }
    Rigid_motion j = joint_motion(k, q0[k], q1[k]);
    // Every factor is valid by construction (a joint quaternion never vanishes, above),
    // so the composition needs no vanishing check. Links come after their parents.
    const long p = links_[k].parent;
    out.push_back(p < 0 || p == base ? std::move(j) : compose_valid(out[p], j, &R[p]));
    if (check) (*check)(k, out.back());
    R.push_back(rotation_numerator(out.back().r));
  }
  return out;
}

std::vector<double> Chain::joint_values(const double *q0, const double *q1, const Rational &t) const {
  if (sgn(t) < 0 || t > 1) throw Input_error("t: " + arith::to_string(t) + " is outside [0, 1]");
  std::vector<double> v(links_.size(), 0.0);
  for (size_t k = 0; k < links_.size(); ++k) {
    const Chain_link &L = links_[k];
    if (L.joint == Joint_type::fixed) continue;
    const Ends e = joint_ends(L, k, q0[k], q1[k]);
    if (L.joint == Joint_type::prismatic) {
      v[k] = arith::nearest_double(line(e.e0, e.e1).eval(t)) * L.axis_norm;
      continue;
    }
    const double C0 = arith::nearest_double(e.c0), S0 = arith::nearest_double(e.s0) * L.axis_norm;
    const double C = arith::nearest_double(line(e.c0, e.c1).eval(t));
    const double S = arith::nearest_double(line(e.s0, e.s1).eval(t)) * L.axis_norm;
    v[k] = q0[k] + 2 * std::atan2(C0 * S - S0 * C, C0 * C + S0 * S);
  }
  for (size_t k = 0; k < v.size(); ++k)  // no NaN answer (issue 23: a huge axis gave one)
    if (!std::isfinite(v[k])) throw arith::Internal_error("joint_values: a non-finite joint value");
  return v;
}

}  // namespace pccd::motion
