#include "scene/scene.h"

#include <algorithm>
#include <map>
#include <string>

#include "scene/combine.h"

namespace pccd::scene {

using arith::Rational;

namespace {

bool contact_less(const Contact_report &x, const Contact_report &y) {
  if (x.lo != y.lo) return x.lo < y.lo;
  if (!(x.a == y.a)) return x.a < y.a;
  return x.b < y.b;
}

// One body pair's outcome.
struct Pair_work {
  size_t i, j;
  std::unique_ptr<Pair_ctx> ctx;
  Pair_outcome out;
};

// First contact over a set of solved pairs (possibly of several body pairs).
First_contact combine(std::vector<std::pair<Pair_work *, size_t>> items, const Scene_options &opt,
                      Search_stats &stats) {
  std::vector<const pred::Contact_result *> res;
  for (auto &it : items) res.push_back(&it.first->out.solved[it.second]->result);
  std::vector<int> rounds(items.size(), 0);
  return first_contact(res, [&](size_t k, const Rational &E) {
    // The finer result replaces the old one, so a later combine (the scene's, after the
    // pair's) starts from it.
    Pair_work *w = items[k].first;
    std::unique_ptr<Solved_pair> &cur = w->out.solved[items[k].second];
    // First-contact mode only needs contacts up to E (a pair found beyond drops out of
    // this combine); all_contacts keeps each pair's own first time.
    pred::Solve_options o = opt.solve;
    if (!opt.all_contacts) o.until = E;
    cur = refine_pair(*w->ctx, *cur, o, rounds[k]++);
    ++stats.refined;
    return &cur->result;
  });
}

}  // namespace

Moving_body prepare_body(const Scene_body &b) {
  if (b.prepared) return narrow::prepare_body(b.body, b.prepared);
  if (b.motion) return narrow::prepare_body(b.body, *b.motion);
  return narrow::prepare_body(b.body, narrow::identity_motion());
}

std::vector<Moving_body> prepare_bodies(const std::vector<Scene_body> &bodies, const std::string &name) {
  std::vector<Moving_body> mb;
  mb.reserve(bodies.size());
  for (size_t k = 0; k < bodies.size(); ++k) {
    try {
      mb.push_back(prepare_body(bodies[k]));
    } catch (const arith::Input_error &e) {
      throw arith::Input_error(name + "[" + std::to_string(k) + "].motion: " + e.what());
    }
  }
  return mb;
}

Scene_report solve_scene(const std::vector<Scene_body> &bodies, const Scene_options &opt,
                         const Pair_set &skipped) {
  if (bodies.size() < 2)  // the one check (Python converts and raises this message)
    throw arith::Input_error("bodies: a scene needs at least 2 bodies, got " +
                             std::to_string(bodies.size()));
  const std::vector<Moving_body> mb = prepare_bodies(bodies, "bodies");
  std::vector<std::pair<size_t, size_t>> pairs;
  for (size_t i = 0; i < mb.size(); ++i)
    for (size_t j = i + 1; j < mb.size(); ++j)
      if (!skipped.count({i, j})) pairs.push_back({i, j});
  std::vector<const Moving_body *> ptr;
  for (const Moving_body &b : mb) ptr.push_back(&b);
  return solve_prepared(ptr, pairs, opt, -1);
}

Scene_report solve_prepared(const std::vector<const Moving_body *> &mb,
                            const std::vector<std::pair<size_t, size_t>> &pairs,
                            const Scene_options &opt, int stored) {
  std::vector<Pair_plan> plans;
  plans.reserve(pairs.size());
  for (const auto &ij : pairs) plans.push_back({ij.first, ij.second, 0.0});
  return solve_planned([&](const Pair_plan &, size_t k) -> const Moving_body & { return *mb[k]; }, plans, opt,
                       stored, false);
}

Scene_report solve_planned(const std::function<const Moving_body &(const Pair_plan &, size_t)> &body,
                           const std::vector<Pair_plan> &plans, const Scene_options &opt,
                           int stored, bool witness) {
  Thread_pool pool(std::max(1u, opt.threads));
  const bool decide = !opt.solve.want_time && !opt.all_contacts;
  witness = witness && opt.solve.want_time && !opt.all_contacts;
  Search_options so;
  so.solve = opt.solve;
  so.all_contacts = opt.all_contacts;
  so.phase = opt.broad_phase;
  so.reach = opt.reach;
  so.stored = stored;
  so.witness = decide || witness;

  std::vector<std::unique_ptr<Pair_work>> work;
  Scene_report rep;
  bool have_best = false;  // witness: the smallest upper bound of a contact found
  Rational best;
  for (const Pair_plan &plan : plans) {
    if (have_best) {
      if (Rational(plan.lower) > best) break;  // sorted: every later pair too
      if (best < so.solve.until) so.solve.until = best;
    }
    auto w = std::make_unique<Pair_work>();
    w->i = plan.i;
    w->j = plan.j;
    w->ctx = std::make_unique<Pair_ctx>(body(plan, w->i), body(plan, w->j));
    Search_options pair_so = so;  // the automatic phase is chosen per pair, by evidence
    pair_so.phase = choose(opt.broad_phase, *w->ctx, opt.solve.min_distance());
    pair_so.apart_at_zero = plan.lower > 0 || plan.apart_at_zero;
    w->out = search_pair(*w->ctx, pair_so, pool);
    rep.stats.add(w->out.stats);
    bool hit = !w->out.solved.empty();
    bool at_zero = false;
    if (hit && witness) {
      // The pair's own first contact (exact when rational; its refined results stay
      // for the combines below) bounds the later pairs. A pair first touching after the
      // bound (a solve may report it: pred/solve.h, until) is dropped, so that the pairs
      // listed do not depend on the broad phase.
      std::vector<std::pair<Pair_work *, size_t>> items;
      for (size_t k = 0; k < w->out.solved.size(); ++k) items.push_back({w.get(), k});
      const First_contact f = combine(items, opt, rep.stats);
      if (f.lo > so.solve.until) {
        w->out.solved.clear();
        hit = false;
      } else {
        if (!have_best || f.hi < best) best = f.hi;
        have_best = true;
        at_zero = f.exact && sgn(f.lo) == 0;
      }
    }
    work.push_back(std::move(w));
    if (hit && decide) {
      rep.free_until = Rational(plan.lower);
      break;
    }
    if (at_zero) break;  // a contact at t = 0 is first
  }

  // Reported in ascending (i, j), whatever order the plans were solved in.
  std::sort(work.begin(), work.end(), [](const auto &x, const auto &y) {
    return std::make_pair(x->i, x->j) < std::make_pair(y->i, y->j);
  });
  std::vector<std::pair<Pair_work *, size_t>> everything;
  for (auto &w : work) {
    if (w->out.solved.empty()) continue;
    std::vector<std::pair<Pair_work *, size_t>> items;
    for (size_t k = 0; k < w->out.solved.size(); ++k) items.push_back({w.get(), k});
    everything.insert(everything.end(), items.begin(), items.end());
    First_contact f = combine(items, opt, rep.stats);
    Pair_report pr;
    pr.i = w->i;
    pr.j = w->j;
    pr.lo = f.lo;
    pr.hi = f.hi;
    pr.exact = f.exact;
    // Contacts: the first ones, or all (each feature pair at its own first time).
    std::vector<size_t> which = f.which;
    if (opt.all_contacts) {
      which.clear();
      for (size_t k = 0; k < items.size(); ++k) which.push_back(k);
    }
    std::map<std::pair<Feature_ref, Feature_ref>, Contact_report> by_feature;
    for (size_t k : which) {
      const Solved_pair &s = *w->out.solved[items[k].second];
      for (const auto &fp : w->ctx->contacts(s.prim, s.result)) {
        Contact_report c{fp.first, fp.second, s.result.lo, s.result.hi, s.result.exact};
        auto it = by_feature.find(fp);
        if (it == by_feature.end() || contact_less(c, it->second)) by_feature[fp] = c;
      }
    }
    for (auto &kv : by_feature) pr.contacts.push_back(kv.second);
    std::sort(pr.contacts.begin(), pr.contacts.end(), contact_less);
    rep.pairs.push_back(std::move(pr));
  }
  if (rep.pairs.empty()) return rep;
  rep.collides = true;
  // The scene's first contact: over all pairs' solved feature pairs at once.
  First_contact f = combine(everything, opt, rep.stats);
  rep.lo = f.lo;
  rep.hi = f.hi;
  rep.exact = f.exact;
  if (!decide) rep.free_until = f.lo;
  for (size_t p = 0; p < rep.pairs.size(); ++p) {
    const Pair_report &pr = rep.pairs[p];
    const bool first = f.exact ? (pr.exact && pr.lo == f.lo) : (pr.lo <= f.hi);
    if (first) rep.first_pairs.push_back(p);
  }
  return rep;
}

}  // namespace pccd::scene
