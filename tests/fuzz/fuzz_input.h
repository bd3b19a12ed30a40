/*
 * fuzz_input.h -- the byte reader, the number encoding and the checks shared by the
 * libFuzzer harnesses tests/fuzz/fuzz_*.c (tests/fuzz/README.md).
 *
 * Byte format (tests/fuzz/seeds.py writes the same format from corpus/ and the shared
 * query set; keep the two in step). Every read past the end yields zeros, so every byte
 * string is a valid input:
 *   u8, u16, u32, i32    little-endian
 *   f64                  8 raw bytes (any bit pattern: NaN, infinities, subnormals)
 *   text                 u8 length L, then L bytes (an embedded NUL ends the C string)
 *   number               u8 tag, then by tag % 4:
 *                          0  an i8: a small integer
 *                          1  an f64
 *                          2  a text (an exact number string for the _s calls, or junk)
 *                          3  an i32 p and a u32 q: the text "p/q" (q may be 0)
 *
 * A number goes to a _d call as a double (a text through strtod, junk as 0) and to a _s
 * call as a text (a double printed with %.17g, so NaN and infinities arrive as "nan" and
 * "inf"). What every harness checks on every call (fz_rc): the status is PCCD_OK or one
 * of the documented negative codes but never PCCD_EINTERNAL (a library bug by its own
 * definition), an error message reads "pccd_function: ..." with the called function's
 * name, and the rounding mode the harness set is left unchanged. A violated check
 * aborts, so libFuzzer keeps the input as a crash.
 *
 * Cost limits (README.md, "Limits of the harnesses"): the library accepts numbers of up
 * to 100,000 characters and decimal exponents up to +-100,000, and degrees up to 64,
 * all of which it must decide exactly but which can take minutes (issue 15, item 1). A
 * harness parses such inputs (parsing is cheap) but does not solve them: a flag
 * (in->too_costly) is set once a number text is longer than FZ_MAX_TEXT or has a
 * decimal exponent beyond +-FZ_MAX_EXP, or a double is beyond 1e+-60, and the harness
 * then returns before the expensive call.
 */
#ifndef PCCD_FUZZ_INPUT_H
#define PCCD_FUZZ_INPUT_H

#include "polyccd.h"

#include <fenv.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FZ_MAX_TEXT 64 /* characters of one number text that is still solved */
#define FZ_MAX_EXP 60  /* |decimal exponent| of one number text that is still solved */

typedef struct fz_in {
  const uint8_t *p;
  size_t n;
  int too_costly; /* a number beyond the cost limits was read */
} fz_in;

typedef struct fz_num {
  int is_text;
  double d;
  char text[260];
} fz_num;

static inline uint8_t fz_u8(fz_in *in)
{
  if (in->n == 0) return 0;
  in->n--;
  return *in->p++;
}
static inline uint16_t fz_u16(fz_in *in)
{
  uint16_t lo = fz_u8(in);
  return (uint16_t)(lo | (uint16_t)fz_u8(in) << 8);
}
static inline uint32_t fz_u32(fz_in *in)
{
  uint32_t lo = fz_u16(in);
  return lo | (uint32_t)fz_u16(in) << 16;
}
static inline int32_t fz_i32(fz_in *in)
{
  uint32_t u = fz_u32(in);
  int32_t v;
  memcpy(&v, &u, sizeof v);
  return v;
}
static inline double fz_f64(fz_in *in)
{
  uint64_t b = 0;
  double d;
  for (int k = 0; k < 8; ++k) b |= (uint64_t)fz_u8(in) << (8 * k);
  memcpy(&d, &b, sizeof d);
  return d;
}
/* A text of at most 255 bytes into buf (cap >= 256). */
static inline void fz_text(fz_in *in, char *buf)
{
  size_t len = fz_u8(in);
  if (len > in->n) len = in->n;
  memcpy(buf, in->p, len);
  buf[len] = 0;
  in->p += len;
  in->n -= len;
}

/* The largest decimal exponent written in s (any e/E followed by digits), saturated. */
static inline long fz_max_exponent(const char *s)
{
  long most = 0;
  for (const char *c = s; *c; ++c) {
    if (*c != 'e' && *c != 'E') continue;
    const char *d = c + 1;
    if (*d == '+' || *d == '-') ++d;
    long v = 0;
    for (; *d >= '0' && *d <= '9'; ++d)
      if (v < 1000000000L) v = v * 10 + (*d - '0');
    if (v > most) most = v;
  }
  return most;
}

/* Whether the library's number parser would read an exponent beyond FZ_MAX_EXP or a
 * text longer than FZ_MAX_TEXT from s (a conservative scan: any e/E followed by digits). */
static inline int fz_text_cost_ok(const char *s)
{
  return strlen(s) <= FZ_MAX_TEXT && fz_max_exponent(s) <= FZ_MAX_EXP;
}

static inline void fz_number(fz_in *in, fz_num *x)
{
  uint8_t tag = fz_u8(in);
  x->is_text = 0;
  x->d = 0;
  x->text[0] = 0;
  switch (tag % 4) {
  case 0: x->d = (int8_t)fz_u8(in); break;
  case 1: x->d = fz_f64(in); break;
  case 2:
    x->is_text = 1;
    fz_text(in, x->text);
    break;
  default: {
    int32_t p = fz_i32(in);
    uint32_t q = fz_u32(in);
    x->is_text = 1;
    snprintf(x->text, sizeof x->text, "%ld/%lu", (long)p, (unsigned long)q);
  }
  }
  if (x->is_text) {
    if (!fz_text_cost_ok(x->text)) in->too_costly = 1;
    char *end = NULL;
    x->d = strtod(x->text, &end);
  } else {
    snprintf(x->text, sizeof x->text, "%.17g", x->d);
    /* the same bound for a double's decimal exponent */
    if (isfinite(x->d) && x->d != 0 && (fabs(x->d) > 1e60 || fabs(x->d) < 1e-60))
      in->too_costly = 1;
  }
}

/* Every harness's fatal check: prints what failed and aborts (libFuzzer keeps the input). */
#define FZ_ASSERT(cond)                                                           \
  do {                                                                            \
    if (!(cond)) {                                                                \
      fprintf(stderr, "fuzz check failed at %s:%d: %s\n  last error: %s\n", __FILE__, \
              __LINE__, #cond, pccd_last_error());                                \
      abort();                                                                    \
    }                                                                             \
  } while (0)

static int fz_mode = FE_TONEAREST; /* the rounding mode the harness runs the calls in */

/* Sets the rounding mode from a byte (one of the four IEEE modes). */
static inline void fz_set_mode(uint8_t b)
{
  static const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
  fz_mode = modes[b % 4];
  fesetround(fz_mode);
}
static inline void fz_restore_mode(void)
{
  fz_mode = FE_TONEAREST;
  fesetround(FE_TONEAREST);
}

/* The checks after every call: a known status, never PCCD_EINTERNAL, a message naming
 * the function, the rounding mode unchanged. Returns rc. */
static inline int fz_rc_(int rc, const char *fn)
{
  if (fegetround() != fz_mode) {
    fprintf(stderr, "fuzz check failed: %s changed the rounding mode\n", fn);
    abort();
  }
  if (rc == PCCD_OK) return rc;
  if (rc != PCCD_EINVAL && rc != PCCD_ENOMEM && rc != PCCD_ELIMIT && rc != PCCD_ERANGE &&
      rc != PCCD_ESTATE) {
    fprintf(stderr, "fuzz check failed: %s returned %d: %s\n", fn, rc, pccd_last_error());
    abort();
  }
  const char *msg = pccd_last_error();
  size_t len = strlen(fn);
  if (strncmp(msg, fn, len) != 0 || strncmp(msg + len, ": ", 2) != 0) {
    fprintf(stderr, "fuzz check failed: %s: the message does not start with \"%s: \": %s\n",
            fn, fn, msg);
    abort();
  }
  return rc;
}
/* fz_rc(pccd_f(args)): the checks of fz_rc_ with the function's name. */
#define FZ_RC(fn, ...) fz_rc_(fn(__VA_ARGS__), #fn)

/* A text output through the (buf, cap, needed) protocol of polyccd.h: the size query
 * (NULL buffer: PCCD_ERANGE and *needed), a buffer one byte short (PCCD_ERANGE, *needed,
 * untouched), then a buffer of *needed bytes (PCCD_OK, the text, *needed again). get
 * calls the getter with its other arguments in ctx. Returns the text (malloc'd, the
 * caller frees it), or NULL with *rc the status of the size query (PCCD_ESTATE: no such
 * value, PCCD_EINVAL: a bad argument). */
typedef int (*fz_text_getter)(const void *ctx, char *buf, size_t cap, size_t *needed);

static inline char *fz_read_text(fz_text_getter get, const void *ctx, const char *fn, int *rc_out)
{
  size_t needed = 0, n2 = 0, n3 = 0;
  int rc = fz_rc_(get(ctx, NULL, 0, &needed), fn);
  *rc_out = rc;
  if (rc != PCCD_ERANGE) {
    FZ_ASSERT(rc != PCCD_OK); /* a NULL buffer never receives the text */
    return NULL;
  }
  FZ_ASSERT(needed >= 2);
  char *shrt = (char *)malloc(needed - 1);
  FZ_ASSERT(shrt != NULL);
  memset(shrt, 'x', needed - 1);
  FZ_ASSERT(fz_rc_(get(ctx, shrt, needed - 1, &n2), fn) == PCCD_ERANGE && n2 == needed);
  for (size_t k = 0; k + 1 < needed; ++k) FZ_ASSERT(shrt[k] == 'x');
  free(shrt);
  char *buf = (char *)malloc(needed);
  FZ_ASSERT(buf != NULL);
  FZ_ASSERT(fz_rc_(get(ctx, buf, needed, &n3), fn) == PCCD_OK);
  FZ_ASSERT(n3 == needed && strlen(buf) + 1 == needed);
  *rc_out = PCCD_OK;
  return buf;
}

#endif /* PCCD_FUZZ_INPUT_H */
