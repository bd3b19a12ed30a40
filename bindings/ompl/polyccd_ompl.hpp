// polyccd_ompl.hpp: OMPL's StateValidityChecker and MotionValidator on polyccd's C API,
// header-only, C++17, for a robot (pccd_robot) among obstacles planned over an
// ompl::base::RealVectorStateSpace of some of its joints: the C++ twin of Python's
// polyccd.ompl (bindings/python/polyccd/ompl.py), with no Python in the planning loop.
// It uses only include/polyccd.h and OMPL's headers (tested with OMPL 1.5, Debian
// libompl-dev: `make test-ompl`, tests/ompl/). In short:
//
//   auto checks = std::make_shared<polyccd_ompl::Robot_checks>(robot, chain, obstacles,
//                                                              dim_links, base);
//   checks->ropt.self_collision = 0;                // C options: cfg, opt, ropt
//   polyccd_ompl::install(si, checks);              // both validators on si, then si->setup()
//
// - isValid(s): pccd_robot_check_many on the one segment q(s) -> q(s) (the robot standing
//   still), decide mode (cfg.want_time = 0): valid when nothing touches. A state outside
//   the space's bounds (the joint limits) is invalid, as Python's limit errors make it.
// - checkMotion(s1, s2): the same call on q(s1) -> q(s2), polyccd's joint path (each
//   revolute joint's half-angle (cos, sin) interpolated linearly, include/polyccd.h
//   "Kinematic chains"; not OMPL's linear interpolation): valid when nothing touches.
// - checkMotion(s1, s2, lastValid): one call in first-contact mode; when the motion is
//   invalid, lastValid.second = f strictly before the certified first contact: f =
//   lo * k for the first k of 15/16, 3/4, 1/2, 1/8 (Python's BACKOFF) such that the path
//   s1 -> state(f) is contact-free by one more exact check, where lo is the contact
//   time's lower end rounded down to a double (so f < lo <= the first contact) and
//   state(f) the joint values at the exact decimal value of f on the joint path
//   (pccd_chain_joint_values_s); f = 0 and s1 itself when none is (or lo = 0).
// Any failed C call (a bad joint value, PCCD_ELIMIT from cfg's limits) makes the state or
// motion invalid, never accepted unchecked; errors() counts them and last_error() keeps
// the message. The checks hold no per-call state: several threads may share them.
//
// The state -> chain values map: chain value v[k] of link k is base[k], then
// v[dim_links[i]] = x[i] for each dimension i of the state, then for each mimic entry
// v[link] = multiplier * x[dim] + offset. base holds the fixed joints' values (and the
// chain's other links: ignored for fixed joints).
#ifndef POLYCCD_OMPL_HPP
#define POLYCCD_OMPL_HPP

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "polyccd.h"

namespace polyccd_ompl {

// A chain link that follows a planned dimension: v[link] = multiplier * x[dim] + offset.
struct Mimic {
  size_t link;
  size_t dim;
  double multiplier;
  double offset;
};

// One check's outcome: ok (the C call answered), collides, lo (the contact time's
// enclosure's lower end, rounded down; NaN without contact), free_until (a double <= the
// certified contact-free prefix).
struct Answer {
  bool ok = false;
  bool collides = true;
  double lo = NAN;
  double free_until = NAN;
};

// The exact decimal expansion of a finite double (glibc's printf prints it exactly: a
// double m 2^-k has k digits after the point), trailing zeros dropped: a rational string
// the C API reads as exactly x.
inline std::string exact_decimal(double x) {
  int n = std::snprintf(nullptr, 0, "%.1074f", x);
  std::string s(size_t(n) + 1, '\0');
  std::snprintf(&s[0], s.size(), "%.1074f", x);
  s.resize(size_t(n));
  size_t end = s.find_last_not_of('0');
  if (end != std::string::npos && s[end] == '.') --end;
  return s.substr(0, end + 1);
}

// What both validators check: the robot, its chain (for the joint values at a time), the
// obstacles (stationary unless motions are given) and the C options, shared. The caller
// keeps robot, chain and the obstacles alive while the checks are used.
class Robot_checks {
 public:
  Robot_checks(const pccd_robot *robot, const pccd_chain *chain,
               std::vector<const pccd_body *> obstacles, std::vector<size_t> dim_links,
               std::vector<double> base, std::vector<Mimic> mimic = {},
               std::vector<const pccd_motion *> motions = {})
      : robot_(robot), chain_(chain), obstacles_(std::move(obstacles)),
        motions_(std::move(motions)), dim_links_(std::move(dim_links)),
        base_(std::move(base)), mimic_(std::move(mimic)) {
    if (!robot_ || !chain_) throw std::invalid_argument("polyccd_ompl: robot or chain is NULL");
    if (pccd_chain_size(chain_, &links_) != PCCD_OK)
      throw std::invalid_argument(std::string("polyccd_ompl: ") + pccd_last_error());
    if (base_.size() != links_)
      throw std::invalid_argument("polyccd_ompl: base: " + std::to_string(base_.size()) +
                                  " values, the chain has " + std::to_string(links_) + " links");
    for (size_t i = 0; i < dim_links_.size(); ++i)
      if (dim_links_[i] >= links_)
        throw std::invalid_argument("polyccd_ompl: dim_links[" + std::to_string(i) + "]: " +
                                    std::to_string(dim_links_[i]) + " is not a chain link");
    for (size_t i = 0; i < mimic_.size(); ++i)
      if (mimic_[i].link >= links_ || mimic_[i].dim >= dim_links_.size())
        throw std::invalid_argument("polyccd_ompl: mimic[" + std::to_string(i) +
                                    "]: link or dim out of range");
    if (!motions_.empty() && motions_.size() != obstacles_.size())
      throw std::invalid_argument("polyccd_ompl: motions: one per obstacle, or none");
    pccd_config_init(&cfg);
    cfg.want_time = 0;  // decide mode; last_valid asks for the time itself
    pccd_scene_options_init(&opt);
    pccd_robot_options_init(&ropt);
  }

  // The C options of every check (read on each call; set them before planning).
  pccd_config cfg;
  pccd_scene_options opt;
  pccd_robot_options ropt;

  size_t dims() const { return dim_links_.size(); }
  size_t links() const { return links_; }

  // The chain values (links() doubles) of a state's values x (dims() doubles).
  void chain_values(const double *x, double *v) const {
    std::memcpy(v, base_.data(), links_ * sizeof(double));
    for (size_t i = 0; i < dim_links_.size(); ++i) v[dim_links_[i]] = x[i];
    for (const Mimic &m : mimic_) v[m.link] = m.multiplier * x[m.dim] + m.offset;
  }

  // One exact check of the segment x0 -> x1 (x0 == x1: a pose) in one C call,
  // pccd_robot_check_many on one segment; first_contact: the first contact time's
  // enclosure in lo (else decide mode, cfg.want_time = 0).
  Answer check(const double *x0, const double *x1, bool first_contact) const {
    std::vector<double> v(2 * links_);
    chain_values(x0, v.data());
    chain_values(x1, v.data() + links_);
    pccd_config c = cfg;
    c.want_time = first_contact ? 1 : 0;
    int status = PCCD_OK;
    unsigned char hit = 0;
    double lo = NAN, hi = NAN, free_until = NAN;
    char message[512] = "";
    pccd_robot_batch_out out;
    std::memset(&out, 0, sizeof out);
    out.struct_size = sizeof out;
    out.status = &status;
    out.messages = message;
    out.message_cap = sizeof message;
    out.collides = &hit;
    out.lo = &lo;
    out.hi = &hi;
    out.free_until = &free_until;
    int rc = pccd_robot_check_many(robot_, v.data(), v.data() + links_, 1, links_,
                                   obstacles_.data(), motions_.empty() ? nullptr : motions_.data(),
                                   obstacles_.size(), &c, &opt, &ropt, &out);
    Answer a;
    if (rc != PCCD_OK || status != PCCD_OK) {
      note_error(rc != PCCD_OK ? pccd_last_error() : message);
      return a;
    }
    a.ok = true;
    a.collides = hit != 0;
    a.lo = lo;
    a.free_until = free_until;
    return a;
  }

  // Contact on x0 -> x1, or an error (never accepted unchecked).
  bool collides(const double *x0, const double *x1) const {
    Answer a = check(x0, x1, false);
    return !a.ok || a.collides;
  }

  // true when x0 -> x1 is contact-free; else false with x_last (dims() doubles) and
  // *fraction a last valid state and its time (the header comment).
  bool last_valid(const double *x0, const double *x1, double *x_last, double *fraction) const {
    Answer a = check(x0, x1, true);
    if (a.ok && !a.collides) return true;
    std::vector<double> best(x0, x0 + dims());
    double f_best = 0.0;
    if (a.ok && a.lo > 0) {
      static const double backoff[] = {15.0 / 16, 3.0 / 4, 1.0 / 2, 1.0 / 8};
      std::vector<double> v(3 * links_), x(dims());
      chain_values(x0, v.data());
      chain_values(x1, v.data() + links_);
      for (double k : backoff) {
        double f = a.lo * k;  // < a.lo for k < 1 (a.lo a positive normal double, <= 1)
        if (!(f > 0 && f < a.lo)) continue;
        std::string t = exact_decimal(f);
        if (pccd_chain_joint_values_s(chain_, v.data(), v.data() + links_, links_, t.c_str(),
                                      v.data() + 2 * links_) != PCCD_OK) {
          note_error(pccd_last_error());
          break;
        }
        for (size_t i = 0; i < dims(); ++i) x[i] = v[2 * links_ + dim_links_[i]];
        if (!collides(x0, x.data())) {
          best = x;
          f_best = f;
          break;
        }
      }
    }
    std::memcpy(x_last, best.data(), dims() * sizeof(double));
    *fraction = f_best;
    return false;
  }

  unsigned long long errors() const { return errors_.load(); }
  std::string last_error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_error_;
  }

 private:
  void note_error(const char *message) const {
    ++errors_;
    std::lock_guard<std::mutex> lock(mutex_);
    last_error_ = message;
  }

  const pccd_robot *robot_;
  const pccd_chain *chain_;
  std::vector<const pccd_body *> obstacles_;
  std::vector<const pccd_motion *> motions_;
  std::vector<size_t> dim_links_;
  std::vector<double> base_;
  std::vector<Mimic> mimic_;
  size_t links_ = 0;
  mutable std::atomic<unsigned long long> errors_{0};
  mutable std::mutex mutex_;
  mutable std::string last_error_;
};

using Real_state = ompl::base::RealVectorStateSpace::StateType;

// Valid: inside the space's bounds and the robot standing still there touches nothing.
class State_validity_checker : public ompl::base::StateValidityChecker {
 public:
  State_validity_checker(const ompl::base::SpaceInformationPtr &si,
                         std::shared_ptr<const Robot_checks> checks)
      : ompl::base::StateValidityChecker(si), checks_(std::move(checks)) {}

  bool isValid(const ompl::base::State *state) const override {
    if (!si_->satisfiesBounds(state)) return false;
    const double *x = state->as<Real_state>()->values;
    return !checks_->collides(x, x);
  }

 private:
  std::shared_ptr<const Robot_checks> checks_;
};

// Valid: polyccd's exact check of the joint path s1 -> s2 finds no contact.
class Motion_validator : public ompl::base::MotionValidator {
 public:
  Motion_validator(const ompl::base::SpaceInformationPtr &si,
                   std::shared_ptr<const Robot_checks> checks)
      : ompl::base::MotionValidator(si), checks_(std::move(checks)) {}

  bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override {
    bool ok = si_->satisfiesBounds(s2) &&
              !checks_->collides(s1->as<Real_state>()->values, s2->as<Real_state>()->values);
    ok ? ++valid_ : ++invalid_;
    return ok;
  }

  bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                   std::pair<ompl::base::State *, double> &lastValid) const override {
    const double *x1 = s1->as<Real_state>()->values;
    std::vector<double> x(checks_->dims());
    double f = 0.0;
    bool ok;
    if (!si_->satisfiesBounds(s2)) {  // s1 is valid (OMPL's contract): keep it
      x.assign(x1, x1 + x.size());
      ok = false;
    } else {
      ok = checks_->last_valid(x1, s2->as<Real_state>()->values, x.data(), &f);
    }
    if (!ok) {
      if (lastValid.first != nullptr)
        std::memcpy(lastValid.first->as<Real_state>()->values, x.data(), x.size() * sizeof(double));
      lastValid.second = f;
    }
    ok ? ++valid_ : ++invalid_;
    return ok;
  }

 private:
  std::shared_ptr<const Robot_checks> checks_;
};

// Both validators on si (a RealVectorStateSpace of checks->dims() dimensions), then
// si->setup().
inline void install(const ompl::base::SpaceInformationPtr &si,
                    std::shared_ptr<const Robot_checks> checks) {
  if (si->getStateDimension() != checks->dims())
    throw std::invalid_argument("polyccd_ompl::install: the space has " +
                                std::to_string(si->getStateDimension()) +
                                " dimensions, the checks " + std::to_string(checks->dims()));
  si->setStateValidityChecker(std::make_shared<State_validity_checker>(si, checks));
  si->setMotionValidator(std::make_shared<Motion_validator>(si, checks));
  si->setup();
}

}  // namespace polyccd_ompl

#endif  // POLYCCD_OMPL_HPP
