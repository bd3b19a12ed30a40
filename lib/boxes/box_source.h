// The box candidate source (PCCD_BROAD_BOXES): time pieces and CGAL box intersection.
//
// [0, 1] is split recursively into dyadic pieces. On each piece every element
// (triangle or ball) gets a conservative box (enclose/enclose.h); elements whose box misses the
// other body's active elements' hull are dropped for that piece and its sub-pieces.
// When the motion's spread over a piece is at most the bodies' typical feature size (or
// the piece is small, or few element pairs are left), CGAL's box_intersection_d pairs
// the boxes of vertices, edges, triangles and balls: those pairs are the piece's
// candidates. A pair whose boxes never meet on any piece has no contact. Pieces are
// visited depth first, earlier half first, so in time order; a piece whose start the
// sink prunes is skipped.
//
// Minimum separation: reach (enclose/enclose.h, reach_of: a double >= delta, 0 without one) grows
// side A's boxes (its points, edges, triangles, balls and their hulls), so every feature
// pair within delta at some t of a piece has meeting boxes there (the coverage argument
// of reach_of), and the rest of the argument above is unchanged. The body box of B
// that filters A's elements is compared with A's grown boxes too.
#pragma once
#include <memory>

#include "narrow/candidate_source.h"

namespace pccd::boxes {

std::unique_ptr<narrow::Candidate_source> box_source(const narrow::Pair_ctx &ctx, double reach = 0);

}  // namespace pccd::boxes
