/*
 * The FMI 3.0 types and functions, declared here from the standard's interface so the build
 * needs no external headers. The ABI test (tests/python/test_fmu_binary.py) compiles
 * fmi3Functions.c against the standard headers shipped with fmpy instead; when those are
 * included first, this file steps aside.
 */
#ifndef fmi3Functions_h
#ifndef UDMAP_FMI3_API_H
#define UDMAP_FMI3_API_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef _WIN32
#define UDMAP_FMI_EXPORT __declspec(dllexport) /* the DLL exports these only */
#else
#define UDMAP_FMI_EXPORT __attribute__((visibility("default")))
#endif

typedef void *fmi3Instance;
typedef void *fmi3InstanceEnvironment;
typedef void *fmi3FMUState;
typedef uint32_t fmi3ValueReference;
typedef float fmi3Float32;
typedef double fmi3Float64;
typedef int8_t fmi3Int8;
typedef uint8_t fmi3UInt8;
typedef int16_t fmi3Int16;
typedef uint16_t fmi3UInt16;
typedef int32_t fmi3Int32;
typedef uint32_t fmi3UInt32;
typedef int64_t fmi3Int64;
typedef uint64_t fmi3UInt64;
typedef bool fmi3Boolean;
typedef char fmi3Char;
typedef const fmi3Char *fmi3String;
typedef uint8_t fmi3Byte;
typedef const fmi3Byte *fmi3Binary;
typedef bool fmi3Clock;

#define fmi3True true
#define fmi3False false
#define fmi3Version "3.0"

typedef enum { fmi3OK, fmi3Warning, fmi3Discard, fmi3Error, fmi3Fatal } fmi3Status;
typedef enum {
  fmi3Independent,
  fmi3Constant,
  fmi3Fixed,
  fmi3Tunable,
  fmi3Discrete,
  fmi3Dependent
} fmi3DependencyKind;
typedef enum {
  fmi3IntervalNotYetKnown,
  fmi3IntervalUnchanged,
  fmi3IntervalChanged
} fmi3IntervalQualifier;

typedef void (*fmi3LogMessageCallback)(fmi3InstanceEnvironment, fmi3Status, fmi3String,
                                       fmi3String);
typedef void (*fmi3ClockUpdateCallback)(fmi3InstanceEnvironment);
typedef void (*fmi3IntermediateUpdateCallback)(fmi3InstanceEnvironment, fmi3Float64, fmi3Boolean,
                                               fmi3Boolean, fmi3Boolean, fmi3Boolean,
                                               fmi3Boolean *, fmi3Float64 *);
typedef void (*fmi3LockPreemptionCallback)(void);
typedef void (*fmi3UnlockPreemptionCallback)(void);

#define UDMAP_FMI3(ret, name, args) UDMAP_FMI_EXPORT ret name args;
#define UDMAP_FMI3_GETSET(T)                                                              \
  UDMAP_FMI3(fmi3Status, fmi3Get##T,                                                      \
             (fmi3Instance, const fmi3ValueReference[], size_t, fmi3##T[], size_t))        \
  UDMAP_FMI3(fmi3Status, fmi3Set##T,                                                      \
             (fmi3Instance, const fmi3ValueReference[], size_t, const fmi3##T[], size_t))

UDMAP_FMI3(const char *, fmi3GetVersion, (void))
UDMAP_FMI3(fmi3Status, fmi3SetDebugLogging, (fmi3Instance, fmi3Boolean, size_t, const fmi3String[]))
UDMAP_FMI3(fmi3Instance, fmi3InstantiateModelExchange,
           (fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean,
            fmi3InstanceEnvironment, fmi3LogMessageCallback))
UDMAP_FMI3(fmi3Instance, fmi3InstantiateCoSimulation,
           (fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean, fmi3Boolean,
            fmi3Boolean, const fmi3ValueReference[], size_t, fmi3InstanceEnvironment,
            fmi3LogMessageCallback, fmi3IntermediateUpdateCallback))
UDMAP_FMI3(fmi3Instance, fmi3InstantiateScheduledExecution,
           (fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean,
            fmi3InstanceEnvironment, fmi3LogMessageCallback, fmi3ClockUpdateCallback,
            fmi3LockPreemptionCallback, fmi3UnlockPreemptionCallback))
UDMAP_FMI3(void, fmi3FreeInstance, (fmi3Instance))
UDMAP_FMI3(fmi3Status, fmi3EnterInitializationMode,
           (fmi3Instance, fmi3Boolean, fmi3Float64, fmi3Float64, fmi3Boolean, fmi3Float64))
UDMAP_FMI3(fmi3Status, fmi3ExitInitializationMode, (fmi3Instance))
UDMAP_FMI3(fmi3Status, fmi3EnterEventMode, (fmi3Instance))
UDMAP_FMI3(fmi3Status, fmi3Terminate, (fmi3Instance))
UDMAP_FMI3(fmi3Status, fmi3Reset, (fmi3Instance))
UDMAP_FMI3_GETSET(Float32)
UDMAP_FMI3_GETSET(Float64)
UDMAP_FMI3_GETSET(Int8)
UDMAP_FMI3_GETSET(UInt8)
UDMAP_FMI3_GETSET(Int16)
UDMAP_FMI3_GETSET(UInt16)
UDMAP_FMI3_GETSET(Int32)
UDMAP_FMI3_GETSET(UInt32)
UDMAP_FMI3_GETSET(Int64)
UDMAP_FMI3_GETSET(UInt64)
UDMAP_FMI3_GETSET(Boolean)
UDMAP_FMI3_GETSET(String)
UDMAP_FMI3(fmi3Status, fmi3GetBinary,
           (fmi3Instance, const fmi3ValueReference[], size_t, size_t[], fmi3Binary[], size_t))
UDMAP_FMI3(fmi3Status, fmi3SetBinary,
           (fmi3Instance, const fmi3ValueReference[], size_t, const size_t[],
            const fmi3Binary[], size_t))
UDMAP_FMI3(fmi3Status, fmi3GetClock, (fmi3Instance, const fmi3ValueReference[], size_t,
                                      fmi3Clock[]))
UDMAP_FMI3(fmi3Status, fmi3SetClock, (fmi3Instance, const fmi3ValueReference[], size_t,
                                      const fmi3Clock[]))
UDMAP_FMI3(fmi3Status, fmi3GetNumberOfVariableDependencies,
           (fmi3Instance, fmi3ValueReference, size_t *))
UDMAP_FMI3(fmi3Status, fmi3GetVariableDependencies,
           (fmi3Instance, fmi3ValueReference, size_t[], fmi3ValueReference[], size_t[],
            fmi3DependencyKind[], size_t))
UDMAP_FMI3(fmi3Status, fmi3GetFMUState, (fmi3Instance, fmi3FMUState *))
UDMAP_FMI3(fmi3Status, fmi3SetFMUState, (fmi3Instance, fmi3FMUState))
UDMAP_FMI3(fmi3Status, fmi3FreeFMUState, (fmi3Instance, fmi3FMUState *))
UDMAP_FMI3(fmi3Status, fmi3SerializedFMUStateSize, (fmi3Instance, fmi3FMUState, size_t *))
UDMAP_FMI3(fmi3Status, fmi3SerializeFMUState, (fmi3Instance, fmi3FMUState, fmi3Byte[], size_t))
UDMAP_FMI3(fmi3Status, fmi3DeserializeFMUState,
           (fmi3Instance, const fmi3Byte[], size_t, fmi3FMUState *))
UDMAP_FMI3(fmi3Status, fmi3GetDirectionalDerivative,
           (fmi3Instance, const fmi3ValueReference[], size_t, const fmi3ValueReference[],
            size_t, const fmi3Float64[], size_t, fmi3Float64[], size_t))
UDMAP_FMI3(fmi3Status, fmi3GetAdjointDerivative,
           (fmi3Instance, const fmi3ValueReference[], size_t, const fmi3ValueReference[],
            size_t, const fmi3Float64[], size_t, fmi3Float64[], size_t))
UDMAP_FMI3(fmi3Status, fmi3EnterConfigurationMode, (fmi3Instance))
UDMAP_FMI3(fmi3Status, fmi3ExitConfigurationMode, (fmi3Instance))
UDMAP_FMI3(fmi3Status, fmi3GetIntervalDecimal,
           (fmi3Instance, const fmi3ValueReference[], size_t, fmi3Float64[],
            fmi3IntervalQualifier[]))
UDMAP_FMI3(fmi3Status, fmi3GetIntervalFraction,
           (fmi3Instance, const fmi3ValueReference[], size_t, fmi3UInt64[], fmi3UInt64[],
            fmi3IntervalQualifier[]))
UDMAP_FMI3(fmi3Status, fmi3GetShiftDecimal,
           (fmi3Instance, const fmi3ValueReference[], size_t, fmi3Float64[]))
UDMAP_FMI3(fmi3Status, fmi3GetShiftFraction,
           (fmi3Instance, const fmi3ValueReference[], size_t, fmi3UInt64[], fmi3UInt64[]))
UDMAP_FMI3(fmi3Status, fmi3SetIntervalDecimal,
           (fmi3Instance, const fmi3ValueReference[], size_t, const fmi3Float64[]))
UDMAP_FMI3(fmi3Status, fmi3SetIntervalFraction,
           (fmi3Instance, const fmi3ValueReference[], size_t, const fmi3UInt64[],
            const fmi3UInt64[]))
UDMAP_FMI3(fmi3Status, fmi3SetShiftDecimal,
           (fmi3Instance, const fmi3ValueReference[], size_t, const fmi3Float64[]))
UDMAP_FMI3(fmi3Status, fmi3SetShiftFraction,
           (fmi3Instance, const fmi3ValueReference[], size_t, const fmi3UInt64[],
            const fmi3UInt64[]))
UDMAP_FMI3(fmi3Status, fmi3EvaluateDiscreteStates, (fmi3Instance))
UDMAP_FMI3(fmi3Status, fmi3UpdateDiscreteStates,
           (fmi3Instance, fmi3Boolean *, fmi3Boolean *, fmi3Boolean *, fmi3Boolean *,
            fmi3Boolean *, fmi3Float64 *))
UDMAP_FMI3(fmi3Status, fmi3EnterContinuousTimeMode, (fmi3Instance))
UDMAP_FMI3(fmi3Status, fmi3CompletedIntegratorStep,
           (fmi3Instance, fmi3Boolean, fmi3Boolean *, fmi3Boolean *))
UDMAP_FMI3(fmi3Status, fmi3SetTime, (fmi3Instance, fmi3Float64))
UDMAP_FMI3(fmi3Status, fmi3SetContinuousStates, (fmi3Instance, const fmi3Float64[], size_t))
UDMAP_FMI3(fmi3Status, fmi3GetContinuousStateDerivatives, (fmi3Instance, fmi3Float64[], size_t))
UDMAP_FMI3(fmi3Status, fmi3GetEventIndicators, (fmi3Instance, fmi3Float64[], size_t))
UDMAP_FMI3(fmi3Status, fmi3GetContinuousStates, (fmi3Instance, fmi3Float64[], size_t))
UDMAP_FMI3(fmi3Status, fmi3GetNominalsOfContinuousStates, (fmi3Instance, fmi3Float64[], size_t))
UDMAP_FMI3(fmi3Status, fmi3GetNumberOfEventIndicators, (fmi3Instance, size_t *))
UDMAP_FMI3(fmi3Status, fmi3GetNumberOfContinuousStates, (fmi3Instance, size_t *))
UDMAP_FMI3(fmi3Status, fmi3EnterStepMode, (fmi3Instance))
UDMAP_FMI3(fmi3Status, fmi3GetOutputDerivatives,
           (fmi3Instance, const fmi3ValueReference[], size_t, const fmi3Int32[], fmi3Float64[],
            size_t))
UDMAP_FMI3(fmi3Status, fmi3DoStep,
           (fmi3Instance, fmi3Float64, fmi3Float64, fmi3Boolean, fmi3Boolean *, fmi3Boolean *,
            fmi3Boolean *, fmi3Float64 *))
UDMAP_FMI3(fmi3Status, fmi3ActivateModelPartition,
           (fmi3Instance, fmi3ValueReference, fmi3Float64))

#undef UDMAP_FMI3_GETSET
#undef UDMAP_FMI3
#endif /* UDMAP_FMI3_API_H */
#else
#define UDMAP_FMI_EXPORT __attribute__((visibility("default")))
#endif /* fmi3Functions_h */
