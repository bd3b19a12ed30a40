// The range candidate source (PCCD_BROAD_RANGE, paper section 3): the stored side's
// primitives as lifted points in range trees, queried per time piece with the
// linearized contact conditions of each primitive of the other side (range_index.h).
// Pieces are the index's equal pieces, in time order, each skipped once the sink prunes
// its start.
#pragma once
#include <memory>

#include "narrow/candidate_source.h"

namespace pccd::range {

// stored: the side (0 or 1) whose primitives are held in the trees; -1: the side with
// more elements (triangles or balls), side 0 on a tie.
std::unique_ptr<narrow::Candidate_source> range_source(const narrow::Pair_ctx &ctx, int stored);

}  // namespace pccd::range
