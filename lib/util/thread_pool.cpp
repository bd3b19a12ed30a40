#include "util/thread_pool.h"

#include <cfenv>

#include "util/rounding.h"

namespace pccd::util {

unsigned usable_threads(unsigned requested) {
  if (requested <= 1) return 1;
  // Read once per process: glibc answers hardware_concurrency() by opening and parsing
  // /sys/devices/system/cpu/online, about 9 us, a quarter of a whole far-apart check.
  static const unsigned hw = std::thread::hardware_concurrency();  // 0: unknown
  const unsigned cap = hw == 0 ? 1 : hw;
  return requested < cap ? requested : cap;
}

Thread_pool::Thread_pool(unsigned threads) : threads_(usable_threads(threads)) {}

void Thread_pool::start() {
  for (unsigned i = 1; i < threads_; ++i) workers_.emplace_back([this] { work(); });
}

Thread_pool::~Thread_pool() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
  }
  start_.notify_all();
  for (auto &t : workers_) t.join();
}

// Takes items until none is left (called with mu_ unlocked).
void Thread_pool::run_items() {
  for (;;) {
    size_t i;
    {
      std::lock_guard<std::mutex> lock(mu_);
      if (next_ >= n_) return;
      i = next_++;
    }
    try {
      (*fn_)(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mu_);
      if (!error_) error_ = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mu_);
    if (++finished_ == n_) done_.notify_all();
  }
}

void Thread_pool::work() {
  unsigned seen = 0;
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mu_);
      start_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      ++busy_;
    }
    {
      // The caller's rounding and work limits (round_, nearest_, budget_ set under mu_).
      const Adopted_rounding rounding(round_, nearest_);
      const Budget_scope scope(budget_);
      run_items();
    }
    std::lock_guard<std::mutex> lock(mu_);
    if (--busy_ == 0) done_.notify_all();
  }
}

void Thread_pool::parallel_for(size_t n, const std::function<void(size_t)> &fn) {
  if (n == 0) return;
  if (threads_ == 1 || n == 1) {
    for (size_t i = 0; i < n; ++i) fn(i);
    return;
  }
  if (workers_.empty()) start();
  {
    std::lock_guard<std::mutex> lock(mu_);
    fn_ = &fn;
    n_ = n;
    round_ = std::fegetround();
    nearest_ = nearest_mode();
    budget_ = current_budget();
    next_ = finished_ = 0;
    error_ = nullptr;
    ++generation_;
  }
  start_.notify_all();
  run_items();
  std::unique_lock<std::mutex> lock(mu_);
  // All items finished and no worker still inside run_items (it reads fn_ and n_).
  done_.wait(lock, [&] { return finished_ == n_ && busy_ == 0; });
  fn_ = nullptr;
  n_ = 0;
  if (error_) {
    std::exception_ptr e = error_;
    error_ = nullptr;
    lock.unlock();
    std::rethrow_exception(e);
  }
}

}  // namespace pccd::util
