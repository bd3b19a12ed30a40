#!/usr/bin/env bash
# ASan + UBSan run of the C tests (`make sanitize`).
#
# Builds the library with -fsanitize=address,undefined into $SAN_BUILD (default
# build-asan/, beside the normal build/, which it does not touch) and links every
# tests/c/test_*.c against it, through the Makefile's own rules (SAN and BUILD
# overridden), then runs them: any address error, leak (LeakSanitizer) or undefined
# behaviour is fatal. The FP-environment checks of the C tests run here too (the
# sanitizer runtimes must not change the rounding mode either).
set -eu
cd "$(dirname "$0")/../.."

SAN_BUILD=${SAN_BUILD:-build-asan}
SAN_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"

progs=()
for src in tests/c/test_*.c; do progs+=("$(basename "$src" .c)"); done
make --no-print-directory SAN="$SAN_FLAGS" BUILD="$SAN_BUILD" "${progs[@]/#/$SAN_BUILD/}"
for prog in "${progs[@]}"; do
  echo "== $SAN_BUILD/$prog (ASan + UBSan)"
  ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1} \
  UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
    "$SAN_BUILD/$prog"
done
echo "sanitizers: clean"
