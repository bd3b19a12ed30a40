#include "range/linearize.h"

#include <algorithm>
#include <cmath>

#include "arith/convert.h"
#include "range/ivec.h"
#include "range/scaled_bernstein.h"
#include "util/work_budget.h"

namespace pccd::range {

namespace {

// The interval-vector operations (range/ivec.h) and their Bernstein-form twins.
using range::cross;
using range::dot;
using range::sub;
using S3 = std::array<Sb, 3>;
S3 sub(const S3 &a, const S3 &b) { return {sb_sub(a[0], b[0]), sb_sub(a[1], b[1]), sb_sub(a[2], b[2])}; }
Sb det2(const Sb &a, const Sb &b, const Sb &c, const Sb &d) { return sb_sub(sb_mul(a, b), sb_mul(c, d)); }
S3 cross(const S3 &a, const S3 &b) {
  return {det2(a[1], b[2], a[2], b[1]), det2(a[2], b[0], a[0], b[2]), det2(a[0], b[1], a[1], b[0])};
}
Sb dot(const S3 &a, const S3 &b) {
  return sb_add(sb_add(sb_mul(a[0], b[0]), sb_mul(a[1], b[1])), sb_mul(a[2], b[2]));
}

// Plücker coordinates of the segment a -> b, (b - a, a x b), into out[0..5].
void put_plucker(const I3 &a, const I3 &b, Interval *out) {
  const I3 d = sub(b, a), m = cross(a, b);
  for (int k = 0; k < 3; ++k) {
    out[k] = d[k];
    out[3 + k] = m[k];
  }
}

// Box corners of a primitive's corner points: lo encloses the exact minimum, hi the
// exact maximum of each coordinate.
template <size_t N>
void box_of(const std::array<I3, N> &c, Interval *lo, Interval *hi) {
  for (int k = 0; k < 3; ++k) {
    Interval l = c[0][k], h = c[0][k];
    for (size_t i = 1; i < N; ++i) {
      l = Interval(std::min(l.lo, c[i][k].lo), std::min(l.hi, c[i][k].hi));
      h = Interval(std::max(h.lo, c[i][k].lo), std::max(h.hi, c[i][k].hi));
    }
    lo[k] = l;
    hi[k] = h;
  }
}

// A polynomial linear in the lifted point s: sum_k s_k c[k] + c0, scaled Bernstein
// forms (range/scaled_bernstein.h) on the piece.
template <int D>
struct Lin {
  std::array<Sb, D> c;
  Sb c0;
};

// Appends the halfspaces "sign * A_j >= 0" for the scaled Bernstein coefficients A_j of
// f at the common degree of its parts (their disjunction: sign * f may be >= 0 on the
// piece) to the open clause.
template <int D>
void add_halfspaces(Cnf<D> &q, const Lin<D> &f, int sign) {
  size_t n = sb_degree(f.c0);
  for (const Sb &p : f.c) n = std::max(n, sb_degree(p));
  std::array<Sb, D> c;
  for (int d = 0; d < D; ++d) c[d] = sb_elevate(f.c[d], n);
  const Sb c0 = sb_elevate(f.c0, n);
  for (size_t k = 0; k <= n; ++k) {
    Halfspace<D> h;
    for (int d = 0; d < D; ++d) {
      const Interval x = c[d].empty() ? Interval(0.0) : c[d][k];
      h.a[d] = sign > 0 ? x : -x;
    }
    const Interval x0 = c0.empty() ? Interval(0.0) : c0[k];
    h.a0 = sign > 0 ? x0 : -x0;
    q.hs.push_back(h);
  }
}

template <int D>
void clause(Cnf<D> &q, const Lin<D> &f, int sign) {
  add_halfspaces(q, f, sign);
  q.end_clause();
}

// f may vanish on the piece: some A_j >= 0 and some A_j <= 0.
template <int D>
void vanishes(Cnf<D> &q, const Lin<D> &f) {
  clause(q, f, +1);
  clause(q, f, -1);
}

std::array<IPoly, 3> reparam(const std::array<IPoly, 3> &p, const Interval &a, const Interval &b) {
  return {poly::reparametrize(p[0], a, b), poly::reparametrize(p[1], a, b),
          poly::reparametrize(p[2], a, b)};
}

double approx_eval(const IPoly &p, double t) {
  double s = 0;
  for (size_t i = p.c.size(); i-- > 0;) s = s * t + 0.5 * (p.c[i].lo + p.c[i].hi);
  return s;
}

}  // namespace

std::vector<std::array<Interval, kDimVertex>> lift_vertices(const Body_data &b,
                                                           const std::vector<uint32_t> &ids) {
  std::vector<std::array<Interval, kDimVertex>> out;
  out.reserve(ids.size());
  for (uint32_t v : ids) {
    if (out.size() % 256 == 0) util::work_step();  // per 256 points (util/work_budget.h)
    out.push_back(enclose_point(b.mesh->vertices()[v]));
  }
  return out;
}

std::vector<std::array<Interval, kDimTriangle>> lift_triangles(const Body_data &b) {
  const auto &V = b.mesh->vertices();
  std::vector<std::array<Interval, kDimTriangle>> out;
  out.reserve(b.mesh->triangles().size());
  for (const auto &t : b.mesh->triangles()) {
    if (out.size() % 256 == 0) util::work_step();  // per 256 triangles
    const std::array<I3, 3> c = {enclose_point(V[t[0]]), enclose_point(V[t[1]]), enclose_point(V[t[2]])};
    const I3 n = cross(sub(c[1], c[0]), sub(c[2], c[0]));
    std::array<Interval, kDimTriangle> s;
    for (int k = 0; k < 3; ++k) s[k] = n[k];
    s[3] = dot(n, c[0]);
    box_of(c, &s[4], &s[7]);
    out.push_back(s);
  }
  return out;
}

std::vector<std::array<Interval, kDimEdge>> lift_edges(const Body_data &b) {
  const auto &V = b.mesh->vertices();
  std::vector<std::array<Interval, kDimEdge>> out;
  out.reserve(b.mesh->edges().size());
  for (const auto &e : b.mesh->edges()) {
    if (out.size() % 256 == 0) util::work_step();  // per 256 edges
    const std::array<I3, 2> c = {enclose_point(V[e[0]]), enclose_point(V[e[1]])};
    std::array<Interval, kDimEdge> s;
    put_plucker(c[0], c[1], &s[0]);
    box_of(c, &s[6], &s[9]);
    out.push_back(s);
  }
  return out;
}

std::vector<std::array<Interval, kDimBall>> lift_balls(const Body_data &b) {
  const auto &C = b.spheres->centers();
  const auto &R = b.spheres->radii();
  std::vector<std::array<Interval, kDimBall>> out;
  out.reserve(C.size());
  for (size_t i = 0; i < C.size(); ++i) {
    if (i % 256 == 0) util::work_step();  // per 256 balls
    const I3 c = enclose_point(C[i]);
    const Interval r = arith::enclose(R[i]);
    out.push_back({c[0], c[1], c[2], dot(c, c) - r * r, r});
  }
  return out;
}

std::vector<std::array<Interval, kDimSides>> lift_triangle_sides(const Body_data &b) {
  const auto &V = b.mesh->vertices();
  std::vector<std::array<Interval, kDimSides>> out;
  out.reserve(b.mesh->triangles().size());
  for (const auto &t : b.mesh->triangles()) {
    if (out.size() % 256 == 0) util::work_step();  // per 256 triangles
    const std::array<I3, 3> c = {enclose_point(V[t[0]]), enclose_point(V[t[1]]), enclose_point(V[t[2]])};
    std::array<Interval, kDimSides> s;
    for (int i = 0; i < 3; ++i) put_plucker(c[i], c[(i + 1) % 3], &s[6 * i]);
    out.push_back(s);
  }
  return out;
}

bool is_linear_translation(const Moving_body &b) {
  if (b.mo->W.degree() > 0) return false;
  for (int i = 0; i < 3; ++i) {
    if (b.mo->O[i].degree() > 1) return false;
    for (int j = 0; j < 3; ++j)
      if (b.mo->Rn[i][j].degree() > 0) return false;
  }
  return true;
}

namespace {

}  // namespace

Relative_motion::Relative_motion(const Moving_body &S, const Moving_body &Q) {
  linear_translation = is_linear_translation(S) && is_linear_translation(Q);
  if (!linear_translation) axis_rotation = detect_axis_rotation(S, Q);
  Relative_pose<IPoly> r = relative_pose(S.mo->Rn_i, S.mo->O_i, S.mo->W_i, Q.mo->Rn_i, Q.mo->O_i, Q.mo->W_i);
  M = std::move(r.M);
  u = std::move(r.u);
  w = std::move(r.w);
}

Relative_motion::Pose Relative_motion::approx(double t) const {
  Pose p;
  p.w = approx_eval(w, t);
  for (int i = 0; i < 3; ++i) {
    p.u[i] = approx_eval(u[i], t);
    for (int j = 0; j < 3; ++j) p.M[i][j] = approx_eval(M[i][j], t);
  }
  return p;
}

Piece_query::Piece_query(const Relative_motion &rel, const Moving_body &query, double a, double b, const Ids *only)
    : q_(query), translation_(rel.linear_translation) {
  const Interval ia(a), ib(b);
  std::array<std::array<IPoly, 3>, 3> M;
  std::array<IPoly, 3> u;
  for (int i = 0; i < 3; ++i) M[i] = reparam(rel.M[i], ia, ib);
  u = reparam(rel.u, ia, ib);
  const IPoly w = poly::reparametrize(rel.w, ia, ib);
  size_t n = std::max<size_t>(1, w.c.size()) - 1;
  for (int i = 0; i < 3; ++i) {
    n = std::max(n, u[i].c.empty() ? size_t(0) : u[i].c.size() - 1);
    for (int j = 0; j < 3; ++j) n = std::max(n, M[i][j].c.empty() ? size_t(0) : M[i][j].c.size() - 1);
  }
  std::array<std::array<Sb, 3>, 3> Ms;
  std::array<Sb, 3> us;
  for (int i = 0; i < 3; ++i) {
    us[i] = sb_elevate(sb_from_power(u[i], n), n);
    for (int j = 0; j < 3; ++j) Ms[i][j] = sb_elevate(sb_from_power(M[i][j], n), n);
  }
  w_ = sb_from_power(w, n);
  w2_ = sb_mul(w_, w_);
  H_.resize(query.n_points());
  for (size_t at = 0; at < (only ? only->size() : H_.size()); ++at) {
    const size_t k = only ? (*only)[at] : at;
    const I3 p = enclose_point(query.point(k));
    for (int i = 0; i < 3; ++i) {
      Sb h(n + 1, Interval(0.0));
      for (size_t j = 0; j <= n; ++j) {
        Interval x = us[i].empty() ? Interval(0.0) : us[i][j];
        for (int c = 0; c < 3; ++c)
          if (!Ms[i][c].empty()) x = x + p[c] * Ms[i][c][j];
        h[j] = x;
      }
      H_[k][i] = std::move(h);
    }
  }
  bool positive = true;
  for (const Interval &x : w_) positive = positive && x.lo > 0;
  if (!positive) return;
  ybox_.resize(H_.size());
  for (size_t at = 0; at < (only ? only->size() : H_.size()); ++at)
    for (size_t i = 0, k = only ? (*only)[at] : at; i < 3; ++i) {
      Interval b(HUGE_VAL, -HUGE_VAL);
      for (size_t j = 0; j <= n; ++j) {
        const Interval y = H_[k][i][j] / w_[j];
        b = Interval(std::min(b.lo, y.lo), std::max(b.hi, y.hi));
      }
      ybox_[k][i] = b;
    }
}

// Conditions "the stored primitive's box [lo, hi] (lifted coordinates lo_at + k,
// hi_at + k) meets the box of the query points pts, each grown by rho, at the same time".
// When every Bernstein coefficient of w is certainly > 0, y_k = H_k / w lies between the
// least and the largest ratio A_j / W_j of its coefficients (rational Bernstein convex
// hull: y(s) = sum A_j b_j(s) / sum W_j b_j(s) is a convex combination of them), so the
// conditions are the bounds lo_k <= max + rho and hi_k >= min - rho (ybox_, rounded
// outward). Otherwise the clauses "some coefficient of H_i,k + rho w - lo_k w is >= 0"
// and "some coefficient of hi_k w + rho w - H_i,k is >= 0" over the points i.
template <int D>
void Piece_query::box_conditions(Cnf<D> &q, std::initializer_list<uint32_t> pts, int lo_at,
                                 int hi_at, const Interval *rho) const {
  if (!ybox_.empty()) {
    const double r = rho ? rho->hi : 0.0;
    for (int k = 0; k < 3; ++k) {
      double mn = HUGE_VAL, mx = -HUGE_VAL;
      for (uint32_t p : pts) {
        mn = std::min(mn, ybox_[p][k].lo);
        mx = std::max(mx, ybox_[p][k].hi);
      }
      q.bounds.push_back({static_cast<uint8_t>(lo_at + k), true, r ? arith::round_up(mx + r) : mx});
      q.bounds.push_back({static_cast<uint8_t>(hi_at + k), false, r ? arith::round_down(mn - r) : mn});
    }
    return;
  }
  const Sb rho_w = rho ? sb_scale(*rho, w_) : Sb();
  for (int k = 0; k < 3; ++k)
    for (int side = 0; side < 2; ++side) {
      for (uint32_t p : pts) {
        const Sb &h = H(p)[k];
        Lin<D> g;
        if (side == 0) {  // H_k + rho w - lo_k w >= 0
          g.c[lo_at + k] = sb_neg(w_);
          g.c0 = rho ? sb_add(h, rho_w) : h;
        } else {  // hi_k w + rho w - H_k >= 0
          g.c[hi_at + k] = w_;
          g.c0 = rho ? sb_sub(rho_w, h) : sb_neg(h);
        }
        add_halfspaces(q, g, +1);
      }
      q.end_clause();
    }
}

Cnf<kDimVertex> Piece_query::triangle_vs_vertices_boxes(uint32_t tri) const {
  const auto &t = q_.mesh->triangles()[tri];
  Cnf<kDimVertex> q;
  // the stored vertex p is its own box: lo = hi = p (coordinates 0..2)
  box_conditions(q, {t[0], t[1], t[2]}, 0, 0);
  return q;
}

void Piece_query::add_triangle_vs_vertices(uint32_t tri, Cnf<kDimVertex> &q) const {
  const auto &t = q_.mesh->triangles()[tri];
  const S3 *h[3] = {&H(t[0]), &H(t[1]), &H(t[2])};
  const S3 n = cross(sub(*h[1], *h[0]), sub(*h[2], *h[0]));
  // plane: n . (w p - H0) = 0
  Lin<kDimVertex> f;
  for (int k = 0; k < 3; ++k) f.c[k] = sb_mul(w_, n[k]);
  f.c0 = sb_neg(dot(n, *h[0]));
  vanishes(q, f);
  // inside: (n x (H_{i+1} - H_i)) . (w p - H_i) >= 0 for each side i
  for (int i = 0; i < 3; ++i) {
    const S3 m = cross(n, sub(*h[(i + 1) % 3], *h[i]));
    Lin<kDimVertex> g;
    for (int k = 0; k < 3; ++k) g.c[k] = sb_mul(w_, m[k]);
    g.c0 = sb_neg(dot(m, *h[i]));
    clause(q, g, +1);
  }
}

Cnf<kDimTriangle> Piece_query::triangle_vs_triangles_boxes(uint32_t tri) const {
  const auto &t = q_.mesh->triangles()[tri];
  Cnf<kDimTriangle> q;
  box_conditions(q, {t[0], t[1], t[2]}, 4, 7);
  return q;
}

void Piece_query::add_triangle_vs_triangle_planes(uint32_t tri, Cnf<kDimTriangle> &q) const {
  const auto &t = q_.mesh->triangles()[tri];
  for (int sign : {+1, -1}) {
    for (uint32_t v : t) {
      Lin<kDimTriangle> f;  // n . H_v - (n . a0) w, as in add_vertex_vs_triangles
      for (int k = 0; k < 3; ++k) f.c[k] = H(v)[k];
      f.c[3] = sb_neg(w_);
      add_halfspaces(q, f, sign);
    }
    q.end_clause();
  }
}

Cnf<kDimEdge> Piece_query::triangle_vs_edges_boxes(uint32_t tri) const {
  const auto &t = q_.mesh->triangles()[tri];
  Cnf<kDimEdge> q;
  box_conditions(q, {t[0], t[1], t[2]}, 6, 9);
  return q;
}

Cnf<kDimTriangle> Piece_query::vertex_vs_triangles_boxes(uint32_t v) const {
  Cnf<kDimTriangle> q;
  box_conditions(q, {v}, 4, 7);
  return q;
}

void Piece_query::add_vertex_vs_triangles(uint32_t v, Cnf<kDimTriangle> &q) const {
  const S3 &h = H(v);
  Lin<kDimTriangle> f;  // n . H - (n . a0) w
  for (int k = 0; k < 3; ++k) f.c[k] = h[k];
  f.c[3] = sb_neg(w_);
  vanishes(q, f);
}

Cnf<kDimEdge> Piece_query::edge_vs_edges_boxes(uint32_t e) const {
  const auto &E = q_.mesh->edges()[e];
  Cnf<kDimEdge> q;
  box_conditions(q, {E[0], E[1]}, 6, 9);
  return q;
}

void Piece_query::add_edge_vs_edges(uint32_t e, Cnf<kDimEdge> &q) const {
  const auto &E = q_.mesh->edges()[e];
  const S3 &h0 = H(E[0]), &h1 = H(E[1]);
  const S3 c = cross(h0, h1), d = sub(h1, h0);
  Lin<kDimEdge> f;  // (a1 - a0) . (H0 x H1) + w (H1 - H0) . (a0 x a1)
  for (int k = 0; k < 3; ++k) {
    f.c[k] = c[k];
    f.c[3 + k] = sb_mul(w_, d[k]);
  }
  vanishes(q, f);
}

Cnf<kDimBall> Piece_query::ball_vs_balls_boxes(uint32_t k) const {
  const Sb rho_w = sb_scale(arith::enclose(q_.spheres->radii()[k]), w_);
  const S3 &h = H(k);
  Cnf<kDimBall> q;
  // The stored ball's box is c -+ r, linear in (c, r) (lifted coordinates 0..2 and 4).
  for (int a = 0; a < 3; ++a) {
    Lin<kDimBall> lo, hi;  // H_a + rho w - (c_a - r) w >= 0; (c_a + r) w + rho w - H_a >= 0
    lo.c[a] = sb_neg(w_);
    lo.c[4] = w_;
    lo.c0 = sb_add(h[a], rho_w);
    clause(q, lo, +1);
    hi.c[a] = w_;
    hi.c[4] = w_;
    hi.c0 = sb_sub(rho_w, h[a]);
    clause(q, hi, +1);
  }
  return q;
}

void Piece_query::add_ball_vs_balls(uint32_t k, Cnf<kDimBall> &q) const {
  const S3 &h = H(k);
  const Interval rho = arith::enclose(q_.spheres->radii()[k]);
  // |H - w c|^2 - (r + rho)^2 w^2 = |H|^2 - 2 w H . c + w^2 s - 2 rho w^2 r - rho^2 w^2 <= 0
  Lin<kDimBall> f;
  for (int a = 0; a < 3; ++a) f.c[a] = sb_scale(Interval(-2.0), sb_mul(w_, h[a]));
  f.c[3] = w2_;
  f.c[4] = sb_scale(Interval(-2.0) * rho, w2_);
  f.c0 = sb_sub(dot(h, h), sb_scale(rho * rho, w2_));
  clause(q, f, -1);
}

Cnf<kDimBall> Piece_query::triangle_vs_balls_boxes(uint32_t tri) const {
  const auto &t = q_.mesh->triangles()[tri];
  const S3 *h[3] = {&H(t[0]), &H(t[1]), &H(t[2])};
  Cnf<kDimBall> q;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {  // max_i H_i,a >= (c_a - r) w; min_i H_i,a <= (c_a + r) w
      for (int i = 0; i < 3; ++i) {
        Lin<kDimBall> g;
        g.c[a] = side == 0 ? sb_neg(w_) : w_;
        g.c[4] = w_;
        g.c0 = side == 0 ? (*h[i])[a] : sb_neg((*h[i])[a]);
        add_halfspaces(q, g, +1);
      }
      q.end_clause();
    }
  return q;
}

Cnf<kDimTriangle> Piece_query::ball_vs_triangles_boxes(uint32_t k) const {
  const Interval rho = arith::enclose(q_.spheres->radii()[k]);
  Cnf<kDimTriangle> q;
  box_conditions(q, {k}, 4, 7, &rho);
  return q;
}

}  // namespace pccd::range
