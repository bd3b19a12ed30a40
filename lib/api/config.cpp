// Reading a call's options into one Call_config (api/config.h): every rule about
// options, once.
#include "api/config.h"

#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>

#include "enclose/enclose.h"
#include "scene/broad_phase.h"

using pccd::arith::Input_error;
using pccd::arith::Rational;

namespace pccd::api {

namespace {

// The size of pccd_config before the work-limit fields (accepted: polyccd.h).
constexpr size_t kConfigSizeV0 = offsetof(pccd_config, max_seconds);

// The solve options of the config last read on this thread, and the texts and flags
// they were read from: callers pass the same config call after call, so each number
// text is parsed once, not per query.
struct Solve_cache {
  bool valid = false;
  std::string tolerance, min_distance;  // the texts; has_*: whether the config set them
  bool has_tolerance = false, has_min_distance = false;
  bool want_time = true, want_exact = true;
  pred::Solve_options solve;
};
thread_local Solve_cache tl_cache;

bool same_text(bool has, const std::string &text, const char *s) {
  return has == (s != nullptr) && (!s || std::strcmp(s, text.c_str()) == 0);
}

pred::Solve_options with_flags(bool want_time, bool want_exact) {
  pred::Solve_options o;
  o.want_time = want_time;
  o.want_exact = want_exact;
  return o;
}

const pred::Solve_options &solve_options(const pccd_config *cfg) {
  static const pred::Solve_options kDefaults;
  if (!cfg) return kDefaults;
  // The layout before the work limits is accepted too (polyccd.h, pccd_config).
  if (cfg->struct_size != sizeof(pccd_config) && cfg->struct_size != kConfigSizeV0)
    throw Input_error("config.struct_size: " + std::to_string(cfg->struct_size) + " is not " +
                      std::to_string(sizeof(pccd_config)) + " (initialise with pccd_config_init)");
  // config.min_distance exists only in the full layout.
  const char *md = cfg->struct_size == sizeof(pccd_config) ? cfg->min_distance : nullptr;
  const bool want_time = cfg->want_time != 0, want_exact = cfg->want_exact != 0;
  if (!cfg->time_tolerance && !md) {  // no number to parse: no thread-local access
    static const pred::Solve_options kFlags[2][2] = {{with_flags(false, false), with_flags(false, true)},
                                                     {with_flags(true, false), with_flags(true, true)}};
    return kFlags[want_time][want_exact];
  }
  Solve_cache &c = tl_cache;
  if (c.valid && c.want_time == want_time && c.want_exact == want_exact &&
      same_text(c.has_tolerance, c.tolerance, cfg->time_tolerance) &&
      same_text(c.has_min_distance, c.min_distance, md))
    return c.solve;
  c.valid = false;
  pred::Solve_options o;
  if (cfg->time_tolerance) {
    o.tol = arith::parse_rational(cfg->time_tolerance, "config.time_tolerance");
    if (sgn(o.tol) <= 0)
      throw Input_error(std::string("config.time_tolerance: \"") + cfg->time_tolerance +
                        "\" must be greater than 0");
  }
  o.want_time = want_time;
  o.want_exact = want_exact;
  if (md) {
    o.set_delta(arith::parse_rational(md, "config.min_distance"));
    if (sgn(o.delta) < 0)
      throw Input_error(std::string("config.min_distance: \"") + md + "\" must be >= 0");
  }
  c.has_tolerance = cfg->time_tolerance != nullptr;
  c.tolerance = c.has_tolerance ? cfg->time_tolerance : "";
  c.has_min_distance = md != nullptr;
  c.min_distance = md ? md : "";
  c.want_time = want_time;
  c.want_exact = want_exact;
  c.solve = std::move(o);
  c.valid = true;
  return c.solve;
}

Call_limits read_limits(const pccd_config *cfg) {
  Call_limits l;
  if (!cfg || cfg->struct_size == kConfigSizeV0) return l;
  if (!(std::isfinite(cfg->max_seconds) && cfg->max_seconds >= 0))
    throw Input_error("config.max_seconds: " + std::to_string(cfg->max_seconds) +
                      " is not a finite number >= 0 (0: no time limit)");
  l.work.max_seconds = cfg->max_seconds;
  l.work.max_steps = cfg->max_work;
  l.work.cancel = cfg->cancel ? &cfg->cancel->flag : nullptr;
  l.max_number_bits = cfg->max_number_bits;
  return l;
}

// "<what>.struct_size: N is not <size> (initialise with <init>)".
void check_size(size_t got, size_t want, const std::string &what, const char *init) {
  if (got != want)
    throw Input_error(what + ".struct_size: " + std::to_string(got) + " is not " + init);
}

}  // namespace

unsigned checked_threads(unsigned n, const std::string &where) {
  if (n < 1 || n > PCCD_MAX_THREADS)
    throw Input_error(where + ": " + std::to_string(n) + " is outside 1.." +
                      std::to_string(PCCD_MAX_THREADS));
  return n;
}

Call_config read_call(const pccd_config *cfg) {
  Call_config c;
  c.solve = &solve_options(cfg);
  c.limits = read_limits(cfg);
  return c;
}

Call_config read_batch_call(const pccd_config *cfg, const pccd_batch_options *opt) {
  if (opt) {
    check_size(opt->struct_size, sizeof(pccd_batch_options), "opt",
               (std::to_string(sizeof(pccd_batch_options)) +
                " (initialise with pccd_batch_options_init)").c_str());
    checked_threads(opt->threads, "opt.threads");
  }
  Call_config c = read_call(cfg);
  if (opt) c.threads = opt->threads;
  return c;
}

Call_config read_scene_call(const pccd_config *cfg, const pccd_scene_options *opt, bool online) {
  const pred::Solve_options &solve = solve_options(cfg);
  int phase = PCCD_BROAD_AUTO;
  unsigned threads = 1;
  bool all_contacts = false;
  if (opt) {
    check_size(opt->struct_size, sizeof(pccd_scene_options), "opt",
               "sizeof(pccd_scene_options) (initialise with pccd_scene_options_init)");
    threads = checked_threads(opt->threads, "opt.threads");
    if (opt->all_contacts != 0 && opt->all_contacts != 1)
      throw Input_error("opt.all_contacts: " + std::to_string(opt->all_contacts) + " is not 0 or 1");
    if (opt->broad_phase < PCCD_BROAD_BOXES || opt->broad_phase > PCCD_BROAD_BVH)
      throw Input_error("opt.broad_phase: " + std::to_string(opt->broad_phase) +
                        " is not PCCD_BROAD_BOXES (0), PCCD_BROAD_BRUTE (1), PCCD_BROAD_RANGE (2), "
                        "PCCD_BROAD_AUTO (3) or PCCD_BROAD_BVH (4)");
    all_contacts = opt->all_contacts == 1;
    phase = opt->broad_phase;
  }
  Call_config c;
  c.solve = &solve;
  // With a minimum distance the range phase has no delta (its linearized contact
  // conditions would need the distance systems; scene/broad_phase.h), so it is refused
  // here and `auto` never resolves to it.
  if (solve.min_distance() && phase == PCCD_BROAD_RANGE)
    throw Input_error("opt.broad_phase: " + std::to_string(phase) +
                      " (PCCD_BROAD_RANGE) does not take config.min_distance > 0; use "
                      "PCCD_BROAD_AUTO, PCCD_BROAD_BVH, PCCD_BROAD_BOXES or PCCD_BROAD_BRUTE");
  c.threads = threads;
  c.all_contacts = all_contacts;
  c.broad_phase = scene::resolve(static_cast<scene::Broad_phase>(phase),  // constants.cpp
                                 online, solve.min_distance());
  c.limits = read_limits(cfg);
  return c;
}

scene::Scene_options Call_config::scene_options() const {
  scene::Scene_options so;
  so.solve = *solve;
  so.all_contacts = all_contacts;
  so.broad_phase = broad_phase;
  so.threads = threads;
  so.reach = enclose::reach_of(solve->delta);
  return so;
}

}  // namespace pccd::api
