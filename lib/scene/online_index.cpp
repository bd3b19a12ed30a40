#include "scene/online_index.h"

#include <algorithm>
#include <string>

#include "bvh/hierarchy.h"
#include "range/range_index.h"

namespace pccd::scene {

namespace {

Moving_body prepare(const Scene_body &b, const std::string &where = "") {
  try {
    return prepare_body(b);
  } catch (const arith::Input_error &e) {
    throw arith::Input_error(where + "motion: " + e.what());
  }
}

}  // namespace

Online_index::Online_index(const Scene_body &stored) : stored_(prepare(stored)) {
  range::stored_trees(*stored_.data);  // the preprocessing: built here, not by the first query
  bvh::hierarchy(*stored_.data);       // automatic's estimate and bvh use it (auto_cost.h)
}

Scene_report Online_index::query(const Scene_body &q, const Scene_options &opt) const {
  const Moving_body query = prepare(q);
  return solve_prepared({&stored_, &query}, {{0, 1}}, opt, 0);
}

void Online_index::query_many(const std::vector<Scene_body> &qs, const Scene_options &opt,
                              std::vector<Scene_report> &out) const {
  std::vector<Moving_body> prepared;
  prepared.reserve(qs.size());
  for (size_t k = 0; k < qs.size(); ++k)
    prepared.push_back(prepare(qs[k], "bodies[" + std::to_string(k) + "]."));
  Scene_options one = opt;
  one.threads = 1;
  out.assign(qs.size(), Scene_report());
  Thread_pool pool(std::max(1u, opt.threads));
  pool.parallel_for(qs.size(), [&](size_t k) {
    out[k] = solve_prepared({&stored_, &prepared[k]}, {{0, 1}}, one, 0);
  });
}

}  // namespace pccd::scene
