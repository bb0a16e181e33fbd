/* Timing of the mapping's hot paths through the C API (built and run by bench_mapping.py).
 *
 * Reads from stdin, one line each:
 *   beam E rho zeta neck_L neck_h neck_b platform_L platform_m platform_J airfoil_L airfoil_h
 *        airfoil_b neck_elements airfoil_elements
 *   asymmetric CF mu pitch y_P beta_L_deg beta_R_deg flat1_x flat1_y flat2_x flat2_y curved_x
 *        curved_y kn_flat kt_flat kn_curved kt_curved
 *   band f_min f_max sigma_all layers repeats
 * and prints one JSON object per line: {"name", "seconds_median", "seconds_min",
 * "seconds_max", "repeats", "evaluations"?, and the results per force}.
 *
 * Measured, each for the 10 forces F_E = 1..10 N:
 *   backbone_cached        udmap_model_backbone on a model whose backbone table is built;
 *   backbone_damper_built  udmap_model_set_damper (drops the table) + udmap_model_backbone:
 *                          the damper's stiffness table exists, the backbone table does not;
 *   backbone_cold          udmap_new_damper_asymmetric from its parameters + set_damper +
 *                          backbone + delete: the whole GG diagram from the damper parameters;
 *   mapping_cold           the same with udmap_model_curves (layers) instead of the backbone,
 *                          the peaks read off the mapped points;
 *   reference              backbone with rtol = 1e-14 and 4 times the grid (not timed).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "udmap.h"

#define NF 10

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static void fail(udmap_error err, const char *what) {
  char msg[1024];
  udmap_get_error(err, msg, sizeof msg);
  fprintf(stderr, "mapping_timing: %s failed: %s\n", what, msg);
  exit(1);
}

static void report(const char *name, double *t, int n, const udmap_point *p) {
  int i;
  qsort(t, n, sizeof *t, cmp);
  printf("{\"name\": \"%s\", \"seconds_median\": %.6e, \"seconds_min\": %.6e, "
         "\"seconds_max\": %.6e, \"repeats\": %d", name, t[n / 2], t[0], t[n - 1], n);
  if (p) {
    printf(", \"gamma_P\": [");
    for (i = 0; i < NF; i++) printf("%s%.17g", i ? ", " : "", p[i].gamma_P);
    printf("], \"f_res\": [");
    for (i = 0; i < NF; i++) printf("%s%.17g", i ? ", " : "", p[i].f_res);
    printf("], \"sigma_a\": [");
    for (i = 0; i < NF; i++) printf("%s%.17g", i ? ", " : "", p[i].sigma_a);
    printf("]");
  }
  printf("}\n");
  fflush(stdout);
}

/* the peaks of the mapped curves: the highest point of each curve that is not a turning
 * point (so only the mapping's own layers count) */
static void mapped_peaks(udmap_error err, udmap_model model, udmap_point *p) {
  int i, j, n;
  for (i = 0; i < NF; i++) {
    double *f, *g, *s;
    int *branch, *part, best = -1;
    if (udmap_model_curve_size(err, model, i, &n)) fail(err, "curve size");
    f = malloc(n * sizeof *f);
    g = malloc(n * sizeof *g);
    s = malloc(n * sizeof *s);
    branch = malloc(n * sizeof *branch);
    part = malloc(n * sizeof *part);
    if (udmap_model_curve_get(err, model, i, n, f, g, s, branch, part)) fail(err, "curve get");
    for (j = 0; j < n; j++)
      if (branch[j] != UDMAP_BRANCH_TURNING && (best < 0 || g[j] > g[best])) best = j;
    p[i].gamma_P = g[best];
    p[i].f_res = f[best];
    p[i].sigma_a = s[best];
    free(f); free(g); free(s); free(branch); free(part);
  }
}

int main(void) {
  udmap_beam_params bp;
  udmap_asymmetric_params dp;
  udmap_analysis an;
  udmap_error err = udmap_new_error();
  udmap_blade blade = NULL;
  udmap_damper damper = NULL, fresh = NULL;
  udmap_model model = NULL, ref = NULL;
  udmap_point pts[NF];
  double F[NF], *t, t0;
  double sigma_all;
  int layers, repeats, i, r;
  char tag[32];

  if (scanf("%31s %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %d %d", tag, &bp.E, &bp.rho,
            &bp.zeta, &bp.neck_L, &bp.neck_h, &bp.neck_b, &bp.platform_L, &bp.platform_m,
            &bp.platform_J, &bp.airfoil_L, &bp.airfoil_h, &bp.airfoil_b, &bp.neck_elements,
            &bp.airfoil_elements) != 15 || strcmp(tag, "beam"))
    return 2;
  if (scanf("%31s %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", tag, &dp.CF,
            &dp.mu, &dp.pitch, &dp.y_P, &dp.beta_L_deg, &dp.beta_R_deg, &dp.flat1_x,
            &dp.flat1_y, &dp.flat2_x, &dp.flat2_y, &dp.curved_x, &dp.curved_y, &dp.kn_flat,
            &dp.kt_flat, &dp.kn_curved, &dp.kt_curved) != 17 || strcmp(tag, "asymmetric"))
    return 2;
  udmap_analysis_defaults(&an);
  if (scanf("%31s %lf %lf %lf %d %d", tag, &an.f_min, &an.f_max, &sigma_all, &layers,
            &repeats) != 6 || strcmp(tag, "band"))
    return 2;
  an.sigma_all = sigma_all;
  for (i = 0; i < NF; i++) F[i] = i + 1;
  t = malloc(repeats * sizeof *t);

  if (udmap_new_blade_beam(err, &bp, &blade)) fail(err, "blade");
  if (udmap_new_damper_asymmetric(err, &dp, &damper)) fail(err, "damper");
  if (udmap_new_model(err, blade, damper, &an, &model)) fail(err, "model");
  if (udmap_model_backbone(err, model, NF, F, pts)) fail(err, "backbone");

  for (r = 0; r < repeats; r++) {
    t0 = now();
    if (udmap_model_backbone(err, model, NF, F, pts)) fail(err, "backbone");
    t[r] = now() - t0;
  }
  report("backbone_cached", t, repeats, pts);

  for (r = 0; r < repeats; r++) {
    t0 = now();
    if (udmap_model_set_damper(err, model, damper)) fail(err, "set damper");
    if (udmap_model_backbone(err, model, NF, F, pts)) fail(err, "backbone");
    t[r] = now() - t0;
  }
  report("backbone_damper_built", t, repeats, pts);

  for (r = 0; r < repeats; r++) {
    t0 = now();
    if (udmap_new_damper_asymmetric(err, &dp, &fresh)) fail(err, "damper");
    if (udmap_model_set_damper(err, model, fresh)) fail(err, "set damper");
    if (udmap_model_backbone(err, model, NF, F, pts)) fail(err, "backbone");
    if (udmap_model_set_damper(err, model, damper)) fail(err, "set damper");
    udmap_delete_damper(&fresh);
    t[r] = now() - t0;
  }
  report("backbone_cold", t, repeats, pts);

  for (r = 0; r < (repeats + 9) / 10; r++) {
    t0 = now();
    if (udmap_new_damper_asymmetric(err, &dp, &fresh)) fail(err, "damper");
    if (udmap_model_set_damper(err, model, fresh)) fail(err, "set damper");
    if (udmap_model_curves(err, model, NF, F, layers)) fail(err, "curves");
    mapped_peaks(err, model, pts);
    if (udmap_model_set_damper(err, model, damper)) fail(err, "set damper");
    udmap_delete_damper(&fresh);
    t[r] = now() - t0;
  }
  report("mapping_cold", t, (repeats + 9) / 10, pts);

  an.rtol = 1e-14;
  an.grid_per_decade *= 4;
  if (udmap_new_model(err, blade, damper, &an, &ref)) fail(err, "reference model");
  if (udmap_model_backbone(err, ref, NF, F, pts)) fail(err, "reference backbone");
  t[0] = 0;
  report("reference", t, 1, pts);

  udmap_delete_model(&ref);
  udmap_delete_model(&model);
  udmap_delete_damper(&damper);
  udmap_delete_blade(&blade);
  udmap_delete_error(&err);
  free(t);
  return 0;
}
