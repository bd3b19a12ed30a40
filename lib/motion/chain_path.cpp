#include "motion/chain_path.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pccd::motion {

using arith::Interval;
using arith::round_down;
using arith::round_up;

namespace {

constexpr double kSlack = 0x1p-40;  // chain_path.h, "Rounding"
constexpr double kTiny = 1e-300;

double up(double x) { return x * (1 + kSlack) + kTiny; }  // x >= 0, rounding covered

Interval sq(const Interval &x) {
  if (x.lo >= 0 || x.hi <= 0) return x * x;  // one sign: the products' hull is exact
  const double m = std::max(-x.lo, x.hi);
  return {0.0, round_up(m * m)};
}

Interval clip(const Interval &x, double lo, double hi) {
  return {std::max(x.lo, lo), std::min(x.hi, hi)};  // both hold the true value
}

double norm(const double v[3]) { return up(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])); }

// The ball (midpoints, Frobenius norm of the radii) of an entrywise interval matrix.
void ball_of(const Interval M[3][3], double Rm[3][3], double &eps) {
  double s = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double m = 0.5 * M[i][j].lo + 0.5 * M[i][j].hi;
      const double r = std::max(round_up(M[i][j].hi - m), round_up(m - M[i][j].lo));  // >= exact
      Rm[i][j] = m;
      s += r * r;
    }
  eps = up(std::sqrt(up(s)));
}

// C = A B as balls (chain_path.h).
void compose(const double A[3][3], double ea, const double B[3][3], double eb, double C[3][3], double &ec) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) C[i][j] = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
  ec = up(ea + eb + 3 * ea * eb + kSlack * (1 + ea) * (1 + eb));
}

// o += R v for v in the ball (vm, vr): om and rho updated (chain_path.h).
void add_rotated(const double R[3][3], double e, const double vm[3], double vr, double om[3], double &rho) {
  const double nv = norm(vm), no = norm(om);
  for (int i = 0; i < 3; ++i) om[i] += R[i][0] * vm[0] + R[i][1] * vm[1] + R[i][2] * vm[2];
  rho = up(rho + (1 + e) * vr + e * (nv + vr) + kSlack * (no + (1 + e) * nv));
}

// The value of a linear interpolation x0 + t (x1 - x0) over t in T.
Interval line(double x0, double x1, const Interval &T) { return Interval(x0) + T * (Interval(x1) - Interval(x0)); }

// Makes link k and its ancestors below base that are not yet marked in have, parents
// first.
template <class Make>
void make_lazily(const Chain &c, size_t k, long base, char *have, Make make) {
  if (have[k]) return;
  const long p = c.link(k).parent;
  if (p >= 0 && p != base) make_lazily(c, static_cast<size_t>(p), base, have, make);
  make(k);
  have[k] = 1;
}

}  // namespace

std::shared_ptr<const Chain_path::Fixed> Chain_path::fixed_parts(const Chain &c) {
  const size_t n = c.size();
  const bool nearest = arith::nearest_mode();
  auto key_of = [](const Chain_link &L) {
    return std::array<double, 10>{L.axis_d[0],      L.axis_d[1],      L.axis_d[2],      L.origin_p_d[0],
                                  L.origin_p_d[1],  L.origin_p_d[2],  L.origin_q_d[0], L.origin_q_d[1],
                                  L.origin_q_d[2], L.origin_q_d[3]};
  };
  thread_local std::shared_ptr<const Fixed> last;
  if (last && last->nearest == nearest && last->links.size() == n) {
    bool same = true;
    for (size_t k = 0; k < n && same; ++k) {
      const std::array<double, 10> key = key_of(c.link(k));
      same = std::memcmp(key.data(), last->links[k].key.data(), sizeof key) == 0;  // bit for bit
    }
    if (same) return last;
  }
  auto f = std::make_shared<Fixed>();
  f->nearest = nearest;
  f->links.resize(n);
  for (size_t k = 0; k < n; ++k) {
    const Chain_link &L = c.link(k);
    Link_fixed &F = f->links[k];
    F.key = key_of(L);
    Interval a[3];
    for (int i = 0; i < 3; ++i) {
      F.axis[i] = L.axis_d[i];  // exact: the axis was given as doubles
      a[i] = Interval(F.axis[i]);
    }
    F.axis2 = sq(a[0]) + sq(a[1]) + sq(a[2]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) F.B[i][j] = a[i] * a[j] - (i == j ? F.axis2 : Interval(0.0));
    // |a| enclosed: sqrt is within one ulp in any rounding mode, so two steps out suffice.
    const double an_lo = std::sqrt(F.axis2.lo), an_hi = std::sqrt(F.axis2.hi);
    F.A = Interval(round_down(round_down(an_lo)), round_up(round_up(an_hi)));
    Interval w = L.origin_q_d[0], x = L.origin_q_d[1], y = L.origin_q_d[2], z = L.origin_q_d[3];
    const Interval ww = sq(w), xx = sq(x), yy = sq(y), zz = sq(z);
    const Interval nq = ww + xx + yy + zz;  // > 0: add_link refuses the zero quaternion
    const Interval two(2.0);
    Interval R[3][3];
    R[0][0] = (ww + xx - yy - zz) / nq;
    R[0][1] = two * (x * y - w * z) / nq;
    R[0][2] = two * (x * z + w * y) / nq;
    R[1][0] = two * (x * y + w * z) / nq;
    R[1][1] = (ww - xx + yy - zz) / nq;
    R[1][2] = two * (y * z - w * x) / nq;
    R[2][0] = two * (x * z - w * y) / nq;
    R[2][1] = two * (y * z + w * x) / nq;
    R[2][2] = (ww - xx - yy + zz) / nq;
    Pose_bounds &O = F.origin;
    ball_of(R, O.Rm, O.eps);
    for (int i = 0; i < 3; ++i) O.om[i] = L.origin_p_d[i];  // exact
  }
  last = f;
  return f;
}

Chain_path::Chain_path(const Chain &c, const double *q0, const double *q1) : c_(c) {
  c.check_segment(q0, q1);
  const size_t n = c.size();
  fixed_ = fixed_parts(c);
  ends_.resize(n);
  consts_.resize(n);
  for (size_t k = 0; k < n; ++k) {
    ends_[k] = joint_doubles(c.link(k), q0[k], q1[k]);
    Link_consts &C = consts_[k];
    const Joint_doubles &d = ends_[k];
    C.dc = Interval(d.c1) - Interval(d.c0);
    C.ds = Interval(d.s1) - Interval(d.s0);
    const Interval K = Interval(d.c0) * C.ds - Interval(d.s0) * C.dc;
    const double mK = std::max(std::fabs(K.lo), std::fabs(K.hi));
    C.akt = Interval(2.0) * fx(k).A * Interval(mK);  // >= |2 A K|
  }
}

void Chain_path::enclose_link(double a, double b, size_t k, long base, Pose_bounds *out, char *have) const {
  make_lazily(c_, k, base, have, [&](size_t j) { ball_of_link(j, Interval(a, b), out, base); });
}

long Chain_path::common_ancestor(size_t i, size_t j) const {
  auto depth = [&](long k) {
    int n = 0;
    for (; k >= 0; k = c_.link(static_cast<size_t>(k)).parent) ++n;
    return n;
  };
  long a = static_cast<long>(i), b = static_cast<long>(j);
  int da = depth(a), db = depth(b);
  for (; da > db; --da) a = c_.link(static_cast<size_t>(a)).parent;
  for (; db > da; --db) b = c_.link(static_cast<size_t>(b)).parent;
  while (a != b) {
    a = c_.link(static_cast<size_t>(a)).parent;
    b = c_.link(static_cast<size_t>(b)).parent;
  }
  return a;  // -1 when the two hang from different roots
}

void Chain_path::ball_of_link(size_t k, const Interval &T, Pose_bounds *out, long base) const {
  const Chain_link &L = c_.link(k);
  const Joint_doubles &d = ends_[k];
  const Pose_bounds &O = fx(k).origin;
  Pose_bounds &P = out[k];
  double Rpo[3][3], epo;  // R_parent R_origin
  if (L.parent < 0 || L.parent == base) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) Rpo[i][j] = O.Rm[i][j];
      P.om[i] = O.om[i];
    }
    epo = O.eps;
    P.rho = 0;
  } else {
    const Pose_bounds &Q = out[L.parent];
    compose(Q.Rm, Q.eps, O.Rm, O.eps, Rpo, epo);
    for (int i = 0; i < 3; ++i) P.om[i] = Q.om[i];
    P.rho = Q.rho;
    add_rotated(Q.Rm, Q.eps, O.om, 0.0, P.om, P.rho);
  }
  const double *ax = fx(k).axis.data();
  if (L.joint == Joint_type::prismatic) {
    const Interval e = line(d.e0, d.e1, T);
    double vm[3], s = 0;
    for (int i = 0; i < 3; ++i) {
      const Interval v = e * Interval(ax[i]);
      vm[i] = 0.5 * v.lo + 0.5 * v.hi;
      const double r = std::max(round_up(v.hi - vm[i]), round_up(vm[i] - v.lo));
      s += r * r;
    }
    add_rotated(Rpo, epo, vm, up(std::sqrt(up(s))), P.om, P.rho);
  }
  if (L.joint != Joint_type::revolute && L.joint != Joint_type::continuous) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) P.Rm[i][j] = Rpo[i][j];
    P.eps = epo;
    return;
  }
  Interval J[3][3];
  // line(d.c0, d.c1, T) with its slope made once (consts_: the same interval operations)
  const Interval c = Interval(d.c0) + T * consts_[k].dc, s = Interval(d.s0) + T * consts_[k].ds;
  const Interval nn = sq(c) + sq(s) * fx(k).axis2;
  double Jm[3][3], ej;
  if (nn.lo > 0) {
    const Interval two(2.0);
    Interval alpha = two * c * s / nn, beta = two * sq(s) / nn;
    if (fx(k).axis2.lo == 1 && fx(k).axis2.hi == 1) {
      alpha = clip(alpha, -1, 1);
      beta = clip(beta, 0, 2);
    }
    // I + alpha [a]x + beta (a a^T - |a|^2 I), the last matrix made once (consts_)
    const Interval(&B)[3][3] = fx(k).B;
    const double cross[3][3] = {{0.0, -ax[2], ax[1]}, {ax[2], 0.0, -ax[0]}, {-ax[1], ax[0], 0.0}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        Interval v = beta * B[i][j] + alpha * Interval(cross[i][j]);
        if (i == j) v = Interval(1.0) + v;
        J[i][j] = clip(v, -1, 1);
      }
    ball_of(J, Jm, ej);
  } else {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Jm[i][j] = 0;
    ej = 1;  // a rotation has norm 1
  }
  compose(Rpo, epo, Jm, ej, P.Rm, P.eps);
}

void Chain_path::derivatives_link(double a, double b, size_t k, long base, Path_derivs *out, char *have) const {
  make_lazily(c_, k, base, have, [&](size_t j) { derivs_of_link(j, Interval(a, b), out, base); });
}

void Chain_path::derivs_of_link(size_t k, const Interval &T, Path_derivs *out, long base) const {
  auto mag = [](const Interval &x) { return std::max(std::fabs(x.lo), std::fabs(x.hi)); };
  const Chain_link &L = c_.link(k);
  const Joint_doubles &d = ends_[k];
  Path_derivs P;
  Interval d1p(0.0), d2p(0.0), o2p(0.0);
  if (L.parent >= 0 && L.parent != base) {
    const Path_derivs &Q = out[L.parent];
    d1p = Interval(Q.d1);
    d2p = Interval(Q.d2);
    o2p = Interval(Q.o2);
  }
  const Link_consts &C = consts_[k];
  const Interval &A = fx(k).A;
  const double *po = fx(k).origin.om;
  double vmax = norm(po), v1 = 0;
  Interval th1(0.0), th2(0.0);
  if (L.joint == Joint_type::prismatic) {
    vmax = up(vmax + up(A.hi * std::max(std::fabs(d.e0), std::fabs(d.e1))));
    v1 = mag(A * (Interval(d.e1) - Interval(d.e0)));  // |v'| = |A (e1 - e0)|
  } else if (L.joint == Joint_type::revolute || L.joint == Joint_type::continuous) {
    const Interval &dc = C.dc, &ds = C.ds;
    const Interval c = Interval(d.c0) + T * dc, s = Interval(d.s0) + T * ds;  // line(), slopes made once
    const Interval nn = sq(c) + sq(s) * fx(k).axis2;
    if (!(nn.lo > 0)) {
      out[k] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
      return;
    }
    const Interval nlo(nn.lo), np = Interval(2.0) * (c * dc + fx(k).axis2 * s * ds);
    const Interval &akt = C.akt;  // >= |2 A K|
    th1 = Interval(mag(akt / nlo));
    th2 = Interval(mag(akt * Interval(mag(np)) / (nlo * nlo)));
  }
  const Interval d1 = d1p + th1;
  const Interval d2 = d2p + Interval(2.0) * d1p * th1 + th1 * th1 + th2;
  const Interval o2 = o2p + d2p * Interval(vmax) + Interval(2.0) * d1p * Interval(v1);
  P.d1 = d1.hi;
  P.d2 = d2.hi;
  P.o2 = o2.hi;
  if (!std::isfinite(P.d1) || !std::isfinite(P.d2) || !std::isfinite(P.o2)) P = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
  out[k] = P;
}

}  // namespace pccd::motion
