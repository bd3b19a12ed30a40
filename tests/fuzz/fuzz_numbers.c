/*
 * fuzz_numbers.c -- libFuzzer harness of the exact number texts every _s entry point
 * parses (the rational parser of polyccd.h: "-3", "0.1", "2.5e-7", "-7/3"): the whole
 * input is one text (NUL-terminated; an embedded NUL ends it), handed to four entry
 * points that parse it at different PLACEs, in any of the four rounding modes (the last
 * input byte picks the mode and is not part of the text).
 *
 * Checks beyond fuzz_input.h's: the four calls accept or reject the text alike, with
 * the same status (a query coordinate, a query radius, a motion translation coefficient
 * and a body point given to pccd_motion_position_s); an accepted text's exact value,
 * printed back by pccd_motion_position_s of the stationary motion as "p/q 0 0", is a
 * canonical number text (an integer, or a fraction with q > 1 and no leading zeros)
 * that parses back to itself (when within the text limit); a rejected text's message names the PLACE of each call.
 *
 * Cost limits (README.md): texts up to -max_len (512) characters; a text with a decimal
 * exponent from FZ_NUM_MAX_EXP to PCCD_MAX_EXPONENT is skipped (valid, but each parse
 * builds and reduces numbers of up to 100,000 digits: milliseconds under ASan); beyond
 * PCCD_MAX_EXPONENT it is rejected at once, and fuzzed.
 */
#include "fuzz_input.h"

#define FZ_NUM_MAX_EXP 2000

typedef struct pos_ctx {
  const pccd_motion *m;
  const char *const *p;
} pos_ctx;

static int get_pos(const void *ctx, char *buf, size_t cap, size_t *needed)
{
  const pos_ctx *c = (const pos_ctx *)ctx;
  return pccd_motion_position_s(c->m, c->p, "1/2", buf, cap, needed);
}

static int is_digits(const char *s, size_t n)
{
  if (n == 0) return 0;
  for (size_t i = 0; i < n; ++i)
    if (s[i] < '0' || s[i] > '9') return 0;
  return 1;
}

/* "p", "-p" or "p/q" with no leading zeros (but "0"), q > 1; returns 1 when canonical. */
static int canonical(const char *s, size_t n)
{
  if (n > 0 && s[0] == '-') ++s, --n;
  const char *slash = memchr(s, '/', n);
  size_t np = slash ? (size_t)(slash - s) : n;
  if (!is_digits(s, np) || (np > 1 && s[0] == '0')) return 0;
  if (!slash) return 1;
  const char *q = slash + 1;
  size_t nq = n - np - 1;
  if (!is_digits(q, nq) || q[0] == '0' || (nq == 1 && q[0] == '1')) return 0;
  return !(np == 1 && s[0] == '0'); /* 0 is "0", not "0/q" */
}

/* The value's text printed back by position_s (first coordinate), or NULL and *rc. */
static char *value_text(const pccd_motion *m, const char *text, int *rc)
{
  const char *p[3] = {text, "0", "0"};
  pos_ctx c = {m, p};
  char *out = fz_read_text(get_pos, &c, "pccd_motion_position_s", rc);
  if (out) {
    size_t n = strlen(out);
    FZ_ASSERT(n >= 5 && strcmp(out + n - 4, " 0 0") == 0);
    out[n - 4] = 0;
  }
  return out;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size == 0) return 0;
  char *text = (char *)malloc(size);
  FZ_ASSERT(text != NULL);
  memcpy(text, data, size - 1);
  text[size - 1] = 0;
  long e = fz_max_exponent(text);
  if (e >= FZ_NUM_MAX_EXP && e <= PCCD_MAX_EXPONENT) {
    free(text);
    return 0;
  }
  pccd_query *q = NULL;
  pccd_motion *m = NULL;
  FZ_ASSERT(FZ_RC(pccd_query_new, &q, PCCD_SPHERE_SPHERE) == PCCD_OK);
  FZ_ASSERT(FZ_RC(pccd_motion_new, &m) == PCCD_OK);
  fz_set_mode(data[size - 1]);
  const char *one[1] = {text};
  int rc[4];
  rc[0] = FZ_RC(pccd_query_set_coord_s, q, 1, 2, one, 1);
  if (rc[0] != PCCD_OK) FZ_ASSERT(strstr(pccd_last_error(), ": points[1][2][0]: ") != NULL);
  rc[1] = FZ_RC(pccd_query_set_radius_s, q, 1, text);
  if (rc[1] != PCCD_OK) FZ_ASSERT(strstr(pccd_last_error(), ": radii[1]: ") != NULL);
  rc[2] = FZ_RC(pccd_motion_set_translation_s, m, 0, one, 1);
  if (rc[2] != PCCD_OK) FZ_ASSERT(strstr(pccd_last_error(), ": translation[0][0]: ") != NULL);
  pccd_motion *id = NULL;
  FZ_ASSERT(FZ_RC(pccd_motion_new, &id) == PCCD_OK);
  char *v = value_text(id, text, &rc[3]);
  if (rc[3] != PCCD_OK) FZ_ASSERT(strstr(pccd_last_error(), ": p[0]: ") != NULL);
  for (int k = 1; k < 4; ++k) FZ_ASSERT(rc[k] == rc[0]);
  /* The round trip holds within the text limit: "1e-100000" is accepted, but its
   * canonical text "1/1000...0" has 100,003 characters, beyond it (not an error). */
  if (v && strlen(v) <= PCCD_MAX_NUMBER_CHARS) {
    int rc2;
    FZ_ASSERT(canonical(v, strlen(v)));
    char *again = value_text(id, v, &rc2);
    FZ_ASSERT(again != NULL && strcmp(again, v) == 0);
    free(again);
  }
  free(v);
  pccd_motion_free(id);
  pccd_motion_free(m);
  pccd_query_free(q);
  free(text);
  fz_restore_mode();
  return 0;
}
