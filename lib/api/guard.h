// The only place where C++ exceptions become C status codes. Every extern "C" entry
// point runs its body through guard(), so no exception crosses the C API.
#pragma once
#include <cstring>
#include <new>
#include <type_traits>
#include <string>

#include "arith/errors.h"
#include "polyccd.h"

namespace pccd::api {

// Sets the thread's last-error message ("function: what").
void set_error(const char *fn, const std::string &what);
const char *last_error_text();

template <class F>
int guard(const char *fn, F &&body) noexcept {
  try {
    return body();
  } catch (const arith::Input_error &e) {
    set_error(fn, e.what());
    return PCCD_EINVAL;
  } catch (const arith::Limit_error &e) {
    set_error(fn, e.what());
    return PCCD_ELIMIT;
  } catch (const std::bad_alloc &) {
    set_error(fn, "out of memory");
    return PCCD_ENOMEM;
  } catch (const arith::Internal_error &e) {
    set_error(fn, std::string("internal error (please report with the inputs): ") + e.what());
    return PCCD_EINTERNAL;
  } catch (const arith::Uncertain &) {
    set_error(fn, "internal error (please report with the inputs): an interval filter "
                  "failure escaped its exact fallback");
    return PCCD_EINTERNAL;
  } catch (const std::exception &e) {
    set_error(fn, std::string("internal error (please report with the inputs): ") + e.what());
    return PCCD_EINTERNAL;
  } catch (...) {
    set_error(fn, "internal error (please report with the inputs): unknown exception");
    return PCCD_EINTERNAL;
  }
}

// The integer a caller passed as a pccd_kind. C allows any int there; in C++ loading
// an enum outside its value range is undefined, so the bits are copied out instead.
inline long raw_kind(const pccd_kind &k) {
  std::underlying_type_t<pccd_kind> raw;
  std::memcpy(&raw, &k, sizeof raw);
  return static_cast<long>(raw);
}

// Writes text to (buf, cap) with the PCCD_ERANGE protocol of polyccd.h: *needed (when
// not NULL) gets the size with the NUL; a NULL or short buffer gives PCCD_ERANGE.
int write_text(const char *fn, const std::string &text, char *buf, size_t cap, size_t *needed);

// Throws Input_error "<what> is NULL" when p is NULL.
inline void require(const void *p, const char *what) {
  if (!p) throw arith::Input_error(std::string(what) + " is NULL");
}

// The body of pccd_X_new for a default-constructed handle: *out is NULL on failure.
template <class T>
int new_handle(const char *fn, T **out) {
  return guard(fn, [&] {
    require(out, "out");
    *out = nullptr;
    *out = new T;
    return PCCD_OK;
  });
}

}  // namespace pccd::api
