// pccd_body_*: rigid bodies (lib/motion/body.h). Checks the C arguments, converts the
// numbers exactly, builds the body; validation and edge extraction live in lib/motion.
// *out is written only with a complete body, so a failed call leaves it NULL.
#include <string>
#include <vector>

#include "api/body_handle.h"
#include "api/config.h"
#include "api/guard.h"
#include "bvh/hierarchy.h"
#include "util/work_budget.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::arith::Input_error;
using pccd::arith::Rational;
using pccd::motion::Point3_q;

namespace {

using pccd::api::place;

// n points from n * 3 doubles / strings; entry (i, k) is named name[i][k].
std::vector<Point3_q> points_d(const double *values, size_t n, const char *name) {
  if (n > 0) require(values, name);
  std::vector<Point3_q> out(n);
  for (size_t i = 0; i < n; ++i) {
    if (i % 4096 == 0) pccd::util::work_step();  // a step per 4,096 points (body_cfg)
    for (size_t k = 0; k < 3; ++k)
      out[i][k] = pccd::arith::rational_from_double(values[3 * i + k], place(name, {i, k}));
  }
  return out;
}

Rational number_s(const char *text, const std::string &where) {
  require(text, where);
  return pccd::arith::parse_rational(text, where);
}

std::vector<Point3_q> points_s(const char *const *values, size_t n, const char *name) {
  if (n > 0) require(values, name);
  std::vector<Point3_q> out(n);
  for (size_t i = 0; i < n; ++i) {
    if (i % 4096 == 0) pccd::util::work_step();
    for (size_t k = 0; k < 3; ++k) out[i][k] = number_s(values[3 * i + k], place(name, {i, k}));
  }
  return out;
}

std::vector<pccd::motion::Triangle> triangles_of(const unsigned int *tris, size_t nt) {
  pccd::motion::check_body_size(nt, "triangles");
  if (nt > 0) require(tris, "triangles");
  std::vector<pccd::motion::Triangle> out(nt);
  for (size_t t = 0; t < nt; ++t)
    for (size_t k = 0; k < 3; ++k) out[t][k] = tris[3 * t + k];
  return out;
}

// The size checks run before any allocation (nv * 3 cannot overflow below the limit).
int new_mesh(pccd_body **out, std::vector<Point3_q> vertices,
             std::vector<pccd::motion::Triangle> triangles) {
  auto body = std::make_unique<pccd_body>();
  body->mesh = std::make_shared<const pccd::motion::Mesh_body>(std::move(vertices),
                                                         std::move(triangles));
  body->data = pccd::narrow::make_body_data(body->mesh, nullptr);
  body->biggest = pccd::api::biggest_in(*body->mesh);
  pccd::bvh::hierarchy(*body->data);  // built with the body, shared by every check (counts steps)
  *out = body.release();
  return PCCD_OK;
}

int new_spheres(pccd_body **out, std::vector<Point3_q> centers, std::vector<Rational> radii) {
  auto body = std::make_unique<pccd_body>();
  body->spheres = std::make_shared<const pccd::motion::Sphere_body>(std::move(centers),
                                                              std::move(radii));
  body->data = pccd::narrow::make_body_data(nullptr, body->spheres);
  body->biggest = pccd::api::biggest_in(*body->spheres);
  pccd::bvh::hierarchy(*body->data);
  *out = body.release();
  return PCCD_OK;
}

// Runs make() (a constructor's work) under the limits of cfg (the _cfg variants; cfg
// NULL: none): the config's rules are checked as for any call, its work limits bound
// the conversion, the edges and the hierarchy (each counts work steps), and its
// max_number_bits the body's numbers ("vertices[3][1]: ..."), checked once built.
template <class Make>
int under_limits(pccd_body **out, const pccd_config *cfg, Make &&make) {
  require(out, "out");
  *out = nullptr;
  const pccd::api::Call_limits limits = pccd::api::read_call(cfg).limits;
  pccd_body *made = nullptr;
  {
    const pccd::api::Call_budget budget(limits.work);
    make(&made);
  }
  std::unique_ptr<pccd_body> body(made);
  if (cfg) limits.check(body->biggest);
  *out = body.release();
  return PCCD_OK;
}

// A mesh body from nv vertices (points() converts them, doubles or texts) and nt
// triangles, under cfg's limits (NULL: none): every pccd_body_new_mesh_* entry point. The
// size check runs before any allocation.
template <class Points>
int mesh_under_limits(pccd_body **out, const pccd_config *cfg, size_t nv, Points &&points,
                      const unsigned int *triangles, size_t nt) {
  return under_limits(out, cfg, [&](pccd_body **o) {
    pccd::motion::check_body_size(nv, "vertices");
    auto tris = triangles_of(triangles, nt);
    new_mesh(o, points(), std::move(tris));
  });
}

const pccd::motion::Mesh_body &edge_owner(const pccd_body *b, size_t i) {
  require(b, "b");
  const size_t n = b->mesh ? b->mesh->edges().size() : 0;
  if (i >= n)
    throw Input_error("i: edge " + std::to_string(i) + " out of range (the body has " +
                      std::to_string(n) + " edges)");
  return *b->mesh;
}

}  // namespace

extern "C" {

PCCD_API int pccd_body_new_mesh_d(pccd_body **out, const double *vertices, size_t nv,
                                  const unsigned int *triangles, size_t nt) {
  return guard(__func__, [&] {
    return mesh_under_limits(out, nullptr, nv, [&] { return points_d(vertices, nv, "vertices"); },
                             triangles, nt);
  });
}

PCCD_API int pccd_body_new_mesh_s(pccd_body **out, const char *const *vertices, size_t nv,
                                  const unsigned int *triangles, size_t nt) {
  return guard(__func__, [&] {
    return mesh_under_limits(out, nullptr, nv, [&] { return points_s(vertices, nv, "vertices"); },
                             triangles, nt);
  });
}

PCCD_API int pccd_body_new_spheres_d(pccd_body **out, const double *centers,
                                     const double *radii, size_t n) {
  return guard(__func__, [&] {
    require(out, "out");
    *out = nullptr;
    pccd::motion::check_body_size(n, "centers");
    if (n > 0) require(radii, "radii");
    auto c = points_d(centers, n, "centers");
    std::vector<Rational> r(n);
    for (size_t i = 0; i < n; ++i)
      r[i] = pccd::arith::rational_from_double(radii[i], place("radii", {i}));
    return new_spheres(out, std::move(c), std::move(r));
  });
}

PCCD_API int pccd_body_new_spheres_s(pccd_body **out, const char *const *centers,
                                     const char *const *radii, size_t n) {
  return guard(__func__, [&] {
    require(out, "out");
    *out = nullptr;
    pccd::motion::check_body_size(n, "centers");
    if (n > 0) require(radii, "radii");
    auto c = points_s(centers, n, "centers");
    std::vector<Rational> r(n);
    for (size_t i = 0; i < n; ++i) r[i] = number_s(radii[i], place("radii", {i}));
    return new_spheres(out, std::move(c), std::move(r));
  });
}

PCCD_API int pccd_body_new_solid(pccd_body **out, const pccd_body *mesh) {
  return guard(__func__, [&] {
    require(out, "out");
    *out = nullptr;
    require(mesh, "mesh");
    if (!mesh->mesh) throw Input_error("mesh: a sphere body is not a mesh (its balls are solid already)");
    // The same vertices and triangles: the body data and hierarchy are shared.
    auto body = std::make_unique<pccd_body>();
    body->mesh = std::make_shared<const pccd::motion::Mesh_body>(mesh->mesh->vertices(),
                                                                 mesh->mesh->triangles(), true);
    body->data = pccd::narrow::same_geometry(*mesh->data, body->mesh);
    body->biggest = mesh->biggest;
    *out = body.release();
    return PCCD_OK;
  });
}

PCCD_API int pccd_body_solid(const pccd_body *b, int *solid) {
  return pccd::api::getter(__func__, b, "b", solid, "solid",
                           [&] { return !b->mesh || b->mesh->solid() ? 1 : 0; });
}

PCCD_API int pccd_body_new_mesh_cfg_d(pccd_body **out, const double *vertices, size_t nv,
                                      const unsigned int *triangles, size_t nt,
                                      const pccd_config *cfg) {
  return guard(__func__, [&] {
    return mesh_under_limits(out, cfg, nv, [&] { return points_d(vertices, nv, "vertices"); },
                             triangles, nt);
  });
}

PCCD_API int pccd_body_new_mesh_cfg_s(pccd_body **out, const char *const *vertices, size_t nv,
                                      const unsigned int *triangles, size_t nt,
                                      const pccd_config *cfg) {
  return guard(__func__, [&] {
    return mesh_under_limits(out, cfg, nv, [&] { return points_s(vertices, nv, "vertices"); },
                             triangles, nt);
  });
}

PCCD_API void pccd_body_free(pccd_body *b) { delete b; }

PCCD_API int pccd_body_kind(const pccd_body *b, int *kind) {
  return pccd::api::getter(__func__, b, "b", kind, "kind",
                                [&] { return b->mesh ? PCCD_BODY_MESH : PCCD_BODY_SPHERES; });
}

PCCD_API int pccd_body_counts(const pccd_body *b, size_t *vertices_or_spheres, size_t *edges,
                              size_t *triangles) {
  return guard(__func__, [&] {
    require(b, "b");
    const auto *m = b->mesh.get();
    if (vertices_or_spheres)
      *vertices_or_spheres = m ? m->vertices().size() : b->spheres->centers().size();
    if (edges) *edges = m ? m->edges().size() : 0;
    if (triangles) *triangles = m ? m->triangles().size() : 0;
    return PCCD_OK;
  });
}

PCCD_API int pccd_body_edge(const pccd_body *b, size_t i, size_t v[2]) {
  return guard(__func__, [&] {
    const auto &m = edge_owner(b, i);
    require(v, "v");
    v[0] = m.edges()[i][0];
    v[1] = m.edges()[i][1];
    return PCCD_OK;
  });
}

PCCD_API int pccd_body_edge_triangles(const pccd_body *b, size_t i, size_t *tris, size_t cap,
                                      size_t *count) {
  return guard(__func__, [&] {
    size_t n = 0;
    const uint32_t *first = edge_owner(b, i).edge_triangles(i, &n);
    if (count) *count = n;
    if (!tris || cap < n)
      throw pccd::api::Range_error("tris: room for " + std::to_string(cap) + " triangles, " +
                                   std::to_string(n) + " needed");
    for (size_t k = 0; k < n; ++k) tris[k] = first[k];
    return PCCD_OK;
  });
}

}  // extern "C"
