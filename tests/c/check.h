/*
 * check.h -- the checking macros shared by the C API tests (test_body.c, test_scene.c):
 * CHECK counts and prints a failed condition with the library's last error, OK also
 * requires PCCD_OK and an unchanged rounding mode, FAILS a given status and a message
 * containing a word. Each test defines g_pass / g_fail through this header once.
 */
#ifndef PCCD_TESTS_CHECK_H
#define PCCD_TESTS_CHECK_H

#include "polyccd.h"

#include <fenv.h>
#include <stdio.h>
#include <string.h>

static int g_pass, g_fail;

static int check_(int ok, const char *expr, int line)
{
  if (ok) {
    g_pass++;
  } else {
    g_fail++;
    printf("FAIL line %d: %s\n", line, expr);
    printf("     last error: %s\n", pccd_last_error());
  }
  return ok;
}
#define CHECK(cond) check_((cond) ? 1 : 0, #cond, __LINE__)
#define OK(call) CHECK((call) == PCCD_OK && fegetround() == FE_TONEAREST)
/* A call that must fail with status rc and a message containing `word`. */
#define FAILS(call, rc, word) \
  CHECK((call) == (rc) && strstr(pccd_last_error(), (word)) != NULL)

#endif
