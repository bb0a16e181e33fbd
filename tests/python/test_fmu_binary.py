"""The FMU binaries are self-contained: one library per platform with the GCC runtime linked in
statically, needing only the C library (no NEEDED entry for libgfortran or libquadmath, nothing
beside it; checked with LD_DEBUG=libs, whether or not gfortran is installed), only FMI
functions are exported, and the C layer matches the standard FMI headers (those shipped with
fmpy)."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from fmu_harness import PLATFORM, ROOT, binary, extract

SYSTEM = {"libc.so.6", "libm.so.6", "libmvec.so.1", "libpthread.so.0", "libdl.so.2",
          "librt.so.1", "ld-linux-x86-64.so.2"}

FMI2_FUNCTIONS = """GetTypesPlatform GetVersion SetDebugLogging Instantiate FreeInstance
SetupExperiment EnterInitializationMode ExitInitializationMode Terminate Reset GetReal GetInteger
GetBoolean GetString SetReal SetInteger SetBoolean SetString GetFMUstate SetFMUstate FreeFMUstate
SerializedFMUstateSize SerializeFMUstate DeSerializeFMUstate GetDirectionalDerivative
EnterEventMode NewDiscreteStates EnterContinuousTimeMode CompletedIntegratorStep SetTime
SetContinuousStates GetDerivatives GetEventIndicators GetContinuousStates
GetNominalsOfContinuousStates SetRealInputDerivatives GetRealOutputDerivatives DoStep CancelStep GetStatus GetRealStatus
GetIntegerStatus GetBooleanStatus GetStringStatus""".split()
FMI3_FUNCTIONS = """GetVersion SetDebugLogging InstantiateModelExchange InstantiateCoSimulation
InstantiateScheduledExecution FreeInstance EnterInitializationMode ExitInitializationMode
EnterEventMode Terminate Reset GetFloat32 GetFloat64 GetInt8 GetUInt8 GetInt16 GetUInt16 GetInt32
GetUInt32 GetInt64 GetUInt64 GetBoolean GetString GetBinary GetClock SetFloat32 SetFloat64 SetInt8
SetUInt8 SetInt16 SetUInt16 SetInt32 SetUInt32 SetInt64 SetUInt64 SetBoolean SetString SetBinary
SetClock GetNumberOfVariableDependencies GetVariableDependencies GetFMUState SetFMUState
FreeFMUState SerializedFMUStateSize SerializeFMUState DeserializeFMUState
GetDirectionalDerivative GetAdjointDerivative EnterConfigurationMode ExitConfigurationMode
GetIntervalDecimal GetIntervalFraction GetShiftDecimal GetShiftFraction SetIntervalDecimal
SetIntervalFraction SetShiftDecimal SetShiftFraction EvaluateDiscreteStates UpdateDiscreteStates
EnterContinuousTimeMode CompletedIntegratorStep SetTime SetContinuousStates
GetContinuousStateDerivatives GetEventIndicators GetContinuousStates
GetNominalsOfContinuousStates GetNumberOfEventIndicators GetNumberOfContinuousStates
EnterStepMode GetOutputDerivatives DoStep ActivateModelPartition""".split()


def dynamic(path: Path) -> str:
    return subprocess.run(["readelf", "-d", str(path)], check=True, capture_output=True,
                          text=True).stdout


def needed(path: Path) -> set[str]:
    return set(re.findall(r"\(NEEDED\)\s+Shared library: \[(.+?)\]", dynamic(path)))


@pytest.mark.parametrize("version", [2, 3])
def test_dynamic_dependencies(version):
    so = binary(version)
    deps = needed(so)
    assert deps <= SYSTEM, deps - SYSTEM
    assert not any(lib in d for d in deps
                   for lib in ("gfortran", "quadmath", "gcc_s", "lapack", "blas", "arpack"))
    # the Fortran kernel and its runtime are inside: nothing beside the binary, no search path
    assert sorted(p.name for p in extract(version).glob(f"binaries/{PLATFORM[version]}/*")) \
        == ["udmap.so"]
    d = dynamic(so)
    assert "RPATH" not in d and "RUNPATH" not in d, d


def test_kernel_opens_no_asynchronous_unit():
    # fmu/gfortran_runtime.c stands in for libgfortran's asynchronous I/O on that ground
    for src in sorted((ROOT / "kernel" / "src").rglob("*.[fF]90")):
        text = src.read_text()
        assert not re.search(r"asynchronous\s*=", text, re.IGNORECASE), src


@pytest.mark.parametrize("version", [2, 3])
def test_exports_only_fmi_functions(version):
    out = subprocess.run(["nm", "-D", "--defined-only", str(binary(version))], check=True,
                         capture_output=True, text=True).stdout
    symbols = {line.split()[-1] for line in out.splitlines() if line.strip()}
    prefix = f"fmi{version}"
    assert all(s.startswith(prefix) for s in symbols), sorted(s for s in symbols
                                                              if not s.startswith(prefix))
    expected = FMI2_FUNCTIONS if version == 2 else FMI3_FUNCTIONS
    assert symbols == {prefix + f for f in expected}
    # no LAPACK, BLAS, gfortran-module or kernel symbol leaks
    out = subprocess.run(["nm", "-D", str(binary(version))], check=True, capture_output=True,
                         text=True).stdout
    assert not re.search(r"\b(dgesv_|zgetrf_|udmap_\w+|__udmap_\w+)\b", out)


LOADER = r"""
#include <dlfcn.h>
#include <stdio.h>
int main(int argc, char **argv) {
  void *h = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (!h) { fprintf(stderr, "dlopen: %s\n", dlerror()); return 1; }
  const char *(*version)(void) = (const char *(*)(void))dlsym(h, argv[2]);
  if (!version) { fprintf(stderr, "dlsym: %s\n", dlerror()); return 1; }
  printf("%s\n", version());
  return 0;
}
"""


@pytest.fixture(scope="module")
def loader(tmp_path_factory):
    """A minimal C program that only dlopens a library (no Python, no other libraries)."""
    d = tmp_path_factory.mktemp("loader")
    (d / "loader.c").write_text(LOADER)
    cc = shutil.which("cc") or shutil.which("gcc")
    assert cc, "a C compiler is needed (the build needs one too)"
    subprocess.run([cc, "-o", str(d / "loader"), str(d / "loader.c"), "-ldl"], check=True)
    return d / "loader"


@pytest.mark.parametrize("version", [2, 3])
def test_the_binary_loads_alone(version, loader, tmp_path):
    # a fresh copy of the unpacked FMU in a new place: nothing may depend on where it was built
    fmu_dir = tmp_path / "unpacked"
    shutil.copytree(extract(version), fmu_dir)
    bindir = (fmu_dir / "binaries" / PLATFORM[version]).resolve()
    env = {k: v for k, v in os.environ.items() if not k.startswith("LD_")}
    env["LD_DEBUG"] = "libs"
    r = subprocess.run([str(loader), str(bindir / "udmap.so"), f"fmi{version}GetVersion"],
                       capture_output=True, text=True, env=env, timeout=60)
    assert r.returncode == 0, r.stderr[-2000:]
    assert r.stdout.strip() == ("2.0" if version == 2 else "3.0")
    inits = re.findall(r"calling init: (\S+)", r.stderr)
    assert inits, r.stderr[-2000:]
    resolved = {Path(p).name: Path(p).resolve() for p in inits}
    for name, path in resolved.items():
        if path.parent == bindir:
            continue
        assert name in SYSTEM, f"{name} resolved outside the FMU: {path}"
    assert resolved["udmap.so"].parent == bindir
    assert not any("gfortran" in n or "quadmath" in n for n in resolved), sorted(resolved)


@pytest.mark.parametrize("version", [2, 3])
def test_c_layer_matches_standard_headers(version, tmp_path):
    import fmpy
    headers = Path(fmpy.__file__).parent / "c-code"
    header = headers / f"fmi{version}Functions.h"
    assert header.is_file()
    cc = shutil.which("cc") or shutil.which("gcc")
    r = subprocess.run([cc, "-std=c11", "-fsyntax-only", "-Wall", "-Wextra", "-Werror",
                        "-include", str(header), f"-I{ROOT / 'fmu'}",
                        f"-I{ROOT / 'wrappers' / 'c'}", '-DUDMAP_FMU_VERSION="0"',
                        str(ROOT / "fmu" / f"fmi{version}Functions.c")],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
