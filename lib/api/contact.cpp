// pccd_contact_geometry_compute, pccd_contact_geometry_exact: the contact point and normal of two
// features at their first contact time (polyccd.h; the definitions and the enclosures
// are lib/narrow/contact_geometry.h's).
#include <string>

#include "api/body_handle.h"
#include "api/guard.h"
#include "api/motion_handle.h"
#include "narrow/contact_geometry.h"
#include "polyccd.h"

namespace {

using pccd::arith::Input_error;
using pccd::arith::Rational;
using pccd::narrow::Contact_geometry;

// Body `name` (a or b) on motion `mname` (ma or mb; NULL: stationary), validated.
pccd::narrow::Moving_body moving(const pccd_body *body, const char *name, const pccd_motion *m,
                                 const char *mname) {
  pccd::api::require(body, name);
  auto data = pccd::api::motion_data(m);
  if (!data) {
    try {
      m->m.validate();  // throws the message of the invalid motion
    } catch (const Input_error &e) {
      throw Input_error(std::string(mname) + ": " + e.what());
    }
    throw pccd::arith::Internal_error("a motion without data validated");
  }
  return pccd::narrow::prepare_body(body->data, std::move(data));
}

Rational time_s(const char *text, const char *where) {
  pccd::api::require(text, where);
  return pccd::arith::parse_rational(text, where);
}

Contact_geometry compute(const pccd_body *a, const pccd_motion *ma, int feature_a, size_t index_a,
                         const pccd_body *b, const pccd_motion *mb, int feature_b, size_t index_b,
                         const char *t_lo, const char *t_hi) {
  const auto A = moving(a, "a", ma, "ma");
  const auto B = moving(b, "b", mb, "mb");
  const Rational lo = time_s(t_lo, "t_lo"), hi = time_s(t_hi, "t_hi");
  pccd::narrow::Feature_arg fa{feature_a, index_a, "feature_a", "index_a"};
  pccd::narrow::Feature_arg fb{feature_b, index_b, "feature_b", "index_b"};
  return pccd::narrow::contact_geometry(A, fa, B, fb, lo, hi);
}

}  // namespace

extern "C" {

PCCD_API int pccd_contact_geometry_compute(const pccd_body *a, const pccd_motion *ma, int feature_a,
                                   size_t index_a, const pccd_body *b, const pccd_motion *mb,
                                   int feature_b, size_t index_b, const char *t_lo,
                                   const char *t_hi, pccd_contact_geometry *out) {
  return pccd::api::guard(__func__, [&] {
    pccd::api::require(out, "out");
    if (out->struct_size != sizeof(pccd_contact_geometry))
      throw Input_error("out.struct_size: " + std::to_string(out->struct_size) +
                        " is not sizeof(pccd_contact_geometry) = " +
                        std::to_string(sizeof(pccd_contact_geometry)));
    const Contact_geometry g = compute(a, ma, feature_a, index_a, b, mb, feature_b, index_b, t_lo, t_hi);
    for (int k = 0; k < 3; ++k) {
      out->point_lo[k] = g.point[k].lo;
      out->point_hi[k] = g.point[k].hi;
      const bool has = g.normal_state != pccd::narrow::Normal_state::none;
      out->normal_lo[k] = has ? g.normal[k].lo : 0.0;
      out->normal_hi[k] = has ? g.normal[k].hi : 0.0;
    }
    out->normal_state = static_cast<int>(g.normal_state);
    out->exact = g.exact ? 1 : 0;
    return PCCD_OK;
  });
}

PCCD_API int pccd_contact_geometry_exact(const pccd_body *a, const pccd_motion *ma, int feature_a,
                                         size_t index_a, const pccd_body *b,
                                         const pccd_motion *mb, int feature_b, size_t index_b,
                                         const char *t_lo, const char *t_hi, int which,
                                         char *buf, size_t cap, size_t *needed) {
  return pccd::api::guard(__func__, [&] {
    if (which != 0 && which != 1)
      throw Input_error("which: " + std::to_string(which) + " is not 0 (point) or 1 (normal)");
    const Contact_geometry g = compute(a, ma, feature_a, index_a, b, mb, feature_b, index_b, t_lo, t_hi);
    if (!g.exact)
      throw pccd::api::State_error("t_lo, t_hi: the time is not exact (t_lo < t_hi): only "
                                   "enclosures are defined (pccd_contact_geometry_compute)");
    if (which == 1 && g.normal_state != pccd::narrow::Normal_state::enclosed)
      throw pccd::api::State_error("which: no normal is defined for these features at this time");
    const auto &v = which == 0 ? g.point_q : g.normal_q;
    std::string text;
    for (int k = 0; k < 3; ++k) text += (k ? " " : "") + pccd::arith::to_string(v[k]);
    return pccd::api::write_text(text, buf, cap, needed);
  });
}

}  // extern "C"
