// The limits of one call (polyccd.h, pccd_config): the input limit on number sizes,
// checked up front, and the work limits (util/work_budget.h), opened for the call.
#pragma once
#include <cstddef>
#include <optional>
#include <string>

#include "arith/rational.h"
#include "motion/body.h"
#include "motion/rigid_motion.h"
#include "polyccd.h"
#include "util/work_budget.h"

struct pccd_cancel {
  pccd::util::Cancel_flag flag;
};

namespace pccd::api {

// bits(p) + bits(q) of x = p/q in lowest terms (0 = 0/1 has 2).
size_t number_bits(const arith::Rational &x);
// The same for the exact value of a finite double (at most 1,127).
size_t number_bits(double x);

// The largest number of some inputs and where it is (a PLACE of the error grammar,
// relative to the input: "vertices[12][2]", "rotation[0][3]").
struct Biggest_number {
  size_t bits = 0;
  std::string place;
  template <class F>
  void see(const arith::Rational &x, F &&place_of) {
    const size_t b = number_bits(x);
    if (b > bits) {
      bits = b;
      place = place_of();
    }
  }
  void see(const Biggest_number &o, const std::string &prefix) {
    if (o.bits > bits) {
      bits = o.bits;
      place = prefix + o.place;
    }
  }
};

Biggest_number biggest_in(const motion::Mesh_body &b);
Biggest_number biggest_in(const motion::Sphere_body &b);
Biggest_number biggest_in(const motion::Rigid_motion &m);

// The limits of a pccd_config (read by api/config.h).
struct Call_limits {
  util::Work_limits work;
  size_t max_number_bits = PCCD_DEFAULT_MAX_NUMBER_BITS;  // 0: none
  // Limit_error "<prefix><place>: a number of B bits exceeds config.max_number_bits = L ..."
  void check(const Biggest_number &b, const std::string &prefix = "") const;
};

// The work budget of one call on this thread (and the pools it starts); none when the
// config sets no work limit (then work_step costs one thread-local load).
class Call_budget {
 public:
  explicit Call_budget(const util::Work_limits &l) {
    if (l.any()) budget_.emplace(l);
    scope_.emplace(budget_ ? &*budget_ : nullptr);
  }

 private:
  std::optional<util::Work_budget> budget_;
  std::optional<util::Budget_scope> scope_;
};

}  // namespace pccd::api
