/*
 * The FMI core shared by both FMI versions and both interfaces (model exchange and
 * co-simulation), in the manner of the Reference-FMUs' cosimulation.c: instantiation, the
 * state machine (each function checks the states it may be called in), the typed array
 * get/set, the mode changes, the FMU state, and the model-exchange functions of an FMU without
 * continuous states or event indicators. fmi2Functions.c and fmi3Functions.c only translate
 * the FMI signatures to these calls; the udmap numbers come from stages.c and derivatives.c.
 */
#ifndef UDMAP_FMU_CORE_H
#define UDMAP_FMU_CORE_H

#include <stdbool.h>
#include <stddef.h>

#include "model.h"

/* The C types an FMI version stores a variable type in (fmi2Integer and fmi2Boolean are
 * int, fmi3Int32 is int32_t, fmi3Boolean is bool). */
typedef enum { ELEM_FLOAT64, ELEM_INT, ELEM_BOOL } ElementType;

/* A new instance after the checks every instantiation needs; resources is the resource
 * location (an FMU made by `udmap fmu` has its case there, case.h) and token must be the
 * case's or, without a case, the binary's. NULL (with the reason logged through emit) when
 * they fail. */
ModelInstance *core_instantiate(const char *fn, const char *instanceName, int fmiVersion,
                                InterfaceType type, const char *token, const char *resources,
                                LogEmitter emit, void *logger, void *environment,
                                bool loggingOn);
/* The state-machine check and the logCalls message of every call; false: refuse the call. */
bool core_begin(ModelInstance *m, const char *fn, unsigned mask);

Status core_set_debug_logging(ModelInstance *m, const char *fn, bool on, size_t n,
                              const char *const names[]);
/* Start time and optional stop time (FMI 2 SetupExperiment, FMI 3 EnterInitializationMode). */
Status core_setup_experiment(ModelInstance *m, const char *fn, unsigned mask, double startTime,
                             bool stopTimeDefined, double stopTime);
Status core_enter_initialization_mode(ModelInstance *m, const char *fn);
Status core_exit_initialization_mode(ModelInstance *m, const char *fn);
Status core_terminate(ModelInstance *m, const char *fn);
Status core_reset(ModelInstance *m, const char *fn);

/* nValues must equal nvr (FMI 2 passes nvr). A set checks all values before taking any. */
Status core_get(ModelInstance *m, const char *fn, VariableType type, ElementType elem,
                const unsigned vr[], size_t nvr, void *values, size_t nValues);
Status core_set(ModelInstance *m, const char *fn, VariableType type, ElementType elem,
                const unsigned vr[], size_t nvr, const void *values, size_t nValues);
/* A type the FMU has no variables of: an empty call succeeds, any reference is an error. */
Status core_no_variables(ModelInstance *m, const char *fn, bool set, size_t nvr);
/* A function the FMU does not provide (logged as an error naming why). */
Status core_not_provided(ModelInstance *m, const char *fn, const char *why);

/* FMU state (fmi2FMUstate / fmi3FMUState is a ModelSnapshot). */
Status core_get_state(ModelInstance *m, const char *fn, void **state);
Status core_set_state(ModelInstance *m, const char *fn, const void *state);
Status core_free_state(ModelInstance *m, const char *fn, void **state);
Status core_serialized_state_size(ModelInstance *m, const char *fn, size_t *size);
Status core_serialize_state(ModelInstance *m, const char *fn, const void *state, void *buffer,
                            size_t size);
Status core_deserialize_state(ModelInstance *m, const char *fn, const void *buffer, size_t size,
                              void **state);

Status core_directional_derivative(ModelInstance *m, const char *fn, const unsigned unknowns[],
                                   size_t nUnknowns, const unsigned knowns[], size_t nKnowns,
                                   const double seed[], size_t nSeed, double sensitivity[],
                                   size_t nSensitivity);

/* co-simulation */
Status core_do_step(ModelInstance *m, const char *fn, double t, double h);

/* model exchange: no continuous states, no event indicators, no time events */
typedef struct {
  bool discreteStatesNeedUpdate, terminateSimulation, nominalsChanged, valuesChanged,
      nextEventTimeDefined;
  double nextEventTime;
} EventInfo;
Status core_enter_event_mode(ModelInstance *m, const char *fn);
Status core_update_discrete_states(ModelInstance *m, const char *fn, EventInfo *info);
Status core_enter_continuous_time_mode(ModelInstance *m, const char *fn);
Status core_completed_integrator_step(ModelInstance *m, const char *fn, bool *enterEventMode,
                                      bool *terminateSimulation);
Status core_set_time(ModelInstance *m, const char *fn, double time);
/* Set/get of continuous states, derivatives, event indicators, nominals: n must be 0. */
Status core_empty_vector(ModelInstance *m, const char *fn, unsigned mask, const void *array,
                         size_t n);

/* State masks of the calls the adapters check themselves. */
#define CORE_ALL_STATES                                                                       \
  (Instantiated | InitializationMode | StepMode | EventMode | ContinuousTimeMode | Terminated)
#define CORE_MASK_GET CORE_ALL_STATES
#define CORE_MASK_SET                                                                         \
  (Instantiated | InitializationMode | StepMode | EventMode | ContinuousTimeMode)
#define CORE_MASK_ME_RUN (EventMode | ContinuousTimeMode)

#endif /* UDMAP_FMU_CORE_H */
