#include <stdio.h>
#include "polyccd.h"

int main(void) {
  double t0[12] = {0.25, 0.25, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};   /* v, f0, f1, f2 */
  double t1[12] = {0.25, 0.25, -1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  pccd_result *res = NULL;
  char t[64];
  int collides = 0;
  if (pccd_result_new(&res) != PCCD_OK ||
      pccd_solve_linear_d(PCCD_VERTEX_FACE, t0, t1, NULL, res) != PCCD_OK) {
    fprintf(stderr, "%s\n", pccd_last_error());
    return 1;
  }
  pccd_result_collides(res, &collides);
  if (collides && pccd_result_time(res, 1, t, sizeof t, NULL) == PCCD_OK)
    printf("first contact at t = %s\n", t);                     /* 1/2 */
  pccd_result_free(res);
  return 0;
}
