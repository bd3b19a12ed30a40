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

// An unsolved, empty result, in place: no allocation when r held an answer before.
inline void reset(pred::Contact_result &r) {
  r.collides = r.exact = false;
  r.lo = 0;
  r.hi = 0;
  r.features.clear();
  r.stage = pred::STAGE_NONE;
}

// Number of points of a kind; Input_error for an unknown kind.
size_t kind_points(long kind);

struct Biggest_number;
// The largest number of q's trajectories and radii (api/limits.h).
Biggest_number biggest_in(const pccd_query &q);

// Solves with the interval stages built from `q`'s exact data (intervals enclosing it).
pred::Contact_result solve_query(const pccd_query &q, const pred::Solve_options &opt);

// One linear query of a pccd_kind (not SPHERE_SPHERE) of points moving from p0 to p1
// (finite doubles), answered into r (reset first) exactly as pccd_solve_linear_d does:
// the static filter, the hit certificate, then the staged solver (with delta > 0, the
// staged solver alone). The batch and pccd_step_solve call it for each query.
void solve_linear_one(int kind, const double *p0, const double *p1, const pred::Solve_options &opt,
                      pred::Contact_result &r);

// Reads a pccd_config (NULL: defaults) into solver options; Input_error when invalid.
pred::Solve_options read_config(const pccd_config *cfg);
// True when cfg sets config.min_distance (the fast linear paths assume delta = 0).
bool has_min_distance(const pccd_config *cfg);
// The validation of read_config alone (no options built).
void checked_config(const pccd_config *cfg);

}  // namespace pccd::api
