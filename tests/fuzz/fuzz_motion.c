/*
 * fuzz_motion.c -- libFuzzer harness of the rigid motions: sequences of every
 * pccd_motion_* setter (polynomials from doubles and strings, linear / Bezier / Hermite
 * paths, axis rotations, screws, composed poses), copies, pccd_motion_validate and
 * pccd_motion_position_s, in any of the four rounding modes.
 *
 * Input (fuzz_input.h for u8, number, ...):
 *   u8 head   rounding mode = head % 4; bit 2: check that failed setters leave the
 *             motion unchanged (a validate and a position before and after each call)
 *   then up to FZ_MAX_OPS ops until the input ends: u8 op; op & 0x80: the call gets a
 *   NULL array argument (the first one); op % 12:
 *     0/1   set_translation_d/_s: u8 axis (raw: 3 and up are out of range),
 *           u8 n % (FZ_MAX_DEGREE + 2) (op & 0x40: u8 n raw, up to 255: PCCD_ELIMIT
 *           above 65), n numbers
 *     2/3   set_rotation_d/_s: u8 component (raw), then as above
 *     4     linear translation, _s when op & 0x40: 6 numbers
 *     5     Bezier translation (_s as above): 12 numbers
 *     6     Hermite translation (_s as above): 12 numbers
 *     7     axis rotation: 3 + 3 + 2 numbers (axis, center, tau0, tau1)
 *     8     screw: 3 + 3 + 3 numbers (axis, center, tau0, tau1, advance)
 *     9     compose_pose_s: u8 side (raw: 2 and up are invalid), 4 + 3 numbers
 *     10    copy: the copy replaces the motion (and must answer as it did)
 *     11    position_s: 3 numbers p and a number t
 *   at the end: validate, and the position of the body point (1, 2, 3) at t = 1/3.
 *
 * Checks beyond fuzz_input.h's: a failed setter leaves the motion unchanged (its
 * position of (1, 2, 3) at t = 1/3 and its validity before and after agree); a copy
 * answers as its original; a valid motion has a position at every t in [0, 1] asked,
 * and position's (buf, cap, needed) protocol holds.
 *
 * Cost limits (README.md): degree <= FZ_MAX_DEGREE per polynomial (counted up through
 * compositions), the number limits of fuzz_input.h before validate / position.
 */
#include "fuzz_input.h"

#define FZ_MAX_DEGREE 4
#define FZ_MAX_OPS 24

typedef struct pos_ctx {
  const pccd_motion *m;
  const char *const *p;
  const char *t;
} pos_ctx;

static int get_pos(const void *ctx, char *buf, size_t cap, size_t *needed)
{
  const pos_ctx *c = (const pos_ctx *)ctx;
  return pccd_motion_position_s(c->m, c->p, c->t, buf, cap, needed);
}

/* The motion's state as this harness sees it: validity and one position (malloc'd or
 * NULL with its status). */
typedef struct state {
  int valid_rc, pos_rc;
  char *pos;
} state;

static state state_of(const pccd_motion *m)
{
  static const char *const p[3] = {"1", "2", "3"};
  pos_ctx c = {m, p, "1/3"};
  state s;
  s.valid_rc = FZ_RC(pccd_motion_validate, m);
  s.pos = fz_read_text(get_pos, &c, "pccd_motion_position_s", &s.pos_rc);
  if (s.valid_rc == PCCD_OK) FZ_ASSERT(s.pos_rc == PCCD_OK);
  return s;
}

static void same_state(state *a, state *b)
{
  FZ_ASSERT(a->valid_rc == b->valid_rc && a->pos_rc == b->pos_rc);
  if (a->pos) FZ_ASSERT(strcmp(a->pos, b->pos) == 0);
  free(a->pos);
  free(b->pos);
}

static void numbers(fz_in *in, size_t n, fz_num *x, double *d, const char **s)
{
  for (size_t i = 0; i < n; ++i) {
    fz_number(in, &x[i]);
    d[i] = x[i].d;
    s[i] = x[i].text;
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  fz_in in = {data, size, 0};
  uint8_t head = fz_u8(&in);
  static fz_num x[256];
  double d[256];
  const char *s[256];
  int degree = 0; /* a bound on the degrees of the motion's polynomials */
  pccd_motion *m = NULL;
  fz_set_mode(head);
  FZ_ASSERT(FZ_RC(pccd_motion_new, &m) == PCCD_OK);
  for (int ops = 0; ops < FZ_MAX_OPS && in.n > 0; ++ops) {
    uint8_t op = fz_u8(&in);
    int nul = op & 0x80, str = op & 0x40, rc = PCCD_OK, costly = in.too_costly;
    size_t idx, n;
    /* the state before the call, to compare after a failed one (when cheap to get) */
    state before = {0, 0, NULL};
    int compare = (head & 4) && !costly && degree <= FZ_MAX_DEGREE && op % 12 != 10 &&
                  op % 12 != 11;
    if (compare) before = state_of(m);
    switch (op % 12) {
    case 0: case 1: case 2: case 3:
      idx = fz_u8(&in);
      n = str ? fz_u8(&in) : fz_u8(&in) % (FZ_MAX_DEGREE + 2);
      numbers(&in, n, x, d, s);
      if (op % 12 == 0) rc = FZ_RC(pccd_motion_set_translation_d, m, idx, nul ? NULL : d, n);
      if (op % 12 == 1) rc = FZ_RC(pccd_motion_set_translation_s, m, idx, nul ? NULL : s, n);
      if (op % 12 == 2) rc = FZ_RC(pccd_motion_set_rotation_d, m, idx, nul ? NULL : d, n);
      if (op % 12 == 3) rc = FZ_RC(pccd_motion_set_rotation_s, m, idx, nul ? NULL : s, n);
      /* the rotation's degree counts twice in positions; a bound is enough here */
      if (rc == PCCD_OK && (int)n - 1 > degree) degree = (int)n - 1;
      break;
    case 4:
      numbers(&in, 6, x, d, s);
      rc = str ? FZ_RC(pccd_motion_set_linear_translation_s, m, nul ? NULL : s, s + 3)
               : FZ_RC(pccd_motion_set_linear_translation_d, m, nul ? NULL : d, d + 3);
      if (rc == PCCD_OK && degree < 1) degree = 1;
      break;
    case 5:
      numbers(&in, 12, x, d, s);
      rc = str ? FZ_RC(pccd_motion_set_bezier_translation_s, m, nul ? NULL : s)
               : FZ_RC(pccd_motion_set_bezier_translation_d, m, nul ? NULL : d);
      if (rc == PCCD_OK && degree < 3) degree = 3;
      break;
    case 6:
      numbers(&in, 12, x, d, s);
      rc = str ? FZ_RC(pccd_motion_set_hermite_translation_s, m, nul ? NULL : s, s + 3, s + 6, s + 9)
               : FZ_RC(pccd_motion_set_hermite_translation_d, m, nul ? NULL : d, d + 3, d + 6, d + 9);
      if (rc == PCCD_OK && degree < 3) degree = 3;
      break;
    case 7:
      numbers(&in, 8, x, d, s);
      rc = FZ_RC(pccd_motion_set_axis_rotation_s, m, nul ? NULL : s, s + 3, s[6], s[7]);
      if (rc == PCCD_OK) degree = 1;
      break;
    case 8:
      numbers(&in, 9, x, d, s);
      rc = FZ_RC(pccd_motion_set_screw_s, m, nul ? NULL : s, s + 3, s[6], s[7], s[8]);
      if (rc == PCCD_OK) degree = 1;
      break;
    case 9:
      idx = fz_u8(&in);
      numbers(&in, 7, x, d, s);
      rc = FZ_RC(pccd_motion_compose_pose_s, m, (int)idx, nul ? NULL : s, s + 4);
      break;
    case 10: {
      pccd_motion *c = NULL;
      FZ_ASSERT(FZ_RC(pccd_motion_copy, &c, NULL) == PCCD_EINVAL && c == NULL);
      FZ_ASSERT(FZ_RC(pccd_motion_copy, &c, m) == PCCD_OK);
      if (!costly && degree <= FZ_MAX_DEGREE) {
        state a = state_of(m), b = state_of(c);
        same_state(&a, &b);
      }
      pccd_motion_free(m);
      m = c;
      break;
    }
    default: {
      numbers(&in, 4, x, d, s);
      if (in.too_costly || degree > FZ_MAX_DEGREE) break;
      pos_ctx c = {m, nul ? NULL : s, s[3]};
      char *pos = fz_read_text(get_pos, &c, "pccd_motion_position_s", &rc);
      free(pos);
      if (rc == PCCD_OK) FZ_ASSERT(!nul);
    }
    }
    /* a NULL array is an error, except coeffs with n == 0 (the zero polynomial) */
    if (nul && op % 12 >= 4 && op % 12 <= 9) FZ_ASSERT(rc != PCCD_OK);
    if (compare) {
      if (rc != PCCD_OK && !in.too_costly) {
        state after = state_of(m);
        same_state(&before, &after);
      } else {
        free(before.pos);
      }
    }
  }
  if (!in.too_costly && degree <= FZ_MAX_DEGREE) {
    state a = state_of(m);
    free(a.pos);
  }
  pccd_motion_free(m);
  fz_restore_mode();
  return 0;
}
