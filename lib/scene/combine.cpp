#include "scene/combine.h"

namespace pccd::scene {

using arith::Rational;

First_contact first_contact(
    std::vector<const pred::Contact_result *> res,
    const std::function<const pred::Contact_result *(size_t, const Rational &)> &refine) {
  First_contact out;
  constexpr int kMax_rounds = 64;
  for (int round = 0;; ++round) {
    std::vector<size_t> found;
    for (size_t i = 0; i < res.size(); ++i)
      if (res[i]->collides) found.push_back(i);
    if (found.empty()) return out;  // only before the first round (E's owner stays)
    out.collides = true;
    const pred::Contact_result *lo_owner = nullptr, *hi_owner = nullptr, *exact_min = nullptr;
    for (size_t i : found) {
      const pred::Contact_result *r = res[i];
      if (!lo_owner || r->lo < lo_owner->lo) lo_owner = r;
      if (!hi_owner || r->hi < hi_owner->hi) hi_owner = r;
      if (r->exact && (!exact_min || r->lo < exact_min->lo)) exact_min = r;
    }
    out.lo = lo_owner->lo;
    out.hi = hi_owner->hi;
    out.exact = false;
    out.which.clear();
    if (exact_min && exact_min->lo == out.hi) {
      const Rational E = exact_min->lo;
      // E == min hi. An inexact pair with hi_i == E has t_i < E (E is not the minimum);
      // one with lo_i < E < hi_i is undecided and refined.
      std::vector<size_t> straddle;
      bool below = false;
      for (size_t i : found) {
        const pred::Contact_result *r = res[i];
        if (r->exact) continue;
        if (r->hi <= E) below = true;          // t_i < hi_i <= E: E is not the minimum
        else if (r->lo < E) straddle.push_back(i);
      }
      if (!below && straddle.empty()) {
        out.lo = out.hi = E;
        out.exact = true;
        for (size_t i : found)
          if (res[i]->exact && res[i]->lo == E) out.which.push_back(i);
        return out;
      }
      if (!below && round < kMax_rounds) {
        for (size_t i : straddle) res[i] = refine(i, E);
        continue;
      }
    }
    for (size_t i : found)
      if (res[i]->lo <= out.hi) out.which.push_back(i);
    return out;
  }
}

}  // namespace pccd::scene
