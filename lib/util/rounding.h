// The floating-point rounding of one call: opened once per call, carried to the workers.
//
// Every C entry point runs under one Round_to_nearest (lib/api/guard.h): the thread
// computes in round-to-nearest whatever mode the caller left, and the caller's mode comes
// back at the end. Thread_pool hands the caller's mode to its workers before each loop, so
// every item of a call sees the same roundings and the certified filters take the same
// decisions and report the same stages on any thread.
//
// Who asks: arith/interval.h. Its intervals are certified in ANY rounding mode (each IEEE
// operation errs by less than one ulp, and the bounds step one ulp outward); when the
// mode is round-to-nearest it also certifies exact point results with error-free
// transformations (TwoSum, the FMA residual). nearest_mode() reads the mode the double
// operations really use, so code outside a C call (the C++ unit tests, in any mode) is
// certified too. It is one register read on x86-64 (MXCSR), no thread-local flag: a
// thread_local in a shared library costs a __tls_get_addr call per access, about 7% of
// the linear fast path when this scope kept one (callgrind, issue 25).
#pragma once
#include <cfenv>
#if defined(__x86_64__) && defined(__SSE2__)
#include <immintrin.h>
#endif

namespace pccd::util {

// Whether this thread's double operations round to nearest.
inline bool nearest_mode() {
#if defined(__x86_64__) && defined(__SSE2__)
  return (_mm_getcsr() & 0x6000u) == 0;  // MXCSR.RC, bits 13-14: 00 = to nearest
#else
  return std::fegetround() == FE_TONEAREST;
#endif
}

// While alive, the thread computes in round-to-nearest; the caller's mode comes back at
// the end. Nested scopes are harmless.
class Round_to_nearest {
 public:
  Round_to_nearest();
  ~Round_to_nearest();
  Round_to_nearest(const Round_to_nearest &) = delete;
  Round_to_nearest &operator=(const Round_to_nearest &) = delete;

 private:
  int saved_;
};

}  // namespace pccd::util
