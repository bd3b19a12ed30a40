#include "util/rounding.h"

#include <cfenv>

namespace pccd::util {

Round_to_nearest::Round_to_nearest() : saved_mode_(std::fegetround()), saved_flag_(tl_nearest) {
  if (saved_mode_ != FE_TONEAREST) std::fesetround(FE_TONEAREST);
  tl_nearest = true;
}
Round_to_nearest::~Round_to_nearest() {
  if (saved_mode_ != FE_TONEAREST) std::fesetround(saved_mode_);
  tl_nearest = saved_flag_;
}

Adopted_rounding::Adopted_rounding(int mode, bool nearest)
    : saved_mode_(std::fegetround()), saved_flag_(tl_nearest) {
  if (saved_mode_ != mode) std::fesetround(mode);
  // The flag may only claim round-to-nearest when the mode really is.
  tl_nearest = nearest && mode == FE_TONEAREST;
}
Adopted_rounding::~Adopted_rounding() {
  if (std::fegetround() != saved_mode_) std::fesetround(saved_mode_);
  tl_nearest = saved_flag_;
}

}  // namespace pccd::util
