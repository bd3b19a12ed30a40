// pccd_index_*: the on-line collision problem (broad/online_index.h).
#include "api/body_handle.h"
#include "api/guard.h"
#include "api/handles.h"
#include "api/motion_handle.h"
#include "api/scene_handle.h"

using pccd::api::guard;
using pccd::api::require;

namespace {

pccd::broad::Scene_body scene_body(const pccd_body *body, const pccd_motion *motion) {
  pccd::broad::Scene_body b;
  b.body = body->data;
  if (motion) b.motion = motion->m;
  return b;
}

}  // namespace

extern "C" {

PCCD_API int pccd_index_new(pccd_index **out, const pccd_body *body, const pccd_motion *motion) {
  return guard("pccd_index_new", [&] {
    require(out, "out");
    *out = nullptr;
    require(body, "body");
    auto ix = std::make_unique<pccd_index>();
    ix->ix = std::make_unique<const pccd::broad::Online_index>(scene_body(body, motion));
    *out = ix.release();
    return PCCD_OK;
  });
}

PCCD_API void pccd_index_free(pccd_index *ix) { delete ix; }

PCCD_API int pccd_index_query(const pccd_index *ix, const pccd_body *body,
                              const pccd_motion *motion, const pccd_config *cfg,
                              const pccd_scene_options *opt, pccd_report *rep) {
  return guard("pccd_index_query", [&] {
    require(ix, "index");
    require(body, "body");
    require(rep, "report");
    const pccd::broad::Scene_options so = pccd::api::read_scene_options(cfg, opt);
    rep->solved = false;
    rep->r = ix->ix->query(scene_body(body, motion), so);
    rep->solved = true;
    return PCCD_OK;
  });
}

}  // extern "C"
