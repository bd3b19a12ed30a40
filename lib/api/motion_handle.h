// The opaque pccd_motion handle behind polyccd.h: one exact rigid motion, and the
// validated data derived from it (narrow::Motion_data), kept from the first scene or
// index that uses the motion until the motion changes: a caller that checks many body
// pairs with the same motion handles pays for the derivation and the validation once.
#pragma once
#include <memory>
#include <mutex>
#include <utility>

#include "api/limits.h"
#include "narrow/moving_body.h"

struct pccd_motion {
  pccd_motion() = default;
  pccd_motion(const pccd_motion &o) : m(o.m), known_valid(o.known_valid), rn(o.rn) {}
  // (the copy derives its own data)
  explicit pccd_motion(pccd::motion::Rigid_motion mm, bool valid = false)
      : m(std::move(mm)), known_valid(valid) {}

  pccd::motion::Rigid_motion m;  // starts as the identity (stationary) motion; change it
                                 // only through pccd::api::edit (which drops the data)
  bool known_valid = false;      // m is valid by construction (a kinematic chain's link
                                 // motion: motion/chain.h), so its derivation skips the
                                 // exact vanishing test; dropped by edit
  mutable std::shared_ptr<const pccd::motion::Mat3_poly> rn;  // rotation_numerator(m.r) when its
                                                      // maker had it; dropped by edit
  mutable std::mutex mu;
  mutable std::shared_ptr<const pccd::narrow::Motion_data> data;  // of m; null: not yet
  mutable std::shared_ptr<const pccd::api::Biggest_number> biggest;  // of m; null: not yet
};

namespace pccd::api {

// The motion to change (its derived data is dropped first).
inline motion::Rigid_motion &edit(pccd_motion *m) {
  std::lock_guard<std::mutex> lock(m->mu);
  m->data.reset();
  m->biggest.reset();
  m->known_valid = false;
  m->rn.reset();
  return m->m;
}

// The largest number of m's polynomials (config.max_number_bits), found on the first call
// and kept until the motion changes.
inline std::shared_ptr<const Biggest_number> motion_biggest(const pccd_motion *m) {
  std::lock_guard<std::mutex> lock(m->mu);
  if (!m->biggest) m->biggest = std::make_shared<const Biggest_number>(biggest_in(m->m));
  return m->biggest;
}

// The validated data of m's current value (NULL m: the stationary motion), derived on
// the first call; null when the motion is invalid (the solve then reports it, as for
// any motion it derives itself).
inline std::shared_ptr<const narrow::Motion_data> motion_data(const pccd_motion *m) {
  if (!m) return narrow::identity_motion();
  std::lock_guard<std::mutex> lock(m->mu);
  if (!m->data) {
    try {
      m->data = narrow::prepare_motion(m->m, m->known_valid, m->rn.get());
      m->rn.reset();  // in the data now
    } catch (const arith::Input_error &) {
      return nullptr;
    }
  }
  return m->data;
}

}  // namespace pccd::api
