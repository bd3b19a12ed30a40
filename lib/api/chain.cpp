// pccd_chain_*: kinematic chains (lib/motion/chain.h). Validates and converts the C
// inputs, calls lib/motion, maps errors; no algorithm here.
#include <string>
#include <vector>

#include "api/chain_handle.h"
#include "api/config.h"
#include "api/guard.h"
#include "api/motion_handle.h"
#include "motion/chain.h"

using pccd::api::guard;
using pccd::api::place;
using pccd::api::require;
using pccd::arith::Input_error;

namespace {

// The joint value arrays of a segment: both non-NULL with n == the number of links.
void check_segment(const pccd_chain *c, const double *q0, const double *q1, size_t n) {
  require(c, "c");
  if (n != c->c.size())
    throw Input_error("n: " + std::to_string(n) + " joint values given, the chain has " +
                      std::to_string(c->c.size()) + " links");
  if (n > 0) {
    require(q0, "q0");
    require(q1, "q1");
  }
}

// pccd_chain_segment_motions (cfg NULL: no limits) and pccd_chain_segment_motions_cfg:
// the compositions run under the call's work limits, and every link's motion is held
// to max_number_bits as soon as it is built ("motions[3].rotation[0][2]: ...").
int segment_motions(const char *fn, const pccd_chain *c, const double *q0, const double *q1,
                    size_t n, const pccd_config *cfg, pccd_motion **motions) {
  return guard(fn, [&] {
    check_segment(c, q0, q1, n);
    if (n > 0) require(motions, "motions");
    for (size_t k = 0; k < n; ++k) motions[k] = nullptr;
    // the config's rules (struct_size, ...) as for any call; only its limits are used
    const pccd::api::Call_limits limits = pccd::api::read_call(cfg).limits;
    const pccd::motion::Link_check held = [&](size_t k, const pccd::motion::Rigid_motion &m) {
      limits.check(pccd::api::biggest_in(m), place("motions", {k}) + ".");
    };
    const pccd::api::Call_budget budget(limits.work);
    std::vector<pccd::motion::Mat3_poly> rn;
    std::vector<pccd::motion::Rigid_motion> m =
        c->c.segment_motions(q0, q1, &rn, nullptr, cfg && limits.max_number_bits ? &held : nullptr);
    std::vector<pccd_motion *> made;
    try {
      // Valid by construction (Chain::segment_motions): their data skips the vanishing
      // test, and takes the rotation numerator the composition computed.
      for (size_t k = 0; k < m.size(); ++k) {
        made.push_back(new pccd_motion(std::move(m[k]), true));
        made.back()->rn = std::make_shared<const pccd::motion::Mat3_poly>(std::move(rn[k]));
      }
    } catch (...) {
      for (pccd_motion *p : made) delete p;
      throw;
    }
    for (size_t k = 0; k < n; ++k) motions[k] = made[k];
    return PCCD_OK;
  });
}

}  // namespace

extern "C" {

PCCD_API int pccd_chain_new(pccd_chain **out) { return pccd::api::new_handle(__func__, out); }

PCCD_API void pccd_chain_free(pccd_chain *c) { delete c; }

PCCD_API int pccd_chain_add_link(pccd_chain *c, long parent, int joint, const double axis[3],
                                 const double xyz[3], const double rpy[3], size_t *index) {
  return guard(__func__, [&] {
    require(c, "c");
    require(xyz, "xyz");
    require(rpy, "rpy");
    pccd::motion::Chain next = c->c;  // unchanged on error
    const size_t k = next.add_link(parent, joint, axis, xyz, rpy);
    c->c = std::move(next);
    if (index) *index = k;
    return PCCD_OK;
  });
}

PCCD_API int pccd_chain_size(const pccd_chain *c, size_t *n) {
  return pccd::api::getter(__func__, c, "c", n, "n",
                                [&] { return c->c.size(); });
}

PCCD_API int pccd_chain_set_value_place(pccd_chain *c, size_t k, const char *place) {
  return guard(__func__, [&] {
    require(c, "c");
    require(place, "place");
    if (k >= c->c.size())
      throw Input_error("k: " + std::to_string(k) + " out of range (the chain has " +
                        std::to_string(c->c.size()) + " links)");
    c->c.set_value_place(k, place);
    return PCCD_OK;
  });
}

PCCD_API int pccd_chain_segment_motions(const pccd_chain *c, const double *q0, const double *q1,
                                        size_t n, pccd_motion **motions) {
  return segment_motions(__func__, c, q0, q1, n, nullptr, motions);
}

PCCD_API int pccd_chain_segment_motions_cfg(const pccd_chain *c, const double *q0, const double *q1,
                                            size_t n, const pccd_config *cfg, pccd_motion **motions) {
  return segment_motions(__func__, c, q0, q1, n, cfg, motions);
}

PCCD_API int pccd_chain_joint_values_s(const pccd_chain *c, const double *q0, const double *q1,
                                       size_t n, const char *t, double *values) {
  return guard(__func__, [&] {
    check_segment(c, q0, q1, n);
    require(t, "t");
    if (n > 0) require(values, "values");
    const std::vector<double> v = c->c.joint_values(q0, q1, pccd::arith::parse_rational(t, "t"));
    for (size_t k = 0; k < n; ++k) values[k] = v[k];
    return PCCD_OK;
  });
}

}  // extern "C"
