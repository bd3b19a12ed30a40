// pccd_scene_*: scenes of bodies on motions, solved into a pccd_report.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "api/body_handle.h"
#include "api/config.h"
#include "api/guard.h"
#include "api/handles.h"
#include "api/motion_handle.h"
#include "api/scene_handle.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::arith::Input_error;

extern "C" {

PCCD_API int pccd_scene_new(pccd_scene **out) { return pccd::api::new_handle(__func__, out); }

PCCD_API void pccd_scene_free(pccd_scene *s) { delete s; }

PCCD_API int pccd_scene_add(pccd_scene *s, const pccd_body *body, const pccd_motion *motion,
                            size_t *index) {
  return guard(__func__, [&] {
    require(s, "s");
    require(body, "body");
    pccd::api::Biggest_number big = pccd::api::biggest_of(body, motion);
    s->biggest.reserve(s->bodies.size() + 1);
    s->bodies.push_back(pccd::api::scene_body(body, motion));
    s->biggest.push_back(std::move(big));
    if (index) *index = s->bodies.size() - 1;
    return PCCD_OK;
  });
}

PCCD_API int pccd_scene_body_count(const pccd_scene *s, size_t *count) {
  return pccd::api::getter(__func__, s, "s", count, "count",
                                [&] { return s->bodies.size(); });
}

PCCD_API int pccd_scene_set_pair_check(pccd_scene *s, size_t i, size_t j, int check) {
  return guard(__func__, [&] {
    require(s, "s");
    const size_t n = s->bodies.size();
    for (auto [x, name] : {std::make_pair(i, "i"), std::make_pair(j, "j")})
      if (x >= n)
        throw Input_error(std::string(name) + ": " + std::to_string(x) + " out of range (" +
                          std::to_string(n) + " bodies)");
    if (i == j) throw Input_error("j: " + std::to_string(j) + " equals i (a body is not paired with itself)");
    if (check != 0 && check != 1)
      throw Input_error("check: " + std::to_string(check) + " is not 0 (skip) or 1 (check)");
    const std::pair<size_t, size_t> key{std::min(i, j), std::max(i, j)};
    if (check) s->skipped.erase(key); else s->skipped.insert(key);
    return PCCD_OK;
  });
}

PCCD_API int pccd_scene_options_init(pccd_scene_options *opt) {
  return guard(__func__, [&] {
    require(opt, "opt");
    opt->struct_size = sizeof(pccd_scene_options);
    opt->threads = 1;
    opt->all_contacts = 0;
    opt->broad_phase = PCCD_BROAD_AUTO;
    return PCCD_OK;
  });
}

PCCD_API int pccd_pair_solve(const pccd_body *a, const pccd_motion *ma, const pccd_body *b,
                             const pccd_motion *mb, const pccd_config *cfg,
                             const pccd_scene_options *opt, pccd_report *rep) {
  return guard(__func__, [&] {
    require(a, "a");
    require(b, "b");
    require(rep, "rep");
    rep->solved = false;
    const pccd::api::Call_config call = pccd::api::read_scene_call(cfg, opt, false);
    const pccd::api::Call_limits &limits = call.limits;
    if (limits.max_number_bits) {  // named as the scene's two bodies, as the solve names
      limits.check(pccd::api::biggest_of(a, ma), "bodies[0].");  // a motion's error
      limits.check(pccd::api::biggest_of(b, mb), "bodies[1].");
    }
    const pccd::api::Call_budget budget(limits.work);
    std::vector<pccd::scene::Scene_body> bodies{pccd::api::scene_body(a, ma), pccd::api::scene_body(b, mb)};
    rep->r = pccd::scene::solve_scene(bodies, call.scene_options());
    rep->solved = true;
    return PCCD_OK;
  });
}

PCCD_API int pccd_scene_solve(const pccd_scene *s, const pccd_config *cfg,
                              const pccd_scene_options *opt, pccd_report *rep) {
  return guard(__func__, [&] {
    require(s, "s");
    require(rep, "rep");
    rep->solved = false;  // a failed call leaves no earlier answer readable
    const pccd::api::Call_config call = pccd::api::read_scene_call(cfg, opt, false);
    const pccd::api::Call_limits &limits = call.limits;
    for (size_t k = 0; k < s->biggest.size(); ++k)
      limits.check(s->biggest[k], pccd::api::place("bodies", {k}) + ".");
    const pccd::api::Call_budget budget(limits.work);
    rep->r = pccd::scene::solve_scene(s->bodies, call.scene_options(), s->skipped);
    rep->solved = true;
    return PCCD_OK;
  });
}

}  // extern "C"

namespace pccd::api {

Biggest_number biggest_of(const pccd_body *body, const pccd_motion *motion) {
  Biggest_number big;
  big.see(body->biggest, "");
  if (motion) big.see(*motion_biggest(motion), "motion.");
  return big;
}

scene::Scene_body scene_body(const pccd_body *body, const pccd_motion *motion) {
  scene::Scene_body b;
  b.body = body->data;
  b.prepared = motion_data(motion);
  if (motion && !b.prepared) b.motion = motion->m;  // invalid: the solve reports it
  return b;
}

}  // namespace pccd::api
