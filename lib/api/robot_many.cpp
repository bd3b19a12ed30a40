// pccd_robot_check_many and pccd_robot_check_states: many segments (or poses) of one
// robot against the same obstacles in one call, on the call's thread pool. The call's
// arguments are read once (api/robot_handle.h, as pccd_robot_check reads them); each
// segment is then exactly a pccd_robot_check of its own (scene::check_robot), its
// errors kept with its index (status, message) so that one bad segment leaves the
// other answers. The work limits are the batch's: reaching one ends the call.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "api/guard.h"
#include "api/robot_handle.h"
#include "api/scene_handle.h"
#include "util/thread_pool.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::arith::Input_error;

namespace pccd::api {
namespace {

// One segment's outcome: its status and, when it failed, its message.
struct Segment_outcome {
  int status = PCCD_ESTATE;  // not answered (yet)
  std::string message;
};

void clear(const pccd_robot_batch_out &out, size_t n) {
  for (size_t k = 0; k < n; ++k) {
    if (out.status) out.status[k] = PCCD_ESTATE;
    if (out.messages && out.message_cap) out.messages[k * out.message_cap] = '\0';
    if (out.collides) out.collides[k] = 0;
    if (out.lo) out.lo[k] = NAN;
    if (out.hi) out.hi[k] = NAN;
    if (out.free_until) out.free_until[k] = NAN;
    if (out.reports && out.reports[k]) out.reports[k]->solved = false;
  }
}

// The answer of segment k (status PCCD_OK).
void write(const pccd_robot_batch_out &out, size_t k, scene::Scene_report &&r) {
  if (out.collides) out.collides[k] = r.collides ? 1 : 0;
  if (out.lo) out.lo[k] = r.collides ? arith::enclose(r.lo).lo : NAN;
  if (out.hi) out.hi[k] = r.collides ? arith::enclose(r.hi).hi : NAN;
  if (out.free_until) out.free_until[k] = arith::enclose(r.free_until).lo;
  if (out.reports && out.reports[k]) {
    out.reports[k]->r = std::move(r);
    out.reports[k]->solved = true;
  }
}

// fn's message "pccd_fn: what" with the segment's place after the function name.
std::string placed(const char *fn, const std::string &message, const std::string &where) {
  const std::string head = std::string(fn) + ": ";
  const std::string what = message.compare(0, head.size(), head) == 0 ? message.substr(head.size()) : message;
  return head + where + ": " + what;
}

int check_many(const char *fn, const char *noun, const pccd_robot *r, const double *q0,
               const double *q1, size_t n_segments, size_t n, const pccd_body *const *obstacles,
               const pccd_motion *const *motions, size_t n_obstacles, const pccd_config *cfg,
               const pccd_scene_options *opt, const pccd_robot_options *ropt,
               pccd_robot_batch_out *out) {
  require(r, "r");
  require(out, "out");
  if (out->struct_size != sizeof(pccd_robot_batch_out))
    throw Input_error("out.struct_size: " + std::to_string(out->struct_size) +
                      " is not sizeof(pccd_robot_batch_out)");
  if (out->messages && out->message_cap == 0)
    throw Input_error("out.message_cap: is 0 with out.messages set");
  if (out->reports)
    for (size_t k = 0; k < n_segments; ++k)
      if (out->reports[k]) out->reports[k]->solved = false;  // no earlier answer readable
  check_value_count(*r, n);
  const Robot_call rc = read_robot_call(*r, obstacles, motions, n_obstacles, cfg, opt, ropt);
  if (n_segments == 0) return PCCD_OK;
  if (n > 0) {
    require(q0, "q0");
    require(q1, "q1");
  }
  clear(*out, n_segments);
  const scene::Robot_options ro = with_link_check(rc.ro, rc.call.limits);
  scene::Scene_options one = rc.call.scene_options();
  one.threads = 1;  // the threads share the segments, each solved on one
  std::vector<Segment_outcome> outcome(n_segments);
  {
    const Call_budget budget(rc.call.limits.work);
    const size_t threads = std::min<size_t>(rc.call.threads, n_segments);
    util::Thread_pool pool(static_cast<unsigned>(std::max<size_t>(1, threads)));
    try {
      pool.parallel_for(n_segments, [&](size_t k) {
        std::exception_ptr stop;  // a work limit: ends the batch (rethrown below)
        scene::Scene_report rep;
        const int status = guard(fn, [&] {
          try {
            rep = scene::check_robot(r->m, q0 + k * n, q1 + k * n, rc.obstacles, one, ro);
          } catch (const util::Limit_reached &) {
            stop = std::current_exception();
          }
          return PCCD_OK;
        });
        if (stop) std::rethrow_exception(stop);
        outcome[k].status = status;
        if (status != PCCD_OK) {
          outcome[k].message = placed(fn, last_error_text(), place(noun, {k}));
          return;
        }
        write(*out, k, std::move(rep));
      });
    } catch (...) {  // a work limit: no answer readable
      clear(*out, n_segments);
      throw;
    }
  }
  if (!out->status) {  // the first failing segment fails the call
    for (size_t k = 0; k < n_segments; ++k)
      if (outcome[k].status != PCCD_OK) {
        set_error(fn, outcome[k].message.substr(std::strlen(fn) + 2));
        return outcome[k].status;
      }
    return PCCD_OK;
  }
  for (size_t k = 0; k < n_segments; ++k) {
    out->status[k] = outcome[k].status;
    if (out->messages) {
      const std::string &m = outcome[k].message;
      const size_t len = std::min(m.size(), out->message_cap - 1);
      std::memcpy(out->messages + k * out->message_cap, m.data(), len);
      out->messages[k * out->message_cap + len] = '\0';
    }
  }
  return PCCD_OK;
}

}  // namespace
}  // namespace pccd::api

extern "C" {

PCCD_API int pccd_robot_check_many(const pccd_robot *r, const double *q0, const double *q1,
                                   size_t n_segments, size_t n,
                                   const pccd_body *const *obstacles,
                                   const pccd_motion *const *motions, size_t n_obstacles,
                                   const pccd_config *cfg, const pccd_scene_options *opt,
                                   const pccd_robot_options *ropt, pccd_robot_batch_out *out) {
  static const char *const fn = __func__;
  int rc = PCCD_OK;
  const int g = guard(fn, [&] {
    rc = pccd::api::check_many(fn, "segments", r, q0, q1, n_segments, n, obstacles,
                               motions, n_obstacles, cfg, opt, ropt, out);
    return PCCD_OK;
  });
  return g != PCCD_OK ? g : rc;
}

PCCD_API int pccd_robot_check_states(const pccd_robot *r, const double *q, size_t n_states,
                                     size_t n, const pccd_body *const *obstacles,
                                     const pccd_motion *const *motions, size_t n_obstacles,
                                     const pccd_config *cfg, const pccd_scene_options *opt,
                                     const pccd_robot_options *ropt, pccd_robot_batch_out *out) {
  static const char *const fn = __func__;
  int rc = PCCD_OK;
  const int g = guard(fn, [&] {
    rc = pccd::api::check_many(fn, "states", r, q, q, n_states, n, obstacles, motions,
                               n_obstacles, cfg, opt, ropt, out);
    return PCCD_OK;
  });
  return g != PCCD_OK ? g : rc;
}

}  // extern "C"
