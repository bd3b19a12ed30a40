// pccd_motion_*: exact rigid motions (lib/motion). Validates and converts the C inputs,
// calls lib/motion, maps errors; no algorithm here. Every setter builds its new value
// completely before assigning it, so a failed call leaves the motion unchanged.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "api/guard.h"
#include "api/config.h"
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

using pccd::api::place;

// Checks the handle, the index (< count) and the degree limit of a coefficient list.
// what is "translation" (index = axis) or "rotation" (index = component); coefficient i
// is named what[index][i], as Python's Motion(translation, rotation) nests it.
void check_poly_args(const pccd_motion *m, const char *what, const char *index_name,
                     size_t index, size_t count, const void *coeffs, size_t n) {
  require(m, "m");
  if (index >= count)
    throw Input_error(std::string(index_name) + ": " + std::to_string(index) +
                      " out of range (0.." + std::to_string(count - 1) + ")");
  if (n > PCCD_MAX_TRAJ_DEGREE + 1)
    throw Limit_error(place(what, {index}) + ": degree " + std::to_string(n - 1) +
                      " exceeds the limit of " + std::to_string(PCCD_MAX_TRAJ_DEGREE));
  if (n > 0) require(coeffs, "coeffs");
}

Poly_q poly_d(const char *what, size_t index, const double *coeffs, size_t n) {
  std::vector<Rational> c;
  for (size_t i = 0; i < n; ++i)
    c.push_back(pccd::arith::rational_from_double(coeffs[i], place(what, {index, i})));
  return Poly_q(std::move(c));
}

// One rational string named `where` ("tau0", "quat[2]").
Rational number_s(const char *text, const std::string &where) {
  require(text, where);
  return pccd::arith::parse_rational(text, where);
}

Poly_q poly_s(const char *what, size_t index, const char *const *coeffs, size_t n) {
  std::vector<Rational> c;
  for (size_t i = 0; i < n; ++i) c.push_back(number_s(coeffs[i], place(what, {index, i})));
  return Poly_q(std::move(c));
}

// The vector values[0..2], entries named name[i]; or, for point k of a flat array of
// points (ctrl), values[3k..3k+2] named name[k][i].
const size_t kNo_point = static_cast<size_t>(-1);

std::string entry(const char *name, size_t k, size_t i) {
  return k == kNo_point ? place(name, {i}) : place(name, {k, i});
}

Vec3_q vec_d(const double *values, const char *name, size_t k = kNo_point) {
  require(values, name);
  const size_t first = k == kNo_point ? 0 : 3 * k;
  Vec3_q v;
  for (size_t i = 0; i < 3; ++i)
    v[i] = pccd::arith::rational_from_double(values[first + i], entry(name, k, i));
  return v;
}

Vec3_q vec_s(const char *const *values, const char *name, size_t k = kNo_point) {
  require(values, name);
  const size_t first = k == kNo_point ? 0 : 3 * k;
  Vec3_q v;
  for (size_t i = 0; i < 3; ++i) v[i] = number_s(values[first + i], entry(name, k, i));
  return v;
}

// pccd_motion_compose (cfg NULL: no limits) and pccd_motion_compose_cfg.
int compose(const char *fn, pccd_motion **out, const pccd_motion *outer, const pccd_motion *inner,
            const pccd_config *cfg) {
  return guard(fn, [&] {
    require(out, "out");
    *out = nullptr;
    require(outer, "outer");
    require(inner, "inner");
    // the config's rules (struct_size, ...) as for any call; only its limits are used
    const pccd::api::Call_limits limits = pccd::api::read_call(cfg).limits;
    if (cfg) {
      limits.check(*pccd::api::motion_biggest(outer), "outer.");
      limits.check(*pccd::api::motion_biggest(inner), "inner.");
    }
    const pccd::api::Call_budget budget(limits.work);
    pccd::motion::Rigid_motion m = pccd::motion::compose_motions(outer->m, inner->m);
    // The same limit as the setters, on every polynomial of the result.
    int deg = 0;
    for (const Poly_q &c : m.r) deg = std::max(deg, c.degree());
    for (int i = 0; i < 3; ++i) deg = std::max(deg, std::max(m.o[i].degree(), m.b[i].degree()));
    if (deg > PCCD_MAX_TRAJ_DEGREE)
      throw Limit_error("outer, inner: the composite motion has a polynomial of degree " +
                        std::to_string(deg) + ", above the limit of " +
                        std::to_string(PCCD_MAX_TRAJ_DEGREE));
    *out = new pccd_motion{std::move(m)};
    return PCCD_OK;
  });
}

// pccd_motion_validate (cfg NULL: no limits) and pccd_motion_validate_cfg.
int validate(const char *fn, const pccd_motion *m, const pccd_config *cfg) {
  return guard(fn, [&] {
    require(m, "m");
    // the config's rules (struct_size, ...) as for any call; only its limits are used
    const pccd::api::Call_limits limits = pccd::api::read_call(cfg).limits;
    if (cfg) limits.check(*pccd::api::motion_biggest(m), "m.");
    const pccd::api::Call_budget budget(limits.work);
    m->m.validate();
    return PCCD_OK;
  });
}

// pccd_motion_position_s (cfg NULL: no limits at all, as before the limits existed) and
// pccd_motion_position_cfg_s.
int position(const char *fn, const pccd_motion *m, const char *const p[3], const char *t,
             const pccd_config *cfg, char *buf, size_t cap, size_t *needed) {
  return guard(fn, [&] {
    require(m, "m");
    // the config's rules (struct_size, ...) as for any call; only its limits are used
    const pccd::api::Call_limits limits = pccd::api::read_call(cfg).limits;
    const Vec3_q point = vec_s(p, "p");
    const Rational time = number_s(t, "t");
    if (cfg) {  // the input limit: the point, the time and the motion
      pccd::api::Biggest_number big;
      for (size_t k = 0; k < 3; ++k) big.see(point[k], [&] { return place("p", {k}); });
      big.see(time, [] { return std::string("t"); });
      big.see(*pccd::api::motion_biggest(m), "m.");
      limits.check(big);
    }
    const pccd::api::Call_budget budget(limits.work);
    const Vec3_q x = m->m.position(point, time);
    std::string text;
    for (int i = 0; i < 3; ++i) text += (i ? " " : "") + pccd::arith::to_string(x[i]);
    return pccd::api::write_text(text, buf, cap, needed);
  });
}

// The quaternion values[0..3], entries named name[i].
pccd::motion::Quat_q quat_d(const double *values, const char *name) {
  require(values, name);
  pccd::motion::Quat_q q;
  for (size_t i = 0; i < 4; ++i) q[i] = pccd::arith::rational_from_double(values[i], place(name, {i}));
  return q;
}

pccd::motion::Quat_q quat_s(const char *const *values, const char *name) {
  require(values, name);
  pccd::motion::Quat_q q;
  for (size_t i = 0; i < 4; ++i) q[i] = number_s(values[i], place(name, {i}));
  return q;
}

// The translation and rotation of a row-major 4x4 pose matrix named `name`.
std::pair<Vec3_q, pccd::motion::Quat_q> pose_of_matrix(const double *M, const char *name) {
  require(M, name);
  for (size_t c = 0; c < 4; ++c)
    if (M[12 + c] != (c == 3 ? 1.0 : 0.0))
      throw Input_error(place(name, {3, c}) + ": the last row of a pose matrix must be exactly "
                        "0 0 0 1, got " + pccd::arith::to_string(pccd::arith::rational_from_double(
                                              M[12 + c], place(name, {3, c}))));
  Vec3_q p;
  double R[9];
  for (size_t r = 0; r < 3; ++r) {
    p[r] = pccd::arith::rational_from_double(M[4 * r + 3], place(name, {r, 3}));
    for (size_t c = 0; c < 3; ++c) R[3 * r + c] = M[4 * r + c];
  }
  return {p, pccd::motion::quaternion_of_rotation(R, name)};
}

}  // namespace

extern "C" {

PCCD_API int pccd_motion_new(pccd_motion **out) {
  return pccd::api::new_handle(__func__, out);
}

PCCD_API void pccd_motion_free(pccd_motion *m) { delete m; }

PCCD_API int pccd_motion_copy(pccd_motion **out, const pccd_motion *m) {
  return guard(__func__, [&] {
    require(out, "out");
    *out = nullptr;
    require(m, "m");
    *out = new pccd_motion(*m);
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_translation_d(pccd_motion *m, size_t axis, const double *coeffs,
                                           size_t n) {
  return guard(__func__, [&] {
    check_poly_args(m, "translation", "axis", axis, 3, coeffs, n);
    pccd::api::edit(m).set_translation(static_cast<int>(axis), poly_d("translation", axis, coeffs, n));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_translation_s(pccd_motion *m, size_t axis,
                                           const char *const *coeffs, size_t n) {
  return guard(__func__, [&] {
    check_poly_args(m, "translation", "axis", axis, 3, coeffs, n);
    pccd::api::edit(m).set_translation(static_cast<int>(axis), poly_s("translation", axis, coeffs, n));
    return PCCD_OK;
  });
}

// The rotation cannot be edited once a body-side offset turns with it (polyccd.h).
static void require_rotation_settable(const pccd_motion *m) {
  if (m->m.has_body_offset())
    throw pccd::api::State_error(
        "m: a body-side pose with a nonzero offset, or a motion with a turning outer factor, "
        "was composed into this motion, so its rotation can no longer be set component by "
        "component (set the rotation first, then compose)");
}

PCCD_API int pccd_motion_set_rotation_d(pccd_motion *m, size_t component, const double *coeffs,
                                        size_t n) {
  return guard(__func__, [&]() -> int {
    check_poly_args(m, "rotation", "component", component, 4, coeffs, n);
    Poly_q f = poly_d("rotation", component, coeffs, n);
    require_rotation_settable(m);
    pccd::api::edit(m).set_rotation(static_cast<int>(component), std::move(f));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_rotation_s(pccd_motion *m, size_t component,
                                        const char *const *coeffs, size_t n) {
  return guard(__func__, [&]() -> int {
    check_poly_args(m, "rotation", "component", component, 4, coeffs, n);
    Poly_q f = poly_s("rotation", component, coeffs, n);
    require_rotation_settable(m);
    pccd::api::edit(m).set_rotation(static_cast<int>(component), std::move(f));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_linear_translation_d(pccd_motion *m, const double p0[3],
                                                  const double p1[3]) {
  return guard(__func__, [&] {
    require(m, "m");
    const Vec3_q a = vec_d(p0, "p0"), b = vec_d(p1, "p1");  // in argument order
    pccd::api::edit(m).set_translation(pccd::motion::linear_path(a, b));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_linear_translation_s(pccd_motion *m, const char *const p0[3],
                                                  const char *const p1[3]) {
  return guard(__func__, [&] {
    require(m, "m");
    const Vec3_q a = vec_s(p0, "p0"), b = vec_s(p1, "p1");  // in argument order
    pccd::api::edit(m).set_translation(pccd::motion::linear_path(a, b));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_bezier_translation_d(pccd_motion *m, const double ctrl[12]) {
  return guard(__func__, [&] {
    require(m, "m");
    std::array<Vec3_q, 4> c;
    for (size_t k = 0; k < 4; ++k) c[k] = vec_d(ctrl, "ctrl", k);
    pccd::api::edit(m).set_translation(pccd::motion::bezier_path(c));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_bezier_translation_s(pccd_motion *m, const char *const ctrl[12]) {
  return guard(__func__, [&] {
    require(m, "m");
    std::array<Vec3_q, 4> c;
    for (size_t k = 0; k < 4; ++k) c[k] = vec_s(ctrl, "ctrl", k);
    pccd::api::edit(m).set_translation(pccd::motion::bezier_path(c));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_hermite_translation_d(pccd_motion *m, const double p0[3],
                                                   const double v0[3], const double p1[3],
                                                   const double v1[3]) {
  return guard(__func__, [&] {
    require(m, "m");
    // Converted in argument order, so an error names the first bad argument.
    const Vec3_q a = vec_d(p0, "p0"), va = vec_d(v0, "v0"), b = vec_d(p1, "p1"), vb = vec_d(v1, "v1");
    pccd::api::edit(m).set_translation(pccd::motion::hermite_path(a, va, b, vb));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_hermite_translation_s(pccd_motion *m, const char *const p0[3],
                                                   const char *const v0[3],
                                                   const char *const p1[3],
                                                   const char *const v1[3]) {
  return guard(__func__, [&] {
    require(m, "m");
    // Converted in argument order, so an error names the first bad argument.
    const Vec3_q a = vec_s(p0, "p0"), va = vec_s(v0, "v0"), b = vec_s(p1, "p1"), vb = vec_s(v1, "v1");
    pccd::api::edit(m).set_translation(pccd::motion::hermite_path(a, va, b, vb));
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_axis_rotation_s(pccd_motion *m, const char *const axis[3],
                                             const char *const center[3], const char *tau0,
                                             const char *tau1) {
  return guard(__func__, [&] {
    require(m, "m");
    // Converted in argument order, so an error names the first bad argument.
    const Vec3_q u = vec_s(axis, "axis"), c = vec_s(center, "center");
    const Rational a = number_s(tau0, "tau0"), b = number_s(tau1, "tau1");
    pccd::api::edit(m) = pccd::motion::axis_rotation(u, c, a, b);
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_screw_s(pccd_motion *m, const char *const axis[3],
                                     const char *const center[3], const char *tau0,
                                     const char *tau1, const char *advance) {
  return guard(__func__, [&] {
    require(m, "m");
    // Converted in argument order, so an error names the first bad argument.
    const Vec3_q u = vec_s(axis, "axis"), c = vec_s(center, "center");
    const Rational a = number_s(tau0, "tau0"), b = number_s(tau1, "tau1");
    const Rational h = number_s(advance, "advance");
    pccd::api::edit(m) = pccd::motion::screw(u, c, a, b, h);
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_between_d(pccd_motion *m, const double p0[3], const double q0[4],
                                       const double p1[3], const double q1[4]) {
  return guard(__func__, [&] {
    require(m, "m");
    // Converted one by one, in argument order (an error names the first bad input; the
    // order of a call's argument evaluation is unspecified in C++).
    const Vec3_q a = vec_d(p0, "p0");
    const pccd::motion::Quat_q qa = quat_d(q0, "q0");
    const Vec3_q b = vec_d(p1, "p1");
    const pccd::motion::Quat_q qb = quat_d(q1, "q1");
    pccd::api::edit(m) = pccd::motion::pose_between(a, qa, b, qb);
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_between_s(pccd_motion *m, const char *const p0[3],
                                       const char *const q0[4], const char *const p1[3],
                                       const char *const q1[4]) {
  return guard(__func__, [&] {
    require(m, "m");
    const Vec3_q a = vec_s(p0, "p0");  // in argument order, as above
    const pccd::motion::Quat_q qa = quat_s(q0, "q0");
    const Vec3_q b = vec_s(p1, "p1");
    const pccd::motion::Quat_q qb = quat_s(q1, "q1");
    pccd::api::edit(m) = pccd::motion::pose_between(a, qa, b, qb);
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_set_between_matrices_d(pccd_motion *m, const double M0[16],
                                                const double M1[16]) {
  return guard(__func__, [&] {
    require(m, "m");
    const auto [p0, q0] = pose_of_matrix(M0, "M0");
    const auto [p1, q1] = pose_of_matrix(M1, "M1");
    pccd::api::edit(m) = pccd::motion::pose_between(p0, q0, p1, q1);
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_compose_pose_s(pccd_motion *m, int side, const char *const quat[4],
                                        const char *const offset[3]) {
  return guard(__func__, [&] {
    require(m, "m");
    if (side != PCCD_POSE_BODY && side != PCCD_POSE_WORLD)
      throw Input_error("side: " + std::to_string(side) + " is not 0 (body) or 1 (world)");
    require(quat, "quat");
    pccd::motion::Quat_q q;
    for (size_t i = 0; i < 4; ++i) q[i] = number_s(quat[i], place("quat", {i}));
    const Vec3_q p = vec_s(offset, "offset");
    pccd::motion::Rigid_motion next = m->m;
    if (side == PCCD_POSE_BODY) next.compose_body(q, p); else next.compose_world(q, p);
    pccd::api::edit(m) = std::move(next);
    return PCCD_OK;
  });
}

PCCD_API int pccd_motion_compose(pccd_motion **out, const pccd_motion *outer,
                                 const pccd_motion *inner) {
  return compose(__func__, out, outer, inner, nullptr);
}

PCCD_API int pccd_motion_compose_cfg(pccd_motion **out, const pccd_motion *outer,
                                     const pccd_motion *inner, const pccd_config *cfg) {
  return compose(__func__, out, outer, inner, cfg);
}

PCCD_API int pccd_motion_validate(const pccd_motion *m) { return validate(__func__, m, nullptr); }

PCCD_API int pccd_motion_validate_cfg(const pccd_motion *m, const pccd_config *cfg) {
  return validate(__func__, m, cfg);
}

PCCD_API int pccd_motion_position_s(const pccd_motion *m, const char *const p[3], const char *t,
                                    char *buf, size_t cap, size_t *needed) {
  return position(__func__, m, p, t, nullptr, buf, cap, needed);
}

PCCD_API int pccd_motion_position_cfg_s(const pccd_motion *m, const char *const p[3], const char *t,
                                        const pccd_config *cfg, char *buf, size_t cap, size_t *needed) {
  return position(__func__, m, p, t, cfg, buf, cap, needed);
}

}  // extern "C"
