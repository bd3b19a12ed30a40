// Error types shared by every layer. The C API (lib/api) maps them to status codes.
#pragma once
#include <stdexcept>
#include <string>

namespace pccd::arith {

// Bad input: the message says what is wrong and where. Maps to PCCD_EINVAL.
struct Input_error : std::runtime_error {
  explicit Input_error(const std::string &m) : std::runtime_error(m) {}
};

// A documented size or degree limit was exceeded. Maps to PCCD_ELIMIT.
struct Limit_error : std::runtime_error {
  explicit Limit_error(const std::string &m) : std::runtime_error(m) {}
};

// A filter could not decide a sign with certainty. Never escapes a filtered predicate:
// the caller catches it and recomputes exactly (see lib/pred/solve.cpp).
struct Uncertain {};

// An internal invariant failed (a bug). Maps to PCCD_EINTERNAL.
struct Internal_error : std::logic_error {
  explicit Internal_error(const std::string &m) : std::logic_error(m) {}
};

}  // namespace pccd::arith
