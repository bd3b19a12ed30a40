#include "narrow/pair_ctx.h"

#include <algorithm>
#include <type_traits>

#include "pred/static_contact.h"

namespace pccd::narrow {

using motion::Point_traj;
using poly::Poly;

Pair_ctx::Pair_ctx(const Moving_body &a, const Moving_body &b) : A_(a), B_(b) {}

// The common-denominator trajectories, on the first solve (a pair the broad phase
// finds no candidate for never needs them; call_once: solves run in parallel).
const Pair_ctx::Common &Pair_ctx::init() const {
  std::call_once(once_, [this] { c_ = compute(); });
  return *c_;
}

std::unique_ptr<const Pair_ctx::Common> Pair_ctx::compute() const {
  auto c = std::make_unique<Common>();
  const Moving_body *sides[2] = {&A_, &B_};
  for (int s = 0; s < 2; ++s) {
    const Moving_body &me = *sides[s], &other = *sides[1 - s];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        c->M[s][i][j] = me.mo->Rn[i][j] * other.mo->W;
        c->Mi[s][i][j] = poly::convert<Interval>(c->M[s][i][j]);
      }
      c->N[s][i] = me.mo->O[i] * other.mo->W;
      c->Ni[s][i] = poly::convert<Interval>(c->N[s][i]);
    }
  }
  c->D = A_.mo->W * B_.mo->W;
  c->Di = poly::convert<Interval>(c->D);
  return c;
}

Point_traj<Rational> Pair_ctx::traj_q(int s, uint32_t k) const {
  return traj_q_.get(point_key(s, k), [&] {
    const Common &c = init();
    const motion::Point3_q &p = side(s).point(k);
    Point_traj<Rational> x;
    for (int i = 0; i < 3; ++i) {
      Poly_q v = c.N[s][i];
      for (int j = 0; j < 3; ++j)
        if (sgn(p[j]) != 0) v = v + c.M[s][i][j] * Poly_q::constant(p[j]);
      x[i] = std::move(v);
    }
    return x;
  });
}

Point_traj<Interval> Pair_ctx::traj_i(int s, uint32_t k) const {
  return traj_i_.get(point_key(s, k), [&] {
    const Common &c = init();
    const motion::Point3_q &p = side(s).point(k);
    Interval q[3];
    for (int j = 0; j < 3; ++j) q[j] = arith::enclose(p[j]);
    Point_traj<Interval> x;
    for (int i = 0; i < 3; ++i) {
      Poly<Interval> v = c.Ni[s][i];
      for (int j = 0; j < 3; ++j)
        if (!q[j].is_point_zero()) v = v + c.Mi[s][i][j] * Poly<Interval>::constant(q[j]);
      x[i] = std::move(v);
    }
    return x;
  });
}

template <class NT>
void Pair_ctx::add_rotated(Point_traj<NT> &x, int s, const motion::Point3_q &v) const {
  const Motion_data &m = *side(s).mo;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (sgn(v[j]) == 0) continue;
      if constexpr (std::is_same_v<NT, Rational>) x[i] = x[i] + m.Rn[i][j] * Poly_q::constant(v[j]);
      else x[i] = x[i] + m.Rn_i[i][j] * Poly<Interval>::constant(arith::enclose(v[j]));
    }
}

template <class NT>
Point_traj<NT> Pair_ctx::own(int s, uint32_t k) const {
  auto make = [&] {
    const Motion_data &m = *side(s).mo;
    Point_traj<NT> x;
    for (int i = 0; i < 3; ++i) {
      if constexpr (std::is_same_v<NT, Rational>) x[i] = m.O[i];
      else x[i] = m.O_i[i];
    }
    add_rotated(x, s, side(s).point(k));
    return x;
  };
  if constexpr (std::is_same_v<NT, Rational>) return own_q_.get(point_key(s, k), make);
  else return own_i_.get(point_key(s, k), make);
}

std::array<uint32_t, 3> Pair_ctx::triangle(int s, uint32_t t) const {
  return side(s).mesh->triangles()[t];
}

template <class NT>
pred::Query_data<NT> Pair_ctx::query(const Prim_pair &p, bool scaled) const {
  std::vector<std::pair<int, uint32_t>> points;  // (side, index) of q.p's points
  auto traj = [&](int s, uint32_t k) {
    points.push_back({s, k});
    if constexpr (std::is_same_v<NT, Rational>) return traj_q(s, k);
    else return traj_i(s, k);
  };
  auto convert_radius = [](const Rational &r) {
    if constexpr (std::is_same_v<NT, Rational>) return r;
    else return arith::enclose(r);
  };
  pred::Query_data<NT> q;
  switch (p.type) {
    case VF:
    case FV: {
      const int vs = p.type == VF ? 0 : 1;
      const uint32_t v = p.type == VF ? p.a : p.b, t = p.type == VF ? p.b : p.a;
      q.kind = pred::VERTEX_FACE;
      q.p.push_back(traj(vs, v));
      for (uint32_t k : triangle(1 - vs, t)) q.p.push_back(traj(1 - vs, k));
      break;
    }
    case EE: {
      q.kind = pred::EDGE_EDGE;
      for (uint32_t k : A_.mesh->edges()[p.a]) q.p.push_back(traj(0, k));
      for (uint32_t k : B_.mesh->edges()[p.b]) q.p.push_back(traj(1, k));
      break;
    }
    case SS: {
      q.kind = pred::SPHERE_SPHERE;
      q.p = {traj(0, p.a), traj(1, p.b)};
      q.radius[0] = convert_radius(A_.spheres->radii()[p.a]);
      q.radius[1] = convert_radius(B_.spheres->radii()[p.b]);
      break;
    }
    case ST:
    case TS: {
      const int bs = p.type == ST ? 0 : 1;
      const uint32_t c = p.type == ST ? p.a : p.b, t = p.type == ST ? p.b : p.a;
      q.kind = pred::SPHERE_TRIANGLE;
      q.p.push_back(traj(bs, c));
      for (uint32_t k : triangle(1 - bs, t)) q.p.push_back(traj(1 - bs, k));
      q.radius[0] = convert_radius(side(bs).spheres->radii()[c]);
      q.radius[1] = convert_radius(Rational(0));
      break;
    }
    default:
      throw arith::Internal_error("Pair_ctx::query: not a time-dependent feature pair");
  }
  if (scaled || p.type == SS || p.type == ST || p.type == TS) {
    const Common &c = init();
    if constexpr (std::is_same_v<NT, Rational>) q.scale = c.D;
    else q.scale = c.Di;
  }
  // Each side's points carry the other side's W: when one W is not a constant, the
  // systems take same-body differences from the own trajectories (pred::Query_data::own;
  // a static obstacle's edges and normals are then constants, not multiples of W).
  if (A_.mo->W.degree() >= 1 || B_.mo->W.degree() >= 1) {
    for (const auto &[s, k] : points) q.own.push_back(own<NT>(s, k));
    // The face's normal Rn_s n0 (n0 its body-frame normal, in the order of its points):
    // the cross product of its own edges is W_s Rn_s n0 (cof(Rn) = W Rn for Rn = W R).
    if (q.kind == pred::VERTEX_FACE || q.kind == pred::SPHERE_TRIANGLE) {
      const int fs = points[1].first;
      const motion::Point3_q &p0 = side(fs).point(points[1].second),
                             &p1 = side(fs).point(points[2].second),
                             &p2 = side(fs).point(points[3].second);
      Point_traj<NT> n;
      add_rotated(n, fs, pred::cross3(pred::sub(p1, p0), pred::sub(p2, p0)));
      q.face_normal.push_back(std::move(n));
    }
  }
  if constexpr (std::is_same_v<NT, Rational>) {
    // Each side's points carry the other side's W (pred::Query_data::positive_factors).
    for (const Moving_body *m : {&A_, &B_})
      if (m->mo->W.degree() >= 1) q.positive_factors.push_back(m->mo->W);
  }
  return q;
}

pred::Contact_result Pair_ctx::solve(const Prim_pair &p, const pred::Solve_options &opt) const {
  // With a minimum separation the point kinds need the scale D too: delta enters their
  // systems as delta^2 D^2 (pred/query_systems.h), the trajectories being D times the
  // positions. Without D a body whose motion has W != 1 (a rotation) was within
  // delta / D, not delta (test_min_distance.py, test_delta_scaled_by_the_motion_denominator).
  const bool scaled = opt.min_distance();
  // With a minimum separation, the pair's memo of irrational features (irrational_memo.h).
  Query_irrational::Points points;
  const int n = scaled ? query_points(p, points) : 0;
  if (n == 0 || !irrational_.bind(opt.delta))
    return pred::solve(query<Interval>(p, scaled), [&] { return query<Rational>(p, scaled); }, opt);
  Query_irrational known(irrational_, points, n);
  return pred::solve(query<Interval>(p, scaled), [&] { return query<Rational>(p, scaled); }, opt, &known);
}

int Pair_ctx::query_points(const Prim_pair &p, Query_irrational::Points &out) const {
  switch (p.type) {  // the order of query()
    case VF:
    case FV: {
      const int vs = p.type == VF ? 0 : 1;
      const std::array<uint32_t, 3> t = triangle(1 - vs, p.type == VF ? p.b : p.a);
      out = {{{vs, p.type == VF ? p.a : p.b}, {1 - vs, t[0]}, {1 - vs, t[1]}, {1 - vs, t[2]}}};
      return 4;
    }
    case EE: {
      const auto &a = A_.mesh->edges()[p.a], &b = B_.mesh->edges()[p.b];
      out = {{{0, a[0]}, {0, a[1]}, {1, b[0]}, {1, b[1]}}};
      return 4;
    }
    default:
      return 0;
  }
}

template <class NT, size_t K>
std::array<pred::Vec3<NT>, K> Pair_ctx::at_zero(int s, const std::array<uint32_t, K> &ids) const {
  // Positions at t = 0 times D(0) > 0: N_s(0) + M_s(0) p, the constant coefficients of
  // the trajectories (traj_q / traj_i), taken without making the polynomials.
  const Common &c = init();
  const NT zero(0);
  auto at0 = [&](const auto &poly) { return poly.c.empty() ? zero : poly.c[0]; };
  std::array<pred::Vec3<NT>, K> x;
  for (size_t v = 0; v < K; ++v) {
    const motion::Point3_q &p = side(s).point(ids[v]);
    for (int i = 0; i < 3; ++i) {
      if constexpr (std::is_same_v<NT, Rational>) {
        NT y = at0(c.N[s][i]);
        for (int j = 0; j < 3; ++j)
          if (sgn(p[j]) != 0) y += at0(c.M[s][i][j]) * p[j];
        x[v][i] = y;
      } else {  // p_j within pt_err of its double (Body_data), rounded outward
        const Body_data &d = *side(s).data;
        NT y = at0(c.Ni[s][i]);
        for (int j = 0; j < 3; ++j) {
          if (sgn(p[j]) == 0) continue;
          const double m = d.pts[ids[v]][j];
          const NT pj = d.pt_err == 0 ? NT(m) : NT(arith::round_down(m - d.pt_err), arith::round_up(m + d.pt_err));
          y += at0(c.Mi[s][i][j]) * pj;
        }
        x[v][i] = y;
      }
    }
  }
  return x;
}

bool Pair_ctx::triangles_meet_at_zero(uint32_t a, uint32_t b) const {
  try {
    return pred::triangles_meet(at_zero<Interval>(0, triangle(0, a)), at_zero<Interval>(1, triangle(1, b)));
  } catch (const arith::Uncertain &) {
    return pred::triangles_meet(at_zero<Rational>(0, triangle(0, a)), at_zero<Rational>(1, triangle(1, b)));
  }
}

bool Pair_ctx::edge_meets_triangle_at_zero(int s, uint32_t e, uint32_t t) const {
  const auto &E = side(s).mesh->edges()[e];
  const std::array<uint32_t, 2> ends = {E[0], E[1]};
  auto test = [&](auto zero) {
    using NT = decltype(zero);
    const auto p = at_zero<NT>(s, ends);
    const auto x = at_zero<NT>(1 - s, triangle(1 - s, t));
    return pred::segment_meets_triangle(p[0], p[1], x);
  };
  try {
    return test(Interval(0.0));
  } catch (const arith::Uncertain &) {
    return test(Rational(0));
  }
}

bool Pair_ctx::within_at_zero(const Prim_pair &p, const pred::Solve_options &opt) const {
  if (p.type != VF && p.type != FV && p.type != EE) return false;
  const Common &c = init();
  auto test = [&](auto zero) {
    using NT = decltype(zero);
    // The positions are D(0) times the true ones (at_zero), so delta enters as
    // delta^2 D(0)^2 (pred/static_contact.h), as in pred::solve's static test.
    NT d0 = zero, r = zero;
    if constexpr (std::is_same_v<NT, Rational>) {
      if (!c.D.c.empty()) d0 = c.D.c[0];
      r = opt.delta;
    } else {
      if (!c.Di.c.empty()) d0 = c.Di.c[0];
      r = opt.delta_box;
    }
    const NT r2d2 = r * r * d0 * d0;
    if (p.type == EE) {
      const auto &ea = A_.mesh->edges()[p.a], &eb = B_.mesh->edges()[p.b];
      const auto x = at_zero<NT>(0, std::array<uint32_t, 2>{ea[0], ea[1]});
      const auto y = at_zero<NT>(1, std::array<uint32_t, 2>{eb[0], eb[1]});
      return pred::segments_within(x[0], x[1], y[0], y[1], r2d2);
    }
    const int vs = p.type == VF ? 0 : 1;
    const uint32_t v = p.type == VF ? p.a : p.b, t = p.type == VF ? p.b : p.a;
    const auto x = at_zero<NT>(vs, std::array<uint32_t, 1>{v});
    return pred::ball_meets_triangle(x[0], r2d2, at_zero<NT>(1 - vs, triangle(1 - vs, t)));
  };
  try {
    return test(Interval(0.0));
  } catch (const arith::Uncertain &) {
    return test(Rational(0));
  }
}

std::vector<std::pair<Feature_ref, Feature_ref>> Pair_ctx::contacts(
    const Prim_pair &p, const pred::Contact_result &r) const {
  std::vector<std::pair<Feature_ref, Feature_ref>> out;
  auto add = [&](Feature_ref a, Feature_ref b) { out.push_back({a, b}); };
  switch (p.type) {
    case VF: add({F_VERTEX, p.a}, {F_TRIANGLE, p.b}); break;
    case FV: add({F_TRIANGLE, p.a}, {F_VERTEX, p.b}); break;
    case EE: add({F_EDGE, p.a}, {F_EDGE, p.b}); break;
    case SS: add({F_SPHERE, p.a}, {F_SPHERE, p.b}); break;
    case TT: add({F_TRIANGLE, p.a}, {F_TRIANGLE, p.b}); break;
    case IN_A: add({F_SOLID, 0}, {side(1).is_mesh() ? F_VERTEX : F_SPHERE, p.b}); break;
    case IN_B: add({side(0).is_mesh() ? F_VERTEX : F_SPHERE, p.a}, {F_SOLID, 0}); break;
    case ST:
    case TS: {
      const int ts = p.type == ST ? 1 : 0;  // the mesh side
      const uint32_t ball = p.type == ST ? p.a : p.b, t = p.type == ST ? p.b : p.a;
      const auto tri = triangle(ts, t);
      for (const pred::Feature &f : r.features) {
        Feature_ref m;
        switch (f.kind) {
          case pred::SPHERE_EDGE: {
            const int64_t e = side(ts).data->tri_edges[t][f.points[1] - 1];
            if (e < 0) throw arith::Internal_error("ball contact on a degenerate side");
            m = {F_EDGE, static_cast<uint32_t>(e)};
            break;
          }
          case pred::SPHERE_VERTEX: m = {F_VERTEX, tri[f.points[1] - 1]}; break;
          default: m = {F_TRIANGLE, t}; break;  // SPHERE_FACE, SPHERE_TRIANGLE (t = 0)
        }
        if (ts == 1) add({F_SPHERE, ball}, m);
        else add(m, {F_SPHERE, ball});
      }
      break;
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace pccd::narrow
