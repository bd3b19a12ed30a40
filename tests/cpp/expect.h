// The pass / fail counter of a tests/cpp program (one translation unit each): expect()
// counts a check and prints the first 20 failures; main prints "N passed, N failed"
// from passed and failed and returns failed != 0.
#pragma once
#include <cstdio>
#include <string>

static long passed = 0, failed = 0;

static void expect(bool ok, const std::string &what) {
  if (ok) {
    ++passed;
  } else if (++failed <= 20) {
    std::printf("FAIL %s\n", what.c_str());
  }
}
