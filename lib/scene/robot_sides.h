// The filter's sides of a robot check's bodies (link_filter.h, Filter_side): body k
// (the robot's bodies, then the obstacles) relative to a pair's base, the links' lowest
// common ancestor for a self pair (the motion of the joints above it moves both alike
// and drops out; -1 against an obstacle), with its poses from the check's Piece_poses.
// A body of the base's own link stands still in that frame (the identity pose).
#pragma once
#include <cstdint>
#include <vector>

#include "bvh/hierarchy.h"
#include "scene/robot.h"  // before piece_poses.h: it names scene.h's Moving_body
#include "scene/link_filter.h"
#include "scene/piece_poses.h"

namespace pccd::scene {

class Robot_sides {
 public:
  // share: the check's key of its poses (Filter_side::share: first_uncleared keeps a
  // link's boxes on a piece for its next pair; shared_memo.h), never 0.
  Robot_sides(const Robot_model &r, const std::vector<Moving_body> &obst, Piece_poses &poses, uint64_t share)
      : r_(r), obst_(obst), poses_(poses), share_(share), trees_(r.bodies.size() + obst.size(), nullptr) {}

  Filter_side operator()(size_t k, long base);

 private:
  const Robot_model &r_;
  const std::vector<Moving_body> &obst_;
  Piece_poses &poses_;
  uint64_t share_;
  // Each body's hierarchy, looked up once per check (bvh::hierarchy takes a lock).
  std::vector<const bvh::Hierarchy *> trees_;
};

}  // namespace pccd::scene
