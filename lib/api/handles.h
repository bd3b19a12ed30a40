// The opaque handle types behind polyccd.h.
#pragma once
#include <string>
#include <vector>

#include "pred/solve.h"

struct pccd_query {
  int kind = 0;
  std::vector<pccd::motion::Point_traj<pccd::arith::Rational>> points;
  pccd::arith::Rational radius[2];
};

struct pccd_result {
  bool solved = false;
  pccd::pred::Contact_result r;
};

namespace pccd::api {

// Number of points of a kind; Input_error for an unknown kind.
size_t kind_points(long kind);

struct Biggest_number;
// The largest number of q's trajectories and radii (api/limits.h).
Biggest_number biggest_in(const pccd_query &q);

// Solves with the interval stages built from `q`'s exact data (intervals enclosing it).
pred::Contact_result solve_query(const pccd_query &q, const pred::Solve_options &opt);

}  // namespace pccd::api
