"""The Windows x86-64 binaries of both FMUs (built with -DUDMAP_WINDOWS_FMU=ON, `make
test-windows`): packed beside the Linux ones, importing Windows system DLLs only, exporting the
FMI functions only, and giving the Linux outputs under Wine.

The same importer source (tests/windows/fmu_import.c) is built with MinGW-w64 and run under
Debian's wine64 on udmap.dll, and built natively and run on udmap.so; both drive FMI
co-simulation or model exchange over blade A's F_E sequence with changes of CF, mu and the
excitation frequency, then two out-of-range inputs (an FMI error; the instance keeps its values
and goes on), and print the outputs as IEEE-754 bit patterns. Real outputs agree to 1e-12
relative, integers, booleans, statuses and the error messages exactly. The same holds for an
FMU of a case made by `python -m udmap fmu` (blade A as a matrices blade read from Matrix
Market files, with a measured damper table), unpacked into a folder whose name has a space, so
that its resources are found through a percent-encoded file URI (FMI 2) or a Windows path
(FMI 3). The numbers are written to <build>/windows-test.json for the record."""
from __future__ import annotations

import json
import os
import re
import shutil
import struct
import subprocess
import sys
import urllib.parse
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
# out of range (mu in [1e-4, 10], CF in [1e-3, 1e6]): an FMI error, nothing of the call taken
BAD = [(900.0, 20.0, 185.0, [12.0]), (0.0, 0.3, 185.0, [30.0])]
STEP = 0.5
OK, ERROR = 0, 3


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


def windows_uri(path: Path) -> str:
    """file:///Z:/dir%20name/... (RFC 8089, percent-encoded), as a Windows importer gives."""
    return "file:///" + urllib.parse.quote(windows_path(path).replace("\\", "/"), safe="/:")


def unpacked(version: int, tmp: Path, fmu: Path | None = None) -> Path:
    fmu = fmu or FMUS[version]
    assert fmu.is_file(), f"{fmu} is missing: build with make test-windows"
    d = tmp / f"fmi{version} unpacked"  # a space: percent-encoded in the FMI 2 resource URI
    with zipfile.ZipFile(fmu) as zf:
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


def steps(vars_: dict) -> list[dict]:
    """The input values of each step (the inputs the FMU has) and the status it must give."""
    out = []
    for segments, status in ((SEGMENTS, OK), (BAD, ERROR)):
        for CF, mu, f_exc, forces in segments:
            for F in forces:
                values = {"F_E": F, "CF": CF, "mu": mu, "f_exc": f_exc}
                out.append({"inputs": {n: values[n] for n in INPUTS if n in vars_},
                            "status": status})
    # an FMU without mu and CF (a table damper) cannot be given out-of-range values of them
    return [s for s in out if s["status"] == OK or set(s["inputs"]) == set(INPUTS)]


def script(vars_: dict) -> tuple[str, list[str], list[str], list[str], list[dict]]:
    real_kinds = {"Real", "Float64"}
    outs = [n for n, (_, _, c) in vars_.items() if c == "output"]
    reals = [n for n in outs if vars_[n][1] in real_kinds]
    ints = [n for n in outs if vars_[n][1] in {"Integer", "Int32"}]
    bools = [n for n in outs if vars_[n][1] == "Boolean"]
    assert len(reals) >= 8 and ints and bools, outs
    inputs = [n for n in INPUTS if n in vars_]
    assert "F_E" in inputs and "f_exc" in inputs, inputs
    lines = []
    for names in (inputs, reals, ints, bools):
        lines.append(" ".join([str(len(names))] + [str(vars_[n][0]) for n in names]))
    todo = steps(vars_)
    lines.append(str(len(todo)))
    for k, step in enumerate(todo):
        lines.append(" ".join([repr(k * STEP), repr(STEP)]
                              + [repr(step["inputs"][n]) for n in inputs]))
    return "\n".join(lines) + "\n", reals, ints, bools, todo


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


def run_both(version: int, root: Path, tmp: Path, interface: str) -> dict:
    """Runs the importer on the Linux binary and, under Wine, on the DLL of the unpacked FMU
    `root`, compares the two and returns the record of the comparison."""
    vars_, token = variables(root)
    text, reals, ints, bools, todo = script(vars_)
    (tmp / "steps.txt").write_text(text)
    so = root / "binaries" / LINUX[version] / "udmap.so"
    dll = root / "binaries" / WINDOWS[version] / "udmap.dll"
    # FMI 2: the resources as a file URI; FMI 3: the resources folder's path, ending in a
    # separator
    resources = root / "resources"
    linux_res = resources.as_uri() if version == 2 else str(resources) + "/"
    win_res = windows_uri(resources) if version == 2 else windows_path(resources) + "\\"
    linux = subprocess.run([str(IMPORTER), str(version), str(so), token, linux_res,
                            str(tmp / "steps.txt"), interface],
                           capture_output=True, text=True, timeout=60)
    assert linux.returncode == 0, linux.stderr[-2000:]
    win = subprocess.run([wine(), str(IMPORTER_EXE), str(version), windows_path(dll), token,
                          win_res, windows_path(tmp / "steps.txt"), interface],
                         capture_output=True, text=True, timeout=100, env=wine_env())
    assert win.returncode == 0, (win.stdout[-1000:], win.stderr[-2000:])
    a = parse(linux.stdout, len(reals), len(ints), len(bools))
    b = parse(win.stdout, len(reals), len(ints), len(bools))
    assert len(a) == len(b) == len(todo)
    worst, where, identical = 0.0, None, 0
    for (k, st_a, ra, ia), (k_b, st_b, rb, ib), step in zip(a, b, todo):
        assert k == k_b and st_a == st_b == step["status"], (k, st_a, st_b, step)
        assert ia == ib, (k, dict(zip(ints + bools, ia)), dict(zip(ints + bools, ib)))
        if step["status"] == ERROR:  # nothing of the call taken: the last step's outputs
            assert (ra, ia) == (a[k - 1][2], a[k - 1][3]), k
        for name, x, y in zip(reals, ra, rb):
            assert x == x and y == y, (k, name, x, y)  # no NaN
            d = abs(x - y) / abs(x) if x != 0.0 else abs(y)
            if d > worst:
                worst, where = d, (k, name, x, y)
            identical += x == y
            assert d <= RTOL, (k, name, x, y, d)
    # the error messages (the FMU's own formatting of the numbers) are the same
    def errors(stderr: str) -> list[str]:
        return [line.split(": ", 1)[1] for line in stderr.splitlines() if "must be" in line]
    n_bad = sum(s["status"] == ERROR for s in todo)
    assert len(errors(linux.stderr)) == n_bad, linux.stderr[-2000:]
    assert errors(win.stderr) == errors(linux.stderr), (win.stderr[-2000:], linux.stderr)
    return {"regimes": sorted({r[3][ints.index("regime")] for r in a}), "steps": len(todo),
            "error_steps": n_bad, "error_messages": errors(linux.stderr),
            "real_outputs": reals, "max_relative_difference": worst, "worst": where,
            "bitwise_identical_values": identical, "values": len(todo) * len(reals)}


@pytest.mark.parametrize("interface", ["cs", "me"])
@pytest.mark.parametrize("version", [2, 3])
def test_wine_gives_the_linux_outputs(version, interface, tmp_path):
    result = run_both(version, unpacked(version, tmp_path), tmp_path, interface)
    # the sequence crosses the regimes: 0 stuck, 1 partial slip, 2 full slip
    assert {0, 1, 2} <= set(result["regimes"]), result["regimes"]
    assert result["error_steps"] == len(BAD)
    record(f"fmi{version}_{interface}_wine_vs_linux", result)


@pytest.fixture(scope="module")
def case_file(tmp_path_factory):
    """The case of tests/python/test_fmu_case.py: blade A as a matrices blade with its damper
    tabulated as a measured table."""
    sys.path[:0] = [str(ROOT / "wrappers" / "python"), str(ROOT / "tests" / "python")]
    from fmu_harness import write_matrices_table_case
    return write_matrices_table_case(tmp_path_factory.mktemp("case"))


@pytest.mark.parametrize("version", [2, 3])
def test_wine_gives_the_linux_outputs_of_a_case_fmu(version, case_file, tmp_path):
    fmu = tmp_path / f"case-fmi{version}.fmu"
    env = dict(os.environ, PYTHONPATH=str(ROOT / "wrappers" / "python"),
               UDMAP_BUILD_DIR=str(BUILD))
    r = subprocess.run([sys.executable, "-m", "udmap", "fmu", str(case_file), "--out", str(fmu),
                        "--fmi", str(version)], cwd=ROOT, env=env, capture_output=True,
                       text=True, timeout=100)
    assert r.returncode == 0, r.stderr
    root = unpacked(version, tmp_path, fmu)
    # the case is read at instantiation: its token differs from the generic FMU's, and its
    # blade comes from the Matrix Market files beside the case file
    assert variables(root)[1] != variables(unpacked(version, tmp_path / "generic"))[1]
    assert (root / "resources" / "udmap-case.txt").is_file()
    assert (root / "resources" / "K.mtx").is_file()
    vars_ = variables(root)[0]
    assert "mu" not in vars_ and "CF" not in vars_  # a table damper
    result = run_both(version, root, tmp_path, "cs")
    assert result["error_steps"] == 0
    record(f"fmi{version}_case_wine_vs_linux", result)
