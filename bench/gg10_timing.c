/* Run time and results of the GG diagram workload gg10 (the 10 peaks F_E = 1..10 N) by every
 * method, through the C API (built and run by bench_gg10.py; no Python in the timed loops).
 *
 * Reads from stdin, one line each:
 *   beam E rho zeta neck_L neck_h neck_b platform_L platform_m platform_J airfoil_L airfoil_h
 *        airfoil_b neck_elements airfoil_elements
 *     or
 *   matrices M_path K_path gamma_dof exc_dof stress_K_path stress_M_path zeta
 *   asymmetric CF mu pitch y_P beta_L_deg beta_R_deg flat1_x flat1_y flat2_x flat2_y curved_x
 *        curved_y kn_flat kt_flat kn_curved kt_curved
 *   band f_min f_max sigma_all
 * then any number of jobs, one per line, each starting with its kind and a label:
 *   build    LABEL repeats                   the blade from its parameters or files (modes)
 *   setup    LABEL repeats                   udmap_new_model + the first backbone (gg10): the
 *                                            bare-blade data of the band, once per blade
 *   backbone LABEL repeats rtol grid_per_decade
 *   mapping  LABEL repeats layers sweep_points
 *   standard LABEL repeats variant tol tol_path peak_tol ds_max max_angle aft_samples
 *            warm_start full_band
 *   harmonics LABEL repeats H                 the backbone at H harmonics (0: auto), default
 *                                            tolerances
 *   harmonics_jenkins LABEL repeats H         the same with a Jenkins damper (kt = the
 *                                            asymmetric damper's stuck stiffness, M_slip half
 *                                            its plateau moments' span)
 * and prints one JSON object per job: {"name", "kind", "samples": [...], "seconds_median",
 * "seconds_min", "seconds_max", "repeats", "gamma_P": [...], "f_res": [...], "sigma_a": [...]}
 * (standard:
 * also "iterations", "aft_calls", "steps", summed over the forces).
 *
 * What is timed, for the 10 forces, from the damper parameters on (the blade and its
 * bare-blade data exist; they do not depend on the damper):
 *   backbone  udmap_new_damper_asymmetric (tracing, stiffness table) + set_damper + backbone;
 *   harmonics the same at H harmonics, cold: each repeat's damper has CF changed by a relative
 *             1e-12 r, so the model rebuilds what depends on the damper (with equal parameters
 *             it would keep the multi-harmonic roots of the last repeat as warm starts);
 *             harmonics_jenkins: udmap_new_damper_jenkins, M_slip changed so;
 *   mapping   the same with udmap_model_curves (`layers`) and the peaks read off the mapped
 *             points (the highest point of a curve that is not a turning point);
 *   standard  udmap_new_contact_asymmetric + udmap_hbm_peaks (harmonic balance with H = 1,
 *             event-driven or sampled AFT on the contact model, continuation in frequency).
 * A job with repeats = 0 runs once untimed (a reference). A standard job whose continuation
 * fails prints {"name", "kind", "failed": message} instead.
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
  fprintf(stderr, "gg10_timing: %s failed: %s\n", what, msg);
  exit(1);
}

static void print_array(const char *name, const double *v) {
  int i;
  printf(", \"%s\": [", name);
  for (i = 0; i < NF; i++) printf("%s%.17g", i ? ", " : "", v[i]);
  printf("]");
}

/* timing statistics and results of one job */
/* the samples (in the order taken) and their statistics */
static void print_times(const char *kind, const char *name, double *t, int n) {
  int i;
  printf("{\"name\": \"%s\", \"kind\": \"%s\", \"samples\": [", name, kind);
  for (i = 0; i < n; i++) printf("%s%.6e", i ? ", " : "", t[i]);
  printf("]");
  qsort(t, n, sizeof *t, cmp);
  printf(", \"seconds_median\": %.6e, \"seconds_min\": %.6e, \"seconds_max\": %.6e, "
         "\"repeats\": %d", n ? t[n / 2] : 0.0, n ? t[0] : 0.0, n ? t[n - 1] : 0.0, n);
}

static void report(const char *kind, const char *name, double *t, int n, const double *g,
                   const double *f, const double *s) {
  print_times(kind, name, t, n);
  print_array("gamma_P", g);
  print_array("f_res", f);
  print_array("sigma_a", s);
}

/* the peaks of the mapped curves: the highest point of each curve that is not a turning
 * point (so only the mapping's own layers count, not the backbone roots it includes) */
static void mapped_peaks(udmap_error err, udmap_model model, double *g, double *f, double *s) {
  int i, j, n;
  for (i = 0; i < NF; i++) {
    double *cf, *cg, *cs;
    int *branch, *part, best = -1;
    if (udmap_model_curve_size(err, model, i, &n)) fail(err, "curve size");
    cf = malloc(n * sizeof *cf);
    cg = malloc(n * sizeof *cg);
    cs = malloc(n * sizeof *cs);
    branch = malloc(n * sizeof *branch);
    part = malloc(n * sizeof *part);
    if (udmap_model_curve_get(err, model, i, n, cf, cg, cs, branch, part)) fail(err, "curve get");
    for (j = 0; j < n; j++)
      if (branch[j] != UDMAP_BRANCH_TURNING && (best < 0 || cg[j] > cg[best])) best = j;
    g[i] = cg[best];
    f[i] = cf[best];
    s[i] = cs[best];
    free(cf); free(cg); free(cs); free(branch); free(part);
  }
}

static int new_blade(udmap_error err, int is_beam, const udmap_beam_params *bp,
                     const char *M_path, const char *K_path, int gamma_dof, int exc_dof,
                     const char *sK_path, const char *sM_path, double zeta, udmap_blade *blade) {
  if (is_beam) return udmap_new_blade_beam(err, bp, blade);
  return udmap_new_blade_matrices(err, M_path, K_path, NULL, gamma_dof, exc_dof, sK_path,
                                  sM_path, zeta, blade);
}

int main(void) {
  udmap_beam_params bp;
  udmap_asymmetric_params dp;
  char M_path[1024] = "", K_path[1024] = "", sK_path[1024] = "", sM_path[1024] = "";
  int gamma_dof = 0, exc_dof = 0, is_beam;
  double zeta = 0;
  udmap_analysis an0;
  udmap_error err = udmap_new_error();
  udmap_blade blade = NULL;
  udmap_damper damper = NULL, jenkins = NULL;
  udmap_damper_info info;
  double kt, M_slip;
  double F[NF], g[NF], f[NF], s[NF], *t = NULL;
  double f_min, f_max, sigma_all;
  int i, r;
  char tag[32], label[256];

  if (scanf("%31s", tag) != 1) return 2;
  is_beam = !strcmp(tag, "beam");
  if (is_beam) {
    if (scanf("%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %d %d", &bp.E, &bp.rho,
              &bp.zeta, &bp.neck_L, &bp.neck_h, &bp.neck_b, &bp.platform_L, &bp.platform_m,
              &bp.platform_J, &bp.airfoil_L, &bp.airfoil_h, &bp.airfoil_b, &bp.neck_elements,
              &bp.airfoil_elements) != 14)
      return 2;
  } else if (strcmp(tag, "matrices") || scanf("%1023s %1023s %d %d %1023s %1023s %lf", M_path,
                                              K_path, &gamma_dof, &exc_dof, sK_path, sM_path,
                                              &zeta) != 7) {
    return 2;
  }
  if (scanf("%31s %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", tag, &dp.CF,
            &dp.mu, &dp.pitch, &dp.y_P, &dp.beta_L_deg, &dp.beta_R_deg, &dp.flat1_x,
            &dp.flat1_y, &dp.flat2_x, &dp.flat2_y, &dp.curved_x, &dp.curved_y, &dp.kn_flat,
            &dp.kt_flat, &dp.kn_curved, &dp.kt_curved) != 17 || strcmp(tag, "asymmetric"))
    return 2;
  if (scanf("%31s %lf %lf %lf", tag, &f_min, &f_max, &sigma_all) != 4 || strcmp(tag, "band"))
    return 2;
  udmap_analysis_defaults(&an0);
  an0.f_min = f_min;
  an0.f_max = f_max;
  an0.sigma_all = sigma_all;
  for (i = 0; i < NF; i++) F[i] = i + 1;

  if (new_blade(err, is_beam, &bp, M_path, K_path, gamma_dof, exc_dof, sK_path, sM_path, zeta,
                &blade))
    fail(err, "blade");
  if (udmap_new_damper_asymmetric(err, &dp, &damper)) fail(err, "damper");
  if (udmap_damper_get_info(err, damper, &info)) fail(err, "damper info");
  kt = info.k_stuck;
  M_slip = 0.5 * (info.M_max - info.M_min);
  if (udmap_new_damper_jenkins(err, kt, M_slip, &jenkins)) fail(err, "jenkins damper");

  while (scanf("%31s %255s", tag, label) == 2) {
    int repeats, n;
    if (scanf("%d", &repeats) != 1 || repeats < 0) return 2;
    n = repeats ? repeats : 1;
    t = realloc(t, n * sizeof *t);
    if (!strcmp(tag, "build")) {
      for (r = 0; r < n; r++) {
        udmap_blade fresh = NULL;
        double t0 = now();
        if (new_blade(err, is_beam, &bp, M_path, K_path, gamma_dof, exc_dof, sK_path, sM_path,
                      zeta, &fresh))
          fail(err, "blade");
        udmap_delete_blade(&fresh);
        t[r] = now() - t0;
      }
      print_times(tag, label, t, n);
      printf("}\n");
    } else if (!strcmp(tag, "setup")) {
      udmap_point pts[NF];
      for (r = 0; r < n; r++) {
        udmap_model model = NULL;
        double t0 = now();
        if (udmap_new_model(err, blade, damper, &an0, &model)) fail(err, "model");
        if (udmap_model_backbone(err, model, NF, F, pts)) fail(err, "backbone");
        t[r] = now() - t0;
        udmap_delete_model(&model);
      }
      for (i = 0; i < NF; i++) {
        g[i] = pts[i].gamma_P;
        f[i] = pts[i].f_res;
        s[i] = pts[i].sigma_a;
      }
      report(tag, label, t, n, g, f, s);
      printf("}\n");
    } else if (!strcmp(tag, "backbone") || !strcmp(tag, "mapping") ||
               !strcmp(tag, "harmonics") || !strcmp(tag, "harmonics_jenkins")) {
      udmap_analysis an = an0;
      udmap_model model = NULL;
      udmap_damper fresh = NULL;
      udmap_asymmetric_params dr = dp;
      udmap_point pts[NF];
      int layers = 0, mapping = !strcmp(tag, "mapping"), jen = !strcmp(tag, "harmonics_jenkins");
      int cold = jen || !strcmp(tag, "harmonics");
      udmap_damper base = jen ? jenkins : damper;
      if (mapping) {
        if (scanf("%d %d", &layers, &an.sweep_points) != 2) return 2;
      } else if (cold) {
        if (scanf("%d", &an.harmonics) != 1) return 2;
      } else {
        if (scanf("%lf %d", &an.rtol, &an.grid_per_decade) != 2) return 2;
      }
      if (udmap_new_model(err, blade, base, &an, &model)) fail(err, "model");
      /* the bare-blade data (band sweep, eigen start) exist before the clock starts (a first
       * call with the same arguments, as bench_mapping.py does: the first call of the mapping
       * with many layers also pays for growing its storage) */
      if (mapping) {
        if (udmap_model_curves(err, model, NF, F, layers)) fail(err, "curves");
      } else if (udmap_model_backbone(err, model, NF, F, pts)) {
        fail(err, "backbone");
      }
      for (r = 0; r < n; r++) {
        double t0;
        if (cold) dr.CF = dp.CF * (1 + 1e-12 * (r + 1));
        t0 = now();
        if (jen) {
          if (udmap_new_damper_jenkins(err, kt, M_slip * (1 + 1e-12 * (r + 1)), &fresh))
            fail(err, "damper");
        } else if (udmap_new_damper_asymmetric(err, &dr, &fresh)) {
          fail(err, "damper");
        }
        if (udmap_model_set_damper(err, model, fresh)) fail(err, "set damper");
        if (mapping) {
          if (udmap_model_curves(err, model, NF, F, layers)) fail(err, "curves");
          mapped_peaks(err, model, g, f, s);
        } else {
          if (udmap_model_backbone(err, model, NF, F, pts)) fail(err, "backbone");
          for (i = 0; i < NF; i++) {
            g[i] = pts[i].gamma_P;
            f[i] = pts[i].f_res;
            s[i] = pts[i].sigma_a;
          }
        }
        if (udmap_model_set_damper(err, model, base)) fail(err, "set damper");
        udmap_delete_damper(&fresh);
        t[r] = now() - t0;
      }
      report(tag, label, t, repeats, g, f, s);
      printf("}\n");
      udmap_delete_model(&model);
    } else if (!strcmp(tag, "standard")) {
      udmap_hbm_settings hs;
      udmap_hbm_point pts[NF];
      udmap_contact contact = NULL;
      int it = 0, aft = 0, steps = 0;
      udmap_hbm_defaults(&hs);
      if (scanf("%d %lf %lf %lf %lf %lf %d %d %d", &hs.variant, &hs.tol, &hs.tol_path,
                &hs.peak_tol, &hs.ds_max, &hs.max_angle, &hs.aft_samples, &hs.warm_start,
                &hs.full_band) != 9)
        return 2;
      if (hs.ds_initial > hs.ds_max) hs.ds_initial = hs.ds_max;
      for (r = 0; r < n; r++) {
        double t0 = now();
        if (udmap_new_contact_asymmetric(err, &dp, &contact)) fail(err, "contact");
        if (udmap_hbm_peaks(err, blade, contact, f_min, f_max, &hs, NF, F, pts)) break;
        udmap_delete_contact(&contact);
        t[r] = now() - t0;
      }
      if (r < n) {
        /* a setting on which the method fails is reported, not timed */
        char msg[1024], *c;
        udmap_get_error(err, msg, sizeof msg);
        for (c = msg; *c; c++)
          if (*c == '"' || *c == '\\') *c = '\'';
        udmap_delete_contact(&contact);
        printf("{\"name\": \"%s\", \"kind\": \"%s\", \"failed\": \"%s\"}\n", label, tag, msg);
        fflush(stdout);
        continue;
      }
      for (i = 0; i < NF; i++) {
        g[i] = pts[i].gamma_P;
        f[i] = pts[i].f_res;
        s[i] = pts[i].sigma_a;
        it += pts[i].iterations;
        aft += pts[i].aft_calls;
        steps += pts[i].steps;
      }
      report(tag, label, t, repeats, g, f, s);
      printf(", \"iterations\": %d, \"aft_calls\": %d, \"steps\": %d}\n", it, aft, steps);
    } else {
      fprintf(stderr, "gg10_timing: unknown job kind '%s'\n", tag);
      return 2;
    }
    fflush(stdout);
  }

  udmap_delete_damper(&damper);
  udmap_delete_damper(&jenkins);
  udmap_delete_blade(&blade);
  udmap_delete_error(&err);
  free(t);
  return 0;
}
