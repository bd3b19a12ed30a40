#include "range/rotation_query.h"

#include <cmath>

#include "range/ivec.h"

namespace pccd::range {

std::vector<std::array<Interval, kDimEnds>> lift_edge_ends(const Body_data &b) {
  const auto &V = b.mesh->vertices();
  std::vector<std::array<Interval, kDimEnds>> out;
  out.reserve(b.mesh->edges().size());
  for (const auto &e : b.mesh->edges()) {
    const I3 p = enclose_point(V[e[0]]), q = enclose_point(V[e[1]]);
    out.push_back({p[0], p[1], p[2], q[0], q[1], q[2]});
  }
  return out;
}

namespace {

// Enclosure of sqrt over [max(lo, 0), hi] (std::sqrt is correctly rounded in the
// current mode: one ulp outward covers every mode).
Interval isqrt(const Interval &x) {
  return Interval(std::max(0.0, arith::round_down(std::sqrt(std::max(0.0, x.lo)))),
                  arith::round_up(std::sqrt(x.hi)));
}

bool finite(const Interval &x) { return std::fabs(x.lo) < HUGE_VAL && std::fabs(x.hi) < HUGE_VAL; }

// The range of b0 (1 - s)^2 + 2 b1 s (1 - s) + b2 s^2 over s in [s.lo, s.hi] (inside
// [0, 1]): the hull of its Bernstein coefficients on that interval, the values at the
// ends and the polar form b0 (1 - s0)(1 - s1) + b1 ((1 - s0) s1 + s0 (1 - s1)) + b2 s0 s1.
Interval bernstein2(const Interval *b, const Interval &s) {
  const Interval s0(s.lo), s1(s.hi), r0 = Interval(1.0) - s0, r1 = Interval(1.0) - s1;
  const Interval c[3] = {b[0] * (r0 * r0) + Interval(2.0) * b[1] * (s0 * r0) + b[2] * (s0 * s0),
                         b[0] * (r0 * r1) + b[1] * (r0 * s1 + s0 * r1) + b[2] * (s0 * s1),
                         b[0] * (r1 * r1) + Interval(2.0) * b[1] * (s1 * r1) + b[2] * (s1 * s1)};
  return Interval(std::min({c[0].lo, c[1].lo, c[2].lo}), std::max({c[0].hi, c[1].hi, c[2].hi}));
}

template <int D>
void eval3(const std::array<Halfspace<D>, 3> &h, const Interval *x, Interval *b) {
  for (int j = 0; j < 3; ++j) b[j] = Interval(lower_bound(h[j], x), upper_bound(h[j], x));
}

// Intervals in [0, 1] that enclose every root in [0, 1] of the quadratic with Bernstein
// coefficients b (none when it certainly has none there). Power form c0 + c1 s + c2 s^2
// with c0 = b0, c1 = 2 (b1 - b0), c2 = b0 - 2 b1 + b2; the quadratic formula when c2
// certainly is not 0 and its root intervals come out narrow (width <= 2^-20), else the
// cells of 64 equal ones where the value may vanish.
int root_cells(const Interval *b, Interval *out /* [64] */) {
  for (int j = 0; j < 3; ++j)
    if (!finite(b[j])) {
      out[0] = Interval(0.0, 1.0);
      return 1;
    }
  const Interval c0 = b[0], c1 = Interval(2.0) * (b[1] - b[0]), c2 = b[0] - Interval(2.0) * b[1] + b[2];
  int n = 0;
  if (c2.lo > 0 || c2.hi < 0) {
    const Interval disc = c1 * c1 - Interval(4.0) * c0 * c2;
    if (disc.hi < 0) return 0;
    const Interval sq = isqrt(disc), den = Interval(2.0) * c2;
    bool narrow = true;
    for (const Interval &r : {(-c1 - sq) / den, (-c1 + sq) / den}) {
      if (r.lo > 1 || r.hi < 0) continue;
      narrow = narrow && r.hi - r.lo <= 0x1p-20;  // false for NaN
      out[n++] = Interval(std::max(0.0, r.lo), std::min(1.0, r.hi));
    }
    if (narrow) return n;
    n = 0;
  }
  for (int i = 0; i < 64; ++i) {
    const Interval s(i / 64.0, (i + 1) / 64.0);
    const Interval v = bernstein2(b, s);
    if (!(v.lo > 0 || v.hi < 0)) out[n++] = s;
  }
  return n;
}

// Whether the side values (each the quadratic with Bernstein coefficients from h, at x,
// evaluated over s) may satisfy the mode.
template <int D>
bool set_ok(const Side_set<D> &set, const Interval *x, const Interval &s) {
  bool pos = true, neg = true;
  Interval prev;
  for (size_t i = 0; i < set.sides.size(); ++i) {
    Interval b[3];
    eval3(set.sides[i], x, b);
    const Interval v = bernstein2(b, s);
    if (set.mode == Side_mode::Opposite) {  // the two values' product may be <= 0
      if (i == 1 && (prev * v).lo > 0) return false;
      prev = v;
      continue;
    }
    pos = pos && !(v.hi < 0);
    neg = neg && !(v.lo > 0);
  }
  return set.mode == Side_mode::All_nonneg ? pos : (pos || neg);
}

template <int D>
bool sets_ok(const std::vector<Side_set<D>> &sets, const Interval *x, const Interval &s) {
  for (const Side_set<D> &set : sets)
    if (!set_ok(set, x, s)) return false;
  return true;
}

const I3 kAxes[3] = {{Interval(1.0), Interval(0.0), Interval(0.0)},
                     {Interval(0.0), Interval(1.0), Interval(0.0)},
                     {Interval(0.0), Interval(0.0), Interval(1.0)}};

}  // namespace

template <int D1, int D2>
bool Root_sides<D1, D2>::possible(const Interval *x1, const Interval *x2) const {
  Interval b[3], cell[64];
  eval3(f, x1, b);
  const int n = root_cells(b, cell);
  for (int i = 0; i < n; ++i)
    if (sets_ok(sets1, x1, cell[i]) && sets_ok(sets2, x2, cell[i])) return true;
  return false;
}

template struct Root_sides<kDimTriangle, kDimSides>;
template struct Root_sides<kDimVertex, kDimVertex>;
template struct Root_sides<kDimEdge, kDimEnds>;

Rotation_piece::Rotation_piece(const Axis_rotation &ax, const Moving_body &query, double ta, double tb)
    : q_(query), c_(ax.c) {
  const Interval u[2][2] = {{ax.alpha0 + ax.alpha1 * Interval(ta), Interval(ta)},
                            {ax.alpha0 + ax.alpha1 * Interval(tb), Interval(tb)}};
  // [a]x and 2 a a^T - |a|^2 I
  const I3 &a = ax.a;
  const std::array<I3, 3> K = {I3{Interval(0.0), -a[2], a[1]}, I3{a[2], Interval(0.0), -a[0]},
                               I3{-a[1], a[0], Interval(0.0)}};
  for (int j = 0; j < 3; ++j) {
    const int x = j == 2 ? 1 : 0, y = j == 0 ? 0 : 1;  // (u0, u0), (u0, u1), (u1, u1)
    const Interval aa = u[x][0] * u[y][0], ab = u[x][0] * u[y][1] + u[y][0] * u[x][1],
                   bb = u[x][1] * u[y][1];
    W_[j] = aa + bb * ax.a2;
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) {
        const Interval sym = Interval(2.0) * a[r] * a[k] - (r == k ? ax.a2 : Interval(0.0));
        R_[j][r][k] = (r == k ? aa : Interval(0.0)) + ab * K[r][k] + bb * sym;
      }
  }
  q_pts_.resize(query.n_points());
  Y_.resize(query.n_points());
  for (size_t k = 0; k < q_pts_.size(); ++k) {
    const I3 p = enclose_point(query.point(k));
    I3 q;
    for (int i = 0; i < 3; ++i) q[i] = ax.M0[i][0] * p[0] + ax.M0[i][1] * p[1] + ax.M0[i][2] * p[2] + ax.v0[i];
    q_pts_[k] = q;
    for (int j = 0; j < 3; ++j) Y_[k][j] = add(scale3(W_[j], c_), rot(j, q));
  }
}

Rotation_piece::I3 Rotation_piece::rot(int j, const I3 &v) const {
  return {dot(R_[j][0], v), dot(R_[j][1], v), dot(R_[j][2], v)};
}

void Rotation_piece::add_ball_vs_balls(uint32_t k, Cnf<kDimBall> &q) const {
  // W_j (|c|^2 + |q|^2 - rho^2) + 2 c . R_j q + c_S . (-2 W_j c - 2 R_j q) + W_j s_S - 2 rho W_j r
  const Interval rho = arith::enclose(q_.spheres->radii()[k]);
  const I3 &p = q_pts_[k];
  const Interval base = dot(c_, c_) + dot(p, p) - rho * rho;
  Quadratic<kDimBall> c;
  c.kind = Quadratic<kDimBall>::Nonpositive;
  for (int j = 0; j < 3; ++j) {
    const I3 rq = rot(j, p);
    const I3 g = scale3(Interval(-2.0), add(scale3(W_[j], c_), rq));
    for (int i = 0; i < 3; ++i) c.f[j].a[i] = g[i];
    c.f[j].a[3] = W_[j];
    c.f[j].a[4] = Interval(-2.0) * rho * W_[j];
    c.f[j].a0 = W_[j] * base + Interval(2.0) * dot(c_, rq);
  }
  q.quads.push_back(c);
}

Root_sides<kDimTriangle, kDimSides> Rotation_piece::vertex_vs_triangle_sides(uint32_t v) const {
  // Plane: n . Y_j - (n . a0) W_j (lifted coordinates 0..3). Sides, per axis e: the line
  // (W e, Y x e) through the vertex against the stored sides (u_i, v_i):
  // u_i . (Y_j x e) + W_j e . v_i.
  Root_sides<kDimTriangle, kDimSides> r;
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 3; ++k) r.f[j].a[k] = Y_[v][j][k];
    r.f[j].a[3] = -W_[j];
  }
  r.sets2.resize(3);
  for (int ax = 0; ax < 3; ++ax) {
    auto &sides = r.sets2[ax].sides;
    sides.resize(3);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const I3 m = cross(Y_[v][j], kAxes[ax]);
        for (int k = 0; k < 3; ++k) sides[i][j].a[6 * i + k] = m[k];
        sides[i][j].a[6 * i + 3 + ax] = W_[j];
      }
  }
  return r;
}

Root_sides<kDimVertex, kDimVertex> Rotation_piece::triangle_vs_vertex_sides(uint32_t tri) const {
  // The query triangle q0 q1 q2 (relative to c) turns by R(s): plane
  // (R_j n) . (p - c) - (n . q0) W_j, sides (R_j m_i) . (p - c) - (m_i . q_i) W_j >= 0 with
  // n = (q1 - q0) x (q2 - q0), m_i = n x (q_{i+1} - q_i) (R preserves dot products).
  const auto &t = q_.mesh->triangles()[tri];
  const I3 qs[3] = {q_pts_[t[0]], q_pts_[t[1]], q_pts_[t[2]]};
  const I3 n = cross(sub(qs[1], qs[0]), sub(qs[2], qs[0]));
  auto lin = [&](const I3 &m, const Interval &off, int j) {
    Halfspace<kDimVertex> h;
    const I3 rm = rot(j, m);
    for (int k = 0; k < 3; ++k) h.a[k] = rm[k];
    h.a0 = -dot(rm, c_) - off * W_[j];
    return h;
  };
  Root_sides<kDimVertex, kDimVertex> r;
  for (int j = 0; j < 3; ++j) r.f[j] = lin(n, dot(n, qs[0]), j);
  r.sets1.resize(1);
  r.sets1[0].mode = Side_mode::All_nonneg;
  auto &sides = r.sets1[0].sides;
  sides.resize(3);
  for (int i = 0; i < 3; ++i) {
    const I3 m = cross(n, sub(qs[(i + 1) % 3], qs[i]));
    for (int j = 0; j < 3; ++j) sides[i][j] = lin(m, dot(m, qs[i]), j);
  }
  return r;
}

Root_sides<kDimEdge, kDimEnds> Rotation_piece::edge_vs_edge_sides(uint32_t e) const {
  // Query line (homogeneous): D = Rn d, Mo = c x D + Rn (q0 x q1); against the stored
  // line (d_s, m_s) (lifted coordinates 0..5): d_s . Mo + m_s . D.
  const auto &E = q_.mesh->edges()[e];
  const I3 &q0 = q_pts_[E[0]], &q1 = q_pts_[E[1]];
  const I3 d = sub(q1, q0), m = cross(q0, q1);
  Root_sides<kDimEdge, kDimEnds> r;
  r.sets1.resize(3);
  r.sets2.resize(3);
  for (int ax = 0; ax < 3; ++ax) {
    r.sets1[ax].mode = r.sets2[ax].mode = Side_mode::Opposite;
    r.sets1[ax].sides.resize(2);
    r.sets2[ax].sides.resize(2);
  }
  for (int j = 0; j < 3; ++j) {
    const I3 D = rot(j, d), Mo = add(cross(c_, D), rot(j, m));
    for (int k = 0; k < 3; ++k) {
      r.f[j].a[k] = Mo[k];
      r.f[j].a[3 + k] = D[k];
    }
    for (int ax = 0; ax < 3; ++ax) {
      const I3 &e = kAxes[ax];
      // The query endpoints' lines (W e, Y x e) against the stored line (d_s, m_s):
      // d_s . (Y x e) + W e . m_s.
      for (int s = 0; s < 2; ++s) {
        Halfspace<kDimEdge> &h = r.sets1[ax].sides[s][j];
        const I3 ye = cross(Y_[E[s]][j], e);
        for (int k = 0; k < 3; ++k) h.a[k] = ye[k];
        h.a[3 + ax] = W_[j];
      }
      // The stored endpoints' lines (e, a_k x e) against the query line (D, Mo):
      // e . Mo + D . (a_k x e) = e . Mo + a_k . (e x D).
      const I3 eD = cross(e, D);
      for (int s = 0; s < 2; ++s) {
        Halfspace<kDimEnds> &h = r.sets2[ax].sides[s][j];
        for (int k = 0; k < 3; ++k) h.a[3 * s + k] = eD[k];
        h.a0 = Mo[ax];
      }
    }
  }
  return r;
}

}  // namespace pccd::range
