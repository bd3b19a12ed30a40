// The floating-point rounding of one call: opened once per call, carried to the workers.
//
// Every C entry point runs under one Round_to_nearest (lib/api/guard.h): the thread
// computes in round-to-nearest whatever mode the caller left, and records that in a
// thread-local flag. Thread_pool hands the caller's mode and flag to its workers before
// each loop (Adopted_rounding), so every item of a call sees the same roundings and the
// certified filters take the same decisions and report the same stages on any thread.
//
// What reads the flag: arith/interval.h. Its intervals are certified in ANY rounding mode
// (each IEEE operation errs by less than one ulp, and the bounds step one ulp outward);
// in round-to-nearest only, it also certifies exact point results with error-free
// transformations (TwoSum, the FMA residual). Code that runs outside a C call (the C++
// unit tests) gets the conservative default, not-nearest, unless it opens a scope.
#pragma once

namespace pccd::util {

inline thread_local bool tl_nearest = false;
// Whether this thread computes in round-to-nearest (set only by the scopes below).
inline bool nearest_mode() { return tl_nearest; }

// While alive, the thread computes in round-to-nearest and knows it; the caller's mode
// and flag come back at the end. Nested scopes are harmless.
class Round_to_nearest {
 public:
  Round_to_nearest();
  ~Round_to_nearest();
  Round_to_nearest(const Round_to_nearest &) = delete;
  Round_to_nearest &operator=(const Round_to_nearest &) = delete;

 private:
  int saved_mode_;
  bool saved_flag_;
};

// While alive, a pool worker computes in the mode and with the flag of the thread that
// started the loop (mode from fegetround there, flag from nearest_mode()).
class Adopted_rounding {
 public:
  Adopted_rounding(int mode, bool nearest);
  ~Adopted_rounding();
  Adopted_rounding(const Adopted_rounding &) = delete;
  Adopted_rounding &operator=(const Adopted_rounding &) = delete;

 private:
  int saved_mode_;
  bool saved_flag_;
};

}  // namespace pccd::util
