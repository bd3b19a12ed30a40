// pccd_config_init and pccd_query_solve (the config is read by api/config.h).
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>

#include "api/config.h"
#include "api/guard.h"
#include "api/handles.h"

using pccd::api::guard;
using pccd::api::place;
using pccd::api::require;
using pccd::arith::Input_error;
using pccd::arith::Interval;
using pccd::arith::Rational;

namespace pccd::api {

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
    const pccd::api::Call_config call = pccd::api::read_call(cfg);
    call.limits.check(pccd::api::biggest_in(*q));
    const pccd::api::Call_budget budget(call.limits.work);
    res->r = pccd::api::solve_query(*q, *call.solve);
    res->solved = true;
    return PCCD_OK;
  });
}

}  // extern "C"
