// The broad-phase choice: which candidate source (narrow/candidate_source.h) feeds the
// driver. Speed only: every broad phase gives the same answers.
#pragma once
#include <memory>

#include "narrow/candidate_source.h"

namespace pccd::scene {

// The values of pccd_broad_phase (polyccd.h; checked in lib/api/constants.cpp).
enum class Broad_phase { boxes = 0, brute = 1, range = 2, automatic = 3, bvh = 4 };

// The default (automatic), chosen by measurement (docs/design.md, "Broad phases";
// tests/bench/bench_bvh.py, tests/bench/bench_online.py). online: the pair comes from an
// on-line index (the stored side's trees exist already and are shared by every query):
// range; otherwise a scene's body pair: bvh (the hierarchies are built with the bodies).
// min_distance: the solve has a minimum separation delta > 0 (pred::Solve_options):
// bvh, online too. Boxes and bvh grow one side's bounds by delta (enclose/enclose.h,
// reach_of); the range phase's linearized contact conditions have no delta (its
// halfspaces would need the distance conditions of pred/delta_systems.h), so the api
// refuses range with delta > 0 (api/config.cpp, the one caller), and an index query takes the stored body's hierarchy
// (kept with the body like the trees, thread-safe) rather than brute force.
inline Broad_phase resolve(Broad_phase p, bool online, bool min_distance) {
  if (p != Broad_phase::automatic) return p;
  return online && !min_distance ? Broad_phase::range : Broad_phase::bvh;
}

// The source of a resolved phase. stored: the range phase's stored side (-1: the
// larger). reach: enclose::reach_of of the minimum separation (0: none); range is
// only chosen with 0 (api/config.cpp).
std::unique_ptr<narrow::Candidate_source> make_source(Broad_phase p, const narrow::Pair_ctx &ctx,
                                                      int stored, double reach = 0);

}  // namespace pccd::scene
