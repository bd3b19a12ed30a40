// pccd_motion_*: exact rigid motions (lib/motion). Validates and converts the C inputs,
// calls lib/motion, maps errors; no algorithm here. Every setter builds its new value
// completely before assigning it, so a failed call leaves the motion unchanged.
#include <array>
#include <cstring>
#include <string>
#include <vector>

#include "api/guard.h"
#include "api/motion_handle.h"
#include "motion/standard_motions.h"

using pccd::api::guard;
using pccd::api::require;
using pccd::arith::Input_error;
using pccd::arith::Limit_error;
using pccd::arith::Rational;
using pccd::motion::Poly_q;
using pccd::motion::Vec3_q;

namespace {

const char *const kAxisNames[] = {"x", "y", "z"};
const char *const kQuatNames[] = {"w", "x", "y", "z"};

// "translation y", "rotation w": the name of one coordinate polynomial in messages.
std::string poly_name(const char *what, size_t index) {
  const char *const *names = std::strcmp(what, "rotation") == 0 ? kQuatNames : kAxisNames;
  return std::string(what) + " " + names[index];
}

// Checks the handle, the index (< count) and the degree limit of a coefficient list.
void check_poly_args(const pccd_motion *m, const char *what, const char *index_name,
                     size_t index, size_t count, const void *coeffs, size_t n) {
  require(m, "motion");
  if (index >= count)
    throw Input_error(std::string(index_name) + " " + std::to_string(index) +
                      " out of range (0.." + std::to_string(count - 1) + ")");
  if (n > PCCD_MAX_TRAJ_DEGREE + 1)
    throw Limit_error(poly_name(what, index) + ": degree " + std::to_string(n - 1) +
                      " exceeds the limit of " + std::to_string(PCCD_MAX_TRAJ_DEGREE));
  if (n > 0) require(coeffs, "coeffs");
}

std::string coeff_place(const char *what, size_t index, size_t i) {
  return poly_name(what, index) + " coefficient " + std::to_string(i);
}

Poly_q poly_d(const char *what, size_t index, const double *coeffs, size_t n) {
  std::vector<Rational> c;
  for (size_t i = 0; i < n; ++i)
    c.push_back(pccd::arith::rational_from_double(coeffs[i], coeff_place(what, index, i)));
  return Poly_q(std::move(c));
}

Poly_q poly_s(const char *what, size_t index, const char *const *coeffs, size_t n) {
  std::vector<Rational> c;
  for (size_t i = 0; i < n; ++i) {
    const std::string place = coeff_place(what, index, i);
    if (!coeffs[i]) throw Input_error(place + " is NULL");
    c.push_back(pccd::arith::parse_rational(coeffs[i], place));
  }
  return Poly_q(std::move(c));
}

// One rational string named `name` ("tau0", "t").
Rational number_s(const char *text, const std::string &name) {
  if (!text) throw Input_error(name + " is NULL");
  return pccd::arith::parse_rational(text, name);
}

// values[first .. first+2] as a vector; entries are named name[first + i].
Vec3_q vec_d(const double *values, const char *name, size_t first = 0) {
  require(values, name);
  Vec3_q v;
  for (size_t i = 0; i < 3; ++i)
    v[i] = pccd::arith::rational_from_double(
        values[first + i], std::string(name) + "[" + std::to_string(first + i) + "]");
  return v;
}

Vec3_q vec_s(const char *const *values, const char *name, size_t first = 0) {
  require(values, name);
  Vec3_q v;
  for (size_t i = 0; i < 3; ++i)
    v[i] = number_s(values[first + i], std::string(name) + "[" + std::to_string(first + i) + "]");
  return v;
}

}  // namespace

extern "C" {

PCCD_API int pccd_motion_new(pccd_motion **out) {
  return pccd::api::new_handle("pccd_motion_new", out);
}

PCCD_API void pccd_motion_free(pccd_motion *m) { delete m; }

PCCD_API int pccd_motion_copy(pccd_motion **out, const pccd_motion *m) {
  return guard("pccd_motion_copy", [&] {
    require(out, "out");
    *out = nullptr;
    require(m, "motion");
    *out = new pccd_motion(*m);
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_translation_d(pccd_motion *m, size_t axis, const double *coeffs,
                                           size_t n) {
  return guard("pccd_motion_set_translation_d", [&] {
    check_poly_args(m, "translation", "axis", axis, 3, coeffs, n);
    m->m.set_translation(static_cast<int>(axis), poly_d("translation", axis, coeffs, n));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_translation_s(pccd_motion *m, size_t axis,
                                           const char *const *coeffs, size_t n) {
  return guard("pccd_motion_set_translation_s", [&] {
    check_poly_args(m, "translation", "axis", axis, 3, coeffs, n);
    m->m.set_translation(static_cast<int>(axis), poly_s("translation", axis, coeffs, n));
    return PCCD_OK;
  });
}

// The rotation cannot be edited once a body-side offset turns with it (polyccd.h).
static int rotation_locked(const char *fn, const pccd_motion *m) {
  if (!m->m.has_body_offset()) return 0;
  pccd::api::set_error(fn, "a body-side pose with a nonzero offset was composed into this "
                           "motion, so its rotation can no longer be set component by "
                           "component (set the rotation first, then compose)");
  return PCCD_ESTATE;
}

PCCD_API int pccd_motion_set_rotation_d(pccd_motion *m, size_t component, const double *coeffs,
                                        size_t n) {
  return guard("pccd_motion_set_rotation_d", [&]() -> int {
    check_poly_args(m, "rotation", "component", component, 4, coeffs, n);
    Poly_q f = poly_d("rotation", component, coeffs, n);
    if (int rc = rotation_locked("pccd_motion_set_rotation_d", m)) return rc;
    m->m.set_rotation(static_cast<int>(component), std::move(f));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_rotation_s(pccd_motion *m, size_t component,
                                        const char *const *coeffs, size_t n) {
  return guard("pccd_motion_set_rotation_s", [&]() -> int {
    check_poly_args(m, "rotation", "component", component, 4, coeffs, n);
    Poly_q f = poly_s("rotation", component, coeffs, n);
    if (int rc = rotation_locked("pccd_motion_set_rotation_s", m)) return rc;
    m->m.set_rotation(static_cast<int>(component), std::move(f));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_linear_translation_d(pccd_motion *m, const double p0[3],
                                                  const double p1[3]) {
  return guard("pccd_motion_set_linear_translation_d", [&] {
    require(m, "motion");
    m->m.set_translation(pccd::motion::linear_path(vec_d(p0, "p0"), vec_d(p1, "p1")));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_linear_translation_s(pccd_motion *m, const char *const p0[3],
                                                  const char *const p1[3]) {
  return guard("pccd_motion_set_linear_translation_s", [&] {
    require(m, "motion");
    m->m.set_translation(pccd::motion::linear_path(vec_s(p0, "p0"), vec_s(p1, "p1")));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_bezier_translation_d(pccd_motion *m, const double ctrl[12]) {
  return guard("pccd_motion_set_bezier_translation_d", [&] {
    require(m, "motion");
    std::array<Vec3_q, 4> c;
    for (size_t k = 0; k < 4; ++k) c[k] = vec_d(ctrl, "ctrl", 3 * k);
    m->m.set_translation(pccd::motion::bezier_path(c));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_bezier_translation_s(pccd_motion *m, const char *const ctrl[12]) {
  return guard("pccd_motion_set_bezier_translation_s", [&] {
    require(m, "motion");
    std::array<Vec3_q, 4> c;
    for (size_t k = 0; k < 4; ++k) c[k] = vec_s(ctrl, "ctrl", 3 * k);
    m->m.set_translation(pccd::motion::bezier_path(c));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_hermite_translation_d(pccd_motion *m, const double p0[3],
                                                   const double v0[3], const double p1[3],
                                                   const double v1[3]) {
  return guard("pccd_motion_set_hermite_translation_d", [&] {
    require(m, "motion");
    m->m.set_translation(pccd::motion::hermite_path(vec_d(p0, "p0"), vec_d(v0, "v0"),
                                                    vec_d(p1, "p1"), vec_d(v1, "v1")));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_hermite_translation_s(pccd_motion *m, const char *const p0[3],
                                                   const char *const v0[3],
                                                   const char *const p1[3],
                                                   const char *const v1[3]) {
  return guard("pccd_motion_set_hermite_translation_s", [&] {
    require(m, "motion");
    m->m.set_translation(pccd::motion::hermite_path(vec_s(p0, "p0"), vec_s(v0, "v0"),
                                                    vec_s(p1, "p1"), vec_s(v1, "v1")));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_axis_rotation_s(pccd_motion *m, const char *const axis[3],
                                             const char *const center[3], const char *tau0,
                                             const char *tau1) {
  return guard("pccd_motion_set_axis_rotation_s", [&] {
    require(m, "motion");
    m->m = pccd::motion::axis_rotation(vec_s(axis, "axis"), vec_s(center, "center"),
                                       number_s(tau0, "tau0"), number_s(tau1, "tau1"));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_screw_s(pccd_motion *m, const char *const axis[3],
                                     const char *const center[3], const char *tau0,
                                     const char *tau1, const char *advance) {
  return guard("pccd_motion_set_screw_s", [&] {
    require(m, "motion");
    m->m = pccd::motion::screw(vec_s(axis, "axis"), vec_s(center, "center"),
                               number_s(tau0, "tau0"), number_s(tau1, "tau1"),
                               number_s(advance, "advance"));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_compose_pose_s(pccd_motion *m, int side, const char *const quat[4],
                                        const char *const offset[3]) {
  return guard("pccd_motion_compose_pose_s", [&] {
    require(m, "motion");
    if (side != PCCD_POSE_BODY && side != PCCD_POSE_WORLD)
      throw Input_error("side is " + std::to_string(side) + "; expected 0 (body) or 1 (world)");
    require(quat, "quat");
    pccd::motion::Quat_q q;
    for (size_t i = 0; i < 4; ++i) q[i] = number_s(quat[i], "quat[" + std::to_string(i) + "]");
    const Vec3_q p = vec_s(offset, "offset");
    pccd::motion::Rigid_motion next = m->m;
    if (side == PCCD_POSE_BODY) next.compose_body(q, p); else next.compose_world(q, p);
    m->m = std::move(next);
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_validate(const pccd_motion *m) {
  return guard("pccd_motion_validate", [&] {
    require(m, "motion");
    m->m.validate();
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_position_s(const pccd_motion *m, const char *const p[3], const char *t,
                                    char *buf, size_t cap, size_t *needed) {
  return guard("pccd_motion_position_s", [&] {
    require(m, "motion");
    const Vec3_q x = m->m.position(vec_s(p, "p"), number_s(t, "t"));
    std::string text;
    for (int i = 0; i < 3; ++i) text += (i ? " " : "") + pccd::arith::to_string(x[i]);
    return pccd::api::write_text("pccd_motion_position_s", text, buf, cap, needed);
  });
}

}  // extern "C"
