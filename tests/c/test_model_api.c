/* The mapping section of the C API (wrappers/c/udmap.h): the one-DOF Jenkins oscillator of
 * PHYSICS.md 8 built from Matrix Market files, its published peaks, the response at a
 * frequency and the mapped curves checked against the scalar equation
 * a |1 + k(a) H| = F |H| evaluated here in C complex arithmetic, udmap_model_classify
 * against blade A's backbone points, and the statuses of bad calls. */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "udmap.h"

static const double KT = 0.25, SLIP = 0.2, CV = 0.01;

static double complex jenkins(double a) {
  double a_s = SLIP / KT, beta;
  if (a <= a_s) return KT;
  beta = acos(1 - 2 * a_s / a);
  return KT / M_PI * (beta - sin(2 * beta) / 2) + I * 4 * SLIP / (M_PI * a) * (1 - a_s / a);
}

/* relative residual of a |1 + k(a) H| = F |H| at omega [rad/s] */
static double residual(double a, double omega, double F) {
  double complex H = 1 / (1 - omega * omega + I * CV * omega);
  return (a * cabs(1 + jenkins(a) * H) - F * cabs(H)) / (F * cabs(H));
}

static void write_mtx(const char *dir, const char *name, double value) {
  char path[512];
  FILE *f;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  f = fopen(path, "w");
  fprintf(f, "%%%%MatrixMarket matrix coordinate real symmetric\n1 1 1\n1 1 %.17g\n", value);
  fclose(f);
}

int main(void) {
  static const double published[3][3] = {
      {0.05, 0.946956, 1.106824}, {0.1, 1.214018, 1.083677}, {0.3, 7.279801, 1.007341}};
  char dir[] = "/tmp/udmap_model_api_XXXXXX", pM[600], pK[600], pC[600];
  udmap_error err = udmap_new_error();
  udmap_blade blade = NULL;
  udmap_damper damper = NULL;
  udmap_model model = NULL, none = NULL;
  udmap_analysis analysis;
  udmap_point points[3];
  double forces[3], F_lim = 0, gam[2] = {1e-3, 1e3}, F_bb[2], f_res[2], worst = 0;
  int status, i, j, n = 0;

  if (!mkdtemp(dir)) return 1;
  write_mtx(dir, "M.mtx", 1.0);
  write_mtx(dir, "K.mtx", 1.0);
  write_mtx(dir, "C.mtx", CV);
  snprintf(pM, sizeof pM, "%s/M.mtx", dir);
  snprintf(pK, sizeof pK, "%s/K.mtx", dir);
  snprintf(pC, sizeof pC, "%s/C.mtx", dir);
  status = udmap_new_blade_matrices(err, pM, pK, pC, 1, 1, NULL, NULL, 0.0, &blade);
  check(status == UDMAP_OK, "matrices blade");
  status = udmap_new_damper_jenkins(err, KT, SLIP, &damper);
  check(status == UDMAP_OK, "jenkins damper");

  udmap_analysis_defaults(&analysis);
  check(analysis.grid_per_decade == 24 && analysis.rtol == 1e-12 && analysis.sigma_all == 80e6,
        "analysis defaults");
  status = udmap_new_model(err, blade, damper, &analysis, &model);
  check(status == UDMAP_EINPUT && model == NULL, "band unset is an input error");
  analysis.f_min = 0.8 / (2 * M_PI);
  analysis.f_max = 1.4 / (2 * M_PI);
  status = udmap_new_model(err, blade, damper, &analysis, &model);
  check(status == UDMAP_OK && model != NULL, "model");

  status = udmap_model_limit_force(err, model, &F_lim);
  check_close(F_lim, 4 * SLIP / M_PI, 1e-14, "F_lim");

  for (i = 0; i < 3; i++) forces[i] = published[i][0];
  status = udmap_model_backbone(err, model, 3, forces, points);
  check(status == UDMAP_OK, "backbone");
  for (i = 0; i < 3; i++) {
    check_close(points[i].gamma_P, published[i][1], 1e-6, "peak amplitude");
    check_close(2 * M_PI * points[i].f_res, published[i][2], 1e-6, "peak omega");
    check(points[i].nroots == 1 && points[i].roots[0] == points[i].gamma_P, "one root");
    check(!points[i].unbounded, "bounded (explicit damping)");
  }
  check(points[0].regime == 2 && points[2].regime == 3 && !points[2].hcf_ok, "regimes");

  status = udmap_model_backbone_curve(err, model, 2, gam, F_bb, f_res);
  check(status == UDMAP_OK, "backbone curve");
  check_close(2 * M_PI * f_res[0], sqrt(1.25), 1e-4, "stuck backbone frequency");
  check_close(2 * M_PI * f_res[1], 1.0, 1e-4, "free backbone frequency");

  status = udmap_model_response(err, model, 1.05 / (2 * M_PI), 3, forces, points);
  check(status == UDMAP_OK, "response");
  for (i = 0; i < 3; i++)
    for (j = 0; j < points[i].nroots; j++)
      worst = fmax(worst, fabs(residual(points[i].roots[j], 1.05, forces[i])));
  check(worst < 1e-11, "response roots on the equation");

  status = udmap_model_curves(err, model, 3, forces, 30);
  check(status == UDMAP_OK, "curves");
  worst = 0;
  for (i = 0; i < 3; i++) {
    double *f, *g, *s;
    int *branch, *part, turning = 0;
    status = udmap_model_curve_size(err, model, i, &n);
    check(status == UDMAP_OK && n > 60, "curve size");
    f = malloc(n * sizeof *f);
    g = malloc(n * sizeof *g);
    s = malloc(n * sizeof *s);
    branch = malloc(n * sizeof *branch);
    part = malloc(n * sizeof *part);
    status = udmap_model_curve_get(err, model, i, n, f, g, s, branch, part);
    check(status == UDMAP_OK, "curve get");
    for (j = 0; j < n; j++) {
      worst = fmax(worst, fabs(residual(g[j], 2 * M_PI * f[j], forces[i])));
      turning += branch[j] == UDMAP_BRANCH_TURNING;
    }
    check(turning == 1, "one turning point per curve");
    status = udmap_model_curve_get(err, model, i, n - 1, f, g, s, branch, part);
    check(status == UDMAP_EINPUT, "curve get with a short buffer");
    free(f); free(g); free(s); free(branch); free(part);
  }
  check(worst < 1e-9, "curve points on the equation");
  status = udmap_model_curve_size(err, model, 3, &n);
  check(status == UDMAP_EINPUT, "curve index out of range");

  /* multi-harmonic layers (PHYSICS.md 4.1): harmonics 0..3 on the same model, then back to
   * the single-harmonic path with bit-identical numbers */
  {
    udmap_point h3[2], h1[2], b1[2];
    double gh[8], sh[8];
    int nh = 0;
    check(analysis.harmonics == 1 && analysis.harmonic_tol == 1e-3, "harmonics defaults");
    status = udmap_model_backbone(err, model, 2, forces, b1);
    check(status == UDMAP_OK && b1[0].harmonics == 1 && b1[0].gamma_max == b1[0].gamma_P &&
              b1[0].sigma_max == b1[0].sigma_a, "H = 1 point fields");
    status = udmap_model_set_harmonics(err, model, 3, 1e-3);
    check(status == UDMAP_OK, "set harmonics 3");
    status = udmap_model_backbone(err, model, 2, forces, h3);
    check(status == UDMAP_OK && h3[0].harmonics == 3 && h3[1].harmonics == 3, "backbone H = 3");
    check(h3[0].gamma_max > 0 && fabs(h3[0].gamma_P / b1[0].gamma_P - 1) < 0.2,
          "H = 3 near H = 1");
    status = udmap_model_point_harmonics(err, model, 1, 8, gh, sh, &nh);
    check(status == UDMAP_OK && nh == 4 && gh[1] == h3[1].gamma_P, "harmonic content");
    check(gh[1] - gh[2] - gh[3] <= h3[1].gamma_max && h3[1].gamma_max <= gh[1] + gh[2] + gh[3],
          "gamma_max between the bounds of its harmonics");
    status = udmap_model_point_harmonics(err, model, 2, 8, gh, sh, &nh);
    check(status == UDMAP_EINPUT, "harmonic content: index out of range");
    status = udmap_model_set_harmonics(err, model, 65, 1e-3);
    check(status == UDMAP_EINPUT, "harmonics 65 refused");
    status = udmap_model_set_harmonics(err, model, 0, 0.5);
    check(status == UDMAP_EINPUT, "harmonic_tol 0.5 refused");
    status = udmap_model_set_harmonics(err, model, 1, 1e-3);
    status = udmap_model_backbone(err, model, 2, forces, h1);
    check(status == UDMAP_OK && h1[0].gamma_P == b1[0].gamma_P &&
              h1[1].f_res == b1[1].f_res && h1[1].sigma_a == b1[1].sigma_a,
          "back to H = 1: the same numbers");
    /* the interblade phase of the next calls: a Jenkins damper does not feel it (PHYSICS.md
     * 2.6), so the same numbers; a phase that is not a finite angle is refused */
    {
      char msg[512];
      status = udmap_model_set_ibpa(err, model, NAN);
      udmap_get_error(err, msg, sizeof msg);
      check(status == UDMAP_EINPUT && strstr(msg, "ibpa_deg") != NULL,
            "set_ibpa: NaN refused, naming ibpa_deg");
    }
    status = udmap_model_set_ibpa(err, model, 90.0);
    check(status == UDMAP_OK, "set_ibpa 90 deg");
    status = udmap_model_backbone(err, model, 2, forces, h1);
    check(status == UDMAP_OK && h1[0].gamma_P == b1[0].gamma_P && h1[1].f_res == b1[1].f_res,
          "a Jenkins damper at 90 deg: the same numbers");
    status = udmap_model_set_ibpa(err, model, 0.0);
    check(status == UDMAP_OK, "set_ibpa back to 0");
  }

  /* udmap_model_classify on blade A's backbone points: the kernel's regime and hcf_ok of
   * points computed elsewhere, here the backbone's own (every regime, both hcf_ok values) */
  {
    udmap_beam_params beam = blade_a_beam_params();
    udmap_asymmetric_params dp = blade_a_damper_params();
    udmap_blade ba = NULL;
    udmap_damper da = NULL;
    udmap_model ma = NULL;
    udmap_analysis an;
    udmap_point bp[6];
    double F[6] = {0.05, 1, 5, 10, 12, 25}, g[6], sg[6], Fl = 0, Fb = 0, nan = NAN;
    int un[6], reg[6], hcf[6], seen[4] = {0}, n_ok = 0, same = 1;
    status = udmap_new_blade_beam(err, &beam, &ba);
    status |= udmap_new_damper_asymmetric(err, &dp, &da);
    udmap_analysis_defaults(&an);
    an.f_min = 150;
    an.f_max = 230;
    an.sigma_all = 200e6;
    status |= udmap_new_model(err, ba, da, &an, &ma);
    status |= udmap_model_limit_force(err, ma, &Fl);
    status |= udmap_model_limit_force_backbone(err, ma, &Fb);
    status |= udmap_model_backbone(err, ma, 6, F, bp);
    check(status == UDMAP_OK, "blade A backbone");
    for (i = 0; i < 6; i++) {
      g[i] = bp[i].gamma_P;
      sg[i] = bp[i].sigma_a;
      un[i] = bp[i].unbounded;
      reg[i] = hcf[i] = -1;
    }
    status = udmap_model_classify(err, ma, fmin(Fl, Fb), 6, F, g, sg, un, reg, hcf);
    check(status == UDMAP_OK, "classify");
    for (i = 0; i < 6; i++) {
      same &= reg[i] == bp[i].regime && hcf[i] == bp[i].hcf_ok;
      if (reg[i] >= 0 && reg[i] < 4) seen[reg[i]] = 1;
      n_ok += hcf[i];
    }
    check(same, "classify: the backbone's regime and hcf_ok");
    check(seen[0] && seen[1] && seen[2] && seen[3] && n_ok > 0 && n_ok < 6,
          "classify: every regime and both hcf_ok values covered");
    un[1] = 1;
    g[1] = sg[1] = nan; /* not read for an unbounded point */
    status = udmap_model_classify(err, ma, Fl, 6, F, g, sg, un, reg, hcf);
    check(status == UDMAP_OK && reg[1] == 3 && hcf[1] == 0, "classify: unbounded point");
    status = udmap_model_classify(err, ma, INFINITY, 1, F, g, sg, un, reg, hcf);
    check(status == UDMAP_OK && reg[0] == bp[0].regime && hcf[0] == 0,
          "classify: no limit known, never admissible");
    status = udmap_model_classify(err, ma, Fl, 0, F, g, sg, un, reg, hcf);
    check(status == UDMAP_OK, "classify: no points");
    /* bad calls */
    un[1] = 0;
    status = udmap_model_classify(err, none, Fl, 1, F, g, sg, un, reg, hcf);
    check_error(err, status, "NULL", "classify: NULL model");
    status = udmap_model_classify(err, ma, Fl, -1, F, g, sg, un, reg, hcf);
    check_error(err, status, "n must not be negative", "classify: negative n");
    status = udmap_model_classify(err, ma, 0.0, 1, F, g, sg, un, reg, hcf);
    check_error(err, status, "F_lim must be positive", "classify: F_lim = 0");
    status = udmap_model_classify(err, ma, nan, 1, F, g, sg, un, reg, hcf);
    check_error(err, status, "F_lim must be positive", "classify: F_lim NaN");
    F[2] = -1;
    status = udmap_model_classify(err, ma, Fl, 3, F, g, sg, un, reg, hcf);
    check_error(err, status, "F_E(3)", "classify: negative force named");
    F[2] = 5;
    status = udmap_model_classify(err, ma, Fl, 3, F, g, sg, un, reg, hcf);
    check_error(err, status, "gamma_P(2)", "classify: NaN gamma_P named");
    g[1] = bp[1].gamma_P;
    sg[1] = -1;
    status = udmap_model_classify(err, ma, Fl, 3, F, g, sg, un, reg, hcf);
    check_error(err, status, "sigma(2)", "classify: negative stress named");
    udmap_delete_model(&ma);
    udmap_delete_damper(&da);
    udmap_delete_blade(&ba);
  }

  /* bad calls */
  forces[1] = -1;
  status = udmap_model_backbone(err, model, 3, forces, points);
  {
    char msg[512];
    udmap_get_error(err, msg, sizeof msg);
    check(status == UDMAP_EINPUT && strstr(msg, "F_E(2)") != NULL, "negative force named");
  }
  status = udmap_model_limit_force(err, none, &F_lim);
  check(status == UDMAP_EINPUT, "NULL model");
  status = udmap_model_response(err, model, 1.0, 1, forces, points);
  check(status == UDMAP_EINPUT, "f_exc beyond 3 f_max");
  /* outside the band [0.127, 0.223] Hz but within 3 f_max: answered at that frequency */
  status = udmap_model_response(err, model, 0.5, 1, forces, points);
  check(status == UDMAP_OK && points[0].f_res == 0.5 && points[0].gamma_P > 0.0,
        "f_exc outside the band, within 3 f_max, answered");

  udmap_delete_model(&model);
  check(model == NULL, "delete model");
  udmap_delete_model(&model);
  udmap_delete_damper(&damper);
  udmap_delete_blade(&blade);
  udmap_delete_error(&err);
  unlink(pM);
  unlink(pK);
  unlink(pC);
  rmdir(dir);
  return check_finish();
}
