#!/usr/bin/env bash
# ASan + UBSan run of the C tests of primitives, scenes and the on-line index (meant for
# a `make sanitize` target; see below).
#
# Builds the library with -fsanitize=address,undefined into $SAN_BUILD (default
# build-asan/, beside the normal build/, which it does not touch) through the Makefile's
# own compile rules (SAN, BUILD and LIB overridden), links the query tests (tests/c/test_config.c,
# test_query.c, test_result.c, test_solve.c, test_solve_face.c),
# test_scene.c and test_index.c against it and runs them: any address error, leak (LeakSanitizer) or undefined behaviour is fatal.
# The FP-environment checks of those tests run here too (the sanitizer runtimes must not
# change the rounding mode either).
#
# Suggested Makefile target:
#   sanitize:
#   	bash tests/c/run_sanitizers.sh
set -eu
cd "$(dirname "$0")/../.."

SAN_BUILD=${SAN_BUILD:-build-asan}
SAN_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
CC=${CC:-cc}

make --no-print-directory SAN="$SAN_FLAGS" BUILD="$SAN_BUILD" LIB="$SAN_BUILD/libpolyccd.so" \
  "$SAN_BUILD/libpolyccd.so"
for prog in test_config test_query test_result test_solve test_solve_face test_scene test_index; do
  $CC -std=c99 -Wall -Wextra -Werror -g -Iinclude $SAN_FLAGS -o "$SAN_BUILD/$prog" \
    "tests/c/$prog.c" -L"$SAN_BUILD" -lpolyccd -Wl,-rpath,'$ORIGIN' -lm
  echo "== $SAN_BUILD/$prog (ASan + UBSan)"
  ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1} \
  UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
    "$SAN_BUILD/$prog"
done
echo "sanitizers: clean"
