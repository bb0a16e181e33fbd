/*
 * A minimal FMI 2.0 / FMI 3.0 importer (co-simulation or model exchange) for the Windows test
 * (tests/windows/test_fmu_wine.py): the same source is built for Windows with MinGW-w64 (run
 * under Wine on udmap.dll) and for Linux (run on udmap.so), and the two outputs are compared.
 *
 *   udmap-fmu-import <2|3> <binary> <token> <resource location> <script> [cs|me]
 *
 * Co-simulation (cs, the default): per step the inputs are set, fmiDoStep(time, step size)
 * runs and the outputs are read. Model exchange (me): after initialization the event mode is
 * left (NewDiscreteStates / UpdateDiscreteStates until nothing is to iterate) for the
 * continuous-time mode; per step the time is set to time + step size, the inputs are set, the
 * outputs are read and the integrator step is completed.
 *
 * The script (text, whitespace separated) lists the value references, then the steps:
 *   <nIn> <vr>...      real inputs set before each step
 *   <nReal> <vr>...    real outputs read after each step
 *   <nInt> <vr>...     integer outputs
 *   <nBool> <vr>...    boolean outputs
 *   <nSteps>, then per step: <time> <step size> <nIn input values>
 * Per step one line on stdout: the step number, the worst FMI status of the step, the real
 * outputs as the hexadecimal IEEE-754 bit patterns (exact, whatever the C runtime's printf),
 * then the integers and booleans. FMU log messages go to stderr. Exit status 0, or 1 when the
 * script or the binary cannot be used.
 */
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _WIN32
#include <windows.h>
typedef HMODULE library_t;
static library_t library_open(const char *path) { return LoadLibraryA(path); }
static void *library_symbol(library_t h, const char *name) {
  return (void *)(intptr_t)GetProcAddress(h, name);
}
static void library_close(library_t h) { FreeLibrary(h); }
static const char *library_error(void) { return "LoadLibrary/GetProcAddress failed"; }
#else
#include <dlfcn.h>
typedef void *library_t;
static library_t library_open(const char *path) { return dlopen(path, RTLD_NOW | RTLD_LOCAL); }
static void *library_symbol(library_t h, const char *name) { return dlsym(h, name); }
static void library_close(library_t h) { dlclose(h); }
static const char *library_error(void) { return dlerror(); }
#endif

#define MAX_VARS 64

/* FMI 2.0 (fmi2TypesPlatform "default") */
typedef void (*fmi2Logger)(void *, const char *, int, const char *, const char *, ...);
typedef struct {
  fmi2Logger logger;
  void *(*allocateMemory)(size_t, size_t);
  void (*freeMemory)(void *);
  void (*stepFinished)(void *, int);
  void *componentEnvironment;
} fmi2Callbacks;
typedef void *(*fmi2InstantiateT)(const char *, int, const char *, const char *,
                                  const fmi2Callbacks *, int, int);
typedef int (*fmi2SetupExperimentT)(void *, int, double, double, int, double);
typedef int (*fmi2ComponentT)(void *);
typedef void (*fmi2FreeInstanceT)(void *);
typedef int (*fmi2SetRealT)(void *, const unsigned int *, size_t, const double *);
typedef int (*fmi2GetRealT)(void *, const unsigned int *, size_t, double *);
typedef int (*fmi2GetIntegerT)(void *, const unsigned int *, size_t, int *);
typedef int (*fmi2DoStepT)(void *, double, double, int);
typedef struct {
  int newDiscreteStatesNeeded, terminateSimulation, nominalsOfContinuousStatesChanged,
      valuesOfContinuousStatesChanged, nextEventTimeDefined;
  double nextEventTime;
} fmi2EventInfo;
typedef int (*fmi2NewDiscreteStatesT)(void *, fmi2EventInfo *);
typedef int (*fmi2SetTimeT)(void *, double);
typedef int (*fmi2CompletedIntegratorStepT)(void *, int, int *, int *);

/* FMI 3.0 */
typedef void (*fmi3LogMessage)(void *, int, const char *, const char *);
typedef void *(*fmi3InstantiateCoSimulationT)(const char *, const char *, const char *, bool,
                                              bool, bool, bool, const uint32_t *, size_t,
                                              void *, fmi3LogMessage, void *);
typedef int (*fmi3EnterInitializationModeT)(void *, bool, double, double, bool, double);
typedef int (*fmi3InstanceT)(void *);
typedef void (*fmi3FreeInstanceT)(void *);
typedef int (*fmi3SetFloat64T)(void *, const uint32_t *, size_t, const double *, size_t);
typedef int (*fmi3GetFloat64T)(void *, const uint32_t *, size_t, double *, size_t);
typedef int (*fmi3GetInt32T)(void *, const uint32_t *, size_t, int32_t *, size_t);
typedef int (*fmi3GetBooleanT)(void *, const uint32_t *, size_t, bool *, size_t);
typedef int (*fmi3DoStepT)(void *, double, double, bool, bool *, bool *, bool *, double *);
typedef void *(*fmi3InstantiateModelExchangeT)(const char *, const char *, const char *, bool,
                                               bool, void *, fmi3LogMessage);
typedef int (*fmi3UpdateDiscreteStatesT)(void *, bool *, bool *, bool *, bool *, bool *,
                                         double *);
typedef int (*fmi3SetTimeT)(void *, double);
typedef int (*fmi3CompletedIntegratorStepT)(void *, bool, bool *, bool *);

static void logger2(void *env, const char *name, int status, const char *category,
                 const char *message, ...) {
  (void)env;
  va_list ap;
  va_start(ap, message);
  fprintf(stderr, "[%s] status %d %s: ", name ? name : "", status, category ? category : "");
  vfprintf(stderr, message ? message : "", ap);
  fputc('\n', stderr);
  va_end(ap);
}

static void logger3(void *env, int status, const char *category, const char *message) {
  (void)env;
  fprintf(stderr, "status %d %s: %s\n", status, category ? category : "",
          message ? message : "");
}

static int fail(const char *what, const char *detail) {
  fprintf(stderr, "udmap-fmu-import: %s%s%s\n", what, detail ? ": " : "", detail ? detail : "");
  return 1;
}

static int read_count(FILE *f, size_t *n) {
  unsigned int u;
  if (fscanf(f, "%u", &u) != 1) return 0;
  *n = u;
  return 1;
}

static int read_vrs(FILE *f, size_t *n, uint32_t *vr) {
  if (!read_count(f, n) || *n > MAX_VARS) return 0;
  for (size_t i = 0; i < *n; i++)
    if (fscanf(f, "%u", &vr[i]) != 1) return 0;
  return 1;
}

static void print_real(double x) {
  uint64_t bits;
  memcpy(&bits, &x, sizeof bits);
  printf(" %016llx", (unsigned long long)bits);
}

#define SYMBOL(var, type, name)                                               \
  type var = (type)(intptr_t)library_symbol(lib, name);                       \
  if (!var) return fail("missing FMI function", name)

static int max_status(int a, int b) { return a > b ? a : b; }

/* One step of the script: its time, step size and input values (0, or 1 with a message). */
static int read_step(FILE *f, const char *script, double *t, double *h, size_t n_in,
                     double *in) {
  if (fscanf(f, "%lf %lf", t, h) != 2) return fail("malformed step", script);
  for (size_t i = 0; i < n_in; i++)
    if (fscanf(f, "%lf", &in[i]) != 1) return fail("malformed input value", script);
  return 0;
}

/* The step's line on stdout (booleans as 0/1, whichever FMI type held them). */
static void print_step(size_t k, int st, size_t n_real, const double *real, size_t n_int,
                       const int32_t *ints, size_t n_bool, const int *bools) {
  printf("%u %d", (unsigned int)k, st);
  for (size_t i = 0; i < n_real; i++) print_real(real[i]);
  for (size_t i = 0; i < n_int; i++) printf(" %d", (int)ints[i]);
  for (size_t i = 0; i < n_bool; i++) printf(" %d", bools[i] ? 1 : 0);
  printf("\n");
}

int main(int argc, char **argv) {
  if (argc != 6 && argc != 7)
    return fail("usage: udmap-fmu-import <2|3> <binary> <token> <resource> <script> [cs|me]",
                NULL);
  int version = atoi(argv[1]);
  if (version != 2 && version != 3) return fail("the FMI version must be 2 or 3", argv[1]);
  if (argc == 7 && strcmp(argv[6], "cs") != 0 && strcmp(argv[6], "me") != 0)
    return fail("the interface must be cs or me", argv[6]);
  const bool me = argc == 7 && strcmp(argv[6], "me") == 0;
  FILE *f = fopen(argv[5], "r");
  if (!f) return fail("cannot open the script", argv[5]);
  size_t n_in, n_real, n_int, n_bool, n_steps;
  uint32_t vr_in[MAX_VARS], vr_real[MAX_VARS], vr_int[MAX_VARS], vr_bool[MAX_VARS];
  if (!read_vrs(f, &n_in, vr_in) || !read_vrs(f, &n_real, vr_real) ||
      !read_vrs(f, &n_int, vr_int) || !read_vrs(f, &n_bool, vr_bool) ||
      !read_count(f, &n_steps)) {
    fclose(f);
    return fail("malformed script header", argv[5]);
  }

  library_t lib = library_open(argv[2]);
  if (!lib) {
    fclose(f);
    return fail("cannot load the binary", library_error());
  }
  int rc = 0;
  double in[MAX_VARS], real[MAX_VARS];
  int32_t ints[MAX_VARS];
  int bools2[MAX_VARS];
  bool bools3[MAX_VARS];
  unsigned int vr2_in[MAX_VARS], vr2_real[MAX_VARS], vr2_int[MAX_VARS], vr2_bool[MAX_VARS];
  for (size_t i = 0; i < MAX_VARS; i++) {
    vr2_in[i] = vr_in[i];
    vr2_real[i] = vr_real[i];
    vr2_int[i] = vr_int[i];
    vr2_bool[i] = vr_bool[i];
  }

  if (version == 2) {
    SYMBOL(instantiate, fmi2InstantiateT, "fmi2Instantiate");
    SYMBOL(setup, fmi2SetupExperimentT, "fmi2SetupExperiment");
    SYMBOL(enter, fmi2ComponentT, "fmi2EnterInitializationMode");
    SYMBOL(exit_init, fmi2ComponentT, "fmi2ExitInitializationMode");
    SYMBOL(terminate, fmi2ComponentT, "fmi2Terminate");
    SYMBOL(free_instance, fmi2FreeInstanceT, "fmi2FreeInstance");
    SYMBOL(set_real, fmi2SetRealT, "fmi2SetReal");
    SYMBOL(get_real, fmi2GetRealT, "fmi2GetReal");
    SYMBOL(get_integer, fmi2GetIntegerT, "fmi2GetInteger");
    SYMBOL(get_boolean, fmi2GetIntegerT, "fmi2GetBoolean");
    SYMBOL(do_step, fmi2DoStepT, "fmi2DoStep");
    fmi2NewDiscreteStatesT new_discrete_states = NULL;
    fmi2ComponentT enter_continuous = NULL;
    fmi2SetTimeT set_time = NULL;
    fmi2CompletedIntegratorStepT completed = NULL;
    if (me) {
      SYMBOL(nds, fmi2NewDiscreteStatesT, "fmi2NewDiscreteStates");
      SYMBOL(ect, fmi2ComponentT, "fmi2EnterContinuousTimeMode");
      SYMBOL(stm, fmi2SetTimeT, "fmi2SetTime");
      SYMBOL(cis, fmi2CompletedIntegratorStepT, "fmi2CompletedIntegratorStep");
      new_discrete_states = nds, enter_continuous = ect, set_time = stm, completed = cis;
    }
    fmi2Callbacks cb = {logger2, calloc, free, NULL, NULL};
    /* fmi2ModelExchange = 0, fmi2CoSimulation = 1 */
    void *c = instantiate("udmap", me ? 0 : 1, argv[3], argv[4], &cb, 0, 0);
    if (!c) rc = fail("fmi2Instantiate returned NULL", NULL);
    if (c) {
      int st = setup(c, 0, 0.0, 0.0, 0, 0.0);
      st = max_status(st, enter(c));
      st = max_status(st, exit_init(c));
      if (me) {
        fmi2EventInfo event = {1, 0, 0, 0, 0, 0.0};
        for (int i = 0; st <= 1 && event.newDiscreteStatesNeeded && i < 100; i++)
          st = max_status(st, new_discrete_states(c, &event));
        if (event.newDiscreteStatesNeeded) rc = fail("event iteration does not end", NULL);
        st = max_status(st, enter_continuous(c));
      }
      if (st > 1) rc = fail("initialization failed", NULL);
      for (size_t k = 0; !rc && k < n_steps; k++) {
        double t, h;
        if ((rc = read_step(f, argv[5], &t, &h, n_in, in))) break;
        st = me ? set_time(c, t + h) : 0;
        st = max_status(st, set_real(c, vr2_in, n_in, in));
        if (!me) st = max_status(st, do_step(c, t, h, 1));
        st = max_status(st, get_real(c, vr2_real, n_real, real));
        st = max_status(st, get_integer(c, vr2_int, n_int, ints));
        st = max_status(st, get_boolean(c, vr2_bool, n_bool, bools2));
        if (me) {
          int enter_event = 0, terminate_sim = 0;
          st = max_status(st, completed(c, 1, &enter_event, &terminate_sim));
          if (enter_event || terminate_sim) rc = fail("unexpected event or termination", NULL);
        }
        print_step(k, st, n_real, real, n_int, ints, n_bool, bools2);
      }
      terminate(c);
      free_instance(c);
    }
  } else {
    SYMBOL(enter, fmi3EnterInitializationModeT, "fmi3EnterInitializationMode");
    SYMBOL(exit_init, fmi3InstanceT, "fmi3ExitInitializationMode");
    SYMBOL(terminate, fmi3InstanceT, "fmi3Terminate");
    SYMBOL(free_instance, fmi3FreeInstanceT, "fmi3FreeInstance");
    SYMBOL(set_real, fmi3SetFloat64T, "fmi3SetFloat64");
    SYMBOL(get_real, fmi3GetFloat64T, "fmi3GetFloat64");
    SYMBOL(get_integer, fmi3GetInt32T, "fmi3GetInt32");
    SYMBOL(get_boolean, fmi3GetBooleanT, "fmi3GetBoolean");
    SYMBOL(do_step, fmi3DoStepT, "fmi3DoStep");
    fmi3UpdateDiscreteStatesT update_discrete_states = NULL;
    fmi3InstanceT enter_continuous = NULL;
    fmi3SetTimeT set_time = NULL;
    fmi3CompletedIntegratorStepT completed = NULL;
    const char *resource = argv[4][0] ? argv[4] : NULL;
    void *c;
    if (me) {
      SYMBOL(instantiate, fmi3InstantiateModelExchangeT, "fmi3InstantiateModelExchange");
      SYMBOL(uds, fmi3UpdateDiscreteStatesT, "fmi3UpdateDiscreteStates");
      SYMBOL(ect, fmi3InstanceT, "fmi3EnterContinuousTimeMode");
      SYMBOL(stm, fmi3SetTimeT, "fmi3SetTime");
      SYMBOL(cis, fmi3CompletedIntegratorStepT, "fmi3CompletedIntegratorStep");
      update_discrete_states = uds, enter_continuous = ect, set_time = stm, completed = cis;
      c = instantiate("udmap", argv[3], resource, false, false, NULL, logger3);
    } else {
      SYMBOL(instantiate, fmi3InstantiateCoSimulationT, "fmi3InstantiateCoSimulation");
      c = instantiate("udmap", argv[3], resource, false, false, false, false, NULL, 0, NULL,
                      logger3, NULL);
    }
    if (!c) rc = fail("fmi3Instantiate returned NULL", NULL);
    if (c) {
      int st = enter(c, false, 0.0, 0.0, false, 0.0);
      st = max_status(st, exit_init(c));
      if (me) {
        bool again = true, terminate_sim = false, nominals = false, values = false,
             next_defined = false;
        double next = 0.0;
        for (int i = 0; st <= 1 && again && i < 100; i++)
          st = max_status(st, update_discrete_states(c, &again, &terminate_sim, &nominals,
                                                     &values, &next_defined, &next));
        if (again) rc = fail("event iteration does not end", NULL);
        st = max_status(st, enter_continuous(c));
      }
      if (st > 1) rc = fail("initialization failed", NULL);
      for (size_t k = 0; !rc && k < n_steps; k++) {
        double t, h;
        if ((rc = read_step(f, argv[5], &t, &h, n_in, in))) break;
        bool event = false, terminate_sim = false, early = false;
        double last = 0.0;
        st = me ? set_time(c, t + h) : 0;
        st = max_status(st, set_real(c, vr_in, n_in, in, n_in));
        if (!me)
          st = max_status(st, do_step(c, t, h, true, &event, &terminate_sim, &early, &last));
        st = max_status(st, get_real(c, vr_real, n_real, real, n_real));
        st = max_status(st, get_integer(c, vr_int, n_int, ints, n_int));
        st = max_status(st, get_boolean(c, vr_bool, n_bool, bools3, n_bool));
        if (me) {
          st = max_status(st, completed(c, true, &event, &terminate_sim));
          if (event || terminate_sim) rc = fail("unexpected event or termination", NULL);
        }
        for (size_t i = 0; i < n_bool; i++) bools2[i] = bools3[i];
        print_step(k, st, n_real, real, n_int, ints, n_bool, bools2);
      }
      terminate(c);
      free_instance(c);
    }
  }
  fclose(f);
  library_close(lib);
  return rc;
}
