// The exact solve of a robot check's pairs the filter left (robot.h, step 3): the links'
// exact motions built on the first demand, a self pair in its links' common ancestor's
// frame, optionally over a time window of the segment. Namespace pccd::scene.
#pragma once
#include <vector>

#include "motion/chain_path.h"
#include "scene/robot.h"

namespace pccd::scene {

// A time window [lo, hi] of [0, 1] holding the first contact (no checked pair touches
// before lo: the filter's bounds; some pair touches at hi: a witness), solved as the
// segment t = lo + (hi - lo) s, s in [0, 1]: the exact motions reparametrized (the same
// motion, each polynomial composed with that affine map), the report's times mapped
// back. The first contact, the pairs touching first and their features are those of
// [0, 1]; the exact solve's enclosures are far tighter on the short window.
struct Window {
  bool on = false;
  double lo = 0, hi = 1;  // dyadic doubles
  Rational to_t(const Rational &s) const { return Rational(lo) + (Rational(hi) - Rational(lo)) * s; }
  double to_s(double t) const {  // a lower bound of the window time of t >= lo
    return std::max(0.0, arith::round_down((t - lo) / (hi - lo)));
  }
};

// The report's times mapped from the window's time s back to t.
void map_back(Scene_report &rep, const Window &w);

// The exact solve of plans (scene.h, solve_planned) on the segment q0 -> q1 (path: its
// Chain_path), over the window win when on (obstacles stationary then).
Scene_report solve_exact(const Robot_model &r, const motion::Chain_path &path, const double *q0, const double *q1,
                         const std::vector<Moving_body> &obst, std::vector<Pair_plan> plans, const Scene_options &opt,
                         const Robot_options &ro, const Window &win = {});

}  // namespace pccd::scene
