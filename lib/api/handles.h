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

// Solves with the interval stages built from `q`'s exact data (intervals enclosing it).
pred::Contact_result solve_query(const pccd_query &q, const pred::Solve_options &opt);

// Reads a pccd_config (NULL: defaults) into solver options; Input_error when invalid.
pred::Solve_options read_config(const pccd_config *cfg);

}  // namespace pccd::api
