// The C++ OMPL validators of bindings/ompl/polyccd_ompl.hpp against the C API, on the
// Panda of example-robot-data among the wall and shelf of examples/ompl_panda.py (the
// file of tests/ompl/scene_file.py, argv[1]); `make test-ompl` builds and runs it when
// OMPL's headers are installed.
//  1. isValid and checkMotion on random states and edges equal pccd_robot_check's answers
//     (the single-segment call and its report, decide and first-contact mode; self-
//     collision off and on), states outside the bounds are invalid, a C error (a NaN
//     joint value) is invalid and counted.
//  2. checkMotion with a last valid state: the motion's answer as above; when invalid,
//     0 <= f < the first contact time, the state is the joint path's at f
//     (pccd_chain_joint_values_s) and the path from s1 to it is free (pccd_robot_check).
//     Two threads sharing the checks answer as one does.
//  3. RRTConnect on the file's query, then OMPL's checked simplifiers: every segment of
//     the returned path is free by an exact first-contact check, and poses every 0.01 rad
//     along polyccd's joint path are free by exact static checks (dense).
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>

#include "../cpp/expect.h"
#include "scene_file.hpp"

namespace ob = ompl::base;
namespace og = ompl::geometric;
using polyccd_ompl::Real_state;

struct Reference {  // the answers of pccd_robot_check, one segment, its own report
  const scene_file::Scene &sc;
  const polyccd_ompl::Robot_checks &checks;
  pccd_report *rep = nullptr;
  explicit Reference(const scene_file::Scene &s, const polyccd_ompl::Robot_checks &c) : sc(s), checks(c) {
    pccd_report_new(&rep);
  }
  ~Reference() { pccd_report_free(rep); }
  // 1 collides, 0 free, -1 error; *approx: a double near the first contact time.
  int check(const double *x0, const double *x1, bool self, bool want_time, double *approx = nullptr) {
    std::vector<double> v0(checks.links()), v1(checks.links());
    checks.chain_values(x0, v0.data());
    checks.chain_values(x1, v1.data());
    pccd_config cfg;
    pccd_config_init(&cfg);
    cfg.want_time = want_time;
    pccd_robot_options ropt;
    pccd_robot_options_init(&ropt);
    ropt.self_collision = self;
    auto obs = sc.obstacle_list();
    if (pccd_robot_check(sc.robot, v0.data(), v1.data(), v0.size(), obs.data(), nullptr, obs.size(),
                         &cfg, nullptr, &ropt, rep) != PCCD_OK)
      return -1;
    int hit = 0;
    pccd_report_collides(rep, &hit);
    if (hit && approx) pccd_report_time_info(rep, PCCD_WHOLE, PCCD_WHOLE, nullptr, approx);
    return hit;
  }
};

static bool same_state_at(const scene_file::Scene &sc, const polyccd_ompl::Robot_checks &checks,
                          const double *x0, const double *x1, double f, const double *x) {
  std::vector<double> v0(checks.links()), v1(checks.links()), v(checks.links());
  checks.chain_values(x0, v0.data());
  checks.chain_values(x1, v1.data());
  if (pccd_chain_joint_values_s(sc.chain, v0.data(), v1.data(), v.size(),
                                polyccd_ompl::exact_decimal(f).c_str(), v.data()) != PCCD_OK)
    return false;
  for (size_t i = 0; i < checks.dims(); ++i)
    if (x[i] != v[sc.dim_links[i]]) return false;
  return true;
}

// Dense exact checks along polyccd's joint path of one segment: poses at t = k / n,
// n = ceil(largest joint change / step); true when every pose is free.
static bool dense_free(Reference &ref, const pccd_chain *chain, const double *x0, const double *x1,
                       double step) {
  const auto &c = ref.checks;
  double most = 0;
  for (size_t i = 0; i < c.dims(); ++i) most = std::max(most, std::fabs(x1[i] - x0[i]));
  long n = std::max(1L, long(std::ceil(most / step)));
  std::vector<double> v0(c.links()), v1(c.links()), v(c.links()), x(c.dims());
  c.chain_values(x0, v0.data());
  c.chain_values(x1, v1.data());
  for (long k = 0; k <= n; ++k) {
    std::string t = std::to_string(k) + "/" + std::to_string(n);
    if (pccd_chain_joint_values_s(chain, v0.data(), v1.data(), v.size(), t.c_str(), v.data()) != PCCD_OK)
      return false;
    for (size_t i = 0; i < c.dims(); ++i) x[i] = v[ref.sc.dim_links[i]];
    if (ref.check(x.data(), x.data(), false, false) != 0) return false;
  }
  return true;
}

int main(int argc, char **argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SCENE_FILE (tests/ompl/scene_file.py)\n", argv[0]);
    return 2;
  }
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  ompl::RNG::setSeed(3);  // before OMPL makes any generator: the plan is reproducible
  scene_file::Scene sc;
  scene_file::read(argv[1], sc);
  const size_t d = sc.dim_links.size();
  auto space = std::make_shared<ob::RealVectorStateSpace>(d);
  ob::RealVectorBounds bounds(d);
  for (size_t i = 0; i < d; ++i) bounds.setLow(i, sc.bounds[i].first), bounds.setHigh(i, sc.bounds[i].second);
  space->setBounds(bounds);
  auto checks = std::make_shared<polyccd_ompl::Robot_checks>(sc.robot, sc.chain, sc.obstacle_list(),
                                                             sc.dim_links, sc.base, sc.mimic);
  checks->ropt.self_collision = 0;
  auto si = std::make_shared<ob::SpaceInformation>(space);
  polyccd_ompl::install(si, checks);
  auto self_checks = std::make_shared<polyccd_ompl::Robot_checks>(sc.robot, sc.chain, sc.obstacle_list(),
                                                                  sc.dim_links, sc.base, sc.mimic);
  auto si_self = std::make_shared<ob::SpaceInformation>(space);
  polyccd_ompl::install(si_self, self_checks);  // self_collision: the library's default, on
  Reference ref(sc, *checks);

  // 1, 2: random states and edges (seeded), each joint of an edge moving up to 0.6 rad
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ob::State *a = si->allocState(), *b = si->allocState(), *last = si->allocState();
  int states = 0, colliding_states = 0, edges = 0, colliding_edges = 0, backed_off = 0;
  for (int trial = 0; trial < 300; ++trial) {
    double *x = a->as<Real_state>()->values, *y = b->as<Real_state>()->values;
    for (size_t i = 0; i < d; ++i) {
      x[i] = sc.bounds[i].first + u(rng) * (sc.bounds[i].second - sc.bounds[i].first);
      y[i] = std::clamp(x[i] + 1.2 * (u(rng) - 0.5), sc.bounds[i].first, sc.bounds[i].second);
    }
    std::string at = "trial " + std::to_string(trial);
    int hit = ref.check(x, x, false, false);
    expect(hit >= 0 && si->isValid(a) == (hit == 0), at + ": isValid == pccd_robot_check");
    expect(hit == ref.check(x, x, false, true), at + ": decide == first-contact (state)");
    int self_hit = ref.check(x, x, true, false);
    expect(si_self->isValid(a) == (self_hit == 0), at + ": isValid, self-collision on");
    ++states, colliding_states += hit;
    if (hit) continue;  // OMPL checks motions from valid states
    double lo = NAN;
    int edge = ref.check(x, y, false, true, &lo);
    expect(edge >= 0 && si->checkMotion(a, b) == (edge == 0), at + ": checkMotion == pccd_robot_check");
    expect(edge == ref.check(x, y, false, false), at + ": decide == first-contact (edge)");
    if (self_hit == 0)
      expect(si_self->checkMotion(a, b) == (ref.check(x, y, true, false) == 0), at + ": self-collision on");
    ++edges, colliding_edges += edge;
    std::pair<ob::State *, double> lv(last, -1.0);
    bool ok = si->getMotionValidator()->checkMotion(a, b, lv);
    expect(ok == (edge == 0), at + ": checkMotion(last valid) == pccd_robot_check");
    std::pair<ob::State *, double> no_state(nullptr, -1.0);
    expect(si->getMotionValidator()->checkMotion(a, b, no_state) == ok && no_state.second == (ok ? -1.0 : lv.second),
           at + ": lastValid.first nullptr: same answer and time");
    if (ok) {
      expect(lv.second == -1.0, at + ": a valid motion leaves lastValid alone");
      continue;
    }
    const double *z = last->as<Real_state>()->values;
    expect(lv.second >= 0 && lv.second < lo, at + ": 0 <= f < the first contact");
    expect(ref.check(x, z, false, true) == 0, at + ": the path s1 -> last valid state is free");
    if (lv.second > 0) {
      ++backed_off;
      expect(same_state_at(sc, *checks, x, y, lv.second, z), at + ": the state is the path's at f");
    } else {
      expect(std::equal(x, x + d, z), at + ": f = 0: s1 itself");
    }
  }
  std::printf("states %d (%d colliding), edges %d (%d colliding, %d last valid states after s1)\n",
              states, colliding_states, edges, colliding_edges, backed_off);
  expect(colliding_states > 10 && edges - colliding_edges > 10 && colliding_edges > 10 && backed_off > 5,
         "the random cases reach every kind of answer");

  // two threads sharing the validators answer as one thread does (Robot_checks keeps no
  // per-call state; the C API shares a robot passed as const)
  std::vector<std::vector<double>> poses(120, std::vector<double>(d));
  for (auto &p : poses)
    for (size_t i = 0; i < d; ++i) p[i] = sc.bounds[i].first + u(rng) * (sc.bounds[i].second - sc.bounds[i].first);
  std::vector<int> serial(poses.size()), shared(poses.size());
  for (size_t k = 0; k < poses.size(); ++k) serial[k] = checks->collides(poses[k].data(), poses[k].data());
  auto half = [&](size_t from) {
    for (size_t k = from; k < poses.size(); k += 2) shared[k] = checks->collides(poses[k].data(), poses[k].data());
  };
  std::thread t0(half, 0), t1(half, 1);
  t0.join(), t1.join();
  expect(serial == shared, "two threads sharing the checks answer as one");

  // bounds and errors
  double *x = a->as<Real_state>()->values;
  for (size_t i = 0; i < d; ++i) x[i] = sc.queries.at(0).first[i];
  expect(si->isValid(a), "the query's start is valid");
  x[0] = sc.bounds[0].second + 0.1;
  expect(!si->isValid(a), "a state beyond the joint limit is invalid");
  x[0] = NAN;
  unsigned long long before = checks->errors();
  expect(!si->isValid(a) && checks->errors() == before + 1 && !checks->last_error().empty(),
         "a C error (NaN joint value) is invalid and counted: " + checks->last_error());

  // 3: a planned path, checked exactly and densely
  og::SimpleSetup ss(si);
  ob::ScopedState<> start(space), goal(space);
  for (size_t i = 0; i < d; ++i) start[i] = sc.queries[0].first[i], goal[i] = sc.queries[0].second[i];
  ss.setStartAndGoalStates(start, goal);
  ss.setPlanner(std::make_shared<og::RRTConnect>(si));
  bool solved = ss.solve(60.0) && ss.haveExactSolutionPath();
  expect(solved, "RRTConnect solves the query");
  if (solved) {
    og::PathGeometric &path = ss.getSolutionPath();
    for (int pass = 0; pass < 2; ++pass) {  // as planned, then simplified (checked edges only)
      size_t n = path.getStateCount();
      std::string what = pass ? "simplified path" : "path";
      expect(n >= 2, what + ": has states");
      for (size_t k = 0; k + 1 < n; ++k) {
        const double *p = path.getState(k)->as<Real_state>()->values;
        const double *q = path.getState(k + 1)->as<Real_state>()->values;
        std::string at = what + " segment " + std::to_string(k);
        expect(ref.check(p, q, false, true) == 0, at + ": free (exact, first-contact mode)");
        expect(dense_free(ref, sc.chain, p, q, 0.01), at + ": free (poses every 0.01 rad)");
      }
      std::printf("%s: %zu states\n", what.c_str(), n);
      og::PathSimplifier simplifier(si);
      simplifier.reduceVertices(path);
      simplifier.collapseCloseVertices(path);
    }
  }
  si->freeState(a), si->freeState(b), si->freeState(last);
  std::printf("test_ompl_validator: %ld passed, %ld failed\n", passed, failed);
  return failed != 0;
}
