// The only place where C++ exceptions become C status codes. Every extern "C" entry
// point runs its body through guard(__func__, ...), so no exception crosses the C API
// and every message starts with the entry point's name.
//
// Messages follow the grammar of polyccd.h ("Error messages"): "pccd_function: PLACE:
// what is wrong", PLACE a C argument or field name with [index] subscripts, built by
// place() below.
#pragma once
#include <cstring>
#include <initializer_list>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <string>

#include "arith/errors.h"
#include "arith/interval.h"
#include "polyccd.h"
#include "util/rounding.h"
#include "util/work_budget.h"

namespace pccd::api {

// Sets the thread's last-error message ("function: what").
void set_error(const char *fn, const std::string &what);
const char *last_error_text();

// The call is not allowed in the handle's state. Maps to PCCD_ESTATE.
struct State_error : std::runtime_error {
  explicit State_error(const std::string &m) : std::runtime_error(m) {}
};

// A caller buffer is too small (*needed already written). Maps to PCCD_ERANGE.
struct Range_error : std::runtime_error {
  explicit Range_error(const std::string &m) : std::runtime_error(m) {}
};

// A PLACE of the error grammar: name followed by one [i] per index, e.g.
// place("points", {1, 0, 2}) == "points[1][0][2]".
inline std::string place(const std::string &name, std::initializer_list<size_t> indices) {
  std::string s = name;
  for (size_t i : indices) s += "[" + std::to_string(i) + "]";
  return s;
}

template <class F>
int guard(const char *fn, F &&body) noexcept {
  const util::Round_to_nearest nearest;  // the call's one rounding scope (util/rounding.h)
  try {
    return body();
  } catch (const arith::Input_error &e) {
    set_error(fn, e.what());
    return PCCD_EINVAL;
  } catch (const arith::Limit_error &e) {
    set_error(fn, e.what());
    return PCCD_ELIMIT;
  } catch (const util::Limit_reached &e) {  // a work limit of pccd_config
    set_error(fn, e.what());
    return PCCD_ELIMIT;
  } catch (const State_error &e) {
    set_error(fn, e.what());
    return PCCD_ESTATE;
  } catch (const Range_error &e) {
    set_error(fn, e.what());
    return PCCD_ERANGE;
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
// not NULL) gets the size with the NUL; a NULL or short buffer throws Range_error
// naming `where` (the buffer argument, "buf").
int write_text(const std::string &text, char *buf, size_t cap, size_t *needed,
               const char *where = "buf");

// Throws Input_error "<where>: is NULL" when p is NULL; where is the argument's name.
// The const char * overload builds no string unless p is NULL: the checks of every entry
// point's arguments are on the hot path of the linear query (tens of nanoseconds).
inline void require(const void *p, const char *where) {
  if (!p) throw arith::Input_error(std::string(where) + ": is NULL");
}
inline void require(const void *p, const std::string &where) {
  if (!p) throw arith::Input_error(where + ": is NULL");
}

// The one check that a result or report handle (any H with a bool `solved`) holds an
// answer: Input_error when h is NULL, State_error "<where>: holds no answer (nothing was
// solved into it, or the last solve failed)" when it holds none.
template <class H>
void require_solved(const H *h, const char *where) {
  require(h, where);
  if (!h->solved)
    throw State_error(std::string(where) +
                      ": holds no answer (nothing was solved into it, or the last solve failed)");
}

// The body of a getter pccd_X_Y(h, out): h checked (Solved: it must hold an answer,
// require_solved), out not NULL, then *out = value().
template <bool Solved = false, class H, class T, class F>
int getter(const char *fn, const H *h, const char *h_name, T *out, const char *out_name, F &&value) {
  return guard(fn, [&] {
    if constexpr (Solved) require_solved(h, h_name); else require(h, h_name);
    require(out, out_name);
    *out = value();
    return PCCD_OK;
  });
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
