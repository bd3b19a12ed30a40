/*
 * test_index_errors.c -- every error path of the on-line index of the C API
 * (pccd_index_new, pccd_index_query): the status, the message naming the place, *out
 * NULL after a failed pccd_index_new, no answer readable after a failed query, and the
 * index still answering afterwards (its known answers: test_index.c).
 *
 * Plain C99 (built with -std=c99 -Wall -Wextra -Werror). Prints every failed check,
 * then "N passed, N failed"; exit status 0 only when nothing failed. Every handle is
 * freed (valgrind-clean).
 */
#include "polyccd.h"

#include <stdio.h>
#include <string.h>

#include "check.h"
#include "scene_fixtures.h"

/* Every error path of pccd_index_new and pccd_index_query. */
static void errors(void)
{
  pccd_body *cube = NULL;
  pccd_motion *bad = vanishing(), *m = slide_x(3, 0);
  pccd_index *ix = NULL, *sentinel = NULL;
  pccd_report *rep = NULL;
  pccd_scene_options opt;
  pccd_config cfg;
  int v = 0;
  if (!CHECK(bad != NULL && m != NULL)) return;
  OK(pccd_body_new_mesh_d(&cube, kCubeV, 8, kCubeT, 12));
  OK(pccd_report_new(&rep));

  /* pccd_index_new: *out is NULL after every error. */
  FAILS(pccd_index_new(NULL, cube, NULL), PCCD_EINVAL, "pccd_index_new: out: is NULL");
  sentinel = (pccd_index *)&v; /* any non-NULL value */
  ix = sentinel;
  FAILS(pccd_index_new(&ix, NULL, NULL), PCCD_EINVAL, "body: is NULL");
  CHECK(ix == NULL);
  CHECK(strstr(pccd_last_error(), "pccd_index_new") != NULL);
  ix = sentinel;
  FAILS(pccd_index_new(&ix, cube, bad), PCCD_EINVAL, "motion: ");
  CHECK(strstr(pccd_last_error(), "vanishes at t = 1/2") != NULL);
  CHECK(ix == NULL);

  /* pccd_index_query. */
  OK(pccd_index_new(&ix, cube, NULL));
  FAILS(pccd_index_query(NULL, cube, m, NULL, NULL, rep), PCCD_EINVAL, "pccd_index_query: ix: is NULL");
  FAILS(pccd_index_query(ix, NULL, m, NULL, NULL, rep), PCCD_EINVAL, "body: is NULL");
  FAILS(pccd_index_query(ix, cube, m, NULL, NULL, NULL), PCCD_EINVAL, "rep: is NULL");
  FAILS(pccd_index_query(ix, cube, bad, NULL, NULL, rep), PCCD_EINVAL, "motion: ");
  CHECK(strstr(pccd_last_error(), "pccd_index_query") != NULL &&
        strstr(pccd_last_error(), "vanishes at t = 1/2") != NULL);
  FAILS(pccd_report_collides(rep, &v), PCCD_ESTATE, "rep: holds no answer");
  OK(pccd_scene_options_init(&opt));
  opt.struct_size = 3;
  FAILS(pccd_index_query(ix, cube, m, NULL, &opt, rep), PCCD_EINVAL, "opt.struct_size: 3 is not");
  OK(pccd_scene_options_init(&opt));
  opt.threads = 0;
  FAILS(pccd_index_query(ix, cube, m, NULL, &opt, rep), PCCD_EINVAL, "opt.threads: 0 is outside");
  opt.threads = 1025;
  FAILS(pccd_index_query(ix, cube, m, NULL, &opt, rep), PCCD_EINVAL, "opt.threads: 1025 is outside");
  OK(pccd_scene_options_init(&opt));
  opt.all_contacts = 2;
  FAILS(pccd_index_query(ix, cube, m, NULL, &opt, rep), PCCD_EINVAL, "opt.all_contacts: 2 is not 0 or 1");
  OK(pccd_scene_options_init(&opt));
  opt.broad_phase = 5;
  FAILS(pccd_index_query(ix, cube, m, NULL, &opt, rep), PCCD_EINVAL, "opt.broad_phase: 5 is not");
  CHECK(strstr(pccd_last_error(), "PCCD_BROAD_BVH (4)") != NULL);
  opt.broad_phase = -1;
  FAILS(pccd_index_query(ix, cube, m, NULL, &opt, rep), PCCD_EINVAL, "opt.broad_phase: -1 is not");
  OK(pccd_config_init(&cfg));
  cfg.time_tolerance = "0";
  FAILS(pccd_index_query(ix, cube, m, &cfg, NULL, rep), PCCD_EINVAL, "pccd_index_query: config.time_tolerance: ");
  FAILS(pccd_report_collides(rep, &v), PCCD_ESTATE, "rep: holds no answer");
  /* A failed call leaves no earlier answer readable: solve, then fail on bad options. */
  OK(pccd_index_query(ix, cube, m, NULL, NULL, rep));
  OK(pccd_report_collides(rep, &v));
  OK(pccd_scene_options_init(&opt));
  opt.threads = 0;
  FAILS(pccd_index_query(ix, cube, m, NULL, &opt, rep), PCCD_EINVAL, "opt.threads: 0 is outside");
  FAILS(pccd_report_collides(rep, &v), PCCD_ESTATE, "rep: holds no answer");
  /* The defaults of pccd_scene_options_init: PCCD_BROAD_AUTO, 1 thread, first contacts. */
  OK(pccd_scene_options_init(&opt));
  CHECK(opt.broad_phase == PCCD_BROAD_AUTO && opt.threads == 1 && opt.all_contacts == 0 &&
        opt.struct_size == sizeof(pccd_scene_options));
  /* After the errors the index still answers. */
  OK(pccd_config_init(&cfg));
  OK(pccd_index_query(ix, cube, m, &cfg, &opt, rep));
  CHECK(time_is(rep, PCCD_WHOLE, PCCD_WHOLE, 2, "2/3"));

  pccd_index_free(ix);
  pccd_report_free(rep);
  pccd_body_free(cube);
  pccd_motion_free(bad);
  pccd_motion_free(m);
}

int main(void)
{
  errors();
  printf("%d passed, %d failed\n", g_pass, g_fail);
  return g_fail == 0 ? 0 : 1;
}
