#include "pred/solve.h"

#include <algorithm>
#include <utility>

#include "poly/earliest.h"
#include "poly/integer.h"
#include "poly/rational_root.h"
#include "pred/delta_axis.h"
#include "pred/delta_filter.h"
#include "pred/filters.h"
#include "pred/static_contact.h"
#include "util/work_budget.h"

namespace pccd::pred {

using arith::Interval;
using arith::Rational;

namespace {

Rational to_rational(const Rational &x) { return x; }
Rational to_rational(const Interval &x) {
  if (x.lo != x.hi) throw arith::Internal_error("search time is not a point");
  Rational r;
  mpq_set_d(r.get_mpq_t(), x.lo);
  return r;
}

template <class NT>
void fill(Contact_result &out, const Feature_set<NT> &set, const poly::Search_result<NT> &r) {
  out.collides = r.found;
  if (!r.found) return;
  out.lo = to_rational(r.lo);
  out.hi = to_rational(r.hi);
  out.exact = r.exact;
  for (size_t i : r.which) out.features.push_back(set.features[set.systems[i].tag]);
}

template <class NT>
poly::Search_result<NT> search(const Feature_set<NT> &set, const Solve_options &opt,
                               poly::Search_state<NT> *progress = nullptr,
                               const poly::Search_state<NT> *resume = nullptr) {
  poly::Earliest_options so;
  so.tol = opt.tol;
  so.want_time = opt.want_time;
  so.until = opt.until;
  return poly::earliest_contact(set.systems, so, progress, resume);
}

// The exact twin of an interval search's last certain state: the same bounds (points,
// exact doubles) and the same systems, matched by feature and kind. Not valid when a
// system has no twin (then the exact search starts over, with the same result).
poly::Search_state<Rational> exact_state(const poly::Search_state<Interval> &st,
                                         const Feature_set<Interval> &iset,
                                         const Feature_set<Rational> &eset) {
  poly::Search_state<Rational> out;
  if (!st.valid) return out;
  for (size_t i : st.active) {
    const System<Interval> &is = iset.systems[i];
    const Feature &f = iset.features[is.tag];
    bool found = false;
    for (size_t k = 0; k < eset.systems.size() && !found; ++k)
      if (eset.features[eset.systems[k].tag] == f &&
          int(eset.systems[k].kind) == int(is.kind)) {
        out.active.push_back(k);
        found = true;
      }
    if (!found) return poly::Search_state<Rational>();
  }
  out.lo = to_rational(st.lo);
  out.hi = to_rational(st.hi);
  out.valid = true;
  return out;
}

template <class NT>
NT at_zero(const Poly<NT> &p) { return p.c.empty() ? arith::from_int<NT>(0) : p.c[0]; }

// The primitives already touch at t = 0: SPHERE_TRIANGLE, the ball meets the closed
// triangle; a query with a minimum separation delta, the closed primitives are within
// delta (the vertex's ball of radius delta meets the closed triangle or segment, or
// the segments are within delta).
template <class NT>
bool meets_at_zero(const Query_data<NT> &q) {
  std::vector<Vec3<NT>> x(q.p.size());
  for (size_t i = 0; i < q.p.size(); ++i)
    for (int a = 0; a < 3; ++a) x[i][a] = at_zero(q.p[i][a]);
  NT d = q.scale.c.empty() ? arith::from_int<NT>(1) : at_zero(q.scale);
  const NT &r = q.kind == SPHERE_TRIANGLE ? q.radius[0] : q.delta;
  NT r2d2 = r * r * d * d;
  switch (q.kind) {
    case SPHERE_TRIANGLE:
    case VERTEX_FACE: return ball_meets_triangle(x[0], r2d2, {{x[1], x[2], x[3]}});
    case VERTEX_EDGE: return ball_meets_segment(x[0], r2d2, x[1], x[2]);
    case VERTEX_VERTEX: {
      Vec3<NT> e = sub(x[0], x[1]);
      return arith::sign(dot3(e, e) - r2d2) <= 0;
    }
    case EDGE_EDGE: return segments_within(x[0], x[1], x[2], x[3], r2d2);
  }
  throw arith::Internal_error("meets_at_zero: no static test for this kind");
}

// The query over [0, u] reparametrized to [0, 1] (for the filters of a bounded search).
Query_data<Interval> restricted(const Query_data<Interval> &q, double u) {
  Query_data<Interval> r = q;
  const Interval zero(0.0), end(u);
  for (auto &p : r.p)
    for (int a = 0; a < 3; ++a) p[a] = poly::reparametrize(p[a], zero, end);
  for (auto &p : r.own)
    for (int a = 0; a < 3; ++a) p[a] = poly::reparametrize(p[a], zero, end);
  for (auto &p : r.face_normal)
    for (int a = 0; a < 3; ++a) p[a] = poly::reparametrize(p[a], zero, end);
  if (!r.scale.c.empty()) r.scale = poly::reparametrize(r.scale, zero, end);
  return r;
}

// The exact query with its points and radii scaled by the common denominator L > 0 of
// their coefficients. Every contact condition is homogeneous in point differences and
// radii (the scale D is kept; query_systems.h), so every system has the same roots and
// signs, hence the same answers, and the exact stage works on integers, which GMP
// multiplies without reducing fractions (the gcds of mpq arithmetic dominated it).
Query_data<Rational> integral(Query_data<Rational> q) {
  arith::Integer L = 1;
  auto take = [&](const Rational &x) { mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), x.get_den_mpz_t()); };
  for (const auto &pt : q.p)
    for (int a = 0; a < 3; ++a)
      for (const Rational &c : pt[a].c) take(c);
  for (const Rational &r : q.radius) take(r);
  take(q.delta);
  if (L != 1) {
    const Rational l(L);
    for (auto &pt : q.p)
      for (int a = 0; a < 3; ++a)
        for (Rational &c : pt[a].c) c *= l;
    for (Rational &r : q.radius) r *= l;
    q.delta *= l;
  }
  // The own trajectories by their own common denominator: they enter the systems only
  // through differences of two of them (query_systems.h), each scaled alike; and the
  // face normal by its own (every system is homogeneous in it).
  for (auto *v : {&q.own, &q.face_normal}) {
    arith::Integer L_own = 1;
    for (const auto &pt : *v)
      for (int a = 0; a < 3; ++a)
        for (const Rational &c : pt[a].c) mpz_lcm(L_own.get_mpz_t(), L_own.get_mpz_t(), c.get_den_mpz_t());
    if (L_own == 1) continue;
    const Rational l(L_own);
    for (auto &pt : *v)
      for (int a = 0; a < 3; ++a)
        for (Rational &c : pt[a].c) c *= l;
  }
  return q;
}

// f certainly has no rational root: its integer form misses a root modulo a small prime.
bool no_rational_root(const Poly<Rational> &f) {
  return f.degree() >= 1 && !poly::may_have_rational_root(poly::primitive_positive(f));
}

// The systems with the query's positive factors divided out (Query_data::positive_factors):
// the same roots and signs on [0, 1], fewer factors for the modular test to trip on (a
// factor W_j of a joint's quadratic has a root modulo about half the primes, so a
// product of a few of them defeats the test) and a lower degree for the exact counts.
void strip_positive(Feature_set<Rational> &set, const Query_data<Rational> &q) {
  if (q.positive_factors.empty()) return;
  for (System<Rational> &s : set.systems) {
    if (s.kind != System<Rational>::Kind::zero_f)
      s.f = poly::divide_out_positive(std::move(s.f), q.positive_factors);
    for (Poly<Rational> &g : s.g) g = poly::divide_out_positive(std::move(g), q.positive_factors);
  }
}

// True when t*, a root of the polynomial of one of the systems of `active` (the ones
// touching first), is certainly irrational: each of their exact polynomials, as an
// integer polynomial, misses a root modulo some small prime, so has no rational root
// (poly::may_have_rational_root). Builds those systems alone, not the whole set, from
// the integral query.
bool first_time_irrational(const Query_data<Rational> &q, const std::vector<Feature> &active) {
  // The face and edge-edge polynomials directly (the common case: their side
  // conditions are not needed here); any other feature through its system.
  std::vector<Poly<Rational>> fs;
  std::vector<Feature> others;
  for (const Feature &f : active) {
    const auto &p = q.p;
    const auto &i = f.points;
    if (q.has_delta)
      others.push_back(f);  // the polynomials below are those of delta = 0
    else if (f.kind == VERTEX_FACE && q.kind == VERTEX_FACE)
      fs.push_back(vertex_face_polynomial(p[i[0]], {{&p[i[1]], &p[i[2]], &p[i[3]]}}));
    else if (f.kind == EDGE_EDGE && q.kind == EDGE_EDGE)
      fs.push_back(edge_edge_polynomial(p[i[0]], p[i[1]], p[i[2]], p[i[3]]));
    else
      others.push_back(f);
  }
  if (!others.empty()) {
    const Feature_set<Rational> part = build_systems(q, &others);
    if (part.systems.size() != others.size()) return false;
    for (const System<Rational> &s : part.systems) {
      if (s.kind == System<Rational>::Kind::zero_f) return false;
      fs.push_back(s.f);
    }
  }
  if (fs.empty()) return false;
  for (const Poly<Rational> &f : fs)
    if (!no_rational_root(poly::divide_out_positive(f, q.positive_factors))) return false;
  return true;
}

// Touching at t = 0 by the static test: the feature is the whole query (its kind, all
// its points).
void set_contact_at_zero(Contact_result &out, int stage, int kind) {
  out.collides = out.exact = true;
  out.lo = out.hi = 0;
  Feature whole{kind, {{0, 1, -1, -1}}};
  const int points = kind == VERTEX_EDGE ? 3 : kind == VERTEX_VERTEX ? 2 : 4;
  for (int i = 0; i < points; ++i) whole.points[i] = i;
  out.features = {whole};
  out.stage = stage;
}

// The query at minimum separation delta > 0 (Solve_options::delta): radii + delta for
// balls, the delta systems for the point kinds (query_systems.h, has_delta).
template <class NT>
Query_data<NT> with_delta(Query_data<NT> q, const NT &delta) {
  if (q.kind == SPHERE_SPHERE || q.kind == SPHERE_TRIANGLE) {
    q.radius[0] = q.radius[0] + delta;
  } else {
    q.has_delta = true;
    q.delta = delta;
  }
  return q;
}

Contact_result solve_at(const Query_data<Interval> &iq,
                        const std::function<Query_data<Rational>()> &exact_points,
                        const Solve_options &opt, Irrational_features *known, bool filters = true);

// Whether an earlier query of the pair found one of this query's vertex-edge or
// vertex-vertex features (delta_systems.h, in its order of points) among those touching
// first (Irrational_features::has): this query has that contact too, no later than the
// bound the earlier one set, so the exclusion filters, which look for no contact up to
// `until`, fail. The feature pairs tied at one vertex-edge approach (7 on the UR5's)
// each spent about a fifth of their solve in them (issue 33). Skipping a filter only
// costs time: the search decides either way.
bool touches_known(int kind, const Irrational_features *known) {
  if (!known) return false;
  auto has = [&](int k, int a, int b, int c) { return known->has(Feature{k, {{a, b, c, -1}}}); };
  if (kind == VERTEX_FACE)
    for (int i = 1; i <= 3; ++i)
      if (has(VERTEX_EDGE, 0, i, 1 + i % 3) || has(VERTEX_VERTEX, 0, i, -1)) return true;
  if (kind == EDGE_EDGE)
    for (int i = 0; i < 2; ++i)
      if (has(VERTEX_EDGE, i, 2, 3) || has(VERTEX_EDGE, 2 + i, 0, 1) || has(VERTEX_VERTEX, i, 2, -1) ||
          has(VERTEX_VERTEX, i, 3, -1))
        return true;
  return false;
}

// solve's body for an interval query given as an lvalue (copied into its delta form) or
// as an rvalue (moved: the query's trajectories are not copied again; a robot window's
// feature pairs, each excluded after a few cheap tests, spent about 4% copying them).
template <class Q>
Contact_result solve_query(Q &&iq, const std::function<Query_data<Rational>()> &exact_points,
                           const Solve_options &opt, Irrational_features *known) {
  if (sgn(opt.delta) < 0) throw arith::Internal_error("solve: a negative minimum distance");
  if (!opt.min_distance()) return solve_at(iq, exact_points, opt, known);
  // A plain linear query: first the separating-direction filter (delta_filter.h), which
  // pccd_solve_linear_d and the batch run on the same enclosures before building iq.
  // Any other query: first the nearest-point axis filter (delta_axis.h).
  Linear_points lp;
  const bool linear = linear_points_of(iq, lp);
  const int kind = iq.kind;
  const Query_data<Interval> dq = with_delta(std::forward<Q>(iq), opt.delta_box);
  const bool filters = !touches_known(kind, known);
  if (filters && (linear ? delta_separated(kind, lp, opt.delta_box) : delta_axis_separated(dq))) {
    util::work_step();  // one query, as in solve_at
    Contact_result out;
    out.stage = STAGE_BOUNDS;
    return out;
  }
  return solve_at(dq, [&] { return with_delta(exact_points(), opt.delta); }, opt, known, filters);
}

}  // namespace

Contact_result solve(const Query_data<Interval> &iq, const std::function<Query_data<Rational>()> &exact_points,
                     const Solve_options &opt, Irrational_features *known) {
  return solve_query(iq, exact_points, opt, known);
}

Contact_result solve(Query_data<Interval> &&iq, const std::function<Query_data<Rational>()> &exact_points,
                     const Solve_options &opt, Irrational_features *known) {
  return solve_query(std::move(iq), exact_points, opt, known);
}

namespace {

Contact_result solve_at(const Query_data<Interval> &iq,
                        const std::function<Query_data<Rational>()> &exact_points,
                        const Solve_options &opt, Irrational_features *known, bool filters) {
  Contact_result out;
  util::work_step();  // one query (util/work_budget.h)
  // filters false (touches_known): none of them can exclude this query.
  if (filters && bounds_separate(iq)) {
    out.stage = STAGE_BOUNDS;
    return out;
  }
  if (filters && bernstein_excludes(iq)) {
    out.stage = STAGE_BERNSTEIN;
    return out;
  }
  // Only contacts up to `until` are wanted: the same filters over [0, u], u >= until.
  if (filters && opt.want_time && opt.until < 1) {
    const double u = arith::enclose(opt.until).hi;
    if (u < 1) {
      const Query_data<Interval> r = restricted(iq, u);
      if (bounds_separate(r)) {
        out.stage = STAGE_BOUNDS;
        return out;
      }
      if (bernstein_excludes(r)) {
        out.stage = STAGE_BERNSTEIN;
        return out;
      }
      // With a minimum distance, the axis filter too (delta_axis.h: polynomial queries
      // only, as in solve; most feature pairs after the first contact end here).
      Linear_points lp;
      if (r.has_delta && !linear_points_of(iq, lp) && delta_axis_separated(r)) {
        out.stage = STAGE_BOUNDS;
        return out;
      }
    }
  }
  if (iq.kind == SPHERE_TRIANGLE || iq.has_delta) {
    bool meets;
    int stage = STAGE_INTERVAL;
    try {
      meets = meets_at_zero(iq);
    } catch (const arith::Uncertain &) {
      meets = meets_at_zero(integral(exact_points()));
      stage = STAGE_EXACT;
    }
    if (meets) {
      set_contact_at_zero(out, stage, iq.kind);
      return out;
    }
  }
  bool decided = false;
  // Where the interval bisection stood when it could not tell (the exact search goes on
  // from there: the midpoint bisection's steps do not depend on the stage taking them).
  poly::Search_state<Interval> progress;
  Feature_set<Interval> iset;
  if (opt.interval_search) try {
      iset = build_systems(iq);
      poly::Search_result<Interval> r = search(iset, opt, &progress);
      fill(out, iset, r);
      out.stage = STAGE_INTERVAL;
      decided = true;
    } catch (const arith::Uncertain &) {
      out = Contact_result();
    }
  if (decided && !(out.collides && opt.want_time && opt.want_exact && !out.exact)) return out;

  // A time was enclosed in intervals and may be rational. Most are not, which a cheap
  // modular test of the first-touching systems alone proves.
  // Every feature touching first already proven so in an earlier query of the pair: the
  // same answer without the exact query (the feature pairs of one vertex-vertex
  // approach, 35-47 on the UR5's, share its vertex-vertex feature; issue 33).
  auto is_known = [&](const Feature &f) { return known->has(f); };
  if (decided && known && !out.features.empty() && std::all_of(out.features.begin(), out.features.end(), is_known))
    return out;
  const Query_data<Rational> eq = integral(exact_points());
  if (decided && first_time_irrational(eq, out.features)) {
    if (known)
      for (const Feature &f : out.features) known->add(f);
    return out;
  }
  // A decided search needs only the systems of the features touching first (the
  // rationality test below); the exact search resumes from the interval one's last
  // state, which looks at that state's active systems alone (poly/earliest.h), so it
  // needs theirs; from scratch it needs them all. (Building and stripping all seven to
  // nine delta systems in rationals was most of the exact stage of a robot's near
  // vertex-vertex approaches, the interval bisection ending near 2^-23; issue 33.)
  std::vector<Feature> resumed;
  if (!decided && progress.valid)
    for (size_t i : progress.active) resumed.push_back(iset.features[iset.systems[i].tag]);
  Feature_set<Rational> set = decided ? build_systems(eq, &out.features)
                              : resumed.empty() ? build_systems(eq) : build_systems(eq, &resumed);
  strip_positive(set, eq);
  if (!decided) {
    poly::Search_state<Rational> resume = exact_state(progress, iset, set);
    if (!resume.valid && !resumed.empty()) {  // a system with no exact twin: from scratch
      set = build_systems(eq);
      strip_positive(set, eq);
      resume = exact_state(progress, iset, set);
    }
    poly::Search_result<Rational> r = search<Rational>(set, opt, nullptr, &resume);
    fill(out, set, r);
    out.stage = STAGE_EXACT;
    if (!(out.collides && opt.want_time && opt.want_exact && !out.exact)) return out;
    // Continue below with the exact enclosure.
  }
  // Is the first contact time rational? Only the systems touching in (lo, hi] matter;
  // features are identified by tag, which is the same for both number types.
  std::vector<size_t> active;
  for (size_t i = 0; i < set.systems.size(); ++i)
    for (const Feature &f : out.features)
      if (set.features[set.systems[i].tag] == f) active.push_back(i);
  // After the exact search, the modular test first (the interval path ran it above): when
  // none of their polynomials can have a rational root, t* is irrational and the
  // enclosure stays (what rational_first_contact would find, at a fraction of its cost).
  if (!decided) {
    bool irrational = !active.empty();
    for (size_t i : active)
      irrational = irrational && set.systems[i].kind != System<Rational>::Kind::zero_f &&
                   no_rational_root(set.systems[i].f);
    if (irrational) return out;
  }
  poly::Rational_root_result rr = poly::rational_first_contact(set.systems, active, out.lo, out.hi);
  out.stage = STAGE_EXACT;  // exact root isolation decided whether the time is rational
  if (rr.exact) {
    out.exact = true;
    out.lo = out.hi = rr.t;
    out.features.clear();
    for (size_t i : rr.which) out.features.push_back(set.features[set.systems[i].tag]);
  }
  return out;
}

}  // namespace

}  // namespace pccd::pred
