// pccd_robot_*: a chain with bodies on its links, kept across segments, checked over a
// segment against obstacles and itself (lib/scene/robot.h). Validates and converts the C
// inputs, calls lib/scene, maps errors; no algorithm here.
#include <algorithm>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "api/body_handle.h"
#include "api/chain_handle.h"
#include "api/config.h"
#include "api/guard.h"
#include "api/handles.h"
#include "api/motion_handle.h"
#include "api/robot_handle.h"
#include "api/scene_handle.h"
#include "scene/robot.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::api::place;
using pccd::arith::Input_error;

namespace pccd::api {

void check_value_count(const pccd_robot &r, size_t n) {
  if (n != r.m.chain.size())
    throw Input_error("n: " + std::to_string(n) + " joint values given, the chain has " +
                      std::to_string(r.m.chain.size()) + " links");
}

Robot_call read_robot_call(const pccd_robot &r, const pccd_body *const *obstacles,
                           const pccd_motion *const *motions, size_t n_obstacles,
                           const pccd_config *cfg, const pccd_scene_options *opt,
                           const pccd_robot_options *ropt) {
  if (n_obstacles > 0) require(obstacles, "obstacles");
  Robot_call out;
  if (ropt) {
    if (ropt->struct_size != sizeof(pccd_robot_options))
      throw Input_error("ropt.struct_size: " + std::to_string(ropt->struct_size) +
                        " is not sizeof(pccd_robot_options) (initialise with pccd_robot_options_init)");
    if (ropt->self_collision != 0 && ropt->self_collision != 1)
      throw Input_error("ropt.self_collision: " + std::to_string(ropt->self_collision) + " is not 0 or 1");
    if (ropt->filter != 0 && ropt->filter != 1)
      throw Input_error("ropt.filter: " + std::to_string(ropt->filter) + " is not 0 or 1");
    out.ro.self_collision = ropt->self_collision == 1;
    out.ro.filter = ropt->filter == 1;
  }
  out.call = read_scene_call(cfg, opt, false);
  const Call_limits &limits = out.call.limits;
  for (size_t k = 0; k < r.biggest.size(); ++k) limits.check(r.biggest[k], place("bodies", {k}) + ".");
  for (size_t k = 0; k < n_obstacles; ++k) {
    const std::string where = place("obstacles", {k});
    require(obstacles[k], where);
    const pccd_motion *m = motions ? motions[k] : nullptr;
    limits.check(biggest_of(obstacles[k], m), where + ".");
    out.obstacles.push_back(scene_body(obstacles[k], m));
  }
  return out;
}

scene::Robot_options with_link_check(scene::Robot_options ro, const Call_limits &limits) {
  if (limits.max_number_bits)  // the link motions, built on demand (scene/robot.h)
    ro.check_link = [&limits](size_t k, const motion::Rigid_motion &m) {
      limits.check(biggest_in(m), place("links", {k}) + ".motion.");
    };
  return ro;
}

}  // namespace pccd::api

extern "C" {

PCCD_API int pccd_robot_new(pccd_robot **out, const pccd_chain *chain) {
  return guard(__func__, [&] {
    require(out, "out");
    *out = nullptr;
    require(chain, "chain");
    auto r = std::make_unique<pccd_robot>();
    r->m.chain = chain->c;
    *out = r.release();
    return PCCD_OK;
  });
}

PCCD_API void pccd_robot_free(pccd_robot *r) { delete r; }

PCCD_API int pccd_robot_add_body(pccd_robot *r, size_t link, size_t group, const pccd_body *body,
                                 size_t *index) {
  return guard(__func__, [&] {
    require(r, "r");
    require(body, "body");
    if (link >= r->m.chain.size())
      throw Input_error("link: " + std::to_string(link) + " out of range (" +
                        std::to_string(r->m.chain.size()) + " chain links)");
    r->biggest.reserve(r->biggest.size() + 1);
    r->m.bodies.push_back({link, group, body->data});
    r->biggest.push_back(body->biggest);
    if (index) *index = r->m.bodies.size() - 1;
    return PCCD_OK;
  });
}

PCCD_API int pccd_robot_set_allowed(pccd_robot *r, const size_t *groups, size_t n) {
  return guard(__func__, [&] {
    require(r, "r");
    if (n > 0) require(groups, "groups");
    std::set<std::pair<size_t, size_t>> allowed;
    for (size_t k = 0; k < n; ++k) {
      const size_t g = groups[2 * k], h = groups[2 * k + 1];
      allowed.insert({std::min(g, h), std::max(g, h)});
    }
    r->m.allowed = std::move(allowed);
    return PCCD_OK;
  });
}

PCCD_API int pccd_robot_options_init(pccd_robot_options *opt) {
  return guard(__func__, [&] {
    require(opt, "opt");
    opt->struct_size = sizeof(pccd_robot_options);
    opt->self_collision = 1;
    opt->filter = 1;
    return PCCD_OK;
  });
}

PCCD_API int pccd_robot_check(const pccd_robot *r, const double *q0, const double *q1, size_t n,
                              const pccd_body *const *obstacles, const pccd_motion *const *motions,
                              size_t n_obstacles, const pccd_config *cfg,
                              const pccd_scene_options *opt, const pccd_robot_options *ropt,
                              pccd_report *rep) {
  return guard(__func__, [&] {
    require(r, "r");
    require(rep, "rep");
    rep->solved = false;
    pccd::api::check_value_count(*r, n);
    if (n > 0) {
      require(q0, "q0");
      require(q1, "q1");
    }
    const pccd::api::Robot_call rc =
        pccd::api::read_robot_call(*r, obstacles, motions, n_obstacles, cfg, opt, ropt);
    const pccd::scene::Robot_options ro = pccd::api::with_link_check(rc.ro, rc.call.limits);
    const pccd::api::Call_budget budget(rc.call.limits.work);
    rep->r = pccd::scene::check_robot(r->m, q0, q1, rc.obstacles, rc.call.scene_options(), ro);
    rep->solved = true;
    return PCCD_OK;
  });
}

}  // extern "C"
