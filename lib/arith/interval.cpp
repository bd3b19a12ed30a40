#include "arith/interval.h"

#include <cfenv>

namespace pccd::arith {
Nearest_scope::Nearest_scope() : saved_(tl_nearest) { tl_nearest = std::fegetround() == FE_TONEAREST; }
Nearest_scope::~Nearest_scope() { tl_nearest = saved_; }

Round_to_nearest::Round_to_nearest() : saved_(std::fegetround()) {
  if (saved_ != FE_TONEAREST) std::fesetround(FE_TONEAREST);
}
Round_to_nearest::~Round_to_nearest() {
  if (saved_ != FE_TONEAREST) std::fesetround(saved_);
}

}  // namespace pccd::arith
