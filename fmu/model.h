/*
 * The udmap-specific part of the FMU, shared by the FMI 2 and FMI 3 layers: the values of
 * all variables, the kernel handles (blade, damper, model) and the lazy, staged evaluation
 * of the outputs (stages.c), the FMI state machine, logging, and the FMU state.
 */
#ifndef UDMAP_FMU_MODEL_H
#define UDMAP_FMU_MODEL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "case.h"
#include "config.h"
#include "udmap.h"

/* Same numbers as fmi2Status / fmi3Status. */
typedef enum { OK, Warning, Discard, Error, Fatal } Status;

/* Interface states; each FMI function has a mask of the states it may be called in. */
typedef enum {
  StartAndEnd = 1 << 0,
  Instantiated = 1 << 1,
  InitializationMode = 1 << 2,
  StepMode = 1 << 3,           /* co-simulation */
  EventMode = 1 << 4,          /* model exchange */
  ContinuousTimeMode = 1 << 5, /* model exchange */
  Terminated = 1 << 6
} ModelState;

/* The interface an instance was created for (same numbers as fmi2Type). */
typedef enum { ModelExchange, CoSimulation } InterfaceType;

/* Log categories (bits), named as in the modelDescription's LogCategories. */
enum {
  LOG_WARNING = 1 << 0,
  LOG_DISCARD = 1 << 1,
  LOG_ERROR = 1 << 2,
  LOG_EVENTS = 1 << 3,
  LOG_CALLS = 1 << 4,
  LOG_ALL = (1 << 5) - 1,
  LOG_DEFAULT = LOG_WARNING | LOG_DISCARD | LOG_ERROR
};

/* Evaluation stages of the outputs; each runs at most once per set of values. */
typedef enum {
  STAGE_BLADE,  /* udmap_new_blade_beam */
  STAGE_DAMPER, /* udmap_new_damper_asymmetric, traced at the start value of CF */
  STAGE_CF,     /* udmap_damper_set_CF to the current CF */
  STAGE_MODEL,  /* udmap_new_model */
  STAGE_LIMIT,  /* udmap_model_limit_force, udmap_damper_get_info */
  STAGE_POINT,  /* udmap_model_backbone or udmap_model_response for F_E */
  STAGE_F1,     /* bare first natural frequency (f_res of an unbounded response) */
  STAGE_COVER,  /* udmap_model_cover_forces over [F_E_min, F_E_max] at the current harmonics */
  NSTAGES
} Stage;

typedef struct ModelInstance ModelInstance;

/* Emits one formatted message through the importer's logger (set by the FMI layer). */
typedef void (*LogEmitter)(ModelInstance *m, Status status, const char *category,
                           const char *message);

struct ModelInstance {
  /* FMI bookkeeping */
  char *instanceName;
  int fmiVersion; /* 2 or 3 */
  InterfaceType type;
  ModelState state;
  LogEmitter emit;
  void *logger;      /* the importer's callback, called by emit */
  void *environment; /* the importer's environment pointer */
  unsigned logMask;  /* enabled LOG_* categories */
  bool stopTimeDefined;
  double stopTime;

  /* the case of an FMU made by `udmap fmu` (NULL: the generic FMU of blade A), and the
   * instantiation token the instance answers to */
  CaseConfig *config;
  bool owns_config;
  char token[40];

  /* every point solved exactly, no force table (the finite-difference scratch instance,
   * whose differences of 1e-4 would magnify the table's 1e-6 interpolation error) */
  bool exact_points;

  /* values of all variables by value reference (time at vr_time); outputs are computed */
  double value[UDMAP_NVARS];

  /* kernel */
  udmap_error err;
  udmap_blade blade;
  udmap_damper damper;
  udmap_model model;
  double damper_CF; /* the centrifugal load the damper currently has */

  /* staged evaluation */
  unsigned done; /* stages evaluated for the current values (bit per Stage) */
  Status stage_status[NSTAGES];
  char stage_message[NSTAGES][512];
  double F_lim;
  double F_lim_backbone;
  udmap_damper_info info;
  udmap_point point;
  int jump; /* the point sits at a jump of k(gamma) */
  double f1_bare;

  /* the force range prepared by the last cover (STAGE_COVER) [N], what it cost, and whether a
   * force outside it was logged (once per range) */
  double cover_lo, cover_hi;
  double cover_seconds;
  int cover_points, cover_leaves, cover_exact;
  bool outside_logged;

  /* the analysis settings the model was built with, the model of the plausibility checks
   * (over the same blade, damper and settings; dropped with the model), the kinds (bit per UDMAP_WARNING_*) of the plausibility warnings of the
   * last check, and whether the blade, damper, CF or band changed since */
  udmap_analysis analysis;
  udmap_model probe;
  unsigned plausibility_kinds;
  bool plausibility_stale;

  /* counters, for tests and diagnostics (not part of the FMU state) */
  unsigned long stage_runs[NSTAGES];

  /* a second instance for the finite differences of the directional derivatives, so that
   * the caches of this one are kept (created on first use, derivatives.c) */
  struct ModelInstance *scratch;
};

ModelInstance *model_new(const char *instanceName, int fmiVersion, InterfaceType type,
                         LogEmitter emit, void *logger, void *environment, bool loggingOn);
void model_free(ModelInstance *m);
/* Start values, no kernel objects, state Instantiated. */
void model_reset(ModelInstance *m);
/* Makes m the FMU of a case (taking ownership if owns) and resets it to the case's starts. */
void model_set_case(ModelInstance *m, CaseConfig *config, bool owns);
/* Whether variable vr exists in this FMU (a case FMU leaves out what does not apply). */
bool model_has(const ModelInstance *m, unsigned vr);
/* The start value of variable vr: the case's, or that of the generic FMU (blade A). */
double model_start_value(const ModelInstance *m, int vr);

/* printf-style message through the logger, if its category is enabled. */
void model_log(ModelInstance *m, Status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void model_log_category(ModelInstance *m, unsigned category, Status status, const char *fmt,
                        ...) __attribute__((format(printf, 4, 5)));
/* Enables (on) or disables the named categories; n = 0 means all of them. */
Status model_set_debug_logging(ModelInstance *m, bool on, size_t n, const char *const names[]);

/* State-machine check: logs and returns false when `fn` may not be called now. */
bool model_allowed(ModelInstance *m, const char *fn, unsigned mask);

/* Sets variable vr from a value of type `type` (Integer and Boolean passed as double); with
 * apply = false only checks. Discard (value not taken) for a NaN, an infinity or a value out
 * of range; Error for an unknown vr, a type mismatch or a variable that cannot be set. */
Status model_set(ModelInstance *m, const char *fn, ValueReference vr, VariableType type,
                 double value, bool apply);

/* Gets variable vr as type `type`, computing outputs on demand. `logged` collects the stages
 * whose failure was already logged during this call (start with 0). */
Status model_get(ModelInstance *m, const char *fn, ValueReference vr, VariableType type,
                 double *value, unsigned *logged);

/* The end of the initialization (ExitInitializationMode): builds the blade, damper and model
 * and prepares the force range [F_E_min, F_E_max] (stages.c), logging its time in one line.
 * Error (logged, naming the variables) for a range with F_E_min >= F_E_max; any other
 * failure is left to the gets, as before the range existed. */
Status model_prepare(ModelInstance *m, const char *fn);

/* Advances time over a communication step (the outputs are quasi-steady). */
Status model_do_step(ModelInstance *m, const char *fn, double t, double h);

/* Marks stale the stages a change of a value of `group` feeds (stages.c). */
void model_invalidate(ModelInstance *m, Group group);

/* The value of output vr for the current values (computed on demand, stages.c) and the stage
 * whose status and message it carries. */
Status model_output(ModelInstance *m, ValueReference vr, double *value, Stage *stage);
const char *model_stage_message(const ModelInstance *m, Stage stage);
/* Copies the values of all inputs and parameters of src into m (invalidating what changed). */
void model_copy_values(ModelInstance *m, const ModelInstance *src);

/* Directional derivative (derivatives.c): sensitivity[i] = sum_j d unknowns[i] / d knowns[j]
 * seed[j], the unknowns real outputs, the knowns real inputs or tunable parameters. */
Status model_directional_derivative(ModelInstance *m, const char *fn,
                                    const unsigned unknowns[], size_t nUnknowns,
                                    const unsigned knowns[], size_t nKnowns,
                                    const double seed[], double sensitivity[]);

/* FMU state: the values of all variables and the time, as one plain block. */
typedef struct {
  uint64_t magic;
  uint64_t size;
  char token[40];
  double value[UDMAP_NVARS];
} ModelSnapshot;

ModelSnapshot *model_snapshot(ModelInstance *m, ModelSnapshot *reuse);
Status model_restore(ModelInstance *m, const char *fn, const ModelSnapshot *s);
Status model_check_snapshot(ModelInstance *m, const char *fn, const void *data, size_t size);

#endif /* UDMAP_FMU_MODEL_H */
