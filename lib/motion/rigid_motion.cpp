#include "motion/rigid_motion.h"

#include <utility>
#include <vector>

#include "poly/earliest.h"
#include "poly/gcd.h"
#include "poly/lowest_terms.h"
#include "poly/rational_root.h"

namespace pccd::motion {

using arith::Input_error;
using arith::Rational;
using V3 = Vec3p<Rational>;

namespace {

V3 add(const V3 &a, const V3 &b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
V3 scale(const Poly_q &s, const V3 &a) { return {{s * a[0], s * a[1], s * a[2]}}; }
V3 scale(const Rational &s, const V3 &a) { return {{s * a[0], s * a[1], s * a[2]}}; }
V3 constant(const Vec3_q &p) {
  return {{Poly_q::constant(p[0]), Poly_q::constant(p[1]), Poly_q::constant(p[2])}};
}

// The constant coefficient of p (0 for the zero polynomial).
Rational coeff0(const Poly_q &p) { return p.c.empty() ? Rational(0) : p.c[0]; }

Rational norm2(const Quat_q &q) { return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]; }

// Input_error "<where>: ..." (where names the quaternion argument, as the C API does).
void require_nonzero(const Quat_q &q, const char *where) {
  if (sgn(norm2(q)) == 0)
    throw Input_error(std::string(where) + ": the zero quaternion is not a rotation");
}

}  // namespace

void Rigid_motion::set_translation(int axis, Poly_q f) {
  o[axis] = std::move(f);
  b[axis] = Poly_q();
}

void Rigid_motion::set_translation(const V3 &path) {
  o = path;
  b = V3();
}

bool Rigid_motion::has_body_offset() const {
  return !(b[0].c.empty() && b[1].c.empty() && b[2].c.empty());
}

void Rigid_motion::set_rotation(int c, Poly_q f) {
  if (has_body_offset())
    throw arith::Internal_error("set_rotation on a motion with a body-side offset");
  r[c] = std::move(f);
}

Poly_q Rigid_motion::denominator() const { return quat_norm2(r); }

V3 Rigid_motion::offset_numerator() const { return add(b, scale(denominator(), o)); }

Homogeneous_traj Rigid_motion::point_trajectory(const Vec3_q &p) const {
  Homogeneous_traj h;
  h.W = denominator();
  h.X = add(mat_vec(rotation_numerator(r), p), add(b, scale(h.W, o)));
  return h;
}

Vec3_q Rigid_motion::position(const Vec3_q &p, const Rational &t) const {
  if (sgn(t) < 0 || t > 1)
    throw Input_error("t: " + arith::to_string(t) + " is outside [0, 1]");
  // x = (Rn(r(t)) p + b(t)) / |r(t)|^2 + o(t), in integers: the rotation depends on the
  // direction of r(t) alone, so r(t) = A / S is scaled to the integers A (Rn(A) =
  // S^2 Rn(r(t)), |A|^2 = S^2 |r(t)|^2, and b(t) takes the factor S^2). Every product
  // is counted by cost, and each coordinate is reduced once, within the time limit
  // (poly/lowest_terms.h): fraction arithmetic reduced after every operation, each a
  // gcd of millions of bits at a time of 63,000 bits on a degree-64 motion.
  using arith::Integer;
  auto cost = [](const Integer &x, const Integer &y) {
    util::work_cost([&] { return poly::limbs(x) * poly::limbs(y); });
  };
  auto mul = [&](const Integer &x, const Integer &y) {
    cost(x, y);
    return Integer(x * y);
  };
  const Poly_q *rq[4] = {&r[0], &r[1], &r[2], &r[3]};
  std::vector<Integer> A;
  Integer S;
  poly::eval_common(rq, 4, t, &A, &S);
  Integer prod[4][4];
  for (int a = 0; a < 4; ++a)
    for (int b2 = a; b2 < 4; ++b2) prod[a][b2] = mul(A[a], A[b2]);
  const Integer W = prod[0][0] + prod[1][1] + prod[2][2] + prod[3][3];
  if (sgn(W) == 0)
    throw Input_error("the rotation quaternion r(t) vanishes at t = " + arith::to_string(t));
  // rotation_numerator (quaternion.cpp) on the integers A.
  const Integer &ww = prod[0][0], &xx = prod[1][1], &yy = prod[2][2], &zz = prod[3][3];
  const Integer Rn[3][3] = {
      {ww + xx - yy - zz, 2 * (prod[1][2] - prod[0][3]), 2 * (prod[1][3] + prod[0][2])},
      {2 * (prod[1][2] + prod[0][3]), ww - xx + yy - zz, 2 * (prod[2][3] - prod[0][1])},
      {2 * (prod[1][3] - prod[0][2]), 2 * (prod[2][3] + prod[0][1]), ww - xx - yy + zz}};
  // p = P / D over the lcm D of its denominators.
  Integer D = 1;
  for (int j = 0; j < 3; ++j) mpz_lcm(D.get_mpz_t(), D.get_mpz_t(), p[j].get_den_mpz_t());
  Integer P[3];
  for (int j = 0; j < 3; ++j) {
    mpz_divexact(P[j].get_mpz_t(), D.get_mpz_t(), p[j].get_den_mpz_t());
    P[j] *= p[j].get_num();
  }
  const Integer S2 = mul(S, S);
  Vec3_q x;
  for (int i = 0; i < 3; ++i) {
    // x_i = (Rn_i . P / D + S^2 B / Bd) / W + O / Od
    //     = ((Rn_i . P) Bd Od + S^2 B D Od + O W D Bd) / (W D Bd Od).
    const Poly_q *bi = &b[i], *oi = &o[i];
    std::vector<Integer> B, O;
    Integer Bd, Od;
    poly::eval_common(&bi, 1, t, &B, &Bd);
    poly::eval_common(&oi, 1, t, &O, &Od);
    Integer RP = 0;
    for (int j = 0; j < 3; ++j) RP += mul(Rn[i][j], P[j]);
    const Integer BdOd = mul(Bd, Od), WD = mul(W, D);
    const Integer num = mul(RP, BdOd) + mul(mul(S2, B[0]), mul(D, Od)) + mul(mul(O[0], WD), Bd);
    x[i] = poly::lowest_terms(num, mul(WD, BdOd));
  }
  return x;
}

// r(t) = 0 exactly when the four components share the root t, i.e. when t is a root of
// g = gcd(w, x, y, z) (a common root of polynomials over Q is a root of their gcd, and
// conversely). The decision is exact: g(0) and g(1) are evaluated, and the real roots
// of g in the open (0, 1) are counted (poly::count_roots). The first root is then
// enclosed by bisection on exact counts (poly::earliest_contact, width <= 1e-12) and
// tested for rationality (poly::rational_first_contact: a rational root p/q of the
// square-free part F has q | lc(F)).
Vanishing Rigid_motion::vanishing() const {
  Vanishing v;
  if (quat_is_zero(r)) {
    v.vanishes = v.identically = true;
    return v;
  }
  Poly_q g = poly::gcd(poly::gcd(r[0], r[1]), poly::gcd(r[2], r[3]));
  if (g.degree() < 1) return v;  // a nonzero constant gcd: no common root anywhere
  const Rational zero(0), one(1);
  const bool at0 = sgn(g.eval(zero)) == 0;
  const bool inside = !at0 && poly::count_roots(g, {}, zero, one) > 0;
  const bool at1 = sgn(g.eval(one)) == 0;
  if (!(at0 || inside || at1)) return v;
  v.vanishes = true;
  if (!inside) {  // the first zero is t = 0, or t = 1 with none before it
    v.exact = true;
    v.lo = v.hi = at0 ? zero : one;
    return v;
  }
  poly::System<Rational> s;
  s.f = g;
  const std::vector<poly::System<Rational>> sys{s};
  poly::Search_result<Rational> e = poly::earliest_contact(sys, poly::Earliest_options());
  if (!e.found) throw arith::Internal_error("vanishing: a counted root was not found");
  v.lo = e.lo;
  v.hi = e.hi;
  v.exact = e.exact;
  if (!v.exact) {  // e.lo < t* <= e.hi, and e.lo is not a root
    poly::Rational_root_result rr = poly::rational_first_contact(sys, {0}, e.lo, e.hi);
    if (rr.exact) {
      v.exact = true;
      v.lo = v.hi = rr.t;
    }
  }
  return v;
}

std::string describe_vanishing(const Vanishing &v) {
  if (v.identically) return "the rotation quaternion r(t) is the zero polynomial";
  std::string where = v.exact ? "t = " + arith::to_string(v.lo)
                              : "an irrational time t with " + arith::to_string(v.lo) +
                                    " < t < " + arith::to_string(v.hi);
  return "the rotation quaternion r(t) = w + x i + y j + z k vanishes at " + where +
         " (its four components have a common root there, so R(r(t)) is undefined)";
}

void Rigid_motion::validate() const {
  Vanishing v = vanishing();
  if (v.vanishes) throw Input_error(describe_vanishing(v));
}

void Rigid_motion::compose_body(const Quat_q &q0, const Vec3_q &p0) {
  require_nonzero(q0, "quat");
  // b' = |q0|^2 (Rn(r) p0 + b), with the old r; then r' = r q0.
  b = scale(norm2(q0), add(mat_vec(rotation_numerator(r), p0), b));
  r = quat_mul(r, quat_constant(q0));
}

void Rigid_motion::compose_world(const Quat_q &q1, const Vec3_q &p1) {
  require_nonzero(q1, "quat");
  const Mat3_poly R1n = rotation_numerator(quat_constant(q1));  // constant polynomials
  b = mat_vec(R1n, b);
  const Rational inv = 1 / norm2(q1);
  o = add(scale(inv, mat_vec(R1n, o)), constant(p1));
  r = quat_mul(quat_constant(q1), r);
}

Rigid_motion compose_motions(const Rigid_motion &outer, const Rigid_motion &inner) {
  for (const auto &f : {std::make_pair(&outer, "outer"), std::make_pair(&inner, "inner")}) {
    Vanishing v = f.first->vanishing();
    if (v.vanishes) throw Input_error(std::string(f.second) + ": " + describe_vanishing(v));
  }
  return compose_valid(outer, inner);
}

Rigid_motion compose_valid(const Rigid_motion &outer, const Rigid_motion &inner,
                           const Mat3_poly *Rn_outer) {
  Rigid_motion m;
  m.r = quat_mul(outer.r, inner.r);
  const Mat3_poly Rn_o = Rn_outer ? *Rn_outer : rotation_numerator(outer.r);
  const Poly_q W_i = inner.denominator();
  bool constant_outer = true;
  for (const Poly_q &c : outer.r) constant_outer = constant_outer && c.degree() < 1;
  if (constant_outer) {
    // r_o = q: O = Rn(q) (b_i + W_i o_i) + W_i (b_o + n_q o_o), W = n_q W_i, so
    // o = Rn(q) o_i / n_q + o_o and b = Rn(q) b_i + W_i b_o.
    const Rational inv = 1 / norm2(Quat_q{{coeff0(outer.r[0]), coeff0(outer.r[1]),
                                           coeff0(outer.r[2]), coeff0(outer.r[3])}});
    m.o = add(scale(inv, mat_vec(Rn_o, inner.o)), outer.o);
    m.b = add(mat_vec(Rn_o, inner.b), scale(W_i, outer.b));
  } else {
    m.o = outer.o;
    m.b = add(mat_vec(Rn_o, inner.offset_numerator()), scale(W_i, outer.b));
  }
  return m;
}

}  // namespace pccd::motion
