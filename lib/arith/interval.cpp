#include "arith/interval.h"

#include <cfenv>

namespace pccd::arith {
Nearest_scope::Nearest_scope() : saved_(tl_nearest) { tl_nearest = std::fegetround() == FE_TONEAREST; }
Nearest_scope::~Nearest_scope() { tl_nearest = saved_; }

}  // namespace pccd::arith
