/*
 * FMI 3.0 model exchange and co-simulation: signatures translated to the shared core
 * (core.c), which checks the instance states and logs every failure. Scheduled execution,
 * event mode in co-simulation, clocks and configuration mode are not provided; their
 * functions log an error and return fmi3Error.
 */
#include <stdio.h>

#include "fmi3_api.h"
#include "core.h"

static void emit3(ModelInstance *m, Status status, const char *category, const char *message) {
  fmi3LogMessageCallback logger = (fmi3LogMessageCallback)m->logger;
  if (logger) logger(m->environment, (fmi3Status)status, category, message);
}

#define M ((ModelInstance *)instance)
#define CALL(expr) return instance ? (fmi3Status)(expr) : fmi3Error;
#define NOT_PROVIDED(fn, why) CALL(core_not_provided(M, fn, why))
#define VR(vr) ((const unsigned *)(vr))

UDMAP_FMI_EXPORT const char *fmi3GetVersion(void) { return fmi3Version; }

UDMAP_FMI_EXPORT fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn,
                                                size_t nCategories,
                                                const fmi3String categories[]) {
  CALL(core_set_debug_logging(M, "fmi3SetDebugLogging", loggingOn, nCategories, categories))
}

/* ---------------------------------------------------------------- instantiation */

UDMAP_FMI_EXPORT fmi3Instance fmi3InstantiateModelExchange(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage) {
  (void)visible;
  return core_instantiate("fmi3InstantiateModelExchange", instanceName, 3, ModelExchange,
                          instantiationToken, resourcePath, emit3, (void *)logMessage, instanceEnvironment,
                          loggingOn);
}

UDMAP_FMI_EXPORT fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate) {
  (void)visible, (void)earlyReturnAllowed, (void)requiredIntermediateVariables,
      (void)intermediateUpdate;
  const char *fn = "fmi3InstantiateCoSimulation";
  ModelInstance *m = core_instantiate(fn, instanceName, 3, CoSimulation, instantiationToken,
                                      resourcePath, emit3, (void *)logMessage, instanceEnvironment, loggingOn);
  const char *why = !m ? NULL
                    : eventModeUsed ? "the FMU has no event mode (hasEventMode = false)"
                    : nRequiredIntermediateVariables > 0
                        ? "the FMU provides no intermediate variables"
                        : NULL;
  if (why) {
    model_log(m, Error, "%s: %s", fn, why);
    model_free(m);
    return NULL;
  }
  return m;
}

UDMAP_FMI_EXPORT fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption) {
  (void)instanceName, (void)instantiationToken, (void)resourcePath, (void)visible,
      (void)loggingOn, (void)clockUpdate, (void)lockPreemption, (void)unlockPreemption;
  if (logMessage)
    logMessage(instanceEnvironment, fmi3Error, "logStatusError",
               "fmi3InstantiateScheduledExecution: udmap provides model exchange and "
               "co-simulation only");
  return NULL;
}

UDMAP_FMI_EXPORT void fmi3FreeInstance(fmi3Instance instance) { model_free(M); }

/* ---------------------------------------------------------------- modes */

UDMAP_FMI_EXPORT fmi3Status fmi3EnterInitializationMode(fmi3Instance instance,
                                                        fmi3Boolean toleranceDefined,
                                                        fmi3Float64 tolerance,
                                                        fmi3Float64 startTime,
                                                        fmi3Boolean stopTimeDefined,
                                                        fmi3Float64 stopTime) {
  (void)toleranceDefined, (void)tolerance;
  if (!instance) return fmi3Error;
  Status st = core_setup_experiment(M, "fmi3EnterInitializationMode", Instantiated, startTime,
                                    stopTimeDefined, stopTime);
  if (st == OK) st = core_enter_initialization_mode(M, "fmi3EnterInitializationMode");
  return (fmi3Status)st;
}

UDMAP_FMI_EXPORT fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
  CALL(core_exit_initialization_mode(M, "fmi3ExitInitializationMode"))
}

UDMAP_FMI_EXPORT fmi3Status fmi3EnterEventMode(fmi3Instance instance) {
  CALL(core_enter_event_mode(M, "fmi3EnterEventMode"))
}

UDMAP_FMI_EXPORT fmi3Status fmi3EnterStepMode(fmi3Instance instance) {
  NOT_PROVIDED("fmi3EnterStepMode", "the co-simulation interface has no event mode to leave")
}

UDMAP_FMI_EXPORT fmi3Status fmi3Terminate(fmi3Instance instance) {
  CALL(core_terminate(M, "fmi3Terminate"))
}

UDMAP_FMI_EXPORT fmi3Status fmi3Reset(fmi3Instance instance) {
  CALL(core_reset(M, "fmi3Reset"))
}

/* ---------------------------------------------------------------- get and set */

UDMAP_FMI_EXPORT fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[],
                                           size_t nvr, fmi3Float64 values[], size_t nValues) {
  CALL(core_get(M, "fmi3GetFloat64", REAL, ELEM_FLOAT64, VR(vr), nvr, values, nValues))
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[],
                                           size_t nvr, const fmi3Float64 values[],
                                           size_t nValues) {
  CALL(core_set(M, "fmi3SetFloat64", REAL, ELEM_FLOAT64, VR(vr), nvr, values, nValues))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference vr[],
                                         size_t nvr, fmi3Int32 values[], size_t nValues) {
  CALL(core_get(M, "fmi3GetInt32", INTEGER, ELEM_INT, VR(vr), nvr, values, nValues))
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference vr[],
                                         size_t nvr, const fmi3Int32 values[], size_t nValues) {
  CALL(core_set(M, "fmi3SetInt32", INTEGER, ELEM_INT, VR(vr), nvr, values, nValues))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference vr[],
                                           size_t nvr, fmi3Boolean values[], size_t nValues) {
  CALL(core_get(M, "fmi3GetBoolean", BOOLEAN, ELEM_BOOL, VR(vr), nvr, values, nValues))
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference vr[],
                                           size_t nvr, const fmi3Boolean values[],
                                           size_t nValues) {
  CALL(core_set(M, "fmi3SetBoolean", BOOLEAN, ELEM_BOOL, VR(vr), nvr, values, nValues))
}

/* Types the FMU has no variables of. */
#define UNUSED_TYPE(T)                                                                      \
  UDMAP_FMI_EXPORT fmi3Status fmi3Get##T(fmi3Instance instance,                            \
                                         const fmi3ValueReference vr[], size_t nvr,        \
                                         fmi3##T values[], size_t nValues) {               \
    (void)vr, (void)values, (void)nValues;                                                  \
    CALL(core_no_variables(M, "fmi3Get" #T, false, nvr))                                    \
  }                                                                                         \
  UDMAP_FMI_EXPORT fmi3Status fmi3Set##T(fmi3Instance instance,                            \
                                         const fmi3ValueReference vr[], size_t nvr,        \
                                         const fmi3##T values[], size_t nValues) {         \
    (void)vr, (void)values, (void)nValues;                                                  \
    CALL(core_no_variables(M, "fmi3Set" #T, true, nvr))                                     \
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
  CALL(core_no_variables(M, "fmi3GetBinary", false, nvr))
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[],
                                          size_t nvr, const size_t valueSizes[],
                                          const fmi3Binary values[], size_t nValues) {
  (void)vr, (void)valueSizes, (void)values, (void)nValues;
  CALL(core_no_variables(M, "fmi3SetBinary", true, nvr))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference vr[],
                                         size_t nvr, fmi3Clock values[]) {
  (void)vr, (void)values;
  CALL(core_no_variables(M, "fmi3GetClock", false, nvr))
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference vr[],
                                         size_t nvr, const fmi3Clock values[]) {
  (void)vr, (void)values;
  CALL(core_no_variables(M, "fmi3SetClock", true, nvr))
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

/* ---------------------------------------------------------------- FMU state, derivatives */

UDMAP_FMI_EXPORT fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *FMUState) {
  CALL(core_get_state(M, "fmi3GetFMUState", FMUState))
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState) {
  CALL(core_set_state(M, "fmi3SetFMUState", FMUState))
}

UDMAP_FMI_EXPORT fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *FMUState) {
  CALL(core_free_state(M, "fmi3FreeFMUState", FMUState))
}

UDMAP_FMI_EXPORT fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance,
                                                       fmi3FMUState FMUState, size_t *size) {
  (void)FMUState;
  CALL(core_serialized_state_size(M, "fmi3SerializedFMUStateSize", size))
}

UDMAP_FMI_EXPORT fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState,
                                                  fmi3Byte serializedState[], size_t size) {
  CALL(core_serialize_state(M, "fmi3SerializeFMUState", FMUState, serializedState, size))
}

UDMAP_FMI_EXPORT fmi3Status fmi3DeserializeFMUState(fmi3Instance instance,
                                                    const fmi3Byte serializedState[],
                                                    size_t size, fmi3FMUState *FMUState) {
  CALL(core_deserialize_state(M, "fmi3DeserializeFMUState", serializedState, size, FMUState))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetDirectionalDerivative(
    fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
    fmi3Float64 sensitivity[], size_t nSensitivity) {
  CALL(core_directional_derivative(M, "fmi3GetDirectionalDerivative", VR(unknowns), nUnknowns,
                                   VR(knowns), nKnowns, seed, nSeed, sensitivity, nSensitivity))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetAdjointDerivative(
    fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
    fmi3Float64 sensitivity[], size_t nSensitivity) {
  (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed,
      (void)sensitivity, (void)nSensitivity;
  NOT_PROVIDED("fmi3GetAdjointDerivative",
               "not provided (providesAdjointDerivatives = false); use "
               "fmi3GetDirectionalDerivative")
}

/* ---------------------------------------------------------------- not provided */

UDMAP_FMI_EXPORT fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance) {
  NOT_PROVIDED("fmi3EnterConfigurationMode", "the FMU has no structural parameters")
}

UDMAP_FMI_EXPORT fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance) {
  NOT_PROVIDED("fmi3ExitConfigurationMode", "the FMU has no structural parameters")
}

#define NO_CLOCKS(fn) NOT_PROVIDED(fn, "the FMU has no clocks")

UDMAP_FMI_EXPORT fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance,
                                                   const fmi3ValueReference vr[], size_t nvr,
                                                   fmi3Float64 intervals[],
                                                   fmi3IntervalQualifier qualifiers[]) {
  (void)vr, (void)nvr, (void)intervals, (void)qualifiers;
  NO_CLOCKS("fmi3GetIntervalDecimal")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetIntervalFraction(fmi3Instance instance,
                                                    const fmi3ValueReference vr[], size_t nvr,
                                                    fmi3UInt64 counters[],
                                                    fmi3UInt64 resolutions[],
                                                    fmi3IntervalQualifier qualifiers[]) {
  (void)vr, (void)nvr, (void)counters, (void)resolutions, (void)qualifiers;
  NO_CLOCKS("fmi3GetIntervalFraction")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetShiftDecimal(fmi3Instance instance,
                                                const fmi3ValueReference vr[], size_t nvr,
                                                fmi3Float64 shifts[]) {
  (void)vr, (void)nvr, (void)shifts;
  NO_CLOCKS("fmi3GetShiftDecimal")
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetShiftFraction(fmi3Instance instance,
                                                 const fmi3ValueReference vr[], size_t nvr,
                                                 fmi3UInt64 counters[],
                                                 fmi3UInt64 resolutions[]) {
  (void)vr, (void)nvr, (void)counters, (void)resolutions;
  NO_CLOCKS("fmi3GetShiftFraction")
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance,
                                                   const fmi3ValueReference vr[], size_t nvr,
                                                   const fmi3Float64 intervals[]) {
  (void)vr, (void)nvr, (void)intervals;
  NO_CLOCKS("fmi3SetIntervalDecimal")
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetIntervalFraction(fmi3Instance instance,
                                                    const fmi3ValueReference vr[], size_t nvr,
                                                    const fmi3UInt64 counters[],
                                                    const fmi3UInt64 resolutions[]) {
  (void)vr, (void)nvr, (void)counters, (void)resolutions;
  NO_CLOCKS("fmi3SetIntervalFraction")
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetShiftDecimal(fmi3Instance instance,
                                                const fmi3ValueReference vr[], size_t nvr,
                                                const fmi3Float64 shifts[]) {
  (void)vr, (void)nvr, (void)shifts;
  NO_CLOCKS("fmi3SetShiftDecimal")
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetShiftFraction(fmi3Instance instance,
                                                 const fmi3ValueReference vr[], size_t nvr,
                                                 const fmi3UInt64 counters[],
                                                 const fmi3UInt64 resolutions[]) {
  (void)vr, (void)nvr, (void)counters, (void)resolutions;
  NO_CLOCKS("fmi3SetShiftFraction")
}

UDMAP_FMI_EXPORT fmi3Status fmi3ActivateModelPartition(fmi3Instance instance,
                                                       fmi3ValueReference clockReference,
                                                       fmi3Float64 activationTime) {
  (void)clockReference, (void)activationTime;
  NOT_PROVIDED("fmi3ActivateModelPartition", "scheduled execution is not provided")
}

UDMAP_FMI_EXPORT fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance) {
  NOT_PROVIDED("fmi3EvaluateDiscreteStates",
               "not provided (providesEvaluateDiscreteStates = false): the FMU has no discrete "
               "states")
}

/* ---------------------------------------------------------------- model exchange */

UDMAP_FMI_EXPORT fmi3Status fmi3UpdateDiscreteStates(
    fmi3Instance instance, fmi3Boolean *discreteStatesNeedUpdate,
    fmi3Boolean *terminateSimulation, fmi3Boolean *nominalsOfContinuousStatesChanged,
    fmi3Boolean *valuesOfContinuousStatesChanged, fmi3Boolean *nextEventTimeDefined,
    fmi3Float64 *nextEventTime) {
  EventInfo e;
  Status st = instance ? core_update_discrete_states(M, "fmi3UpdateDiscreteStates", &e) : Error;
  if (st != OK) return (fmi3Status)st;
  if (discreteStatesNeedUpdate) *discreteStatesNeedUpdate = e.discreteStatesNeedUpdate;
  if (terminateSimulation) *terminateSimulation = e.terminateSimulation;
  if (nominalsOfContinuousStatesChanged) *nominalsOfContinuousStatesChanged = e.nominalsChanged;
  if (valuesOfContinuousStatesChanged) *valuesOfContinuousStatesChanged = e.valuesChanged;
  if (nextEventTimeDefined) *nextEventTimeDefined = e.nextEventTimeDefined;
  if (nextEventTime) *nextEventTime = e.nextEventTime;
  return fmi3OK;
}

UDMAP_FMI_EXPORT fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance) {
  CALL(core_enter_continuous_time_mode(M, "fmi3EnterContinuousTimeMode"))
}

UDMAP_FMI_EXPORT fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance,
                                                        fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                                        fmi3Boolean *enterEventMode,
                                                        fmi3Boolean *terminateSimulation) {
  (void)noSetFMUStatePriorToCurrentPoint;
  CALL(core_completed_integrator_step(M, "fmi3CompletedIntegratorStep", enterEventMode,
                                      terminateSimulation))
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time) {
  CALL(core_set_time(M, "fmi3SetTime", time))
}

UDMAP_FMI_EXPORT fmi3Status fmi3SetContinuousStates(fmi3Instance instance,
                                                    const fmi3Float64 continuousStates[],
                                                    size_t nContinuousStates) {
  CALL(core_empty_vector(M, "fmi3SetContinuousStates", CORE_MASK_ME_RUN, continuousStates,
                         nContinuousStates))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance,
                                                              fmi3Float64 derivatives[],
                                                              size_t nContinuousStates) {
  CALL(core_empty_vector(M, "fmi3GetContinuousStateDerivatives", CORE_MASK_GET, derivatives,
                         nContinuousStates))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetEventIndicators(fmi3Instance instance,
                                                   fmi3Float64 eventIndicators[],
                                                   size_t nEventIndicators) {
  CALL(core_empty_vector(M, "fmi3GetEventIndicators", CORE_MASK_GET, eventIndicators,
                         nEventIndicators))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetContinuousStates(fmi3Instance instance,
                                                    fmi3Float64 continuousStates[],
                                                    size_t nContinuousStates) {
  CALL(core_empty_vector(M, "fmi3GetContinuousStates", CORE_MASK_GET, continuousStates,
                         nContinuousStates))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance,
                                                              fmi3Float64 nominals[],
                                                              size_t nContinuousStates) {
  CALL(core_empty_vector(M, "fmi3GetNominalsOfContinuousStates", CORE_MASK_GET, nominals,
                         nContinuousStates))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance,
                                                           size_t *nEventIndicators) {
  if (instance && nEventIndicators) *nEventIndicators = 0;
  CALL(core_empty_vector(M, "fmi3GetNumberOfEventIndicators", CORE_MASK_GET, NULL, 0))
}

UDMAP_FMI_EXPORT fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance,
                                                            size_t *nContinuousStates) {
  if (instance && nContinuousStates) *nContinuousStates = 0;
  CALL(core_empty_vector(M, "fmi3GetNumberOfContinuousStates", CORE_MASK_GET, NULL, 0))
}

/* ---------------------------------------------------------------- co-simulation */

UDMAP_FMI_EXPORT fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance,
                                                     const fmi3ValueReference vr[], size_t nvr,
                                                     const fmi3Int32 orders[],
                                                     fmi3Float64 values[], size_t nValues) {
  (void)vr, (void)orders, (void)values, (void)nValues;
  CALL(core_no_variables(M, "fmi3GetOutputDerivatives", false, nvr))
}

UDMAP_FMI_EXPORT fmi3Status fmi3DoStep(fmi3Instance instance,
                                       fmi3Float64 currentCommunicationPoint,
                                       fmi3Float64 communicationStepSize,
                                       fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean *eventHandlingNeeded,
                                       fmi3Boolean *terminateSimulation,
                                       fmi3Boolean *earlyReturn,
                                       fmi3Float64 *lastSuccessfulTime) {
  (void)noSetFMUStatePriorToCurrentPoint;
  if (!instance) return fmi3Error;
  Status st = core_do_step(M, "fmi3DoStep", currentCommunicationPoint, communicationStepSize);
  if (eventHandlingNeeded) *eventHandlingNeeded = false;
  if (terminateSimulation) *terminateSimulation = false;
  if (earlyReturn) *earlyReturn = false;
  if (lastSuccessfulTime) *lastSuccessfulTime = M->value[vr_time];
  return (fmi3Status)st;
}
