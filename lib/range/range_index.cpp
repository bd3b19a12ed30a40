#include "range/range_index.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace pccd::range {

using narrow::EE;
using narrow::FV;
using narrow::SS;
using narrow::ST;
using narrow::TS;
using narrow::TT;
using narrow::VF;

namespace {
constexpr int kMax_log_pieces = 6;
constexpr size_t kChunk = 64;  // query primitives per parallel task
}  // namespace

// The trees split on the box coordinates only (Range_tree): the point of a vertex, the
// box corners lo, hi of a triangle (4..9) or an edge (6..11), the centre of a ball.
Stored_trees::Stored_trees(const Body_data &d) {
  if (d.mesh) {
    vertices = std::make_unique<Range_tree<kDimVertex>>(lift_vertices(d, d.surface_vertices), 0x7u);
    triangles = std::make_unique<Range_tree<kDimTriangle>>(lift_triangles(d), 0x3f0u);
    edges = std::make_unique<Range_tree<kDimEdge>>(lift_edges(d), 0xfc7u);
    triangle_sides = lift_triangle_sides(d);
    edge_ends = lift_edge_ends(d);
  } else {
    balls = std::make_unique<Range_tree<kDimBall>>(lift_balls(d), 0x7u);
  }
}

const Stored_trees &stored_trees(const Body_data &d) {
  return d.attached<Stored_trees>([&] { return std::make_shared<const Stored_trees>(d); });
}

Range_index::Range_index(const Pair_ctx &ctx, int stored)
    : ctx_(ctx), s_(stored), rel_(ctx.side(stored), ctx.side(1 - stored)),
      trees_(stored_trees(*ctx.side(stored).data)) {
  const Moving_body &S = ctx.side(s_), &Q = ctx.side(1 - s_);
  const Body_data &d = *S.data;
  // Pieces: the relative path length of the query body's box corners, in feature sizes.
  const Body_data &qd = *Q.data;
  std::array<std::array<double, 3>, 8> corner;
  for (int c = 0; c < 8; ++c)
    for (int a = 0; a < 3; ++a) corner[c][a] = qd.box_c[a] + ((c >> a) & 1 ? qd.box_h[a] : -qd.box_h[a]);
  std::array<double, 8> len{};
  std::array<std::array<double, 3>, 8> prev;
  for (int i = 0; i <= 16; ++i) {
    const Relative_motion::Pose pose = rel_.approx(i / 16.0);
    for (int c = 0; c < 8; ++c) {
      const std::array<double, 3> y = pose.apply(corner[c]);
      if (i > 0)
        len[c] += std::sqrt((y[0] - prev[c][0]) * (y[0] - prev[c][0]) + (y[1] - prev[c][1]) * (y[1] - prev[c][1]) +
                            (y[2] - prev[c][2]) * (y[2] - prev[c][2]));
      prev[c] = y;
    }
  }
  const double path = *std::max_element(len.begin(), len.end());
  const double feature = std::min(d.feature, qd.feature);
  int k = 0;
  while (k < kMax_log_pieces && path > feature * double(1 << k)) ++k;
  if (!std::isfinite(path)) k = kMax_log_pieces;
  pieces_ = 1 << k;
}

Prim_pair Range_index::pair(uint8_t if_a, uint8_t if_b, uint32_t stored, uint32_t query) const {
  return s_ == 0 ? Prim_pair{if_a, stored, query} : Prim_pair{if_b, query, stored};
}

size_t Range_index::query_items() const {
  const Moving_body &Q = ctx_.side(1 - s_);
  if (Q.is_mesh() && ctx_.side(s_).is_mesh()) return Q.data->surface_vertices.size() + Q.mesh->triangles().size() + Q.mesh->edges().size();
  return Q.is_mesh() ? Q.mesh->triangles().size() : Q.spheres->centers().size();
}

void Range_index::query_one(const Piece_query &pq, const Rotation_piece *rp, size_t item,
                            std::vector<Prim_pair> &out, std::vector<uint32_t> &ids) const {
  const Moving_body &S = ctx_.side(s_), &Q = ctx_.side(1 - s_);
  ids.clear();
  // Cheap box clauses against the hull of all stored points first, then the contact
  // conditions and the tree search.
  auto run = [&](const auto &tree, auto boxes, auto add) {
    auto q = boxes();
    if (!tree->may_hit(q)) return false;
    add(q);
    tree->search(q, ids);
    return true;
  };
  // Fixed-axis rotation: the exact root clause in the tree (built only past the hull
  // test), then the sides at the roots on each candidate (range/rotation_query.h).
  auto rotation = [&](const auto &tree, auto boxes, auto make, auto second, auto emit) {
    std::optional<decltype(make())> rs;
    if (!run(tree, boxes, [&](auto &q) {
          rs.emplace(make());
          q.quads.push_back(rs->clause());
        }))
      return;
    for (uint32_t i : ids)
      if (rs->possible(tree->lifted(i).data(), second(i))) emit(i);
  };
  if (S.is_mesh() && Q.is_mesh()) {
    const size_t nv = Q.data->surface_vertices.size(), nt = Q.mesh->triangles().size();
    if (item < nv) {
      const uint32_t v = Q.data->surface_vertices[item];
      if (rp)
        return rotation(
            trees_.triangles, [&] { return pq.vertex_vs_triangles_boxes(v); },
            [&] { return rp->vertex_vs_triangle_sides(v); },
            [&](uint32_t t) { return trees_.triangle_sides[t].data(); },
            [&](uint32_t t) { out.push_back(pair(FV, VF, t, v)); });
      run(trees_.triangles, [&] { return pq.vertex_vs_triangles_boxes(v); },
          [&](auto &q) { pq.add_vertex_vs_triangles(v, q); });
      if (pq.linear_translation() && !ids.empty()) {  // second level: the triangle's sides
        const Cnf<kDimSides> sides = pq.translation_sides_vs_triangles(v);
        for (uint32_t t : ids)
          if (cnf_possible(sides, trees_.triangle_sides[t].data())) out.push_back(pair(FV, VF, t, v));
        return;
      }
      for (uint32_t t : ids) out.push_back(pair(FV, VF, t, v));
    } else if (item < nv + nt) {
      const uint32_t t = static_cast<uint32_t>(item - nv);
      if (rp)
        return rotation(
            trees_.vertices, [&] { return pq.triangle_vs_vertices_boxes(t); },
            [&] { return rp->triangle_vs_vertex_sides(t); },
            [&](uint32_t i) { return trees_.vertices->lifted(i).data(); },
            [&](uint32_t i) { out.push_back(pair(VF, FV, S.data->surface_vertices[i], t)); });
      run(trees_.vertices, [&] { return pq.triangle_vs_vertices_boxes(t); },
          [&](auto &q) {
            pq.add_triangle_vs_vertices(t, q);
            if (pq.linear_translation()) pq.add_translation_sides_vs_vertices(t, q);
          });
      for (uint32_t i : ids) out.push_back(pair(VF, FV, S.data->surface_vertices[i], t));
    } else {
      const uint32_t e = static_cast<uint32_t>(item - nv - nt);
      if (rp)
        return rotation(
            trees_.edges, [&] { return pq.edge_vs_edges_boxes(e); },
            [&] { return rp->edge_vs_edge_sides(e); },
            [&](uint32_t f) { return trees_.edge_ends[f].data(); },
            [&](uint32_t f) { out.push_back(pair(EE, EE, f, e)); });
      run(trees_.edges, [&] { return pq.edge_vs_edges_boxes(e); },
          [&](auto &q) {
            pq.add_edge_vs_edges(e, q);
            if (pq.linear_translation()) pq.add_translation_sides_vs_edges(e, q);
          });
      for (uint32_t f : ids) out.push_back(pair(EE, EE, f, e));
    }
    return;
  }
  const uint32_t k = static_cast<uint32_t>(item);
  auto none = [](auto &) {};
  if (!S.is_mesh() && !Q.is_mesh()) {
    run(trees_.balls, [&] { return pq.ball_vs_balls_boxes(k); }, [&](auto &q) {
      if (rp)
        rp->add_ball_vs_balls(k, q);
      else
        pq.add_ball_vs_balls(k, q);
    });
    for (uint32_t b : ids) out.push_back(pair(SS, SS, b, k));
  } else if (!S.is_mesh()) {
    run(trees_.balls, [&] { return pq.triangle_vs_balls_boxes(k); }, none);
    for (uint32_t b : ids) out.push_back(pair(ST, TS, b, k));
  } else {
    run(trees_.triangles, [&] { return pq.ball_vs_triangles_boxes(k); }, none);
    for (uint32_t t : ids) out.push_back(pair(TS, ST, t, k));
  }
}

namespace {

// fn(i, out, ids) for i in [0, n), in parallel chunks of kChunk; the outputs in index
// order (independent of the thread count).
template <class F>
std::vector<Prim_pair> collect(size_t n, Thread_pool &pool, F fn) {
  const size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::vector<Prim_pair>> parts(chunks);
  pool.parallel_for(chunks, [&](size_t c) {
    util::work_step();  // one chunk of query primitives (util/work_budget.h)
    std::vector<uint32_t> ids;
    for (size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) fn(i, parts[c], ids);
  });
  std::vector<Prim_pair> out;
  for (auto &p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

}  // namespace

std::vector<Prim_pair> Range_index::candidates(double a, double b, Thread_pool &pool) const {
  const Piece_query pq(rel_, ctx_.side(1 - s_), a, b);
  std::optional<Rotation_piece> rp;
  if (rel_.axis_rotation && b > a) rp.emplace(*rel_.axis_rotation, ctx_.side(1 - s_), a, b);
  const Rotation_piece *r = rp ? &*rp : nullptr;
  std::vector<Prim_pair> out = collect(query_items(), pool, [&](size_t i, auto &part, auto &ids) {
    query_one(pq, r, i, part, ids);
  });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The stored triangles that some query triangle may meet at t = 0 (sorted, unique): the
// stored triangle tree searched, per query triangle, with its boxes and planes clauses
// (its corners not all strictly on one side of the stored plane, the boxes meet; both
// necessary for the closed triangles to meet).
std::vector<uint32_t> Range_index::near_at_zero(Thread_pool &pool) const {
  const Piece_query pq(rel_, ctx_.side(1 - s_), 0.0, 0.0);
  const size_t n = ctx_.side(1 - s_).mesh->triangles().size();
  const size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::vector<uint32_t>> parts(chunks);
  pool.parallel_for(chunks, [&](size_t c) {
    util::work_step();
    for (size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
      const uint32_t t = static_cast<uint32_t>(i);
      Cnf<kDimTriangle> planes = pq.triangle_vs_triangles_boxes(t);
      if (!trees_.triangles->may_hit(planes)) continue;
      pq.add_triangle_vs_triangle_planes(t, planes);
      trees_.triangles->search(planes, parts[c]);
    }
  });
  std::vector<uint32_t> out;
  for (auto &p : parts) out.insert(out.end(), p.begin(), p.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Prim_pair> Range_index::static_candidates(Thread_pool &pool) const {
  std::vector<Prim_pair> out;
  std::optional<Relative_motion> back;  // side s_'s triangles in the query side's frame
  // The stored side's triangles searched in the query side's trees: only those near
  // some query triangle (near_at_zero), and only their corners prepared (Piece_query's
  // `only`). Looping over (and preparing) every stored triangle made each on-line query
  // linear in the stored body (issue 31: 2.4 ms per query on 500 translated needles,
  // 20 ms on 8,000; now 0.8 and 1.2 ms: tests/bench/online_families.py).
  const std::vector<uint32_t> near = near_at_zero(pool);
  std::vector<uint32_t> near_points;  // their corners: the only stored points prepared
  for (uint32_t t : near)
    for (uint32_t v : ctx_.side(s_).mesh->triangles()[t]) near_points.push_back(v);
  std::sort(near_points.begin(), near_points.end());
  near_points.erase(std::unique(near_points.begin(), near_points.end()), near_points.end());
  for (int es : {s_, 1 - s_}) {         // es: the side whose edges are searched
    if (es != s_ && near.empty()) break;
    const Relative_motion &rel = es == s_ ? rel_ : back.emplace(ctx_.side(es), ctx_.side(s_));
    const Piece_query pq(rel, ctx_.side(1 - es), 0.0, 0.0, es == s_ ? nullptr : &near_points);
    const Stored_trees &trees = es == s_ ? trees_ : stored_trees(*ctx_.side(es).data);
    const motion::Mesh_body &edges_of = *ctx_.side(es).mesh;
    const size_t n = es == s_ ? ctx_.side(1 - es).mesh->triangles().size() : near.size();
    const motion::Mesh_body &tris_of = *ctx_.side(1 - es).mesh;
    std::vector<Prim_pair> part = collect(n, pool, [&](size_t i, auto &part, auto &ids) {
      const uint32_t t = es == s_ ? static_cast<uint32_t>(i) : near[i];
      auto emit = [&](uint32_t f) { part.push_back(es == 0 ? Prim_pair{TT, f, t} : Prim_pair{TT, t, f}); };
      // First: can t meet any triangle of side es at all (planes, boxes)? The pairs that
      // meet pass it both ways, so only triangles passing it are searched by edges.
      Cnf<kDimTriangle> planes = pq.triangle_vs_triangles_boxes(t);
      if (!trees.triangles->may_hit(planes)) return;
      pq.add_triangle_vs_triangle_planes(t, planes);
      const auto &c = tris_of.triangles()[t];
      if (c[0] == c[1] && c[1] == c[2]) {  // a point, no edge of its own: by triangles
        ids.clear();
        trees.triangles->search(planes, ids);
        for (uint32_t f : ids) emit(f);
        return;
      }
      if (!trees.triangles->any(planes)) return;
      Cnf<kDimEdge> q = pq.triangle_vs_edges_boxes(t);
      if (!trees.edges->may_hit(q)) return;
      pq.add_triangle_vs_edge_sides(t, q);
      ids.clear();
      trees.edges->search(q, ids);
      for (uint32_t e : ids) {
        if (!ctx_.edge_meets_triangle_at_zero(es, e, t)) continue;
        size_t count;
        const uint32_t *f = edges_of.edge_triangles(e, &count);
        for (size_t j = 0; j < count; ++j) emit(f[j]);
      }
    });
    out.insert(out.end(), part.begin(), part.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace pccd::range
