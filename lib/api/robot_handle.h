// The pccd_robot handle and the reading of a robot call's arguments, shared by the
// one-segment check (robot.cpp) and the batches (robot_many.cpp), so that every rule
// about those arguments is decided in one place.
#pragma once
#include <vector>

#include "api/config.h"
#include "api/limits.h"
#include "polyccd.h"
#include "scene/robot.h"

struct pccd_robot {
  pccd::scene::Robot_model m;
  std::vector<pccd::api::Biggest_number> biggest;  // of each body
};

namespace pccd::api {

// A robot call's validated arguments but the joint values: the options (ropt.struct_size
// and its 0/1 fields, cfg and opt as read_scene_call), the bodies' and obstacles'
// number sizes against config.max_number_bits, and the obstacles as scene bodies.
// Input_error / Limit_error name the bad argument ("obstacles[2]: is NULL").
struct Robot_call {
  Call_config call;
  scene::Robot_options ro;
  std::vector<scene::Scene_body> obstacles;
};
Robot_call read_robot_call(const pccd_robot &r, const pccd_body *const *obstacles,
                           const pccd_motion *const *motions, size_t n_obstacles,
                           const pccd_config *cfg, const pccd_scene_options *opt,
                           const pccd_robot_options *ropt);

// ro with its check_link hook holding the link motions to the call's max_number_bits
// ("links[k].motion." ...): the hook refers to `limits`, which must outlive ro's use.
scene::Robot_options with_link_check(scene::Robot_options ro, const Call_limits &limits);

// Input_error unless n is the chain's link count ("n: 6 joint values given, ...").
void check_value_count(const pccd_robot &r, size_t n);

}  // namespace pccd::api
