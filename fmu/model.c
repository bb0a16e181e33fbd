/*
 * udmap FMU model: values, state machine, logging and snapshots; the staged lazy evaluation
 * of the outputs over the kernel's C API is in stages.c. The FMI 2 and FMI 3 layers (fmi2Functions.c, fmi3Functions.c) are
 * thin adapters over these functions, so both FMUs compute the same numbers.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model.h"

#define BIT(stage) (1u << (stage))
#define V(name) (m->value[vr_##name])

static const char *const category_names[] = {"logStatusWarning", "logStatusDiscard",
                                             "logStatusError", "logEvents", "logCalls"};

static const char *const type_names[] = {"Real/Float64", "Integer/Int32", "Boolean"};
static const char *const causality_names[] = {"the independent variable", "an input",
                                              "a parameter", "an output"};

/* ---------------------------------------------------------------- logging */

static void vlog(ModelInstance *m, unsigned category, Status status, const char *fmt,
                 va_list ap) {
  if (!(m->logMask & category) || !m->emit) return;
  char buf[1024];
  vsnprintf(buf, sizeof buf, fmt, ap);
  int index = 0;
  while (index < 4 && !(category & (1u << index))) index++;
  m->emit(m, status, category_names[index], buf);
}

static unsigned category_of(Status status) {
  switch (status) {
    case OK: return LOG_EVENTS;
    case Warning: return LOG_WARNING;
    case Discard: return LOG_DISCARD;
    default: return LOG_ERROR;
  }
}

void model_log(ModelInstance *m, Status status, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vlog(m, category_of(status), status, fmt, ap);
  va_end(ap);
}

void model_log_category(ModelInstance *m, unsigned category, Status status, const char *fmt,
                        ...) {
  va_list ap;
  va_start(ap, fmt);
  vlog(m, category, status, fmt, ap);
  va_end(ap);
}

Status model_set_debug_logging(ModelInstance *m, bool on, size_t n, const char *const names[]) {
  if (n == 0) {
    m->logMask = on ? LOG_ALL : LOG_DEFAULT;
    return OK;
  }
  for (size_t i = 0; i < n; i++) {
    unsigned bit = 0;
    for (unsigned k = 0; k < sizeof category_names / sizeof category_names[0]; k++)
      if (names[i] && strcmp(names[i], category_names[k]) == 0) bit = 1u << k;
    if (!bit) {
      model_log(m, Error, "SetDebugLogging: unknown log category '%s'",
                names[i] ? names[i] : "(null)");
      return Error;
    }
    if (on) m->logMask |= bit;
    else m->logMask &= ~bit;
  }
  return OK;
}

static const char *state_name(const ModelInstance *m) {
  switch (m->state) {
    case StartAndEnd: return "StartAndEnd";
    case Instantiated: return "Instantiated";
    case InitializationMode: return "InitializationMode";
    case StepMode: return m->fmiVersion == 2 ? "slaveInitialized (step complete)" : "StepMode";
    case EventMode: return "EventMode";
    case ContinuousTimeMode: return "ContinuousTimeMode";
    case Terminated: return "Terminated";
  }
  return "unknown";
}

bool model_allowed(ModelInstance *m, const char *fn, unsigned mask) {
  if (m->state & mask) return true;
  model_log(m, Error, "%s: not allowed in state %s", fn, state_name(m));
  return false;
}

/* ---------------------------------------------------------------- lifecycle */

static void free_kernel_objects(ModelInstance *m) {
  /* the models borrow blade and damper: release them first */
  udmap_delete_model(&m->probe);
  udmap_delete_model(&m->model);
  udmap_delete_damper(&m->damper);
  udmap_delete_blade(&m->blade);
}

ModelInstance *model_new(const char *instanceName, int fmiVersion, InterfaceType type,
                         LogEmitter emit, void *logger, void *environment, bool loggingOn) {
  ModelInstance *m = calloc(1, sizeof *m);
  if (!m) return NULL;
  m->fmiVersion = fmiVersion;
  m->type = type;
  m->emit = emit;
  m->logger = logger;
  m->environment = environment;
  m->logMask = loggingOn ? LOG_ALL : LOG_DEFAULT;
  m->instanceName = strdup(instanceName ? instanceName : "");
  udmap_fmu_token(m->token, sizeof m->token);
  m->err = udmap_new_error();
  if (!m->instanceName || !m->err) {
    model_free(m);
    return NULL;
  }
  model_reset(m);
  return m;
}

void model_free(ModelInstance *m) {
  if (!m) return;
  model_free(m->scratch);
  free_kernel_objects(m);
  if (m->owns_config) case_free(m->config);
  udmap_delete_error(&m->err);
  free(m->instanceName);
  free(m);
}

double model_start_value(const ModelInstance *m, int vr) {
  return m->config ? m->config->start[vr] : udmap_variables[vr].start;
}

bool model_has(const ModelInstance *m, unsigned vr) {
  return vr < UDMAP_NVARS && (!m->config || m->config->present[vr]);
}

void model_set_case(ModelInstance *m, CaseConfig *config, bool owns) {
  if (m->owns_config) case_free(m->config);
  m->config = config;
  m->owns_config = owns;
  if (config) memcpy(m->token, config->token, sizeof m->token);
  model_reset(m);
}

void model_reset(ModelInstance *m) {
  free_kernel_objects(m);
  for (int i = 0; i < UDMAP_NVARS; i++)
    m->value[i] = udmap_variables[i].causality == OUTPUT ? 0.0 : model_start_value(m, i);
  m->done = 0;
  m->damper_CF = NAN;
  m->outside_logged = false;
  m->plausibility_kinds = 0;
  m->plausibility_stale = false;
  m->state = Instantiated;
  m->stopTimeDefined = false;
  m->stopTime = 0.0;
}

/* ---------------------------------------------------------------- set and get */

/* x as the Python package writes numbers in its messages (udmap.case.fmt_number): 15
 * significant digits, exponent form outside [1e-4, 1e5) without '+' or leading zeros. */
static void fmt_number(char *buf, size_t n, double x) {
  if (isnan(x)) {
    snprintf(buf, n, "NaN");
  } else if (isinf(x)) {
    snprintf(buf, n, x > 0 ? "inf" : "-inf");
  } else if (x != 0.0 && !(fabs(x) >= 1e-4 && fabs(x) < 1e5)) {
    char mant[48];
    snprintf(mant, sizeof mant, "%.14e", x);
    char *e = strchr(mant, 'e');
    int exp10 = e ? atoi(e + 1) : 0;
    if (e) *e = '\0';
    size_t len = strlen(mant);
    while (len > 0 && mant[len - 1] == '0') mant[--len] = '\0';
    if (len > 0 && mant[len - 1] == '.') mant[--len] = '\0';
    snprintf(buf, n, "%se%d", mant, exp10);
  } else {
    snprintf(buf, n, "%.15g", x);
  }
}

static bool valid_value(const VariableInfo *v, double x) {
  if (!isfinite(x)) return false;
  if (v->type == BOOLEAN) return x == 0.0 || x == 1.0;
  if (v->type == INTEGER && x != floor(x)) return false;
  if ((v->flags & POSITIVE) && !(x > 0.0)) return false;
  if ((v->flags & OPEN) ? !(x > v->min && x < v->max) : (x < v->min || x > v->max)) return false;
  return !((v->flags & EVEN) && fmod(x, 2.0) != 0.0);
}

/* The message of the case-file validation (udmap.case): "E must be in [1e6, 1e13] Pa, got
 * 1e300", with the FMU's variable name for the case file's dotted path. */
static void invalid_message(const VariableInfo *v, double x, char *buf, size_t n) {
  char lo[48], hi[48], got[48];
  fmt_number(lo, sizeof lo, v->min);
  fmt_number(hi, sizeof hi, v->max);
  fmt_number(got, sizeof got, x);
  if (v->type == BOOLEAN) {
    snprintf(buf, n, "%s must be 0 or 1, got %s", v->name, got);
    return;
  }
  const char *what = v->type != INTEGER ? "" : v->flags & EVEN ? "an even integer " : "an integer ";
  bool open_lo = (v->flags & (OPEN | POSITIVE)) || isinf(v->min);
  bool open_hi = (v->flags & OPEN) || isinf(v->max);
  snprintf(buf, n, "%s must be %sin %c%s, %s%c%s%s, got %s", v->name, what, open_lo ? '(' : '[',
           lo, hi, open_hi ? ')' : ']', v->unit[0] ? " " : "", v->unit, got);
}

static Status check_vr(ModelInstance *m, const char *fn, ValueReference vr, VariableType type) {
  if (!model_has(m, (unsigned)vr)) {
    model_log(m, Error, "%s: unknown value reference %u", fn, (unsigned)vr);
    return Error;
  }
  const VariableInfo *v = &udmap_variables[vr];
  if (v->type != type) {
    model_log(m, Error, "%s: variable %s (value reference %u) is of type %s, not %s", fn,
              v->name, (unsigned)vr, type_names[v->type], type_names[type]);
    return Error;
  }
  return OK;
}

Status model_set(ModelInstance *m, const char *fn, ValueReference vr, VariableType type,
                 double x, bool apply) {
  Status st = check_vr(m, fn, vr, type);
  if (st != OK) return st;
  const VariableInfo *v = &udmap_variables[vr];
  if (v->causality != INPUT && v->causality != PARAMETER) {
    model_log(m, Error, "%s: %s is %s and cannot be set", fn, v->name,
              causality_names[v->causality]);
    return Error;
  }
  if (!valid_value(v, x)) {  /* an FMI error; the instance keeps its value and stays usable */
    char why[256], keep[48];
    invalid_message(v, x, why, sizeof why);
    fmt_number(keep, sizeof keep, m->value[vr]);
    model_log(m, Error, "%s: %s; %s keeps %s", fn, why, v->name, keep);
    return Error;
  }
  if (apply && m->value[vr] != x) {
    m->value[vr] = x;
    model_invalidate(m, v->group);
  }
  return OK;
}

void model_copy_values(ModelInstance *m, const ModelInstance *src) {
  for (int i = 0; i < UDMAP_NVARS; i++) {
    const VariableInfo *v = &udmap_variables[i];
    if (v->causality != INPUT && v->causality != PARAMETER) continue;
    if (m->value[i] != src->value[i]) {
      m->value[i] = src->value[i];
      model_invalidate(m, v->group);
    }
  }
}


Status model_get(ModelInstance *m, const char *fn, ValueReference vr, VariableType type,
                 double *value, unsigned *logged) {
  Status st = check_vr(m, fn, vr, type);
  if (st != OK) {
    *value = 0.0;
    return st;
  }
  const VariableInfo *v = &udmap_variables[vr];
  if (v->causality != OUTPUT) {
    *value = m->value[vr];
    return OK;
  }
  Stage stage;
  st = model_output(m, vr, value, &stage);
  if (st != OK && !(*logged & BIT(stage))) {
    *logged |= BIT(stage);
    model_log(m, st, "%s: %s", fn, m->stage_message[stage]);
  }
  if (st == OK && !isfinite(*value)) {
    /* e.g. F_E / F_lim overflowing for absurd inputs: never a non-finite OK value */
    model_log(m, Error, "%s: %s = %g is not finite (F_E = %g N, F_lim = %g N)", fn, v->name,
              *value, V(F_E), m->F_lim);
    return Error;
  }
  return st;
}

/* ---------------------------------------------------------------- time */

Status model_do_step(ModelInstance *m, const char *fn, double t, double h) {
  const double now = m->value[vr_time];
  if (!isfinite(t) || !isfinite(h) || h < 0.0) {
    model_log(m, Error, "%s: currentCommunicationPoint = %g and communicationStepSize = %g "
              "must be finite, the step size >= 0", fn, t, h);
    return Error;
  }
  const double tol = 1e-9 * fmax(1.0, fabs(now));
  if (fabs(t - now) > tol) {
    model_log(m, Error, "%s: currentCommunicationPoint = %.17g differs from the FMU time "
              "%.17g", fn, t, now);
    return Error;
  }
  if (m->stopTimeDefined && t + h > m->stopTime + 1e-9 * fmax(1.0, fabs(m->stopTime))) {
    model_log(m, Error, "%s: a step to %.17g goes beyond the stop time %.17g", fn, t + h,
              m->stopTime);
    return Error;
  }
  m->value[vr_time] = t + h;
  return OK;
}

/* ---------------------------------------------------------------- FMU state */

#define SNAPSHOT_MAGIC 0x75646d6170464d55ULL /* "udmapFMU" */

ModelSnapshot *model_snapshot(ModelInstance *m, ModelSnapshot *reuse) {
  ModelSnapshot *s = reuse ? reuse : malloc(sizeof *s);
  if (!s) {
    model_log(m, Error, "GetFMUState: out of memory");
    return NULL;
  }
  memset(s, 0, sizeof *s);
  s->magic = SNAPSHOT_MAGIC;
  s->size = sizeof *s;
  memcpy(s->token, m->token, sizeof s->token);
  memcpy(s->value, m->value, sizeof s->value);
  return s;
}

Status model_check_snapshot(ModelInstance *m, const char *fn, const void *data, size_t size) {
  ModelSnapshot s;
  char token[40] = {0};
  if (!data || size != sizeof s) {
    model_log(m, Error, "%s: a serialized state has %zu bytes, not %zu", fn, size, sizeof s);
    return Error;
  }
  memcpy(&s, data, sizeof s);
  memcpy(token, m->token, sizeof token);
  if (s.magic != SNAPSHOT_MAGIC || s.size != sizeof s ||
      memcmp(s.token, token, sizeof token) != 0) {
    model_log(m, Error, "%s: the state was not saved by this FMU (magic, size or token "
              "differ)", fn);
    return Error;
  }
  for (int i = 0; i < UDMAP_NVARS; i++) {
    const VariableInfo *v = &udmap_variables[i];
    if (v->causality != INPUT && v->causality != PARAMETER) continue;
    if (!valid_value(v, s.value[i])) {
      char why[256];
      invalid_message(v, s.value[i], why, sizeof why);
      model_log(m, Error, "%s: the state holds an invalid value: %s", fn, why);
      return Error;
    }
  }
  return OK;
}

Status model_restore(ModelInstance *m, const char *fn, const ModelSnapshot *s) {
  Status st = model_check_snapshot(m, fn, s, s ? (size_t)s->size : 0);
  if (st != OK) return st;
  ModelInstance src; /* only its values are read */
  memcpy(src.value, s->value, sizeof src.value);
  model_copy_values(m, &src);
  m->value[vr_time] = s->value[vr_time];
  return OK;
}
