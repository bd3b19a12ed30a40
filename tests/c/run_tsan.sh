#!/usr/bin/env bash
# ThreadSanitizer run of the concurrency test (`make tsan`).
#
# Builds the library with gcc's -fsanitize=thread into $TSAN_BUILD (default build-tsan/,
# beside the normal build/, which it does not touch) and links tests/c/test_threads.c
# against it, through the Makefile's own rules (SAN and BUILD overridden), then runs it:
# any data race, lock-order inversion or thread leak TSan sees is fatal (halt_on_error,
# exit status 66). GMP is not instrumented: its own memory accesses are invisible to
# TSan, but every polyccd structure around them is.
set -eu
cd "$(dirname "$0")/../.."

TSAN_BUILD=${TSAN_BUILD:-build-tsan}
make --no-print-directory SAN="-fsanitize=thread -fno-omit-frame-pointer" BUILD="$TSAN_BUILD" \
  "$TSAN_BUILD/test_threads"
echo "== $TSAN_BUILD/test_threads (ThreadSanitizer)"
TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1:report_thread_leaks=1} \
  "$TSAN_BUILD/test_threads"
echo "tsan: clean"
