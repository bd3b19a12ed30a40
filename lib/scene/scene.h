// Scenes of moving bodies: every body pair in contact, and the scene's first contact.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "scene/pair_search.h"

namespace pccd::scene {

using narrow::Body_data;

struct Scene_body {
  std::shared_ptr<const Body_data> body;  // make_body_data, once per body
  // The motion's validated data when the caller has it (a pccd_motion keeps it:
  // api/motion_handle.h). Else the motion, derived and validated by the solve (an
  // invalid motion is reported there); neither: stationary.
  std::shared_ptr<const narrow::Motion_data> prepared;
  std::optional<motion::Rigid_motion> motion;
};

// The body on its motion (prepared or derived now; Input_error when the motion is
// invalid).
Moving_body prepare_body(const Scene_body &b);
// Every body prepared, in order; Input_error "<name>[k].motion: ..." for an invalid motion.
std::vector<Moving_body> prepare_bodies(const std::vector<Scene_body> &bodies, const std::string &name);

// Read once by the api (api/config.h, Call_config::scene_options).
struct Scene_options {
  pred::Solve_options solve;
  bool all_contacts = false;
  Broad_phase broad_phase = Broad_phase::bvh;  // resolve(); automatic: choose() per pair (broad_phase.h)
  unsigned threads = 1;
  double reach = 0;  // enclose::reach_of(solve.delta): 0 without a minimum separation
};

struct Contact_report {
  Feature_ref a, b;       // features of body i and body j
  arith::Rational lo, hi; // this feature pair's first contact time (lo == hi when exact)
  bool exact = false;
};

struct Pair_report {
  size_t i = 0, j = 0;  // i < j
  arith::Rational lo, hi;
  bool exact = false;
  std::vector<Contact_report> contacts;  // sorted by time, then features
};

struct Scene_report {
  bool collides = false;
  arith::Rational lo, hi;
  bool exact = false;
  std::vector<Pair_report> pairs;   // the pairs in contact, ascending (i, j)
  std::vector<size_t> first_pairs;  // indices into pairs: those that may touch first
  Search_stats stats;
  // A certified contact-free prefix: no checked pair touches at any t < free_until
  // (1 without a contact: then none touches on the closed [0, 1]). First-contact mode:
  // lo. Decide mode (solve.want_time false): the lower bound of the pair that stopped
  // the solve (Pair_plan::lower; 0 for a scene's pairs, which have none).
  arith::Rational free_until = 1;
};

// A body pair to check with a certified lower bound of its contact times (a filter's:
// scene/robot.h; 0 when none is known). apart_at_zero: the pair is certainly apart at
// t = 0 (with a minimum distance: farther than delta) even where lower is 0; a filter's
// lower > 0 says so by itself.
struct Pair_plan {
  size_t i = 0, j = 0;
  double lower = 0;
  bool apart_at_zero = false;
};

// Body pairs (i, j), i < j, that are not checked (a robot's adjacent links, pairs a
// caller allows to touch): left out of the pair list before any broad phase runs, so
// every phase honours them and they never appear in a report.
using Pair_set = std::set<std::pair<size_t, size_t>>;

// Input_error naming "bodies[k].motion" when a motion's quaternion vanishes on [0, 1]
// (every body's motion is validated, also of bodies whose pairs are all skipped).
Scene_report solve_scene(const std::vector<Scene_body> &bodies, const Scene_options &opt,
                         const Pair_set &skipped = {});

// The report of the body pairs (i, j), i < j, of bodies already on their (validated)
// motions: solve_scene's work after validation, also behind the on-line index
// (online_index.h). stored: Search_options::stored of every pair (range phase).
Scene_report solve_prepared(const std::vector<const Moving_body *> &mb,
                            const std::vector<std::pair<size_t, size_t>> &pairs,
                            const Scene_options &opt, int stored);

// The same over pairs in ascending order of Pair_plan::lower, each pair's body on demand
// (body(plan, k): the prepared body k, k = plan.i or plan.j, built at most once by the
// caller; in any frame common to the pair's two bodies, which may differ from pair to
// pair: a robot's self pairs are solved relative to a link, scene/robot.cpp). Modes:
//  - decide (opt.solve.want_time false, not all_contacts): the first pair found in
//    contact ends the solve; the report holds it alone, with a witness (some contact
//    and some enclosure of one of its times), and free_until = its lower bound.
//  - witness (first-contact mode, not all_contacts): the pairs that cannot touch
//    before the best upper bound found so far are not solved (a pair whose lower bound
//    is above it; the others are asked only up to it), and a contact at exactly t = 0
//    ends the solve. The first contact and the pairs touching first are those of the
//    full solve; the report lists the pairs found touching, not every pair in contact.
//  - otherwise as solve_prepared: every pair.
Scene_report solve_planned(const std::function<const Moving_body &(const Pair_plan &, size_t)> &body,
                           const std::vector<Pair_plan> &plans, const Scene_options &opt,
                           int stored, bool witness);

}  // namespace pccd::scene
