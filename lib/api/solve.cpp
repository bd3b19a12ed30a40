// pccd_config_init, pccd_query_solve, and reading a pccd_config.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>

#include "api/guard.h"
#include "api/handles.h"
#include "api/limits.h"

using pccd::api::guard;
using pccd::api::place;
using pccd::api::require;
using pccd::arith::Input_error;
using pccd::arith::Interval;
using pccd::arith::Rational;

namespace pccd::api {

namespace {

// A number text of the config and its value, as last parsed on this thread: callers
// pass the same config call after call, so each text is parsed once, not per query.
struct Number_cache {
  std::string text;
  Rational value;
  bool valid = false;
};
thread_local Number_cache tl_tolerance, tl_min_distance;

// The value of `text` (the config field `field`), parsed and checked by `check` (which
// throws Input_error) only when it differs from the cached text.
template <class Check>
const Rational &cached_number(Number_cache &c, const char *text, const char *field, Check check) {
  if (c.valid && std::strcmp(text, c.text.c_str()) == 0) return c.value;
  c.valid = false;
  Rational x = arith::parse_rational(text, field);
  check(x);
  c.text = text;
  c.value = std::move(x);
  c.valid = true;
  return c.value;
}

// Validates cfg (NULL: defaults); the parsed tolerance when cfg has one, else nullptr.
const Rational *checked_tolerance(const pccd_config *cfg) {
  if (!cfg) return nullptr;
  // The layout before the work limits is accepted too (polyccd.h, pccd_config).
  if (cfg->struct_size != sizeof(pccd_config) && cfg->struct_size != offsetof(pccd_config, max_seconds))
    throw Input_error("config.struct_size: " + std::to_string(cfg->struct_size) + " is not " +
                      std::to_string(sizeof(pccd_config)) + " (initialise with pccd_config_init)");
  if (!cfg->time_tolerance) return nullptr;
  return &cached_number(tl_tolerance, cfg->time_tolerance, "config.time_tolerance",
                        [&](const Rational &tol) {
                          if (sgn(tol) <= 0)
                            throw Input_error(std::string("config.time_tolerance: \"") +
                                              cfg->time_tolerance + "\" must be greater than 0");
                        });
}

}  // namespace

void checked_config(const pccd_config *cfg) { checked_tolerance(cfg); }

bool has_min_distance(const pccd_config *cfg) {
  return cfg && cfg->struct_size == sizeof(pccd_config) && cfg->min_distance;
}

pred::Solve_options read_config(const pccd_config *cfg) {
  pred::Solve_options o;
  if (const Rational *tol = checked_tolerance(cfg)) o.tol = *tol;
  if (!cfg) return o;
  o.want_time = cfg->want_time != 0;
  o.want_exact = cfg->want_exact != 0;
  if (has_min_distance(cfg))
    o.delta = cached_number(tl_min_distance, cfg->min_distance, "config.min_distance",
                            [&](const Rational &d) {
                              if (sgn(d) < 0)
                                throw Input_error(std::string("config.min_distance: \"") +
                                                  cfg->min_distance + "\" must be >= 0");
                            });
  return o;
}

static void check_radii(const pccd_query &q) {
  if (q.kind != PCCD_SPHERE_SPHERE) return;
  for (int i = 0; i < 2; ++i)
    if (sgn(q.radius[i]) <= 0)
      throw Input_error(place("radii", {static_cast<size_t>(i)}) + ": " +
                        arith::to_string(q.radius[i]) + " is not > 0 (radii must be greater than 0)");
}

Biggest_number biggest_in(const pccd_query &q) {
  Biggest_number out;
  for (size_t p = 0; p < q.points.size(); ++p)
    for (size_t a = 0; a < 3; ++a)
      for (size_t i = 0; i < q.points[p][a].c.size(); ++i)
        out.see(q.points[p][a].c[i], [&] { return place("points", {p, a, i}); });
  for (size_t i = 0; i < 2; ++i) out.see(q.radius[i], [&] { return place("radii", {i}); });
  return out;
}

pred::Contact_result solve_query(const pccd_query &q, const pred::Solve_options &opt) {
  check_radii(q);
  const arith::Nearest_scope nearest;  // before any interval arithmetic
  pred::Query_data<Interval> iq;
  iq.kind = q.kind;
  for (const auto &p : q.points) iq.p.push_back(motion::convert_traj<Interval>(p));
  for (int i = 0; i < 2; ++i) iq.radius[i] = arith::enclose(q.radius[i]);
  auto exact = [&] {
    pred::Query_data<Rational> eq;
    eq.kind = q.kind;
    eq.p = q.points;
    eq.radius[0] = q.radius[0];
    eq.radius[1] = q.radius[1];
    return eq;
  };
  return pred::solve(iq, exact, opt);
}

}  // namespace pccd::api

extern "C" {

PCCD_API int pccd_config_init(pccd_config *cfg) {
  return guard(__func__, [&] {
    require(cfg, "cfg");
    std::memset(cfg, 0, sizeof *cfg);
    cfg->struct_size = sizeof *cfg;
    cfg->time_tolerance = nullptr;
    cfg->want_time = 1;
    cfg->want_exact = 1;
    cfg->max_seconds = 0;
    cfg->max_work = 0;
    cfg->cancel = nullptr;
    cfg->max_number_bits = PCCD_DEFAULT_MAX_NUMBER_BITS;
    cfg->min_distance = nullptr;
    return PCCD_OK;
  });
}

PCCD_API int pccd_query_solve(const pccd_query *q, const pccd_config *cfg, pccd_result *res) {
  return guard(__func__, [&] {
    require(res, "res");
    res->solved = false;
    res->r = pccd::pred::Contact_result();
    require(q, "q");
    pccd::pred::Solve_options opt = pccd::api::read_config(cfg);
    const pccd::api::Call_limits limits = pccd::api::read_limits(cfg);
    limits.check(pccd::api::biggest_in(*q));
    const pccd::api::Call_budget budget(limits.work);
    res->r = pccd::api::solve_query(*q, opt);
    res->solved = true;
    return PCCD_OK;
  });
}

}  // extern "C"
