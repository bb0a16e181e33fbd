/*
 * FMI 2.0 co-simulation interface over model.c. Every function checks its instance and the
 * states it may be called in, and every failure is logged through the importer's logger.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2_api.h"
#include "model.h"

#define ALL_STATES (Instantiated | InitializationMode | StepMode | Terminated)
#define MASK_SET (Instantiated | InitializationMode | StepMode)
#define MASK_GET (Instantiated | InitializationMode | StepMode | Terminated)

/* The FMI 2 logger takes a printf format: pass messages with '%' doubled. */
static void escape_percent(const char *message, char *buf, size_t n) {
  size_t j = 0;
  for (size_t i = 0; message[i] && j + 2 < n; i++) {
    if (message[i] == '%') buf[j++] = '%';
    buf[j++] = message[i];
  }
  buf[j] = '\0';
}

static void emit2(ModelInstance *m, Status status, const char *category, const char *message) {
  fmi2CallbackLogger logger = (fmi2CallbackLogger)m->logger;
  if (!logger) return;
  char buf[2048];
  escape_percent(message, buf, sizeof buf);
  logger(m->environment, m->instanceName, (fmi2Status)status, category, buf);
}

#define BEGIN(fn, mask)                                        \
  ModelInstance *m = (ModelInstance *)c;                       \
  if (!m) return fmi2Error;                                    \
  if (!model_allowed(m, fn, mask)) return fmi2Error;           \
  model_log_category(m, LOG_CALLS, OK, "%s", fn);

UDMAP_FMI_EXPORT const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }

UDMAP_FMI_EXPORT const char *fmi2GetVersion(void) { return fmi2Version; }

UDMAP_FMI_EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn,
                                                size_t nCategories,
                                                const fmi2String categories[]) {
  BEGIN("fmi2SetDebugLogging", ALL_STATES)
  return (fmi2Status)model_set_debug_logging(m, loggingOn != fmi2False, nCategories,
                                             categories);
}

UDMAP_FMI_EXPORT fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType,
                                               fmi2String fmuGUID,
                                               fmi2String fmuResourceLocation,
                                               const fmi2CallbackFunctions *functions,
                                               fmi2Boolean visible, fmi2Boolean loggingOn) {
  (void)fmuResourceLocation;
  (void)visible;
  fmi2CallbackLogger logger = functions ? functions->logger : NULL;
  void *env = functions ? functions->componentEnvironment : NULL;
  const char *name = instanceName ? instanceName : "udmap";
  char token[40], msg[256];
  udmap_fmu_token(token, sizeof token);
  msg[0] = '\0';
  if (fmuType != fmi2CoSimulation)
    snprintf(msg, sizeof msg, "fmi2Instantiate: udmap is a co-simulation FMU only (fmuType "
             "must be fmi2CoSimulation)");
  else if (!fmuGUID || strcmp(fmuGUID, token) != 0)
    snprintf(msg, sizeof msg, "fmi2Instantiate: GUID '%s' does not match this binary's '%s'",
             fmuGUID ? fmuGUID : "(null)", token);
  if (msg[0]) {
    char buf[512];
    escape_percent(msg, buf, sizeof buf);
    if (logger) logger(env, name, fmi2Error, "logStatusError", buf);
    return NULL;
  }
  ModelInstance *m = model_new(name, 2, emit2, (void *)logger, env, loggingOn != fmi2False);
  if (!m && logger)
    logger(env, name, fmi2Error, "logStatusError", "fmi2Instantiate: out of memory");
  return m;
}

UDMAP_FMI_EXPORT void fmi2FreeInstance(fmi2Component c) { model_free((ModelInstance *)c); }

UDMAP_FMI_EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                                                fmi2Real tolerance, fmi2Real startTime,
                                                fmi2Boolean stopTimeDefined,
                                                fmi2Real stopTime) {
  BEGIN("fmi2SetupExperiment", Instantiated)
  (void)toleranceDefined;
  (void)tolerance;
  if (!isfinite(startTime) || (stopTimeDefined && !(stopTime >= startTime))) {
    model_log(m, Error, "fmi2SetupExperiment: startTime = %g, stopTime = %g are not a valid "
              "interval", startTime, stopTime);
    return fmi2Error;
  }
  m->value[vr_time] = startTime;
  m->stopTimeDefined = stopTimeDefined != fmi2False;
  m->stopTime = stopTime;
  return fmi2OK;
}

UDMAP_FMI_EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  BEGIN("fmi2EnterInitializationMode", Instantiated)
  m->state = InitializationMode;
  return fmi2OK;
}

UDMAP_FMI_EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  BEGIN("fmi2ExitInitializationMode", InitializationMode)
  m->state = StepMode;
  return fmi2OK;
}

UDMAP_FMI_EXPORT fmi2Status fmi2Terminate(fmi2Component c) {
  BEGIN("fmi2Terminate", StepMode)
  m->state = Terminated;
  return fmi2OK;
}

UDMAP_FMI_EXPORT fmi2Status fmi2Reset(fmi2Component c) {
  BEGIN("fmi2Reset", ALL_STATES)
  model_reset(m);
  return fmi2OK;
}

/* ---------------------------------------------------------------- get and set */

static fmi2Status get_values(fmi2Component c, const char *fn, VariableType type,
                             const fmi2ValueReference vr[], size_t nvr, void *values) {
  BEGIN(fn, MASK_GET)
  if (nvr > 0 && (!vr || !values)) {
    model_log(m, Error, "%s: NULL array argument", fn);
    return fmi2Error;
  }
  Status status = OK;
  unsigned logged = 0;
  for (size_t i = 0; i < nvr; i++) {
    double x;
    Status st = model_get(m, fn, (ValueReference)vr[i], type, &x, &logged);
    if (st > status) status = st;
    switch (type) {
      case REAL: ((fmi2Real *)values)[i] = x; break;
      case INTEGER: ((fmi2Integer *)values)[i] = (fmi2Integer)x; break;
      case BOOLEAN: ((fmi2Boolean *)values)[i] = x != 0.0 ? fmi2True : fmi2False; break;
    }
  }
  return (fmi2Status)status;
}

/* All values are checked before any is taken: a rejected call changes nothing. */
static fmi2Status set_values(fmi2Component c, const char *fn, VariableType type,
                             const fmi2ValueReference vr[], size_t nvr, const void *values) {
  BEGIN(fn, MASK_SET)
  if (nvr > 0 && (!vr || !values)) {
    model_log(m, Error, "%s: NULL array argument", fn);
    return fmi2Error;
  }
  for (int apply = 0; apply < 2; apply++) {
    Status status = OK;
    for (size_t i = 0; i < nvr; i++) {
      double x = 0.0;
      switch (type) {
        case REAL: x = ((const fmi2Real *)values)[i]; break;
        case INTEGER: x = ((const fmi2Integer *)values)[i]; break;
        case BOOLEAN: x = ((const fmi2Boolean *)values)[i] != fmi2False ? 1.0 : 0.0; break;
      }
      Status st = model_set(m, fn, (ValueReference)vr[i], type, x, apply != 0);
      if (st > status) status = st;
    }
    if (status != OK) return (fmi2Status)status;
  }
  return fmi2OK;
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, fmi2Real value[]) {
  return get_values(c, "fmi2GetReal", REAL, vr, nvr, value);
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[],
                                           size_t nvr, fmi2Integer value[]) {
  return get_values(c, "fmi2GetInteger", INTEGER, vr, nvr, value);
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                                           size_t nvr, fmi2Boolean value[]) {
  return get_values(c, "fmi2GetBoolean", BOOLEAN, vr, nvr, value);
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[],
                                          size_t nvr, fmi2String value[]) {
  BEGIN("fmi2GetString", MASK_GET)
  (void)vr;
  (void)value;
  if (nvr == 0) return fmi2OK;
  model_log(m, Error, "fmi2GetString: the FMU has no String variables");
  return fmi2Error;
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Real value[]) {
  return set_values(c, "fmi2SetReal", REAL, vr, nvr, value);
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[],
                                           size_t nvr, const fmi2Integer value[]) {
  return set_values(c, "fmi2SetInteger", INTEGER, vr, nvr, value);
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                                           size_t nvr, const fmi2Boolean value[]) {
  return set_values(c, "fmi2SetBoolean", BOOLEAN, vr, nvr, value);
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[],
                                          size_t nvr, const fmi2String value[]) {
  BEGIN("fmi2SetString", MASK_SET)
  (void)vr;
  (void)value;
  if (nvr == 0) return fmi2OK;
  model_log(m, Error, "fmi2SetString: the FMU has no String variables");
  return fmi2Error;
}

/* ---------------------------------------------------------------- FMU state */

UDMAP_FMI_EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
  BEGIN("fmi2GetFMUstate", ALL_STATES)
  if (!FMUstate) {
    model_log(m, Error, "fmi2GetFMUstate: FMUstate is NULL");
    return fmi2Error;
  }
  ModelSnapshot *s = model_snapshot(m, (ModelSnapshot *)*FMUstate);
  if (!s) return fmi2Error;
  *FMUstate = s;
  return fmi2OK;
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
  BEGIN("fmi2SetFMUstate", ALL_STATES)
  return (fmi2Status)model_restore(m, "fmi2SetFMUstate", (const ModelSnapshot *)FMUstate);
}

UDMAP_FMI_EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
  BEGIN("fmi2FreeFMUstate", ALL_STATES)
  if (FMUstate) {
    free(*FMUstate);
    *FMUstate = NULL;
  }
  return fmi2OK;
}

UDMAP_FMI_EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate,
                                                       size_t *size) {
  BEGIN("fmi2SerializedFMUstateSize", ALL_STATES)
  (void)FMUstate;
  if (!size) {
    model_log(m, Error, "fmi2SerializedFMUstateSize: size is NULL");
    return fmi2Error;
  }
  *size = sizeof(ModelSnapshot);
  return fmi2OK;
}

UDMAP_FMI_EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                                  fmi2Byte serializedState[], size_t size) {
  BEGIN("fmi2SerializeFMUstate", ALL_STATES)
  if (!FMUstate || !serializedState || size != sizeof(ModelSnapshot)) {
    model_log(m, Error, "fmi2SerializeFMUstate: needs a state and a buffer of %zu bytes "
              "(got %zu)", sizeof(ModelSnapshot), size);
    return fmi2Error;
  }
  memcpy(serializedState, FMUstate, sizeof(ModelSnapshot));
  return fmi2OK;
}

UDMAP_FMI_EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c,
                                                    const fmi2Byte serializedState[],
                                                    size_t size, fmi2FMUstate *FMUstate) {
  BEGIN("fmi2DeSerializeFMUstate", ALL_STATES)
  if (!FMUstate) {
    model_log(m, Error, "fmi2DeSerializeFMUstate: FMUstate is NULL");
    return fmi2Error;
  }
  Status st = model_check_snapshot(m, "fmi2DeSerializeFMUstate", serializedState, size);
  if (st != OK) return (fmi2Status)st;
  ModelSnapshot *s = *FMUstate ? (ModelSnapshot *)*FMUstate : malloc(sizeof *s);
  if (!s) {
    model_log(m, Error, "fmi2DeSerializeFMUstate: out of memory");
    return fmi2Error;
  }
  memcpy(s, serializedState, sizeof *s);
  *FMUstate = s;
  return fmi2OK;
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetDirectionalDerivative(
    fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
    const fmi2ValueReference vKnown_ref[], size_t nKnown, const fmi2Real dvKnown[],
    fmi2Real dvUnknown[]) {
  BEGIN("fmi2GetDirectionalDerivative", ALL_STATES)
  (void)vUnknown_ref, (void)nUnknown, (void)vKnown_ref, (void)nKnown, (void)dvKnown,
      (void)dvUnknown;
  model_log(m, Error, "fmi2GetDirectionalDerivative: not provided by this FMU");
  return fmi2Error;
}

/* ---------------------------------------------------------------- co-simulation */

UDMAP_FMI_EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c,
                                                        const fmi2ValueReference vr[],
                                                        size_t nvr, const fmi2Integer order[],
                                                        const fmi2Real value[]) {
  BEGIN("fmi2SetRealInputDerivatives", MASK_SET)
  (void)vr, (void)order, (void)value;
  if (nvr == 0) return fmi2OK;
  model_log(m, Error, "fmi2SetRealInputDerivatives: the FMU cannot interpolate inputs");
  return fmi2Error;
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c,
                                                         const fmi2ValueReference vr[],
                                                         size_t nvr, const fmi2Integer order[],
                                                         fmi2Real value[]) {
  BEGIN("fmi2GetRealOutputDerivatives", MASK_GET)
  (void)vr, (void)order, (void)value;
  if (nvr == 0) return fmi2OK;
  model_log(m, Error, "fmi2GetRealOutputDerivatives: the FMU provides no output derivatives");
  return fmi2Error;
}

UDMAP_FMI_EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                                       fmi2Real communicationStepSize,
                                       fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
  BEGIN("fmi2DoStep", StepMode)
  (void)noSetFMUStatePriorToCurrentPoint;
  return (fmi2Status)model_do_step(m, "fmi2DoStep", currentCommunicationPoint,
                                   communicationStepSize);
}

UDMAP_FMI_EXPORT fmi2Status fmi2CancelStep(fmi2Component c) {
  BEGIN("fmi2CancelStep", StepMode)
  model_log(m, Error, "fmi2CancelStep: no step is pending (fmi2DoStep never returns "
            "fmi2Pending)");
  return fmi2Error;
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s,
                                          fmi2Status *value) {
  BEGIN("fmi2GetStatus", StepMode | Terminated)
  if (s == fmi2DoStepStatus && value) {
    *value = fmi2OK;
    return fmi2OK;
  }
  model_log(m, Discard, "fmi2GetStatus: status kind %d is not available", (int)s);
  return fmi2Discard;
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s,
                                              fmi2Real *value) {
  BEGIN("fmi2GetRealStatus", StepMode | Terminated)
  if (s == fmi2LastSuccessfulTime && value) {
    *value = m->value[vr_time];
    return fmi2OK;
  }
  model_log(m, Discard, "fmi2GetRealStatus: status kind %d is not available", (int)s);
  return fmi2Discard;
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s,
                                                 fmi2Integer *value) {
  BEGIN("fmi2GetIntegerStatus", StepMode | Terminated)
  (void)value;
  model_log(m, Discard, "fmi2GetIntegerStatus: status kind %d is not available", (int)s);
  return fmi2Discard;
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s,
                                                 fmi2Boolean *value) {
  BEGIN("fmi2GetBooleanStatus", StepMode | Terminated)
  if (s == fmi2Terminated && value) {
    *value = fmi2False;
    return fmi2OK;
  }
  model_log(m, Discard, "fmi2GetBooleanStatus: status kind %d is not available", (int)s);
  return fmi2Discard;
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s,
                                                fmi2String *value) {
  BEGIN("fmi2GetStringStatus", StepMode | Terminated)
  (void)value;
  model_log(m, Discard, "fmi2GetStringStatus: status kind %d is not available", (int)s);
  return fmi2Discard;
}
