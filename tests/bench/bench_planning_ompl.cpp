// The C++ side of tests/bench/bench_planning_cpp.py: OMPL 1.5's RRTConnect (the system
// libompl, the one plainmp links) on bindings/ompl/polyccd_ompl.hpp's validators, for the
// scene file of tests/ompl/scene_file.py. Built as a shared library
// (build/bench/libbench_planning_ompl.so, tests/ompl/ompl.mk) that the Python driver loads
// with ctypes, so that it plans in the same process as plainmp and polyccd.ompl, on the
// same problems, interleaved. Its C functions:
//   bench_planning_seed(seed)       ompl::RNG::setSeed, before any plan (once a process)
//   bench_planning_open(path, check_seconds, self_collision) -> handle or NULL
//   bench_planning_plan(handle, start, goal, seconds, out...) -> 1 solved, 0 not, -1 error
//   bench_planning_close(handle); bench_planning_error() -> the last message
// A plan: SimpleSetup + RRTConnect, solve(seconds) (timed: wall and this thread's CPU
// time), then OMPL's checked simplifiers as polyccd.ompl.simplify (reduceVertices and
// collapseCloseVertices, up to 3 rounds; timed apart), the waypoints written out.
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <ctime>
#include <exception>
#include <string>

#include "../ompl/scene_file.hpp"

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

std::string last_error;

double thread_cpu() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

double wall() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The state validity checker, counting its calls (the motion validator counts its own).
class Counting_checker : public polyccd_ompl::State_validity_checker {
 public:
  using State_validity_checker::State_validity_checker;
  bool isValid(const ob::State *s) const override {
    ++calls;
    return State_validity_checker::isValid(s);
  }
  mutable unsigned long long calls = 0;
};

struct Bench {
  scene_file::Scene scene;
  std::shared_ptr<ob::RealVectorStateSpace> space;
  std::shared_ptr<polyccd_ompl::Robot_checks> checks;
  std::shared_ptr<Counting_checker> checker;
  ob::SpaceInformationPtr si;
};

}  // namespace

extern "C" {

const char *bench_planning_error() { return last_error.c_str(); }

void bench_planning_seed(unsigned long seed) {
  ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
  ompl::RNG::setSeed(seed);
}

void *bench_planning_open(const char *path, double check_seconds, int self_collision) {
  try {
    auto *b = new Bench;
    try {
      scene_file::read(path, b->scene);
      const size_t d = b->scene.dim_links.size();
      b->space = std::make_shared<ob::RealVectorStateSpace>(d);
      ob::RealVectorBounds bounds(d);
      for (size_t i = 0; i < d; ++i) {
        bounds.setLow(i, b->scene.bounds[i].first);
        bounds.setHigh(i, b->scene.bounds[i].second);
      }
      b->space->setBounds(bounds);
      b->checks = std::make_shared<polyccd_ompl::Robot_checks>(
          b->scene.robot, b->scene.chain, b->scene.obstacle_list(), b->scene.dim_links,
          b->scene.base, b->scene.mimic);
      b->checks->ropt.self_collision = self_collision;
      b->checks->cfg.max_seconds = check_seconds;  // as bench_planning's Limits(max_seconds)
      b->si = std::make_shared<ob::SpaceInformation>(b->space);
      polyccd_ompl::install(b->si, b->checks);
      b->checker = std::make_shared<Counting_checker>(b->si, b->checks);
      b->si->setStateValidityChecker(b->checker);
      b->si->setup();
    } catch (...) {
      delete b;
      throw;
    }
    return b;
  } catch (const std::exception &e) {
    last_error = e.what();
    return nullptr;
  }
}

void bench_planning_close(void *h) { delete static_cast<Bench *>(h); }

// times[4]: solve wall s, solve CPU s (this thread), simplify wall s, simplify CPU s;
// counts[3]: the solve's state checks and motion checks, check errors (solve and simplify); waypoints: up to cap states of
// dims doubles each, *n_states the path's state count (0 when not solved).
int bench_planning_plan(void *h, const double *start, const double *goal, double seconds,
                        double *times, unsigned long long *counts, double *waypoints,
                        size_t cap, size_t *n_states) {
  try {
    auto *b = static_cast<Bench *>(h);
    const size_t d = b->scene.dim_links.size();
    unsigned long long states0 = b->checker->calls, errors0 = b->checks->errors();
    b->si->getMotionValidator()->resetMotionCounter();
    og::SimpleSetup ss(b->si);
    ob::ScopedState<> s(b->space), g(b->space);
    for (size_t i = 0; i < d; ++i) s[i] = start[i], g[i] = goal[i];
    ss.setStartAndGoalStates(s, g);
    ss.setPlanner(std::make_shared<og::RRTConnect>(b->si));
    double w0 = wall(), c0 = thread_cpu();
    bool solved = ss.solve(seconds) && ss.haveExactSolutionPath();
    double w1 = wall(), c1 = thread_cpu();
    counts[0] = b->checker->calls - states0;  // the solve's checks (the simplifier's not counted)
    counts[1] = b->si->getMotionValidator()->getCheckedMotionCount();
    *n_states = 0;
    if (solved) {
      og::PathGeometric &path = ss.getSolutionPath();
      og::PathSimplifier simplifier(b->si);
      for (int round = 0; round < 3; ++round) {
        bool changed = simplifier.reduceVertices(path);
        changed = simplifier.collapseCloseVertices(path) || changed;
        if (!changed) break;
      }
      *n_states = path.getStateCount();
      for (size_t k = 0; k < *n_states && k < cap; ++k)
        for (size_t i = 0; i < d; ++i)
          waypoints[k * d + i] = path.getState(k)->as<polyccd_ompl::Real_state>()->values[i];
    }
    times[0] = w1 - w0, times[1] = c1 - c0, times[2] = wall() - w1, times[3] = thread_cpu() - c1;
    counts[2] = b->checks->errors() - errors0;
    return solved ? 1 : 0;
  } catch (const std::exception &e) {
    last_error = e.what();
    return -1;
  }
}

}  // extern "C"
