// CGAL's box intersection on the enclosures' boxes (enclose/enclose.h), for the box
// broad phase (box_source.h).
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "enclose/enclose.h"

namespace pccd::boxes {

using enclose::Box;

// Every (i, j) with boxes a[i] and b[j] meeting (closed), by CGAL box_intersection_d.
// Appended to out in no particular order.
void box_pairs(const std::vector<Box> &a, const std::vector<Box> &b,
               std::vector<std::pair<uint32_t, uint32_t>> &out);

}  // namespace pccd::boxes
