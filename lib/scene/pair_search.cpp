#include "scene/pair_search.h"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <unordered_map>

#include "bvh/least_at_zero.h"
#include "enclose/enclose.h"
#include "narrow/containment.h"
#include "pred/closest_axis.h"
#include "scene/auto_cost.h"

namespace pccd::scene {

Broad_phase choose(Broad_phase p, const Pair_ctx &ctx, bool min_distance) {
  if (p != Broad_phase::automatic) return p;
  if (min_distance) return Broad_phase::bvh;
  const Auto_costs c = estimate_costs(ctx);
  return c.range < c.bvh ? Broad_phase::range : Broad_phase::bvh;
}

namespace {

class Driver final : public narrow::Candidate_sink {
 public:
  Driver(const Pair_ctx &ctx, const Search_options &opt, Thread_pool &pool, Pair_outcome &out)
      : ctx_(ctx), opt_(opt), pool_(pool), out_(out), reach_(opt.reach) {}

  void run() {
    std::unique_ptr<narrow::Candidate_source> source = make_source(opt_.phase, ctx_, opt_.stored, reach_);
    if (ctx_.side(0).is_mesh() && ctx_.side(1).is_mesh() && !opt_.apart_at_zero) {
      whole(source->static_candidates(pool_));
      if (found_any_ && !opt_.all_contacts) return;
    }
    // Solids (narrow/containment.h): a point strictly inside the other's solid at t = 0
    // is a contact at t = 0, first and exact. Two meshes are tested only when their
    // surfaces are apart at t = 0 (the static pass); apart_at_zero speaks of surfaces
    // only, so it does not skip this.
    if (!found_any_ && narrow::has_solid(ctx_)) {
      if (std::optional<Prim_pair> in = narrow::contained_at_zero(ctx_)) {
        auto s = std::make_unique<Solved_pair>();
        s->prim = *in;
        s->result.collides = s->result.exact = true;
        s->result.lo = s->result.hi = 0;
        cleared_.emplace(in->key(), kDone);
        found_any_ = have_best_ = true;
        best_hi_ = opt_.solve.want_time ? Rational(0) : Rational(-1);
        out_.solved.push_back(std::move(s));
        if (!opt_.all_contacts) return;
      }
    }
    // The pair of least key within delta at t = 0, found in key order
    // (bvh/least_at_zero.h) where the source would list and sort every candidate of the
    // piece holding 0 for within_at_zero: the same pair. None: within_at_zero has
    // nothing to find, and the source runs as without a witness pass.
    if (!found_any_ && zero_pass() && ctx_.side(0).is_mesh() && ctx_.side(1).is_mesh() &&
        !narrow::has_infinite_bounds(ctx_)) {
      zero_ = bvh::least_within_at_zero(ctx_, opt_.solve, reach_, out_.stats.static_tests);
      zero_searched_ = true;
      if (zero_) return solve_batch({*zero_}, 1.0);
      // Only contacts at t = 0 wanted (until = 0: a robot's witness at 0, robot.cpp), and
      // no feature pair is within delta then: none. The source would solve every
      // candidate of the piece holding 0 for nothing (1,949 feature pairs, 40 ms, of a
      // UR5 link pair near delta at 0; issue 33).
      if (opt_.solve.want_time && sgn(opt_.solve.until) == 0) return;
    }
    source->run(*this, out_.stats, pool_);
    if (zero_) solve_batch({*zero_}, 1.0);  // the witness pass's pair (within_at_zero)
  }

  // A piece starting after the best upper bound, or after the caller's solve.until (a
  // scene's bound from other pairs: scene.h, solve_planned), holds no contact to report.
  bool pruned(double a) const override {
    if (zero_) return a > 0 || !opt_.solve.want_time;  // within_at_zero: a contact at t = 0
    if (opt_.all_contacts || (!have_best_ && !(opt_.solve.until < 1))) return false;
    Rational ra;
    mpq_set_d(ra.get_mpq_t(), a);
    return (have_best_ && ra > best_hi_) || ra > opt_.solve.until;
  }

  void whole(std::vector<Prim_pair> cand) override {
    std::vector<Prim_pair> fresh = fresh_of(std::move(cand), 1.0);
    if (within_at_zero(fresh)) return;
    bool all_tt = true;  // the static pass (a contact at t = 0 is first)
    for (const Prim_pair &p : fresh) all_tt = all_tt && p.type == narrow::TT;
    if (!opt_.witness || opt_.all_contacts || (opt_.solve.want_time && !all_tt)) return solve_batch(fresh, 1.0);
    // Search_options::witness: chunks in key order; of the chunk that ends the search
    // only its first touching pair is kept, which is then the touching pair of least key
    // (the same for every broad phase: each lists every pair touching at t = 0).
    constexpr size_t kChunk = 64;
    for (size_t i = 0; i < fresh.size() && !witness_done(); i += kChunk) {
      const size_t before = out_.solved.size();
      solve_batch(std::vector<Prim_pair>(fresh.begin() + i, fresh.begin() + std::min(fresh.size(), i + kChunk)),
                  1.0);
      if (witness_done() && out_.solved.size() > before + 1) out_.solved.resize(before + 1);
    }
  }

  // Search_options::witness: a contact without times, or one at t = 0, ends the search.
  bool witness_done() const {
    return found_any_ && (!opt_.solve.want_time || (have_best_ && sgn(best_hi_) == 0));
  }

  // Solves the candidates of [a, b] in the order of the first of kSub equal sub-pieces
  // on which their two boxes meet (pair_search.h). A pair about to be solved is first
  // tested on the kSub equal parts of that sub-piece (their enclosures made once, when
  // first needed): the start of its first part where the boxes meet, or the sub-piece's
  // end when none does, is a finer lower bound of its contacts in [a, b], and a pair
  // whose finer bound is pruned is not solved (as a pair whose coarse bound is). On the
  // 75k-triangle bunnies turning (bench_bvh.py, rot) this kept 170 of 293 solved pairs,
  // none touching, from the solver.
  void piece(double a, double b, std::vector<Prim_pair> cand) override {
    std::vector<Prim_pair> fresh = fresh_of(std::move(cand), b);
    if (fresh.empty()) return;
    if (a == 0 && within_at_zero(fresh)) return;
    constexpr size_t kBatch = 64;
    const std::vector<Part> sub = parts(a, b);
    std::vector<std::pair<int, Prim_pair>> order;  // (first sub-piece where boxes meet, pair)
    for (size_t i = 0; i < fresh.size(); ++i) {
      if (i % kStepPairs == 0) util::work_step();
      const int k = first_meeting(fresh[i], sub);
      if (k < kSub) order.push_back({k, fresh[i]});
    }
    std::sort(order.begin(), order.end());
    std::vector<std::vector<Part>> fine(kSub);  // parts of sub-piece k, when needed
    auto fine_pruned = [&](int k, const Prim_pair &p) {
      if (opt_.all_contacts || !have_best_) return false;
      if (fine[k].empty()) fine[k] = parts(sub[k].a, sub[k].b);
      const int j = first_meeting(p, fine[k]);
      return pruned(j < kSub ? fine[k][j].a : sub[k].b);
    };
    size_t size = 4;  // batches of 4, 8, ..., kBatch pairs: the first bound comes early
    for (size_t i = 0; i < order.size(); size = std::min(kBatch, 2 * size)) {
      std::vector<Prim_pair> batch;
      for (; i < order.size() && batch.size() < size; ++i) {
        if (pruned(sub[order[i].first].a)) {
          i = order.size();  // sorted: every later bound is pruned too
          break;
        }
        if (!fine_pruned(order[i].first, order[i].second)) batch.push_back(order[i].second);
      }
      solve_batch(batch, b);
    }
  }

 private:
  static constexpr int kSub = 8;
  // A time part [a, b] and the two motions' enclosures over it.
  struct Part {
    double a, b;
    std::array<enclose::Pose_piece, 2> pose;
  };
  // [a, b] cut into kSub equal parts (exact: pieces and parts are dyadic).
  std::vector<Part> parts(double a, double b) const {
    std::vector<Part> out(kSub);
    for (int k = 0; k < kSub; ++k) {
      out[k].a = a + (b - a) * k / kSub;
      out[k].b = k + 1 == kSub ? b : a + (b - a) * (k + 1) / kSub;
      for (int s = 0; s < 2; ++s) out[k].pose[s] = enclose::enclose_pose(ctx_.side(s), out[k].a, out[k].b);
    }
    return out;
  }
  // The first part on which the pair's two feature boxes are within the minimum
  // separation's reach (kSub: none; enclose::boxes_within, reach_of: features within delta
  // have boxes within reach, so the bound stays a lower bound of their contacts).
  // With a minimum separation, a point feature pair (VF, FV, EE) whose boxes are within
  // reach on a part must also not be apart on the direction of its nearest points (the
  // points' box centres, pred/closest_axis.h): its boxes, of features far larger than
  // delta, kept 1,000-5,000 feature pairs of a Panda window whose axis test in the
  // solver (pred/delta_axis.h, each after building the pair's query) then ended them.
  int first_meeting(const Prim_pair &p, const std::vector<Part> &part) const {
    narrow::Query_irrational::Points pts;
    const int n = reach_ > 0 ? ctx_.query_points(p, pts) : 0;
    for (int k = 0; k < kSub; ++k) {
      if (n > 0 ? within_on_part(pts, n, part[k])
                : enclose::boxes_within(enclose::feature_box(ctx_.side(0), 0, p, part[k].pose[0]),
                                        enclose::feature_box(ctx_.side(1), 1, p, part[k].pose[1]), reach_))
        return k;
    }
    return kSub;
  }
  // The point feature pair of points pts[0, n) (Pair_ctx::query_points) may be within
  // reach on the part: the hulls of its points' boxes over the part (feature_box's boxes)
  // are within reach, and those boxes are not more than reach |d| apart on the
  // direction d of the features' nearest points at the boxes' centres (each feature
  // lies in the convex hull of its points' boxes; enclose::axis_separates).
  bool within_on_part(const narrow::Query_irrational::Points &pts, int n, const Part &part) const {
    enclose::Box box[2][3], hull[2] = {enclose::empty_box(), enclose::empty_box()};
    double mid[2][3][3];
    int count[2] = {0, 0};
    for (int i = 0; i < n; ++i) {
      const int s = pts[i].first, c = count[s]++;
      const narrow::Body_data &d = *ctx_.side(s).data;
      box[s][c] = enclose::point_box(part.pose[s], d.pts[pts[i].second], d.pt_err);
      hull[s] = enclose::hull(hull[s], box[s][c]);
      for (int a = 0; a < 3; ++a) mid[s][c][a] = 0.5 * box[s][c].lo[a] + 0.5 * box[s][c].hi[a];
    }
    if (!enclose::boxes_within(hull[0], hull[1], reach_)) return false;
    double axis[3];
    return !(pred::closest_direction(mid[0], count[0], mid[1], count[1], axis) &&
             enclose::axis_separates(axis, box[0], count[0], box[1], count[1], reach_));
  }

  const Pair_ctx &ctx_;
  const Search_options &opt_;
  Thread_pool &pool_;
  Pair_outcome &out_;
  const double reach_;  // opt_.reach: 0 without a minimum separation
  // Search_options::witness with a minimum separation: a feature pair within delta at
  // t = 0 is a first contact, and the report lists the pairs found, not every pair in
  // contact (scene.h). So the candidates of a piece starting at 0 (or of the whole
  // interval) are tested at t = 0 alone before any solve (Pair_ctx::within_at_zero:
  // exact, from the positions at t = 0, no trajectories); once one is within delta, the
  // pieces starting after 0 are pruned, those starting at 0 are only tested, and after
  // the source's run the pair of least key within delta is solved (its report is the
  // solver's) as the body pair's only contact at t = 0: every source lists every pair
  // within delta at t = 0 in a piece starting at 0, so that pair does not depend on
  // the broad phase (as the static pass's touching pair of least key). Decide mode
  // stops at the first. Without this a robot's start pose within delta of an obstacle
  // solved every candidate near t = 0 (issue 33: 1,261 pairs, first contact 30x the
  // time without min_distance). Returns whether a pair within delta is known.
  std::optional<Prim_pair> zero_;
  bool zero_searched_ = false;  // zero_ is run()'s search's answer
  bool zero_pass() const {
    return opt_.witness && !opt_.all_contacts && !opt_.apart_at_zero && opt_.solve.min_distance();
  }
  bool within_at_zero(const std::vector<Prim_pair> &fresh) {
    if (!zero_pass()) return false;
    if (zero_searched_) return zero_.has_value();
    if (fresh.empty() || fresh.front().type > narrow::EE) return zero_.has_value();  // sorted: TT last
    constexpr size_t kChunk = 256;
    bool found = false;
    for (size_t i = 0; i < fresh.size() && !found; i += kChunk) {
      if (zero_ && (!opt_.solve.want_time || !(fresh[i] < *zero_))) break;  // in key order
      util::work_step();
      const size_t n = std::min(kChunk, fresh.size() - i);
      std::vector<char> within(n, 0);
      pool_.parallel_for(n, [&](size_t k) { within[k] = ctx_.within_at_zero(fresh[i + k], opt_.solve); });
      out_.stats.static_tests += n;
      for (size_t k = 0; k < n && !found; ++k)
        if (within[k] && (!zero_ || fresh[i + k] < *zero_)) {
          zero_ = fresh[i + k];
          found = true;
        }
    }
    return zero_.has_value();
  }

  // Per feature pair solved: a time c such that it has no contact in [0, c] (+inf: it
  // touches, with its result kept, or has no contact at all). A pair of a piece [a, b] is
  // solved only for contacts up to min(best, b) (much cheaper for a pair whose boxes
  // meet long before it could touch): if it touches later, a later piece holding that
  // time reports it again (candidate_source.h) and it is solved again up to that
  // piece's end. A reported contact never depends on the bound (pred/solve.h).
  std::unordered_map<uint64_t, double> cleared_;
  static constexpr double kDone = std::numeric_limits<double>::infinity();
  // Candidates handled per work step outside the solves (util/work_budget.h): a piece
  // can list hundreds of thousands of pairs before the first one is solved.
  static constexpr size_t kStepPairs = 4096;
  bool found_any_ = false, have_best_ = false;
  Rational best_hi_;

  // Contacts up to min(best, horizon) (first-contact mode with times; else all of [0, 1]).
  pred::Solve_options bounded_options(double horizon) const {
    pred::Solve_options o = opt_.solve;
    if (opt_.all_contacts || !opt_.solve.want_time) return o;
    if (horizon < 1 && Rational(horizon) < o.until) o.until = Rational(horizon);  // exact: a double
    if (have_best_ && best_hi_ < o.until) o.until = best_hi_;
    return o;
  }

  // The pairs of cand not yet cleared up to horizon, once each, in key order.
  std::vector<Prim_pair> fresh_of(std::vector<Prim_pair> cand, double horizon) const {
    util::work_step(1 + cand.size() / kStepPairs);  // the sort
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
    std::vector<Prim_pair> fresh;
    for (const Prim_pair &p : cand) {
      auto it = cleared_.find(p.key());
      if (it == cleared_.end() || (it->second < horizon && it->second != kDone)) fresh.push_back(p);
    }
    return fresh;
  }

  // Solves the pairs of `fresh` (not seen before) in parallel; appends the touching ones
  // in the given order and updates the best upper bound.
  void solve_batch(const std::vector<Prim_pair> &fresh, double horizon) {
    if (fresh.empty()) return;
    // A pair met again (cleared before, up to an earlier piece) is solved up to the best
    // bound at once: each pair is solved at most twice.
    bool again = false;
    for (const Prim_pair &p : fresh) again = again || cleared_.count(p.key());
    if (again && horizon < 1) {
      std::vector<Prim_pair> first, second;
      for (const Prim_pair &p : fresh) (cleared_.count(p.key()) ? second : first).push_back(p);
      solve_batch(first, horizon);
      horizon = 1.0;
      return solve_batch(second, horizon);
    }
    const pred::Solve_options o = bounded_options(horizon);
    // No contact in [0, until] for a pair found apart (a double at or below until).
    const double clear = o.until >= 1 ? kDone : mpq_get_d(o.until.get_mpq_t());
    std::vector<std::unique_ptr<Solved_pair>> res(fresh.size());
    pool_.parallel_for(fresh.size(), [&](size_t i) {
      auto s = std::make_unique<Solved_pair>();
      s->prim = fresh[i];
      if (fresh[i].type == narrow::TT) {
        s->result.collides = ctx_.triangles_meet_at_zero(fresh[i].a, fresh[i].b);
        if (s->result.collides) {
          s->result.exact = true;
          s->result.lo = s->result.hi = 0;
        }
      } else {
        s->result = ctx_.solve(fresh[i], o);
        util::work_solved();  // progress for a work-limit message (util/work_budget.h)
      }
      res[i] = std::move(s);
    });
    for (auto &s : res) {
      auto ins = cleared_.emplace(s->prim.key(), 0.0);
      ins.first->second = s->result.collides ? kDone : clear;
      if (s->prim.type == narrow::TT) ++out_.stats.static_tests;
      else if (ins.second) {
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
};

}  // namespace

Pair_outcome search_pair(const Pair_ctx &ctx, const Search_options &opt, Thread_pool &pool) {
  Pair_outcome out;
  Driver(ctx, opt, pool, out).run();
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

}  // namespace pccd::scene
