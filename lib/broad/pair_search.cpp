#include "broad/pair_search.h"

#include <algorithm>
#include <unordered_set>

#include "broad/boxes.h"
#include "broad/range_index.h"

namespace pccd::broad {

using arith::Rational;

void Search_stats::add(const Search_stats &o) {
  pieces += o.pieces;
  leaves += o.leaves;
  candidates += o.candidates;
  solved += o.solved;
  static_tests += o.static_tests;
  refined += o.refined;
  for (int k = 0; k < 5; ++k) by_stage[k] += o.by_stage[k];
}

namespace {

constexpr int kMax_depth = 24;       // pieces of width 2^-24 at most
constexpr double kLeaf_pairs = 64;   // |active A| * |active B| at most: intersect now

// Boxes of one side's points, cached per piece by a stamp (meshes: each vertex is
// shared by several triangles and edges; a ball's box is used once per piece, so sphere
// sets keep no cache and allocate nothing per query).
struct Side {
  const Moving_body *b = nullptr;
  std::vector<Box> vbox;
  std::vector<uint32_t> vstamp, vlisted, elisted;
  uint32_t stamp = 0;

  // The caches are allocated on first use: the range phase never uses them, and an
  // on-line query must not pay for the stored body's size.
  explicit Side(const Moving_body &body) : b(&body) {}

  void allocate() {
    if (!b->is_mesh() || !vstamp.empty()) return;
    vbox.resize(b->n_points());
    vstamp.assign(b->n_points(), 0);
    vlisted.assign(b->n_points(), 0);
    elisted.assign(b->mesh->edges().size(), 0);
  }

  Box point(const Pose_piece &pose, uint32_t k) {
    if (!b->is_mesh()) return point_box(pose, b->data->pts[k], b->data->pt_err);
    allocate();
    if (vstamp[k] != stamp) {
      vbox[k] = point_box(pose, b->data->pts[k], b->data->pt_err);
      vstamp[k] = stamp;
    }
    return vbox[k];
  }
  // Box of element e: triangle (mesh) or ball.
  Box element(const Pose_piece &pose, uint32_t e) {
    if (b->is_mesh()) {
      const auto &t = b->mesh->triangles()[e];
      return hull(hull(point(pose, t[0]), point(pose, t[1])), point(pose, t[2]));
    }
    return grow(point(pose, e), b->data->radius_up[e]);
  }
  size_t n_elements() const {
    return b->is_mesh() ? b->mesh->triangles().size() : b->spheres->centers().size();
  }
};

class Searcher {
 public:
  Searcher(const Pair_ctx &ctx, const Search_options &opt, Thread_pool &pool, Pair_outcome &out)
      : ctx_(ctx), opt_(opt), pool_(pool), out_(out), side_{Side(ctx.side(0)), Side(ctx.side(1))} {}

  void run() {
    const bool meshes = ctx_.side(0).is_mesh() && ctx_.side(1).is_mesh();
    std::unique_ptr<Range_index> index;
    if (opt_.range && !opt_.brute) {
      // The side opt_.stored, or by default the one with more elements, is stored.
      const int stored = opt_.stored >= 0 ? opt_.stored
                                          : side_[0].n_elements() >= side_[1].n_elements() ? 0 : 1;
      index = std::make_unique<Range_index>(ctx_, stored);
    }
    if (meshes) {
      static_pass(index.get());
      if (found_any_ && !opt_.all_contacts) return;
    }
    if (opt_.brute) return brute();
    if (index) return range_pieces(*index);
    std::vector<uint32_t> all[2];
    for (int s = 0; s < 2; ++s) {
      all[s].resize(side_[s].n_elements());
      for (size_t e = 0; e < all[s].size(); ++e) all[s][e] = static_cast<uint32_t>(e);
    }
    delta_ = std::min(ctx_.side(0).data->feature, ctx_.side(1).data->feature);
    piece(0.0, 1.0, 0, all[0], all[1]);
  }

 private:
  const Pair_ctx &ctx_;
  const Search_options &opt_;
  Thread_pool &pool_;
  Pair_outcome &out_;
  Side side_[2];
  std::unordered_set<uint64_t> seen_;
  bool found_any_ = false, have_best_ = false;
  Rational best_hi_;
  double delta_ = 0;
  double piece_lo_ = 0, piece_hi_ = 1;  // the leaf being intersected

  bool pruned(double a) const {
    if (opt_.all_contacts || !have_best_) return false;
    Rational ra;
    mpq_set_d(ra.get_mpq_t(), a);
    return ra > best_hi_;
  }

  pred::Solve_options bounded_options() const {
    pred::Solve_options o = opt_.solve;
    if (!opt_.all_contacts && have_best_ && opt_.solve.want_time && best_hi_ < 1) o.until = best_hi_;
    return o;
  }

  // Solves the pairs of `fresh` (not seen before) in parallel; appends the touching ones
  // in the given order and updates the best upper bound.
  void solve_batch(const std::vector<Prim_pair> &fresh) {
    if (fresh.empty()) return;
    const pred::Solve_options o = bounded_options();
    std::vector<std::unique_ptr<Solved_pair>> res(fresh.size());
    pool_.parallel_for(fresh.size(), [&](size_t i) {
      auto s = std::make_unique<Solved_pair>();
      s->prim = fresh[i];
      if (fresh[i].type == TT) {
        s->result.collides = ctx_.triangles_meet_at_zero(fresh[i].a, fresh[i].b);
        if (s->result.collides) {
          s->result.exact = true;
          s->result.lo = s->result.hi = 0;
        }
      } else {
        s->result = ctx_.solve(fresh[i], o);
      }
      res[i] = std::move(s);
    });
    for (auto &s : res) {
      seen_.insert(s->prim.key());
      if (s->prim.type == TT) ++out_.stats.static_tests;
      else {
        ++out_.stats.solved;
        if (s->result.stage >= 0 && s->result.stage < 5) ++out_.stats.by_stage[s->result.stage];
      }
      if (s->result.collides) {
        found_any_ = true;
        const Rational hi = opt_.solve.want_time ? s->result.hi : Rational(-1);
        if (!have_best_ || hi < best_hi_) best_hi_ = hi;
        have_best_ = true;
      }
      if (s->result.collides) out_.solved.push_back(std::move(s));
    }
  }

  // The pairs of cand not seen before, once each, in key order.
  std::vector<Prim_pair> fresh_of(std::vector<Prim_pair> cand) const {
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
    std::vector<Prim_pair> fresh;
    for (const Prim_pair &p : cand)
      if (!seen_.count(p.key())) fresh.push_back(p);
    return fresh;
  }

  void solve(std::vector<Prim_pair> cand) { solve_batch(fresh_of(std::move(cand))); }

  // TT at t = 0: every pair of triangles (brute), the triangles whose box meets a query
  // triangle's (range: a search of the stored triangles' tree), or box intersection.
  void static_pass(const Range_index *index) {
    std::vector<Prim_pair> cand;
    const size_t na = side_[0].n_elements(), nb = side_[1].n_elements();
    if (index) {
      cand = index->static_candidates(pool_);
    } else if (opt_.brute) {
      for (uint32_t a = 0; a < na; ++a)
        for (uint32_t b = 0; b < nb; ++b) cand.push_back({TT, a, b});
    } else {
      std::vector<Box> boxes[2];
      for (int s = 0; s < 2; ++s) {
        const Pose_piece pose = enclose_pose(*side_[s].b, 0.0, 0.0);
        ++side_[s].stamp;
        for (uint32_t e = 0; e < side_[s].n_elements(); ++e) boxes[s].push_back(side_[s].element(pose, e));
      }
      std::vector<std::pair<uint32_t, uint32_t>> pairs;
      box_pairs(boxes[0], boxes[1], pairs);
      for (auto &p : pairs) cand.push_back({TT, p.first, p.second});
    }
    solve(std::move(cand));
  }

  // The range broad phase (broad/range_index.h): pieces are visited in time order and
  // pruned like the boxes' pieces.
  void range_pieces(const Range_index &index) {
    const int n = index.pieces();
    for (int k = 0; k < n; ++k) {
      const double a = double(k) / n, b = double(k + 1) / n;  // exact: n is a power of 2
      if (pruned(a)) break;
      ++out_.stats.pieces;
      std::vector<Prim_pair> cand = index.candidates(a, b, pool_);
      if (cand.empty()) continue;
      ++out_.stats.leaves;
      out_.stats.candidates += cand.size();
      piece_lo_ = a;
      piece_hi_ = b;
      solve_in_time_order(std::move(cand));
    }
  }

  // Every feature pair of the body types.
  void brute() {
    const Moving_body &A = ctx_.side(0), &B = ctx_.side(1);
    std::vector<Prim_pair> cand;
    auto all = [&](uint8_t type, size_t na, size_t nb, const std::vector<uint32_t> *va,
                   const std::vector<uint32_t> *vb) {
      for (size_t i = 0; i < (va ? va->size() : na); ++i)
        for (size_t j = 0; j < (vb ? vb->size() : nb); ++j)
          cand.push_back({type, va ? (*va)[i] : uint32_t(i), vb ? (*vb)[j] : uint32_t(j)});
    };
    if (A.is_mesh() && B.is_mesh()) {
      all(VF, 0, B.mesh->triangles().size(), &A.data->surface_vertices, nullptr);
      all(FV, A.mesh->triangles().size(), 0, nullptr, &B.data->surface_vertices);
      all(EE, A.mesh->edges().size(), B.mesh->edges().size(), nullptr, nullptr);
    } else if (!A.is_mesh() && !B.is_mesh()) {
      all(SS, A.n_points(), B.n_points(), nullptr, nullptr);
    } else if (!A.is_mesh()) {
      all(ST, A.n_points(), B.mesh->triangles().size(), nullptr, nullptr);
    } else {
      all(TS, A.mesh->triangles().size(), B.n_points(), nullptr, nullptr);
    }
    solve(std::move(cand));
  }

  // Keeps the elements of `act` (side s) whose box meets `other`; returns their hull.
  Box filter(int s, const Pose_piece &pose, std::vector<uint32_t> &act, const Box &other) {
    Box h = empty_box();
    size_t kept = 0;
    for (uint32_t e : act) {
      Box b = side_[s].element(pose, e);
      if (!boxes_meet(b, other)) continue;
      act[kept++] = e;
      h = hull(h, b);
    }
    act.resize(kept);
    return h;
  }

  void piece(double a, double b, int depth, std::vector<uint32_t> actA, std::vector<uint32_t> actB) {
    if (pruned(a)) return;
    ++out_.stats.pieces;
    Pose_piece pose[2] = {enclose_pose(ctx_.side(0), a, b), enclose_pose(ctx_.side(1), a, b)};
    for (int s = 0; s < 2; ++s) ++side_[s].stamp;
    Box bodyB = frame_box(pose[1], ctx_.side(1).data->box_c, ctx_.side(1).data->box_h);
    Box hullA = filter(0, pose[0], actA, bodyB);
    if (actA.empty()) return;
    Box hullB = filter(1, pose[1], actB, hullA);
    if (actB.empty()) return;
    hullA = filter(0, pose[0], actA, hullB);
    if (actA.empty()) return;
    const bool leaf = depth >= kMax_depth ||
                      std::max(pose[0].spread, pose[1].spread) <= delta_ ||
                      double(actA.size()) * double(actB.size()) <= kLeaf_pairs;
    if (leaf) {
      piece_lo_ = a;
      piece_hi_ = b;
      return intersect(pose, actA, actB);
    }
    const double m = 0.5 * (a + b);  // exact: dyadic pieces
    piece(a, m, depth + 1, actA, actB);
    piece(m, b, depth + 1, std::move(actA), std::move(actB));
  }

  // Vertices and edges of the active triangles of side s (each once).
  void parts(int s, const std::vector<uint32_t> &tris, std::vector<uint32_t> &verts,
             std::vector<uint32_t> &edges) {
    Side &sd = side_[s];
    sd.allocate();
    const auto &T = sd.b->mesh->triangles();
    for (uint32_t t : tris)
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = T[t][k];
        if (sd.vlisted[v] != sd.stamp) {
          sd.vlisted[v] = sd.stamp;
          verts.push_back(v);
        }
        const int64_t e = sd.b->data->tri_edges[t][k];
        if (e >= 0 && sd.elisted[e] != sd.stamp) {
          sd.elisted[e] = sd.stamp;
          edges.push_back(static_cast<uint32_t>(e));
        }
      }
  }

  void intersect(const Pose_piece pose[2], const std::vector<uint32_t> &actA,
                 const std::vector<uint32_t> &actB) {
    ++out_.stats.leaves;
    const std::vector<uint32_t> *act[2] = {&actA, &actB};
    std::vector<Box> elem[2];
    for (int s = 0; s < 2; ++s)
      for (uint32_t e : *act[s]) elem[s].push_back(side_[s].element(pose[s], e));
    std::vector<Prim_pair> cand;
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    auto emit = [&](uint8_t type, const std::vector<uint32_t> &ia, const std::vector<uint32_t> &ib) {
      for (auto &p : pairs) cand.push_back({type, ia[p.first], ib[p.second]});
      out_.stats.candidates += pairs.size();
      pairs.clear();
    };
    const bool mA = ctx_.side(0).is_mesh(), mB = ctx_.side(1).is_mesh();
    if (mA && mB) {
      std::vector<uint32_t> verts[2], edges[2];
      std::vector<Box> vb[2], eb[2];
      for (int s = 0; s < 2; ++s) {
        parts(s, *act[s], verts[s], edges[s]);
        const auto &E = side_[s].b->mesh->edges();
        for (uint32_t v : verts[s]) vb[s].push_back(side_[s].point(pose[s], v));
        for (uint32_t e : edges[s])
          eb[s].push_back(hull(side_[s].point(pose[s], E[e][0]), side_[s].point(pose[s], E[e][1])));
      }
      box_pairs(vb[0], elem[1], pairs);
      emit(VF, verts[0], actB);
      box_pairs(elem[0], vb[1], pairs);
      emit(FV, actA, verts[1]);
      box_pairs(eb[0], eb[1], pairs);
      emit(EE, edges[0], edges[1]);
    } else {
      box_pairs(elem[0], elem[1], pairs);
      emit(!mA && !mB ? SS : !mA ? ST : TS, actA, actB);
    }
    solve_in_time_order(std::move(cand));
  }

  // The box of one side's primitive of a pair over a pose (vertex, edge, triangle, ball).
  Box prim_box(int s, uint8_t type, uint32_t k, const Pose_piece &pose) {
    Side &sd = side_[s];
    const bool vertex = (s == 0 && type == VF) || (s == 1 && type == FV);
    if (vertex) return point_box(pose, sd.b->data->pts[k], sd.b->data->pt_err);
    if (type == EE) {
      const auto &e = sd.b->mesh->edges()[k];
      return hull(point_box(pose, sd.b->data->pts[e[0]], sd.b->data->pt_err),
                  point_box(pose, sd.b->data->pts[e[1]], sd.b->data->pt_err));
    }
    if (!sd.b->is_mesh()) return grow(point_box(pose, sd.b->data->pts[k], sd.b->data->pt_err), sd.b->data->radius_up[k]);
    const auto &t = sd.b->mesh->triangles()[k];
    Box h = point_box(pose, sd.b->data->pts[t[0]], sd.b->data->pt_err);
    for (int v = 1; v < 3; ++v) h = hull(h, point_box(pose, sd.b->data->pts[t[v]], sd.b->data->pt_err));
    return h;
  }

  // Candidates of a leaf piece [a, b]: each gets the start of the first of kSub equal
  // sub-pieces on which its two boxes meet (a lower bound of its contacts in [a, b];
  // none: no contact in [a, b], so it is left for a later piece). They are solved in
  // order of that bound, in batches of fixed, growing sizes; a batch starts only with pairs whose
  // bound is <= the best upper bound so far, and each pair is asked only for contacts
  // up to that bound (pred::Solve_options::until). Batches do not depend on threads.
  void solve_in_time_order(std::vector<Prim_pair> cand) {
    std::vector<Prim_pair> fresh = fresh_of(std::move(cand));
    if (fresh.empty()) return;
    constexpr int kSub = 8;
    constexpr size_t kBatch = 64;
    const double a = piece_lo_, b = piece_hi_;
    std::vector<std::array<Pose_piece, 2>> sub(kSub);
    for (int k = 0; k < kSub; ++k)
      for (int s = 0; s < 2; ++s)
        sub[k][s] = enclose_pose(ctx_.side(s), a + (b - a) * k / kSub, k + 1 == kSub ? b : a + (b - a) * (k + 1) / kSub);
    std::vector<std::pair<double, Prim_pair>> order;
    for (const Prim_pair &p : fresh)
      for (int k = 0; k < kSub; ++k)
        if (boxes_meet(prim_box(0, p.type, p.a, sub[k][0]), prim_box(1, p.type, p.b, sub[k][1]))) {
          order.push_back({a + (b - a) * k / kSub, p});
          break;
        }
    std::sort(order.begin(), order.end(), [](const auto &x, const auto &y) {
      return x.first != y.first ? x.first < y.first : x.second < y.second;
    });
    size_t size = 4;  // batches of 4, 8, ..., kBatch pairs: the first bound comes early
    for (size_t start = 0; start < order.size(); start += size, size = std::min(kBatch, 2 * size)) {
      std::vector<Prim_pair> batch;
      for (size_t i = start; i < std::min(order.size(), start + size); ++i)
        if (!pruned(order[i].first)) batch.push_back(order[i].second);
      if (batch.empty()) break;  // sorted: every later bound is pruned too
      solve_batch(batch);
    }
  }
};

}  // namespace

Pair_outcome search_pair(const Pair_ctx &ctx, const Search_options &opt, Thread_pool &pool) {
  Pair_outcome out;
  Searcher(ctx, opt, pool, out).run();
  return out;
}

std::unique_ptr<Solved_pair> refine_pair(const Pair_ctx &ctx, const Solved_pair &s,
                                         const pred::Solve_options &opt, int round) {
  pred::Solve_options finer = opt;
  mpz_class two_pow = 1;
  two_pow <<= 20 * (round + 1);
  finer.tol = opt.tol / Rational(two_pow);
  auto r = std::make_unique<Solved_pair>();
  r->prim = s.prim;
  r->result = ctx.solve(s.prim, finer);
  return r;
}

}  // namespace pccd::broad
