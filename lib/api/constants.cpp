// The inner layers keep their own copies of the public constants (they do not include
// polyccd.h); this file checks at compile time that every copy equals the public value,
// so the C API can pass values through unchanged.
#include "polyccd.h"
#include "motion/body.h"
#include "narrow/pair_ctx.h"
#include "pred/features.h"
#include "pred/solve.h"
#include "scene/broad_phase.h"

namespace pccd::api {

static_assert(arith::kMax_number_chars == PCCD_MAX_NUMBER_CHARS, "number text limit");
static_assert(arith::kMax_exponent == PCCD_MAX_EXPONENT, "exponent limit");
static_assert(motion::kMax_body_elements == PCCD_MAX_BODY_ELEMENTS, "body size limit");

static_assert(int(pred::VERTEX_FACE) == int(PCCD_VERTEX_FACE) && int(pred::EDGE_EDGE) == int(PCCD_EDGE_EDGE) &&
                  int(pred::VERTEX_EDGE) == int(PCCD_VERTEX_EDGE) && int(pred::VERTEX_VERTEX) == int(PCCD_VERTEX_VERTEX) &&
                  int(pred::SPHERE_SPHERE) == int(PCCD_SPHERE_SPHERE),
              "pccd_kind");

static_assert(int(pred::STAGE_NONE) == int(PCCD_STAGE_NONE) && int(pred::STAGE_BOUNDS) == int(PCCD_STAGE_BOUNDS) &&
                  int(pred::STAGE_BERNSTEIN) == int(PCCD_STAGE_BERNSTEIN) &&
                  int(pred::STAGE_INTERVAL) == int(PCCD_STAGE_INTERVAL) && int(pred::STAGE_EXACT) == int(PCCD_STAGE_EXACT),
              "pccd_stage");

static_assert(int(narrow::F_VERTEX) == int(PCCD_FEATURE_VERTEX) && int(narrow::F_EDGE) == int(PCCD_FEATURE_EDGE) &&
                  int(narrow::F_TRIANGLE) == int(PCCD_FEATURE_TRIANGLE) && int(narrow::F_SPHERE) == int(PCCD_FEATURE_SPHERE) &&
                  int(narrow::F_SOLID) == int(PCCD_FEATURE_SOLID),
              "pccd_feature");

static_assert(int(scene::Broad_phase::boxes) == PCCD_BROAD_BOXES &&
                  int(scene::Broad_phase::brute) == PCCD_BROAD_BRUTE &&
                  int(scene::Broad_phase::range) == PCCD_BROAD_RANGE &&
                  int(scene::Broad_phase::automatic) == PCCD_BROAD_AUTO &&
                  int(scene::Broad_phase::bvh) == PCCD_BROAD_BVH,
              "pccd_broad_phase");

}  // namespace pccd::api
