/*
 * Benchmark driver of the FMU binaries (used by bench/bench_fmu.py): loads an unpacked FMU's
 * udmap.so like an importer, and times communication steps the way a master runs them:
 * set the changed input, fmi2DoStep / fmi3DoStep, get every output.
 *
 *   udmap-fmu-bench SO TOKEN VERSION MODE CYCLES [HARMONICS [F_E_MIN F_E_MAX [BLADES EO]]]
 *     VERSION 2 or 3; MODE F_E (F_E = 1..10 N in turn, blade A's GG peaks), F_E_dense (F_E
 *     in [1, 10] N by the golden-ratio sequence: every step a new force, never repeated),
 *     F_E_random (F_E uniform in [F_E_MIN, F_E_MAX], a fixed pseudo-random sequence) or
 *     damper (mu alternates between 0.31 and 0.30, F_E = 5 N); HARMONICS the parameter
 *     harmonics (default 1; 0 = auto); F_E_MIN, F_E_MAX the parameters of the force range
 *     prepared at ExitInitializationMode (default: their start values, 1 and 10 N); BLADES,
 *     EO the parameters blades and engine_order (default 24 and 0: in phase; at EO != 0 the
 *     force table is built on demand, as the steps visit it).
 * Prints one JSON object: the median, min, max and mean time of a step [s], the time of
 * ExitInitializationMode [s] and the outputs of the last cycle (for the accuracy columns).
 */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "config.h"
#include "fmi2_api.h"
#include "fmi3_api.h"

#define NOUT 11
static const unsigned r2[] = {vr_gamma_P, vr_sigma_a, vr_F_lim, vr_f_res,
                              vr_u_E, vr_k_re, vr_k_im, vr_F_ratio};
static const unsigned i2[] = {vr_regime};
static const unsigned b2[] = {vr_hcf_ok, vr_lift_off};

static void logger2(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                    fmi2String category, fmi2String message, ...) {
  (void)env;
  if (status != fmi2OK) fprintf(stderr, "%s [%s] %d: %s\n", name, category, status, message);
}

static void logger3(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                    fmi3String message) {
  (void)env;
  if (status != fmi3OK) fprintf(stderr, "[%s] %d: %s\n", category, status, message);
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

#define LOAD(h, name) __typeof__(name) *p_##name = (__typeof__(name) *)dlsym(h, #name)

typedef struct {
  void *inst;
  int version;
  void *h;
  __typeof__(fmi2SetReal) *set2;
  __typeof__(fmi2DoStep) *step2;
  __typeof__(fmi2GetReal) *getr2;
  __typeof__(fmi2GetInteger) *geti2;
  __typeof__(fmi2GetBoolean) *getb2;
  __typeof__(fmi3SetFloat64) *set3;
  __typeof__(fmi3DoStep) *step3;
  __typeof__(fmi3GetFloat64) *getr3;
  __typeof__(fmi3GetInt32) *geti3;
  __typeof__(fmi3GetBoolean) *getb3;
} Fmu;

#define SYM(field, name) f->field = (__typeof__(name) *)dlsym(f->h, #name)

static int resolve(Fmu *f) {
  if (f->version == 2) {
    SYM(set2, fmi2SetReal), SYM(step2, fmi2DoStep), SYM(getr2, fmi2GetReal);
    SYM(geti2, fmi2GetInteger), SYM(getb2, fmi2GetBoolean);
    return f->set2 && f->step2 && f->getr2 && f->geti2 && f->getb2;
  }
  SYM(set3, fmi3SetFloat64), SYM(step3, fmi3DoStep), SYM(getr3, fmi3GetFloat64);
  SYM(geti3, fmi3GetInt32), SYM(getb3, fmi3GetBoolean);
  return f->set3 && f->step3 && f->getr3 && f->geti3 && f->getb3;
}

/* One communication step: set one Float64 input, step, get all outputs. */
static int step(Fmu *f, ValueReference vr, double value, double t, double out[NOUT]) {
  int st = 0;
  unsigned vri = vr;
  if (f->version == 2) {
    fmi2Integer iv[1];
    fmi2Boolean bv[2];
    st |= f->set2(f->inst, &vri, 1, &value);
    st |= f->step2(f->inst, t, 1e-3, fmi2True);
    st |= f->getr2(f->inst, r2, 8, out);
    st |= f->geti2(f->inst, i2, 1, iv);
    st |= f->getb2(f->inst, b2, 2, bv);
    out[8] = iv[0], out[9] = bv[0], out[10] = bv[1];
  } else {
    fmi3Int32 iv[1];
    fmi3Boolean bv[2], e, term, early;
    fmi3Float64 last;
    st |= f->set3(f->inst, &vri, 1, &value, 1);
    st |= f->step3(f->inst, t, 1e-3, true, &e, &term, &early, &last);
    st |= f->getr3(f->inst, r2, 8, out, 8);
    st |= f->geti3(f->inst, i2, 1, iv, 1);
    st |= f->getb3(f->inst, b2, 2, bv, 2);
    out[8] = iv[0], out[9] = bv[0], out[10] = bv[1];
  }
  return st;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* A uniform number in [0, 1) (64-bit LCG, top 53 bits): the same sequence on every run. */
static double uniform(unsigned long long *state) {
  *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*state >> 11) * 0x1.0p-53;
}

int main(int argc, char **argv) {
  if (argc != 6 && argc != 7 && argc != 9 && argc != 11) {
    fprintf(stderr, "usage: %s SO TOKEN VERSION F_E|F_E_dense|F_E_random|damper CYCLES "
            "[HARMONICS [F_E_MIN F_E_MAX [BLADES EO]]]\n", argv[0]);
    return 2;
  }
  const char *token = argv[2];
  int version = atoi(argv[3]);
  int damper = strcmp(argv[4], "damper") == 0;
  int dense = strcmp(argv[4], "F_E_dense") == 0;
  int random = strcmp(argv[4], "F_E_random") == 0;
  int harmonics = argc >= 7 ? atoi(argv[6]) : 1;
  const double range[2] = {argc >= 9 ? atof(argv[7]) : 1.0, argc >= 9 ? atof(argv[8]) : 10.0};
  const int wave[2] = {argc == 11 ? atoi(argv[9]) : 24, argc == 11 ? atoi(argv[10]) : 0};
  const unsigned vr_h = vr_harmonics, vr_range[2] = {vr_F_E_min, vr_F_E_max};
  const unsigned vr_wave[2] = {vr_blades, vr_engine_order};
  unsigned long long seed = 20230523ULL;
  double t_init = 0;
  int cycles = atoi(argv[5]);
  Fmu f = {.version = version, .h = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL)};
  if (!f.h) {
    fprintf(stderr, "dlopen: %s\n", dlerror());
    return 1;
  }
  if (!resolve(&f)) {
    fprintf(stderr, "dlsym: %s\n", dlerror());
    return 1;
  }
  if (version == 2) {
    LOAD(f.h, fmi2Instantiate);
    LOAD(f.h, fmi2SetupExperiment);
    LOAD(f.h, fmi2EnterInitializationMode);
    LOAD(f.h, fmi2ExitInitializationMode);
    LOAD(f.h, fmi2SetInteger);
    fmi2CallbackFunctions cb = {logger2, NULL, NULL, NULL, NULL};
    f.inst = p_fmi2Instantiate("bench", fmi2CoSimulation, token, "", &cb, fmi2False, fmi2False);
    const fmi2Integer hv = harmonics, wv[2] = {wave[0], wave[1]};
    if (!f.inst || p_fmi2SetupExperiment(f.inst, fmi2False, 0, 0, fmi2False, 0) ||
        p_fmi2EnterInitializationMode(f.inst) || p_fmi2SetInteger(f.inst, &vr_h, 1, &hv) ||
        p_fmi2SetInteger(f.inst, vr_wave, 2, wv) || f.set2(f.inst, vr_range, 2, range))
      return 1;
    t_init = now();
    if (p_fmi2ExitInitializationMode(f.inst)) return 1;
    t_init = now() - t_init;
  } else {
    LOAD(f.h, fmi3InstantiateCoSimulation);
    LOAD(f.h, fmi3EnterInitializationMode);
    LOAD(f.h, fmi3ExitInitializationMode);
    LOAD(f.h, fmi3SetInt32);
    f.inst = p_fmi3InstantiateCoSimulation("bench", token, "", false, false, false, false, NULL,
                                           0, NULL, logger3, NULL);
    const fmi3Int32 hv = harmonics, wv[2] = {wave[0], wave[1]};
    if (!f.inst || p_fmi3EnterInitializationMode(f.inst, false, 0, 0, false, 0) ||
        p_fmi3SetInt32(f.inst, &vr_h, 1, &hv, 1) || p_fmi3SetInt32(f.inst, vr_wave, 2, wv, 2) ||
        f.set3(f.inst, vr_range, 2, range, 2))
      return 1;
    t_init = now();
    if (p_fmi3ExitInitializationMode(f.inst)) return 1;
    t_init = now() - t_init;
  }
  const int per_cycle = damper ? 2 : 10;
  int n = cycles * per_cycle;
  double *times = malloc(sizeof(double) * (size_t)n), out[NOUT], t = 0, total = 0;
  /* steps over 1 ms, timed again afterwards: a slowness that comes back is the FMU's, one
   * that does not is the machine's (preemption on shared cores) */
  enum { NSLOW = 200 };
  double slow_value[NSLOW];
  int nslow = 0, slow_total = 0;
  /* the outputs of the last cycle (at harmonics != 1 the ones from the force table) */
  double table[10][NOUT], forces[10];
  /* warm-up: the first point (ExitInitializationMode built the blade, damper and model and
   * prepared the force range) */
  if (step(&f, vr_F_E, 5.0, t, out)) return 1;
  t += 1e-3;
  for (int i = 0; i < n; i++) {
    int k = i % per_cycle;
    ValueReference vr = damper ? vr_mu : vr_F_E;
    /* the warm-up left mu = 0.30: the first timed step already changes it */
    double value = damper ? (k ? 0.30 : 0.31) : (double)(k + 1);
    if (dense) value = 1.0 + 9.0 * fmod(0.6180339887498949 * (i + 1), 1.0);
    if (random) value = range[0] + (range[1] - range[0]) * uniform(&seed);
    double t0 = now();
    int st = step(&f, vr, value, t, out);
    times[i] = now() - t0;
    total += times[i];
    t += 1e-3;
    if (st) {
      fprintf(stderr, "step %d: status %d\n", i, st);
      return 1;
    }
    if (!damper && times[i] > 1e-3) {
      slow_total++;
      if (nslow < NSLOW) slow_value[nslow++] = value;
    }
    if (i >= n - per_cycle) {
      memcpy(table[k], out, sizeof out);
      forces[k] = damper ? 5.0 : value;
    }
  }
  /* each slow force again, three times after a step elsewhere: the least of the three */
  double retimed_max = 0.0;
  const double elsewhere = random ? 0.5 * (range[0] + range[1]) : 5.5;
  for (int j = 0; j < nslow; j++) {
    double best = INFINITY;
    for (int r = 0; r < 3; r++) {
      if (step(&f, vr_F_E, elsewhere, t, out)) return 1;
      t += 1e-3;
      double t0 = now();
      if (step(&f, vr_F_E, slow_value[j], t, out)) return 1;
      double dt = now() - t0;
      t += 1e-3;
      if (dt < best) best = dt;
    }
    if (best > retimed_max) retimed_max = best;
  }
  qsort(times, (size_t)n, sizeof(double), cmp);
  printf("{\"version\": %d, \"mode\": \"%s\", \"harmonics\": %d, \"blades\": %d, "
         "\"engine_order\": %d, \"steps\": %d, "
         "\"F_E_min\": %.17g, \"F_E_max\": %.17g, \"init_seconds\": %.9e, "
         "\"seconds_median\": %.9e, \"seconds_min\": %.9e, \"seconds_max\": %.9e, "
         "\"seconds_p999\": %.9e, \"seconds_mean\": %.9e, \"steps_over_1ms\": %d, "
         "\"seconds_max_retimed\": %.9e", version, argv[4], harmonics, wave[0], wave[1], n,
         range[0], range[1],
         t_init, times[n / 2], times[0], times[n - 1], times[(size_t)(0.999 * (n - 1))],
         total / n, slow_total, retimed_max);
  printf(", \"points\": [");
  for (int k = 0; k < per_cycle; k++)
    printf("%s{\"F_E\": %.17g, \"mu\": %.2f, \"gamma_P\": %.17g, \"sigma_a\": %.17g, "
           "\"f_res\": %.17g}", k ? ", " : "", forces[k],
           damper ? (k ? 0.30 : 0.31) : 0.3, table[k][0], table[k][1], table[k][3]);
  printf("]}\n");
  free(times);
  if (version == 2) {
    LOAD(f.h, fmi2FreeInstance);
    p_fmi2FreeInstance(f.inst);
  } else {
    LOAD(f.h, fmi3FreeInstance);
    p_fmi3FreeInstance(f.inst);
  }
  dlclose(f.h);
  return 0;
}
