#include "util/rounding.h"

namespace pccd::util {

Round_to_nearest::Round_to_nearest() : saved_(std::fegetround()) {
  if (saved_ != FE_TONEAREST) std::fesetround(FE_TONEAREST);
}
Round_to_nearest::~Round_to_nearest() {
  if (saved_ != FE_TONEAREST) std::fesetround(saved_);
}

}  // namespace pccd::util
