// Robot checks: a kinematic chain with bodies attached to its links, kept across
// segments (the bodies' hierarchies are built once, with the bodies), checked over a
// joint-space segment against obstacles and itself.
//
// One check (check_robot):
//  1. the body pairs: every robot body against every obstacle, and with self_collision
//     every two robot bodies of different groups whose group pair is not allowed
//     (groups: a URDF link's geometries share one; allowed: adjacency, SRDF
//     disable_collisions, as the caller sets). Obstacle pairs are never checked.
//  2. the filter (link_filter.h), unless off: each pair's certified lower bound of its
//     contact times from the links' interval poses straight from the joint path
//     (motion/chain_path.h) and the obstacles' enclosures; a pair separated on all of
//     [0, 1] is dropped, the others are sorted by their bound. A pair with a solid mesh
//     whose bodies' boxes meet at t = 0 gets bound 0 and is kept (the filter bounds
//     surface contacts, not containment: narrow/containment.h) unless solid_start.h
//     certifies that neither holds a containment point of the other at t = 0.
//  3. the exact link motions (motion::Chain::segment_motions, lazily: only the links of
//     the pairs left, and their ancestors; a self pair's in the frame of its links'
//     lowest common ancestor, the same contacts at far lower degrees) and the exact
//     solve of those pairs, in order
//     (scene.h, solve_planned: decide mode stops at the first pair in contact; first-
//     contact mode skips the pairs whose bound is above the best upper bound so far and
//     stops at a contact at t = 0).
// What the filter drops never touches: the answer (collides, the first contact, the
// pairs and features touching first) is that of the exact solve of every pair.
// Body indices in the report: the robot's bodies in order, then the obstacles.
#pragma once
#include <set>
#include <utility>
#include <vector>

#include "motion/chain.h"
#include "scene/scene.h"

namespace pccd::scene {

struct Robot_body {
  size_t link = 0;   // chain link the body is fixed to (in the link's frame)
  size_t group = 0;  // bodies of one group are never checked against each other
  std::shared_ptr<const Body_data> body;
};

struct Robot_model {
  motion::Chain chain;
  std::vector<Robot_body> bodies;
  std::set<std::pair<size_t, size_t>> allowed;  // group pairs (g, h), g < h, not checked
};

struct Robot_options {
  bool self_collision = true;
  bool filter = true;  // false: every pair goes to the exact solve (for tests)
  // Called on every link motion built (motion::Link_check; empty: none): the api holds
  // them to config.max_number_bits.
  motion::Link_check check_link;
};

// Input_error: "q0[k]" / "q1[k]" as motion::Chain::segment_motions, "obstacles[k].motion"
// for an obstacle motion whose quaternion vanishes. No pair at all (no geometry, or one
// body and no obstacle) is no contact.
Scene_report check_robot(const Robot_model &r, const double *q0, const double *q1,
                         const std::vector<Scene_body> &obstacles, const Scene_options &opt,
                         const Robot_options &ro);

}  // namespace pccd::scene
