// The automatic broad phase by estimated cost (issue 31): the one place where "auto" is
// decided for a body pair without a minimum separation (broad_phase.h, choose).
//
// Both candidate sources give the same answers; their costs differ. With Q the pair's
// side of fewer elements (triangles or balls; the range phase stores the other, S):
//   range: a call's cost plus one per query primitive (Q's surface vertices, triangles and
//          edges, or balls) and time piece (relative motion, clauses and tree searches,
//          range/range_index.h), with the piece count the range phase takes (the path of
//          Q's box corners in S's frame at 17 times, in feature sizes: Range_index); two
//          meshes have constants of their own (the static pass at t = 0, three trees);
//   bvh:   kBvh_call + kPair per element pair whose boxes meet on a piece (each piece's
//          pairs are candidates the driver checks, bvh/bvh_source.h): the pairs are
//          estimated by taking at most kSamples elements of Q at a fixed stride and
//          counting, on each of the same pieces, S's elements whose body-frame box meets
//          the sample's box over the piece (float poses at the piece's ends, S's box
//          hierarchy, bvh/hierarchy.h), scaled by |Q| / samples and by bvh's extra
//          halvings (its certified spread over the feature size, per piece); the count
//          stops once it makes bvh the dearer (at most kCap).
// auto takes range when its estimate is lower, bvh otherwise. The constants are CPU
// seconds measured on the on-line families (tests/bench/bench_adversarial.py: terrain,
// molecules, translated needles, nested shells, turned blades; docs/benchmarks-broad.md, "auto
// by estimated cost"); only their ratios matter, and an estimate off by 2x moves the
// choice only where the two phases cost about the same. The estimate costs
// O(kSamples pieces + kCap log n) float operations. Floats and samples: it decides a speed,
// never an answer.
#pragma once
#include "narrow/pair_ctx.h"

namespace pccd::scene {

struct Auto_costs {
  double bvh = 0, range = 0;  // estimated seconds
  double pairs = 0;           // estimated element pairs whose boxes meet (bvh candidates)
  int pieces = 1;             // the range phase's time pieces
};

Auto_costs estimate_costs(const narrow::Pair_ctx &ctx);

}  // namespace pccd::scene
