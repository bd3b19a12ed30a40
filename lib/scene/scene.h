// Scenes of moving bodies: every body pair in contact, and the scene's first contact.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
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

// Read once by the api (api/config.h, Call_config::scene_options).
struct Scene_options {
  pred::Solve_options solve;
  bool all_contacts = false;
  Broad_phase broad_phase = Broad_phase::bvh;  // resolved (resolve(), broad_phase.h)
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

}  // namespace pccd::scene
