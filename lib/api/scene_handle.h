// The opaque pccd_scene and pccd_report handles behind polyccd.h.
#pragma once
#include <vector>

#include "broad/scene.h"

struct pccd_scene {
  std::vector<pccd::broad::Scene_body> bodies;  // shared bodies, copied motions
};

struct pccd_report {
  bool solved = false;
  pccd::broad::Scene_report r;
};
