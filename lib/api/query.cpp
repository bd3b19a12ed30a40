// pccd_query_* and pccd_kind_points: building primitive queries.
#include <string>

#include "api/guard.h"
#include "api/handles.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::arith::Input_error;
using pccd::arith::Limit_error;
using pccd::arith::Rational;
using Poly_q = pccd::poly::Poly<Rational>;

namespace pccd::api {

size_t kind_points(long kind) {
  switch (kind) {
    case PCCD_VERTEX_FACE: case PCCD_EDGE_EDGE: return 4;
    case PCCD_VERTEX_EDGE: return 3;
    case PCCD_VERTEX_VERTEX: case PCCD_SPHERE_SPHERE: return 2;
  }
  throw Input_error("kind: " + std::to_string(kind) +
                    " is not a pccd_kind (expected 0 vertex-face .. 4 sphere-sphere)");
}

}  // namespace pccd::api

namespace {

using pccd::api::place;

// Checks the handle, the indices and the degree of pccd_query_set_coord_*. Coefficient i
// of the call is named points[point][axis][i], as Python's solve(kind, points) nests it.
void check_index(const pccd_query *q, size_t point, size_t axis, const void *coeffs, size_t n) {
  require(q, "q");
  if (point >= q->points.size())
    throw Input_error("point: " + std::to_string(point) + " out of range (this kind has " +
                      std::to_string(q->points.size()) + " points)");
  if (axis > 2) throw Input_error("axis: " + std::to_string(axis) + " out of range (0, 1 or 2)");
  if (n > PCCD_MAX_TRAJ_DEGREE + 1)
    throw Limit_error(place("points", {point, axis}) + ": degree " + std::to_string(n - 1) +
                      " exceeds the limit of " + std::to_string(PCCD_MAX_TRAJ_DEGREE));
  if (n > 0) require(coeffs, "coeffs");
}

}  // namespace

extern "C" {

PCCD_API const char *pccd_version(void) { return PCCD_VERSION_STRING; }

PCCD_API int pccd_kind_points(pccd_kind kind, size_t *count) {
  return guard(__func__, [&] {
    require(count, "count");
    *count = pccd::api::kind_points(pccd::api::raw_kind(kind));
    return PCCD_OK;
  });
}

PCCD_API int pccd_query_new(pccd_query **out, pccd_kind kind) {
  return guard(__func__, [&] {
    require(out, "out");
    *out = nullptr;
    const long k = pccd::api::raw_kind(kind);
    size_t n = pccd::api::kind_points(k);
    auto *q = new pccd_query;
    q->kind = static_cast<int>(k);
    q->points.resize(n);
    *out = q;
    return PCCD_OK;
  });
}

PCCD_API void pccd_query_free(pccd_query *q) { delete q; }

PCCD_API int pccd_query_set_coord_d(pccd_query *q, size_t point, size_t axis,
                                    const double *coeffs, size_t n) {
  return guard(__func__, [&] {
    check_index(q, point, axis, coeffs, n);
    std::vector<Rational> c;
    for (size_t i = 0; i < n; ++i)
      c.push_back(pccd::arith::rational_from_double(coeffs[i], place("points", {point, axis, i})));
    q->points[point][static_cast<int>(axis)] = Poly_q(std::move(c));
    return PCCD_OK;
  });
}

PCCD_API int pccd_query_set_coord_s(pccd_query *q, size_t point, size_t axis,
                                    const char *const *coeffs, size_t n) {
  return guard(__func__, [&] {
    check_index(q, point, axis, coeffs, n);
    std::vector<Rational> c;
    for (size_t i = 0; i < n; ++i) {
      const std::string where = place("points", {point, axis, i});
      require(coeffs[i], where);
      c.push_back(pccd::arith::parse_rational(coeffs[i], where));
    }
    q->points[point][static_cast<int>(axis)] = Poly_q(std::move(c));
    return PCCD_OK;
  });
}

PCCD_API int pccd_query_set_linear_d(pccd_query *q, const double *p_t0, const double *p_t1) {
  return guard(__func__, [&] {
    require(q, "q");
    require(p_t0, "p_t0");
    require(p_t1, "p_t1");
    std::vector<pccd::motion::Point_traj<Rational>> pts(q->points.size());
    for (size_t i = 0; i < pts.size(); ++i)
      for (size_t a = 0; a < 3; ++a) {
        // p_t0[3i + a] is coordinate a of point i: named p_t0[i][a].
        Rational x0 = pccd::arith::rational_from_double(p_t0[3 * i + a], place("p_t0", {i, a}));
        Rational x1 = pccd::arith::rational_from_double(p_t1[3 * i + a], place("p_t1", {i, a}));
        pts[i][static_cast<int>(a)] = Poly_q(std::vector<Rational>{x0, x1 - x0});
      }
    q->points = std::move(pts);
    return PCCD_OK;
  });
}

static int set_radius(pccd_query *q, size_t which, const Rational &r) {
  if (q->kind != PCCD_SPHERE_SPHERE)
    throw Input_error("radii: only sphere-sphere queries have radii");
  if (which > 1) throw Input_error("which: " + std::to_string(which) + " out of range (0 or 1)");
  q->radius[which] = r;
  return PCCD_OK;
}

PCCD_API int pccd_query_set_radius_d(pccd_query *q, size_t which, double r) {
  return guard(__func__, [&] {
    require(q, "q");
    return set_radius(q, which, pccd::arith::rational_from_double(r, place("radii", {which})));
  });
}

PCCD_API int pccd_query_set_radius_s(pccd_query *q, size_t which, const char *r) {
  return guard(__func__, [&] {
    require(q, "q");
    require(r, place("radii", {which}));
    return set_radius(q, which, pccd::arith::parse_rational(r, place("radii", {which})));
  });
}

}  // extern "C"
