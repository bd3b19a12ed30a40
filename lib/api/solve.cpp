// pccd_config_init, pccd_query_solve, pccd_solve_linear_d.
#include <cmath>
#include <cstring>
#include <string>

#include "api/guard.h"
#include "api/handles.h"
#include "pred/linear_filter.h"

using pccd::api::guard;
using pccd::api::place;
using pccd::api::require;
using pccd::arith::Input_error;
using pccd::arith::Interval;
using pccd::arith::Rational;

namespace pccd::api {

namespace {

// The tolerance text of this thread's last call and its value: callers pass the same
// config call after call, so its text is parsed once, not per query.
struct Tolerance_cache {
  std::string text;
  Rational value;
  bool valid = false;
};
thread_local Tolerance_cache tl_tolerance;

// Validates cfg (NULL: defaults); the parsed tolerance when cfg has one, else nullptr.
const Rational *checked_tolerance(const pccd_config *cfg) {
  if (!cfg) return nullptr;
  if (cfg->struct_size != sizeof(pccd_config))
    throw Input_error("config.struct_size: " + std::to_string(cfg->struct_size) + " is not " +
                      std::to_string(sizeof(pccd_config)) + " (initialise with pccd_config_init)");
  if (!cfg->time_tolerance) return nullptr;
  Tolerance_cache &c = tl_tolerance;
  if (c.valid && std::strcmp(cfg->time_tolerance, c.text.c_str()) == 0) return &c.value;
  c.valid = false;
  Rational tol = arith::parse_rational(cfg->time_tolerance, "config.time_tolerance");
  if (sgn(tol) <= 0)
    throw Input_error(std::string("config.time_tolerance: \"") + cfg->time_tolerance +
                      "\" must be greater than 0");
  c.text = cfg->time_tolerance;
  c.value = std::move(tol);
  c.valid = true;
  return &c.value;
}

}  // namespace

void checked_config(const pccd_config *cfg) { checked_tolerance(cfg); }

pred::Solve_options read_config(const pccd_config *cfg) {
  pred::Solve_options o;
  if (const Rational *tol = checked_tolerance(cfg)) o.tol = *tol;
  if (!cfg) return o;
  o.want_time = cfg->want_time != 0;
  o.want_exact = cfg->want_exact != 0;
  return o;
}

static void check_radii(const pccd_query &q) {
  if (q.kind != PCCD_SPHERE_SPHERE) return;
  for (int i = 0; i < 2; ++i)
    if (sgn(q.radius[i]) <= 0)
      throw Input_error(place("radii", {static_cast<size_t>(i)}) + ": " +
                        arith::to_string(q.radius[i]) + " is not > 0 (radii must be greater than 0)");
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
    res->r = pccd::api::solve_query(*q, opt);
    res->solved = true;
    return PCCD_OK;
  });
}

PCCD_API int pccd_solve_linear_d(pccd_kind kind, const double *p_t0, const double *p_t1,
                                 const pccd_config *cfg, pccd_result *res) {
  return guard(__func__, [&] {
    require(res, "res");
    res->solved = false;
    pccd::api::reset(res->r);
    require(p_t0, "p_t0");
    require(p_t1, "p_t1");
    const long k = pccd::api::raw_kind(kind);
    if (k == PCCD_SPHERE_SPHERE)
      throw Input_error("kind: sphere-sphere queries need radii: use pccd_query_new");
    const size_t n = pccd::api::kind_points(k);
    pccd::api::checked_config(cfg);
    // A non-finite coordinate a of point i is named p_t0[i][a] (or p_t1[i][a]).
    for (size_t i = 0; i < n; ++i)
      for (size_t a = 0; a < 3; ++a) {
        const double x0 = p_t0[3 * i + a], x1 = p_t1[3 * i + a];
        if (!std::isfinite(x0)) pccd::arith::rational_from_double(x0, place("p_t0", {i, a}));
        if (!std::isfinite(x1)) pccd::arith::rational_from_double(x1, place("p_t1", {i, a}));
      }
    // The static filter (pred/linear_filter.h) proves most misses without allocating.
    switch (pccd::pred::linear_filter(static_cast<int>(k), p_t0, p_t1)) {
      case pccd::pred::Linear_verdict::boxes_apart:
        res->r.stage = pccd::pred::STAGE_BOUNDS;
        res->solved = true;
        return PCCD_OK;
      case pccd::pred::Linear_verdict::no_root:
        res->r.stage = pccd::pred::STAGE_BERNSTEIN;
        res->solved = true;
        return PCCD_OK;
      case pccd::pred::Linear_verdict::misses:
        res->r.stage = pccd::pred::STAGE_INTERVAL;
        res->solved = true;
        return PCCD_OK;
      case pccd::pred::Linear_verdict::unknown:
        break;
    }
    pccd::pred::Solve_options opt = pccd::api::read_config(cfg);
    const pccd::arith::Nearest_scope nearest;  // before any interval arithmetic
    // The interval stages see the doubles as exact points; the exact trajectories are
    // built only if those stages cannot decide.
    pccd::pred::Query_data<Interval> iq;
    iq.kind = static_cast<int>(k);
    iq.p.resize(n);
    for (size_t i = 0; i < n; ++i)
      for (size_t a = 0; a < 3; ++a) {
        const double x0 = p_t0[3 * i + a], x1 = p_t1[3 * i + a];
        // x(t) = x0 + (x1 - x0) t: the slope is enclosed, not rounded.
        iq.p[i][static_cast<int>(a)] = pccd::poly::Poly<Interval>(
            std::vector<Interval>{Interval(x0), Interval(x1) - Interval(x0)});
      }
    auto exact = [&] {
      pccd::pred::Query_data<Rational> eq;
      eq.kind = static_cast<int>(k);
      eq.p.resize(n);
      for (size_t i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) {
          Rational x0 = pccd::arith::rational_from_double(p_t0[3 * i + a], "p_t0");
          Rational x1 = pccd::arith::rational_from_double(p_t1[3 * i + a], "p_t1");
          eq.p[i][a] = pccd::poly::Poly<Rational>(std::vector<Rational>{x0, x1 - x0});
        }
      return eq;
    };
    res->r = pccd::pred::solve(iq, exact, opt);
    res->solved = true;
    return PCCD_OK;
  });
}

}  // extern "C"
