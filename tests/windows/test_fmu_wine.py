"""The Windows x86-64 binaries of both FMUs (built with -DUDMAP_WINDOWS_FMU=ON, `make
test-windows`): packed beside the Linux ones, importing Windows system DLLs only, exporting the
FMI functions only, and giving the Linux outputs under Wine.

The same importer source (tests/windows/fmu_import.c) is built with MinGW-w64 and run under
Debian's wine64 on udmap.dll, and built natively and run on udmap.so; both drive FMI
co-simulation over blade A's F_E sequence with changes of CF, mu and the excitation frequency,
and print the outputs as IEEE-754 bit patterns. Real outputs agree to 1e-12 relative,
integers, booleans and statuses exactly. The numbers are written to
<build>/windows-test.json for the record."""
from __future__ import annotations

import json
import os
import re
import shutil
import struct
import subprocess
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("UDMAP_BUILD_DIR", ROOT / "build"))
FMUS = {2: BUILD / "udmap.fmu", 3: BUILD / "udmap-fmi3.fmu"}
LINUX = {2: "linux64", 3: "x86_64-linux"}
WINDOWS = {2: "win64", 3: "x86_64-windows"}
IMPORTER = BUILD / "fmu" / "udmap-fmu-import"
IMPORTER_EXE = BUILD / "win64" / "fmu" / "udmap-fmu-import.exe"
RTOL = 1e-12
# DLLs that are part of every Windows installation (the MinGW C runtime is msvcrt.dll)
SYSTEM_DLLS = {"kernel32.dll", "msvcrt.dll", "user32.dll", "advapi32.dll", "shell32.dll",
               "ws2_32.dll", "ntdll.dll", "ucrtbase.dll", "bcrypt.dll"}
INPUTS = ["F_E", "CF", "mu", "f_exc"]
# blade A (the FMU's start values): F_E from the stuck through the partial-slip to the gross-slip
# regime at the nominal CF and mu, then a CF change alone, mu changes and an excitation frequency
FORCES = [0.1, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0,
          12.0, 15.0, 20.0, 25.0, 30.0]
SEGMENTS = ([(900.0, 0.3, 0.0, FORCES)]
            + [(1200.0, 0.3, 0.0, [0.5, 2.0, 5.0, 12.0, 20.0])]
            + [(1200.0, 0.22, 0.0, [0.5, 2.0, 5.0, 12.0, 20.0])]
            + [(700.0, 0.35, 0.0, [0.5, 3.5, 8.0, 20.0])]
            + [(900.0, 0.3, 185.0, [1.0, 5.0, 12.0])])
STEP = 0.5


def wine() -> str:
    path = shutil.which("wine64") or shutil.which("wine")
    if not path and Path("/usr/lib/wine/wine64").is_file():  # Debian's wine64 package
        path = "/usr/lib/wine/wine64"
    assert path, "wine64 is needed (Debian package wine64; make test-windows installs it)"
    return path


def wine_env() -> dict:
    env = dict(os.environ)
    env["WINEPREFIX"] = str(BUILD / "wine-prefix")  # created by the first run (~20 s)
    env["WINEDEBUG"] = "-all"
    env.setdefault("WINEDLLOVERRIDES", "mscoree,mshtml=")  # no Mono/Gecko installer prompt
    return env


def windows_path(path: Path) -> str:
    return "Z:" + str(path.resolve()).replace("/", "\\")


def unpacked(version: int, tmp: Path) -> Path:
    assert FMUS[version].is_file(), f"{FMUS[version]} is missing: build with make test-windows"
    d = tmp / f"fmi{version}"
    with zipfile.ZipFile(FMUS[version]) as zf:
        zf.extractall(d)
    return d


def variables(root: Path) -> tuple[dict, str]:
    md = ET.parse(root / "modelDescription.xml").getroot()
    token = md.get("guid") or md.get("instantiationToken")
    out = {}
    for v in md.iter():
        if v.get("valueReference") is None or v.get("name") is None:
            continue
        if v.tag == "ScalarVariable":  # FMI 2: the type is the child element
            kind = v[0].tag
        else:
            kind = v.tag
        out[v.get("name")] = (int(v.get("valueReference")), kind, v.get("causality"))
    return out, token


def script(vars_: dict) -> tuple[str, list[str], list[str], list[str]]:
    real_kinds = {"Real", "Float64"}
    outs = [n for n, (_, _, c) in vars_.items() if c == "output"]
    reals = [n for n in outs if vars_[n][1] in real_kinds]
    ints = [n for n in outs if vars_[n][1] in {"Integer", "Int32"}]
    bools = [n for n in outs if vars_[n][1] == "Boolean"]
    assert len(reals) >= 8 and ints and bools, outs
    lines = []
    for names in (INPUTS, reals, ints, bools):
        lines.append(" ".join([str(len(names))] + [str(vars_[n][0]) for n in names]))
    rows = []
    t = 0.0
    for CF, mu, f_exc, forces in SEGMENTS:
        for F in forces:
            rows.append(f"{t!r} {STEP!r} {F!r} {CF!r} {mu!r} {f_exc!r}")
            t += STEP
    lines.append(str(len(rows)))
    lines += rows
    return "\n".join(lines) + "\n", reals, ints, bools


def parse(stdout: str, n_real: int, n_int: int, n_bool: int) -> list[tuple]:
    rows = []
    for line in stdout.splitlines():
        f = line.split()
        if not f:
            continue
        assert len(f) == 2 + n_real + n_int + n_bool, line
        reals = [struct.unpack("<d", bytes.fromhex(h)[::-1])[0] for h in f[2:2 + n_real]]
        rest = [int(x) for x in f[2 + n_real:]]
        rows.append((int(f[0]), int(f[1]), reals, rest))
    return rows


def test_importers_are_built():
    assert IMPORTER.is_file(), f"{IMPORTER} is missing (configure with -DUDMAP_WINDOWS_FMU=ON)"
    assert IMPORTER_EXE.is_file(), f"{IMPORTER_EXE} is missing"


@pytest.mark.parametrize("version", [2, 3])
def test_fmu_carries_linux_and_windows_binaries(version):
    with zipfile.ZipFile(FMUS[version]) as zf:
        names = {n for n in zf.namelist() if n.startswith("binaries/") and not n.endswith("/")}
    # one DLL for Windows, nothing beside it; the Linux folder is test_fmu_binary.py's
    assert {n for n in names if n.startswith(f"binaries/{WINDOWS[version]}/")} == {
        f"binaries/{WINDOWS[version]}/udmap.dll"}, names
    assert f"binaries/{LINUX[version]}/udmap.so" in names
    assert {n.split("/")[1] for n in names} == {LINUX[version], WINDOWS[version]}, names


def pe(path: Path) -> str:
    return subprocess.run(["x86_64-w64-mingw32-objdump", "-p", str(path)], check=True,
                          capture_output=True, text=True).stdout


@pytest.mark.parametrize("version", [2, 3])
def test_dll_imports_system_dlls_only(version, tmp_path):
    dll = unpacked(version, tmp_path) / "binaries" / WINDOWS[version] / "udmap.dll"
    text = pe(dll)
    assert "file format pei-x86-64" in text
    imports = {n.lower() for n in re.findall(r"DLL Name: (\S+)", text)}
    assert imports and imports <= SYSTEM_DLLS, imports - SYSTEM_DLLS
    assert not any(re.search(r"gfortran|quadmath|gcc|pthread|lapack|blas|stdc", n)
                   for n in imports), imports
    # exports: the FMI functions only (no kernel, LAPACK or runtime symbol)
    table = text.split("[Ordinal/Name Pointer] Table", 1)[1].split("\n\n", 1)[0]
    exports = re.findall(r"\]\s+(\S+)", table)
    assert len(exports) > 30 and all(e.startswith(f"fmi{version}") for e in exports), exports
    record(f"fmi{version}_dll_imports", sorted(imports))


def record(key: str, value) -> None:
    path = BUILD / "windows-test.json"
    data = json.loads(path.read_text()) if path.is_file() else {}
    data[key] = value
    path.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")


@pytest.mark.parametrize("version", [2, 3])
def test_wine_gives_the_linux_outputs(version, tmp_path):
    root = unpacked(version, tmp_path)
    vars_, token = variables(root)
    text, reals, ints, bools = script(vars_)
    (tmp_path / "steps.txt").write_text(text)
    so = root / "binaries" / LINUX[version] / "udmap.so"
    dll = root / "binaries" / WINDOWS[version] / "udmap.dll"
    resources = (root / "resources").as_uri() if version == 2 else ""
    linux = subprocess.run([str(IMPORTER), str(version), str(so), token, resources,
                            str(tmp_path / "steps.txt")],
                           capture_output=True, text=True, timeout=60)
    assert linux.returncode == 0, linux.stderr[-2000:]
    win_resources = ("file:///" + windows_path(root / "resources").replace("\\", "/")
                     if version == 2 else "")
    win = subprocess.run([wine(), str(IMPORTER_EXE), str(version), windows_path(dll), token,
                          win_resources, windows_path(tmp_path / "steps.txt")],
                         capture_output=True, text=True, timeout=100, env=wine_env())
    assert win.returncode == 0, (win.stdout[-1000:], win.stderr[-2000:])
    a = parse(linux.stdout, len(reals), len(ints), len(bools))
    b = parse(win.stdout, len(reals), len(ints), len(bools))
    n_steps = sum(len(s[3]) for s in SEGMENTS)
    assert len(a) == len(b) == n_steps
    worst, where, identical = 0.0, None, 0
    for (k, st_a, ra, ia), (k_b, st_b, rb, ib) in zip(a, b):
        assert k == k_b and st_a == st_b == 0, (k, st_a, st_b)
        assert ia == ib, (k, dict(zip(ints + bools, ia)), dict(zip(ints + bools, ib)))
        for name, x, y in zip(reals, ra, rb):
            assert x == x and y == y, (k, name, x, y)  # no NaN
            d = abs(x - y) / abs(x) if x != 0.0 else abs(y)
            if d > worst:
                worst, where = d, (k, name, x, y)
            identical += x == y
            assert d <= RTOL, (k, name, x, y, d)
    # the sequence crosses the regimes: 0 stuck, 1 partial slip, 2 full slip
    regimes = sorted({r[3][ints.index("regime")] for r in a})
    assert {0, 1, 2} <= set(regimes), regimes
    record(f"fmi{version}_wine_vs_linux", {
        "regimes": regimes,
        "steps": n_steps, "real_outputs": reals, "max_relative_difference": worst,
        "worst": where, "bitwise_identical_values": identical,
        "values": n_steps * len(reals)})
