#include "scene/robot.h"

#include <algorithm>
#include <string>

#include "bvh/hierarchy.h"
#include "motion/chain_path.h"
#include "poly/poly.h"
#include "scene/instant_scan.h"
#include "scene/link_filter.h"
#include "scene/node_memo.h"
#include "scene/piece_poses.h"
#include "scene/robot_exact.h"
#include "scene/robot_sides.h"
#include "scene/solid_start.h"
#include "util/work_budget.h"

namespace pccd::scene {

namespace {

// Whether a motion stands still on [0, 1]: its exact homogeneous form is constant.
bool stands_still(const narrow::Motion_data &m) {
  for (const auto &row : m.Rn)
    for (const auto &e : row)
      if (e.degree() > 0) return false;
  for (const auto &e : m.O.v)
    if (e.degree() > 0) return false;
  return m.W.degree() <= 0;
}

// The report of a witness found by the filter (decide mode): the pair alone, touching
// exactly at the witness's instant (scene.h, solve_planned's decide report).
Scene_report witness_report(size_t i, size_t j, const Witness &w, double free_until) {
  Scene_report rep;
  const Rational t = Rational(static_cast<long>(w.index)) / Rational(mpz_class(1) << w.depth);
  Pair_report pr;
  pr.i = i;
  pr.j = j;
  pr.lo = pr.hi = t;
  pr.exact = true;
  pr.contacts.push_back({{narrow::F_TRIANGLE, w.a}, {narrow::F_TRIANGLE, w.b}, t, t, true});
  rep.pairs.push_back(std::move(pr));
  rep.first_pairs.push_back(0);
  rep.collides = true;
  rep.lo = rep.hi = t;
  rep.exact = true;
  rep.free_until = Rational(free_until);
  return rep;
}


}  // namespace

Scene_report check_robot(const Robot_model &r, const double *q0, const double *q1,
                         const std::vector<Scene_body> &obstacles, const Scene_options &opt,
                         const Robot_options &ro) {
  const motion::Chain_path path(r.chain, q0, q1);  // Input_error for a rejected segment
  const std::vector<Moving_body> obst = prepare_bodies(obstacles, "obstacles");
  const size_t nr = r.bodies.size();
  // No pair at all (a robot without geometry, a lone link without obstacles): nothing
  // can touch, so no contact (issue 33: this was "nothing to check", an error).
  std::vector<Pair_plan> plans;
  for (size_t i = 0; i < nr; ++i) {
    if (ro.self_collision)
      for (size_t j = i + 1; j < nr; ++j) {
        const size_t g = r.bodies[i].group, h = r.bodies[j].group;
        if (g != h && !r.allowed.count({std::min(g, h), std::max(g, h)})) plans.push_back({i, j, 0.0});
      }
    for (size_t k = 0; k < obst.size(); ++k) plans.push_back({i, nr + k, 0.0});
  }

  // A step per check and per body pair (util/work_budget.h): a check whose pairs all
  // clear at once (a robot state) takes no other step, and a Cancel set before the call
  // or a spent budget must still end it.
  util::work_step(1 + plans.size());
  if (ro.filter) {
    Piece_poses poses(path, obst);
    // A key for this check's poses (Filter_side::share; robot_sides.h). Per thread, never 0.
    thread_local uint64_t tl_checks = 0;
    const uint64_t share = ++tl_checks;
    const double reach = opt.reach;
    const bool decide = !opt.solve.want_time && !opt.all_contacts;
    Robot_sides side(r, obst, poses, share);
    auto base_of = [&](const Pair_plan &p) {
      return p.j < nr ? path.common_ancestor(r.bodies[p.i].link, r.bodies[p.j].link) : -1L;
    };
    auto solid = [](const Body_data *d) { return d->mesh && d->mesh->solid(); };
    auto solid_pair = [&](const Pair_plan &p) {
      return solid(r.bodies[p.i].body.get()) ||
             solid(p.j < nr ? r.bodies[p.j].body.get() : obst[p.j - nr].data.get());
    };
    // A solid (narrow/containment.h) may hold the other body with no surface near: the
    // filter bounds surface contacts only, so a pair with a solid whose bodies' boxes
    // (Body_data::box_c, box_h: they hold the exact points) meet at t = 0 through the
    // pose enclosures then may be in contact at t = 0 whatever its bound, unless
    // solid_start.h certifies that neither holds a containment point of the other then
    // (issue 30: such pairs, nearly all never near, were 93% of a Panda's free
    // segments' time). Boxes apart at t = 0: neither holds a point of the other then,
    // and by continuity none until the surfaces meet, which the bound covers.
    // Where the interval test is in doubt, the exact one (narrow/containment.h) on the
    // exact poses at t = 0: the links on the segment q0 -> q0 (their t = 0 poses, built
    // once, on the first such pair), the obstacles on their own motions.
    std::vector<motion::Rigid_motion> at_zero;
    std::vector<std::shared_ptr<const narrow::Motion_data>> at_zero_data(r.chain.size());
    auto body_at_zero = [&](size_t k) -> Moving_body {
      if (k >= nr) return obst[k - nr];
      if (at_zero.empty())
        at_zero = r.chain.segment_motions(q0, q0, nullptr, nullptr, ro.check_link ? &ro.check_link : nullptr);
      const size_t L = r.bodies[k].link;
      if (!at_zero_data[L]) at_zero_data[L] = narrow::prepare_motion(at_zero[L], true);
      return narrow::prepare_body(r.bodies[k].body, at_zero_data[L]);
    };
    auto may_contain_at_zero = [&](const Pair_plan &p) {
      if (!solid_pair(p)) return false;
      const long base = base_of(p);
      const Filter_side a = side(p.i, base), b = side(p.j, base);
      return enclose::boxes_meet(enclose::frame_box(a.instant(0, 0), a.data->box_c, a.data->box_h),
                                 enclose::frame_box(b.instant(0, 0), b.data->box_c, b.data->box_h)) &&
             !solids_apart_at_zero(a, b) && contained_exactly_at_zero(body_at_zero(p.i), body_at_zero(p.j));
    };
    // Pairs whose root boxes over [0, 1] are apart (roots_apart, link_filter.h): no
    // witness, no contact, no containment at t = 0, so the decide scan and the
    // containment test skip them (their answers are known: none). Most pairs of a free
    // segment are such; the scan's instant poses and traversals of them were about a
    // tenth of a free Panda segment (perf, issue 30).
    // Each body's root box over [0, 1] in the world frame made once (a link's was remade
    // for each obstacle); a self pair's, in its common ancestor's frame, per pair.
    std::vector<signed char> far_of(plans.size(), -1), has_whole(nr + obst.size(), 0);
    std::vector<enclose::Box> whole(nr + obst.size());
    auto whole_of = [&](size_t k, const Filter_side &s) {
      if (s.base != -1) return whole_box(s);
      if (!has_whole[k]) {
        whole[k] = whole_box(s);
        has_whole[k] = 1;
      }
      return whole[k];
    };
    auto far = [&](size_t q) {
      if (far_of[q] < 0) {
        const long base = base_of(plans[q]);
        far_of[q] = roots_apart(whole_of(plans[q].i, side(plans[q].i, base)),
                                whole_of(plans[q].j, side(plans[q].j, base)), reach);
      }
      return far_of[q] == 1;
    };
    // The witness scans' pairs and node pairs per pair and instant (instant_scan.h).
    Instant_scan scan(nr + obst.size());
    auto scan_side = [&](size_t q, int s) { return side(s == 0 ? plans[q].i : plans[q].j, base_of(plans[q])); };
    constexpr size_t kScan_tests = 64;
    std::vector<Pair_plan> kept;
    Witness found;
    size_t found_i = 0, found_j = 0;
    // After a witness at t_w: decide mode clears the other pairs only up to the witness
    // pair's bound, and briefly (kAfter_tests: their bounds serve free_until alone);
    // first-contact mode clears them up to t_w (the first contact is at most t_w) and
    // keeps those that may touch by then. 64 node pairs a pair: 1024 cost 1.2 ms of a
    // colliding Panda segment's 2.9 (bench above), for free_until alone.
    constexpr size_t kAfter_tests = 64;
    Filter_limits lim;
    lim.delta_lo = reach > 0 ? opt.solve.delta_box.lo : 0;  // witnesses within delta
    // A robot state (q0 = q1, obstacles standing still): every instant holds the same
    // poses. Only what the filter spends depends on it (link_filter.h: a bound is valid
    // either way); a state check was 155 us on the Panda, most of it in equal pieces.
    lim.frozen = std::equal(q0, q0 + r.chain.size(), q1) &&
                 std::all_of(obst.begin(), obst.end(), [](const Moving_body &b) { return stands_still(*b.mo); });
    double horizon = 1;  // first-contact mode: the witness's t_w
    // Decide mode: a scan for a witness at 1/2, then 1/4 and 3/4, over every pair, before
    // any pair is cleared: on a segment that collides over a stretch of time a contact is
    // found in a few root-down traversals, where clearing the pairs in turn first (each
    // to its first uncleared piece, then the others up to it for free_until) cost 3.2 ms
    // on a Panda's colliding segments (issue 30). A found witness is a certain contact as
    // any (touching_at) and ends the check at once: decide mode answers whether, and
    // spends nothing on the prefix (free_until 0, a valid bound; pccd_report_free_until).
    if (decide && !opt.all_contacts) {
      // The instants and the node pairs per pair and instant: measured on the Panda bench
      // (200 segments, CPU ms per segment, colliding / free means): no scan 2.37 / 0.65,
      // 1/2 and the quarters with 64 pairs 1.12 / 0.70, the eighths too 0.86 / 0.80, 16
      // pairs 1.73 / 0.81 (a near pair needs more to reach its leaves).
      // (depth, index): 1/2, 1/4, 3/4; with a minimum distance 0 first (a start within
      // delta, where the start was checked for touching alone, ended at a midpoint
      // witness near 0 after traversals: up to 9 ms on the UR5's; issue 33).
      static const long kScan[4][2] = {{0, 0}, {1, 1}, {2, 1}, {2, 3}};
      const auto *scan_from = lim.delta_lo > 0 ? kScan : kScan + 1;
      // With a minimum distance, a pair within delta at an instant holds a front of many
      // node pairs within reach, and 64 seldom reach a leaf pair certainly within delta:
      // 1024 (bench_robot.py --n 1000 --min-distance 0.05, two runs each, decide ratio
      // with / without delta: UR5 with self-collision 3.65x, 3.56x -> 3.34x, 3.38x;
      // without 2.68x, 2.76x -> 2.54x, 2.51x; Panda 1.75x, 1.80x -> 1.68x, 1.67x with it,
      // 1.82x, 1.87x -> 1.78x, 1.84x without; 4096 no better).
      constexpr size_t kScan_tests_delta = 1024;
      const size_t tests = lim.delta_lo > 0 ? kScan_tests_delta : kScan_tests;
      Witness w;
      for (const auto *m = scan_from; m != kScan + 4; ++m) {
        if (lim.frozen && m != scan_from) break;  // every instant holds the same poses
        const size_t q = scan.find(plans, static_cast<int>((*m)[0]), (*m)[1], reach, lim.delta_lo, tests,
                                   scan_side, far, w);
        if (w.found) return witness_report(plans[q].i, plans[q].j, w, 0.0);
      }
    }
    // First-contact mode with a minimum distance: a pair certainly within delta at t = 0
    // (touching_at on the poses at 0, kWitness_tests node pairs) has bound 0, which is
    // what its traversal returns (the piece holding 0 is never separated), and is a
    // witness at 0 when none was found before. The traversal of such a pair went down to
    // the finest piece with a front of thousands (links within 5 cm over a stretch:
    // 50-100 ms each on the UR5's self pairs; issue 33), and a witness at 0 leaves the
    // later pairs nothing to clear (until = 0).
    const bool zero_witness = !decide && reach > 0 && lim.delta_lo > 0;
    constexpr size_t kZero_tests = 4096;
    // Each pair's test at 0 runs before any traversal. Once some pair (zero_q) is
    // certainly within delta at 0, the first contact is 0: a pair before it that the same
    // test finds farther than delta at 0 (kApart) cannot touch first and is dropped; any
    // other goes to the exact solve with bound 0, which decides it at 0 (pair_search.h).
    // Their traversals to the finest piece holding 0 took up to kMax_tests node pairs for
    // that (35 ms for a UR5 base-forearm pair within delta at 0 by a hair; issue 33).
    enum : signed char { kUntested = 0, kWithin = 1, kApart = 2 };
    std::vector<signed char> zero_of(plans.size(), kUntested);
    std::vector<std::pair<uint32_t, uint32_t>> zero_at(plans.size());
    size_t zero_q = plans.size();
    for (size_t q = 0; zero_witness && q < plans.size(); ++q) {
      const long base = base_of(plans[q]);
      const Filter_side a = side(plans[q].i, base), b = side(plans[q].j, base);
      size_t budget = kZero_tests;
      bool apart = false;
      if (a.data->mesh && b.data->mesh &&
          touching_at(*a.data, a.instant(0, 0), *b.data, b.instant(0, 0), kRoots, budget, zero_at[q].first,
                      zero_at[q].second, reach, lim.delta_lo, a.tree, b.tree, nullptr, &apart)) {
        zero_of[q] = kWithin;
        zero_q = std::min(zero_q, q);
      } else if (apart) {
        zero_of[q] = kApart;
      }
    }
    // Witness tests per instant after a pair's bound in first-contact mode: an exact
    // solve follows anyway (10 ms and more on the UR5), and a tighter window saves most
    // of it; 4096 node pairs reached the leaf pairs within delta near a plate where
    // kWitness_tests did not (issue 33).
    constexpr size_t kWindow_tests = 4096;
    // First-contact mode with a minimum distance, no witness at 0: a scan at 1/8, ...,
    // 7/8 in turn (instant_scan.h) bounds the first contact before any traversal. Then
    // the pairs are cleared in turn, the scan's pair first, each only up to the least
    // witness so far (until) and without midpoint witnesses, so to the finest piece (the
    // window's bound); a pair left uncleared before it tries a witness just after its
    // bound (witness_after), which bounds the pairs after it. The pairs before the
    // midpoint witness were cleared over all of [0, 1], those after it to the finest
    // piece up to that coarse witness, and the witness pair twice: 3.7 of the 8.5 ms of a
    // UR5 segment first within delta after 0 (issue 33). Without a minimum distance
    // contacts are rarer and the scan's instants cost the free segments: the median
    // first-contact Panda segment of bench_plainmp.py went from 366 to 473 us (one run).
    const bool scan_first = !decide && !opt.all_contacts && !lim.frozen && lim.delta_lo > 0 && zero_q == plans.size();
    size_t s = plans.size();  // the scan's pair
    for (long k = 1; scan_first && k < 8 && s == plans.size(); ++k) {
      s = scan.find(plans, 3, k, reach, lim.delta_lo, kScan_tests, scan_side, far, found);
      if (s < plans.size()) horizon = lim.until = std::ldexp(static_cast<double>(k), -3);
    }
    const bool scanned = s < plans.size();
    if (scanned) {
      found_i = plans[s].i;
      found_j = plans[s].j;
      std::vector<double> lower(plans.size(), kNever);
      constexpr size_t kBound_tries = 8;  // witness tries in the pass (a pair each)
      size_t tries = 0;
      auto clear = [&](size_t q) {
        const Pair_plan &p = plans[q];
        if (far(q) && lim.delta_lo <= reach) return;  // as below: never within reach
        const long base = base_of(p);
        const Filter_side a = side(p.i, base), b = side(p.j, base);
        lower[q] = first_uncleared(a, b, reach, lim);
        if (lower[q] > 0 && may_contain_at_zero(p)) {  // as below: the exact solve's test at 0
          lower[q] = 0;
          return;
        }
        Witness w;
        if (lower[q] < horizon && tries++ < kBound_tries &&
            witness_after(a, b, lower[q], w, reach, lim.delta_lo, kWindow_tests)) {
          const double t = std::ldexp(static_cast<double>(w.index), -w.depth);  // exact: dyadic
          if (t < horizon) {
            horizon = lim.until = t;
            found = w;
            found_i = p.i;
            found_j = p.j;
          }
        }
      };
      clear(s);
      for (size_t q = 0; q < plans.size(); ++q)
        if (q != s) clear(q);
      for (size_t q = 0; q < plans.size(); ++q)
        if (lower[q] <= horizon) kept.push_back({plans[q].i, plans[q].j, lower[q]});
    }
    for (size_t q = 0; q < plans.size() && !scanned; ++q) {
      Pair_plan p = plans[q];
      Witness w;
      const long base = base_of(p);
      const Filter_side a = side(p.i, base), b = side(p.j, base);
      const bool before_zero = q < zero_q && zero_q < plans.size() && !opt.all_contacts && !found.found;
      if (zero_of[q] == kWithin) {
        p.lower = 0;
        if (!opt.all_contacts && !found.found) w = Witness{true, 0, 0, zero_at[q].first, zero_at[q].second};
      } else if (before_zero) {  // the pairs before zero_q (above)
        if (zero_of[q] == kApart && (far(q) || !may_contain_at_zero(p))) continue;  // unless a solid holds a point
        p.lower = 0;
      } else if (far(q) && lim.delta_lo <= reach) {
        // Root boxes over [0, 1] apart (the box first_uncleared's first piece tests):
        // what its call returns, without the call (a fifth of a free Panda segment's
        // calls' cost was their setup). No witness: one would be within delta_lo <= reach
        // of a pair certainly farther than reach.
        p.lower = lim.until > 0 ? kNever : 0;
      } else {
        p.lower = first_uncleared(a, b, reach, lim, !opt.all_contacts && !found.found ? &w : nullptr);
      }
      if (w.found) {
        found = w;
        found_i = p.i;
        found_j = p.j;
        horizon = std::ldexp(static_cast<double>(w.index), -w.depth);  // exact: dyadic
        lim.until = decide ? p.lower : horizon;
        if (decide) lim.max_tests = kAfter_tests;
      }
      // Such a pair goes to the exact solve (its containment test at t = 0) with bound 0.
      if (p.lower > 0 && !far(q) && may_contain_at_zero(p)) p.lower = 0;
      if (p.lower <= horizon) kept.push_back(p);
    }
    std::stable_sort(kept.begin(), kept.end(),
                     [](const Pair_plan &x, const Pair_plan &y) { return x.lower < y.lower; });
    // Decide mode: a witness just after a kept pair's bound, before any exact motion.
    for (size_t k = 0; k < kept.size() && decide && !found.found; ++k)
      if (witness_after(side(kept[k].i, base_of(kept[k])), side(kept[k].j, base_of(kept[k])), kept[k].lower, found,
                        reach, lim.delta_lo)) {
        found_i = kept[k].i;
        found_j = kept[k].j;
      }
    if (found.found && decide) return witness_report(found_i, found_j, found, kept.empty() ? 1.0 : kept[0].lower);
    if (found.found) {  // first-contact mode: only contacts up to t_w can be first
      // A tighter window (the scan's pass above made it already): the witness pair's own bound without witnesses (to the finest
      // piece), and a witness just after it.
      // A witness pair that may be in contact at t = 0 by containment keeps bound 0 (the
      // bound below is of surface contacts only: a window from it would test
      // containment at its start, not at 0).
      for (Pair_plan &p : kept)
        if (!scanned && p.i == found_i && p.j == found_j && !may_contain_at_zero(p)) {
          Filter_limits upto;
          upto.until = horizon;
          upto.delta_lo = lim.delta_lo;
          upto.from = p.lower;  // separated before it: the first traversal's (link_filter.h)
          const long base = base_of(p);
          // (The guard above: a link holding an obstacle at t = 0 was reported first
          // touching where its surface left it: corpus/robots/solid-link-holds-obstacle-at-zero.robot.)
          p.lower = std::max(p.lower, first_uncleared(side(p.i, base), side(p.j, base), reach, upto));
          Witness w;
          if (p.lower < horizon &&
              witness_after(side(p.i, base), side(p.j, base), p.lower, w, reach, lim.delta_lo, kWindow_tests)) {
            const double t = std::ldexp(static_cast<double>(w.index), -w.depth);
            if (t < horizon) horizon = t;
          }
        }
      // Then a witness just after the earliest bounds of up to kWindow_tries other pairs
      // (kept is sorted by bound): a pair first within delta well before the witness
      // pair's contact left a window of 1/20 and about 100 feature pairs solved exactly
      // (issue 33: a UR5 segment 132 ms with min_distance 0.05, 30 ms without).
      constexpr size_t kWindow_tries = 4;
      size_t tried = scanned ? kWindow_tries : 0;  // the scan's pass tried them
      for (const Pair_plan &p : kept) {
        if (!(p.lower < horizon) || tried == kWindow_tries) break;
        if (p.i == found_i && p.j == found_j) continue;
        ++tried;
        Witness w;
        const long base = base_of(p);
        bool ok = witness_after(side(p.i, base), side(p.j, base), p.lower, w, reach, lim.delta_lo, kWindow_tests);
          if (ok)
          horizon = std::min(horizon, std::ldexp(static_cast<double>(w.index), -w.depth));
      }
      std::vector<Pair_plan> left;
      for (const Pair_plan &p : kept)
        if (p.lower <= horizon) left.push_back(p);
      std::stable_sort(left.begin(), left.end(),
                       [](const Pair_plan &x, const Pair_plan &y) { return x.lower < y.lower; });
      // A witness at t = 0: the witness pair touches then, so the exact solve (scene.h,
      // solve_planned: a contact at t = 0 ends it) never reaches the pairs after it, yet
      // their links' exact motions were built (every pair after the witness pair got
      // bound 0 from until = 0: about 60-80 of them on the Panda's min_distance bench
      // segments, 3.7% of its first-contact mean). Dropped: the same pairs are solved.
      if (horizon == 0)
        for (size_t k = 0; k < left.size(); ++k)
          if (left[k].i == found_i && left[k].j == found_j) {
            left.resize(k + 1);
            break;
          }
      // Only the witness pair left (every pair before it farther than delta at 0, none
      // holding the other's point): it is the pair the exact solve would report, first
      // at 0, and its witness is a certain contact then (one triangle pair, as the
      // contract's start pose within delta reports). The solve built the pair's exact
      // link motions and searched for the pair of least key within delta at 0: 2-8 ms
      // of UR5 segments starting within delta (issue 33).
      if (horizon == 0 && left.size() == 1 && left[0].i == found_i && left[0].j == found_j)
        return witness_report(found_i, found_j, found, 0.0);
      Window win;
      win.lo = left.empty() ? 0 : std::min(left[0].lower, horizon);
      win.hi = horizon;
      // A witness at t = 0 (a certain contact within delta then): the solve needs only
      // the poses at 0, yet over [0, 1] the bvh phase's boxes held whole sweeps, and it
      // listed and tested thousands of feature pairs (half the exact solve of a UR5
      // segment within delta at 0 with self-collision: 40-80 ms; perf, issue 33). The
      // finest piece's window [0, 2^-kMax_depth] holds the same contacts at 0: the
      // witness pair's touches there, so it ends the solve, and the pair reported is
      // the one of least key within delta at 0 (pair_search.cpp, within_at_zero), the
      // same for any window starting at 0.
      if (horizon == 0) win.hi = std::ldexp(1.0, -kMax_depth);
      bool still = true;
      for (const Moving_body &o : obst) still = still && o.mo == narrow::identity_motion();
      win.on = still && win.lo < win.hi && !(opt.solve.until < Rational(horizon));
      Scene_options bounded = opt;
      if (Rational(horizon) < bounded.solve.until) bounded.solve.until = Rational(horizon);
      return solve_exact(r, path, q0, q1, obst, left, bounded, ro, win);
    }
    plans = std::move(kept);
  }

  return solve_exact(r, path, q0, q1, obst, plans, opt, ro);
}

}  // namespace pccd::scene
