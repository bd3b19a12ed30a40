#include "step/tree.h"

#include <algorithm>

#include "util/work_budget.h"

namespace pccd::step {
namespace {

// Spreads the low 10 bits of x to every third bit.
uint32_t spread3(uint32_t x) {
  x &= 0x3ff;
  x = (x | (x << 16)) & 0x030000ff;
  x = (x | (x << 8)) & 0x0300f00f;
  x = (x | (x << 4)) & 0x030c30c3;
  x = (x | (x << 2)) & 0x09249249;
  return x;
}

}  // namespace

Box_tree::Box_tree(const std::vector<Box> &boxes) {
  const size_t n = boxes.size();
  if (n == 0) return;
  // A work step per 4,096 boxes before each pass over them (util/work_budget.h): a
  // step's trees are built by pccd_step_solve under its limits (issue 33: a 1M-triangle
  // step ran 1 s past max_seconds building them).
  const uint64_t pass = 1 + n / 4096;
  util::work_step(pass);
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a) lo[a] = hi[a] = 0.5 * boxes[0].lo[a] + 0.5 * boxes[0].hi[a];
  std::vector<double> c(3 * n);
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      // A centre only orders the boxes; any value (even inf from an unbounded box) works.
      double x = 0.5 * boxes[i].lo[a] + 0.5 * boxes[i].hi[a];
      if (!(x == x)) x = 0;
      c[3 * i + a] = x;
      lo[a] = std::min(lo[a], x);
      hi[a] = std::max(hi[a], x);
    }
  // One scale for all axes (the largest extent): a thin axis (a flat cloth) then adds
  // few bits to the codes instead of spreading its noise over all of them.
  double w = 0;
  for (int a = 0; a < 3; ++a) w = std::max(w, hi[a] - lo[a]);
  const double unit = w > 0 && w < 1e300 ? 1023.0 / w : 0.0;
  const double scale[3] = {unit, unit, unit};
  std::vector<uint32_t> code(n);
  for (size_t i = 0; i < n; ++i) {
    uint32_t m = 0;
    for (int a = 0; a < 3; ++a) {
      double q = (c[3 * i + a] - lo[a]) * scale[a];
      q = q > 0 ? (q < 1023 ? q : 1023) : 0;
      m |= spread3(static_cast<uint32_t>(q)) << a;
    }
    code[i] = m;
  }
  util::work_step(pass);
  // Stable LSD radix sort of indices by code, 10 bits per pass.
  order_.resize(n);
  for (size_t i = 0; i < n; ++i) order_[i] = static_cast<uint32_t>(i);
  std::vector<uint32_t> tmp(n);
  for (int shift = 0; shift < 30; shift += 10) {
    std::vector<uint32_t> count(1025, 0);
    for (size_t i = 0; i < n; ++i) ++count[((code[order_[i]] >> shift) & 1023) + 1];
    for (size_t d = 0; d < 1024; ++d) count[d + 1] += count[d];
    for (size_t i = 0; i < n; ++i) tmp[count[(code[order_[i]] >> shift) & 1023]++] = order_[i];
    order_.swap(tmp);
    util::work_step(pass);
  }
  sorted_.resize(n);
  for (size_t k = 0; k < n; ++k) sorted_[k] = boxes[order_[k]];
  size_t leaves = (n + kLeaf - 1) / kLeaf, width = 1;
  while (width < leaves) width *= 2;
  first_leaf_ = static_cast<uint32_t>(width - 1);
  nodes_.assign(2 * width - 1, enclose::empty_box());
  for (size_t i = 0; i < leaves; ++i) {
    Box h = sorted_[i * kLeaf];
    for (size_t k = i * kLeaf + 1; k < std::min(n, (i + 1) * kLeaf); ++k) h = enclose::hull(h, sorted_[k]);
    nodes_[first_leaf_ + i] = h;
  }
  for (size_t k = first_leaf_; k-- > 0;) nodes_[k] = enclose::hull(nodes_[2 * k + 1], nodes_[2 * k + 2]);
}

}  // namespace pccd::step
