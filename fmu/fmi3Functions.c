/*
 * FMI 3.0 co-simulation interface over model.c. Every function checks its instance and the
 * states it may be called in, and every failure is logged through the importer's logger.
 * Model exchange, scheduled execution, event mode, clocks and configuration mode are not
 * provided; their functions log an error and return fmi3Error.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3_api.h"
#include "model.h"

#define ALL_STATES (Instantiated | InitializationMode | StepMode | Terminated)
#define MASK_SET (Instantiated | InitializationMode | StepMode)
#define MASK_GET (Instantiated | InitializationMode | StepMode | Terminated)

static void emit3(ModelInstance *m, Status status, const char *category, const char *message) {
  fmi3LogMessageCallback logger = (fmi3LogMessageCallback)m->logger;
  if (logger) logger(m->environment, (fmi3Status)status, category, message);
}

#define BEGIN(fn, mask)                                        \
  ModelInstance *m = (ModelInstance *)instance;                \
  if (!m) return fmi3Error;                                    \
  if (!model_allowed(m, fn, mask)) return fmi3Error;           \
  model_log_category(m, LOG_CALLS, OK, "%s", fn);

#define NOT_PROVIDED(fn, what)                                 \
  {                                                            \
    BEGIN(fn, ALL_STATES)                                      \
    model_log(m, Error, "%s: %s", fn, what);                   \
    return fmi3Error;                                          \
  }

UDMAP_FMI_EXPORT const char *fmi3GetVersion(void) { return fmi3Version; }

UDMAP_FMI_EXPORT fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn,
                                                size_t nCategories,
                                                const fmi3String categories[]) {
  BEGIN("fmi3SetDebugLogging", ALL_STATES)
  return (fmi3Status)model_set_debug_logging(m, loggingOn, nCategories, categories);
}

/* ---------------------------------------------------------------- instantiation */

static void log_early(fmi3LogMessageCallback logMessage, fmi3InstanceEnvironment env,
                      const char *message) {
  if (logMessage) logMessage(env, fmi3Error, "logStatusError", message);
}

UDMAP_FMI_EXPORT fmi3Instance fmi3InstantiateModelExchange(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage) {
  (void)instanceName, (void)instantiationToken, (void)resourcePath, (void)visible,
      (void)loggingOn;
  log_early(logMessage, instanceEnvironment,
            "fmi3InstantiateModelExchange: udmap is a co-simulation FMU only");
  return NULL;
}

UDMAP_FMI_EXPORT fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate) {
  (void)resourcePath, (void)visible, (void)earlyReturnAllowed,
      (void)requiredIntermediateVariables, (void)intermediateUpdate;
  char token[40], msg[256];
  udmap_fmu_token(token, sizeof token);
  if (!instantiationToken || strcmp(instantiationToken, token) != 0) {
    snprintf(msg, sizeof msg, "fmi3InstantiateCoSimulation: instantiation token '%s' does "
             "not match this binary's '%s'", instantiationToken ? instantiationToken : "(null)",
             token);
    log_early(logMessage, instanceEnvironment, msg);
    return NULL;
  }
  if (eventModeUsed) {
    log_early(logMessage, instanceEnvironment,
              "fmi3InstantiateCoSimulation: the FMU has no event mode (hasEventMode = false)");
    return NULL;
  }
  if (nRequiredIntermediateVariables > 0) {
    log_early(logMessage, instanceEnvironment,
              "fmi3InstantiateCoSimulation: the FMU provides no intermediate variables");
    return NULL;
  }
  ModelInstance *m = model_new(instanceName ? instanceName : "udmap", 3, emit3,
                               (void *)logMessage, instanceEnvironment, loggingOn);
  if (!m) log_early(logMessage, instanceEnvironment, "fmi3InstantiateCoSimulation: out of memory");
  return m;
}

UDMAP_FMI_EXPORT fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption) {
  (void)instanceName, (void)instantiationToken, (void)resourcePath, (void)visible,
      (void)loggingOn, (void)clockUpdate, (void)lockPreemption, (void)unlockPreemption;
  log_early(logMessage, instanceEnvironment,
            "fmi3InstantiateScheduledExecution: udmap is a co-simulation FMU only");
  return NULL;
}

UDMAP_FMI_EXPORT void fmi3FreeInstance(fmi3Instance instance) {
  model_free((ModelInstance *)instance);
}

/* ---------------------------------------------------------------- modes */

UDMAP_FMI_EXPORT fmi3Status fmi3EnterInitializationMode(fmi3Instance instance,
                                                        fmi3Boolean toleranceDefined,
                                                        fmi3Float64 tolerance,
                                                        fmi3Float64 startTime,
                                                        fmi3Boolean stopTimeDefined,
                                                        fmi3Float64 stopTime) {
  BEGIN("fmi3EnterInitializationMode", Instantiated)
  (void)toleranceDefined, (void)tolerance;
  if (!isfinite(startTime) || (stopTimeDefined && !(stopTime >= startTime))) {
    model_log(m, Error, "fmi3EnterInitializationMode: startTime = %g, stopTime = %g are not a "
              "valid interval", startTime, stopTime);
    return fmi3Error;
  }
  m->value[vr_time] = startTime;
  m->stopTimeDefined = stopTimeDefined;
  m->stopTime = stopTime;
  m->state = InitializationMode;
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
  BEGIN("fmi3ExitInitializationMode", InitializationMode)
  m->state = StepMode;
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3EnterEventMode(fmi3Instance instance)
    NOT_PROVIDED("fmi3EnterEventMode", "the FMU has no event mode")

UDMAP_FMI_EXPORT fmi3Status fmi3EnterStepMode(fmi3Instance instance)
    NOT_PROVIDED("fmi3EnterStepMode", "the FMU has no event mode to leave")

UDMAP_FMI_EXPORT fmi3Status fmi3Terminate(fmi3Instance instance) {
  BEGIN("fmi3Terminate", StepMode)
  m->state = Terminated;
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3Reset(fmi3Instance instance) {
  BEGIN("fmi3Reset", ALL_STATES)
  model_reset(m);
  return fmi3OK;
}

/* ---------------------------------------------------------------- get and set */

static fmi3Status get_values(fmi3Instance instance, const char *fn, VariableType type,
                             const fmi3ValueReference vr[], size_t nvr, void *values,
                             size_t nValues) {
  BEGIN(fn, MASK_GET)
  if (nValues != nvr || (nvr > 0 && (!vr || !values))) {
    model_log(m, Error, "%s: %zu values for %zu scalar variables (or a NULL array)", fn,
              nValues, nvr);
    return fmi3Error;
  }
  Status status = OK;
  unsigned logged = 0;
  for (size_t i = 0; i < nvr; i++) {
    double x;
    Status st = model_get(m, fn, (ValueReference)vr[i], type, &x, &logged);
    if (st > status) status = st;
    switch (type) {
      case REAL: ((fmi3Float64 *)values)[i] = x; break;
      case INTEGER: ((fmi3Int32 *)values)[i] = (fmi3Int32)x; break;
      case BOOLEAN: ((fmi3Boolean *)values)[i] = x != 0.0; break;
    }
  }
  return (fmi3Status)status;
}

/* All values are checked before any is taken: a rejected call changes nothing. */
static fmi3Status set_values(fmi3Instance instance, const char *fn, VariableType type,
                             const fmi3ValueReference vr[], size_t nvr, const void *values,
                             size_t nValues) {
  BEGIN(fn, MASK_SET)
  if (nValues != nvr || (nvr > 0 && (!vr || !values))) {
    model_log(m, Error, "%s: %zu values for %zu scalar variables (or a NULL array)", fn,
              nValues, nvr);
    return fmi3Error;
  }
  for (int apply = 0; apply < 2; apply++) {
    Status status = OK;
    for (size_t i = 0; i < nvr; i++) {
      double x = 0.0;
      switch (type) {
        case REAL: x = ((const fmi3Float64 *)values)[i]; break;
        case INTEGER: x = ((const fmi3Int32 *)values)[i]; break;
        case BOOLEAN: x = ((const fmi3Boolean *)values)[i] ? 1.0 : 0.0; break;
      }
      Status st = model_set(m, fn, (ValueReference)vr[i], type, x, apply != 0);
      if (st > status) status = st;
    }
    if (status != OK) return (fmi3Status)status;
  }
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[],
                                           size_t nvr, fmi3Float64 values[], size_t nValues) {
  return get_values(instance, "fmi3GetFloat64", REAL, vr, nvr, values, nValues);
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[],
                                           size_t nvr, const fmi3Float64 values[],
                                           size_t nValues) {
  return set_values(instance, "fmi3SetFloat64", REAL, vr, nvr, values, nValues);
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference vr[],
                                         size_t nvr, fmi3Int32 values[], size_t nValues) {
  return get_values(instance, "fmi3GetInt32", INTEGER, vr, nvr, values, nValues);
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference vr[],
                                         size_t nvr, const fmi3Int32 values[], size_t nValues) {
  return set_values(instance, "fmi3SetInt32", INTEGER, vr, nvr, values, nValues);
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference vr[],
                                           size_t nvr, fmi3Boolean values[], size_t nValues) {
  return get_values(instance, "fmi3GetBoolean", BOOLEAN, vr, nvr, values, nValues);
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference vr[],
                                           size_t nvr, const fmi3Boolean values[],
                                           size_t nValues) {
  return set_values(instance, "fmi3SetBoolean", BOOLEAN, vr, nvr, values, nValues);
}

/* Types the FMU has no variables of: an empty call succeeds, any reference is an error. */
static fmi3Status no_variables(fmi3Instance instance, const char *fn, unsigned mask,
                               size_t nvr) {
  BEGIN(fn, mask)
  if (nvr == 0) return fmi3OK;
  model_log(m, Error, "%s: the FMU has no variables of this type", fn);
  return fmi3Error;
}

#define UNUSED_TYPE(T)                                                                      \
  UDMAP_FMI_EXPORT fmi3Status fmi3Get##T(fmi3Instance instance,                            \
                                         const fmi3ValueReference vr[], size_t nvr,        \
                                         fmi3##T values[], size_t nValues) {               \
    (void)vr, (void)values, (void)nValues;                                                  \
    return no_variables(instance, "fmi3Get" #T, MASK_GET, nvr);                             \
  }                                                                                         \
  UDMAP_FMI_EXPORT fmi3Status fmi3Set##T(fmi3Instance instance,                            \
                                         const fmi3ValueReference vr[], size_t nvr,        \
                                         const fmi3##T values[], size_t nValues) {         \
    (void)vr, (void)values, (void)nValues;                                                  \
    return no_variables(instance, "fmi3Set" #T, MASK_SET, nvr);                             \
  }

UNUSED_TYPE(Float32)
UNUSED_TYPE(Int8)
UNUSED_TYPE(UInt8)
UNUSED_TYPE(Int16)
UNUSED_TYPE(UInt16)
UNUSED_TYPE(UInt32)
UNUSED_TYPE(Int64)
UNUSED_TYPE(UInt64)
UNUSED_TYPE(String)

UDMAP_FMI_EXPORT fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference vr[],
                                          size_t nvr, size_t valueSizes[], fmi3Binary values[],
                                          size_t nValues) {
  (void)vr, (void)valueSizes, (void)values, (void)nValues;
  return no_variables(instance, "fmi3GetBinary", MASK_GET, nvr);
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[],
                                          size_t nvr, const size_t valueSizes[],
                                          const fmi3Binary values[], size_t nValues) {
  (void)vr, (void)valueSizes, (void)values, (void)nValues;
  return no_variables(instance, "fmi3SetBinary", MASK_SET, nvr);
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference vr[],
                                         size_t nvr, fmi3Clock values[]) {
  (void)vr, (void)values;
  return no_variables(instance, "fmi3GetClock", MASK_GET, nvr);
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference vr[],
                                         size_t nvr, const fmi3Clock values[]) {
  (void)vr, (void)values;
  return no_variables(instance, "fmi3SetClock", MASK_SET, nvr);
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance,
                                                                fmi3ValueReference vr,
                                                                size_t *nDependencies) {
  (void)vr, (void)nDependencies;
  NOT_PROVIDED("fmi3GetNumberOfVariableDependencies",
               "not provided; the dependencies are in the modelDescription")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetVariableDependencies(
    fmi3Instance instance, fmi3ValueReference dependent, size_t elementIndicesOfDependent[],
    fmi3ValueReference independents[], size_t elementIndicesOfIndependents[],
    fmi3DependencyKind dependencyKinds[], size_t nDependencies) {
  (void)dependent, (void)elementIndicesOfDependent, (void)independents,
      (void)elementIndicesOfIndependents, (void)dependencyKinds, (void)nDependencies;
  NOT_PROVIDED("fmi3GetVariableDependencies",
               "not provided; the dependencies are in the modelDescription")
}

/* ---------------------------------------------------------------- FMU state */

UDMAP_FMI_EXPORT fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *FMUState) {
  BEGIN("fmi3GetFMUState", ALL_STATES)
  if (!FMUState) {
    model_log(m, Error, "fmi3GetFMUState: FMUState is NULL");
    return fmi3Error;
  }
  ModelSnapshot *s = model_snapshot(m, (ModelSnapshot *)*FMUState);
  if (!s) return fmi3Error;
  *FMUState = s;
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState) {
  BEGIN("fmi3SetFMUState", ALL_STATES)
  return (fmi3Status)model_restore(m, "fmi3SetFMUState", (const ModelSnapshot *)FMUState);
}

UDMAP_FMI_EXPORT fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *FMUState) {
  BEGIN("fmi3FreeFMUState", ALL_STATES)
  if (FMUState) {
    free(*FMUState);
    *FMUState = NULL;
  }
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance,
                                                       fmi3FMUState FMUState, size_t *size) {
  BEGIN("fmi3SerializedFMUStateSize", ALL_STATES)
  (void)FMUState;
  if (!size) {
    model_log(m, Error, "fmi3SerializedFMUStateSize: size is NULL");
    return fmi3Error;
  }
  *size = sizeof(ModelSnapshot);
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState,
                                                  fmi3Byte serializedState[], size_t size) {
  BEGIN("fmi3SerializeFMUState", ALL_STATES)
  if (!FMUState || !serializedState || size != sizeof(ModelSnapshot)) {
    model_log(m, Error, "fmi3SerializeFMUState: needs a state and a buffer of %zu bytes "
              "(got %zu)", sizeof(ModelSnapshot), size);
    return fmi3Error;
  }
  memcpy(serializedState, FMUState, sizeof(ModelSnapshot));
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3DeserializeFMUState(fmi3Instance instance,
                                                    const fmi3Byte serializedState[],
                                                    size_t size, fmi3FMUState *FMUState) {
  BEGIN("fmi3DeserializeFMUState", ALL_STATES)
  if (!FMUState) {
    model_log(m, Error, "fmi3DeserializeFMUState: FMUState is NULL");
    return fmi3Error;
  }
  Status st = model_check_snapshot(m, "fmi3DeserializeFMUState", serializedState, size);
  if (st != OK) return (fmi3Status)st;
  ModelSnapshot *s = *FMUState ? (ModelSnapshot *)*FMUState : malloc(sizeof *s);
  if (!s) {
    model_log(m, Error, "fmi3DeserializeFMUState: out of memory");
    return fmi3Error;
  }
  memcpy(s, serializedState, sizeof *s);
  *FMUState = s;
  return fmi3OK;
}

/* ---------------------------------------------------------------- not provided */

UDMAP_FMI_EXPORT fmi3Status fmi3GetDirectionalDerivative(
    fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
    fmi3Float64 sensitivity[], size_t nSensitivity) {
  (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed,
      (void)sensitivity, (void)nSensitivity;
  NOT_PROVIDED("fmi3GetDirectionalDerivative", "not provided by this FMU")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetAdjointDerivative(
    fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
    fmi3Float64 sensitivity[], size_t nSensitivity) {
  (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed,
      (void)sensitivity, (void)nSensitivity;
  NOT_PROVIDED("fmi3GetAdjointDerivative", "not provided by this FMU")
}

UDMAP_FMI_EXPORT fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance)
    NOT_PROVIDED("fmi3EnterConfigurationMode", "the FMU has no structural parameters")

UDMAP_FMI_EXPORT fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance)
    NOT_PROVIDED("fmi3ExitConfigurationMode", "the FMU has no structural parameters")

UDMAP_FMI_EXPORT fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance,
                                                   const fmi3ValueReference vr[], size_t nvr,
                                                   fmi3Float64 intervals[],
                                                   fmi3IntervalQualifier qualifiers[]) {
  (void)vr, (void)nvr, (void)intervals, (void)qualifiers;
  NOT_PROVIDED("fmi3GetIntervalDecimal", "the FMU has no clocks")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetIntervalFraction(fmi3Instance instance,
                                                    const fmi3ValueReference vr[], size_t nvr,
                                                    fmi3UInt64 counters[],
                                                    fmi3UInt64 resolutions[],
                                                    fmi3IntervalQualifier qualifiers[]) {
  (void)vr, (void)nvr, (void)counters, (void)resolutions, (void)qualifiers;
  NOT_PROVIDED("fmi3GetIntervalFraction", "the FMU has no clocks")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetShiftDecimal(fmi3Instance instance,
                                                const fmi3ValueReference vr[], size_t nvr,
                                                fmi3Float64 shifts[]) {
  (void)vr, (void)nvr, (void)shifts;
  NOT_PROVIDED("fmi3GetShiftDecimal", "the FMU has no clocks")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetShiftFraction(fmi3Instance instance,
                                                 const fmi3ValueReference vr[], size_t nvr,
                                                 fmi3UInt64 counters[],
                                                 fmi3UInt64 resolutions[]) {
  (void)vr, (void)nvr, (void)counters, (void)resolutions;
  NOT_PROVIDED("fmi3GetShiftFraction", "the FMU has no clocks")
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance,
                                                   const fmi3ValueReference vr[], size_t nvr,
                                                   const fmi3Float64 intervals[]) {
  (void)vr, (void)nvr, (void)intervals;
  NOT_PROVIDED("fmi3SetIntervalDecimal", "the FMU has no clocks")
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetIntervalFraction(fmi3Instance instance,
                                                    const fmi3ValueReference vr[], size_t nvr,
                                                    const fmi3UInt64 counters[],
                                                    const fmi3UInt64 resolutions[]) {
  (void)vr, (void)nvr, (void)counters, (void)resolutions;
  NOT_PROVIDED("fmi3SetIntervalFraction", "the FMU has no clocks")
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetShiftDecimal(fmi3Instance instance,
                                                const fmi3ValueReference vr[], size_t nvr,
                                                const fmi3Float64 shifts[]) {
  (void)vr, (void)nvr, (void)shifts;
  NOT_PROVIDED("fmi3SetShiftDecimal", "the FMU has no clocks")
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetShiftFraction(fmi3Instance instance,
                                                 const fmi3ValueReference vr[], size_t nvr,
                                                 const fmi3UInt64 counters[],
                                                 const fmi3UInt64 resolutions[]) {
  (void)vr, (void)nvr, (void)counters, (void)resolutions;
  NOT_PROVIDED("fmi3SetShiftFraction", "the FMU has no clocks")
}

UDMAP_FMI_EXPORT fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance)
    NOT_PROVIDED("fmi3EvaluateDiscreteStates", "the FMU has no event mode")

UDMAP_FMI_EXPORT fmi3Status fmi3UpdateDiscreteStates(
    fmi3Instance instance, fmi3Boolean *discreteStatesNeedUpdate,
    fmi3Boolean *terminateSimulation, fmi3Boolean *nominalsOfContinuousStatesChanged,
    fmi3Boolean *valuesOfContinuousStatesChanged, fmi3Boolean *nextEventTimeDefined,
    fmi3Float64 *nextEventTime) {
  (void)discreteStatesNeedUpdate, (void)terminateSimulation,
      (void)nominalsOfContinuousStatesChanged, (void)valuesOfContinuousStatesChanged,
      (void)nextEventTimeDefined, (void)nextEventTime;
  NOT_PROVIDED("fmi3UpdateDiscreteStates", "the FMU has no event mode")
}

UDMAP_FMI_EXPORT fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance)
    NOT_PROVIDED("fmi3EnterContinuousTimeMode", "model exchange is not provided")

UDMAP_FMI_EXPORT fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance,
                                                        fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                                        fmi3Boolean *enterEventMode,
                                                        fmi3Boolean *terminateSimulation) {
  (void)noSetFMUStatePriorToCurrentPoint, (void)enterEventMode, (void)terminateSimulation;
  NOT_PROVIDED("fmi3CompletedIntegratorStep", "model exchange is not provided")
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time) {
  (void)time;
  NOT_PROVIDED("fmi3SetTime", "model exchange is not provided")
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetContinuousStates(fmi3Instance instance,
                                                    const fmi3Float64 continuousStates[],
                                                    size_t nContinuousStates) {
  (void)continuousStates, (void)nContinuousStates;
  NOT_PROVIDED("fmi3SetContinuousStates", "model exchange is not provided")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance,
                                                              fmi3Float64 derivatives[],
                                                              size_t nContinuousStates) {
  (void)derivatives, (void)nContinuousStates;
  NOT_PROVIDED("fmi3GetContinuousStateDerivatives", "model exchange is not provided")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetEventIndicators(fmi3Instance instance,
                                                   fmi3Float64 eventIndicators[],
                                                   size_t nEventIndicators) {
  (void)eventIndicators, (void)nEventIndicators;
  NOT_PROVIDED("fmi3GetEventIndicators", "model exchange is not provided")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetContinuousStates(fmi3Instance instance,
                                                    fmi3Float64 continuousStates[],
                                                    size_t nContinuousStates) {
  (void)continuousStates, (void)nContinuousStates;
  NOT_PROVIDED("fmi3GetContinuousStates", "model exchange is not provided")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance,
                                                              fmi3Float64 nominals[],
                                                              size_t nContinuousStates) {
  (void)nominals, (void)nContinuousStates;
  NOT_PROVIDED("fmi3GetNominalsOfContinuousStates", "model exchange is not provided")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance,
                                                           size_t *nEventIndicators) {
  BEGIN("fmi3GetNumberOfEventIndicators", ALL_STATES)
  if (nEventIndicators) *nEventIndicators = 0;
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance,
                                                            size_t *nContinuousStates) {
  BEGIN("fmi3GetNumberOfContinuousStates", ALL_STATES)
  if (nContinuousStates) *nContinuousStates = 0;
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance,
                                                     const fmi3ValueReference vr[], size_t nvr,
                                                     const fmi3Int32 orders[],
                                                     fmi3Float64 values[], size_t nValues) {
  (void)vr, (void)orders, (void)values, (void)nValues;
  return no_variables(instance, "fmi3GetOutputDerivatives", MASK_GET, nvr);
}

UDMAP_FMI_EXPORT fmi3Status fmi3DoStep(fmi3Instance instance,
                                       fmi3Float64 currentCommunicationPoint,
                                       fmi3Float64 communicationStepSize,
                                       fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean *eventHandlingNeeded,
                                       fmi3Boolean *terminateSimulation,
                                       fmi3Boolean *earlyReturn,
                                       fmi3Float64 *lastSuccessfulTime) {
  BEGIN("fmi3DoStep", StepMode)
  (void)noSetFMUStatePriorToCurrentPoint;
  Status st = model_do_step(m, "fmi3DoStep", currentCommunicationPoint, communicationStepSize);
  if (eventHandlingNeeded) *eventHandlingNeeded = false;
  if (terminateSimulation) *terminateSimulation = false;
  if (earlyReturn) *earlyReturn = false;
  if (lastSuccessfulTime) *lastSuccessfulTime = m->value[vr_time];
  return (fmi3Status)st;
}

UDMAP_FMI_EXPORT fmi3Status fmi3ActivateModelPartition(fmi3Instance instance,
                                                       fmi3ValueReference clockReference,
                                                       fmi3Float64 activationTime) {
  (void)clockReference, (void)activationTime;
  NOT_PROVIDED("fmi3ActivateModelPartition", "scheduled execution is not provided")
}
