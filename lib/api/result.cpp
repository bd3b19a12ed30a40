// pccd_result_*: reading answers.
#include <cstring>
#include <string>

#include "api/guard.h"
#include "api/handles.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::arith::Input_error;

extern "C" {

PCCD_API int pccd_result_new(pccd_result **out) {
  return pccd::api::new_handle("pccd_result_new", out);
}

PCCD_API void pccd_result_free(pccd_result *r) { delete r; }

#define PCCD_NEED_SOLVED(fn)                                                  \
  require(res, "result");                                                     \
  if (!res->solved) {                                                         \
    pccd::api::set_error(fn, "no query has been solved into this result");   \
    return PCCD_ESTATE;                                                       \
  }

PCCD_API int pccd_result_collides(const pccd_result *res, int *collides) {
  return guard("pccd_result_collides", [&] {
    PCCD_NEED_SOLVED("pccd_result_collides");
    require(collides, "collides");
    *collides = res->r.collides ? 1 : 0;
    return PCCD_OK;
  });
}

PCCD_API int pccd_result_stage(const pccd_result *res, int *stage) {
  return guard("pccd_result_stage", [&] {
    PCCD_NEED_SOLVED("pccd_result_stage");
    require(stage, "stage");
    *stage = res->r.stage;
    return PCCD_OK;
  });
}

PCCD_API int pccd_result_time(const pccd_result *res, int which, char *buf, size_t cap,
                              size_t *needed) {
  return guard("pccd_result_time", [&]() -> int {
    PCCD_NEED_SOLVED("pccd_result_time");
    if (which < 0 || which > 2)
      throw Input_error("which is " + std::to_string(which) + "; expected 0 (lo), 1 (hi) or 2 (exact)");
    if (!res->r.collides) {
      pccd::api::set_error("pccd_result_time", "there is no contact, so no contact time");
      return PCCD_ESTATE;
    }
    if (which == 2 && !res->r.exact) {
      pccd::api::set_error("pccd_result_time", "the first contact time is not known exactly "
                                               "(irrational, or want_exact was 0)");
      return PCCD_ESTATE;
    }
    return pccd::api::write_text("pccd_result_time",
                                 pccd::arith::to_string(which == 0 ? res->r.lo : res->r.hi), buf,
                                 cap, needed);
  });
}

PCCD_API int pccd_result_time_is_exact(const pccd_result *res, int *exact) {
  return guard("pccd_result_time_is_exact", [&] {
    PCCD_NEED_SOLVED("pccd_result_time_is_exact");
    require(exact, "exact");
    *exact = res->r.collides && res->r.exact ? 1 : 0;
    return PCCD_OK;
  });
}

PCCD_API int pccd_result_time_approx(const pccd_result *res, double *t) {
  return guard("pccd_result_time_approx", [&] {
    PCCD_NEED_SOLVED("pccd_result_time_approx");
    require(t, "t");
    if (!res->r.collides) {
      pccd::api::set_error("pccd_result_time_approx", "there is no contact, so no contact time");
      return PCCD_ESTATE;
    }
    *t = pccd::arith::nearest_double((res->r.lo + res->r.hi) / 2);
    return PCCD_OK;
  });
}

PCCD_API int pccd_result_feature_count(const pccd_result *res, size_t *count) {
  return guard("pccd_result_feature_count", [&] {
    PCCD_NEED_SOLVED("pccd_result_feature_count");
    require(count, "count");
    *count = res->r.features.size();
    return PCCD_OK;
  });
}

PCCD_API int pccd_result_feature(const pccd_result *res, size_t i, int *kind, size_t points[4]) {
  return guard("pccd_result_feature", [&] {
    PCCD_NEED_SOLVED("pccd_result_feature");
    require(kind, "kind");
    require(points, "points");
    if (i >= res->r.features.size())
      throw Input_error("feature index " + std::to_string(i) + " out of range (" +
                        std::to_string(res->r.features.size()) + " features)");
    const auto &f = res->r.features[i];
    *kind = f.kind;
    for (int k = 0; k < 4; ++k) points[k] = f.points[k] < 0 ? static_cast<size_t>(-1) : static_cast<size_t>(f.points[k]);
    return PCCD_OK;
  });
}

}  // extern "C"
