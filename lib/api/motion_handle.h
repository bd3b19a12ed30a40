// The opaque pccd_motion handle behind polyccd.h: one exact rigid motion.
#pragma once
#include "motion/rigid_motion.h"

struct pccd_motion {
  pccd::motion::Rigid_motion m;  // starts as the identity (stationary) motion
};
