// The broad-phase choice: which candidate source (narrow/candidate_source.h) feeds the
// driver. Speed only: every broad phase gives the same answers.
#pragma once
#include <memory>

#include "narrow/candidate_source.h"

namespace pccd::scene {

// The values of pccd_broad_phase (polyccd.h; checked in lib/api/constants.cpp).
enum class Broad_phase { boxes = 0, brute = 1, range = 2, automatic = 3, bvh = 4 };

// The default (automatic) is chosen per body pair (choose, below). With a minimum
// separation delta > 0 (pred::Solve_options) it is bvh, online too: boxes and bvh grow
// one side's bounds by delta (enclose/enclose.h, reach_of); the range phase's linearized
// contact conditions have no delta (its halfspaces would need the distance conditions
// of pred/delta_systems.h), so the api refuses range with delta > 0 (api/config.cpp),
// and an index query takes the stored body's hierarchy (kept with the body like the
// trees, thread-safe).

// What can be resolved before the bodies are known (api/config.cpp, the one caller):
// with a minimum separation automatic is bvh; otherwise it stays automatic, for choose()
// per body pair (online or not: an index's stored body is one side of every pair).
inline Broad_phase resolve(Broad_phase p, bool /*online*/, bool min_distance) {
  if (p != Broad_phase::automatic) return p;
  return min_distance ? Broad_phase::bvh : Broad_phase::automatic;
}

// The automatic phase of one body pair: p itself unless it is automatic; bvh with a
// minimum separation (range has no delta); otherwise the phase of the lower estimated
// cost, range or bvh (scene/auto_cost.h: the rule, its cost model and where its
// constants were measured). Speed only: every phase gives the same answers.
Broad_phase choose(Broad_phase p, const narrow::Pair_ctx &ctx, bool min_distance);

// The source of a resolved phase. stored: the range phase's stored side (-1: the
// larger). reach: enclose::reach_of of the minimum separation (0: none); range is
// only chosen with 0 (api/config.cpp).
std::unique_ptr<narrow::Candidate_source> make_source(Broad_phase p, const narrow::Pair_ctx &ctx,
                                                      int stored, double reach = 0);

}  // namespace pccd::scene
