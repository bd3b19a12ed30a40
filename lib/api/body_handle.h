// The opaque pccd_body handle behind polyccd.h: one immutable rigid body, a mesh or a
// set of balls (exactly one of the two is set). Shared, so scenes keep bodies alive
// after pccd_body_free.
#pragma once
#include <memory>

#include "narrow/moving_body.h"
#include "motion/body.h"
#include "api/limits.h"

struct pccd_body {
  std::shared_ptr<const pccd::motion::Mesh_body> mesh;      // set for PCCD_BODY_MESH
  std::shared_ptr<const pccd::motion::Sphere_body> spheres;  // set for PCCD_BODY_SPHERES
  std::shared_ptr<const pccd::narrow::Body_data> data;        // derived once, for scenes
  pccd::api::Biggest_number biggest;  // its largest number, for config.max_number_bits
};
