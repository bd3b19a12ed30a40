/*
 * check.h -- the checking macros and helpers shared by the C API tests (tests/c/test_*.c).
 * CHECK counts and prints a failed condition with the running case, the rounding mode and
 * the library's last error; OK also requires PCCD_OK and an unchanged rounding mode;
 * FAILS a given status and a message containing a word (case-sensitive, so it pins the
 * PLACE of polyccd.h's error grammar); CHECK_RC / CHECK_ERR (status, then a
 * case-insensitive mention) for calls wrapped in API(), which counts the calls after
 * which the rounding mode changed. run_in_every_mode() runs a test's cases under each
 * IEEE rounding mode (house style 21 and 39) after the no-FMA check, prints
 * "N passed, N failed" and gives the exit status. Each test includes this header once.
 *
 * No "#pragma STDC FENV_ACCESS ON": GCC ignores it with a -Wunknown-pragmas warning (an
 * error under -Werror). The tests do no floating-point arithmetic whose rounding matters
 * while a directed rounding mode is set: expected approximations are hex literals, scaled
 * inputs are built with ldexp/nextafter (exact in every mode), and the fused
 * multiply-add check runs under FE_TONEAREST. Helpers a test does not use are static
 * inline, so -Wall -Werror does not reject them.
 */
#ifndef PCCD_TESTS_CHECK_H
#define PCCD_TESTS_CHECK_H

#include "polyccd.h"

#include <fenv.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int g_pass, g_fail;
static const char *g_case = "";  /* name of the running case, printed with a failure */
static int g_mode = FE_TONEAREST; /* the rounding mode every API call must leave behind */
static const char *g_mode_name = "FE_TONEAREST";
static long g_calls, g_mode_changed; /* API calls made / calls after which the mode differed */
static int g_verbose; /* PCCD_TEST_VERBOSE set: print the message of every checked error */

static int check_(int ok, const char *expr, int line)
{
  if (ok) {
    g_pass++;
  } else {
    g_fail++;
    printf("FAIL line %d [%s, %s]: %s\n", line, g_case, g_mode_name, expr);
    printf("     last error: %s\n", pccd_last_error());
  }
  return ok;
}
#define CHECK(cond) check_((cond) ? 1 : 0, #cond, __LINE__)
#define OK(call) CHECK((call) == PCCD_OK && fegetround() == g_mode)
/* A call that must fail with status rc and a message containing `word`. */
#define FAILS(call, rc, word) \
  CHECK((call) == (rc) && strstr(pccd_last_error(), (word)) != NULL && fegetround() == g_mode)

static inline const char *rc_name(int rc)
{
  switch (rc) {
  case PCCD_OK: return "PCCD_OK";
  case PCCD_EINVAL: return "PCCD_EINVAL";
  case PCCD_ENOMEM: return "PCCD_ENOMEM";
  case PCCD_ELIMIT: return "PCCD_ELIMIT";
  case PCCD_ERANGE: return "PCCD_ERANGE";
  case PCCD_ESTATE: return "PCCD_ESTATE";
  case PCCD_EINTERNAL: return "PCCD_EINTERNAL";
  default: return "(unknown status)";
  }
}

/* rc must equal want; on a mismatch the failure shows both and the library's message. */
static inline int check_rc_(int rc, int want, const char *expr, int line)
{
  if (rc == want) {
    g_pass++;
    return 1;
  }
  g_fail++;
  printf("FAIL line %d [%s, %s]: %s returned %d %s, expected %s; pccd_last_error: \"%s\"\n",
         line, g_case, g_mode_name, expr, rc, rc_name(rc), rc_name(want),
         rc < 0 ? pccd_last_error() : "(not an error)");
  return 0;
}
#define CHECK_RC(call, want) check_rc_((call), (want), #call, __LINE__)

/* Every API call goes through API(): afterwards the rounding mode must be unchanged. */
static inline int after_call(int rc)
{
  g_calls++;
  if (fegetround() != g_mode) {
    g_mode_changed++;
    fesetround(g_mode);
  }
  return rc;
}
#define API(call) after_call(call)

/* Case-insensitive substring test (the messages' wording is the library's). */
static inline int mentions(const char *msg, const char *what)
{
  size_t n = strlen(what), i, j;
  for (i = 0; msg[i] != '\0'; i++) {
    for (j = 0; j < n; j++) {
      char a = msg[i + j], b = what[j];
      if (a >= 'A' && a <= 'Z') a = (char)(a - 'A' + 'a');
      if (b >= 'A' && b <= 'Z') b = (char)(b - 'A' + 'a');
      if (a == '\0' || a != b) break;
    }
    if (j == n) return 1;
  }
  return n == 0;
}

/* An error path: rc must be `want`, pccd_last_error() non-NULL, non-empty and, when
 * `mention` is given, it must name the offending place (an index, a value). */
static inline void check_err_(int rc, int want, const char *mention, const char *expr, int line)
{
  const char *msg;
  if (!check_rc_(rc, want, expr, line)) return;
  msg = pccd_last_error();
  if (g_verbose) printf("ok line %d: %s -> %s: \"%s\"\n", line, expr, rc_name(rc), msg ? msg : "(NULL)");
  if (!check_(msg != NULL, "pccd_last_error() != NULL", line)) return;
  if (!check_(msg[0] != '\0', "pccd_last_error() is not empty", line)) return;
  if (mention != NULL && !mentions(msg, mention)) {
    g_fail++;
    printf("FAIL line %d [%s, %s]: the message of %s does not mention \"%s\": \"%s\"\n",
           line, g_case, g_mode_name, expr, mention, msg);
  } else if (mention != NULL) {
    g_pass++;
  }
}
#define CHECK_ERR(call, want, mention) check_err_(API(call), (want), (mention), #call, __LINE__)

/* The interval filters assume that a*a + b is rounded twice (a product, then a sum):
 * a fused multiply-add would round once and break their error bounds. The library is
 * built with -ffp-contract=off; this test program is built with -std=c99, under which
 * GCC also does not contract. a = 1 + 2^-27: a*a = 1 + 2^-26 + 2^-54, which rounds to
 * 1 + 2^-26 (2^-54 is below half an ulp of 1), so a*a + b with b = -(1 + 2^-26) is 0
 * when not fused and 2^-54 when fused. */
static inline void check_no_fma(void)
{
  volatile double a = 0x1.0000002p+0, b = -0x1.0000004p+0;
  double r;
  g_case = "a*a + b is not fused";
  fesetround(FE_TONEAREST);
  r = a * a + b;
  if (!CHECK(r == 0.0)) printf("    a*a + b = %a (fused multiply-add?)\n", r);
}

/* Runs cases() under each IEEE rounding mode, after the no-FMA check: every answer must
 * be the same, and no API call may return with another mode. Prints "N passed, N failed";
 * returns the exit status (0 only when nothing failed). */
static inline int run_in_every_mode(void (*cases)(void))
{
  static const struct {
    int mode;
    const char *name;
  } modes[] = {{FE_TONEAREST, "FE_TONEAREST"},
               {FE_UPWARD, "FE_UPWARD"},
               {FE_DOWNWARD, "FE_DOWNWARD"},
               {FE_TOWARDZERO, "FE_TOWARDZERO"}};
  size_t m;

  g_verbose = getenv("PCCD_TEST_VERBOSE") != NULL;
  check_no_fma();
  for (m = 0; m < sizeof modes / sizeof modes[0]; m++) {
    g_mode = modes[m].mode;
    g_mode_name = modes[m].name;
    g_calls = g_mode_changed = 0;
    if (!CHECK(fesetround(g_mode) == 0)) continue;
    cases();
    g_case = "rounding mode preserved";
    if (!CHECK(g_mode_changed == 0))
      printf("    %ld of %ld API calls returned with a rounding mode other than %s\n",
             g_mode_changed, g_calls, g_mode_name);
  }
  fesetround(FE_TONEAREST);
  g_mode = FE_TONEAREST;
  g_mode_name = "FE_TONEAREST";
  printf("%d passed, %d failed\n", g_pass, g_fail);
  return g_fail == 0 ? 0 : 1;
}

#endif
