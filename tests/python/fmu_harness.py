"""Helpers of the FMU tests: where the FMUs are, and a direct ctypes importer for FMI 2.0 and
FMI 3.0, co-simulation or model exchange, that returns status codes (instead of raising) and records every log
message, so that the tests can check statuses and messages exactly.
"""
from __future__ import annotations

import ctypes
import json
import os
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("UDMAP_BUILD_DIR", ROOT / "build"))
FMUS = {2: BUILD / "udmap.fmu", 3: BUILD / "udmap-fmi3.fmu"}
PLATFORM = {2: "linux64", 3: "x86_64-linux"}
CASE = ROOT / "cases" / "blade_a.json"

OK, WARNING, DISCARD, ERROR, FATAL = range(5)

_extracted: dict[int, Path] = {}


def extract(version: int) -> Path:
    """The FMU unpacked into a temporary directory (once per process)."""
    if version not in _extracted:
        path = FMUS[version]
        assert path.is_file(), f"{path} is missing: build with 'make build'"
        tmp = Path(tempfile.mkdtemp(prefix=f"udmap-fmi{version}-"))
        with zipfile.ZipFile(path) as zf:
            zf.extractall(tmp)
        _extracted[version] = tmp
    return _extracted[version]


def binary(version: int) -> Path:
    return extract(version) / "binaries" / PLATFORM[version] / "udmap.so"


_descriptions: dict = {}


def description(version: int):
    """fmpy's reading of the FMU's modelDescription.xml (parsed once per process)."""
    if version not in _descriptions:
        from fmpy import read_model_description
        _descriptions[version] = read_model_description(str(FMUS[version]))
    return _descriptions[version]


class _Fmi2Callbacks(ctypes.Structure):
    _fields_ = [("logger", ctypes.c_void_p), ("allocateMemory", ctypes.c_void_p),
                ("freeMemory", ctypes.c_void_p), ("stepFinished", ctypes.c_void_p),
                ("componentEnvironment", ctypes.c_void_p)]


_FMI2_LOGGER = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int,
                                ctypes.c_char_p, ctypes.c_char_p)
_FMI3_LOGGER = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_int, ctypes.c_char_p,
                                ctypes.c_char_p)


class Instance:
    """One co-simulation instance of the FMU `version` (2 or 3), driven through ctypes.

    Every call returns the FMI status as an int; get() returns (status, values). Log messages
    are collected in `self.logs` as (status, category, message)."""

    def __init__(self, version: int, name: str = "udmap", logging_on: bool = False,
                 token: str | None = None, model_exchange: bool = False):
        self.version = version
        self.model_exchange = model_exchange
        self.md = description(version)
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.dll = ctypes.CDLL(str(binary(version)))
        self.logs: list[tuple[int, str, str]] = []
        self.time = 0.0
        token = token if token is not None else (self.md.guid if version == 2
                                                 else self.md.instantiationToken)
        resource = (extract(version) / "resources").as_uri().encode()
        if version == 2:
            self._logger = _FMI2_LOGGER(self._log2)
            self._callbacks = _Fmi2Callbacks(ctypes.cast(self._logger, ctypes.c_void_p),
                                             None, None, None, None)
            f = self.dll.fmi2Instantiate
            f.restype = ctypes.c_void_p
            f.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p,
                          ctypes.POINTER(_Fmi2Callbacks), ctypes.c_int, ctypes.c_int]
            self.c = f(name.encode(), 0 if model_exchange else 1, token.encode(), resource,
                       ctypes.byref(self._callbacks), 0, int(logging_on))
        else:
            self._logger = _FMI3_LOGGER(self._log3)
        if version == 3 and model_exchange:
            f = self.dll.fmi3InstantiateModelExchange
            f.restype = ctypes.c_void_p
            f.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_bool,
                          ctypes.c_bool, ctypes.c_void_p, _FMI3_LOGGER]
            self.c = f(name.encode(), token.encode(), resource, False, logging_on, None,
                       self._logger)
        elif version == 3:
            f = self.dll.fmi3InstantiateCoSimulation
            f.restype = ctypes.c_void_p
            f.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_bool,
                          ctypes.c_bool, ctypes.c_bool, ctypes.c_bool, ctypes.c_void_p,
                          ctypes.c_size_t, ctypes.c_void_p, _FMI3_LOGGER, ctypes.c_void_p]
            self.c = f(name.encode(), token.encode(), resource, False, logging_on, False, False,
                       None, 0, None, self._logger, None)
        self._declare()

    # ------------------------------------------------------------------ plumbing
    def _log2(self, env, name, status, category, message):
        self.logs.append((status, category.decode(), message.decode()))

    def _log3(self, env, status, category, message):
        self.logs.append((status, category.decode(), message.decode()))

    def _fn(self, name, argtypes, restype=ctypes.c_int):
        f = getattr(self.dll, name)
        f.argtypes = [ctypes.c_void_p] + argtypes
        f.restype = restype
        return f

    def _declare(self):
        p = f"fmi{self.version}"
        vr_p = ctypes.POINTER(ctypes.c_uint32 if self.version == 3 else ctypes.c_uint)
        if self.version == 2:
            self._types = {"Real": ctypes.c_double, "Integer": ctypes.c_int,
                           "Boolean": ctypes.c_int}
        else:
            self._types = {"Float64": ctypes.c_double, "Int32": ctypes.c_int32,
                           "Boolean": ctypes.c_bool}
        self._get, self._set = {}, {}
        for kind, ct in self._types.items():
            args = [vr_p, ctypes.c_size_t, ctypes.POINTER(ct)]
            if self.version == 3:
                args.append(ctypes.c_size_t)
            self._get[kind] = self._fn(f"{p}Get{kind}", args)
            self._set[kind] = self._fn(f"{p}Set{kind}", args)
        self.f_reset = self._fn(f"{p}Reset", [])
        self.f_terminate = self._fn(f"{p}Terminate", [])
        self.f_free = self._fn(f"{p}FreeInstance", [], None)
        state = "FMUstate" if self.version == 2 else "FMUState"
        self.f_get_state = self._fn(f"{p}Get{state}", [ctypes.POINTER(ctypes.c_void_p)])
        self.f_set_state = self._fn(f"{p}Set{state}", [ctypes.c_void_p])
        self.f_free_state = self._fn(f"{p}Free{state}", [ctypes.POINTER(ctypes.c_void_p)])
        self.f_state_size = self._fn(f"{p}Serialized{state}Size",
                                     [ctypes.c_void_p, ctypes.POINTER(ctypes.c_size_t)])
        self.f_serialize = self._fn(f"{p}Serialize{state}",
                                    [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_size_t])
        deser = "DeSerializeFMUstate" if self.version == 2 else "DeserializeFMUState"
        self.f_deserialize = self._fn(f"{p}{deser}", [ctypes.c_char_p, ctypes.c_size_t,
                                                      ctypes.POINTER(ctypes.c_void_p)])
        if self.version == 2:
            self.f_setup = self._fn("fmi2SetupExperiment", [ctypes.c_int, ctypes.c_double,
                                                            ctypes.c_double, ctypes.c_int,
                                                            ctypes.c_double])
            self.f_enter = self._fn("fmi2EnterInitializationMode", [])
            self.f_do_step = self._fn("fmi2DoStep", [ctypes.c_double, ctypes.c_double,
                                                     ctypes.c_int])
        else:
            self.f_enter = self._fn("fmi3EnterInitializationMode",
                                    [ctypes.c_bool, ctypes.c_double, ctypes.c_double,
                                     ctypes.c_bool, ctypes.c_double])
            bp = ctypes.POINTER(ctypes.c_bool)
            self.f_do_step = self._fn("fmi3DoStep", [ctypes.c_double, ctypes.c_double,
                                                     ctypes.c_bool, bp, bp, bp,
                                                     ctypes.POINTER(ctypes.c_double)])
        self.f_exit = self._fn(f"{p}ExitInitializationMode", [])
        dd = [vr_p, ctypes.c_size_t, vr_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_double)]
        if self.version == 3:
            dd += [ctypes.c_size_t, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t]
        else:
            dd += [ctypes.POINTER(ctypes.c_double)]
        self.f_derivative = self._fn(f"{p}GetDirectionalDerivative", dd)

    def _kind(self, name):
        return self.vars[name].type

    # ------------------------------------------------------------------ FMI calls
    def setup(self, start_time: float = 0.0) -> int:
        """Setup/enter/exit initialization: the instance is then in step mode."""
        self.time = start_time
        if self.version == 2:
            st = self.f_setup(self.c, 0, 0.0, start_time, 0, 0.0)
            st = max(st, self.f_enter(self.c))
        else:
            st = self.f_enter(self.c, False, 0.0, start_time, False, 0.0)
        return max(st, self.f_exit(self.c))

    def set(self, **values) -> int:
        """Sets variables by name, one FMI call per type; returns the worst status."""
        by_kind: dict[str, list] = {}
        for name, value in values.items():
            by_kind.setdefault(self._kind(name), []).append((self.vars[name].valueReference,
                                                             value))
        status = OK
        for kind, items in by_kind.items():
            ct = self._types[kind]
            n = len(items)
            vrs = (ctypes.c_uint32 * n)(*[vr for vr, _ in items])
            vals = (ct * n)(*[ct(v) if kind != "Boolean" else ct(bool(v)) for _, v in items])
            args = [self.c, vrs, n, vals] + ([n] if self.version == 3 else [])
            status = max(status, self._set[kind](*args))
        return status

    def get(self, *names) -> tuple[int, list]:
        """Values of the named variables (Python floats, ints or bools), and the worst status."""
        out: list = [None] * len(names)
        status = OK
        groups: dict[str, list] = {}
        for i, name in enumerate(names):
            groups.setdefault(self._kind(name), []).append(i)
        for kind, idx in groups.items():
            ct = self._types[kind]
            n = len(idx)
            vrs = (ctypes.c_uint32 * n)(*[self.vars[names[i]].valueReference for i in idx])
            vals = (ct * n)()
            args = [self.c, vrs, n, vals] + ([n] if self.version == 3 else [])
            status = max(status, self._get[kind](*args))
            for j, i in enumerate(idx):
                v = vals[j]
                out[i] = bool(v) if kind == "Boolean" else v
        return status, out

    def outputs(self) -> tuple[int, dict]:
        names = [v.name for v in self.md.modelVariables if v.causality == "output"]
        st, vals = self.get(*names)
        return st, dict(zip(names, vals))

    def derivative(self, unknowns, knowns, seed) -> tuple[int, list]:
        """Directional derivative of the named real outputs along `seed` over the named knowns."""
        nu, nk = len(unknowns), len(knowns)
        u = (ctypes.c_uint32 * nu)(*[self.vars[n].valueReference for n in unknowns])
        k = (ctypes.c_uint32 * nk)(*[self.vars[n].valueReference for n in knowns])
        sd = (ctypes.c_double * nk)(*seed)
        out = (ctypes.c_double * nu)()
        if self.version == 3:
            st = self.f_derivative(self.c, u, nu, k, nk, sd, nk, out, nu)
        else:
            st = self.f_derivative(self.c, u, nu, k, nk, sd, out)
        return st, list(out)

    def step(self, h: float) -> int:
        if self.version == 2:
            st = self.f_do_step(self.c, self.time, h, 1)
        else:
            b = [ctypes.c_bool() for _ in range(3)]
            last = ctypes.c_double()
            st = self.f_do_step(self.c, self.time, h, True, ctypes.byref(b[0]),
                                ctypes.byref(b[1]), ctypes.byref(b[2]), ctypes.byref(last))
        if st <= WARNING:
            self.time += h
        return st

    def reset(self) -> int:
        self.time = 0.0
        return self.f_reset(self.c)

    def get_state(self):
        s = ctypes.c_void_p()
        assert self.f_get_state(self.c, ctypes.byref(s)) == OK
        return s

    def set_state(self, s) -> int:
        st = self.f_set_state(self.c, s)
        if st == OK:
            self.time = self.get("time")[1][0]
        return st

    def free_state(self, s) -> int:
        return self.f_free_state(self.c, ctypes.byref(s))

    def serialize(self, s) -> bytes:
        size = ctypes.c_size_t()
        assert self.f_state_size(self.c, s, ctypes.byref(size)) == OK
        buf = ctypes.create_string_buffer(size.value)
        assert self.f_serialize(self.c, s, buf, size.value) == OK
        return buf.raw

    def deserialize(self, data: bytes):
        s = ctypes.c_void_p()
        st = self.f_deserialize(self.c, data, len(data), ctypes.byref(s))
        return st, s

    def free(self) -> None:
        if self.c:
            self.f_free(self.c)
            self.c = None

    def messages(self, min_status: int = WARNING) -> list[str]:
        return [m for st, _, m in self.logs if st >= min_status]


def cli(*args) -> dict:
    """Runs `python3 -m udmap ARGS --json` and returns the parsed JSON."""
    env = dict(os.environ, PYTHONPATH=str(ROOT / "wrappers" / "python"))
    r = subprocess.run([sys.executable, "-m", "udmap", *map(str, args), "--json"], cwd=ROOT,
                       env=env, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, f"udmap {' '.join(map(str, args))} failed: {r.stderr}"
    return json.loads(r.stdout)


def step_table(segments, duration: float):
    """An fmpy input table that holds each (F_E, CF, mu, f_exc) for `duration` seconds and then
    steps: segments are (CF, mu, f_exc, [F_E, ...]). Returns the table and its end time."""
    import numpy as np
    rows, t = [], 0.0
    for CF, mu, f_exc, forces in segments:
        for F in forces:
            rows.append((t, F, CF, mu, f_exc))
            t += duration
            rows.append((t, F, CF, mu, f_exc))
    dtype = [("time", float), ("F_E", float), ("CF", float), ("mu", float), ("f_exc", float)]
    return np.array(rows, dtype=dtype), t


def write_matrices_table_case(d: Path) -> Path:
    """Blade A as a matrices blade (its Matrix Market export with the stress rows) with blade A's
    damper tabulated as a measured table, written to d: the case FMU tests' case."""
    import numpy as np

    from udmap.case import build_blade, build_damper, load_case
    case = load_case(CASE)
    build_blade(case).export(d)
    damper = build_damper(case)
    gammas = np.geomspace(1e-6, 5e-3, 60)
    k = damper.stiffness(gammas)
    with open(d / "k.csv", "w") as f:
        f.write("gamma,k_re,k_im\n")
        for row in zip(gammas, k.real, k.imag):
            f.write(",".join(repr(float(x)) for x in row) + "\n")
    data = {"blade": {"kind": "matrices", "M": "M.mtx", "K": "K.mtx", "stress_K": "stress_K.mtx",
                      "stress_M": "stress_M.mtx", "gamma_dof": 16, "exc_dof": 39,
                      "zeta": 0.002},
            "damper": {"kind": "table", "file": "k.csv",
                       "delta_M": damper.M_max - damper.M_min},
            "analysis": {"f_min": 150.0, "f_max": 230.0}}
    path = d / "matrices_table.json"
    path.write_text(json.dumps(data))
    return path


def case_with(tmp_path: Path, name: str = "case", **damper) -> Path:
    """blade_a.json with some damper fields replaced, written to tmp_path."""
    data = json.loads(CASE.read_text())
    data["damper"].update(damper)
    path = tmp_path / f"{name}.json"
    path.write_text(json.dumps(data))
    return path


def reference(tmp_path: Path, CF, mu, f_exc, forces, name: str | None = None):
    """The command line's answer for blade A with CF and mu (backbone when f_exc is 0, else the
    response at f_exc): (its JSON, its points by F_E)."""
    case = case_with(tmp_path, name or f"cf{CF}_mu{mu}", CF=CF, mu=mu)
    arg = ",".join(repr(F) for F in forces)
    if f_exc == 0.0:
        data = cli("backbone", case, "--forces", arg)
    else:
        data = cli("response", case, "--forces", arg, "--freq", repr(f_exc))
    return data, {p["F_E"]: p for p in data["points"]}


# A C importer that runs N cycles of: instantiate, compute, save the state, change mu, CF, a
# blade parameter and F_E, have a value rejected, restore the state, reset, free. It prints the
# growth of its resident memory from cycle 20 to the end ("rss_growth_kib N").
_CYCLES = r"""
/* instantiate, compute, save state, change everything, reject a value, restore, reset, free */
#include <dlfcn.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#define S(name) void *name = dlsym(h, #name); if (!name) return 3;
typedef int (*f_v)(void *);
typedef int (*f_rw)(void *, const unsigned *, size_t, double *);
typedef int (*f_rw3)(void *, const unsigned *, size_t, double *, size_t);
typedef int (*f_st)(void *, void **);
typedef int (*f_st1)(void *, void *);
static long resident_kib(void) {
  long pages = 0, resident = 0;
  FILE *f = fopen("/proc/self/statm", "r");
  if (!f || fscanf(f, "%%ld %%ld", &pages, &resident) != 2) resident = -1;
  if (f) fclose(f);
  return resident * 4;
}
static void log2_(void *e, const char *n, int s, const char *c, const char *m, ...) {
  (void)e; (void)n; (void)c; (void)s; (void)m; }
static void log3_(void *e, int s, const char *c, const char *m) {
  (void)e; (void)s; (void)c; (void)m; }
int main(int argc, char **argv) {
  void *h = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (!h) return 2;
  int v3 = argv[3][0] == '3', n = atoi(argv[4]);
  unsigned out[] = {%(out)s}, in[] = {%(in)s};
  double x[] = {0.25, 1000.0, 0.009, 40.0}, bad[] = {0.3, 900.0, 0.008, -1.0}, y[3];
  long rss0 = resident_kib();
  for (int i = 0; i < n; i++) {
    void *c;
    if (i == 20) rss0 = resident_kib();
    if (v3) {
      S(fmi3InstantiateCoSimulation) S(fmi3EnterInitializationMode) S(fmi3ExitInitializationMode)
      c = ((void *(*)(const char *, const char *, const char *, bool, bool, bool, bool,
                      const unsigned *, size_t, void *, void *, void *))
           fmi3InstantiateCoSimulation)("x", argv[2], "", 0, 0, 0, 0, NULL, 0, NULL,
                                        (void *)log3_, NULL);
      if (!c) return 4;
      ((int (*)(void *, bool, double, double, bool, double))fmi3EnterInitializationMode)(
          c, 0, 0, 0, 0, 0);
      ((f_v)fmi3ExitInitializationMode)(c);
    } else {
      S(fmi2Instantiate) S(fmi2SetupExperiment) S(fmi2EnterInitializationMode)
      S(fmi2ExitInitializationMode)
      void *cb[5] = {(void *)log2_, NULL, NULL, NULL, NULL};
      c = ((void *(*)(const char *, int, const char *, const char *, void *, int, int))
           fmi2Instantiate)("x", 1, argv[2], "", cb, 0, 0);
      if (!c) return 4;
      ((int (*)(void *, int, double, double, int, double))fmi2SetupExperiment)(c, 0, 0, 0, 0, 0);
      ((f_v)fmi2EnterInitializationMode)(c);
      ((f_v)fmi2ExitInitializationMode)(c);
    }
    void *get = dlsym(h, v3 ? "fmi3GetFloat64" : "fmi2GetReal");
    void *set = dlsym(h, v3 ? "fmi3SetFloat64" : "fmi2SetReal");
    void *gs = dlsym(h, v3 ? "fmi3GetFMUState" : "fmi2GetFMUstate");
    void *ss = dlsym(h, v3 ? "fmi3SetFMUState" : "fmi2SetFMUstate");
    void *fs = dlsym(h, v3 ? "fmi3FreeFMUState" : "fmi2FreeFMUstate");
    void *rs = dlsym(h, v3 ? "fmi3Reset" : "fmi2Reset");
    void *fr = dlsym(h, v3 ? "fmi3FreeInstance" : "fmi2FreeInstance");
#define GET() (v3 ? ((f_rw3)get)(c, out, 3, y, 3) : ((f_rw)get)(c, out, 3, y))
#define SET(a) (v3 ? ((f_rw3)set)(c, in, 4, a, 4) : ((f_rw)set)(c, in, 4, a))
    void *state = NULL;
    if (GET() || ((f_st)gs)(c, &state)) return 5;
    if (SET(x) || GET() > 1 || SET(bad) != 3) return 6; /* F_E < 0: an FMI error */
    if (((f_st1)ss)(c, state) || GET() || ((f_st)fs)(c, &state)) return 7;
    if (((f_v)rs)(c) || GET()) return 8;
    ((void (*)(void *))fr)(c);
  }
  printf("rss_growth_kib %%ld\n", resident_kib() - rss0);
  dlclose(h);
  return 0;
}
"""


def cycles_program(version: int, directory: Path) -> Path:
    """Compiles the cycle program for the FMU `version`; returns the executable."""
    import shutil
    md = description(version)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    src = _CYCLES % {"out": ", ".join(str(vr[n]) for n in ("gamma_P", "F_lim", "sigma_a")),
                     "in": ", ".join(str(vr[n]) for n in ("mu", "CF", "neck_h", "F_E"))}
    (directory / "cycles.c").write_text(src)
    cc = shutil.which("cc") or shutil.which("gcc")
    assert cc, "a C compiler is needed (the build needs one too)"
    exe = directory / "cycles"
    subprocess.run([cc, "-O1", "-g", "-o", str(exe), str(directory / "cycles.c"), "-ldl"],
                   check=True)
    return exe


def token(version: int) -> str:
    md = description(version)
    return md.guid if version == 2 else md.instantiationToken
