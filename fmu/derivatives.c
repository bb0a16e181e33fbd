/*
 * Directional derivatives of the real outputs with respect to the real inputs and tunable
 * parameters (fmi2GetDirectionalDerivative, fmi3GetDirectionalDerivative).
 *
 * F_E, analytic: the output gamma_P solves F_bb(gamma) = F_E, and by the envelope theorem the
 *   slope of the backbone F_bb = gamma / max_w |g~(w; k(gamma))| needs only the partial
 *   derivative at the peak frequency, d|g~|/dgamma = Re(conj(g~) dg~/dk dk/dgamma) / |g~| with
 *   dg~/dk = -g~ H_gg / (1 + k H_gg) and the kernel's dk/dgamma. At a given f_exc,
 *   gamma |1 + k(gamma) H_gg| = F_E |H_gE| is differentiated the same way. k_re, k_im follow
 *   by the chain rule; f_res and the stress and displacement per unit force (|s~|, |u~|) by
 *   the chain rule with their slope along the backbone taken as a five-point central
 *   difference in gamma of relative step LAYER_STEP (error O(h^4); the layer quantities only,
 *   no new roots are solved).
 * CF, exact: the scaling law k(gamma; lambda CF) = k(gamma / lambda; CF) makes gamma_P,
 *   sigma_a, u_E and F_lim homogeneous of degree 1 in (F_E, CF) and f_res, k_re, k_im, F_ratio
 *   of degree 0, so by Euler's theorem CF dy/dCF = degree y - F_E dy/dF_E.
 * Every other known (mu, contact stiffnesses, blade, damper and band parameters, f_exc):
 *   one central difference along the seed vector restricted to those knowns (two evaluations
 *   per call, whatever the number of knowns), with the step t chosen so that the largest
 *   relative change of a known is FD_STEP; where x - t s leaves a variable's range (e.g.
 *   zeta = 0), the second-order one-sided formula (-3 y0 + 4 y(t) - y(2t)) / (2t). The
 *   evaluations run on a second instance, so the caches of this one are kept. f_exc = 0 means
 *   "at resonance", a switch, not a frequency: its derivative there is 0.
 */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "model.h"

#define FD_STEP 1e-4    /* largest relative change of a known in the finite differences */
#define LAYER_STEP 1e-4 /* relative step in gamma along the backbone */

#define V(name) (m->value[vr_##name])

static bool real_output(unsigned vr) {
  return vr < UDMAP_NVARS && udmap_variables[vr].type == REAL &&
         udmap_variables[vr].causality == OUTPUT;
}

static bool real_known(const ModelInstance *m, unsigned vr) {
  return model_has(m, vr) && udmap_variables[vr].type == REAL &&
         (udmap_variables[vr].causality == INPUT || udmap_variables[vr].causality == PARAMETER);
}

/* The outputs whose slopes in F_E and CF force_slopes() gives; any other real output (one
 * added to the table later) gets them from the finite difference along the whole seed. */
static bool analytic(unsigned vr) {
  return vr == vr_gamma_P || vr == vr_sigma_a || vr == vr_f_res || vr == vr_u_E ||
         vr == vr_k_re || vr == vr_k_im || vr == vr_F_lim || vr == vr_F_ratio;
}

/* The analytic slopes hold for the single-harmonic backbone (its envelope theorem); with
 * multi-harmonic layers every output takes the finite difference. */
static bool analytic_at(const ModelInstance *m, unsigned vr) {
  return m->value[vr_harmonics] == 1.0 && analytic(vr);
}

/* Degree of homogeneity of an output in (F_E, CF). */
static double cf_degree(unsigned vr) {
  return vr == vr_gamma_P || vr == vr_sigma_a || vr == vr_u_E || vr == vr_F_lim ? 1.0 : 0.0;
}

/* All real outputs of instance m for its current values; Error with a message in msg when
 * they are not finite numbers (a failed stage, an unbounded response). */
static Status real_outputs(ModelInstance *m, double y[UDMAP_NVARS], char *msg, size_t n) {
  for (unsigned vr = 0; vr < UDMAP_NVARS; vr++) {
    if (!real_output(vr)) continue;
    Stage stage;
    Status st = model_output(m, (ValueReference)vr, &y[vr], &stage);
    if (st >= Discard || !isfinite(y[vr])) {
      snprintf(msg, n, "%s", st >= Discard ? model_stage_message(m, stage)
                                           : "the response is unbounded (zeta = 0 and F_E >= "
                                             "F_lim): no derivative");
      return Error;
    }
  }
  return OK;
}

/* Layer quantities at frequency f [Hz] and damper stiffness k: g~, s~, u~ per unit force. */
static int layer(ModelInstance *m, double f, double complex k, double complex *g,
                 double complex *s, double complex *u, double complex *H_gg,
                 double complex *H_gE) {
  double h[10];
  int stat = udmap_blade_receptances(m->err, m->blade, 1, &f, h);
  if (stat != UDMAP_OK) return stat;
  *H_gE = h[0] + I * h[1];
  *H_gg = h[2] + I * h[3];
  const double complex H_EE = h[4] + I * h[5], H_sE = h[6] + I * h[7], H_sg = h[8] + I * h[9];
  *g = *H_gE / (1.0 + k * *H_gg);
  *s = H_sE - k * H_sg * *g;
  *u = H_EE - k * *H_gE * *g;
  return UDMAP_OK;
}

/* |s~| and |u~| on the layer of amplitude gamma (at its peak frequency, or at f_exc). */
static int layer_at(ModelInstance *m, double gamma, double *f, double *s_abs, double *u_abs) {
  int stat;
  if (V(f_exc) == 0.0) {
    double F_bb;
    stat = udmap_model_backbone_curve(m->err, m->model, 1, &gamma, &F_bb, f);
    if (stat != UDMAP_OK) return stat;
  } else {
    *f = V(f_exc);
  }
  double k_re, k_im;
  stat = udmap_damper_stiffness(m->err, m->damper, 1, &gamma, &k_re, &k_im);
  if (stat != UDMAP_OK) return stat;
  double complex g, s, u, H_gg, H_gE;
  stat = layer(m, *f, k_re + I * k_im, &g, &s, &u, &H_gg, &H_gE);
  *s_abs = cabs(s);
  *u_abs = cabs(u);
  return stat;
}

/* d y / d F_E for every real output (analytic, see the header). */
static Status force_slopes(ModelInstance *m, const double y[UDMAP_NVARS], double d[UDMAP_NVARS],
                           char *msg, size_t n) {
  const udmap_point *p = &m->point;
  const double F = V(F_E), gamma = p->gamma_P;
  const double complex k = p->k_re + I * p->k_im;
  double complex g, s, u, H_gg, H_gE;
  int stat = layer(m, p->f_res, k, &g, &s, &u, &H_gg, &H_gE);
  double dgamma_dF = 0.0, ds = 0.0, du = 0.0, df = 0.0, dk_re = 0.0, dk_im = 0.0;
  if (stat == UDMAP_OK && (F == 0.0 || gamma == 0.0)) {
    /* the limit F_E -> 0+: stuck, the response is linear in F_E */
    dgamma_dF = cabs(g);
  } else if (stat == UDMAP_OK) {
    stat = udmap_damper_stiffness_derivative(m->err, m->damper, 1, &gamma, &dk_re, &dk_im);
    const double complex dk = dk_re + I * dk_im, a = 1.0 + k * H_gg;
    if (V(f_exc) == 0.0) {
      const double G = cabs(g);
      const double dG = creal(conj(g) * (-g * H_gg / a) * dk) / G; /* envelope theorem */
      dgamma_dF = G * G / (G - gamma * dG);
    } else {
      const double dphi = cabs(a) + gamma * creal(conj(a) * dk * H_gg) / cabs(a);
      dgamma_dF = cabs(H_gE) / dphi;
    }
    /* five-point central difference (the centre has weight 0): error O(h^4) */
    static const double c[4] = {1.0, -1.0, 2.0, -2.0}, w[4] = {8.0, -8.0, -1.0, 1.0};
    const double step = 12.0 * LAYER_STEP * gamma;
    for (int i = 0; i < 4 && stat == UDMAP_OK; i++) {
      double f = 0.0, s_abs = 0.0, u_abs = 0.0;
      stat = layer_at(m, gamma * (1.0 + c[i] * LAYER_STEP), &f, &s_abs, &u_abs);
      df += w[i] * f / step;
      ds += w[i] * s_abs / step;
      du += w[i] * u_abs / step;
    }
  }
  if (stat != UDMAP_OK) {
    char kmsg[400];
    udmap_get_error(m->err, kmsg, sizeof kmsg);
    snprintf(msg, n, "slope along the backbone failed (status %d): %s", stat, kmsg);
    return Error;
  }
  memset(d, 0, UDMAP_NVARS * sizeof d[0]);
  d[vr_gamma_P] = dgamma_dF;
  d[vr_f_res] = df * dgamma_dF;
  d[vr_k_re] = dk_re * dgamma_dF;
  d[vr_k_im] = dk_im * dgamma_dF;
  d[vr_sigma_a] = cabs(s) + F * ds * dgamma_dF;
  d[vr_u_E] = cabs(u) + F * du * dgamma_dF;
  d[vr_F_lim] = 0.0;
  d[vr_F_ratio] = 1.0 / y[vr_F_lim];
  return OK;
}

/* The scratch instance at the values of m moved by c t r; false if a value leaves its range. */
static bool move(ModelInstance *m, ModelInstance *w, const double r[UDMAP_NVARS], double ct) {
  model_copy_values(w, m);
  for (unsigned vr = 0; vr < UDMAP_NVARS; vr++)
    if (r[vr] != 0.0 && model_set(w, "", (ValueReference)vr, REAL, m->value[vr] + ct * r[vr],
                                  true) != OK)
      return false;
  return true;
}

/* One finite difference along r (the knowns other than F_E and CF). */
static Status finite_difference(ModelInstance *m, const double y0[UDMAP_NVARS],
                                const double r[UDMAP_NVARS], double d[UDMAP_NVARS], char *msg,
                                size_t n) {
  if (!m->scratch) {
    m->scratch = model_new("derivatives", m->fmiVersion, m->type, NULL, NULL, NULL, false);
    if (!m->scratch) {
      snprintf(msg, n, "out of memory");
      return Error;
    }
    if (m->config) model_set_case(m->scratch, m->config, false);
    m->scratch->exact_points = true;
  }
  ModelInstance *w = m->scratch;
  double ratio = 0.0;
  for (unsigned vr = 0; vr < UDMAP_NVARS; vr++) {
    if (r[vr] == 0.0) continue;
    const double x = fabs(m->value[vr]), x0 = fabs(udmap_variables[vr].start);
    ratio = fmax(ratio, fabs(r[vr]) / (x > 0.0 ? x : x0 > 0.0 ? x0 : 1.0));
  }
  const double t = FD_STEP / ratio;
  /* points c t r and weights of (sum w_c y_c) / t: central, or one-sided of second order */
  static const double c_central[2] = {1.0, -1.0}, w_central[2] = {0.5, -0.5};
  static const double c_forward[2] = {1.0, 2.0}, w_forward[2] = {2.0, -0.5};
  static const double c_backward[2] = {-1.0, -2.0}, w_backward[2] = {-2.0, 0.5};
  const double *c = c_central, *wt = w_central;
  double w0 = 0.0;
  if (!move(m, w, r, -t)) c = c_forward, wt = w_forward, w0 = -1.5;
  else if (!move(m, w, r, t)) c = c_backward, wt = w_backward, w0 = 1.5;
  /* a one-sided difference takes y0 from the scratch too: its points are all exact, while
   * this instance's may come from the force table */
  double y0w[UDMAP_NVARS];
  if (w0 != 0.0) {
    char why[600] = "a known leaves its range";
    if (!move(m, w, r, 0.0) || real_outputs(w, y0w, why, sizeof why) != OK) {
      snprintf(msg, n, "finite difference at the point itself: %s", why);
      return Error;
    }
    y0 = y0w;
  }
  for (unsigned vr = 0; vr < UDMAP_NVARS; vr++) d[vr] = w0 * y0[vr];
  for (int i = 0; i < 2; i++) {
    double y[UDMAP_NVARS];
    if (!move(m, w, r, c[i] * t)) {
      snprintf(msg, n, "no finite difference step of %g along the seed keeps the knowns in "
               "their ranges", t);
      return Error;
    }
    char why[600];
    if (real_outputs(w, y, why, sizeof why) != OK) {
      snprintf(msg, n, "finite difference at %g times the seed: %s", c[i] * t, why);
      return Error;
    }
    for (unsigned vr = 0; vr < UDMAP_NVARS; vr++)
      if (real_output(vr)) d[vr] += wt[i] * y[vr];
  }
  for (unsigned vr = 0; vr < UDMAP_NVARS; vr++) d[vr] /= t;
  return OK;
}

Status model_directional_derivative(ModelInstance *m, const char *fn,
                                    const unsigned unknowns[], size_t nUnknowns,
                                    const unsigned knowns[], size_t nKnowns,
                                    const double seed[], double sensitivity[]) {
  double dx[UDMAP_NVARS] = {0};
  for (size_t i = 0; i < nUnknowns; i++) {
    if (!real_output(unknowns[i])) {
      model_log(m, Error, "%s: unknown %u is not a real output", fn, unknowns[i]);
      return Error;
    }
    sensitivity[i] = 0.0;
  }
  for (size_t j = 0; j < nKnowns; j++) {
    const unsigned vr = knowns[j];
    if (!real_known(m, vr)) {
      model_log(m, Error, "%s: known %u is not a real input or tunable parameter", fn, vr);
      return Error;
    }
    if (!isfinite(seed[j])) {
      model_log(m, Error, "%s: seed %zu = %g is not finite", fn, j, seed[j]);
      return Error;
    }
    dx[vr] += seed[j];
  }
  if (nUnknowns == 0) return OK;
  if (V(f_exc) == 0.0) dx[vr_f_exc] = 0.0; /* "at resonance" is a switch */

  char msg[800];
  double y0[UDMAP_NVARS] = {0}, d[UDMAP_NVARS], total[UDMAP_NVARS] = {0};
  Status st = real_outputs(m, y0, msg, sizeof msg);
  bool others = false; /* unknowns without analytic slopes: all by finite differences */
  for (size_t i = 0; i < nUnknowns; i++) others = others || !analytic_at(m, unknowns[i]);
  if (st == OK && others && (dx[vr_F_E] != 0.0 || dx[vr_CF] != 0.0)) {
    double full[UDMAP_NVARS];
    st = finite_difference(m, y0, dx, full, msg, sizeof msg);
    for (unsigned vr = 0; st == OK && vr < UDMAP_NVARS; vr++)
      if (!analytic_at(m, vr)) total[vr] = full[vr];
  }
  if (st == OK && (dx[vr_F_E] != 0.0 || dx[vr_CF] != 0.0)) {
    st = force_slopes(m, y0, d, msg, sizeof msg);
    for (unsigned vr = 0; st == OK && vr < UDMAP_NVARS; vr++) {
      if (!analytic_at(m, vr)) continue;
      const double dCF = (cf_degree(vr) * y0[vr] - V(F_E) * d[vr]) / V(CF);
      total[vr] += dx[vr_F_E] * d[vr] + dx[vr_CF] * dCF;
    }
  }
  const bool full_done = others && (dx[vr_F_E] != 0.0 || dx[vr_CF] != 0.0);
  dx[vr_F_E] = dx[vr_CF] = 0.0;
  bool rest = false;
  for (unsigned vr = 0; vr < UDMAP_NVARS; vr++) rest = rest || dx[vr] != 0.0;
  if (st == OK && rest) {
    st = finite_difference(m, y0, dx, d, msg, sizeof msg);
    for (unsigned vr = 0; st == OK && vr < UDMAP_NVARS; vr++)
      if (analytic_at(m, vr) || !full_done) total[vr] += d[vr];
  }
  if (st != OK) {
    model_log(m, Error, "%s: %s", fn, msg);
    return Error;
  }
  for (size_t i = 0; i < nUnknowns; i++) sensitivity[i] = total[unknowns[i]];
  return OK;
}
