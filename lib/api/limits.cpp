// pccd_cancel_*, pccd_threads_usable, and the number sizes of the limits (api/limits.h).
#include "api/limits.h"

#include <cmath>

#include "api/config.h"
#include "api/guard.h"
#include "util/thread_pool.h"

using pccd::api::guard;
using pccd::api::place;
using pccd::api::require;
using pccd::arith::Input_error;
using pccd::arith::Rational;

namespace pccd::api {

size_t number_bits(const Rational &x) {
  return mpz_sizeinbase(x.get_num_mpz_t(), 2) + mpz_sizeinbase(x.get_den_mpz_t(), 2);
}

size_t number_bits(double x) { return number_bits(Rational(x)); }  // exact: mpq_set_d

Biggest_number biggest_in(const motion::Mesh_body &b) {
  Biggest_number out;
  const auto &v = b.vertices();
  for (size_t i = 0; i < v.size(); ++i)
    for (size_t k = 0; k < 3; ++k) out.see(v[i][k], [&] { return place("vertices", {i, k}); });
  return out;
}

Biggest_number biggest_in(const motion::Sphere_body &b) {
  Biggest_number out;
  const auto &c = b.centers();
  for (size_t i = 0; i < c.size(); ++i) {
    for (size_t k = 0; k < 3; ++k) out.see(c[i][k], [&] { return place("centers", {i, k}); });
    out.see(b.radii()[i], [&] { return place("radii", {i}); });
  }
  return out;
}

Biggest_number biggest_in(const motion::Rigid_motion &m) {
  Biggest_number out;
  for (size_t c = 0; c < 4; ++c)
    for (size_t i = 0; i < m.r[c].c.size(); ++i)
      out.see(m.r[c].c[i], [&] { return place("rotation", {c, i}); });
  for (size_t a = 0; a < 3; ++a) {
    for (size_t i = 0; i < m.o[a].c.size(); ++i)
      out.see(m.o[a].c[i], [&] { return place("translation", {a, i}); });
    for (size_t i = 0; i < m.b[a].c.size(); ++i)  // from composed poses
      out.see(m.b[a].c[i], [&] { return place("pose_offset", {a, i}); });
  }
  return out;
}

void Call_limits::check(const Biggest_number &b, const std::string &prefix) const {
  if (max_number_bits == 0 || b.bits <= max_number_bits) return;
  throw arith::Limit_error(prefix + b.place + ": a number of " + std::to_string(b.bits) +
                           " bits (numerator and denominator) exceeds config.max_number_bits = " +
                           std::to_string(max_number_bits) +
                           " (raise it, or set 0 for no limit, to solve this input)");
}

}  // namespace pccd::api

extern "C" {

PCCD_API int pccd_threads_usable(unsigned requested, unsigned *usable) {
  return guard(__func__, [&] {
    require(usable, "usable");
    *usable = pccd::util::usable_threads(pccd::api::checked_threads(requested, "requested"));
    return PCCD_OK;
  });
}

PCCD_API int pccd_cancel_new(pccd_cancel **out) { return pccd::api::new_handle(__func__, out); }

PCCD_API void pccd_cancel_free(pccd_cancel *c) { delete c; }

PCCD_API int pccd_cancel_set(pccd_cancel *c) {
  // No guard: this must stay async-signal-safe (no locale, no allocation, no throw).
  if (!c) return PCCD_EINVAL;
  c->flag.set();
  return PCCD_OK;
}

PCCD_API int pccd_cancel_reset(pccd_cancel *c) {
  return guard(__func__, [&] {
    require(c, "c");
    c->flag.reset();
    return PCCD_OK;
  });
}

PCCD_API int pccd_cancel_is_set(const pccd_cancel *c, int *is_set) {
  return pccd::api::getter(__func__, c, "c", is_set, "is_set",
                                [&] { return c->flag.is_set() ? 1 : 0; });
}

}  // extern "C"
