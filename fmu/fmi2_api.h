/*
 * The FMI 2.0 types and functions this FMU implements (model exchange and co-simulation), declared here from
 * the standard's interface so the build needs no external headers. The ABI test
 * (tests/python/test_fmu_binary.py) compiles fmi2Functions.c against the standard headers
 * shipped with fmpy instead; when those are included first, this file steps aside.
 */
#ifndef fmi2Functions_h
#ifndef UDMAP_FMI2_API_H
#define UDMAP_FMI2_API_H

#include <stddef.h>

#ifdef _WIN32
#define UDMAP_FMI_EXPORT __declspec(dllexport) /* the DLL exports these only */
#else
#define UDMAP_FMI_EXPORT __attribute__((visibility("default")))
#endif

typedef void *fmi2Component;
typedef void *fmi2ComponentEnvironment;
typedef void *fmi2FMUstate;
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Integer;
typedef int fmi2Boolean;
typedef char fmi2Char;
typedef const fmi2Char *fmi2String;
typedef char fmi2Byte;

#define fmi2True 1
#define fmi2False 0
#define fmi2TypesPlatform "default"
#define fmi2Version "2.0"

typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;
typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;
typedef enum {
  fmi2DoStepStatus,
  fmi2PendingStatus,
  fmi2LastSuccessfulTime,
  fmi2Terminated
} fmi2StatusKind;

typedef void (*fmi2CallbackLogger)(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String,
                                   fmi2String, ...);
typedef void *(*fmi2CallbackAllocateMemory)(size_t, size_t);
typedef void (*fmi2CallbackFreeMemory)(void *);
typedef void (*fmi2StepFinished)(fmi2ComponentEnvironment, fmi2Status);

typedef struct {
  const fmi2CallbackLogger logger;
  const fmi2CallbackAllocateMemory allocateMemory;
  const fmi2CallbackFreeMemory freeMemory;
  const fmi2StepFinished stepFinished;
  const fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;

typedef struct {
  fmi2Boolean newDiscreteStatesNeeded;
  fmi2Boolean terminateSimulation;
  fmi2Boolean nominalsOfContinuousStatesChanged;
  fmi2Boolean valuesOfContinuousStatesChanged;
  fmi2Boolean nextEventTimeDefined;
  fmi2Real nextEventTime;
} fmi2EventInfo;

#define UDMAP_FMI2(ret, name, args) UDMAP_FMI_EXPORT ret name args;

UDMAP_FMI2(const char *, fmi2GetTypesPlatform, (void))
UDMAP_FMI2(const char *, fmi2GetVersion, (void))
UDMAP_FMI2(fmi2Status, fmi2SetDebugLogging,
           (fmi2Component, fmi2Boolean, size_t, const fmi2String[]))
UDMAP_FMI2(fmi2Component, fmi2Instantiate,
           (fmi2String, fmi2Type, fmi2String, fmi2String, const fmi2CallbackFunctions *,
            fmi2Boolean, fmi2Boolean))
UDMAP_FMI2(void, fmi2FreeInstance, (fmi2Component))
UDMAP_FMI2(fmi2Status, fmi2SetupExperiment,
           (fmi2Component, fmi2Boolean, fmi2Real, fmi2Real, fmi2Boolean, fmi2Real))
UDMAP_FMI2(fmi2Status, fmi2EnterInitializationMode, (fmi2Component))
UDMAP_FMI2(fmi2Status, fmi2ExitInitializationMode, (fmi2Component))
UDMAP_FMI2(fmi2Status, fmi2Terminate, (fmi2Component))
UDMAP_FMI2(fmi2Status, fmi2Reset, (fmi2Component))
UDMAP_FMI2(fmi2Status, fmi2GetReal,
           (fmi2Component, const fmi2ValueReference[], size_t, fmi2Real[]))
UDMAP_FMI2(fmi2Status, fmi2GetInteger,
           (fmi2Component, const fmi2ValueReference[], size_t, fmi2Integer[]))
UDMAP_FMI2(fmi2Status, fmi2GetBoolean,
           (fmi2Component, const fmi2ValueReference[], size_t, fmi2Boolean[]))
UDMAP_FMI2(fmi2Status, fmi2GetString,
           (fmi2Component, const fmi2ValueReference[], size_t, fmi2String[]))
UDMAP_FMI2(fmi2Status, fmi2SetReal,
           (fmi2Component, const fmi2ValueReference[], size_t, const fmi2Real[]))
UDMAP_FMI2(fmi2Status, fmi2SetInteger,
           (fmi2Component, const fmi2ValueReference[], size_t, const fmi2Integer[]))
UDMAP_FMI2(fmi2Status, fmi2SetBoolean,
           (fmi2Component, const fmi2ValueReference[], size_t, const fmi2Boolean[]))
UDMAP_FMI2(fmi2Status, fmi2SetString,
           (fmi2Component, const fmi2ValueReference[], size_t, const fmi2String[]))
UDMAP_FMI2(fmi2Status, fmi2GetFMUstate, (fmi2Component, fmi2FMUstate *))
UDMAP_FMI2(fmi2Status, fmi2SetFMUstate, (fmi2Component, fmi2FMUstate))
UDMAP_FMI2(fmi2Status, fmi2FreeFMUstate, (fmi2Component, fmi2FMUstate *))
UDMAP_FMI2(fmi2Status, fmi2SerializedFMUstateSize, (fmi2Component, fmi2FMUstate, size_t *))
UDMAP_FMI2(fmi2Status, fmi2SerializeFMUstate, (fmi2Component, fmi2FMUstate, fmi2Byte[], size_t))
UDMAP_FMI2(fmi2Status, fmi2DeSerializeFMUstate,
           (fmi2Component, const fmi2Byte[], size_t, fmi2FMUstate *))
UDMAP_FMI2(fmi2Status, fmi2GetDirectionalDerivative,
           (fmi2Component, const fmi2ValueReference[], size_t, const fmi2ValueReference[],
            size_t, const fmi2Real[], fmi2Real[]))
UDMAP_FMI2(fmi2Status, fmi2EnterEventMode, (fmi2Component))
UDMAP_FMI2(fmi2Status, fmi2NewDiscreteStates, (fmi2Component, fmi2EventInfo *))
UDMAP_FMI2(fmi2Status, fmi2EnterContinuousTimeMode, (fmi2Component))
UDMAP_FMI2(fmi2Status, fmi2CompletedIntegratorStep,
           (fmi2Component, fmi2Boolean, fmi2Boolean *, fmi2Boolean *))
UDMAP_FMI2(fmi2Status, fmi2SetTime, (fmi2Component, fmi2Real))
UDMAP_FMI2(fmi2Status, fmi2SetContinuousStates, (fmi2Component, const fmi2Real[], size_t))
UDMAP_FMI2(fmi2Status, fmi2GetDerivatives, (fmi2Component, fmi2Real[], size_t))
UDMAP_FMI2(fmi2Status, fmi2GetEventIndicators, (fmi2Component, fmi2Real[], size_t))
UDMAP_FMI2(fmi2Status, fmi2GetContinuousStates, (fmi2Component, fmi2Real[], size_t))
UDMAP_FMI2(fmi2Status, fmi2GetNominalsOfContinuousStates, (fmi2Component, fmi2Real[], size_t))
UDMAP_FMI2(fmi2Status, fmi2SetRealInputDerivatives,
           (fmi2Component, const fmi2ValueReference[], size_t, const fmi2Integer[],
            const fmi2Real[]))
UDMAP_FMI2(fmi2Status, fmi2GetRealOutputDerivatives,
           (fmi2Component, const fmi2ValueReference[], size_t, const fmi2Integer[], fmi2Real[]))
UDMAP_FMI2(fmi2Status, fmi2DoStep, (fmi2Component, fmi2Real, fmi2Real, fmi2Boolean))
UDMAP_FMI2(fmi2Status, fmi2CancelStep, (fmi2Component))
UDMAP_FMI2(fmi2Status, fmi2GetStatus, (fmi2Component, const fmi2StatusKind, fmi2Status *))
UDMAP_FMI2(fmi2Status, fmi2GetRealStatus, (fmi2Component, const fmi2StatusKind, fmi2Real *))
UDMAP_FMI2(fmi2Status, fmi2GetIntegerStatus,
           (fmi2Component, const fmi2StatusKind, fmi2Integer *))
UDMAP_FMI2(fmi2Status, fmi2GetBooleanStatus,
           (fmi2Component, const fmi2StatusKind, fmi2Boolean *))
UDMAP_FMI2(fmi2Status, fmi2GetStringStatus, (fmi2Component, const fmi2StatusKind, fmi2String *))

#undef UDMAP_FMI2
#endif /* UDMAP_FMI2_API_H */
#else
#define UDMAP_FMI_EXPORT __attribute__((visibility("default")))
#endif /* fmi2Functions_h */
