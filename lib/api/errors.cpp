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

int write_text(const std::string &text, char *buf, size_t cap, size_t *needed,
               const char *where) {
  if (needed) *needed = text.size() + 1;
  if (!buf || cap < text.size() + 1)
    throw Range_error(std::string(where) + ": " + std::to_string(cap) + " bytes are too few; " +
                      std::to_string(text.size() + 1) + " needed");
  std::memcpy(buf, text.c_str(), text.size() + 1);
  return PCCD_OK;
}

}  // namespace pccd::api

extern "C" PCCD_API const char *pccd_last_error(void) {
  return pccd::api::last_error_text();
}
