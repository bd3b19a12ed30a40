/*
 * exact_rational.h -- a small non-negative decimal bignum and rationals for the query tests:
 * enough to compare the "p/q" strings the library prints, exactly, by cross-
 * multiplication (no GMP in the test, so it checks the library with independent code).
 * Header-only static inline functions (a test that uses few of them still compiles under
 * -Werror); included through query_check.h.
 */
#ifndef POLYCCD_TESTS_EXACT_RATIONAL_H
#define POLYCCD_TESTS_EXACT_RATIONAL_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* Base 1e9, little-endian limbs. */
#define BIG_BASE 1000000000u
#define BIG_LIMBS 600 /* 5400 decimal digits; a longer string fails a check, never overflows */

typedef struct big {
  uint32_t d[BIG_LIMBS];
  size_t n; /* limbs in use; 0 means the value 0 */
} big;

static int g_big_overflow; /* set when a value does not fit BIG_LIMBS */

static inline void big_norm(big *r)
{
  while (r->n > 0 && r->d[r->n - 1] == 0) r->n--;
}

static inline void big_small(big *r, uint32_t v)
{
  r->n = 0;
  if (v >= BIG_BASE) {
    r->d[0] = v % BIG_BASE;
    r->d[1] = v / BIG_BASE;
    r->n = 2;
  } else if (v > 0) {
    r->d[0] = v;
    r->n = 1;
  }
}

/* Digits s[0..len) (all '0'..'9', len >= 1) into r; 0 when too long. */
static inline int big_from_digits(big *r, const char *s, size_t len)
{
  size_t end = len;
  r->n = 0;
  if (len > (size_t)BIG_LIMBS * 9) {
    g_big_overflow = 1;
    return 0;
  }
  while (end > 0) {
    size_t start = end >= 9 ? end - 9 : 0, i;
    uint32_t limb = 0;
    for (i = start; i < end; i++) limb = limb * 10u + (uint32_t)(s[i] - '0');
    r->d[r->n++] = limb;
    end = start;
  }
  big_norm(r);
  return 1;
}

static inline int big_cmp(const big *a, const big *b)
{
  size_t i;
  if (a->n != b->n) return a->n < b->n ? -1 : 1;
  for (i = a->n; i-- > 0;) {
    if (a->d[i] != b->d[i]) return a->d[i] < b->d[i] ? -1 : 1;
  }
  return 0;
}

/* r = a * b; r must not alias a or b. */
static inline void big_mul(big *r, const big *a, const big *b)
{
  size_t i, j;
  if (a->n == 0 || b->n == 0) {
    r->n = 0;
    return;
  }
  if (a->n + b->n > BIG_LIMBS) {
    g_big_overflow = 1;
    r->n = 0;
    return;
  }
  memset(r->d, 0, (a->n + b->n) * sizeof r->d[0]);
  for (i = 0; i < a->n; i++) {
    uint64_t carry = 0;
    for (j = 0; j < b->n; j++) {
      /* < 1e18 + 1e9 + 1e9 < 2^64 */
      uint64_t cur = (uint64_t)r->d[i + j] + (uint64_t)a->d[i] * b->d[j] + carry;
      r->d[i + j] = (uint32_t)(cur % BIG_BASE);
      carry = cur / BIG_BASE;
    }
    for (j = i + b->n; carry != 0; j++) {
      uint64_t cur = (uint64_t)r->d[j] + carry;
      r->d[j] = (uint32_t)(cur % BIG_BASE);
      carry = cur / BIG_BASE;
    }
  }
  r->n = a->n + b->n;
  big_norm(r);
}

/* r = a + b (r may alias a or b). */
static inline void big_add(big *r, const big *a, const big *b)
{
  size_t n = a->n > b->n ? a->n : b->n, i;
  uint32_t carry = 0;
  if (n + 1 > BIG_LIMBS) {
    g_big_overflow = 1;
    r->n = 0;
    return;
  }
  for (i = 0; i < n; i++) {
    uint32_t s = carry + (i < a->n ? a->d[i] : 0) + (i < b->n ? b->d[i] : 0);
    carry = s >= BIG_BASE;
    r->d[i] = carry ? s - BIG_BASE : s;
  }
  r->d[n] = carry;
  r->n = n + 1;
  big_norm(r);
}

/* r = a - b, requires a >= b (r may alias a). */
static inline void big_sub(big *r, const big *a, const big *b)
{
  size_t i;
  uint32_t borrow = 0;
  for (i = 0; i < a->n; i++) {
    uint32_t bi = (i < b->n ? b->d[i] : 0) + borrow;
    borrow = a->d[i] < bi;
    r->d[i] = borrow ? a->d[i] + BIG_BASE - bi : a->d[i] - bi;
  }
  r->n = a->n;
  big_norm(r);
}

/* A non-negative rational num/den, den > 0. */
typedef struct rat {
  big num, den;
} rat;

/* Parses "p" or "p/q" (decimal digits only, q > 0), the form the library prints times in
 * and the form the expectations below are written in. 0 when s is anything else. */
static inline int rat_parse(rat *r, const char *s)
{
  const char *slash = strchr(s, '/');
  size_t len = slash ? (size_t)(slash - s) : strlen(s), i;
  if (len == 0) return 0;
  for (i = 0; i < len; i++)
    if (s[i] < '0' || s[i] > '9') return 0;
  if (!big_from_digits(&r->num, s, len)) return 0;
  if (slash == NULL) {
    big_small(&r->den, 1);
    return 1;
  }
  len = strlen(slash + 1);
  if (len == 0) return 0;
  for (i = 0; i < len; i++)
    if (slash[1 + i] < '0' || slash[1 + i] > '9') return 0;
  if (!big_from_digits(&r->den, slash + 1, len)) return 0;
  return r->den.n != 0;
}

/* sign(a - b) */
static inline int rat_cmp(const rat *a, const rat *b)
{
  static big x, y; /* static: large (2.4 KB each); the test is single-threaded */
  big_mul(&x, &a->num, &b->den);
  big_mul(&y, &b->num, &a->den);
  return big_cmp(&x, &y);
}

/* hi - lo <= tol  <=>  hi.num lo.den tol.den <= tol.num hi.den lo.den + lo.num hi.den tol.den */
static inline int rat_width_le(const rat *lo, const rat *hi, const rat *tol)
{
  static big a, b, l, r1, r2;
  big_mul(&a, &hi->num, &lo->den);
  big_mul(&l, &a, &tol->den);
  big_mul(&a, &tol->num, &hi->den);
  big_mul(&r1, &a, &lo->den);
  big_mul(&b, &lo->num, &hi->den);
  big_mul(&r2, &b, &tol->den);
  big_add(&r1, &r1, &r2);
  return big_cmp(&l, &r1) <= 0;
}

#endif /* POLYCCD_TESTS_EXACT_RATIONAL_H */
