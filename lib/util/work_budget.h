// Work limits of one library call: a wall-clock limit, a deterministic count of work
// steps, and a cancellation flag another thread (or a signal handler) may set.
//
// The api layer opens a Budget_scope for the calling thread; the thread pool hands the
// same budget to its workers for each loop (thread_pool.h). The layers below call
// work_step() at the points where work repeats without a bound known up front:
//   - a primitive query solved (pred::solve), and each root-search step of it
//     (a bisection or refinement step of poly/earliest.h, poly/rational_root.cpp),
//   - a time piece of a broad phase, a batch of candidate pairs of the scene driver.
// Exact operations on long numbers also count by cost (work_cost below): the
// polynomial products, remainders, evaluations and eliminations of lib/poly, on which
// the motions, the feature systems and the index are built, add one step per
// kCostPerStep limb operations and check the limits there, so the time between two
// checks is bounded whatever the number sizes (issue 23: a rotation numerator of
// 2,400-digit coefficients ran 300 s before its first check).
// A step is one such unit or kCostPerStep limb operations, so a call's count of steps is
// a function of its inputs alone: the scene driver solves the same pairs with the same options for
// any number of threads (scene/pair_search.cpp), so a work limit ends the same calls
// for any thread count. (Data a handle keeps between calls, such as a motion's
// derivation, is counted by the call that derives it.) The input limit on number sizes
// (polyccd.h, pccd_config.max_number_bits) is checked up front.
//
// When a limit is reached, work_step throws Limit_reached, and every later step of the
// same call throws too (the budget is spent), so parallel workers stop at their next
// step. The api maps it to PCCD_ELIMIT with the message of Limit_reached::what().
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace pccd::util {

// A cancellation flag: set by anyone, read by the running calls that were given it.
// set() is a lock-free atomic store, safe from another thread or a signal handler.
class Cancel_flag {
 public:
  void set() { flag_.store(1, std::memory_order_relaxed); }
  void reset() { flag_.store(0, std::memory_order_relaxed); }
  bool is_set() const { return flag_.load(std::memory_order_relaxed) != 0; }

 private:
  std::atomic<int> flag_{0};
  static_assert(std::atomic<int>::is_always_lock_free, "Cancel_flag must be signal-safe");
};

struct Work_limits {
  double max_seconds = 0;           // wall clock from the start of the call; 0: none
  std::uint64_t max_steps = 0;      // work steps; 0: none
  const Cancel_flag *cancel = nullptr;
  bool any() const { return max_seconds > 0 || max_steps > 0 || cancel; }
};

// Which limit ended a call, and the message for the caller.
struct Limit_reached : std::runtime_error {
  enum Which { SECONDS, STEPS, CANCEL } which;
  Limit_reached(Which w, const std::string &m) : std::runtime_error(m), which(w) {}
};

class Work_budget {
 public:
  explicit Work_budget(const Work_limits &l);
  // Counts n steps; throws Limit_reached when a limit is reached (and from then on).
  void step(std::uint64_t n = 1) {
    const std::uint64_t done = steps_.fetch_add(n, std::memory_order_relaxed) + n;
    if (spent_.load(std::memory_order_relaxed) || (limits_.max_steps && done > limits_.max_steps) ||
        (limits_.cancel && limits_.cancel->is_set()) ||
        (limits_.max_seconds > 0 && std::chrono::steady_clock::now() >= deadline_))
      stop(done);
  }
  std::uint64_t steps() const { return steps_.load(std::memory_order_relaxed); }
  // Seconds left before max_seconds ends the call (infinity without a time limit).
  double seconds_left() const;
  // Ends the call as max_seconds does, before a step that cannot be interrupted and
  // would end past the deadline (`what` says which and its predicted time).
  [[noreturn]] void stop_ahead(const std::string &what);
  // Progress the message reports: primitive pairs (or queries) solved so far.
  void count_solved(std::uint64_t n = 1) { solved_.fetch_add(n, std::memory_order_relaxed); }

 private:
  [[noreturn]] void stop(std::uint64_t done, const std::string &ahead = "");
  Work_limits limits_;
  std::chrono::steady_clock::time_point start_, deadline_;
  std::atomic<std::uint64_t> steps_{0}, solved_{0};
  std::atomic<bool> spent_{false};
  std::atomic<int> which_{-1};  // the first limit reached
};

// The budget of the calling thread's current call (nullptr: no limits).
Work_budget *current_budget();

// Makes b the calling thread's budget until the scope ends (b may be nullptr).
class Budget_scope {
 public:
  explicit Budget_scope(Work_budget *b);
  ~Budget_scope();
  Budget_scope(const Budget_scope &) = delete;
  Budget_scope &operator=(const Budget_scope &) = delete;

 private:
  Work_budget *saved_;
};

namespace detail {
extern thread_local Work_budget *tl_budget;
}

// One unit of work of the current call (see the top of this file); nothing without limits.
inline void work_step(std::uint64_t n = 1) {
  if (Work_budget *b = detail::tl_budget) b->step(n);
}
// Work counted by its cost: `cost` limb operations (a product of an n-limb by an m-limb
// number costs n * m, a gcd of such numbers too: an upper bound of GMP's work) are
// cost / kCostPerStep steps, and the limits are checked. cost_of() is only called under
// a budget, so without limits this is one thread-local load. Operations cheaper than
// kCostPerStep add nothing and do not check (the unit steps around them do): 2^16 limb
// operations take 20-60 us, so a check costs under 1% of the operation it follows, and
// the cheap operations between two checks (at most a polynomial's coefficients, 65 of
// degree 64, times a few) stay within milliseconds.
constexpr std::uint64_t kCostPerStep = std::uint64_t(1) << 16;
template <class F>
inline void work_cost(F &&cost_of) {
  if (Work_budget *b = detail::tl_budget) {
    const std::uint64_t c = cost_of();
    if (c >= kCostPerStep) b->step(c / kCostPerStep);
  }
}

inline void work_solved() {
  if (Work_budget *b = detail::tl_budget) b->count_solved();
}

}  // namespace pccd::util
