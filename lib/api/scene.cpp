// pccd_scene_*: scenes of bodies on motions, solved into a pccd_report.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "api/body_handle.h"
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
  return guard(__func__, [&] {
    require(s, "s");
    require(count, "count");
    *count = s->bodies.size();
    return PCCD_OK;
  });
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
    const pccd::scene::Scene_options so = pccd::api::read_scene_options(cfg, opt);
    const pccd::api::Call_limits limits = pccd::api::read_limits(cfg);
    if (limits.max_number_bits) {  // named as the scene's two bodies, as the solve names
      limits.check(pccd::api::biggest_of(a, ma), "bodies[0].");  // a motion's error
      limits.check(pccd::api::biggest_of(b, mb), "bodies[1].");
    }
    const pccd::api::Call_budget budget(limits.work);
    std::vector<pccd::scene::Scene_body> bodies{pccd::api::scene_body(a, ma), pccd::api::scene_body(b, mb)};
    rep->r = pccd::scene::solve_scene(bodies, so);
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
    const pccd::scene::Scene_options so = pccd::api::read_scene_options(cfg, opt);
    const pccd::api::Call_limits limits = pccd::api::read_limits(cfg);
    for (size_t k = 0; k < s->biggest.size(); ++k)
      limits.check(s->biggest[k], pccd::api::place("bodies", {k}) + ".");
    const pccd::api::Call_budget budget(limits.work);
    rep->r = pccd::scene::solve_scene(s->bodies, so, s->skipped);
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

scene::Scene_options read_scene_options(const pccd_config *cfg, const pccd_scene_options *opt) {
  scene::Scene_options so;
  so.solve = read_config(cfg);

  if (!opt) return so;
  if (opt->struct_size != sizeof(pccd_scene_options))
    throw Input_error("opt.struct_size: " + std::to_string(opt->struct_size) +
                      " is not sizeof(pccd_scene_options) (initialise with pccd_scene_options_init)");
  if (opt->threads < 1 || opt->threads > 1024)
    throw Input_error("opt.threads: " + std::to_string(opt->threads) + " is outside 1..1024");
  if (opt->all_contacts != 0 && opt->all_contacts != 1)
    throw Input_error("opt.all_contacts: " + std::to_string(opt->all_contacts) + " is not 0 or 1");
  if (opt->broad_phase < PCCD_BROAD_BOXES || opt->broad_phase > PCCD_BROAD_BVH)
    throw Input_error("opt.broad_phase: " + std::to_string(opt->broad_phase) +
                      " is not PCCD_BROAD_BOXES (0), PCCD_BROAD_BRUTE (1), PCCD_BROAD_RANGE (2), "
                      "PCCD_BROAD_AUTO (3) or PCCD_BROAD_BVH (4)");
  so.threads = opt->threads;
  so.all_contacts = opt->all_contacts == 1;
  so.broad_phase = static_cast<scene::Broad_phase>(opt->broad_phase);  // constants.cpp
  // With a minimum distance the range phase has no delta (its linearized contact
  // conditions would need the distance systems; scene/broad_phase.h); auto takes bvh.
  if (sgn(so.solve.delta) > 0 && so.broad_phase == scene::Broad_phase::range)
    throw Input_error("opt.broad_phase: " + std::to_string(opt->broad_phase) +
                      " (PCCD_BROAD_RANGE) does not take config.min_distance > 0; use "
                      "PCCD_BROAD_AUTO, PCCD_BROAD_BVH, PCCD_BROAD_BOXES or PCCD_BROAD_BRUTE");
  return so;
}

}  // namespace pccd::api
