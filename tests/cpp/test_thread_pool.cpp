// util::Thread_pool: every item runs once, the results by index do not depend on the
// thread count, at most the hardware's thread count are started (a 1024-thread request
// on a 2-core machine ran a scene 6x slower than 2 threads before the cap), and every
// item runs in the caller's rounding mode and under the caller's work budget (a limit
// reached in a worker ends the loop with Limit_reached). Prints "N passed, N failed".
#include <atomic>
#include <chrono>
#include <cfenv>
#include <cstdio>
#include <thread>
#include <vector>

#include "util/thread_pool.h"

using pccd::util::Thread_pool;
using pccd::util::usable_threads;

static long passed = 0, failed = 0;
#define CHECK(c) ((c) ? (void)++passed : (void)(++failed, std::printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, #c)))

int main() {
  const unsigned hw = std::thread::hardware_concurrency();
  const unsigned cap = hw == 0 ? 1 : hw;
  CHECK(usable_threads(0) == 1);
  CHECK(usable_threads(1) == 1);
  CHECK(usable_threads(1024) == cap);
  CHECK(usable_threads(cap) == cap);
  for (unsigned threads : {1u, 2u, 3u, 1024u}) {
    Thread_pool pool(threads);
    CHECK(pool.size() == usable_threads(threads));
    for (int mode : {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
      std::fesetround(mode);
      const size_t n = 200;  // items of 100 us: every worker gets some
      std::vector<int> seen(n, 0), modes(n, -1);
      std::vector<double> value(n);
      pool.parallel_for(n, [&](size_t i) {
        std::this_thread::sleep_for(std::chrono::microseconds(100));
        ++seen[i];
        modes[i] = std::fegetround();
        volatile double one = 1.0, tiny = 0x1p-60;  // rounds differently by mode
        value[i] = one + tiny * double(i % 3);
      });
      std::fesetround(FE_TONEAREST);
      bool once = true, same_mode = true, same_value = true;
      for (size_t i = 0; i < n; ++i) {
        once = once && seen[i] == 1;
        same_mode = same_mode && modes[i] == mode;
        const double want = (mode == FE_UPWARD && i % 3) ? 1.0 + 0x1p-52 : 1.0;
        same_value = same_value && value[i] == want;
      }
      CHECK(once);
      CHECK(same_mode);
      CHECK(same_value);
    }
  }
  // Work budgets: every item sees the caller's; a step limit reached in any worker
  // ends parallel_for with Limit_reached, and later loops of the spent budget too.
  for (unsigned threads : {1u, 3u}) {
    Thread_pool pool(threads);
    pccd::util::Work_limits lim;
    lim.max_steps = 50;
    pccd::util::Work_budget budget(lim);
    {
      const pccd::util::Budget_scope scope(&budget);
      std::vector<const pccd::util::Work_budget *> seen(20, nullptr);
      pool.parallel_for(20, [&](size_t i) {
        std::this_thread::sleep_for(std::chrono::microseconds(100));
        seen[i] = pccd::util::current_budget();
        pccd::util::work_step();
      });
      bool all = true;
      for (auto *b : seen) all = all && b == &budget;
      CHECK(all);
      CHECK(budget.steps() == 20);
      bool stopped = false;
      try {
        pool.parallel_for(100, [&](size_t) { pccd::util::work_step(); });
      } catch (const pccd::util::Limit_reached &e) {
        stopped = e.which == pccd::util::Limit_reached::STEPS;
      }
      CHECK(stopped);
      bool again = false;
      try {
        pool.parallel_for(3, [&](size_t) { pccd::util::work_step(); });
      } catch (const pccd::util::Limit_reached &) {
        again = true;
      }
      CHECK(again);
    }
    CHECK(pccd::util::current_budget() == nullptr);  // the scope restored "no budget"
  }
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed ? 1 : 0;
}
