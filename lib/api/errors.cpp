#include <string>

#include "api/guard.h"

namespace pccd::api {
namespace {
thread_local std::string last_error = "no error";
}

void set_error(const char *fn, const std::string &what) {
  try {
    last_error = std::string(fn) + ": " + what;
  } catch (...) {
    // Out of memory while reporting: keep the previous text; the status still tells.
  }
}

const char *last_error_text() { return last_error.c_str(); }

}  // namespace pccd::api

extern "C" PCCD_API const char *pccd_last_error(void) {
  return pccd::api::last_error_text();
}
