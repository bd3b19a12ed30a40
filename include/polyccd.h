/*
 * polyccd.h -- exact continuous collision detection of moving primitives.
 *
 * The only public header of libpolyccd. Pure C99.
 *
 * Conventions (all entry points):
 *  - Every function returns an int status: PCCD_OK (0) or a negative pccd_status.
 *    After a negative status, pccd_last_error() describes what was wrong and where.
 *  - Error messages have one grammar:   pccd_function: PLACE: what is wrong
 *    PLACE names the bad input: a C argument or struct field name, followed by zero or
 *    more [index] subscripts and .field selectors. Subscripts nest as the Python
 *    bindings' arguments do, so Python reports the same PLACE verbatim:
 *      points[1][0][2]        point 1, axis 0, coefficient 2 of a query's trajectories
 *      p_t0[3][1]             point 3, axis 1 of a linear query (p_t0[3 * 3 + 1])
 *      radii[1]               radius `which` = 1 of a query, or ball 1 of a body
 *      vertices[4][2]         vertex 4, coordinate 2 (vertices[4 * 3 + 2]); so are
 *                             centers[i][k] and ctrl[k][i] (control point k)
 *      triangles[3][1]        the second index of triangle 3
 *      translation[1][2]      axis 1, coefficient 2 of o(t); rotation[0][1]: component 0
 *                             (w), coefficient 1 of r(t); translation[1] (the whole
 *                             polynomial, e.g. for its degree)
 *      quat[2], offset[0], p1[1], tau0, t     entries of motion arguments
 *      config.time_tolerance, opt.threads     fields of option structs
 *      bodies[3].motion       the motion of scene body 3 (or of query body 3)
 *      q, res, rep, m, b, out, coeffs, which, point, axis, i, pair, contact   arguments
 *    e.g. "pccd_query_set_coord_s: points[1][0][2]: "abc" is not a number (...)",
 *    "pccd_body_new_spheres_d: radii[2]: -1/2 is not > 0", "pccd_result_time: res: holds
 *    no answer (...)". "what is wrong" gives the value and what was expected. A message
 *    about no single input keeps the form "pccd_function: what is wrong" (e.g.
 *    "pccd_motion_validate: the rotation quaternion r(t) = ... vanishes at t = 1/2").
 *  - "No contact" is a result, never a status.
 *  - Doubles are taken as their exact binary values; non-finite doubles are rejected
 *    with PCCD_EINVAL. Rationals travel as strings: an integer ("-3"), a decimal
 *    ("0.1" is exactly 1/10, "2.5e-7"), or a fraction ("-7/3").
 *  - Handles are created by pccd_X_new(&out, ...) and released by pccd_X_free(p);
 *    pccd_X_free(NULL) does nothing. The library copies every input it keeps.
 *  - Variable-size outputs use a caller buffer (buf, cap) plus *needed (bytes including
 *    the terminating NUL); when cap is too small the call returns PCCD_ERANGE, writes
 *    *needed and leaves buf untouched.
 *  - No entry point changes the floating-point environment (rounding mode) it was
 *    called with. No C++ exception ever crosses this interface.
 *  - Threads: distinct handles may be used from different threads at the same time. A
 *    handle passed as const (a query or scene solved, an index queried, a body or
 *    motion added to scenes or queried against, a result or report read) may be shared
 *    by any number of threads at once, with the same answers as one thread gets
 *    (tests/c/test_threads.c, also under ThreadSanitizer). A handle being changed (set,
 *    solved into, freed) must not be used by another thread at the same time.
 *
 * Meaning of a contact (see docs/formats.md): closed time interval [0, 1],
 * closed triangles, segments and balls; touching (distance exactly 0) is a contact.
 */
#ifndef POLYCCD_H
#define POLYCCD_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32)
#define PCCD_API
#else
#define PCCD_API __attribute__((visibility("default")))
#endif

#define PCCD_VERSION_STRING "0.1.0"

/* Status codes. Stable values, append-only. */
typedef enum pccd_status {
  PCCD_OK = 0,
  PCCD_EINVAL = -1,   /* a bad argument: NULL, out of range, non-finite, unparsable text */
  PCCD_ENOMEM = -2,   /* out of memory */
  PCCD_ELIMIT = -3,   /* a documented size or degree limit was exceeded, or a work limit
                         of pccd_config (time, work steps, cancellation) was reached */
  PCCD_ERANGE = -4,   /* an output buffer is too small; *needed tells the size */
  PCCD_ESTATE = -5,   /* the handle is not in a state that allows the call */
  PCCD_EINTERNAL = -6 /* an internal error: a bug, please report it with the inputs */
} pccd_status;

/* Kinds of primitive queries (and of the features reported in results).
 * Point order of a query:
 *   VERTEX_FACE   v, f0, f1, f2       (a point against a closed triangle)
 *   EDGE_EDGE     a0, a1, b0, b1      (two closed segments)
 *   VERTEX_EDGE   v, e0, e1           (a point against a closed segment)
 *   VERTEX_VERTEX a, b                (two points)
 *   SPHERE_SPHERE ca, cb  + radii     (two closed balls) */
typedef enum pccd_kind {
  PCCD_VERTEX_FACE = 0,
  PCCD_EDGE_EDGE = 1,
  PCCD_VERTEX_EDGE = 2,
  PCCD_VERTEX_VERTEX = 3,
  PCCD_SPHERE_SPHERE = 4
} pccd_kind;

/* Which stage of the engine decided a query (for statistics; see pccd_result_stage). */
typedef enum pccd_stage {
  PCCD_STAGE_NONE = 0,      /* no query solved into this result yet */
  PCCD_STAGE_BOUNDS = 1,    /* conservative space-time bounds separated the primitives */
  PCCD_STAGE_BERNSTEIN = 2, /* interval Bernstein enclosures excluded every contact */
  PCCD_STAGE_INTERVAL = 3,  /* the full algorithm ran in certified interval arithmetic */
  PCCD_STAGE_EXACT = 4      /* the full algorithm ran in exact rational arithmetic, or the
                               exact search for a rational first time did */
} pccd_stage;

/* Limits (PCCD_ELIMIT beyond them). */
#define PCCD_MAX_TRAJ_DEGREE 64      /* degree of one coordinate polynomial of a point */
#define PCCD_MAX_NUMBER_CHARS 100000 /* length of one number string */
#define PCCD_MAX_EXPONENT 100000     /* |e| in a decimal "1e-30" style exponent */
/* The default of pccd_config.max_number_bits: no double (at most 1,127 bits as an exact
 * fraction, subnormals included) and no decimal of fewer than ~4,900 digits exceeds it. */
#define PCCD_DEFAULT_MAX_NUMBER_BITS 16384
/* The most worker threads a call takes (pccd_scene_options.threads,
 * pccd_batch_options.threads, pccd_threads_usable): 1 to PCCD_MAX_THREADS. */
#define PCCD_MAX_THREADS 1024

/* Version of the library as "major.minor.patch"; never NULL. */
PCCD_API const char *pccd_version(void);

/* The message of the last failed call on this thread; never NULL. Meaningful only
 * right after a call returned a negative status. */
PCCD_API const char *pccd_last_error(void);

/* Number of points of a query of this kind (VERTEX_FACE 4, EDGE_EDGE 4, VERTEX_EDGE 3,
 * VERTEX_VERTEX 2, SPHERE_SPHERE 2). Returns PCCD_EINVAL for an unknown kind. */
PCCD_API int pccd_kind_points(pccd_kind kind, size_t *count);

/* A cancellation flag for running calls (pccd_config.cancel): any thread may set it
 * while calls that were given it run; they then end with PCCD_ELIMIT
 * ("config.cancel: the call was cancelled ..."). pccd_cancel_set is a lock-free atomic
 * store: safe from any thread and from a signal handler. A set flag stays set (calls
 * started with it end at once) until pccd_cancel_reset. pccd_cancel_set(NULL) returns
 * PCCD_EINVAL WITHOUT writing pccd_last_error (the one exception to the rule: writing
 * the message allocates, which a signal handler must not). */
typedef struct pccd_cancel pccd_cancel;
PCCD_API int pccd_cancel_new(pccd_cancel **out);
PCCD_API void pccd_cancel_free(pccd_cancel *c);
PCCD_API int pccd_cancel_set(pccd_cancel *c);
PCCD_API int pccd_cancel_reset(pccd_cancel *c);
/* *is_set = 1 when the flag is set. */
PCCD_API int pccd_cancel_is_set(const pccd_cancel *c, int *is_set);

/* How many worker threads a call asking for `requested` (1 to PCCD_MAX_THREADS:
 * pccd_scene_options, pccd_batch_options) starts: min(requested, the hardware's thread
 * count), at least 1.
 * Threads beyond the hardware's only add switching; no answer depends on the count.
 * PCCD_EINVAL when usable is NULL or requested is outside 1..PCCD_MAX_THREADS. */
PCCD_API int pccd_threads_usable(unsigned requested, unsigned *usable);

/* Options of a solve. Initialise with pccd_config_init, then change fields.
 *
 * Work limits (max_seconds, max_work, cancel) bound one call: a solve, a batch, a scene
 * or an index query (with all its threads). A call that reaches one returns PCCD_ELIMIT
 * and holds no answer; the message names the limit and how far the call got
 * ("config.max_work: the limit of 1000 work steps was reached (after 1000 work steps and
 * 0.02 s, 35 primitive pairs solved); no answer"). A work step is one primitive query
 * solved or one step of a root search (a bisection or refinement step): the count of a
 * call depends on its inputs and options alone, not on the thread count, so max_work
 * ends the same calls on every machine and thread count; max_seconds and cancel depend
 * on time. No answer ever depends on the limits: a call either answers as without them
 * or returns PCCD_ELIMIT.
 *
 * max_number_bits is an input limit checked before any work: every number of the
 * inputs (coordinates, radii, motion coefficients), as an exact fraction p/q in lowest
 * terms, must have bits(p) + bits(q) <= max_number_bits; else PCCD_ELIMIT naming the
 * number, before anything is solved. The exact stages' cost grows with these sizes.
 *
 * pccd_config grew the fields after want_exact in version 0.1.0; a struct_size of the
 * older layout (up to want_exact) is accepted and the newer fields take their defaults. */
typedef struct pccd_config {
  size_t struct_size;         /* set by pccd_config_init: sizeof(pccd_config) */
  const char *time_tolerance; /* width of the first-contact enclosure: a positive
                                 rational string; NULL means "1e-12". Copied. */
  int want_time;              /* 1 (default): enclose the first contact time;
                                 0: decide only whether there is a contact (the
                                 reported enclosure is then some enclosure, maybe [0,1]).
                                 Scenes, pair solves, index queries and robots: decide
                                 mode, the solve stops at the first body pair found in
                                 contact and reports it alone with a witness (features,
                                 an enclosure of one of its contact times);
                                 pccd_report_free_until. */
  int want_exact;             /* 1 (default): when the first contact time is rational,
                                 report it exactly (pccd_result_time_is_exact). Only
                                 used when want_time is 1. */
  double max_seconds;         /* wall-clock limit of one call in seconds; 0 (default):
                                 none. Finite and >= 0. */
  unsigned long long max_work; /* limit of work steps of one call; 0 (default): none */
  const pccd_cancel *cancel;  /* NULL (default), or a flag that cancels the call when set */
  size_t max_number_bits;     /* input limit: bits of the largest input number (above);
                                 default PCCD_DEFAULT_MAX_NUMBER_BITS; 0: no limit */
  const char *min_distance;   /* minimum separation delta >= 0, a rational string; NULL
                                 (default) means 0. With delta > 0 a contact is a time
                                 when the closed primitives are within distance delta
                                 (the first time the distance drops to delta or below;
                                 at t = 0 when it starts there); balls grow by delta.
                                 Every query and body kind. Scenes, pair solves and
                                 indexes take the broad phases AUTO (then BVH, index
                                 queries too), BVH, BOXES (one body's swept boxes
                                 grown by delta, rounded outward to a double) and
                                 BRUTE; RANGE (its linearized contact conditions have
                                 no delta): PCCD_EINVAL. Copied. */
} pccd_config;

/* Fills *cfg with the defaults. PCCD_EINVAL when cfg is NULL. */
PCCD_API int pccd_config_init(pccd_config *cfg);

/* A primitive query: the trajectories of the points of one pccd_kind (each coordinate a
 * polynomial of t with rational coefficients, ascending powers), and radii for spheres.
 * A new query has every point fixed at the origin and radii 0. */
typedef struct pccd_query pccd_query;

/* Creates a query of this kind. PCCD_EINVAL for an unknown kind or out == NULL. */
PCCD_API int pccd_query_new(pccd_query **out, pccd_kind kind);
PCCD_API void pccd_query_free(pccd_query *q);

/* Sets coordinate `axis` (0 = x, 1 = y, 2 = z) of point `point` to the polynomial
 * coeffs[0] + coeffs[1] t + ... + coeffs[n-1] t^(n-1). n == 0 means the zero polynomial.
 * PCCD_EINVAL: index out of range, NULL coeffs with n > 0, non-finite double, or a
 * string that is not a number (the message names the coefficient: points[point][axis][i]);
 * PCCD_ELIMIT: degree above PCCD_MAX_TRAJ_DEGREE, or a number beyond the text limits.
 * On error the query is unchanged. */
PCCD_API int pccd_query_set_coord_d(pccd_query *q, size_t point, size_t axis,
                                    const double *coeffs, size_t n);
PCCD_API int pccd_query_set_coord_s(pccd_query *q, size_t point, size_t axis,
                                    const char *const *coeffs, size_t n);

/* Sets every point to move linearly from p_t0[3i..3i+2] (t = 0) to p_t1[3i..3i+2]
 * (t = 1); each array holds pccd_kind_points(kind) * 3 doubles. A non-finite entry
 * p_t0[3i + a] is named "p_t0[i][a]". */
PCCD_API int pccd_query_set_linear_d(pccd_query *q, const double *p_t0, const double *p_t1);

/* Sets the radius of ball `which` (0 or 1) of a SPHERE_SPHERE query. Radii must be > 0
 * when the query is solved (PCCD_EINVAL from pccd_query_solve otherwise; an unset radius
 * is 0: "radii[0]: 0 is not > 0 ..."). PCCD_EINVAL for another kind ("radii: only
 * sphere-sphere queries have radii"). */
PCCD_API int pccd_query_set_radius_d(pccd_query *q, size_t which, double r);
PCCD_API int pccd_query_set_radius_s(pccd_query *q, size_t which, const char *r);

/* The result of a solve; reusable. */
typedef struct pccd_result pccd_result;
PCCD_API int pccd_result_new(pccd_result **out);
PCCD_API void pccd_result_free(pccd_result *r);

/* Decides exactly whether the primitives touch for some t in [0, 1] and, per cfg,
 * encloses the first contact time. cfg == NULL means the defaults.
 * On success *res holds the answer; on error *res is reset to "nothing solved".
 * Degenerate inputs (coplanar or collinear motion for all t, grazing double roots,
 * zero-length edges, collinear triangles, coincident points, contact at t = 0 or 1)
 * are answered exactly by the closed-set contract; nothing is perturbed. */
PCCD_API int pccd_query_solve(const pccd_query *q, const pccd_config *cfg, pccd_result *res);

/* Shortcut for the common linear query without a query handle: equivalent to
 * pccd_query_new + pccd_query_set_linear_d + pccd_query_solve. kind must not be
 * SPHERE_SPHERE. */
PCCD_API int pccd_solve_linear_d(pccd_kind kind, const double *p_t0, const double *p_t1,
                                 const pccd_config *cfg, pccd_result *res);

/* ---- Batches of linear queries ---- */

/* Options of pccd_solve_linear_batch_d; initialise with pccd_batch_options_init. */
typedef struct pccd_batch_options {
  size_t struct_size;  /* sizeof(pccd_batch_options), set by pccd_batch_options_init */
  unsigned threads;    /* worker threads, 1 to PCCD_MAX_THREADS (default 1); answers do
                          not depend on it; at most the hardware's thread count are
                          started */
} pccd_batch_options;
PCCD_API int pccd_batch_options_init(pccd_batch_options *opt);

/* Where pccd_solve_linear_batch_d writes its answers: caller-owned arrays of n entries
 * each; a NULL array is not written. Entry k answers query k exactly as
 * pccd_solve_linear_d would:
 *   collides[k]  1 when the primitives touch during [0, 1], else 0;
 *   stage[k]     the pccd_stage that decided;
 *   lo[k], hi[k] the first contact time's enclosure (pccd_result_time) rounded outward
 *                to doubles, lo[k] <= t* <= hi[k] (with cfg->want_time = 0 it may be as
 *                wide as [0, 1]); NaN when there is no contact;
 *   exact[k]     1 when t* is known exactly (then lo[k], hi[k] are the doubles around
 *                it, equal when t* is a double), else 0. */
typedef struct pccd_batch_out {
  size_t struct_size; /* sizeof(pccd_batch_out) */
  unsigned char *collides;
  int *stage;
  double *lo, *hi;
  unsigned char *exact;
} pccd_batch_out;

/* n linear queries of one kind (not SPHERE_SPHERE) in contiguous arrays: query k's
 * point i moves from t0[(k * npoints + i) * 3 + a] to t1[...], a = 0, 1, 2, npoints =
 * pccd_kind_points(kind). opt may be NULL (one thread). Every coordinate is checked
 * before any query is solved: PCCD_EINVAL names the first bad one "t0[k][i][a]" (or
 * t1) and writes no answer. n = 0 does nothing. */
PCCD_API int pccd_solve_linear_batch_d(pccd_kind kind, size_t n, const double *t0,
                                       const double *t1, const pccd_config *cfg,
                                       const pccd_batch_options *opt, pccd_batch_out *out);

/* *collides = 1 when the primitives touch during [0, 1], else 0.
 * PCCD_ESTATE when nothing was solved into res. */
PCCD_API int pccd_result_collides(const pccd_result *res, int *collides);

/* Which stage decided the query (pccd_stage). */
PCCD_API int pccd_result_stage(const pccd_result *res, int *stage);

/* The first contact time t*: lo <= t* <= hi, as "p/q" (or "p") strings.
 * which: 0 = lo, 1 = hi, 2 = the exact value (only when pccd_result_time_is_exact).
 * PCCD_ESTATE when there is no contact (or, for which = 2, no exact value). */
PCCD_API int pccd_result_time(const pccd_result *res, int which, char *buf, size_t cap,
                              size_t *needed);

/* *exact = 1 when lo == hi == t* (the first contact time is known exactly). */
PCCD_API int pccd_result_time_is_exact(const pccd_result *res, int *exact);

/* A double near t* (the nearest double to the midpoint of the enclosure). */
PCCD_API int pccd_result_time_approx(const pccd_result *res, double *t);

/* The features that touch at the first contact time (within the enclosure). Each is a
 * kind (VERTEX_FACE = the vertex inside the open face, EDGE_EDGE = the open edges
 * cross, VERTEX_EDGE = the vertex inside the open edge, VERTEX_VERTEX = the points
 * coincide, SPHERE_SPHERE) and the query point indices it involves, in the point order
 * of that kind (unused trailing entries are set to (size_t)-1). */
PCCD_API int pccd_result_feature_count(const pccd_result *res, size_t *count);
PCCD_API int pccd_result_feature(const pccd_result *res, size_t i, int *kind,
                                 size_t points[4]);

/* ---- Rigid motions ---- */

/* A rigid motion over t in [0, 1] (formats.md, MOTION; the paper, section 2): a body
 * point p (body coordinates) is at
 *     x(t) = R(r(t)) p + o(t),
 * where o(t) is the translation (the path of the body origin) and r(t) = w + x i + y j
 * + z k the rotation quaternion, polynomials of t with rational coefficients. r need
 * not have unit length: R(r) is the rotation by r/|r|,
 *     R(r) = ((w^2 - |v|^2) I + 2 v v^T + 2 w [v]x) / (w^2 + |v|^2),  v = (x, y, z),
 * the rotation by the angle 2 atan(|v| / w) about v (right-handed). Every position is
 * an exact rational function of t. A motion whose r vanishes somewhere on [0, 1] is
 * invalid (pccd_motion_validate); the setters do not check it, so that r can be built
 * one component at a time.
 *
 * Poses composed in (pccd_motion_compose_pose_s) keep x(t) a rational function of t,
 * but the path of the body origin may then no longer be a polynomial; see there. */
typedef struct pccd_motion pccd_motion;

/* Which side pccd_motion_compose_pose_s composes a pose on. */
typedef enum pccd_pose_side {
  PCCD_POSE_BODY = 0, /* x'(t) = M(R_q p + offset): the pose acts first, in body coordinates */
  PCCD_POSE_WORLD = 1 /* x'(t) = R_q M(p) + offset: the pose acts last, on world positions */
} pccd_pose_side;

/* Creates the stationary motion (identity: o = 0, r = 1). PCCD_EINVAL when out is NULL.
 * Release with pccd_motion_free; pccd_motion_free(NULL) does nothing. */
PCCD_API int pccd_motion_new(pccd_motion **out);
PCCD_API void pccd_motion_free(pccd_motion *m);

/* Creates an independent copy of m in *out. PCCD_EINVAL when out or m is NULL. */
PCCD_API int pccd_motion_copy(pccd_motion **out, const pccd_motion *m);

/* Sets coordinate `axis` (0 = x, 1 = y, 2 = z) of the translation o(t) to the
 * polynomial coeffs[0] + coeffs[1] t + ... + coeffs[n-1] t^(n-1) (n == 0: zero), and
 * keeps the rotation. Afterwards that coordinate of the body origin's path is exactly
 * this polynomial, even when a body-side pose with an offset was composed in before.
 * PCCD_EINVAL: m NULL, axis > 2, NULL coeffs with n > 0, non-finite double, or a string
 * that is not a number (the message names the coefficient, e.g. "translation[1][2]"
 * for axis 1, coefficient 2); PCCD_ELIMIT: degree above PCCD_MAX_TRAJ_DEGREE, or a number beyond
 * the text limits. On error the motion is unchanged. */
PCCD_API int pccd_motion_set_translation_d(pccd_motion *m, size_t axis, const double *coeffs,
                                           size_t n);
PCCD_API int pccd_motion_set_translation_s(pccd_motion *m, size_t axis,
                                           const char *const *coeffs, size_t n);

/* Sets component `component` (0 = w, 1 = x, 2 = y, 3 = z) of the rotation quaternion
 * r(t) to the polynomial coeffs[0..n-1] (ascending powers; n == 0: zero) and keeps the
 * translation o(t). Errors as pccd_motion_set_translation_d (the message names e.g.
 * "rotation[3][0]" for component z, coefficient 0), and PCCD_ESTATE when a body-side pose with a nonzero
 * offset was composed in: that offset turns with the old r, so the body origin's path
 * is no longer a polynomial to keep (set the rotation first, then compose). */
PCCD_API int pccd_motion_set_rotation_d(pccd_motion *m, size_t component, const double *coeffs,
                                        size_t n);
PCCD_API int pccd_motion_set_rotation_s(pccd_motion *m, size_t component,
                                        const char *const *coeffs, size_t n);

/* Translation paths: set all three coordinates of o(t) and keep the rotation (as
 * pccd_motion_set_translation_d for each axis). Degree <= 3 each.
 *  - linear:  p0 + (p1 - p0) t  (p0 at t = 0, p1 at t = 1).
 *  - bezier:  the cubic Bezier curve of the control points ctrl[0..2], ctrl[3..5],
 *             ctrl[6..8], ctrl[9..11] (c0..c3): through c0 at t = 0 and c3 at t = 1,
 *             velocities 3 (c1 - c0) and 3 (c3 - c2) there.
 *  - hermite: the cubic with position p0 and velocity v0 at t = 0, p1 and v1 at t = 1.
 * PCCD_EINVAL: a NULL pointer, a non-finite double, or an unparsable string (the
 * message names it, e.g. "ctrl[2][1]" (ctrl[7]) or "v1[2]"); PCCD_ELIMIT: a number beyond the text
 * limits. On error the motion is unchanged. */
PCCD_API int pccd_motion_set_linear_translation_d(pccd_motion *m, const double p0[3],
                                                  const double p1[3]);
PCCD_API int pccd_motion_set_linear_translation_s(pccd_motion *m, const char *const p0[3],
                                                  const char *const p1[3]);
PCCD_API int pccd_motion_set_bezier_translation_d(pccd_motion *m, const double ctrl[12]);
PCCD_API int pccd_motion_set_bezier_translation_s(pccd_motion *m, const char *const ctrl[12]);
PCCD_API int pccd_motion_set_hermite_translation_d(pccd_motion *m, const double p0[3],
                                                   const double v0[3], const double p1[3],
                                                   const double v1[3]);
PCCD_API int pccd_motion_set_hermite_translation_s(pccd_motion *m, const char *const p0[3],
                                                   const char *const v0[3],
                                                   const char *const p1[3],
                                                   const char *const v1[3]);

/* Replaces the whole motion by the rotation about the fixed axis through `center` with
 * direction `axis` (nonzero, any length), by linear interpolation of the quaternions
 * (1, tau0 axis) at t = 0 and (1, tau1 axis) at t = 1 (the paper, appendix A):
 *     r(t) = 1 + tau(t) (axis_x i + axis_y j + axis_z k),  tau(t) = tau0 + (tau1 - tau0) t.
 * At time t the body is turned about the axis by the angle theta(t) with
 * tan(theta(t) / 2) = tau(t) |axis| (right-handed; |theta| < pi), which is exact even
 * when |axis| is irrational. Every body point on the axis line stays where it is:
 * x(t) = R(r(t)) (p - center) + center. r never vanishes, so the motion is valid.
 * All inputs are rational strings. PCCD_EINVAL: a NULL pointer, an unparsable number
 * (named: "axis[1]", "center[0]", "tau0", "tau1"), or axis = (0, 0, 0); PCCD_ELIMIT: a
 * number beyond the text limits. On error the motion is unchanged. */
PCCD_API int pccd_motion_set_axis_rotation_s(pccd_motion *m, const char *const axis[3],
                                             const char *const center[3], const char *tau0,
                                             const char *tau1);

/* The screw motion: pccd_motion_set_axis_rotation_s plus the translation
 * advance * t * axis along the axis, so the body advances by advance * axis over
 * [0, 1] (a distance |advance| |axis|; advance is the distance when |axis| = 1).
 * Errors as pccd_motion_set_axis_rotation_s ("advance" names a bad advance). */
PCCD_API int pccd_motion_set_screw_s(pccd_motion *m, const char *const axis[3],
                                     const char *const center[3], const char *tau0,
                                     const char *tau1, const char *advance);

/* Replaces the whole motion by the motion between two poses, (R(q0), p0) at t = 0 and
 * (R(q1), p1) at t = 1, exactly: q = (w, x, y, z), any nonzero length. The body origin
 * moves linearly, o(t) = (1 - t) p0 + t p1, and the quaternion is interpolated linearly,
 * r(t) = (1 - t) q0 + t q1', with q1' = q1 or -q1 (the same rotation) chosen exactly so
 * that q0 . q1' >= 0: r never vanishes (the motion is valid) and the body turns the
 * shorter way round, along the great arc from q0 to q1' (not at a constant angular
 * speed). A body point p is at R(r(t)) p + o(t). PCCD_EINVAL: a NULL pointer, a
 * non-finite double or unparsable string (named "p0[2]", "q1[0]"), or a zero quaternion
 * ("q0: the zero quaternion is no rotation"); PCCD_ELIMIT: a number beyond the text
 * limits. On error the motion is unchanged. */
PCCD_API int pccd_motion_set_between_d(pccd_motion *m, const double p0[3], const double q0[4],
                                       const double p1[3], const double q1[4]);
PCCD_API int pccd_motion_set_between_s(pccd_motion *m, const char *const p0[3],
                                       const char *const q0[4], const char *const p1[3],
                                       const char *const q1[4]);

/* pccd_motion_set_between_d from two 4x4 pose matrices M0 (t = 0) and M1 (t = 1), row
 * major (M[4 r + c]): the translation is the last column's first three entries, taken
 * exactly; the rotation is the exact rotation R(q) of the unit quaternion q computed from
 * the upper-left 3x3 block in doubles (Shepperd's method), which equals the block up to
 * the rounding of that computation (about 1e-15 for an orthonormal block). PCCD_EINVAL:
 * a NULL pointer, a non-finite entry ("M0[1][2]"), a last row other than exactly
 * (0, 0, 0, 1), or a block that is not a rotation (some entry of R^T R - I above 1e-6 in
 * magnitude, or det R <= 0: the message gives both). On error the motion is unchanged. */
PCCD_API int pccd_motion_set_between_matrices_d(pccd_motion *m, const double M0[16],
                                                const double M1[16]);

/* Composes m with the constant pose (R_q, offset), where R_q = R(q) is the rotation of
 * the nonzero rational quaternion q = quat[0] + quat[1] i + quat[2] j + quat[3] k (any
 * length) and offset a rational vector:
 *   side PCCD_POSE_BODY  (0): x'(t) = M(R_q p + offset)    (e.g. a mesh placed in its body)
 *   side PCCD_POSE_WORLD (1): x'(t) = R_q M(p) + offset    (e.g. a change of world frame)
 * where M(p) is the position x(t) of p under m before the call. The result is exact and
 * has the same degrees (the rotation becomes r q or q r). After a body-side pose with a
 * nonzero offset, the body origin's path is R(r(t)) offset + o(t), a rational function
 * of t; pccd_motion_set_rotation_* then returns PCCD_ESTATE.
 * PCCD_EINVAL: a NULL pointer, side not 0 or 1, an unparsable number ("quat[2]",
 * "offset[0]"), or q = 0; PCCD_ELIMIT: a number beyond the text limits. On error the
 * motion is unchanged. */
PCCD_API int pccd_motion_compose_pose_s(pccd_motion *m, int side, const char *const quat[4],
                                        const char *const offset[3]);

/* Creates in *out the composition outer o inner of two motions at the same time t:
 *     x(t) = M_outer(M_inner(p, t), t),
 * exactly (lib/motion/rigid_motion.h): rotation r = r_outer r_inner, denominator
 * W = W_outer W_inner, homogeneous offset O = Rn(r_outer) O_inner + W_inner O_outer.
 * Degrees add (deg r = deg r_outer + deg r_inner), so a chain of n links turning about
 * their joints gives degree n. The inputs are unchanged; release *out with
 * pccd_motion_free. When r_outer is not constant, the composite's body origin path is a
 * rational function of t (as after pccd_motion_compose_pose_s with a body-side
 * offset) and pccd_motion_set_rotation_* returns PCCD_ESTATE on it.
 * PCCD_EINVAL: out, outer or inner NULL ("out", "outer", "inner"), or a factor whose
 * r(t) vanishes on [0, 1] (the composite's r vanishes exactly where one factor's does;
 * the message names the factor: "outer: the rotation quaternion r(t) ... vanishes at
 * t = 1/2 ..."); PCCD_ELIMIT: a polynomial of the composite (r, translation) of degree
 * above PCCD_MAX_TRAJ_DEGREE ("outer, inner: ..."). On error *out is NULL. */
PCCD_API int pccd_motion_compose(pccd_motion **out, const pccd_motion *outer,
                                 const pccd_motion *inner);
/* pccd_motion_compose within the limits of cfg (max_seconds, max_work, cancel:
 * PCCD_ELIMIT, *out NULL; max_number_bits: the factors' numbers, "outer.rotation[0][2]:
 * ..."). cfg NULL: no limits, as pccd_motion_compose. */
PCCD_API int pccd_motion_compose_cfg(pccd_motion **out, const pccd_motion *outer,
                                     const pccd_motion *inner, const pccd_config *cfg);

/* Decides exactly whether r(t) vanishes for some t in the CLOSED [0, 1], i.e. whether
 * w, x, y, z have a common root there (r with no common root is valid even when each
 * component has roots). PCCD_OK when the motion is valid. PCCD_EINVAL when r vanishes,
 * with the first such time in the message: exactly ("t = 1/2", including t = 0 and
 * t = 1) when it is rational, else an enclosure "lo < t < hi" of width <= 1e-12 when
 * it is irrational; also PCCD_EINVAL when r is the zero polynomial or m is NULL. */
PCCD_API int pccd_motion_validate(const pccd_motion *m);
/* pccd_motion_validate within the limits of cfg (max_seconds, max_work, cancel: ended
 * with PCCD_ELIMIT; max_number_bits: the motion's numbers, "m.rotation[0][3]: ..."
 * before any work). cfg NULL: no limits, as pccd_motion_validate. */
PCCD_API int pccd_motion_validate_cfg(const pccd_motion *m, const pccd_config *cfg);

/* The exact position x(t) of the body point p = (p[0], p[1], p[2]) at time t, written
 * to buf as "x y z": three exact rationals ("p/q", or "p" for integers) separated by
 * single spaces, NUL-terminated. p and t are rational strings; t must be in [0, 1].
 * *needed (when needed != NULL) receives the size in bytes including the NUL; when
 * cap is too small (or buf is NULL) the call returns PCCD_ERANGE and leaves buf
 * untouched. PCCD_EINVAL: m, p or an entry NULL, an unparsable number ("p[1]", "t"),
 * t outside [0, 1], or r(t) = 0 at this t (the message says so); PCCD_ELIMIT: a
 * number beyond the text limits. */
PCCD_API int pccd_motion_position_s(const pccd_motion *m, const char *const p[3], const char *t,
                                    char *buf, size_t cap, size_t *needed);
/* pccd_motion_position_s within the limits of cfg (the input limit covers p, t and the
 * motion; a time of 60,000 bits on a degree-64 motion is seconds of exact work). cfg
 * NULL: no limits, as pccd_motion_position_s. */
PCCD_API int pccd_motion_position_cfg_s(const pccd_motion *m, const char *const p[3], const char *t,
                                        const pccd_config *cfg, char *buf, size_t cap,
                                        size_t *needed);

/* ---- Kinematic chains ---- */

/* A kinematic chain (tree) of links joined by fixed, revolute, continuous or prismatic
 * joints, as in URDF, and the exact motion of every link over a joint-space segment
 * q0 -> q1 (lib/motion/chain.h has the derivations). Link k hangs from its parent by
 *     X_parent = T_origin J_k(q) X_k,
 * T_origin the joint's origin (translation xyz, rotation roll-pitch-yaw rpy:
 * Rz(yaw) Ry(pitch) Rx(roll)), J_k the motion of the joint: a rotation by q about the
 * axis (right-handed; revolute, continuous), a translation by q along it (prismatic),
 * none (fixed). Every double is taken as its exact binary value; the origin rotation is
 * the exact rotation of the quaternion qz qy qx evaluated in doubles (within ~1e-16 of
 * the roll-pitch-yaw rotation). Over a segment a revolute joint's quaternion is
 * (c(t), s(t) axis) with c, s linear between (cos(q/2), sin(q/2) / |axis|) at q0[k] and
 * q1[k] (rounded to doubles, then exact): the half-angle tangent is interpolated
 * linearly, as by pccd_motion_set_axis_rotation_s, so each link's motion is an exact
 * polynomial rigid motion whose rotation has degree = the number of revolute and
 * continuous joints above it. Policy: a revolute or continuous segment must turn by
 * less than 2 pi (|q1[k] - q0[k]| < 2 pi; split longer ones); joint limits are not
 * checked. Floating and planar joints are not supported (a chain of prismatic and
 * revolute joints expresses them). */
typedef struct pccd_chain pccd_chain;

typedef enum pccd_joint_type {
  PCCD_JOINT_FIXED = 0,
  PCCD_JOINT_REVOLUTE = 1,
  PCCD_JOINT_CONTINUOUS = 2, /* a revolute joint without limits (the same motion) */
  PCCD_JOINT_PRISMATIC = 3
} pccd_joint_type;

/* Creates an empty chain. PCCD_EINVAL when out is NULL. Release with pccd_chain_free
 * (NULL: nothing). */
PCCD_API int pccd_chain_new(pccd_chain **out);
PCCD_API void pccd_chain_free(pccd_chain *c);

/* Appends a link whose joint (a pccd_joint_type) hangs it from link `parent` (an earlier
 * link, or -1 for the world frame), with the joint origin xyz, rpy and the joint axis
 * (any nonzero length; ignored and may be NULL for a fixed joint). *index (when not
 * NULL) receives the new link's index (links are numbered 0, 1, ... in order).
 * PCCD_EINVAL: c, xyz or rpy NULL, axis NULL for a moving joint, parent out of range
 * ("parent: 5 is not -1 (the world) or an earlier link (0..2)"), an unknown joint type,
 * a non-finite double ("axis[1]", "xyz[0]", "rpy[2]"), a zero axis ("axis: the direction
 * is the zero vector"). On error the chain is unchanged. */
PCCD_API int pccd_chain_add_link(pccd_chain *c, long parent, int joint, const double axis[3],
                                 const double xyz[3], const double rpy[3], size_t *index);

/* The number of links in *n. PCCD_EINVAL when c or n is NULL. */
PCCD_API int pccd_chain_size(const pccd_chain *c, size_t *n);

/* How error messages name link k's joint value after "q0" / "q1": place replaces the
 * default "[k]" (a caller that numbers the values otherwise says so: a robot whose
 * joint 2, "elbow", moves link k gives "[2] (elbow)", and a bad value reads
 * "q1[2] (elbow): ..."). Only the messages change. PCCD_EINVAL: c or place NULL, k not
 * a link ("k: 7 out of range (the chain has 4 links)"). */
PCCD_API int pccd_chain_set_value_place(pccd_chain *c, size_t k, const char *place);

/* The world motion of every link over the segment q0 -> q1 (t = 0: q0, t = 1: q1):
 * motions[k] receives a new pccd_motion for link k (release each with
 * pccd_motion_free). q0[k], q1[k]: the value of link k's joint (radians or length
 * units; ignored for fixed joints); n must equal the number of links.
 * PCCD_EINVAL: a NULL pointer, n not the number of links ("n: 3 joint values given, the
 * chain has 4 links"), a non-finite value ("q0[2]"), a revolute segment of 2 pi or more
 * ("q1[2]: the revolute segment from 0 to 7 turns by 2 pi or more; split it ...").
 * On error every motions[k] is NULL. */
PCCD_API int pccd_chain_segment_motions(const pccd_chain *c, const double *q0, const double *q1,
                                        size_t n, pccd_motion **motions);
/* pccd_chain_segment_motions within the limits of cfg: the compositions (exact products
 * whose numbers grow with the depth of the chain) end with PCCD_ELIMIT at max_seconds,
 * max_work or cancel, and every link's motion is held to max_number_bits as soon as it
 * is built ("motions[3].rotation[0][2]: a number of 17000 bits ..."), before its
 * children are composed. On error every motions[k] is NULL. cfg NULL: no limits, as
 * pccd_chain_segment_motions. */
PCCD_API int pccd_chain_segment_motions_cfg(const pccd_chain *c, const double *q0, const double *q1,
                                            size_t n, const pccd_config *cfg, pccd_motion **motions);

/* The joint values at the rational time t in [0, 1] of the same segment, in doubles
 * (outputs, never decisions): a revolute joint's angle theta(t) = q0[k] + twice the angle
 * swept by its half-angle quaternion (c(t), s(t) |axis|) since t = 0, a prismatic joint's
 * displacement, 0 for a fixed joint. values[k] for link k. Errors as
 * pccd_chain_segment_motions, and PCCD_EINVAL for t unparsable or outside [0, 1] ("t"). */
PCCD_API int pccd_chain_joint_values_s(const pccd_chain *c, const double *q0, const double *q1,
                                       size_t n, const char *t, double *values);

/* ---- Bodies ---- */

/* A rigid body in body coordinates (formats.md, BODY): a triangle mesh or a set of
 * balls, with exact rational coordinates. A body never changes after it is created; a
 * pccd_motion moves it. The library copies the inputs.
 *
 * Mesh: vertices (nv points) and triangles (nt index triples, 0-based). At least one
 * triangle; every index < nv. Degenerate triangles are accepted and kept as given
 * (repeated indices such as (0, 0, 1), collinear or coincident vertices): a triangle is
 * the closed set its vertices span. Unused vertices are allowed.
 * The edges of a mesh are derived: every unordered pair {a, b} with a != b that is a
 * side of some triangle, listed once as (a, b) with a < b, sorted by (a, b). A side
 * with a repeated index is a point, not an edge.
 *
 * Spheres: n >= 1 closed balls, centres and radii > 0 (balls may overlap). */
typedef struct pccd_body pccd_body;

/* What a body is (pccd_body_kind). Named _type: pccd_body_kind is the query function. */
typedef enum pccd_body_type {
  PCCD_BODY_MESH = 0,
  PCCD_BODY_SPHERES = 1
} pccd_body_type;

/* Most vertices, triangles or balls of one body (PCCD_ELIMIT beyond). */
#define PCCD_MAX_BODY_ELEMENTS 50000000

/* Creates a mesh body. vertices holds nv * 3 numbers (x, y, z of vertex 0, then vertex
 * 1, ...), triangles nt * 3 indices. The _s variant takes rational strings.
 * PCCD_EINVAL: out NULL, a NULL array with a nonzero count, nt == 0, an index out of
 * range ("triangles[3][1]: index 12 out of range (10 vertices)"), a non-finite double
 * or an unparsable string ("vertices[4][2]: ..."); PCCD_ELIMIT: nv or nt above
 * PCCD_MAX_BODY_ELEMENTS, or a number beyond the text limits. *out is NULL on error.
 * Release with pccd_body_free; pccd_body_free(NULL) does nothing. */
PCCD_API int pccd_body_new_mesh_d(pccd_body **out, const double *vertices, size_t nv,
                                  const unsigned int *triangles, size_t nt);
PCCD_API int pccd_body_new_mesh_s(pccd_body **out, const char *const *vertices, size_t nv,
                                  const unsigned int *triangles, size_t nt);
/* pccd_body_new_mesh_d / _s within the limits of cfg: max_seconds, max_work and cancel
 * bound the building (the numbers' conversion, the edges, the body's hierarchy: work
 * steps per 4,096 elements), PCCD_ELIMIT when reached; max_number_bits: the body's
 * numbers ("vertices[3][1]: ..."). cfg NULL: no limits, as pccd_body_new_mesh_d / _s.
 * *out is NULL on error. */
PCCD_API int pccd_body_new_mesh_cfg_d(pccd_body **out, const double *vertices, size_t nv,
                                      const unsigned int *triangles, size_t nt,
                                      const pccd_config *cfg);
PCCD_API int pccd_body_new_mesh_cfg_s(pccd_body **out, const char *const *vertices, size_t nv,
                                      const unsigned int *triangles, size_t nt,
                                      const pccd_config *cfg);

/* Creates a body of n balls: centers holds n * 3 numbers, radii n numbers.
 * PCCD_EINVAL: out NULL, a NULL array, n == 0, a radius <= 0 ("radii[2]: -1/2 is not
 * > 0"), a non-finite double or an unparsable string ("centers[1][0]: ...");
 * PCCD_ELIMIT: n above PCCD_MAX_BODY_ELEMENTS, or a number beyond the text limits. */
PCCD_API int pccd_body_new_spheres_d(pccd_body **out, const double *centers,
                                     const double *radii, size_t n);
PCCD_API int pccd_body_new_spheres_s(pccd_body **out, const char *const *centers,
                                     const char *const *radii, size_t n);

/* Creates the solid of a mesh (docs/design.md, "Solids"): a new body with the vertices
 * and triangles of `mesh` that stands for the solid they bound, not only the surface.
 * Two bodies touch when their solids share a point (a surface mesh: its closed
 * triangles; a sphere body: its balls); so a body strictly inside a solid touches it at
 * t = 0, reported as a contact of PCCD_FEATURE_SOLID (index 0) with a vertex or ball of
 * the other body. The mesh must be closed and consistently oriented: no triangle repeats
 * a vertex index and every edge is a side of exactly two triangles, once in each
 * direction (outward or inward normals alike; the solid is the closure of the points of
 * nonzero winding number). PCCD_EINVAL: out or mesh NULL, a sphere body, or a mesh that
 * is not closed or consistently oriented, naming the first such edge in edge order
 * (pccd_body_edge) by its vertices and a triangle using it ("triangles: edge (3, 7) of
 * triangle 5 is open: ..."; "... runs the same way (3 -> 7) in triangles 5 and 9: one
 * of them is flipped ..."; "triangles[4]: (2, 2, 6) repeats a vertex index ...").
 * *out is NULL on error; release with pccd_body_free. */
PCCD_API int pccd_body_new_solid(pccd_body **out, const pccd_body *mesh);

/* *solid = 1 for a solid mesh (pccd_body_new_solid) and for a sphere body (balls are
 * solid), 0 for a surface mesh. PCCD_EINVAL when b or solid is NULL. */
PCCD_API int pccd_body_solid(const pccd_body *b, int *solid);

PCCD_API void pccd_body_free(pccd_body *b);

/* *kind = PCCD_BODY_MESH or PCCD_BODY_SPHERES (a pccd_body_type). PCCD_EINVAL when b or kind is NULL. */
PCCD_API int pccd_body_kind(const pccd_body *b, int *kind);

/* The sizes of a body: vertices (mesh) or balls (spheres), edges and triangles (0 for
 * spheres). Each output pointer may be NULL. PCCD_EINVAL when b is NULL. */
PCCD_API int pccd_body_counts(const pccd_body *b, size_t *vertices_or_spheres, size_t *edges,
                              size_t *triangles);

/* Edge i of a mesh (in the order described above): v[0] < v[1], vertex indices.
 * PCCD_EINVAL: b or v NULL, or i >= the number of edges (always for spheres). */
PCCD_API int pccd_body_edge(const pccd_body *b, size_t i, size_t v[2]);

/* The triangles incident to edge i, ascending, each once: *count (when count != NULL)
 * receives their number; when cap < that number (or tris is NULL) the call returns
 * PCCD_ERANGE and leaves tris untouched. PCCD_EINVAL as pccd_body_edge. */
PCCD_API int pccd_body_edge_triangles(const pccd_body *b, size_t i, size_t *tris, size_t cap,
                                      size_t *count);

/* ------------------------------------------------------------------------------------
 * Scenes: bodies on rigid motions, checked exactly over t in [0, 1].
 *
 * Meshes touch when their surfaces (closed triangles) share a point; sphere sets when
 * two balls of different bodies share a point; a sphere set and a mesh when a ball meets
 * a closed triangle. A solid mesh (pccd_body_new_solid) also touches a body that has a
 * vertex or ball centre strictly inside it at t = 0: first contact exactly 0. Every pair of bodies in contact is reported with its first contact
 * time and the feature pairs touching first (or all of them, with all_contacts), and
 * the scene's first contact time over all pairs.
 * ---------------------------------------------------------------------------------- */

/* A feature of one body in a contact. Indices: vertices and triangles as given, edges as
 * pccd_body_edge numbers them, balls as given. A contact found at t = 0 by the static
 * test of two meshes is TRIANGLE / TRIANGLE. */
typedef enum pccd_feature {
  PCCD_FEATURE_VERTEX = 0,
  PCCD_FEATURE_EDGE = 1,
  PCCD_FEATURE_TRIANGLE = 2,
  PCCD_FEATURE_SPHERE = 3,
  PCCD_FEATURE_SOLID = 4  /* the solid of a solid mesh (index 0) holding the other body's
                             vertex or ball at t = 0 (pccd_body_new_solid) */
} pccd_feature;

/* How candidate feature pairs are found. All give identical answers. */
typedef enum pccd_broad_phase {
  PCCD_BROAD_BOXES = 0, /* time pieces + CGAL box intersection */
  PCCD_BROAD_BRUTE = 1, /* every feature pair (a reference; quadratic) */
  PCCD_BROAD_RANGE = 2, /* linearized contact conditions, lifted points in CGAL kd-trees
                           searched with halfspace queries (the paper's section 3) */
  PCCD_BROAD_AUTO = 3,  /* the default: the phase the benchmarks measured fastest for
                           the kind of problem (docs/design.md, "Broad phases") */
  PCCD_BROAD_BVH = 4    /* a bounding-volume hierarchy kept with each body, traversed
                           for both bodies at once over time pieces (swept boxes) */
} pccd_broad_phase;

typedef struct pccd_scene pccd_scene;
typedef struct pccd_report pccd_report;

PCCD_API int pccd_scene_new(pccd_scene **out);
PCCD_API void pccd_scene_free(pccd_scene *s);
/* Appends a body with a motion (NULL: stationary). The scene keeps its own reference to
 * the body and a copy of the motion: both may be freed or changed afterwards. *index
 * (when not NULL) receives the body's position. The motion is validated by
 * pccd_scene_solve. */
PCCD_API int pccd_scene_add(pccd_scene *s, const pccd_body *body, const pccd_motion *motion,
                            size_t *index);
PCCD_API int pccd_scene_body_count(const pccd_scene *s, size_t *count);

/* Whether pccd_scene_solve checks the body pair (i, j) (either order): check = 1 (the
 * default for every pair) or 0 (skip it: e.g. adjacent links of a robot, or any pair
 * allowed to touch). A skipped pair is left out before the broad phase, whichever phase
 * runs, and never appears in a report; the bodies' motions are still validated. Pairs
 * keep their setting when bodies are added. PCCD_EINVAL: s NULL, i or j not a body index
 * ("j: 4 out of range (3 bodies)"), i == j, check not 0 or 1. */
PCCD_API int pccd_scene_set_pair_check(pccd_scene *s, size_t i, size_t j, int check);

typedef struct pccd_scene_options {
  size_t struct_size;     /* set by pccd_scene_options_init */
  unsigned threads;       /* worker threads, 1 to PCCD_MAX_THREADS (default 1); answers do
                             not depend on it; at most the hardware's thread count are
                             started */
  int all_contacts;       /* 0 (default): the feature pairs touching first;
                             1: every touching feature pair with its own first time */
  int broad_phase;        /* a pccd_broad_phase (default PCCD_BROAD_AUTO) */
} pccd_scene_options;

PCCD_API int pccd_scene_options_init(pccd_scene_options *opt);

/* Solves the scene (>= 2 bodies) into rep. cfg and opt may be NULL (defaults).
 * PCCD_EINVAL when a motion's quaternion vanishes on [0, 1] ("bodies[2].motion: ..."),
 * or on bad options ("opt.threads: 0 is outside 1..1024"). On any error rep holds no answer
 * (pccd_report_* return PCCD_ESTATE), whatever it held before. */
PCCD_API int pccd_scene_solve(const pccd_scene *s, const pccd_config *cfg,
                              const pccd_scene_options *opt, pccd_report *rep);

/* Solves the two-body scene of body a on motion ma and body b on motion mb (NULL:
 * stationary) into rep, without a pccd_scene: the answer (report, errors, messages
 * "bodies[1].motion: ...") is that of pccd_scene_solve on a scene made by
 * pccd_scene_add(a, ma) then pccd_scene_add(b, mb). The call for many checks of few
 * bodies: a far-apart pair is rejected by the root boxes of the bodies' hierarchies
 * (PCCD_BROAD_AUTO, PCCD_BROAD_BVH) in a few microseconds, and a motion handle keeps
 * its validated polynomials from the first solve that uses it until it is changed.
 * PCCD_EINVAL: a, b or rep NULL, bad options, or a motion's quaternion vanishes on
 * [0, 1]; on any error rep holds no answer. */
PCCD_API int pccd_pair_solve(const pccd_body *a, const pccd_motion *ma, const pccd_body *b,
                             const pccd_motion *mb, const pccd_config *cfg,
                             const pccd_scene_options *opt, pccd_report *rep);

PCCD_API int pccd_report_new(pccd_report **out);
PCCD_API void pccd_report_free(pccd_report *rep);

/* Whole scene: any contact, and the first contact time (which: 0 = lo, 1 = hi, 2 = exact;
 * PCCD_ESTATE when there is no contact or, for 2, no exact value). */
PCCD_API int pccd_report_collides(const pccd_report *rep, int *collides);
#define PCCD_WHOLE ((size_t)-1)
/* The time of the scene (pair == PCCD_WHOLE), of pair `pair` (contact == PCCD_WHOLE), or of
 * contact `contact` of pair `pair`, as text; which as above. */
PCCD_API int pccd_report_time(const pccd_report *rep, size_t pair, size_t contact, int which,
                              char *buf, size_t cap, size_t *needed);
/* *exact = 1 when that time is known exactly; *approx = a double near it (within the
 * enclosure). Either pointer may be NULL. */
PCCD_API int pccd_report_time_info(const pccd_report *rep, size_t pair, size_t contact,
                                   int *exact, double *approx);
/* Body pairs in contact, ascending (i, j); is_first = 1 when the pair's first contact may
 * be the scene's (exact: equal to it). */
PCCD_API int pccd_report_pair_count(const pccd_report *rep, size_t *count);
PCCD_API int pccd_report_pair(const pccd_report *rep, size_t pair, size_t *body_i,
                              size_t *body_j, int *is_first);
PCCD_API int pccd_report_contact_count(const pccd_report *rep, size_t pair, size_t *count);
/* Contact `contact` of pair `pair`: a feature of body i and one of body j. */
PCCD_API int pccd_report_contact(const pccd_report *rep, size_t pair, size_t contact,
                                 int *feature_i, size_t *index_i, int *feature_j,
                                 size_t *index_j);

/* Contact geometry: a contact point and normal of feature (feature_a, index_a) of body a
 * on motion ma and feature (feature_b, index_b) of body b on mb (NULL: stationary) that
 * touch at a time t* in [t_lo, t_hi] (rational strings; a report's contact and its time:
 * t_lo = t_hi when the time is exact). Positions are world positions at t*; an edge runs
 * from its vertex v[0] to v[1] (pccd_body_edge), a triangle has the winding given.
 * Point:  vertex-X: the vertex.  edge-edge: the crossing a0 + s d_a of the two segments,
 *         s = ((b0 - a0) x d_b) . n / |n|^2, n = d_a x d_b (parallel segments: the first
 *         of a0, a1, b0, b1 on the other segment).  sphere-sphere: c_a + r_a / (r_a + r_b)
 *         (c_b - c_a) (in both balls).  sphere-X: the closest point of X to the centre.
 *         edge-triangle, triangle-triangle (the static test at t = 0): a point of both
 *         (lib/narrow/contact_geometry.h: which one).
 * Normal (orientation): vertex-triangle (either order): (v1 - v0) x (v2 - v0) of the
 *         triangle (its winding); edge-edge: d_a x d_b; sphere-sphere: c_b - c_a; sphere-X:
 *         from a's feature towards b's (point - c_a, or c_b - point). No normal for
 *         vertex-vertex, vertex-edge, edge-triangle, triangle-triangle, parallel edges, or
 *         a zero vector.
 * t_lo = t_hi: exact values, checked: PCCD_EINVAL "the features do not touch at t = ..."
 * when the point is not on both features (e.g. a contact of a solve with
 * config.min_distance > 0: its features are within the distance, maybe apart; no
 * point is defined then). t_lo < t_hi (t* irrational): enclosures from the same
 * formulas in interval arithmetic over [t_lo, t_hi], or, where those are uncertain, the
 * intersection of the two features' boxes over [t_lo, t_hi]; they contain the true
 * values whenever the features touch in [t_lo, t_hi] (PCCD_EINVAL when they certainly
 * do not), and shrink with t_hi - t_lo (config.time_tolerance).
 * PCCD_EINVAL names the argument: a, b or out NULL, out->struct_size wrong, a feature not
 * a pccd_feature or not of the body's kind ("feature_b: triangle is not a feature of a
 * sphere body (sphere)"), an index out of range ("index_a: 12 out of range (10
 * vertices)"), a time unparsable or outside [0, 1] ("t_hi: 3/2 is outside [0, 1]"),
 * t_lo > t_hi, an invalid motion ("ma: ..."). */
typedef enum pccd_normal_state {
  PCCD_NORMAL_NONE = 0,     /* no normal is defined for these features at t* */
  PCCD_NORMAL_ENCLOSED = 1, /* normal_lo <= the unit normal <= normal_hi */
  PCCD_NORMAL_UNKNOWN = 2   /* t* enclosed too loosely to decide; normal_lo/hi = -1/1 */
} pccd_normal_state;

typedef struct pccd_contact_geometry {
  size_t struct_size;   /* the caller sets sizeof(pccd_contact_geometry) */
  double point_lo[3], point_hi[3]; /* point_lo <= the contact point <= point_hi */
  int normal_state;     /* a pccd_normal_state */
  double normal_lo[3], normal_hi[3];
  int exact;            /* 1 when t_lo = t_hi: pccd_contact_geometry_exact has the values */
} pccd_contact_geometry;

PCCD_API int pccd_contact_geometry_compute(const pccd_body *a, const pccd_motion *ma, int feature_a,
                                   size_t index_a, const pccd_body *b, const pccd_motion *mb,
                                   int feature_b, size_t index_b, const char *t_lo,
                                   const char *t_hi, pccd_contact_geometry *out);

/* The exact values at an exact time (t_lo = t_hi = t), same arguments: which 0 = the
 * point, 1 = the normal (unnormalized, as defined above), written as "x y z" (rationals
 * "p/q" or "p", single spaces) with the buffer protocol (PCCD_ERANGE, *needed).
 * PCCD_ESTATE when t_lo != t_hi (t* not exact: use the enclosures of
 * pccd_contact_geometry_compute) or, for which = 1, when no normal is defined;
 * PCCD_EINVAL as pccd_contact_geometry_compute, or which not 0 or 1. */
PCCD_API int pccd_contact_geometry_exact(const pccd_body *a, const pccd_motion *ma, int feature_a,
                                         size_t index_a, const pccd_body *b,
                                         const pccd_motion *mb, int feature_b, size_t index_b,
                                         const char *t_lo, const char *t_hi, int which,
                                         char *buf, size_t cap, size_t *needed);

/* ------------------------------------------------------------------------------------
 * The on-line collision problem (the paper's section 3): one body on its motion is
 * preprocessed once (its vertices, edges and triangles, or its balls, as lifted points
 * in range trees); then any number of query bodies on their own motions are checked
 * against it. A single query primitive is a body of one triangle or one ball.
 * ---------------------------------------------------------------------------------- */
typedef struct pccd_index pccd_index;

/* Preprocesses body on motion (NULL: stationary); the index keeps its own reference to
 * the body and a copy of the motion. PCCD_EINVAL: out or body NULL, or the motion's
 * quaternion vanishes on [0, 1] ("motion: ..."); *out is NULL on error. Release with
 * pccd_index_free; pccd_index_free(NULL) does nothing. */
PCCD_API int pccd_index_new(pccd_index **out, const pccd_body *body, const pccd_motion *motion);
/* pccd_index_new within the limits of cfg (NULL: the defaults of pccd_config_init):
 * max_seconds, max_work and cancel end the preprocessing with PCCD_ELIMIT (*out NULL);
 * max_number_bits is checked on the body and the motion first ("motion.rotation[0][1]:
 * a number of ... bits ..."). pccd_index_new is this without any limit. */
PCCD_API int pccd_index_new_cfg(pccd_index **out, const pccd_body *body, const pccd_motion *motion,
                                const pccd_config *cfg);
PCCD_API void pccd_index_free(pccd_index *ix);

/* Checks body on motion (NULL: stationary) against the indexed body over [0, 1] and
 * writes the answer to rep as a two-body scene: body 0 is the indexed body, body 1 the
 * query (so pccd_report_contact's feature_i is a feature of the indexed body). cfg and
 * opt may be NULL (defaults); opt as for pccd_scene_solve: PCCD_BROAD_AUTO and
 * PCCD_BROAD_RANGE search the index's trees (with config.min_distance > 0 AUTO is
 * PCCD_BROAD_BVH and RANGE is PCCD_EINVAL), PCCD_BROAD_BVH (the two bodies'
 * hierarchies), PCCD_BROAD_BOXES and PCCD_BROAD_BRUTE solve the pair like a scene (same
 * answers; for comparison). The index is only read:
 * several threads may query one index at once, each with its own report.
 * PCCD_EINVAL: ix, body or rep NULL, bad options (as pccd_scene_solve), or the query
 * motion's quaternion vanishes on [0, 1] ("motion: ..."). */
PCCD_API int pccd_index_query(const pccd_index *ix, const pccd_body *body,
                              const pccd_motion *motion, const pccd_config *cfg,
                              const pccd_scene_options *opt, pccd_report *rep);

/* Checks n query bodies against the index: bodies[k] on motions[k] into reports[k]
 * (motions NULL: all stationary; motions[k] NULL: body k stationary). opt->threads
 * workers share the queries, each query solved on one thread; every answer equals that
 * of pccd_index_query. Every query motion is validated before any query is solved:
 * PCCD_EINVAL "bodies[k].motion: ..." (or "bodies[k]: is NULL", "reports[k]: is NULL")
 * leaves every report unsolved. PCCD_EINVAL also when ix, or bodies or reports with
 * n > 0, is NULL, or on bad options. n = 0 does nothing. */
PCCD_API int pccd_index_query_many(const pccd_index *ix, const pccd_body *const *bodies,
                                   const pccd_motion *const *motions, size_t n,
                                   const pccd_config *cfg, const pccd_scene_options *opt,
                                   pccd_report *const *reports);

/* A certified contact-free prefix of a solved report: no checked pair touches at any
 * t < free_until (as text, like pccd_report_time; buf NULL with cap 0: only *needed and
 * *below), and *below (when not NULL) a double <= free_until. Without a contact free_until is 1 (then nothing touches on [0, 1]).
 * First-contact mode: the first contact's lo. Decide mode (cfg->want_time = 0): a
 * certified lower bound from the pairs looked at before the solve stopped (a robot
 * check's filter bounds, pccd_robot_check; 0 for a scene, and 0 for a robot check whose
 * first witness scan found a contact: decide mode spends nothing on the prefix then). For a planner's last valid state (OMPL's
 * checkMotion(s1, s2, lastValid)): every state at t < free_until is contact-free. */
PCCD_API int pccd_report_free_until(const pccd_report *rep, char *buf, size_t cap, size_t *needed,
                                    double *below);

/* ------------------------------------------------------------------------------------
 * Robots: a kinematic chain (pccd_chain) with bodies fixed to its links, kept across
 * segments (bodies and their hierarchies are made once), checked over one joint-space
 * segment q0 -> q1 against obstacles and itself.
 *
 * Each robot body belongs to a group (e.g. its URDF link): bodies of one group are never
 * checked against each other, nor two groups whose pair is allowed
 * (pccd_robot_set_allowed: adjacency, SRDF disable_collisions). Before any exact link
 * motion is built, every body pair is tested by a certified filter: each link's pose is
 * enclosed over time pieces in outward-rounded interval arithmetic straight from the
 * joint path, and the link's hierarchy against the other body's; the exact link motions
 * (those of pccd_chain_segment_motions) are built only for the links of pairs the filter
 * cannot separate, and those pairs are solved in the order of the filter's lower bound.
 * The answer is that of the exact solve of every pair.
 *
 * Report (a pccd_report, body indices: the robot's bodies in order of
 * pccd_robot_add_body, then the obstacles):
 *  - first-contact mode (default): collides, the first contact time and the pairs and
 *    features touching first, as a scene's; the pairs listed are those found in contact
 *    on the way (pairs that cannot touch before the best bound so far are not solved),
 *    and a start pose with touching bodies answers with one touching triangle pair
 *    per pair found at t = 0 rather than every one. With all_contacts every pair in
 *    contact with every touching feature pair.
 *  - decide mode (cfg->want_time = 0): stops at the first pair found in contact; the
 *    report holds that pair with a witness (some touching features, some enclosure of
 *    one of its contact times), and pccd_report_free_until a certified contact-free
 *    prefix.
 * ---------------------------------------------------------------------------------- */
typedef struct pccd_robot pccd_robot;

/* A robot of the chain (copied: later changes to chain do not reach it). */
PCCD_API int pccd_robot_new(pccd_robot **out, const pccd_chain *chain);
PCCD_API void pccd_robot_free(pccd_robot *r);
/* Fixes body to chain link `link` (in the link's frame), in group `group`; *index (when
 * not NULL) receives its body index. PCCD_EINVAL: link out of range, NULL r or body. */
PCCD_API int pccd_robot_add_body(pccd_robot *r, size_t link, size_t group, const pccd_body *body,
                                 size_t *index);
/* Replaces the allowed group pairs: (groups[2k], groups[2k + 1]) for k < n, either order. */
PCCD_API int pccd_robot_set_allowed(pccd_robot *r, const size_t *groups, size_t n);

typedef struct pccd_robot_options {
  size_t struct_size;  /* set by pccd_robot_options_init */
  int self_collision;  /* 1 (default): robot body pairs too (groups, allowed pairs); 0: none */
  int filter;          /* 1 (default): the certified filter first; 0: every pair exactly
                          (the same answers; for tests) */
} pccd_robot_options;
PCCD_API int pccd_robot_options_init(pccd_robot_options *opt);

/* Checks the segment q0 -> q1 (n = the chain's link count, values as
 * pccd_chain_segment_motions) against obstacles[k] on motions[k] (motions NULL or
 * motions[k] NULL: stationary) into rep. cfg, opt, ropt may be NULL (defaults).
 * PCCD_EINVAL: a rejected segment ("q1[3]: ..."), an obstacle motion whose quaternion
 * vanishes ("obstacles[1].motion: ..."), fewer than two bodies ("obstacles: nothing to
 * check ..."), bad options. PCCD_ELIMIT as pccd_scene_solve (input numbers: the bodies
 * as "bodies[k]", obstacles as "obstacles[k]", and the link motions, built only for the
 * pairs the filter cannot clear, as "links[k].motion.rotation[0][2]" when built; the
 * work limits hold inside their compositions). On any error rep holds no answer. */
PCCD_API int pccd_robot_check(const pccd_robot *r, const double *q0, const double *q1, size_t n,
                              const pccd_body *const *obstacles, const pccd_motion *const *motions,
                              size_t n_obstacles, const pccd_config *cfg,
                              const pccd_scene_options *opt, const pccd_robot_options *ropt,
                              pccd_report *rep);

/* Batches of robot checks: many segments (pccd_robot_check_many) or poses
 * (pccd_robot_check_states) of one robot against the same obstacles in one call.
 * opt->threads workers share the segments, each segment solved on one thread; entry k
 * is exactly the answer of pccd_robot_check on segment k (for a pose q, the segment
 * q -> q). Where pccd_robot_check_many and _states write: caller-owned arrays of
 * n_segments entries each; a NULL array is not written.
 *   status[k]    PCCD_OK when segment k was answered, else the status pccd_robot_check
 *                would return for it (PCCD_EINVAL: a bad joint value; PCCD_ELIMIT: a
 *                link motion beyond config.max_number_bits). With status NULL the
 *                first failing segment (lowest k) fails the whole call instead.
 *   messages     NULL, or n_segments * message_cap chars: segment k's error message at
 *                messages + k * message_cap, "pccd_robot_check_many: segments[k]: q1[2]
 *                (elbow): ..." (states: "states[k]: ..."), cut to message_cap - 1 chars
 *                and NUL-terminated; "" for an answered segment.
 *   collides[k]  1 when segment k is in contact, else 0 (0 when status[k] != PCCD_OK);
 *   lo[k], hi[k] the contact time's enclosure rounded outward to doubles (first-contact
 *                mode: the first contact time; decide mode: the witness's); NaN without
 *                contact or answer;
 *   free_until[k] a double <= the segment's certified contact-free prefix
 *                (pccd_report_free_until); NaN without answer;
 *   reports      NULL, or n_segments reports (entries may be NULL): reports[k] gets
 *                segment k's full report (unsolved when status[k] != PCCD_OK). */
typedef struct pccd_robot_batch_out {
  size_t struct_size; /* sizeof(pccd_robot_batch_out) */
  int *status;
  char *messages;
  size_t message_cap;
  unsigned char *collides;
  double *lo, *hi, *free_until;
  pccd_report *const *reports;
} pccd_robot_batch_out;

/* Segment k moves from q0[k * n ...] to q1[k * n ...] (row-major, n = the chain's link
 * count, values as pccd_robot_check). Everything but the joint values is checked once,
 * before any segment is solved, as pccd_robot_check (PCCD_EINVAL / PCCD_ELIMIT of the
 * whole call, nothing written). The work limits (max_seconds, max_work, cancel) bound
 * the whole batch: reaching one ends the call with PCCD_ELIMIT and no answer is
 * readable (every status[k] PCCD_ESTATE, every report unsolved). Otherwise the call
 * returns PCCD_OK with every segment's status (with status NULL: PCCD_OK only when
 * every segment was answered). n_segments = 0 does nothing. */
PCCD_API int pccd_robot_check_many(const pccd_robot *r, const double *q0, const double *q1,
                                   size_t n_segments, size_t n,
                                   const pccd_body *const *obstacles,
                                   const pccd_motion *const *motions, size_t n_obstacles,
                                   const pccd_config *cfg, const pccd_scene_options *opt,
                                   const pccd_robot_options *ropt, pccd_robot_batch_out *out);
/* State validity of n_states poses q[k * n ...]: entry k answers whether the robot at
 * pose k touches an obstacle or itself (the segment q_k -> q_k), as
 * pccd_robot_check_many ("states[k]" in messages). */
PCCD_API int pccd_robot_check_states(const pccd_robot *r, const double *q, size_t n_states,
                                     size_t n, const pccd_body *const *obstacles,
                                     const pccd_motion *const *motions, size_t n_obstacles,
                                     const pccd_config *cfg, const pccd_scene_options *opt,
                                     const pccd_robot_options *ropt, pccd_robot_batch_out *out);

/* Work counters of the last solve (for benchmarks). */
typedef struct pccd_scene_stats {
  unsigned long long pieces, leaves, candidates, solved, static_tests, refined;
  unsigned long long by_stage[5]; /* solved feature pairs by the pccd_stage that decided */
} pccd_scene_stats;
PCCD_API int pccd_report_stats(const pccd_report *rep, pccd_scene_stats *stats);

/* ------------------------------------------------------------------------------------
 * Steps of deforming meshes (a simulator's time step): every vertex moves on its own
 * straight path from its position at t = 0 to its position at t = 1 (doubles at their
 * exact values), or on a polynomial path (pccd_step_set_paths_d). A step holds one or more meshes (triangles, edges, isolated points);
 * pccd_step_solve checks every primitive pair exactly over t in [0, 1]:
 *   VERTEX_FACE    every vertex used by a face, edge or point against every face not
 *                  holding it,
 *   EDGE_EDGE      every edge against every edge with no common vertex,
 *   VERTEX_EDGE, VERTEX_VERTEX   every isolated point against every edge not ending at
 *                  it and every other point,
 * within a mesh (self-collision) and between meshes, for the mesh pairs checked
 * (pccd_step_set_pair_check; all by default). Pairs sharing a vertex are left out (they
 * touch from the start), as in every simulator's CCD. A static obstacle is a mesh with
 * v_t1 = v_t0. config.min_distance > 0 makes a contact "within delta" (pccd_config).
 * The broad phase (swept boxes in a translating frame, a bounding-volume hierarchy
 * rebuilt per step, on opt.threads threads) never changes an answer.
 * ---------------------------------------------------------------------------------- */
typedef struct pccd_step pccd_step;
typedef struct pccd_step_report pccd_step_report;

PCCD_API int pccd_step_new(pccd_step **out);
PCCD_API void pccd_step_free(pccd_step *s);

/* Appends a mesh of nv vertices: vertex i moves from v_t0[3i..3i+2] to v_t1[3i..3i+2].
 * faces: nf index triples (may be 0); edges: ne index pairs, or edges = NULL to derive
 * them from the faces (every side once; ne is then ignored); points: np isolated points (vertex indices:
 * particles, or rod ends). *index (when not NULL) receives the mesh's position.
 * PCCD_EINVAL, naming the place: s NULL, a NULL array with a nonzero count, a non-finite
 * coordinate ("v_t1[4][2]"), an index out of range ("faces[3][1]: index 12 out of range
 * (10 vertices)"), a face or edge repeating a vertex ("faces[3]: repeats vertex 5 (a
 * degenerate face)"); PCCD_ELIMIT: a count above PCCD_MAX_BODY_ELEMENTS. On error the
 * step is unchanged. */
PCCD_API int pccd_step_add_mesh_d(pccd_step *s, const double *v_t0, const double *v_t1, size_t nv,
                                  const unsigned int *faces, size_t nf, const unsigned int *edges,
                                  size_t ne, const unsigned int *points, size_t np, size_t *index);
/* pccd_step_add_mesh_d within the limits of cfg: max_seconds, max_work and cancel bound
 * the building (the checks, the edges derived and sorted: a work step per 4,096
 * elements), PCCD_ELIMIT when reached, the step unchanged. cfg NULL: no limits. A
 * caller with one budget for a whole step (polyccd.check_step) gives the same cfg here
 * and to pccd_step_solve; each call has its own clock. */
PCCD_API int pccd_step_add_mesh_cfg_d(pccd_step *s, const double *v_t0, const double *v_t1,
                                      size_t nv, const unsigned int *faces, size_t nf,
                                      const unsigned int *edges, size_t ne,
                                      const unsigned int *points, size_t np, size_t *index,
                                      const pccd_config *cfg);

/* Replaces the positions of mesh `mesh` (the next step of a simulation: same topology,
 * nv its vertex count). Errors as pccd_step_add_mesh_d, and "mesh", "nv" out of range. */
PCCD_API int pccd_step_set_positions_d(pccd_step *s, size_t mesh, const double *v_t0,
                                       const double *v_t1, size_t nv);

/* Gives mesh `mesh` polynomial paths instead of straight ones: its vertex i is at
 *   x(t) = sum_k coeffs[(k * nv + i) * 3 + axis] t^k,   k = 0 .. ncoeffs - 1
 * (an array of shape (ncoeffs, nv, 3), ascending powers of t as pccd_query_set_coord_d;
 * doubles at their exact values). Pairs with such a vertex are solved by the general
 * exact solver (as pccd_query_solve), their swept boxes from the paths' Bernstein
 * coefficients. pccd_step_set_positions_d makes the paths straight again.
 * PCCD_EINVAL, naming the place: "mesh", "nv" as pccd_step_set_positions_d, ncoeffs
 * outside 1..8 ("ncoeffs"), coeffs NULL with nv > 0, a non-finite coefficient
 * ("coeffs[2][4][1]"). On error the step is unchanged. */
PCCD_API int pccd_step_set_paths_d(pccd_step *s, size_t mesh, const double *coeffs, size_t ncoeffs,
                                   size_t nv);

/* Whether the mesh pair (i, j) is checked: check = 1 (default) or 0; i == j is mesh i's
 * self-collision. PCCD_EINVAL: i or j not a mesh ("j: 4 out of range (3 meshes)"),
 * check not 0 or 1. */
PCCD_API int pccd_step_set_pair_check(pccd_step *s, size_t i, size_t j, int check);

/* What pccd_step_solve answers. */
typedef enum pccd_step_mode {
  PCCD_STEP_FIRST = 0,  /* the exact first contact time, the pairs touching first and the
                           step size (pccd_step_report_stepsize) */
  PCCD_STEP_DECIDE = 1, /* only whether anything touches: stops at the first contacts
                           found (reported without times) */
  PCCD_STEP_ALL = 2     /* FIRST, and every touching pair with its own first time */
} pccd_step_mode;

typedef struct pccd_step_options {
  size_t struct_size; /* set by pccd_step_options_init */
  unsigned threads;   /* worker threads, 1 to 1024 (default 1); answers do not depend on it */
  int mode;           /* a pccd_step_mode (default PCCD_STEP_FIRST) */
} pccd_step_options;
PCCD_API int pccd_step_options_init(pccd_step_options *opt);

/* Solves the step into rep (cfg, opt: NULL for the defaults; cfg->want_time is ignored:
 * the mode says what is computed). PCCD_EINVAL on bad options; PCCD_ELIMIT when a work
 * limit or the input limit of cfg is reached. On error rep holds no answer. */
PCCD_API int pccd_step_solve(const pccd_step *s, const pccd_config *cfg,
                             const pccd_step_options *opt, pccd_step_report *rep);

PCCD_API int pccd_step_report_new(pccd_step_report **out);
PCCD_API void pccd_step_report_free(pccd_step_report *rep);
PCCD_API int pccd_step_report_collides(const pccd_step_report *rep, int *collides);
/* The first contact time t* (modes FIRST, ALL) as text; which: 0 = lo, 1 = hi, 2 = exact.
 * PCCD_ESTATE without contact, in mode DECIDE, or (2) when t* is not known exactly. */
PCCD_API int pccd_step_report_time(const pccd_step_report *rep, int which, char *buf, size_t cap,
                                   size_t *needed);
/* *exact = 1 when t* is known exactly; lo, hi: t*'s enclosure rounded outward to doubles.
 * Any pointer may be NULL. PCCD_ESTATE as pccd_step_report_time. */
PCCD_API int pccd_step_report_time_info(const pccd_step_report *rep, int *exact, double *lo,
                                        double *hi);
/* The largest double <= t* (modes FIRST, ALL), 1.0 when nothing touches: the step may
 * be scaled by it and every position strictly before it is contact-free (at it, the
 * first contact when t* is a double). PCCD_ESTATE in mode DECIDE. */
PCCD_API int pccd_step_report_stepsize(const pccd_step_report *rep, double *stepsize);
PCCD_API int pccd_step_report_contact_count(const pccd_step_report *rep, size_t *count);
/* Contacts first .. first + n - 1 into caller arrays (any may be NULL), sorted by (kind,
 * mesh and index of a, mesh and index of b):
 *   kind[k]          a pccd_kind: VERTEX_FACE (a vertex, b face), EDGE_EDGE (two edges),
 *                    VERTEX_EDGE (a point's vertex, b edge), VERTEX_VERTEX (two vertices);
 *   index[4k..4k+3]  mesh of a, index of a in its mesh, mesh of b, index of b (edges
 *                    numbered as pccd_step_edge gives them);
 *   lo[k], hi[k]     the pair's first contact time rounded outward (NaN in mode DECIDE);
 *   exact[k]         1 when that time is exact.
 * PCCD_EINVAL when first + n exceeds the count. */
PCCD_API int pccd_step_report_contacts(const pccd_step_report *rep, size_t first, size_t n,
                                       int *kind, size_t *index, double *lo, double *hi,
                                       unsigned char *exact);
/* Edges first .. first + n - 1 of mesh `mesh` into v[2k], v[2k + 1] (given or derived
 * edges as (a, b) with a < b, sorted, each once). PCCD_EINVAL: beyond the edge count. */
PCCD_API int pccd_step_edges(const pccd_step *s, size_t mesh, size_t first, size_t n, size_t *v);
/* Sizes of mesh `mesh`: vertices, faces, edges, isolated points (pointers may be NULL). */
PCCD_API int pccd_step_mesh_counts(const pccd_step *s, size_t mesh, size_t *nv, size_t *nf,
                                   size_t *ne, size_t *np);

typedef struct pccd_step_stats {
  unsigned long long queries;    /* broad-phase queries run (vertices, edges, points) */
  unsigned long long candidates; /* primitive pairs whose boxes met: each solved exactly */
  unsigned long long refined;    /* re-solves with a finer time tolerance */
  unsigned long long by_stage[5]; /* solved pairs by the pccd_stage that decided */
} pccd_step_stats;
PCCD_API int pccd_step_report_stats(const pccd_step_report *rep, pccd_step_stats *stats);

#ifdef __cplusplus
}
#endif

#endif /* POLYCCD_H */
