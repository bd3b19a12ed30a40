#include "broad/online_index.h"

#include <string>

#include "broad/range_index.h"

namespace pccd::broad {

namespace {

Moving_body prepare(const Scene_body &b) {
  try {
    return prepare_body(b.body, b.motion);
  } catch (const arith::Input_error &e) {
    throw arith::Input_error(std::string("motion: ") + e.what());
  }
}

}  // namespace

Online_index::Online_index(const Scene_body &stored) : stored_(prepare(stored)) {
  stored_trees(*stored_.data);  // the preprocessing: built here, not by the first query
}

Scene_report Online_index::query(const Scene_body &q, const Scene_options &opt) const {
  const std::vector<Moving_body> mb = {stored_, prepare(q)};
  return solve_prepared(mb, {{0, 1}}, opt, 0);
}

}  // namespace pccd::broad
