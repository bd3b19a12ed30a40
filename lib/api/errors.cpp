#include <cstring>
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

int write_text(const char *fn, const std::string &text, char *buf, size_t cap, size_t *needed) {
  if (needed) *needed = text.size() + 1;
  if (!buf || cap < text.size() + 1) {
    set_error(fn, "buffer of " + std::to_string(cap) + " bytes is too small; " +
                      std::to_string(text.size() + 1) + " needed");
    return PCCD_ERANGE;
  }
  std::memcpy(buf, text.c_str(), text.size() + 1);
  return PCCD_OK;
}

}  // namespace pccd::api

extern "C" PCCD_API const char *pccd_last_error(void) {
  return pccd::api::last_error_text();
}
