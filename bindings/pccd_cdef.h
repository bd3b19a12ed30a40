/* cffi declarations of include/polyccd.h: the part of the C API the bindings use.
 * No preprocessor here. build_ffi.py compiles the generated module against the real
 * header with -Werror, so a function, struct field or constant that drifted from
 * include/polyccd.h fails the build. Enum and #define values are `...`: cffi takes
 * them from the compiler, never from this file. Keep in sync with the header. */

typedef enum pccd_status {
  PCCD_OK = ...,
  PCCD_EINVAL = ...,
  PCCD_ENOMEM = ...,
  PCCD_ELIMIT = ...,
  PCCD_ERANGE = ...,
  PCCD_ESTATE = ...,
  PCCD_EINTERNAL = ...
} pccd_status;

typedef enum pccd_kind {
  PCCD_VERTEX_FACE = ...,
  PCCD_EDGE_EDGE = ...,
  PCCD_VERTEX_EDGE = ...,
  PCCD_VERTEX_VERTEX = ...,
  PCCD_SPHERE_SPHERE = ...
} pccd_kind;

typedef enum pccd_stage {
  PCCD_STAGE_NONE = ...,
  PCCD_STAGE_BOUNDS = ...,
  PCCD_STAGE_BERNSTEIN = ...,
  PCCD_STAGE_INTERVAL = ...,
  PCCD_STAGE_EXACT = ...
} pccd_stage;

#define PCCD_MAX_TRAJ_DEGREE ...
#define PCCD_MAX_NUMBER_CHARS ...
#define PCCD_MAX_EXPONENT ...

static char *const PCCD_VERSION_STRING;

const char *pccd_version(void);
const char *pccd_last_error(void);
int pccd_kind_points(pccd_kind kind, size_t *count);

typedef struct pccd_config {
  size_t struct_size;
  const char *time_tolerance;
  int want_time;
  int want_exact;
} pccd_config;

int pccd_config_init(pccd_config *cfg);

typedef struct pccd_query pccd_query;
int pccd_query_new(pccd_query **out, pccd_kind kind);
void pccd_query_free(pccd_query *q);
int pccd_query_set_coord_d(pccd_query *q, size_t point, size_t axis,
                           const double *coeffs, size_t n);
int pccd_query_set_coord_s(pccd_query *q, size_t point, size_t axis,
                           const char *const *coeffs, size_t n);
int pccd_query_set_linear_d(pccd_query *q, const double *p_t0, const double *p_t1);
int pccd_query_set_radius_d(pccd_query *q, size_t which, double r);
int pccd_query_set_radius_s(pccd_query *q, size_t which, const char *r);

typedef struct pccd_result pccd_result;
int pccd_result_new(pccd_result **out);
void pccd_result_free(pccd_result *r);

int pccd_query_solve(const pccd_query *q, const pccd_config *cfg, pccd_result *res);
int pccd_solve_linear_d(pccd_kind kind, const double *p_t0, const double *p_t1,
                        const pccd_config *cfg, pccd_result *res);

typedef struct pccd_batch_options {
  size_t struct_size;
  unsigned threads;
} pccd_batch_options;
int pccd_batch_options_init(pccd_batch_options *opt);
typedef struct pccd_batch_out {
  size_t struct_size;
  unsigned char *collides;
  int *stage;
  double *lo, *hi;
  unsigned char *exact;
} pccd_batch_out;
int pccd_solve_linear_batch_d(pccd_kind kind, size_t n, const double *t0,
                              const double *t1, const pccd_config *cfg,
                              const pccd_batch_options *opt, pccd_batch_out *out);

int pccd_result_collides(const pccd_result *res, int *collides);
int pccd_result_stage(const pccd_result *res, int *stage);
int pccd_result_time(const pccd_result *res, int which, char *buf, size_t cap,
                     size_t *needed);
int pccd_result_time_is_exact(const pccd_result *res, int *exact);
int pccd_result_time_approx(const pccd_result *res, double *t);
int pccd_result_feature_count(const pccd_result *res, size_t *count);
int pccd_result_feature(const pccd_result *res, size_t i, int *kind, size_t points[4]);

/* ---- Rigid motions ---- */
typedef struct pccd_motion pccd_motion;
typedef enum pccd_pose_side {
  PCCD_POSE_BODY = ...,
  PCCD_POSE_WORLD = ...
} pccd_pose_side;
int pccd_motion_new(pccd_motion **out);
void pccd_motion_free(pccd_motion *m);
int pccd_motion_copy(pccd_motion **out, const pccd_motion *m);
int pccd_motion_set_translation_d(pccd_motion *m, size_t axis, const double *coeffs, size_t n);
int pccd_motion_set_translation_s(pccd_motion *m, size_t axis, const char *const *coeffs,
                                  size_t n);
int pccd_motion_set_rotation_d(pccd_motion *m, size_t component, const double *coeffs,
                               size_t n);
int pccd_motion_set_rotation_s(pccd_motion *m, size_t component, const char *const *coeffs,
                               size_t n);
int pccd_motion_set_linear_translation_d(pccd_motion *m, const double p0[3],
                                         const double p1[3]);
int pccd_motion_set_linear_translation_s(pccd_motion *m, const char *const p0[3],
                                         const char *const p1[3]);
int pccd_motion_set_bezier_translation_d(pccd_motion *m, const double ctrl[12]);
int pccd_motion_set_bezier_translation_s(pccd_motion *m, const char *const ctrl[12]);
int pccd_motion_set_hermite_translation_d(pccd_motion *m, const double p0[3],
                                          const double v0[3], const double p1[3],
                                          const double v1[3]);
int pccd_motion_set_hermite_translation_s(pccd_motion *m, const char *const p0[3],
                                          const char *const v0[3], const char *const p1[3],
                                          const char *const v1[3]);
int pccd_motion_set_axis_rotation_s(pccd_motion *m, const char *const axis[3],
                                    const char *const center[3], const char *tau0,
                                    const char *tau1);
int pccd_motion_set_screw_s(pccd_motion *m, const char *const axis[3],
                            const char *const center[3], const char *tau0, const char *tau1,
                            const char *advance);
int pccd_motion_compose_pose_s(pccd_motion *m, int side, const char *const quat[4],
                               const char *const offset[3]);
int pccd_motion_validate(const pccd_motion *m);
int pccd_motion_position_s(const pccd_motion *m, const char *const p[3], const char *t,
                           char *buf, size_t cap, size_t *needed);

/* ---- Bodies ---- */
typedef struct pccd_body pccd_body;
typedef enum pccd_body_type {
  PCCD_BODY_MESH = ...,
  PCCD_BODY_SPHERES = ...
} pccd_body_type;
#define PCCD_MAX_BODY_ELEMENTS ...
int pccd_body_new_mesh_d(pccd_body **out, const double *vertices, size_t nv,
                         const unsigned int *triangles, size_t nt);
int pccd_body_new_mesh_s(pccd_body **out, const char *const *vertices, size_t nv,
                         const unsigned int *triangles, size_t nt);
int pccd_body_new_spheres_d(pccd_body **out, const double *centers, const double *radii,
                            size_t n);
int pccd_body_new_spheres_s(pccd_body **out, const char *const *centers,
                            const char *const *radii, size_t n);
void pccd_body_free(pccd_body *b);
int pccd_body_kind(const pccd_body *b, int *kind);
int pccd_body_counts(const pccd_body *b, size_t *vertices_or_spheres, size_t *edges,
                     size_t *triangles);
int pccd_body_edge(const pccd_body *b, size_t i, size_t v[2]);
int pccd_body_edge_triangles(const pccd_body *b, size_t i, size_t *tris, size_t cap,
                             size_t *count);

/* Scenes */
typedef enum pccd_feature {
  PCCD_FEATURE_VERTEX = ...,
  PCCD_FEATURE_EDGE = ...,
  PCCD_FEATURE_TRIANGLE = ...,
  PCCD_FEATURE_SPHERE = ...
} pccd_feature;

typedef enum pccd_broad_phase {
  PCCD_BROAD_BOXES = ...,
  PCCD_BROAD_BRUTE = ...,
  PCCD_BROAD_RANGE = ...,
  PCCD_BROAD_AUTO = ...
} pccd_broad_phase;

typedef struct pccd_scene pccd_scene;
typedef struct pccd_report pccd_report;

int pccd_scene_new(pccd_scene **out);
void pccd_scene_free(pccd_scene *s);
int pccd_scene_add(pccd_scene *s, const pccd_body *body, const pccd_motion *motion, size_t *index);
int pccd_scene_body_count(const pccd_scene *s, size_t *count);

typedef struct pccd_scene_options {
  size_t struct_size;
  unsigned threads;
  int all_contacts;
  int broad_phase;
} pccd_scene_options;

int pccd_scene_options_init(pccd_scene_options *opt);
int pccd_scene_solve(const pccd_scene *s, const pccd_config *cfg, const pccd_scene_options *opt,
                     pccd_report *rep);
int pccd_report_new(pccd_report **out);
void pccd_report_free(pccd_report *rep);
int pccd_report_collides(const pccd_report *rep, int *collides);
#define PCCD_WHOLE ...
int pccd_report_time(const pccd_report *rep, size_t pair, size_t contact, int which, char *buf,
                     size_t cap, size_t *needed);
int pccd_report_time_info(const pccd_report *rep, size_t pair, size_t contact, int *exact,
                          double *approx);
int pccd_report_pair_count(const pccd_report *rep, size_t *count);
int pccd_report_pair(const pccd_report *rep, size_t pair, size_t *body_i, size_t *body_j,
                     int *is_first);
int pccd_report_contact_count(const pccd_report *rep, size_t pair, size_t *count);
int pccd_report_contact(const pccd_report *rep, size_t pair, size_t contact, int *feature_i,
                        size_t *index_i, int *feature_j, size_t *index_j);

/* On-line index */
typedef struct pccd_index pccd_index;
int pccd_index_new(pccd_index **out, const pccd_body *body, const pccd_motion *motion);
void pccd_index_free(pccd_index *ix);
int pccd_index_query(const pccd_index *ix, const pccd_body *body, const pccd_motion *motion,
                     const pccd_config *cfg, const pccd_scene_options *opt, pccd_report *rep);
int pccd_index_query_many(const pccd_index *ix, const pccd_body *const *bodies,
                          const pccd_motion *const *motions, size_t n, const pccd_config *cfg,
                          const pccd_scene_options *opt, pccd_report *const *reports);

typedef struct pccd_scene_stats {
  unsigned long long pieces, leaves, candidates, solved, static_tests, refined;
  unsigned long long by_stage[5];
} pccd_scene_stats;
int pccd_report_stats(const pccd_report *rep, pccd_scene_stats *stats);
