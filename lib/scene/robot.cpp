#include "scene/robot.h"

#include <algorithm>
#include <map>
#include <string>
#include <tuple>

#include "motion/chain_path.h"
#include "poly/poly.h"
#include "scene/link_filter.h"
#include "scene/solid_start.h"

namespace pccd::scene {

namespace {

// The link's ball (motion/chain_path.h) in the form enclose::frame_box maps boxes with
// (pivot 0): every entry of R(t) - Rm is at most ||R(t) - Rm||_2 <= eps, every
// coordinate of o(t) - om at most |o(t) - om|_2 <= rho.
enclose::Pose_piece pose_piece(const motion::Pose_bounds &p) {
  enclose::Pose_piece out;
  bool finite = std::isfinite(p.eps) && std::isfinite(p.rho);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      out.Rm[i][j] = p.Rm[i][j];
      out.Rr[i][j] = p.eps;
    }
    out.om[i] = p.om[i];
    out.orad[i] = p.rho;
    finite = finite && std::isfinite(p.om[i]);
  }
  out.finite = finite;
  return out;
}

// The poses of every link and obstacle on the dyadic pieces and at the dyadic instants
// the filter visits, each computed once per check.
class Piece_poses {
 public:
  Piece_poses(const motion::Chain_path &path, const std::vector<Moving_body> &obstacles)
      : path_(path), obstacles_(obstacles) {}

  // Link k over the piece: the ball, and the second-order enclosure (link_filter.h) when
  // its chords' growth is at most half the ball's radii (at the coarse pieces the ball
  // is tighter; the choice is a heuristic, both enclosures hold).
  Side_piece link(long base, size_t k, int d, long i) {
    Piece &p = at(base, d, i);
    const double a = std::ldexp(static_cast<double>(i), -d), b = std::ldexp(static_cast<double>(i + 1), -d);
    Side_piece s;
    s.ball = &link_pose(p, base, k, a, b);
    path_.derivatives_link(a, b, k, base, p.derivs, p.have_derivs);
    const motion::Path_derivs &D = p.derivs[k];
    const double gr = arith::round_up(std::ldexp(D.d2, -2 * d - 3)), go = arith::round_up(std::ldexp(D.o2, -2 * d - 3));
    if (std::isfinite(gr) && std::isfinite(go) && gr <= 0.5 * s.ball->Rr[0][0] && go <= 0.5 * s.ball->orad[0]) {
      s.at_a = &link_at(base, k, d, i);
      s.at_b = &link_at(base, k, d, i + 1);
      s.g_rot = gr;
      s.g_off = go;
    }
    return s;
  }
  const enclose::Pose_piece &link_at(long base, size_t k, int d, long i) {
    const double t = std::ldexp(static_cast<double>(i), -d);
    return link_pose(instant(base, d, i), base, k, t, t);
  }
  Side_piece obstacle(size_t k, int d, long i) {
    Piece &p = at(-1, d, i);
    if (!p.have_obstacle[k]) {
      const double a = std::ldexp(static_cast<double>(i), -d), b = std::ldexp(static_cast<double>(i + 1), -d);
      p.obstacles[k] = still(k) || d == 0 ? enclose::whole_pose(obstacles_[k]) : enclose::enclose_pose(obstacles_[k], a, b);
      p.have_obstacle[k] = true;
    }
    Side_piece s;
    s.ball = &p.obstacles[k];
    s.identity = still(k);
    return s;
  }
  const enclose::Pose_piece &obstacle_at(size_t k, int d, long i) {
    Piece &p = instant(-1, d, i);
    if (!p.have_obstacle[k]) {
      const double t = std::ldexp(static_cast<double>(i), -d);
      p.obstacles[k] = still(k) ? enclose::whole_pose(obstacles_[k]) : enclose::enclose_pose(obstacles_[k], t, t);
      p.have_obstacle[k] = true;
    }
    return p.obstacles[k];
  }

 private:
  // The poses over one piece or at one instant, each link's made on its first demand
  // (with its ancestors': motion/chain_path.h, enclose_link).
  struct Piece {
    std::vector<motion::Pose_bounds> bounds;
    std::vector<char> have_bounds;
    std::vector<enclose::Pose_piece> links;
    std::vector<char> have_links;
    std::vector<motion::Path_derivs> derivs;  // pieces only
    std::vector<char> have_derivs;
    std::vector<enclose::Pose_piece> obstacles;
    std::vector<bool> have_obstacle;
  };
  // A stationary obstacle's pose is the same on every piece.
  bool still(size_t k) const { return obstacles_[k].mo == narrow::identity_motion(); }
  Piece &start(Piece &p) {
    if (p.have_obstacle.empty()) {
      p.obstacles.resize(obstacles_.size());
      p.have_obstacle.assign(obstacles_.size() + 1, false);  // + 1: never empty after this
      p.links.resize(path_.size());
      p.have_links.assign(path_.size(), 0);
    }
    return p;
  }
  const enclose::Pose_piece &link_pose(Piece &p, long base, size_t k, double a, double b) {
    if (!p.have_links[k]) {
      path_.enclose_link(a, b, k, base, p.bounds, p.have_bounds);
      p.links[k] = pose_piece(p.bounds[k]);
      p.have_links[k] = 1;
    }
    return p.links[k];
  }
  Piece &at(long base, int d, long i) { return start(pieces_[{base, d, i}]); }
  // The instant i / 2^d, kept under its lowest terms (the end of one piece is the start
  // of the next, and of pieces of other depths).
  Piece &instant(long base, int d, long i) {
    while (d > 0 && i % 2 == 0) {
      i /= 2;
      --d;
    }
    if (i == 0) d = 0;
    return start(instants_[{base, d, i}]);
  }

  const motion::Chain_path &path_;
  const std::vector<Moving_body> &obstacles_;
  // Keyed by (base, depth, index): links relative to link base (-1: the world, and the
  // obstacles), on the piece or at the instant index / 2^depth.
  std::map<std::tuple<long, int, long>, Piece> pieces_;
  std::map<std::tuple<long, int, long>, Piece> instants_;
};

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

// A time window [lo, hi] of [0, 1] holding the first contact (no checked pair touches
// before lo: the filter's bounds; some pair touches at hi: a witness), solved as the
// segment t = lo + (hi - lo) s, s in [0, 1]: the exact motions reparametrized (the same
// motion, each polynomial composed with that affine map), the report's times mapped
// back. The first contact, the pairs touching first and their features are those of
// [0, 1]; the exact solve's enclosures are far tighter on the short window.
struct Window {
  bool on = false;
  double lo = 0, hi = 1;  // dyadic doubles
  Rational to_t(const Rational &s) const { return Rational(lo) + (Rational(hi) - Rational(lo)) * s; }
  double to_s(double t) const {  // a lower bound of the window time of t >= lo
    return std::max(0.0, arith::round_down((t - lo) / (hi - lo)));
  }
};

void map_back(Scene_report &rep, const Window &w) {
  rep.lo = w.to_t(rep.lo);
  rep.hi = w.to_t(rep.hi);
  rep.free_until = w.to_t(rep.free_until);
  for (Pair_report &p : rep.pairs) {
    p.lo = w.to_t(p.lo);
    p.hi = w.to_t(p.hi);
    for (Contact_report &c : p.contacts) {
      c.lo = w.to_t(c.lo);
      c.hi = w.to_t(c.hi);
    }
  }
}

// The exact solve of the pairs left (scene.h, solve_planned), the exact motions of their
// links built on the first demand (over the window when it is on: obstacles stationary).
Scene_report solve_exact(const Robot_model &r, const double *q0, const double *q1, const std::vector<Moving_body> &obst,
                         std::vector<Pair_plan> plans, const Scene_options &opt, const Robot_options &ro,
                         const Window &win = {}) {
  const size_t nr = r.bodies.size();
  std::vector<bool> needed(r.chain.size(), false);
  for (Pair_plan &p : plans) {
    needed[r.bodies[p.i].link] = true;
    if (p.j < nr) needed[r.bodies[p.j].link] = true;
    if (win.on) p.lower = win.to_s(p.lower);
  }
  std::vector<motion::Rigid_motion> motions;
  std::vector<motion::Mat3_poly> rn;
  std::vector<std::shared_ptr<const narrow::Motion_data>> link_data(r.chain.size());
  std::vector<std::unique_ptr<Moving_body>> robot_mb(nr);
  bool built = false;
  auto body = [&](size_t k) -> const Moving_body & {
    if (k >= nr) return obst[k - nr];
    if (!robot_mb[k]) {
      if (!built) {
        motions = r.chain.segment_motions(q0, q1, win.on ? nullptr : &rn, &needed,
                                          ro.check_link ? &ro.check_link : nullptr);
        if (win.on) {
          const Rational a(win.lo), b(win.hi);
          for (size_t L = 0; L < motions.size(); ++L) {
            if (!needed[L]) continue;
            motion::Rigid_motion &m = motions[L];
            for (auto &c : m.r) c = poly::reparametrize(c, a, b);
            for (int i = 0; i < 3; ++i) {
              m.o[i] = poly::reparametrize(m.o[i], a, b);
              m.b[i] = poly::reparametrize(m.b[i], a, b);
            }
          }
        }
      }
      built = true;
      const size_t L = r.bodies[k].link;
      if (!link_data[L]) link_data[L] = narrow::prepare_motion(motions[L], true, win.on ? nullptr : &rn[L]);
      robot_mb[k] = std::make_unique<Moving_body>(narrow::prepare_body(r.bodies[k].body, link_data[L]));
    }
    return *robot_mb[k];
  };
  Scene_options o = opt;
  if (win.on) o.solve.until = 1;  // the window ends at the witness: every contact up to it
  Scene_report rep = solve_planned(body, plans, o, -1, true);
  if (win.on) map_back(rep, win);
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

  if (ro.filter) {
    Piece_poses poses(path, obst);
    const double reach = opt.reach;
    const bool decide = !opt.solve.want_time && !opt.all_contacts;
    // Body k of pair p's side: a link body relative to the pair's base (the links' lowest
    // common ancestor for a self pair: the motion of the joints above it moves both
    // alike and drops out; -1 against an obstacle), the base's own bodies standing still.
    static const enclose::Pose_piece identity_pose = [] {
      enclose::Pose_piece p;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          p.Rm[i][j] = i == j ? 1 : 0;
          p.Rr[i][j] = 0;
        }
      return p;
    }();
    auto side = [&](size_t k, long base) {
      Filter_side s;
      if (k < nr) {
        const size_t link = r.bodies[k].link;
        s.data = r.bodies[k].body.get();
        if (static_cast<long>(link) == base) {
          s.piece = [](int, long) {
            Side_piece x;
            x.ball = &identity_pose;
            x.identity = true;
            return x;
          };
          s.instant = [](int, long) -> const enclose::Pose_piece & { return identity_pose; };
        } else {
          s.piece = [&poses, base, link](int d, long i) { return poses.link(base, link, d, i); };
          s.instant = [&poses, base, link](int d, long i) -> const enclose::Pose_piece & {
            return poses.link_at(base, link, d, i);
          };
        }
      } else {
        s.data = obst[k - nr].data.get();
        s.piece = [&poses, o = k - nr](int d, long i) { return poses.obstacle(o, d, i); };
        s.instant = [&poses, o = k - nr](int d, long i) -> const enclose::Pose_piece & { return poses.obstacle_at(o, d, i); };
      }
      return s;
    };
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
    std::vector<Pair_plan> kept;
    Witness found;
    size_t found_i = 0, found_j = 0;
    // After a witness at t_w: decide mode clears the other pairs only up to the witness
    // pair's bound, and briefly (kAfter_tests: their bounds serve free_until alone);
    // first-contact mode clears them up to t_w (the first contact is at most t_w) and
    // keeps those that may touch by then.
    constexpr size_t kAfter_tests = 1024;
    Filter_limits lim;
    lim.delta_lo = reach > 0 ? opt.solve.delta_box.lo : 0;  // witnesses within delta
    double horizon = 1;  // first-contact mode: the witness's t_w
    for (Pair_plan p : plans) {
      Witness w;
      const long base = base_of(p);
      p.lower = first_uncleared(side(p.i, base), side(p.j, base), reach, lim,
                                !opt.all_contacts && !found.found ? &w : nullptr);
      if (w.found) {
        found = w;
        found_i = p.i;
        found_j = p.j;
        horizon = std::ldexp(static_cast<double>(w.index), -w.depth);  // exact: dyadic
        lim.until = decide ? p.lower : horizon;
        if (decide) lim.max_tests = kAfter_tests;
      }
      // Such a pair goes to the exact solve (its containment test at t = 0) with bound 0.
      if (p.lower > 0 && may_contain_at_zero(p)) p.lower = 0;
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
      // A tighter window: the witness pair's own bound without witnesses (to the finest
      // piece), and a witness just after it.
      // A witness pair that may be in contact at t = 0 by containment keeps bound 0 (the
      // bound below is of surface contacts only: a window from it would test
      // containment at its start, not at 0).
      for (Pair_plan &p : kept)
        if (p.i == found_i && p.j == found_j && !may_contain_at_zero(p)) {
          Filter_limits upto;
          upto.until = horizon;
          upto.delta_lo = lim.delta_lo;
          const long base = base_of(p);
          p.lower = std::max(p.lower, first_uncleared(side(p.i, base), side(p.j, base), reach, upto));
          Witness w;
          if (p.lower < horizon && witness_after(side(p.i, base), side(p.j, base), p.lower, w, reach, lim.delta_lo)) {
            const double t = std::ldexp(static_cast<double>(w.index), -w.depth);
            if (t < horizon) horizon = t;
          }
        }
      std::vector<Pair_plan> left;
      for (const Pair_plan &p : kept)
        if (p.lower <= horizon) left.push_back(p);
      std::stable_sort(left.begin(), left.end(),
                       [](const Pair_plan &x, const Pair_plan &y) { return x.lower < y.lower; });
      Window win;
      win.lo = left.empty() ? 0 : std::min(left[0].lower, horizon);
      win.hi = horizon;
      bool still = true;
      for (const Moving_body &o : obst) still = still && o.mo == narrow::identity_motion();
      win.on = still && win.lo < win.hi && !(opt.solve.until < Rational(horizon));
      Scene_options bounded = opt;
      if (Rational(horizon) < bounded.solve.until) bounded.solve.until = Rational(horizon);
      return solve_exact(r, q0, q1, obst, left, bounded, ro, win);
    }
    plans = std::move(kept);
  }

  return solve_exact(r, q0, q1, obst, plans, opt, ro);
}

}  // namespace pccd::scene
