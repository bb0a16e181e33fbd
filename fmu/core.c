/*
 * The FMI core shared by FMI 2.0 and FMI 3.0, model exchange and co-simulation (core.h).
 * Every function checks the states it may be called in and logs every failure through the
 * importer's logger; the adapters only translate signatures.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core.h"

#define MASK_INIT_OR_RUN (InitializationMode | StepMode | EventMode | ContinuousTimeMode)

ModelInstance *core_instantiate(const char *fn, const char *instanceName, int fmiVersion,
                                InterfaceType type, const char *token, const char *resources,
                                LogEmitter emit, void *logger, void *environment,
                                bool loggingOn) {
  ModelInstance *m = model_new(instanceName ? instanceName : "udmap", fmiVersion, type, emit,
                               logger, environment, loggingOn);
  if (!m) return NULL; /* out of memory: nothing to log through */
  char msg[CASE_PATH_MAX + 256];
  CaseConfig *config = case_read(resources, msg, sizeof msg); /* an FMU of `udmap fmu` */
  if (!config && msg[0]) {
    model_log(m, Error, "%s: bad case in the resources: %s", fn, msg);
    model_free(m);
    return NULL;
  }
  if (config) model_set_case(m, config, true);
  if (!token || strcmp(token, m->token) != 0) {
    model_log(m, Error, "%s: %s '%s' does not match this FMU's '%s'", fn,
              fmiVersion == 2 ? "GUID" : "instantiation token", token ? token : "(null)",
              m->token);
    model_free(m);
    return NULL;
  }
  return m;
}

bool core_begin(ModelInstance *m, const char *fn, unsigned mask) {
  if (!model_allowed(m, fn, mask)) return false;
  model_log_category(m, LOG_CALLS, OK, "%s", fn);
  return true;
}

Status core_set_debug_logging(ModelInstance *m, const char *fn, bool on, size_t n,
                              const char *const names[]) {
  if (!core_begin(m, fn, CORE_ALL_STATES)) return Error;
  return model_set_debug_logging(m, on, n, names);
}

/* ---------------------------------------------------------------- modes */

Status core_setup_experiment(ModelInstance *m, const char *fn, unsigned mask, double startTime,
                             bool stopTimeDefined, double stopTime) {
  if (!core_begin(m, fn, mask)) return Error;
  if (!isfinite(startTime) || (stopTimeDefined && !(stopTime >= startTime))) {
    model_log(m, Error, "%s: startTime = %g, stopTime = %g are not a valid interval", fn,
              startTime, stopTime);
    return Error;
  }
  m->value[vr_time] = startTime;
  m->stopTimeDefined = stopTimeDefined;
  m->stopTime = stopTime;
  return OK;
}

Status core_enter_initialization_mode(ModelInstance *m, const char *fn) {
  if (!core_begin(m, fn, Instantiated)) return Error;
  m->state = InitializationMode;
  return OK;
}

Status core_exit_initialization_mode(ModelInstance *m, const char *fn) {
  if (!core_begin(m, fn, InitializationMode)) return Error;
  /* the kernel objects and the force range [F_E_min, F_E_max], so that no later step with
   * F_E in the range builds anything */
  if (model_prepare(m, fn) != OK) return Error;
  m->state = m->type == ModelExchange ? EventMode : StepMode;
  return OK;
}

Status core_terminate(ModelInstance *m, const char *fn) {
  if (!core_begin(m, fn, StepMode | EventMode | ContinuousTimeMode)) return Error;
  m->state = Terminated;
  return OK;
}

Status core_reset(ModelInstance *m, const char *fn) {
  if (!core_begin(m, fn, CORE_ALL_STATES)) return Error;
  model_reset(m);
  return OK;
}

/* ---------------------------------------------------------------- get and set */

static Status check_arrays(ModelInstance *m, const char *fn, const unsigned vr[], size_t nvr,
                           const void *values, size_t nValues) {
  if (nValues != nvr || (nvr > 0 && (!vr || !values))) {
    model_log(m, Error, "%s: %zu values for %zu scalar variables (or a NULL array)", fn,
              nValues, nvr);
    return Error;
  }
  return OK;
}

Status core_get(ModelInstance *m, const char *fn, VariableType type, ElementType elem,
                const unsigned vr[], size_t nvr, void *values, size_t nValues) {
  if (!core_begin(m, fn, CORE_MASK_GET)) return Error;
  if (check_arrays(m, fn, vr, nvr, values, nValues) != OK) return Error;
  Status status = OK;
  unsigned logged = 0;
  for (size_t i = 0; i < nvr; i++) {
    double x;
    Status st = model_get(m, fn, (ValueReference)vr[i], type, &x, &logged);
    if (st > status) status = st;
    switch (elem) {
      case ELEM_FLOAT64: ((double *)values)[i] = x; break;
      case ELEM_INT: ((int *)values)[i] = (int)x; break;
      case ELEM_BOOL: ((bool *)values)[i] = x != 0.0; break;
    }
  }
  return status;
}

Status core_set(ModelInstance *m, const char *fn, VariableType type, ElementType elem,
                const unsigned vr[], size_t nvr, const void *values, size_t nValues) {
  if (!core_begin(m, fn, CORE_MASK_SET)) return Error;
  if (check_arrays(m, fn, vr, nvr, values, nValues) != OK) return Error;
  for (int apply = 0; apply < 2; apply++) {
    Status status = OK;
    for (size_t i = 0; i < nvr; i++) {
      double x = 0.0;
      switch (elem) {
        case ELEM_FLOAT64: x = ((const double *)values)[i]; break;
        case ELEM_INT: x = ((const int *)values)[i]; break;
        case ELEM_BOOL: x = ((const bool *)values)[i] ? 1.0 : 0.0; break;
      }
      if (type == BOOLEAN && elem == ELEM_INT) x = x != 0.0 ? 1.0 : 0.0;
      Status st = model_set(m, fn, (ValueReference)vr[i], type, x, apply != 0);
      if (st > status) status = st;
    }
    if (status != OK) return status;
  }
  return OK;
}

Status core_no_variables(ModelInstance *m, const char *fn, bool set, size_t nvr) {
  if (!core_begin(m, fn, set ? CORE_MASK_SET : CORE_MASK_GET)) return Error;
  if (nvr == 0) return OK;
  model_log(m, Error, "%s: the FMU has no variables of this type", fn);
  return Error;
}

Status core_not_provided(ModelInstance *m, const char *fn, const char *why) {
  if (!core_begin(m, fn, CORE_ALL_STATES)) return Error;
  model_log(m, Error, "%s: %s", fn, why);
  return Error;
}

/* ---------------------------------------------------------------- FMU state */

Status core_get_state(ModelInstance *m, const char *fn, void **state) {
  if (!core_begin(m, fn, CORE_ALL_STATES)) return Error;
  if (!state) {
    model_log(m, Error, "%s: the state pointer is NULL", fn);
    return Error;
  }
  ModelSnapshot *s = model_snapshot(m, (ModelSnapshot *)*state);
  if (!s) return Error;
  *state = s;
  return OK;
}

Status core_set_state(ModelInstance *m, const char *fn, const void *state) {
  if (!core_begin(m, fn, CORE_ALL_STATES)) return Error;
  return model_restore(m, fn, (const ModelSnapshot *)state);
}

Status core_free_state(ModelInstance *m, const char *fn, void **state) {
  if (!core_begin(m, fn, CORE_ALL_STATES)) return Error;
  if (state) {
    free(*state);
    *state = NULL;
  }
  return OK;
}

Status core_serialized_state_size(ModelInstance *m, const char *fn, size_t *size) {
  if (!core_begin(m, fn, CORE_ALL_STATES)) return Error;
  if (!size) {
    model_log(m, Error, "%s: size is NULL", fn);
    return Error;
  }
  *size = sizeof(ModelSnapshot);
  return OK;
}

Status core_serialize_state(ModelInstance *m, const char *fn, const void *state, void *buffer,
                            size_t size) {
  if (!core_begin(m, fn, CORE_ALL_STATES)) return Error;
  if (!state || !buffer || size != sizeof(ModelSnapshot)) {
    model_log(m, Error, "%s: needs a state and a buffer of %zu bytes (got %zu)", fn,
              sizeof(ModelSnapshot), size);
    return Error;
  }
  memcpy(buffer, state, sizeof(ModelSnapshot));
  return OK;
}

Status core_deserialize_state(ModelInstance *m, const char *fn, const void *buffer, size_t size,
                              void **state) {
  if (!core_begin(m, fn, CORE_ALL_STATES)) return Error;
  if (!state) {
    model_log(m, Error, "%s: the state pointer is NULL", fn);
    return Error;
  }
  Status st = model_check_snapshot(m, fn, buffer, size);
  if (st != OK) return st;
  ModelSnapshot *s = *state ? (ModelSnapshot *)*state : malloc(sizeof *s);
  if (!s) {
    model_log(m, Error, "%s: out of memory", fn);
    return Error;
  }
  memcpy(s, buffer, sizeof *s);
  *state = s;
  return OK;
}

/* ---------------------------------------------------------------- derivatives */

Status core_directional_derivative(ModelInstance *m, const char *fn, const unsigned unknowns[],
                                   size_t nUnknowns, const unsigned knowns[], size_t nKnowns,
                                   const double seed[], size_t nSeed, double sensitivity[],
                                   size_t nSensitivity) {
  if (!core_begin(m, fn, MASK_INIT_OR_RUN | Terminated)) return Error;
  if (nSeed != nKnowns || nSensitivity != nUnknowns || (nUnknowns && (!unknowns || !sensitivity))
      || (nKnowns && (!knowns || !seed))) {
    model_log(m, Error, "%s: %zu seeds for %zu knowns and %zu sensitivities for %zu unknowns "
              "(or a NULL array)", fn, nSeed, nKnowns, nSensitivity, nUnknowns);
    return Error;
  }
  return model_directional_derivative(m, fn, unknowns, nUnknowns, knowns, nKnowns, seed,
                                      sensitivity);
}

/* ---------------------------------------------------------------- co-simulation */

Status core_do_step(ModelInstance *m, const char *fn, double t, double h) {
  if (!core_begin(m, fn, StepMode)) return Error;
  return model_do_step(m, fn, t, h);
}

/* ---------------------------------------------------------------- model exchange */

Status core_enter_event_mode(ModelInstance *m, const char *fn) {
  if (!core_begin(m, fn, CORE_MASK_ME_RUN)) return Error;
  m->state = EventMode;
  return OK;
}

Status core_update_discrete_states(ModelInstance *m, const char *fn, EventInfo *info) {
  if (!core_begin(m, fn, EventMode)) return Error;
  /* no discrete states: the outputs are algebraic in the inputs, nothing to iterate */
  if (info) memset(info, 0, sizeof *info);
  return OK;
}

Status core_enter_continuous_time_mode(ModelInstance *m, const char *fn) {
  if (!core_begin(m, fn, EventMode)) return Error;
  m->state = ContinuousTimeMode;
  return OK;
}

Status core_completed_integrator_step(ModelInstance *m, const char *fn, bool *enterEventMode,
                                      bool *terminateSimulation) {
  if (!core_begin(m, fn, ContinuousTimeMode)) return Error;
  if (enterEventMode) *enterEventMode = false;
  if (terminateSimulation) *terminateSimulation = false;
  return OK;
}

Status core_set_time(ModelInstance *m, const char *fn, double time) {
  if (!core_begin(m, fn, CORE_MASK_ME_RUN)) return Error;
  if (!isfinite(time)) {
    model_log(m, Error, "%s: time = %g is not finite", fn, time);
    return Error;
  }
  m->value[vr_time] = time;
  return OK;
}

Status core_empty_vector(ModelInstance *m, const char *fn, unsigned mask, const void *array,
                         size_t n) {
  (void)array;
  if (!core_begin(m, fn, mask)) return Error;
  if (n == 0) return OK;
  model_log(m, Error, "%s: the FMU has no continuous states and no event indicators (n = %zu, "
            "not 0)", fn, n);
  return Error;
}
