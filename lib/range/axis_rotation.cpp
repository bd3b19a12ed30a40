#include "range/axis_rotation.h"

#include <vector>

#include "arith/convert.h"
#include "motion/quaternion.h"

namespace pccd::range {

namespace {

using motion::Quat_poly;
using motion::Quat_q;

Rational coeff(const Poly_q &p, int k) { return k <= p.degree() ? p.c[k] : Rational(0); }

// One solution of the linear system rows * x = rhs (3 unknowns), exactly; nullopt when
// it is inconsistent.
std::optional<std::array<Rational, 3>> solve3(std::vector<std::array<Rational, 4>> rows) {
  std::array<int, 3> pivot_row{-1, -1, -1};
  size_t r = 0;
  for (int col = 0; col < 3 && r < rows.size(); ++col) {
    size_t p = r;
    while (p < rows.size() && arith::is_zero(rows[p][col])) ++p;
    if (p == rows.size()) continue;
    std::swap(rows[r], rows[p]);
    for (size_t i = 0; i < rows.size(); ++i) {
      if (i == r || arith::is_zero(rows[i][col])) continue;
      const Rational f = rows[i][col] / rows[r][col];
      for (int k = col; k < 4; ++k) rows[i][k] -= f * rows[r][k];
    }
    pivot_row[col] = static_cast<int>(r++);
  }
  for (size_t i = r; i < rows.size(); ++i)
    if (!arith::is_zero(rows[i][3])) return std::nullopt;  // 0 = nonzero
  std::array<Rational, 3> x{0, 0, 0};                     // free unknowns: 0
  for (int col = 0; col < 3; ++col)
    if (pivot_row[col] >= 0) x[col] = rows[pivot_row[col]][3] / rows[pivot_row[col]][col];
  return x;
}

}  // namespace

std::optional<Axis_rotation> detect_axis_rotation(const Moving_body &S, const Moving_body &Q) {
  const Quat_poly rho = motion::quat_mul(motion::quat_conj(S.mo->motion.r), Q.mo->motion.r);
  for (const Poly_q &p : rho)
    if (p.degree() > 1) return std::nullopt;
  Quat_q r0, r1;
  for (int i = 0; i < 4; ++i) {
    r0[i] = coeff(rho[i], 0);
    r1[i] = coeff(rho[i], 1);
  }
  const Quat_poly e = motion::quat_mul(motion::quat_constant(r1),
                                       motion::quat_conj(motion::quat_constant(r0)));
  std::array<Rational, 3> a;
  for (int i = 0; i < 3; ++i) a[i] = coeff(e[1 + i], 0);
  if (arith::is_zero(a[0]) && arith::is_zero(a[1]) && arith::is_zero(a[2])) return std::nullopt;
  const Rational n0 = r0[0] * r0[0] + r0[1] * r0[1] + r0[2] * r0[2] + r0[3] * r0[3];
  const Rational ew = coeff(e[0], 0);
  const Poly_q t = Poly_q(std::vector<Rational>{0, 1});
  const Quat_poly E = {Poly_q(std::vector<Rational>{n0, ew}), Poly_q::constant(a[0]) * t,
                       Poly_q::constant(a[1]) * t, Poly_q::constant(a[2]) * t};
  const motion::Mat3_poly RE = motion::rotation_numerator(E);
  const Poly_q WE = motion::quat_norm2(E);

  // Exact relative motion: y = (M p + u) / w.
  const Relative_pose<Poly_q> rel = relative_pose(S.mo->Rn, S.mo->O, S.mo->W, Q.mo->Rn, Q.mo->O, Q.mo->W);
  const auto &M = rel.M;
  const auto &u = rel.u;
  const Poly_q &w = rel.w;

  // (u(t) - w(t) c) w(0) WE(t) = RE(t) (u(0) - w(0) c) w(t): for every component i,
  // P_i(t) + sum_j A_ij(t) c_j = 0 with
  //   P = w(0) WE u - w RE u(0),   A = w(0) w (RE - WE I).
  const Rational w0 = coeff(w, 0);
  std::array<Rational, 3> u0;
  for (int i = 0; i < 3; ++i) u0[i] = coeff(u[i], 0);
  std::vector<std::array<Rational, 4>> rows;
  for (int i = 0; i < 3; ++i) {
    Poly_q P = Poly_q::constant(w0) * WE * u[i];
    for (int j = 0; j < 3; ++j) P = P - Poly_q::constant(u0[j]) * w * RE[i][j];
    std::array<Poly_q, 3> A;
    for (int j = 0; j < 3; ++j) A[j] = Poly_q::constant(w0) * w * (i == j ? RE[i][j] - WE : RE[i][j]);
    int deg = P.degree();
    for (const Poly_q &x : A) deg = std::max(deg, x.degree());
    for (int k = 0; k <= deg; ++k) rows.push_back({coeff(A[0], k), coeff(A[1], k), coeff(A[2], k), -coeff(P, k)});
  }
  const std::optional<std::array<Rational, 3>> c = solve3(std::move(rows));
  if (!c) return std::nullopt;

  Axis_rotation r;
  for (int i = 0; i < 3; ++i) {
    r.a[i] = arith::enclose(a[i]);
    r.c[i] = arith::enclose((*c)[i]);
    r.v0[i] = arith::enclose(u0[i] / w0 - (*c)[i]);
    for (int j = 0; j < 3; ++j) r.M0[i][j] = arith::enclose(coeff(M[i][j], 0) / w0);
  }
  r.a2 = arith::enclose(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  r.alpha0 = arith::enclose(n0);
  r.alpha1 = arith::enclose(ew);
  return r;
}

}  // namespace pccd::range
