// The tail of bench_linear (issue 34, item 1): where the time of the slow queries goes.
// Per kind and polyccd mode, the cost histogram by the stage that decided each query
// (pccd_result_stage), and the degenerate families the queries belong to, classified
// exactly (GMP rationals on the input doubles; see bench_linear_tail.cpp).
#ifndef PCCD_BENCH_LINEAR_TAIL_H
#define PCCD_BENCH_LINEAR_TAIL_H

#include <array>
#include <vector>

#include "bench_linear_input.h"
#include "bench_linear_report.h"

namespace bench {

// Prints (and writes under "tail" in json) the stage histogram of polyccd-decide and
// polyccd-time for vertex-face and edge-edge, and the family table. Untimed work only.
void report_tail(const std::vector<Linear_query> &qs, const std::array<Method_run, kMethods> &runs,
                 Json_writer &json);

}  // namespace bench

#endif
