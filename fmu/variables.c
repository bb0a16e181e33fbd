/* The variable table as data, and the instantiation token derived from it. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "config.h"

const VariableInfo udmap_variables[UDMAP_NVARS] = {
#define UDMAP_X_ROW(name, type, caus, group, unit, start, min, max, flags, desc) \
  {#name, type, caus, GROUP_##group, unit, (double)(start), \
   ((min) == NOLIMIT ? -NOLIMIT : (double)(min)), (double)(max), flags, desc},
  UDMAP_VARIABLE_TABLE(UDMAP_X_ROW)
#undef UDMAP_X_ROW
};

static uint64_t fnv1a(uint64_t h, const void *data, size_t n) {
  const unsigned char *p = data;
  for (size_t i = 0; i < n; i++) {
    h ^= p[i];
    h *= 0x100000001b3ULL;
  }
  return h;
}

static uint64_t hash_table(uint64_t h) {
  h = fnv1a(h, UDMAP_FMU_VERSION, strlen(UDMAP_FMU_VERSION));
  for (int i = 0; i < UDMAP_NVARS; i++) {
    const VariableInfo *v = &udmap_variables[i];
    int ints[4] = {(int)v->type, (int)v->causality, (int)v->group, v->flags};
    double reals[3] = {v->start, v->min, v->max};
    h = fnv1a(h, v->name, strlen(v->name) + 1);
    h = fnv1a(h, v->unit, strlen(v->unit) + 1);
    h = fnv1a(h, ints, sizeof ints);
    h = fnv1a(h, reals, sizeof reals);
  }
  return h;
}

void udmap_fmu_token(char *buf, size_t buflen) {
  uint64_t a = hash_table(0xcbf29ce484222325ULL);
  uint64_t b = hash_table(a ^ 0x9e3779b97f4a7c15ULL);
  snprintf(buf, buflen, "{%08x-%04x-%04x-%04x-%012llx}", (unsigned)(a >> 32),
           (unsigned)((a >> 16) & 0xffffu), (unsigned)(a & 0xffffu),
           (unsigned)(b >> 48), (unsigned long long)(b & 0xffffffffffffULL));
}
