// Small 3-vectors of intervals (outward rounded, arith/interval.h) for the
// linearizations: every result encloses the exact one.
#pragma once
#include <array>

#include "arith/convert.h"
#include "arith/interval.h"
#include "motion/body.h"

namespace pccd::range {

using I3 = std::array<arith::Interval, 3>;

inline I3 enclose_point(const motion::Point3_q &p) {
  return {arith::enclose(p[0]), arith::enclose(p[1]), arith::enclose(p[2])};
}
inline I3 add(const I3 &a, const I3 &b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline I3 sub(const I3 &a, const I3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline I3 scale3(const arith::Interval &s, const I3 &a) { return {s * a[0], s * a[1], s * a[2]}; }
inline I3 cross(const I3 &a, const I3 &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline arith::Interval dot(const I3 &a, const I3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace pccd::range
