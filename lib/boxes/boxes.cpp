#include "boxes/boxes.h"

// CGAL's headers otherwise add a load-time test of the FPU rounding modes (for its
// Interval_nt, unused here): it switches the rounding mode during library loading and
// aborts where rounding modes are not emulated (valgrind). polyccd never relies on the
// rounding mode (see arith/interval.h and the error bound in enclose/enclose.h).
#define CGAL_DISABLE_ROUNDING_MATH_CHECK
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>

#include "util/work_budget.h"

namespace pccd::boxes {

void box_pairs(const std::vector<Box> &a, const std::vector<Box> &b,
               std::vector<std::pair<uint32_t, uint32_t>> &out) {
  using CBox = CGAL::Box_intersection_d::Box_with_info_d<double, 3, uint32_t,
                                                         CGAL::Box_intersection_d::ID_EXPLICIT>;
  if (a.empty() || b.empty()) return;
  auto convert = [](const std::vector<Box> &in) {
    std::vector<CBox> v;
    v.reserve(in.size());
    for (size_t i = 0; i < in.size(); ++i) {
      double lo[3] = {in[i].lo[0], in[i].lo[1], in[i].lo[2]};
      double hi[3] = {in[i].hi[0], in[i].hi[1], in[i].hi[2]};
      v.emplace_back(lo, hi, static_cast<uint32_t>(i));
    }
    return v;
  };
  std::vector<CBox> ca = convert(a), cb = convert(b);
  // Closed boxes: touching boxes are reported (CGAL::Box_intersection_d::CLOSED).
  CGAL::box_intersection_d(ca.begin(), ca.end(), cb.begin(), cb.end(),
                           [&](const CBox &x, const CBox &y) {
                             out.emplace_back(x.info(), y.info());
                             // a step per 4,096 pairs: millions can meet (util/work_budget.h)
                             if (out.size() % 4096 == 0) util::work_step();
                           },
                           std::ptrdiff_t(10), CGAL::Box_intersection_d::CLOSED,
                           CGAL::Box_intersection_d::BIPARTITE);
}

}  // namespace pccd::boxes
