// The opaque pccd_body handle behind polyccd.h: one immutable rigid body, a mesh or a
// set of balls (exactly one of the two is set).
#pragma once
#include <memory>

#include "motion/body.h"

struct pccd_body {
  std::unique_ptr<pccd::motion::Mesh_body> mesh;      // set for PCCD_BODY_MESH
  std::unique_ptr<pccd::motion::Sphere_body> spheres;  // set for PCCD_BODY_SPHERES
};
