#include "scene/robot_exact.h"

#include <algorithm>
#include <map>
#include <memory>

#include "poly/poly.h"

namespace pccd::scene {

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
// A self pair is solved in the frame of its links' lowest common ancestor (frame_of;
// motion::Chain::segment_motions with base): the joints above it move both links alike,
// so every distance, contact time and touching feature is that of the world frame, and
// the polynomials are of far lower degree (a UR5 wrist_1 / ee_link pair: squared
// distances of degree 64 in the world frame, 8 in wrist_1's; issue 33: such a pair
// within delta at one vertex pair sent 47 feature pairs of degree 64 to the rational
// stage, 4.5 s). Obstacle pairs, and self pairs of links without a common ancestor, are
// in the world frame (-1).
Scene_report solve_exact(const Robot_model &r, const motion::Chain_path &path, const double *q0, const double *q1,
                         const std::vector<Moving_body> &obst, std::vector<Pair_plan> plans, const Scene_options &opt,
                         const Robot_options &ro, const Window &win) {
  const size_t nr = r.bodies.size();
  auto frame_of = [&](const Pair_plan &p) -> long {
    return p.j < nr ? path.common_ancestor(r.bodies[p.i].link, r.bodies[p.j].link) : -1L;
  };
  // One frame's link motions, built on the first body asked of it.
  struct Frame {
    std::vector<bool> needed;
    std::vector<motion::Rigid_motion> motions;
    std::vector<motion::Mat3_poly> rn;
    std::vector<std::shared_ptr<const narrow::Motion_data>> link_data;
    std::vector<std::unique_ptr<Moving_body>> bodies;
    bool built = false;
  };
  std::map<long, Frame> frames;
  for (Pair_plan &p : plans) {
    Frame &f = frames[frame_of(p)];
    if (f.needed.empty()) f.needed.assign(r.chain.size(), false);
    f.needed[r.bodies[p.i].link] = true;
    if (p.j < nr) f.needed[r.bodies[p.j].link] = true;
    if (win.on) p.lower = win.to_s(p.lower);
    // A window starting at lo > 0 starts where every pair's filter separated it (each
    // pair's lower >= lo is the end of its separated pieces, closed, so the pair is
    // farther than delta at lo): the pair searches skip their pass at s = 0, which
    // looks for contacts there (the static pass and bvh::least_within_at_zero: 12% of
    // the exact solves of the UR5's min_distance bench segments, perf, issue 33).
    if (win.on && win.lo > 0) p.apart_at_zero = true;
  }
  auto body = [&](size_t k, long base) -> const Moving_body & {
    if (k >= nr) return obst[k - nr];
    Frame &f = frames.at(base);
    if (f.bodies.empty()) f.bodies.resize(nr);
    if (!f.bodies[k]) {
      if (!f.built) {
        f.motions = r.chain.segment_motions(q0, q1, win.on ? nullptr : &f.rn, &f.needed,
                                            ro.check_link ? &ro.check_link : nullptr, base);
        f.link_data.resize(r.chain.size());
        if (win.on) {
          const Rational a(win.lo), b(win.hi);
          for (size_t L = 0; L < f.motions.size(); ++L) {
            if (!f.needed[L]) continue;
            motion::Rigid_motion &m = f.motions[L];
            for (auto &c : m.r) c = poly::reparametrize(c, a, b);
            for (int i = 0; i < 3; ++i) {
              m.o[i] = poly::reparametrize(m.o[i], a, b);
              m.b[i] = poly::reparametrize(m.b[i], a, b);
            }
          }
        }
      }
      f.built = true;
      const size_t L = r.bodies[k].link;
      if (!f.link_data[L]) f.link_data[L] = narrow::prepare_motion(f.motions[L], true, win.on ? nullptr : &f.rn[L]);
      f.bodies[k] = std::make_unique<Moving_body>(narrow::prepare_body(r.bodies[k].body, f.link_data[L]));
    }
    return *f.bodies[k];
  };
  Scene_options o = opt;
  // The window ends at the witness: every contact up to it; a witness at 0 (the window
  // [0, 2^-14], until 0): contacts at 0 alone (pair_search.cpp: a pair within delta
  // nowhere at 0 is then done after its search at 0).
  if (win.on) o.solve.until = win.lo == 0 && sgn(opt.solve.until) == 0 ? 0 : 1;
  // The time tolerance is one of t: a width tol / (hi - lo) in s is tol in t (the report's
  // enclosures, combine.h's included, map back scaled by hi - lo). The same tol in s asked
  // for enclosures 2^14 times tighter than tol on a window of 2^-14, below the spacing
  // of doubles there, so the interval stage could not isolate the first time and the
  // contact pair went to the exact stage (issue 30: 8 of the 23 ms of a colliding Panda
  // segment, and most of the min_distance cost).
  if (win.on) o.solve.tol = opt.solve.tol / (Rational(win.hi) - Rational(win.lo));
  // On the window (2^-14 wide on the bench's colliding segments) the automatic phase is
  // bvh: its certified spreads are tiny there, so it hands over a few dozen candidates
  // that the interval stages decide, where the range phase chosen by estimate paid about
  // a quarter of a colliding Panda segment's time for its queries (perf). Speed only
  // (every phase gives the same answers); measured on the bench segments, same run:
  // first-contact means -7% (Panda) and -9% (UR5), answers identical (issue 30).
  if (win.on && o.broad_phase == Broad_phase::automatic) o.broad_phase = Broad_phase::bvh;
  Scene_report rep = solve_planned(
      [&](const Pair_plan &p, size_t k) -> const Moving_body & { return body(k, frame_of(p)); }, plans, o, -1, true);
  if (win.on) map_back(rep, win);
  return rep;
}

}  // namespace pccd::scene
