// One call's options, read once at its entry point: its pccd_config (NULL: defaults)
// and its option struct (pccd_batch_options, pccd_scene_options) become one Call_config
// that is passed down. Every rule about options is decided here, once (config.cpp):
// the struct sizes, the time tolerance, the minimum distance (whether one is set:
// pred::Solve_options::min_distance), the limits (api/limits.h), 1..PCCD_MAX_THREADS
// threads, and the broad phase after `auto` (range refuses a minimum distance).
// Input_error names the bad field.
#pragma once
#include <string>

#include "api/limits.h"
#include "polyccd.h"
#include "pred/solve.h"
#include "scene/scene.h"

namespace pccd::api {

struct Call_config {
  // The solve options. They live in this thread's cache of parsed configs (callers
  // pass the same config call after call, so each number text is parsed once and a
  // linear query copies no rational): valid until this thread reads another config.
  const pred::Solve_options *solve = nullptr;
  Call_limits limits;
  unsigned threads = 1;
  bool all_contacts = false;
  // Resolved (never automatic) by read_scene_call; boxes for the other calls.
  scene::Broad_phase broad_phase = scene::Broad_phase::boxes;

  // The scene layer's options of this call (scene/scene.h).
  scene::Scene_options scene_options() const;
};

// pccd_query_solve, pccd_solve_linear_d: the config alone.
Call_config read_call(const pccd_config *cfg);
// pccd_solve_linear_batch_d (opt NULL: defaults).
Call_config read_batch_call(const pccd_config *cfg, const pccd_batch_options *opt);
// pccd_scene_solve, pccd_pair_solve (online false) and pccd_index_query[_many]
// (online true) (opt NULL: defaults).
Call_config read_scene_call(const pccd_config *cfg, const pccd_scene_options *opt, bool online);

// n when 1 <= n <= PCCD_MAX_THREADS, else Input_error "<where>: n is outside 1..1024".
unsigned checked_threads(unsigned n, const std::string &where);

}  // namespace pccd::api
