#include "util/work_budget.h"

#include <cstdio>
#include <limits>

namespace pccd::util {

namespace detail {
thread_local Work_budget *tl_budget = nullptr;
}

Work_budget *current_budget() { return detail::tl_budget; }

Budget_scope::Budget_scope(Work_budget *b) : saved_(detail::tl_budget) { detail::tl_budget = b; }
Budget_scope::~Budget_scope() { detail::tl_budget = saved_; }

Work_budget::Work_budget(const Work_limits &l) : limits_(l), start_(std::chrono::steady_clock::now()) {
  if (l.max_seconds > 0) {
    // Clamp: a limit of years is no limit, and the duration must not overflow.
    const double s = l.max_seconds < 1e9 ? l.max_seconds : 1e9;
    deadline_ = start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(s));
  }
}

double Work_budget::seconds_left() const {
  if (limits_.max_seconds <= 0) return std::numeric_limits<double>::infinity();
  return std::chrono::duration<double>(deadline_ - std::chrono::steady_clock::now()).count();
}

void Work_budget::stop_ahead(const std::string &what) {
  int none = -1;
  which_.compare_exchange_strong(none, Limit_reached::SECONDS);
  spent_.store(true, std::memory_order_relaxed);
  stop(steps_.load(), which_.load() == Limit_reached::SECONDS ? what : "");
}

void Work_budget::stop(std::uint64_t done, const std::string &ahead) {
  // The first limit reached names the stop; later steps (other threads) repeat it.
  int w = which_.load(std::memory_order_relaxed);
  if (w < 0) {
    const int mine = limits_.cancel && limits_.cancel->is_set()            ? Limit_reached::CANCEL
                     : limits_.max_steps && done > limits_.max_steps ? Limit_reached::STEPS
                                                                     : Limit_reached::SECONDS;
    which_.compare_exchange_strong(w, mine);
    w = which_.load();
    spent_.store(true, std::memory_order_relaxed);
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const unsigned long long steps = limits_.max_steps && w == Limit_reached::STEPS ? limits_.max_steps
                                                                                  : done;
  char progress[160];
  const unsigned long long solved = solved_.load();
  if (solved > 0)
    std::snprintf(progress, sizeof progress, "after %llu work steps and %.3g s, %llu primitive pairs solved",
                  steps, secs, solved);
  else
    std::snprintf(progress, sizeof progress, "after %llu work steps and %.3g s", steps, secs);
  char head[120];
  switch (w) {
    case Limit_reached::STEPS:
      std::snprintf(head, sizeof head, "config.max_work: the limit of %llu work steps was reached",
                    static_cast<unsigned long long>(limits_.max_steps));
      break;
    case Limit_reached::SECONDS:
      std::snprintf(head, sizeof head, "config.max_seconds: the time limit of %g s %s",
                    limits_.max_seconds, ahead.empty() ? "was reached" : "would be passed by ");
      break;
    default:
      std::snprintf(head, sizeof head, "config.cancel: the call was cancelled");
  }
  throw Limit_reached(static_cast<Limit_reached::Which>(w),
                      std::string(head) + ahead + " (" + progress + "); no answer");
}

}  // namespace pccd::util
