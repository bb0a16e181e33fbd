/*
 * FMU configuration: model identifier, value references and the variable table
 * (fmu/variables.h), shared by the FMI 2 and FMI 3 layers and the description generator.
 */
#ifndef UDMAP_FMU_CONFIG_H
#define UDMAP_FMU_CONFIG_H

#include <stddef.h>

#include "variables.h"

#define MODEL_IDENTIFIER "udmap"
#define MODEL_NAME "udmap"
#define MODEL_DESCRIPTION \
  "Quasi-steady forced response of a turbine blade with a dry-friction underplatform damper " \
  "(convergence-free mapping, Gastaldi and Gola, MSSP 2024)"

#ifndef UDMAP_FMU_VERSION
#define UDMAP_FMU_VERSION "0.0.0"
#endif

typedef enum { REAL, INTEGER, BOOLEAN } VariableType;
typedef enum { INDEPENDENT, INPUT, PARAMETER, OUTPUT } Causality;

/* Groups: for inputs and parameters, what a change invalidates; for outputs, which
 * evaluation produces them (stages.c). */
typedef enum {
  GROUP_NONE,
  GROUP_FORCE,    /* F_E, f_exc: only the response point */
  GROUP_CF,       /* CF: rescale of the damper table, no tracing */
  GROUP_DAMPER,   /* mu, contact stiffnesses, geometry: new damper (traced again) */
  GROUP_BLADE,    /* beam parameters: new blade */
  GROUP_ANALYSIS, /* band and allowable stress: new model over the same blade and damper */
  GROUP_HARMONICS, /* harmonics: the response point only (the model keeps its caches) */
  GROUP_POINT,    /* outputs of the response point */
  GROUP_LIMIT,    /* outputs of the limit force and the damper information */
  GROUP_RATIO,    /* F_ratio: F_E over the limit force */
  GROUP_RANGE     /* F_E_min, F_E_max: the force range prepared in advance (the cover) */
} Group;

#define NOLIMIT __builtin_inf() /* bound marker: no min / max */
#define POSITIVE 1    /* flag: the value must be > 0 */
#define EVEN 2        /* flag: the integer must be even */
#define OPEN 4        /* flag: min and max are excluded */

typedef enum {
#define UDMAP_X_ENUM(name, type, caus, group, unit, start, min, max, flags, desc) vr_##name,
  UDMAP_VARIABLE_TABLE(UDMAP_X_ENUM)
#undef UDMAP_X_ENUM
  UDMAP_NVARS
} ValueReference;

typedef struct {
  const char *name;
  VariableType type;
  Causality causality;
  Group group;
  const char *unit;
  double start, min, max; /* min/max: +-NOLIMIT when absent */
  int flags;
  const char *description;
} VariableInfo;

extern const VariableInfo udmap_variables[UDMAP_NVARS];

/* The instantiation token (FMI 3) / GUID (FMI 2): a hash of the table and the version, so a
 * description and a binary built from different tables never match. Writes a NUL-terminated
 * string of 38 characters ("{xxxxxxxx-xxxx-xxxx-xxxx-xxxxxxxxxxxx}") into buf (>= 39). */
void udmap_fmu_token(char *buf, size_t buflen);

#endif /* UDMAP_FMU_CONFIG_H */
