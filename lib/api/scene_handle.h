// The opaque pccd_scene, pccd_index and pccd_report handles behind polyccd.h.
#pragma once
#include <memory>
#include <vector>

#include "scene/online_index.h"
#include "scene/scene.h"
#include "polyccd.h"
#include "api/limits.h"

struct pccd_scene {
  std::vector<pccd::scene::Scene_body> bodies;  // shared bodies, copied motions
  std::vector<pccd::api::Biggest_number> biggest;  // of body k and its motion: "vertices[..]"
  pccd::scene::Pair_set skipped;                // pairs (i, j), i < j, not checked
};

struct pccd_index {
  std::unique_ptr<const pccd::scene::Online_index> ix;
  pccd::api::Biggest_number biggest;  // of the stored body and its motion
};

struct pccd_report {
  bool solved = false;
  pccd::scene::Scene_report r;
};

namespace pccd::api {

// The scene body of a body handle on a motion handle (NULL: stationary), with the
// motion's kept data (api/motion_handle.h).
scene::Scene_body scene_body(const pccd_body *body, const pccd_motion *motion);
// The largest number of a body and its motion (config.max_number_bits), placed as
// "vertices[1][2]" or "motion.rotation[0][1]"; kept by both, so no scan per call.
Biggest_number biggest_of(const pccd_body *body, const pccd_motion *motion);

}  // namespace pccd::api
