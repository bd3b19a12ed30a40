// pccd_index_*: the on-line collision problem (scene/online_index.h).
#include <string>
#include <vector>

#include "api/body_handle.h"
#include "api/config.h"
#include "api/guard.h"
#include "api/handles.h"
#include "api/motion_handle.h"
#include "api/scene_handle.h"

using pccd::api::guard;
using pccd::api::require;

using pccd::api::biggest_of;
using pccd::api::scene_body;

namespace {

// The index of body on motion within the limits of cfg; `unlimited`: no limits at all
// (pccd_index_new, which took no config: any input it accepted, it still accepts).
int new_index(const char *fn, pccd_index **out, const pccd_body *body, const pccd_motion *motion,
              const pccd_config *cfg, bool unlimited) {
  return guard(fn, [&] {
    require(out, "out");
    *out = nullptr;
    require(body, "body");
    pccd::api::Call_limits limits = pccd::api::read_call(cfg).limits;  // all its rules checked
    if (unlimited) limits.max_number_bits = 0;
    auto ix = std::make_unique<pccd_index>();
    ix->biggest = biggest_of(body, motion);
    limits.check(ix->biggest);
    const pccd::api::Call_budget budget(limits.work);
    ix->ix = std::make_unique<const pccd::scene::Online_index>(scene_body(body, motion));
    *out = ix.release();
    return PCCD_OK;
  });
}

}  // namespace

extern "C" {

PCCD_API int pccd_index_new_cfg(pccd_index **out, const pccd_body *body, const pccd_motion *motion,
                               const pccd_config *cfg) {
  return new_index(__func__, out, body, motion, cfg, false);
}

PCCD_API int pccd_index_new(pccd_index **out, const pccd_body *body, const pccd_motion *motion) {
  return new_index(__func__, out, body, motion, nullptr, true);
}

PCCD_API void pccd_index_free(pccd_index *ix) { delete ix; }

PCCD_API int pccd_index_query(const pccd_index *ix, const pccd_body *body,
                              const pccd_motion *motion, const pccd_config *cfg,
                              const pccd_scene_options *opt, pccd_report *rep) {
  return guard(__func__, [&] {
    require(ix, "ix");
    require(body, "body");
    require(rep, "rep");
    rep->solved = false;  // a failed call leaves no earlier answer readable
    const pccd::api::Call_config call = pccd::api::read_scene_call(cfg, opt, true);
    const pccd::scene::Scene_options so = call.scene_options();
    const pccd::api::Call_limits &limits = call.limits;
    limits.check(ix->biggest, "ix: the stored body's ");
    limits.check(body->biggest, "body.");
    if (motion) limits.check(*pccd::api::motion_biggest(motion), "motion.");
    const pccd::api::Call_budget budget(limits.work);
    rep->r = ix->ix->query(scene_body(body, motion), so);
    rep->solved = true;
    return PCCD_OK;
  });
}

PCCD_API int pccd_index_query_many(const pccd_index *ix, const pccd_body *const *bodies,
                                   const pccd_motion *const *motions, size_t n,
                                   const pccd_config *cfg, const pccd_scene_options *opt,
                                   pccd_report *const *reports) {
  return guard(__func__, [&] {
    require(ix, "ix");
    if (n == 0) return PCCD_OK;
    require(bodies, "bodies");
    require(reports, "reports");
    for (size_t k = 0; k < n; ++k)
      require(reports[k], pccd::api::place("reports", {k}));
    for (size_t k = 0; k < n; ++k) reports[k]->solved = false;  // no earlier answer readable
    const pccd::api::Call_config call = pccd::api::read_scene_call(cfg, opt, true);
    const pccd::scene::Scene_options so = call.scene_options();
    const pccd::api::Call_limits &limits = call.limits;
    limits.check(ix->biggest, "ix: the stored body's ");
    std::vector<pccd::scene::Scene_body> qs(n);
    for (size_t k = 0; k < n; ++k) {
      require(bodies[k], pccd::api::place("bodies", {k}));
      limits.check(biggest_of(bodies[k], motions ? motions[k] : nullptr),
                   pccd::api::place("bodies", {k}) + ".");
      qs[k] = scene_body(bodies[k], motions ? motions[k] : nullptr);
    }
    const pccd::api::Call_budget budget(limits.work);
    std::vector<pccd::scene::Scene_report> out;
    ix->ix->query_many(qs, so, out);
    for (size_t k = 0; k < n; ++k) {
      reports[k]->r = std::move(out[k]);
      reports[k]->solved = true;
    }
    return PCCD_OK;
  });
}

}  // extern "C"
