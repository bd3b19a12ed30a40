// A fixed set of worker threads for parallel loops whose results are stored by index,
// so the outcome never depends on the number of threads or on scheduling.
#pragma once
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "util/work_budget.h"

namespace pccd::util {

// min(requested, the hardware's thread count), at least 1.
unsigned usable_threads(unsigned requested);

class Thread_pool {
 public:
  // threads >= 1; 1 runs everything inline. At most usable_threads(threads) run: more
  // threads than the hardware has only add switching (a 1024-thread request on 2 cores
  // ran 6x slower than 2), and no answer depends on the count. The workers start with
  // the first loop of more than one item (a far-apart body pair, which never has one,
  // costs no thread start: about 45 us with two threads).
  explicit Thread_pool(unsigned threads);
  ~Thread_pool();
  Thread_pool(const Thread_pool &) = delete;
  Thread_pool &operator=(const Thread_pool &) = delete;

  // Runs fn(i) for i in [0, n), in parallel; returns when all are done. The first
  // exception thrown by any fn is rethrown here (the others are dropped). Every fn(i)
  // runs in the caller's rounding (mode and flag, rounding.h) and under the caller's work budget
  // (work_budget.h; the workers take both on before each loop), so results never
  // depend on which thread ran an item.
  void parallel_for(size_t n, const std::function<void(size_t)> &fn);
  unsigned size() const { return threads_; }

 private:
  void start();  // starts the workers (once)
  unsigned threads_ = 1;
  void work();
  void run_items();

  std::vector<std::thread> workers_;
  int round_ = 0;         // the caller's rounding mode (fegetround) for the current loop
  bool nearest_ = false;  // and its rounding flag (util/rounding.h)
  Work_budget *budget_ = nullptr;  // the caller's budget for the current loop
  std::mutex mu_;
  std::condition_variable start_, done_;
  const std::function<void(size_t)> *fn_ = nullptr;
  size_t n_ = 0, next_ = 0, finished_ = 0;
  unsigned generation_ = 0, busy_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
};

}  // namespace pccd::util
