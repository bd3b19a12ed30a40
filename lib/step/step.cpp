#include "step/step.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include "arith/convert.h"
#include "pred/features.h"
#include "pred/solve_linear.h"
#include "scene/combine.h"
#include "step/paths.h"
#include "step/separate.h"
#include "step/tree.h"
#include "util/thread_pool.h"
#include "util/work_budget.h"

namespace pccd::step {

using arith::Rational;

double double_below(const Rational &q) {
  double d = arith::nearest_double(q);
  if (Rational(d) > q) d = std::nextafter(d, -HUGE_VAL);
  return d;
}

namespace {

struct Chunk_out {
  std::vector<Step_contact> hits;
  uint64_t candidates = 0;
  uint64_t by_stage[5] = {0, 0, 0, 0, 0};
};

// The common velocity of the boxes' frame: the mean displacement of the used vertices
// (0 when there is none or it overflows). Any value is valid (step.h).
void frame_velocity(const Step_set &s, double u[3]) {
  double sum[3] = {0, 0, 0};
  for (uint32_t v : s.used)
    for (int a = 0; a < 3; ++a) sum[a] += s.x1[3 * size_t(v) + a] - s.x0[3 * size_t(v) + a];
  for (int a = 0; a < 3; ++a) {
    u[a] = s.used.empty() ? 0.0 : sum[a] / static_cast<double>(s.used.size());
    if (!std::isfinite(u[a])) u[a] = 0.0;
  }
}

class Driver {
 public:
  Driver(const Step_set &s, const Step_options &opt, util::Thread_pool &pool) : s_(s), opt_(opt) {
    solve_ = opt.solve;
    solve_.want_time = opt.mode != DECIDE;
    reach_ = enclose::reach_of(opt.solve.delta);
    double u[3];
    frame_velocity(s, u);
    const size_t nv = s.x0.size() / 3;
    // The boxes below: a work step per 4,096 vertices, faces and edges (tree.cpp counts
    // the trees), so the limits hold while a big step is set up.
    util::work_step(1 + (nv + s.faces.size() + s.edges.size()) / 4096);
    vb_.resize(nv);
    for (size_t v = 0; v < nv; ++v)
      for (int a = 0; a < 3; ++a) {
        const double x0 = s.x0[3 * v + a];
        const double x1 = s.x1[3 * v + a] - u[a];  // rounded: widened below
        double lo = std::min(x0, x1), hi = std::max(x0, x1);
        if (u[a] != 0) {
          lo = std::nextafter(lo, -HUGE_VAL);
          hi = std::nextafter(hi, HUGE_VAL);
        }
        vb_[v].lo[a] = lo;
        vb_[v].hi[a] = hi;
      }
    paths_ = s.has_paths();
    if (paths_)
      for (size_t v = 0; v < nv; ++v)
        if (on_path(s, static_cast<uint32_t>(v))) vb_[v] = path_box(s, static_cast<uint32_t>(v), u);
    std::vector<Box> fb(s.faces.size()), pb(s.points.size());
    eb_.resize(s.edges.size());
    for (size_t f = 0; f < fb.size(); ++f) {
      const auto &F = s.faces[f];
      fb[f] = enclose::hull(enclose::hull(vb_[F[0]], vb_[F[1]]), vb_[F[2]]);
    }
    for (size_t e = 0; e < eb_.size(); ++e) eb_[e] = enclose::hull(vb_[s.edges[e][0]], vb_[s.edges[e][1]]);
    for (size_t k = 0; k < pb.size(); ++k) pb[k] = vb_[s.points[k]];
    std::vector<Box> ub(s.used.size());
    for (size_t i = 0; i < ub.size(); ++i) ub[i] = vb_[s.used[i]];
    // The four trees are independent: built at once on the pool. used_ serves only its
    // curve order (queries in that order are coherent).
    std::unique_ptr<Box_tree> *trees[4] = {&used_, &faces_, &edges_, &points_};
    const std::vector<Box> *from[4] = {&ub, &fb, &eb_, &pb};
    pool.parallel_for(4, [&](size_t k) { *trees[k] = std::make_unique<Box_tree>(*from[k]); });
    nu_ = s.used.size();
    ne_ = s.edges.size();
    np_ = s.points.size();
    total_ = nu_ + ne_ + 2 * np_;
  }

  size_t queries() const { return total_; }

  // Runs the queries of chunk c; with stop, the chunk ends at its first contact.
  void run_chunk(size_t c, Chunk_out &out, bool stop) const {
    util::work_step();
    pred::Contact_result r;
    bool done = false;
    // FIRST: a pair touching only after the chunk's earliest contact so far cannot be
    // first; the solver may then stop early (until, pred/solve.h). The bound is the
    // chunk's own, so which pairs drop out depends on the chunk alone, not on threads.
    pred::Solve_options local = solve_;
    auto candidate = [&](int kind, uint32_t a, uint32_t b, const uint32_t *pts, int n) {
      ++out.candidates;
      if (paths_ && any_path(pts, n)) {
        solve_paths(s_, kind, pts, n, local, r);  // paths.h: the general solver
      } else {
        double p0[12], p1[12];
        for (int i = 0; i < n; ++i) {
          std::memcpy(p0 + 3 * i, &s_.x0[3 * size_t(pts[i])], 3 * sizeof(double));
          std::memcpy(p1 + 3 * i, &s_.x1[3 * size_t(pts[i])], 3 * sizeof(double));
        }
        if (separated(kind, p0, p1, reach_)) {  // separate.h: certified, never a contact
          ++out.by_stage[pred::STAGE_BOUNDS];
          return;
        }
        pred::solve_linear(kind, static_cast<size_t>(n), p0, p1, local, r);
      }
      ++out.by_stage[r.stage >= 0 && r.stage < 5 ? r.stage : 0];
      if (r.collides) {
        if (opt_.mode == FIRST && r.hi < local.until) local.until = r.hi;
        out.hits.push_back(Step_contact{kind, a, b, r});
        if (stop) done = true;
      }
    };
    const size_t end = std::min(total_, (c + 1) * kChunk);
    for (size_t q = c * kChunk; q < end && !done; ++q) {
      if (q < nu_) {
        const uint32_t v = s_.used[used_->at(static_cast<uint32_t>(q))];
        faces_->query(grown(vb_[v]), [&](uint32_t f) {
          const auto &F = s_.faces[f];
          if (done || F[0] == v || F[1] == v || F[2] == v || !s_.checked(s_.vmesh[v], s_.fmesh[f])) return;
          const uint32_t pts[4] = {v, F[0], F[1], F[2]};
          candidate(pred::VERTEX_FACE, v, static_cast<uint32_t>(f), pts, 4);
        });
      } else if (q < nu_ + ne_) {
        // Edges in curve order, each against the edges after it on the curve.
        const uint32_t pos = static_cast<uint32_t>(q - nu_), e = edges_->at(pos);
        edges_->query_after(grown(eb_[e]), pos + 1, [&](uint32_t g) {
          const uint32_t lo = std::min(e, g), hi = std::max(e, g);
          const auto &E = s_.edges[lo], &G = s_.edges[hi];
          if (done || E[0] == G[0] || E[0] == G[1] || E[1] == G[0] || E[1] == G[1] ||
              !s_.checked(s_.emesh[lo], s_.emesh[hi]))
            return;
          const uint32_t pts[4] = {E[0], E[1], G[0], G[1]};
          candidate(pred::EDGE_EDGE, lo, hi, pts, 4);
        });
      } else if (q < nu_ + ne_ + np_) {
        const size_t k = q - nu_ - ne_;
        const uint32_t v = s_.points[k];
        edges_->query(grown(vb_[v]), [&](uint32_t g) {
          const auto &G = s_.edges[g];
          if (done || G[0] == v || G[1] == v || !s_.checked(s_.pmesh[k], s_.emesh[g])) return;
          const uint32_t pts[3] = {v, G[0], G[1]};
          candidate(pred::VERTEX_EDGE, v, g, pts, 3);
        });
      } else {
        const size_t k = q - nu_ - ne_ - np_;
        const uint32_t v = s_.points[k];
        points_->query(grown(vb_[v]), [&](uint32_t j) {
          if (done || j <= k || !s_.checked(s_.pmesh[k], s_.pmesh[j])) return;
          const uint32_t pts[2] = {v, s_.points[j]};
          candidate(pred::VERTEX_VERTEX, v, s_.points[j], pts, 2);
        });
      }
    }
  }

  // Re-solves a touching pair with a finer tolerance (round-th refinement), up to until.
  void refine(Step_contact &h, int round, const Rational *until) const {
    pred::Solve_options o = solve_;
    mpz_class two_pow = 1;
    two_pow <<= 20 * (round + 1);
    o.tol = solve_.tol / Rational(two_pow);
    if (until) o.until = *until;
    uint32_t pts[4];
    int n = 0;
    const Step_set &s = s_;
    switch (h.kind) {
      case pred::VERTEX_FACE: pts[0] = h.a; for (int i = 0; i < 3; ++i) pts[1 + i] = s.faces[h.b][i]; n = 4; break;
      case pred::EDGE_EDGE: pts[0] = s.edges[h.a][0]; pts[1] = s.edges[h.a][1]; pts[2] = s.edges[h.b][0]; pts[3] = s.edges[h.b][1]; n = 4; break;
      case pred::VERTEX_EDGE: pts[0] = h.a; pts[1] = s.edges[h.b][0]; pts[2] = s.edges[h.b][1]; n = 3; break;
      default: pts[0] = h.a; pts[1] = h.b; n = 2; break;
    }
    if (paths_ && any_path(pts, n)) {
      solve_paths(s, h.kind, pts, n, o, h.r);
      return;
    }
    double p0[12], p1[12];
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) {
        p0[3 * i + a] = s.x0[3 * size_t(pts[i]) + a];
        p1[3 * i + a] = s.x1[3 * size_t(pts[i]) + a];
      }
    pred::solve_linear(h.kind, static_cast<size_t>(n), p0, p1, o, h.r);
  }

 private:
  bool any_path(const uint32_t *pts, int n) const {
    for (int i = 0; i < n; ++i)
      if (on_path(s_, pts[i])) return true;
    return false;
  }
  Box grown(const Box &b) const { return reach_ > 0 ? enclose::grow(b, reach_) : b; }

  const Step_set &s_;
  const Step_options &opt_;
  pred::Solve_options solve_;
  double reach_ = 0;
  bool paths_ = false;  // some mesh has polynomial paths (paths.h)
  std::vector<Box> vb_, eb_;
  std::unique_ptr<Box_tree> used_, faces_, edges_, points_;
  size_t nu_ = 0, ne_ = 0, np_ = 0, total_ = 0;
};

bool by_pair(const Step_contact &x, const Step_contact &y) {
  if (x.kind != y.kind) return x.kind < y.kind;
  if (x.a != y.a) return x.a < y.a;
  return x.b < y.b;
}

// The first contact over the hits, the pairs touching first, the step size.
void combine(const Driver &d, const Step_options &opt, std::vector<Step_contact> &hits, Step_report &rep) {
  std::vector<const pred::Contact_result *> res;
  for (auto &h : hits) res.push_back(&h.r);
  std::vector<int> rounds(hits.size(), 0);
  auto refine = [&](size_t i, const Rational &E) {
    d.refine(hits[i], rounds[i]++, opt.mode == FIRST ? &E : nullptr);
    ++rep.stats.refined;
    return &hits[i].r;
  };
  scene::First_contact fc = scene::first_contact(res, refine);
  // Step size: refine the possibly-first pairs until no double lies in (lo, hi]; then
  // the largest double <= lo is the largest double <= t*. A bounded number of rounds
  // (each divides the tolerance by 2^20); past it the value is still <= t*.
  for (int round = 0; fc.collides && !fc.exact && round < 8; ++round) {
    if (double_below(fc.lo) == double_below(fc.hi)) break;
    const Rational until = fc.hi;
    for (size_t i : fc.which) {
      d.refine(hits[i], rounds[i]++, opt.mode == FIRST ? &until : nullptr);
      ++rep.stats.refined;
    }
    fc = scene::first_contact(res, refine);
  }
  rep.collides = fc.collides;
  if (!fc.collides) return;
  rep.lo = fc.lo;
  rep.hi = fc.hi;
  rep.exact = fc.exact;
  rep.stepsize = double_below(fc.lo);
  if (opt.mode == ALL) {
    // A pair refined with until may not have its own time: ALL refines without until.
    for (auto &h : hits)
      if (h.r.collides) rep.contacts.push_back(h);
  } else {
    for (size_t i : fc.which) rep.contacts.push_back(hits[i]);
  }
}

}  // namespace

Step_report solve_step(const Step_set &s, const Step_options &opt) {
  Step_report rep;
  util::Thread_pool pool(opt.threads);
  const Driver d(s, opt, pool);
  const size_t chunks = (d.queries() + kChunk - 1) / kChunk;
  std::vector<Chunk_out> outs(chunks);
  size_t ran = chunks;
  if (opt.mode == DECIDE) {
    for (size_t first = 0; first < chunks; first += kRound) {
      const size_t n = std::min(kRound, chunks - first);
      pool.parallel_for(n, [&](size_t i) { d.run_chunk(first + i, outs[first + i], true); });
      bool hit = false;
      for (size_t i = 0; i < n; ++i) hit = hit || !outs[first + i].hits.empty();
      if (hit) {
        ran = first + n;
        break;
      }
    }
  } else {
    pool.parallel_for(chunks, [&](size_t c) { d.run_chunk(c, outs[c], false); });
  }
  std::vector<Step_contact> hits;
  rep.stats.queries = std::min(d.queries(), ran * kChunk);
  for (size_t c = 0; c < ran; ++c) {
    rep.stats.candidates += outs[c].candidates;
    for (int k = 0; k < 5; ++k) rep.stats.by_stage[k] += outs[c].by_stage[k];
    for (auto &h : outs[c].hits) hits.push_back(std::move(h));
  }
  if (opt.mode == DECIDE) {
    rep.collides = !hits.empty();
    rep.contacts = std::move(hits);
  } else {
    combine(d, opt, hits, rep);
  }
  std::sort(rep.contacts.begin(), rep.contacts.end(), by_pair);
  return rep;
}

}  // namespace pccd::step
