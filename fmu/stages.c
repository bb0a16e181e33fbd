/*
 * udmap FMU model, staged evaluation: the outputs computed lazily over the kernel's C API in
 * stages (blade, damper, CF rescale, model, limit force, response point, natural frequency),
 * each run at most once per set of values, what a change of a group's value makes stale, and
 * the value of each output. The values, the state machine, logging and snapshots are in
 * model.c.
 */
#ifndef _WIN32
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#endif
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model.h"

#ifdef _WIN32
/* KERNEL32's performance counter, declared here: windows.h would clash with the FMU's names
 * (INPUT, BOOLEAN); a LARGE_INTEGER is a 64-bit integer */
__declspec(dllimport) int __stdcall QueryPerformanceCounter(long long *count);
__declspec(dllimport) int __stdcall QueryPerformanceFrequency(long long *frequency);
#else
#include <time.h>
#endif

#define BIT(stage) (1u << (stage))
#define V(name) (m->value[vr_##name])

static const char *const stage_names[NSTAGES] = {"blade", "damper", "CF rescale", "model",
                                                 "limit force", "response point",
                                                 "natural frequency", "force range"};

/* Stages a change of a group's value makes stale. Neither CF nor the damper parameters
 * rebuild the model: it notices udmap_damper_set_CF by itself, and a new damper is coupled to
 * it with udmap_model_set_damper (the bare-blade data are kept). Everything the kernel's
 * tables depend on (damper, CF, model, harmonics) and the range itself make the force range
 * stale: the next point prepares it again, in the step that made the change. */
static const unsigned invalidates[] = {
  [GROUP_NONE] = 0,
  [GROUP_FORCE] = BIT(STAGE_POINT),
  [GROUP_CF] = BIT(STAGE_CF) | BIT(STAGE_LIMIT) | BIT(STAGE_POINT) | BIT(STAGE_COVER),
  [GROUP_DAMPER] = BIT(STAGE_DAMPER) | BIT(STAGE_CF) | BIT(STAGE_LIMIT) | BIT(STAGE_POINT) |
                   BIT(STAGE_COVER),
  [GROUP_BLADE] = BIT(STAGE_BLADE) | BIT(STAGE_MODEL) | BIT(STAGE_LIMIT) | BIT(STAGE_POINT) |
                  BIT(STAGE_F1) | BIT(STAGE_COVER),
  [GROUP_ANALYSIS] = BIT(STAGE_MODEL) | BIT(STAGE_LIMIT) | BIT(STAGE_POINT) | BIT(STAGE_COVER),
  [GROUP_HARMONICS] = BIT(STAGE_POINT) | BIT(STAGE_COVER),
  [GROUP_POINT] = 0,
  [GROUP_LIMIT] = 0,
  [GROUP_RATIO] = 0,
  [GROUP_RANGE] = BIT(STAGE_POINT) | BIT(STAGE_COVER),
};

void model_invalidate(ModelInstance *m, Group group) { m->done &= ~invalidates[group]; }

/* ---------------------------------------------------------------- stages */

static Status run(ModelInstance *m, Stage s);

/* Records a kernel failure of stage s with the kernel's message. */
static Status kernel_failure(ModelInstance *m, Stage s, int stat, const char *call) {
  char msg[400];
  udmap_get_error(m->err, msg, sizeof msg);
  const char *kind = stat == UDMAP_EINPUT     ? "bad input"
                     : stat == UDMAP_EPHYSICS ? "physics"
                     : stat == UDMAP_ENUMERIC ? "numerical failure"
                                              : "failure";
  snprintf(m->stage_message[s], sizeof m->stage_message[s], "%s: %s (%s, status %d): %s",
           stage_names[s], call, kind, stat, msg[0] ? msg : "no message");
  return Error;
}

static Status failure(ModelInstance *m, Stage s, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static Status failure(ModelInstance *m, Stage s, const char *fmt, ...) {
  char msg[400];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  snprintf(m->stage_message[s], sizeof m->stage_message[s], "%s: %s", stage_names[s], msg);
  return Error;
}

/* Runs the stages s depends on; on failure s inherits the status and message. */
static Status need(ModelInstance *m, Stage s, const Stage *deps, int ndeps) {
  for (int i = 0; i < ndeps; i++) {
    Status st = run(m, deps[i]);
    if (st >= Discard) {
      memcpy(m->stage_message[s], m->stage_message[deps[i]], sizeof m->stage_message[s]);
      return st;
    }
  }
  return OK;
}

static Status build_blade(ModelInstance *m) {
  udmap_delete_model(&m->probe);
  udmap_delete_model(&m->model);
  udmap_delete_blade(&m->blade);
  const CaseConfig *c = m->config;
  if (c && c->blade == BLADE_MATRICES) {
    /* the kernel's Matrix Market reader on the files in resources/ */
    int stat = udmap_new_blade_matrices(m->err, c->M, c->K, c->C[0] ? c->C : NULL, c->gamma_dof,
                                        c->exc_dof, c->stress_K[0] ? c->stress_K : NULL,
                                        c->stress_M[0] ? c->stress_M : NULL, V(zeta), &m->blade);
    if (stat != UDMAP_OK)
      return kernel_failure(m, STAGE_BLADE, stat, "udmap_new_blade_matrices");
    if (c->u_dof > 0) {
      /* the platform translations of a traveling wave (PHYSICS.md 2.6): unit rows */
      int ndof = 0, has_stress = 0;
      stat = udmap_blade_get_size(m->err, m->blade, &ndof, &has_stress);
      if (stat != UDMAP_OK) return kernel_failure(m, STAGE_BLADE, stat, "udmap_blade_get_size");
      if (c->u_dof > ndof || c->v_dof > ndof)
        return failure(m, STAGE_BLADE, "u_dof = %d or v_dof = %d beyond the %d DOFs of the blade",
                       c->u_dof, c->v_dof, ndof);
      double *rows = calloc(2 * (size_t)ndof, sizeof *rows);
      if (!rows) return failure(m, STAGE_BLADE, "out of memory");
      rows[c->u_dof - 1] = 1.0;
      if (c->v_dof > 0) rows[ndof + c->v_dof - 1] = 1.0;
      stat = udmap_blade_set_platform_rows(m->err, m->blade, ndof, rows,
                                           c->v_dof > 0 ? rows + ndof : NULL);
      free(rows);
      if (stat != UDMAP_OK)
        return kernel_failure(m, STAGE_BLADE, stat, "udmap_blade_set_platform_rows");
    }
    model_log_category(m, LOG_EVENTS, OK, "blade read from %s", c->K);
    return OK;
  }
  udmap_beam_params p = {
    .E = V(E), .rho = V(rho), .zeta = V(zeta),
    .neck_L = V(neck_L), .neck_h = V(neck_h), .neck_b = V(neck_b),
    .platform_L = V(platform_L), .platform_m = V(platform_m), .platform_J = V(platform_J),
    .airfoil_L = V(airfoil_L), .airfoil_h = V(airfoil_h), .airfoil_b = V(airfoil_b),
    .neck_elements = (int)V(neck_elements), .airfoil_elements = (int)V(airfoil_elements),
  };
  int stat = udmap_new_blade_beam(m->err, &p, &m->blade);
  if (stat != UDMAP_OK) return kernel_failure(m, STAGE_BLADE, stat, "udmap_new_blade_beam");
  model_log_category(m, LOG_EVENTS, OK, "blade built (%d neck + %d airfoil elements)",
                     p.neck_elements, p.airfoil_elements);
  return OK;
}

/* The damper is always traced at the start value of CF and rescaled to the current CF
 * (PHYSICS.md 2.3), so its table is a function of the current values alone, whatever the
 * order of the changes that led to them. */
static double reference_CF(const ModelInstance *m) { return model_start_value(m, vr_CF); }

/* Releases the model and marks it (and what it computed) to be built again. */
static void drop_model(ModelInstance *m) {
  udmap_delete_model(&m->probe);
  udmap_delete_model(&m->model);
  m->done &= ~(BIT(STAGE_MODEL) | BIT(STAGE_LIMIT) | BIT(STAGE_POINT) | BIT(STAGE_COVER));
}

/* The damper of a case that is not asymmetric: a Jenkins element or a measured table. */
static int new_case_damper(ModelInstance *m, udmap_damper *d, const char **call) {
  const CaseConfig *c = m->config;
  if (c->damper == DAMPER_JENKINS) {
    *call = "udmap_new_damper_jenkins";
    return udmap_new_damper_jenkins(m->err, c->kt, c->M_slip, d);
  }
  *call = "udmap_new_damper_table";
  return udmap_new_damper_table(m->err, c->n, c->gamma, c->k_re, c->k_im, c->has_delta_M,
                                c->delta_M, d);
}

static Status build_damper(ModelInstance *m) {
  udmap_asymmetric_params p = {
    .CF = reference_CF(m), .mu = V(mu), .pitch = V(pitch), .y_P = V(y_P),
    .beta_L_deg = V(beta_L_deg), .beta_R_deg = V(beta_R_deg),
    .flat1_x = V(flat1_x), .flat1_y = V(flat1_y), .flat2_x = V(flat2_x),
    .flat2_y = V(flat2_y), .curved_x = V(curved_x), .curved_y = V(curved_y),
    .kn_flat = V(kn_flat), .kt_flat = V(kt_flat), .kn_curved = V(kn_curved),
    .kt_curved = V(kt_curved),
  };
  udmap_damper fresh = NULL;
  const char *call = "udmap_new_damper_asymmetric";
  int stat = m->config && m->config->damper != DAMPER_ASYMMETRIC
                 ? new_case_damper(m, &fresh, &call)
                 : udmap_new_damper_asymmetric(m->err, &p, &fresh);
  if (stat != UDMAP_OK) {
    /* the model must not keep borrowing a damper that no longer matches the values */
    drop_model(m);
    udmap_delete_damper(&m->damper);
    m->damper_CF = NAN;
    return kernel_failure(m, STAGE_DAMPER, stat, call);
  }
  model_log_category(m, LOG_EVENTS, OK, "damper traced (mu = %g, CF = %g N)", p.mu, p.CF);
  if (m->model && (m->done & BIT(STAGE_MODEL))) {
    stat = udmap_model_set_damper(m->err, m->model, fresh);
    if (stat == UDMAP_OK)
      model_log_category(m, LOG_EVENTS, OK, "damper coupled to the model (bare-blade data "
                         "kept)");
    else
      drop_model(m); /* built again, with the new damper, when needed */
  } else {
    drop_model(m);
  }
  /* the plausibility checks' model borrows the damper too: couple it to the new one first */
  if (m->probe && udmap_model_set_damper(m->err, m->probe, fresh) != UDMAP_OK)
    udmap_delete_model(&m->probe);
  udmap_delete_damper(&m->damper);
  m->damper = fresh;
  m->damper_CF = p.CF;
  return OK;
}

static Status apply_CF(ModelInstance *m) {
  static const Stage deps[] = {STAGE_DAMPER};
  Status st = need(m, STAGE_CF, deps, 1);
  if (st >= Discard) return st;
  if (!model_has(m, vr_CF) || V(CF) == m->damper_CF) return OK; /* only the asymmetric has CF */
  int stat = udmap_damper_set_CF(m->err, m->damper, V(CF));
  if (stat != UDMAP_OK) {
    m->damper_CF = NAN; /* unknown: set it again next time */
    return kernel_failure(m, STAGE_CF, stat, "udmap_damper_set_CF");
  }
  m->damper_CF = V(CF);
  model_log_category(m, LOG_EVENTS, OK, "damper table rescaled to CF = %g N", V(CF));
  return OK;
}

static Status build_model(ModelInstance *m) {
  static const Stage deps[] = {STAGE_BLADE, STAGE_DAMPER, STAGE_CF};
  Status st = need(m, STAGE_MODEL, deps, 3);
  if (st >= Discard) return st;
  udmap_delete_model(&m->probe);
  udmap_delete_model(&m->model);
  if (!(V(f_min) < V(f_max)))
    return failure(m, STAGE_MODEL, "f_min = %g Hz must be below f_max = %g Hz", V(f_min),
                   V(f_max));
  udmap_analysis a;
  udmap_analysis_defaults(&a);
  if (m->config) a = m->config->analysis; /* the case's settings, as the command line */
  a.f_min = V(f_min);
  a.f_max = V(f_max);
  a.sigma_all = V(sigma_all);
  /* The eigenvalue start from the secular equation alone (no dense zggev per model): exact
   * for the FMU's beam blades, whose bare modes are all computed, and the same peaks as the
   * default to rounding (the start is only where the peak search begins); it keeps a change
   * of mu or of a contact stiffness at some 0.1 ms instead of 2 ms. */
  if (!m->config) a.eigen_method = 2;
  /* the traveling wave of engine order EO on N blades (PHYSICS.md 2.6), its phase in
   * (-180, 180] deg as the command line's nodal sweep takes it */
  const double N = V(blades), EO = fmod(V(engine_order), N);
  a.ibpa_deg = 360.0 * EO / N;
  if (a.ibpa_deg > 180.0) a.ibpa_deg -= 360.0;
  m->analysis = a;
  int stat = udmap_new_model(m->err, m->blade, m->damper, &a, &m->model);
  if (stat != UDMAP_OK) return kernel_failure(m, STAGE_MODEL, stat, "udmap_new_model");
  /* after a change of F_E alone, points come from the verified force table (exact points,
   * interpolated to harmonic_tol/1000 where a panel of them holds F_E): in phase at harmonics
   * != 1, for a traveling wave at every H (each exact point there is a root of layer solves,
   * 16 to 37 ms on blade A at EO = 1 of 24). */
  if (!m->exact_points) {
    stat = udmap_model_set_force_table(m->err, m->model, 1);
    if (stat != UDMAP_OK)
      return kernel_failure(m, STAGE_MODEL, stat, "udmap_model_set_force_table");
  }
  model_log_category(m, LOG_EVENTS, OK, "model built over [%g, %g] Hz", a.f_min, a.f_max);
  return OK;
}

static Status compute_limit(ModelInstance *m) {
  /* CF (and so the damper) first: a new damper may drop the model */
  static const Stage deps[] = {STAGE_CF, STAGE_MODEL};
  Status st = need(m, STAGE_LIMIT, deps, 2);
  if (st >= Discard) return st;
  if (!m->model || !m->damper) return failure(m, STAGE_LIMIT, "internal: no model");
  int stat = udmap_model_limit_force(m->err, m->model, &m->F_lim);
  if (stat != UDMAP_OK) return kernel_failure(m, STAGE_LIMIT, stat, "udmap_model_limit_force");
  stat = udmap_model_limit_force_backbone(m->err, m->model, &m->F_lim_backbone);
  if (stat != UDMAP_OK)
    return kernel_failure(m, STAGE_LIMIT, stat, "udmap_model_limit_force_backbone");
  stat = udmap_damper_get_info(m->err, m->damper, &m->info);
  if (stat != UDMAP_OK) return kernel_failure(m, STAGE_LIMIT, stat, "udmap_damper_get_info");
  if (!isfinite(m->F_lim) || m->F_lim < 0.0)
    return failure(m, STAGE_LIMIT, "the kernel returned F_lim = %g", m->F_lim);
  if (!isfinite(m->F_lim_backbone) || m->F_lim_backbone < 0.0)
    return failure(m, STAGE_LIMIT, "the kernel returned F_lim_backbone = %g", m->F_lim_backbone);
  model_log_category(m, LOG_EVENTS, OK, "limit force computed: F_lim = %.17g N", m->F_lim);
  if (m->F_lim == 0.0) {
    snprintf(m->stage_message[STAGE_LIMIT], sizeof m->stage_message[STAGE_LIMIT],
             "%s: F_lim = 0: the damper dissipates nothing (mu = %g), friction cannot limit "
             "the response", stage_names[STAGE_LIMIT], V(mu));
    return Warning;
  }
  return OK;
}

static Status compute_f1(ModelInstance *m) {
  static const Stage deps[] = {STAGE_BLADE};
  Status st = need(m, STAGE_F1, deps, 1);
  if (st >= Discard) return st;
  int stat = udmap_blade_natural_frequencies(m->err, m->blade, 1, &m->f1_bare);
  if (stat != UDMAP_OK)
    return kernel_failure(m, STAGE_F1, stat, "udmap_blade_natural_frequencies");
  return OK;
}

static double seconds(void) {
#ifdef _WIN32
  long long f, c;
  QueryPerformanceFrequency(&f);
  QueryPerformanceCounter(&c);
  return (double)c / (double)f;
#else
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
#endif
}

/* The harmonics of the point (and of the cover), with the case's tolerance of the auto H. */
static int set_harmonics(ModelInstance *m) {
  const double tol = m->config ? m->config->analysis.harmonic_tol : 1e-3;
  return udmap_model_set_harmonics(m->err, m->model, (int)V(harmonics), tol);
}

static const char *harmonics_text(const ModelInstance *m, char *buf, size_t n) {
  if (V(harmonics) == 0.0) snprintf(buf, n, "auto");
  else snprintf(buf, n, "%d", (int)V(harmonics));
  return buf;
}

/* The force range [F_E_min, F_E_max] prepared in the kernel (udmap_model_cover_forces): the
 * single-harmonic backbone table to F_E_max and, at harmonics != 1, every panel of the force
 * table over the range, so that no later step with F_E in the range builds anything. F_E_min
 * = 0 covers from F_E_max/1000. Not on the finite-difference instance (no force table). */
static Status compute_cover(ModelInstance *m) {
  static const Stage deps[] = {STAGE_CF, STAGE_MODEL};
  Status st = need(m, STAGE_COVER, deps, 2);
  if (st >= Discard) return st;
  if (!m->model) return failure(m, STAGE_COVER, "internal: no model");
  const double lo = V(F_E_min), hi = V(F_E_max);
  if (!(lo < hi))
    return failure(m, STAGE_COVER, "F_E_min = %g N must be below F_E_max = %g N", lo, hi);
  if (m->exact_points) return OK;
  m->outside_logged = false;
  /* a traveling wave's table is built on demand, as a master's forces visit it: preparing the
   * range would take some 10 to 20 s per decade of F_E (a few hundred exact points) */
  if (m->analysis.ibpa_deg != 0.0) {
    m->cover_lo = m->cover_hi = 0.0;
    m->cover_points = m->cover_leaves = m->cover_exact = 0;
    m->cover_seconds = 0.0;
    return OK;
  }
  m->cover_lo = lo > 0.0 ? lo : 1e-3 * hi;
  m->cover_hi = hi;
  const double t0 = seconds();
  int stat = set_harmonics(m);
  if (stat != UDMAP_OK) return kernel_failure(m, STAGE_COVER, stat, "udmap_model_set_harmonics");
  stat = udmap_model_cover_forces(m->err, m->model, m->cover_lo, m->cover_hi);
  if (stat != UDMAP_OK) return kernel_failure(m, STAGE_COVER, stat, "udmap_model_cover_forces");
  stat = udmap_model_force_table_info(m->err, m->model, &m->cover_points, &m->cover_leaves,
                                      &m->cover_exact);
  if (stat != UDMAP_OK)
    return kernel_failure(m, STAGE_COVER, stat, "udmap_model_force_table_info");
  m->cover_seconds = seconds() - t0;
  if (m->state != InitializationMode) {
    char h[16];
    model_log_category(m, LOG_EVENTS, OK, "force range [%g, %g] N prepared again at harmonics "
                       "%s in %.1f ms (%d exact points, %d leaves, %d of them exact)",
                       m->cover_lo, m->cover_hi, harmonics_text(m, h, sizeof h),
                       1e3 * m->cover_seconds, m->cover_points, m->cover_leaves,
                       m->cover_exact);
  }
  return OK;
}

Status model_prepare(ModelInstance *m, const char *fn) {
  if (!(V(F_E_min) < V(F_E_max))) {
    model_log(m, Error, "%s: F_E_min = %g N must be below F_E_max = %g N", fn, V(F_E_min),
              V(F_E_max));
    return Error;
  }
  const double t0 = seconds();
  Status st = run(m, STAGE_COVER);
  const double t = seconds() - t0;
  if (st >= Discard) return OK; /* the gets report it, as without a range */
  char h[16];
  if (m->analysis.ibpa_deg != 0.0) {
    model_log_category(m, LOG_EVENTS, OK, "%s: initialization took %.1f ms (blade, damper and "
                       "model at an interblade phase of %g deg: its force table is built as the "
                       "forces visit it, not over [%g, %g] N in advance)", fn, 1e3 * t,
                       m->analysis.ibpa_deg, V(F_E_min), V(F_E_max));
    return OK;
  }
  model_log_category(m, LOG_EVENTS, OK, "%s: initialization took %.1f ms (blade, damper, model "
                     "and force range [%g, %g] N at harmonics %s in %.1f ms: %d exact points, "
                     "%d leaves, %d of them exact)", fn, 1e3 * t, m->cover_lo, m->cover_hi,
                     harmonics_text(m, h, sizeof h), 1e3 * m->cover_seconds, m->cover_points,
                     m->cover_leaves, m->cover_exact);
  return OK;
}

static Status compute_point(ModelInstance *m) {
  /* CF (and so the damper) first: a new damper may drop the model; the force range before
   * the point, so that it is prepared in the step that made it stale */
  static const Stage deps[] = {STAGE_CF, STAGE_MODEL, STAGE_COVER};
  Status st = need(m, STAGE_POINT, deps, 3);
  if (st >= Discard) return st;
  if (!m->model) return failure(m, STAGE_POINT, "internal: no model");
  const double f_exc = V(f_exc);
  /* F_E = 0 (e.g. an engine model starting from rest) is the limit F_E -> 0+: the kernel
   * answers at a force far inside the stuck range, where the response is linear in F_E, and
   * the amplitudes are scaled to exactly zero; f_res, k, regime and hcf_ok are the limits. */
  const bool at_rest = V(F_E) == 0.0;
  double F_E = V(F_E);
  if (at_rest) {
    st = run(m, STAGE_LIMIT);
    if (st >= Discard) {
      memcpy(m->stage_message[STAGE_POINT], m->stage_message[STAGE_LIMIT],
             sizeof m->stage_message[STAGE_POINT]);
      return st;
    }
    F_E = m->F_lim > 0.0 ? 1e-12 * m->F_lim : 1e-12;
  }
  memset(&m->point, 0, sizeof m->point);
  m->jump = 0;
  /* harmonics only changes the point: the model keeps its caches (bare blade, the
   * single-harmonic table, the contact element of the layers) */
  int stat = set_harmonics(m);
  if (stat != UDMAP_OK) return kernel_failure(m, STAGE_POINT, stat, "udmap_model_set_harmonics");
  if (f_exc == 0.0) {
    /* a force outside the prepared range is answered as before (exact, the force table
     * built on demand), and said once per range */
    if (!m->exact_points && !m->outside_logged && m->analysis.ibpa_deg == 0.0 &&
        !(F_E >= m->cover_lo && F_E <= m->cover_hi)) {
      m->outside_logged = true;
      model_log_category(m, LOG_EVENTS, OK, "F_E = %g N is outside the prepared force range "
                         "[%g, %g] N: answered exactly, the force table built on demand (a "
                         "longer step; said once until the range changes)", F_E, m->cover_lo,
                         m->cover_hi);
    }
    int before = 0, after = 0, leaves, exact;
    const double t0 = seconds();
    if (!m->exact_points) udmap_model_force_table_info(m->err, m->model, &before, &leaves, &exact);
    stat = udmap_model_backbone(m->err, m->model, 1, &F_E, &m->point);
    if (stat == UDMAP_OK && !m->exact_points) {
      udmap_model_force_table_info(m->err, m->model, &after, &leaves, &exact);
      if (after > before)
        model_log_category(m, LOG_EVENTS, OK, "force table: %d exact points built for F_E = "
                           "%.17g N in %.2f ms", after - before, F_E, 1e3 * (seconds() - t0));
    }
    if (stat != UDMAP_OK) return kernel_failure(m, STAGE_POINT, stat, "udmap_model_backbone");
    stat = udmap_model_backbone_jumps(m->err, m->model, 1, &m->jump);
    if (stat != UDMAP_OK)
      return kernel_failure(m, STAGE_POINT, stat, "udmap_model_backbone_jumps");
  } else {
    if (f_exc < V(f_min) || f_exc > V(f_max))
      return failure(m, STAGE_POINT,
                     "f_exc = %g Hz is outside the band [f_min, f_max] = [%g, %g] Hz "
                     "(0 means at resonance)", f_exc, V(f_min), V(f_max));
    stat = udmap_model_response(m->err, m->model, f_exc, 1, &F_E, &m->point);
    if (stat != UDMAP_OK) return kernel_failure(m, STAGE_POINT, stat, "udmap_model_response");
  }
  udmap_point *p = &m->point;
  if (at_rest && !p->unbounded) {
    p->F_E = 0.0;
    p->gamma_P = p->sigma_a = p->u_E = p->gamma_max = p->sigma_max = 0.0;
    for (int i = 0; i < p->nroots && i < UDMAP_MAX_ROOTS; i++) p->roots[i] = 0.0;
  }
  model_log_category(m, LOG_EVENTS, OK, "response point computed for F_E = %.17g N, f_exc = "
                     "%.17g Hz", V(F_E), f_exc);
  if (p->unbounded) {
    /* zeta = 0 at or above F_lim: no finite response. Report the limits instead of
     * numbers that look like a valid answer. */
    st = run(m, STAGE_F1);
    if (st >= Discard) {
      memcpy(m->stage_message[STAGE_POINT], m->stage_message[STAGE_F1],
             sizeof m->stage_message[STAGE_POINT]);
      return st;
    }
    p->gamma_P = p->sigma_a = p->u_E = p->gamma_max = p->sigma_max = INFINITY;
    p->k_re = p->k_im = 0.0;
    p->f_res = f_exc == 0.0 ? m->f1_bare : f_exc;
    p->regime = 3;
    p->hcf_ok = 0;
    snprintf(m->stage_message[STAGE_POINT], sizeof m->stage_message[STAGE_POINT],
             "%s: F_E = %g N is at or above the limit force with zeta = 0: the response is "
             "unbounded (gamma_P = sigma_a = u_E = +inf, regime = 3)",
             stage_names[STAGE_POINT], V(F_E));
    return Warning;
  }
  const double fields[] = {p->gamma_P, p->f_res, p->sigma_a, p->u_E, p->k_re, p->k_im,
                           p->gamma_max, p->sigma_max};
  const char *names[] = {"gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im", "gamma_max",
                         "sigma_max"};
  for (int i = 0; i < 8; i++)
    if (!isfinite(fields[i]))
      return failure(m, STAGE_POINT, "the kernel returned %s = %g for F_E = %g N", names[i],
                     fields[i], V(F_E));
  return OK;
}

/* ---------------------------------------------------------------- plausibility warnings */

/* Most warnings a check gives (one per kind). */
#define MAX_WARNINGS 8

/* The plausibility warnings (docs/case-files.md, "Plausibility") of the current blade, damper
 * and band, each logged as a Warning (category logStatusWarning) when the previous check did
 * not give its kind: once after the model is built, and again only when a change of the
 * values brings a new one. With a model the check runs on a model of its own (m->probe) over
 * the same blade, damper and settings, so that the caches and the numbers of m->model stay
 * exactly what they would be without it (the stuck peak is a backbone point); the probe is
 * built with the model and coupled to each new damper, as the model is. Without a model (its
 * stage failed) the checks that need none are made. Nothing is refused and no status
 * changes: the stages report their own failures. Not on an instance that cannot log (the
 * finite-difference scratch instance). */
static void check_plausibility(ModelInstance *m) {
  m->plausibility_stale = false;
  if (!m->emit || !m->blade) return;
  int kinds[MAX_WARNINGS], n = 0, stat;
  char texts[MAX_WARNINGS * UDMAP_WARNING_LEN];
  if (m->model && m->damper && (m->done & BIT(STAGE_MODEL))) {
    stat = UDMAP_OK;
    if (!m->probe) stat = udmap_new_model(m->err, m->blade, m->damper, &m->analysis, &m->probe);
    if (stat == UDMAP_OK)
      stat = udmap_model_warnings(m->err, m->probe, MAX_WARNINGS, UDMAP_WARNING_LEN, kinds,
                                  texts, &n);
  } else {
    stat = udmap_plausibility_warnings(m->err, m->blade, m->damper, V(f_min), V(f_max),
                                       MAX_WARNINGS, UDMAP_WARNING_LEN, kinds, texts, &n);
  }
  if (stat != UDMAP_OK) return;
  unsigned now = 0;
  for (int i = 0; i < n && i < MAX_WARNINGS; i++) {
    const unsigned bit = 1u << (kinds[i] & 31);
    if (!(m->plausibility_kinds & bit))
      model_log(m, Warning, "plausibility: %s", texts + (size_t)i * UDMAP_WARNING_LEN);
    now |= bit;
  }
  m->plausibility_kinds = now;
}

static Status run(ModelInstance *m, Stage s) {
  if (m->done & BIT(s)) return m->stage_status[s];
  m->stage_message[s][0] = '\0';
  Status st = Error;
  switch (s) {
    case STAGE_BLADE: st = build_blade(m); break;
    case STAGE_DAMPER: st = build_damper(m); break;
    case STAGE_CF: st = apply_CF(m); break;
    case STAGE_MODEL: st = build_model(m); break;
    case STAGE_LIMIT: st = compute_limit(m); break;
    case STAGE_POINT: st = compute_point(m); break;
    case STAGE_F1: st = compute_f1(m); break;
    case STAGE_COVER: st = compute_cover(m); break;
    case NSTAGES: break;
  }
  m->done |= BIT(s);
  m->stage_status[s] = st;
  m->stage_runs[s]++;
  /* a new blade, damper, CF or model: check again once the outputs' stage has run */
  if (s == STAGE_BLADE || s == STAGE_DAMPER || s == STAGE_CF || s == STAGE_MODEL)
    m->plausibility_stale = true;
  else if (m->plausibility_stale && (s == STAGE_POINT || s == STAGE_LIMIT || s == STAGE_COVER))
    check_plausibility(m);
  return st;
}

const char *model_stage_message(const ModelInstance *m, Stage stage) {
  return m->stage_message[stage];
}

Status model_output(ModelInstance *m, ValueReference vr, double *x, Stage *stage) {
  const VariableInfo *v = &udmap_variables[vr];
  *stage = v->group == GROUP_POINT ? STAGE_POINT : STAGE_LIMIT;
  Status st = run(m, *stage);
  *x = 0.0;
  if (st >= Discard) return st;
  const udmap_point *p = &m->point;
  switch (vr) {
    case vr_gamma_P: *x = p->gamma_P; break;
    case vr_sigma_a: *x = p->sigma_a; break;
    case vr_f_res: *x = p->f_res; break;
    case vr_u_E: *x = p->u_E; break;
    case vr_k_re: *x = p->k_re; break;
    case vr_k_im: *x = p->k_im; break;
    case vr_hcf_ok: *x = p->hcf_ok ? 1.0 : 0.0; break;
    case vr_regime: *x = (double)p->regime; break;
    case vr_F_lim: *x = m->F_lim; break;
    case vr_F_lim_backbone: *x = m->F_lim_backbone; break;
    case vr_gamma_max: *x = p->gamma_max; break;
    case vr_sigma_max: *x = p->sigma_max; break;
    case vr_harmonics_used: *x = (double)p->harmonics; break;
    case vr_jump: *x = m->jump ? 1.0 : 0.0; break;
    case vr_lift_off: *x = m->info.lift_off ? 1.0 : 0.0; break;
    case vr_F_ratio:
      if (m->F_lim > 0.0) *x = V(F_E) / m->F_lim;
      else *x = V(F_E) > 0.0 ? INFINITY : 0.0;
      break;
    default: break;
  }
  return st;
}
