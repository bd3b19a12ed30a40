// pccd_result_*: reading answers.
#include <string>

#include "api/guard.h"
#include "api/handles.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::api::require_solved;
using pccd::api::State_error;
using pccd::arith::Input_error;

extern "C" {

PCCD_API int pccd_result_new(pccd_result **out) {
  return pccd::api::new_handle(__func__, out);
}

PCCD_API void pccd_result_free(pccd_result *r) { delete r; }

PCCD_API int pccd_result_collides(const pccd_result *res, int *collides) {
  return pccd::api::getter<true>(__func__, res, "res", collides, "collides",
                                [&] { return res->r.collides ? 1 : 0; });
}

PCCD_API int pccd_result_stage(const pccd_result *res, int *stage) {
  return pccd::api::getter<true>(__func__, res, "res", stage, "stage",
                                [&] { return res->r.stage; });
}

PCCD_API int pccd_result_time(const pccd_result *res, int which, char *buf, size_t cap,
                              size_t *needed) {
  return guard(__func__, [&]() -> int {
    require_solved(res, "res");
    if (which < 0 || which > 2)
      throw Input_error("which: " + std::to_string(which) +
                        " is not 0 (lo), 1 (hi) or 2 (exact)");
    if (!res->r.collides) throw State_error("res: there is no contact, so no contact time");
    if (which == 2 && !res->r.exact)
      throw State_error("res: the first contact time is not known exactly (irrational, or "
                        "want_exact was 0)");
    return pccd::api::write_text(pccd::arith::to_string(which == 0 ? res->r.lo : res->r.hi),
                                 buf, cap, needed);
  });
}

PCCD_API int pccd_result_time_is_exact(const pccd_result *res, int *exact) {
  return pccd::api::getter<true>(__func__, res, "res", exact, "exact",
                                [&] { return res->r.collides && res->r.exact ? 1 : 0; });
}

PCCD_API int pccd_result_time_approx(const pccd_result *res, double *t) {
  return guard(__func__, [&] {
    require_solved(res, "res");
    require(t, "t");
    if (!res->r.collides) throw State_error("res: there is no contact, so no contact time");
    *t = pccd::arith::nearest_double((res->r.lo + res->r.hi) / 2);
    return PCCD_OK;
  });
}

PCCD_API int pccd_result_feature_count(const pccd_result *res, size_t *count) {
  return pccd::api::getter<true>(__func__, res, "res", count, "count",
                                [&] { return res->r.features.size(); });
}

PCCD_API int pccd_result_feature(const pccd_result *res, size_t i, int *kind, size_t points[4]) {
  return guard(__func__, [&] {
    require_solved(res, "res");
    require(kind, "kind");
    require(points, "points");
    if (i >= res->r.features.size())
      throw Input_error("i: " + std::to_string(i) + " out of range (" +
                        std::to_string(res->r.features.size()) + " features)");
    const auto &f = res->r.features[i];
    *kind = f.kind;
    for (int k = 0; k < 4; ++k) points[k] = f.points[k] < 0 ? static_cast<size_t>(-1) : static_cast<size_t>(f.points[k]);
    return PCCD_OK;
  });
}

}  // extern "C"
