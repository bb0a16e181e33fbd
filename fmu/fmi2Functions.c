/*
 * FMI 2.0 model exchange and co-simulation: signatures translated to the shared core
 * (core.c), which checks the instance states and logs every failure.
 */
#include <stdio.h>

#include "fmi2_api.h"
#include "core.h"

/* The FMI 2 logger takes a printf format: pass messages with '%' doubled. */
static void emit2(ModelInstance *m, Status status, const char *category, const char *message) {
  fmi2CallbackLogger logger = (fmi2CallbackLogger)m->logger;
  if (!logger) return;
  char buf[2048];
  size_t j = 0;
  for (size_t i = 0; message[i] && j + 2 < sizeof buf; i++) {
    if (message[i] == '%') buf[j++] = '%';
    buf[j++] = message[i];
  }
  buf[j] = '\0';
  logger(m->environment, m->instanceName, (fmi2Status)status, category, buf);
}

#define M ((ModelInstance *)c)
#define CALL(expr) return c ? (fmi2Status)(expr) : fmi2Error;
#define VR(vr) ((const unsigned *)(vr))

UDMAP_FMI_EXPORT const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }

UDMAP_FMI_EXPORT const char *fmi2GetVersion(void) { return fmi2Version; }

UDMAP_FMI_EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn,
                                                size_t nCategories,
                                                const fmi2String categories[]) {
  CALL(core_set_debug_logging(M, "fmi2SetDebugLogging", loggingOn != fmi2False, nCategories,
                              categories))
}

UDMAP_FMI_EXPORT fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType,
                                               fmi2String fmuGUID,
                                               fmi2String fmuResourceLocation,
                                               const fmi2CallbackFunctions *functions,
                                               fmi2Boolean visible, fmi2Boolean loggingOn) {
  (void)visible;
  fmi2CallbackLogger logger = functions ? functions->logger : NULL;
  void *env = functions ? functions->componentEnvironment : NULL;
  if (fmuType != fmi2ModelExchange && fmuType != fmi2CoSimulation) {
    if (logger)
      logger(env, instanceName ? instanceName : "udmap", fmi2Error, "logStatusError",
             "fmi2Instantiate: fmuType must be fmi2ModelExchange or fmi2CoSimulation");
    return NULL;
  }
  return core_instantiate("fmi2Instantiate", instanceName, 2,
                          fmuType == fmi2ModelExchange ? ModelExchange : CoSimulation,
                          fmuGUID, fmuResourceLocation, emit2, (void *)logger, env,
                          loggingOn != fmi2False);
}

UDMAP_FMI_EXPORT void fmi2FreeInstance(fmi2Component c) { model_free(M); }

UDMAP_FMI_EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                                                fmi2Real tolerance, fmi2Real startTime,
                                                fmi2Boolean stopTimeDefined,
                                                fmi2Real stopTime) {
  (void)toleranceDefined, (void)tolerance;
  CALL(core_setup_experiment(M, "fmi2SetupExperiment", Instantiated, startTime,
                             stopTimeDefined != fmi2False, stopTime))
}

UDMAP_FMI_EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  CALL(core_enter_initialization_mode(M, "fmi2EnterInitializationMode"))
}

UDMAP_FMI_EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  CALL(core_exit_initialization_mode(M, "fmi2ExitInitializationMode"))
}

UDMAP_FMI_EXPORT fmi2Status fmi2Terminate(fmi2Component c) {
  CALL(core_terminate(M, "fmi2Terminate"))
}

UDMAP_FMI_EXPORT fmi2Status fmi2Reset(fmi2Component c) { CALL(core_reset(M, "fmi2Reset")) }

/* ---------------------------------------------------------------- get and set */

UDMAP_FMI_EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, fmi2Real value[]) {
  CALL(core_get(M, "fmi2GetReal", REAL, ELEM_FLOAT64, VR(vr), nvr, value, nvr))
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[],
                                           size_t nvr, fmi2Integer value[]) {
  CALL(core_get(M, "fmi2GetInteger", INTEGER, ELEM_INT, VR(vr), nvr, value, nvr))
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                                           size_t nvr, fmi2Boolean value[]) {
  CALL(core_get(M, "fmi2GetBoolean", BOOLEAN, ELEM_INT, VR(vr), nvr, value, nvr))
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[],
                                          size_t nvr, fmi2String value[]) {
  (void)vr, (void)value;
  CALL(core_no_variables(M, "fmi2GetString", false, nvr))
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Real value[]) {
  CALL(core_set(M, "fmi2SetReal", REAL, ELEM_FLOAT64, VR(vr), nvr, value, nvr))
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[],
                                           size_t nvr, const fmi2Integer value[]) {
  CALL(core_set(M, "fmi2SetInteger", INTEGER, ELEM_INT, VR(vr), nvr, value, nvr))
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                                           size_t nvr, const fmi2Boolean value[]) {
  CALL(core_set(M, "fmi2SetBoolean", BOOLEAN, ELEM_INT, VR(vr), nvr, value, nvr))
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[],
                                          size_t nvr, const fmi2String value[]) {
  (void)vr, (void)value;
  CALL(core_no_variables(M, "fmi2SetString", true, nvr))
}

/* ---------------------------------------------------------------- FMU state, derivatives */

UDMAP_FMI_EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
  CALL(core_get_state(M, "fmi2GetFMUstate", FMUstate))
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
  CALL(core_set_state(M, "fmi2SetFMUstate", FMUstate))
}

UDMAP_FMI_EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
  CALL(core_free_state(M, "fmi2FreeFMUstate", FMUstate))
}

UDMAP_FMI_EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate,
                                                       size_t *size) {
  (void)FMUstate;
  CALL(core_serialized_state_size(M, "fmi2SerializedFMUstateSize", size))
}

UDMAP_FMI_EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                                  fmi2Byte serializedState[], size_t size) {
  CALL(core_serialize_state(M, "fmi2SerializeFMUstate", FMUstate, serializedState, size))
}

UDMAP_FMI_EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c,
                                                    const fmi2Byte serializedState[],
                                                    size_t size, fmi2FMUstate *FMUstate) {
  CALL(core_deserialize_state(M, "fmi2DeSerializeFMUstate", serializedState, size, FMUstate))
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetDirectionalDerivative(
    fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
    const fmi2ValueReference vKnown_ref[], size_t nKnown, const fmi2Real dvKnown[],
    fmi2Real dvUnknown[]) {
  CALL(core_directional_derivative(M, "fmi2GetDirectionalDerivative", VR(vUnknown_ref),
                                   nUnknown, VR(vKnown_ref), nKnown, dvKnown, nKnown,
                                   dvUnknown, nUnknown))
}

/* ---------------------------------------------------------------- model exchange */

UDMAP_FMI_EXPORT fmi2Status fmi2EnterEventMode(fmi2Component c) {
  CALL(core_enter_event_mode(M, "fmi2EnterEventMode"))
}

UDMAP_FMI_EXPORT fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *eventInfo) {
  EventInfo e;
  Status st = c ? core_update_discrete_states(M, "fmi2NewDiscreteStates", &e) : Error;
  if (st == OK && eventInfo) {
    eventInfo->newDiscreteStatesNeeded = e.discreteStatesNeedUpdate;
    eventInfo->terminateSimulation = e.terminateSimulation;
    eventInfo->nominalsOfContinuousStatesChanged = e.nominalsChanged;
    eventInfo->valuesOfContinuousStatesChanged = e.valuesChanged;
    eventInfo->nextEventTimeDefined = e.nextEventTimeDefined;
    eventInfo->nextEventTime = e.nextEventTime;
  }
  return (fmi2Status)st;
}

UDMAP_FMI_EXPORT fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
  CALL(core_enter_continuous_time_mode(M, "fmi2EnterContinuousTimeMode"))
}

UDMAP_FMI_EXPORT fmi2Status fmi2CompletedIntegratorStep(fmi2Component c,
                                                        fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                                        fmi2Boolean *enterEventMode,
                                                        fmi2Boolean *terminateSimulation) {
  (void)noSetFMUStatePriorToCurrentPoint;
  bool event = false, stop = false;
  Status st = c ? core_completed_integrator_step(M, "fmi2CompletedIntegratorStep", &event,
                                                 &stop) : Error;
  if (enterEventMode) *enterEventMode = event ? fmi2True : fmi2False;
  if (terminateSimulation) *terminateSimulation = stop ? fmi2True : fmi2False;
  return (fmi2Status)st;
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time) {
  CALL(core_set_time(M, "fmi2SetTime", time))
}

UDMAP_FMI_EXPORT fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[],
                                                    size_t nx) {
  CALL(core_empty_vector(M, "fmi2SetContinuousStates", CORE_MASK_ME_RUN, x, nx))
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[],
                                               size_t nx) {
  CALL(core_empty_vector(M, "fmi2GetDerivatives", CORE_MASK_GET, derivatives, nx))
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[],
                                                   size_t ni) {
  CALL(core_empty_vector(M, "fmi2GetEventIndicators", CORE_MASK_GET, eventIndicators, ni))
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {
  CALL(core_empty_vector(M, "fmi2GetContinuousStates", CORE_MASK_GET, x, nx))
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c,
                                                              fmi2Real x_nominal[], size_t nx) {
  CALL(core_empty_vector(M, "fmi2GetNominalsOfContinuousStates", CORE_MASK_GET, x_nominal, nx))
}

/* ---------------------------------------------------------------- co-simulation */

UDMAP_FMI_EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c,
                                                        const fmi2ValueReference vr[],
                                                        size_t nvr, const fmi2Integer order[],
                                                        const fmi2Real value[]) {
  (void)vr, (void)order, (void)value;
  if (c && nvr == 0) return core_begin(M, "fmi2SetRealInputDerivatives", CORE_MASK_SET)
                                ? fmi2OK : fmi2Error;
  CALL(core_not_provided(M, "fmi2SetRealInputDerivatives", "the FMU cannot interpolate inputs"))
}

UDMAP_FMI_EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c,
                                                         const fmi2ValueReference vr[],
                                                         size_t nvr, const fmi2Integer order[],
                                                         fmi2Real value[]) {
  (void)vr, (void)order, (void)value;
  CALL(core_no_variables(M, "fmi2GetRealOutputDerivatives", false, nvr))
}

UDMAP_FMI_EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                                       fmi2Real communicationStepSize,
                                       fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
  (void)noSetFMUStatePriorToCurrentPoint;
  CALL(core_do_step(M, "fmi2DoStep", currentCommunicationPoint, communicationStepSize))
}

UDMAP_FMI_EXPORT fmi2Status fmi2CancelStep(fmi2Component c) {
  CALL(core_not_provided(M, "fmi2CancelStep",
                         "no step is pending (fmi2DoStep never returns fmi2Pending)"))
}

/* Status kinds: fmi2DoStepStatus (OK), fmi2LastSuccessfulTime and fmi2Terminated (false). */
typedef enum { STATUS, REAL_STATUS, INTEGER_STATUS, BOOLEAN_STATUS, STRING_STATUS } StatusType;

static fmi2Status get_status(fmi2Component c, const char *fn, StatusType t, fmi2StatusKind s,
                             void *value) {
  if (!c || !core_begin(M, fn, StepMode | Terminated)) return fmi2Error;
  if (value && s == fmi2DoStepStatus && t == STATUS) {
    *(fmi2Status *)value = fmi2OK;
    return fmi2OK;
  }
  if (value && s == fmi2LastSuccessfulTime && t == REAL_STATUS) {
    *(fmi2Real *)value = M->value[vr_time];
    return fmi2OK;
  }
  if (value && s == fmi2Terminated && t == BOOLEAN_STATUS) {
    *(fmi2Boolean *)value = fmi2False;
    return fmi2OK;
  }
  model_log(M, Discard, "%s: status kind %d is not available", fn, (int)s);
  return fmi2Discard;
}

#define STATUS_GETTER(Name, Type, kind)                                                   \
  UDMAP_FMI_EXPORT fmi2Status fmi2Get##Name(fmi2Component c, const fmi2StatusKind s,        \
                                            Type *value) {                                  \
    return get_status(c, "fmi2Get" #Name, kind, s, value);                                  \
  }

STATUS_GETTER(Status, fmi2Status, STATUS)
STATUS_GETTER(RealStatus, fmi2Real, REAL_STATUS)
STATUS_GETTER(IntegerStatus, fmi2Integer, INTEGER_STATUS)
STATUS_GETTER(BooleanStatus, fmi2Boolean, BOOLEAN_STATUS)
STATUS_GETTER(StringStatus, fmi2String, STRING_STATUS)
