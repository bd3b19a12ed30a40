// The opaque pccd_chain handle behind polyccd.h (pccd_chain_* and pccd_robot_new).
#pragma once
#include "motion/chain.h"

struct pccd_chain {
  pccd::motion::Chain c;
};
