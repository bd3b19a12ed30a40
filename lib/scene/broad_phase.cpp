// make_source (broad_phase.h): the candidate source of a resolved broad phase.
#include "scene/broad_phase.h"

#include "boxes/box_source.h"
#include "bvh/bvh_source.h"
#include "range/range_source.h"

namespace pccd::scene {

using narrow::Pair_ctx;

std::unique_ptr<narrow::Candidate_source> make_source(Broad_phase p, const Pair_ctx &ctx, int stored,
                                                      double reach) {
  switch (p) {
    case Broad_phase::brute: return narrow::brute_source(ctx);
    case Broad_phase::range: return range::range_source(ctx, stored);  // reach 0: api/config.cpp
    case Broad_phase::boxes: return boxes::box_source(ctx, reach);
    case Broad_phase::bvh: return bvh::bvh_source(ctx, reach);
    case Broad_phase::automatic: break;
  }
  throw arith::Internal_error("make_source: the broad phase is not resolved");
}

}  // namespace pccd::scene
