"""The portable wheels of `make wheels` (cmake/wheels.py), run by `make test-wheel`.

- The Linux wheel is tagged manylinux, as `auditwheel show` confirms, and its kernel library
  loads nothing from outside the wheel but the C library (libc, libm, libpthread, libdl,
  ld-linux).
- The Windows wheel's udmap.dll imports Windows system DLLs only. Under Wine, a MinGW C driver
  (tests/windows/kernel_driver.c) loads it from the unpacked wheel and gives blade A's F_lim and
  backbone at H = 1, 3 and 9 to 1e-12 of the same driver on the Linux wheel's library.
- Both wheels carry both FMUs, each with its Linux and its Windows binary.
- In a fresh Debian 12 root with only python3, python3-venv and ca-certificates (no compiler,
  no gfortran, no LAPACK; debootstrap, cached in UDMAP_WHEEL_ROOT), the Linux wheel installs
  into a venv; `udmap demo`, `udmap backbone cases/blade_a.json --harmonics auto` and `udmap
  fmu` run there, their numbers are bit-identical to the source build's, and the FMU written
  there has both platforms, passes fmpy's validation and gives under Wine the outputs of its
  Linux binary (the FMUs' Wine test, tests/windows/test_fmu_wine.py, on that FMU).

Environment: UDMAP_DIST (default dist/) holds the wheels; UDMAP_LIBRARY is the source build's
library; the fresh root needs root privileges (chroot) and the Debian mirror.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import struct
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "windows"))
# the FMUs' Wine test: its wine(), and its importer run on both binaries of an FMU
from test_fmu_wine import SYSTEM_DLLS, run_both, unpacked as unpacked_fmu, wine  # noqa: E402
DIST = Path(os.environ.get("UDMAP_DIST", ROOT / "dist"))
FRESH_ROOT = Path(os.environ.get("UDMAP_WHEEL_ROOT", ROOT / "build" / "wheel-root"))
SYSTEM_SO = ("libc.so", "libm.so", "libpthread.so", "libdl.so", "ld-linux", "linux-vdso")
FMU_BINARIES = {"udmap/fmu/udmap.fmu": ("binaries/linux64/udmap.so", "binaries/win64/udmap.dll"),
                "udmap/fmu/udmap-fmi3.fmu": ("binaries/x86_64-linux/udmap.so",
                                             "binaries/x86_64-windows/udmap.dll")}
RTOL = 1e-12
FORCES = "0.5,1,2,5,10,15,20"


def wheel(pattern: str) -> Path:
    found = sorted(DIST.glob(pattern))
    assert len(found) == 1, f"expected one {pattern} in {DIST} (make wheels), found {found}"
    return found[0]


@pytest.fixture(scope="module")
def linux_wheel() -> Path:
    return wheel("udmap-*-py3-none-manylinux_2_*_x86_64.whl")


@pytest.fixture(scope="module")
def windows_wheel() -> Path:
    return wheel("udmap-*-py3-none-win_amd64.whl")


@pytest.fixture(scope="module")
def unpacked(tmp_path_factory, linux_wheel, windows_wheel):
    out = {}
    for name, whl in (("linux", linux_wheel), ("windows", windows_wheel)):
        d = tmp_path_factory.mktemp(name)
        with zipfile.ZipFile(whl) as z:
            z.extractall(d)
        out[name] = d
    return out


def test_auditwheel_confirms_the_manylinux_tag(linux_wheel):
    shown = subprocess.run([sys.executable, "-m", "auditwheel", "show", str(linux_wheel)],
                           check=True, capture_output=True, text=True).stdout
    shown = " ".join(shown.split())  # auditwheel wraps its lines
    tag = re.search(r"manylinux_2_\d+_x86_64", linux_wheel.name).group(0)
    assert f'"{tag}"' in shown and "consistent with the following platform tag" in shown, shown


def test_linux_library_loads_only_the_c_library_from_outside(unpacked):
    root = unpacked["linux"]
    lib = root / "udmap" / "libudmap.so"
    ldd = subprocess.run(["ldd", str(lib)], check=True, capture_output=True, text=True).stdout
    outside = []
    for line in ldd.splitlines():
        m = re.match(r"\s*(\S+)(?:\s+=>\s+(\S+))?", line)
        soname, path = m.group(1), m.group(2)
        if path and Path(path).resolve().is_relative_to(root.resolve()):
            continue
        if not Path(soname).name.startswith(SYSTEM_SO):  # ld-linux comes as a path
            outside.append(line.strip())
    assert not outside, "loaded from outside the wheel:\n" + "\n".join(outside)
    assert "udmap.libs" in ldd  # the bundled runtime is what is loaded


def dll_imports(dll: Path) -> set[str]:
    dump = subprocess.run(["x86_64-w64-mingw32-objdump", "-p", str(dll)], check=True,
                          capture_output=True, text=True).stdout
    return {m.lower() for m in re.findall(r"DLL Name:\s*(\S+)", dump)}


def test_windows_dll_imports_system_dlls_only(unpacked):
    imports = dll_imports(unpacked["windows"] / "udmap" / "udmap.dll")
    assert imports and imports <= SYSTEM_DLLS, imports - SYSTEM_DLLS
    assert not (unpacked["windows"] / "udmap" / "libudmap.so").exists()


@pytest.mark.parametrize("side", ["linux", "windows"])
def test_both_fmus_carry_both_platforms(unpacked, side):
    for fmu, binaries in FMU_BINARIES.items():
        names = zipfile.ZipFile(unpacked[side] / fmu).namelist()
        assert all(b in names for b in binaries), (side, fmu, binaries)


def read_bits(text: str) -> dict[str, float]:
    values = {}
    for line in text.splitlines():
        name, bits, _ = line.split()
        values[name] = struct.unpack("<d", bytes.fromhex(bits)[::-1])[0]
    return values


def test_windows_dll_under_wine_gives_the_linux_backbone(unpacked, tmp_path):
    src = ROOT / "tests" / "windows" / "kernel_driver.c"
    flags = ["-std=c11", "-O2", "-Wall", "-Wextra", "-Werror", f"-I{ROOT / 'wrappers' / 'c'}"]
    native, exe = tmp_path / "driver", tmp_path / "driver.exe"
    subprocess.run(["gcc", *flags, str(src), "-ldl", "-o", str(native)], check=True)
    subprocess.run(["x86_64-w64-mingw32-gcc", *flags, "-static", str(src), "-o", str(exe)],
                   check=True)
    linux = subprocess.run([str(native), str(unpacked["linux"] / "udmap" / "libudmap.so")],
                           check=True, capture_output=True, text=True).stdout
    env = dict(os.environ, WINEPREFIX=str(tmp_path / "wine"), WINEDEBUG="-all")
    dll = unpacked["windows"] / "udmap" / "udmap.dll"
    windows = subprocess.run([wine(), str(exe), "Z:" + str(dll).replace("/", "\\")], env=env,
                             check=True, capture_output=True, text=True, timeout=300).stdout
    a, b = read_bits(linux), read_bits(windows)
    assert a.keys() == b.keys() and len(a) == 1 + 3 * 7 * 3
    worst = max(abs(a[k] - b[k]) / abs(a[k]) for k in a)
    print(f"udmap.dll under Wine against the Linux wheel: {len(a)} numbers, max rel. diff "
          f"{worst:.1e}")
    assert worst <= RTOL


# ---------------------------------------------------------------------- the fresh root
def sh(root: Path, script: str) -> subprocess.CompletedProcess:
    """Runs ``script`` with bash in the chroot ``root``, in a private mount namespace with
    /proc and /dev, and the host's CA bundle and resolver (PyPI through the same egress)."""
    inner = (f"mount -t proc proc {root}/proc && mount --rbind /dev {root}/dev && "
             f"exec chroot {root} /usr/bin/env -i PATH=/usr/local/bin:/usr/bin:/bin HOME=/root "
             "PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_CERT=/etc/ssl/certs/ca-certificates.crt "
             "MPLBACKEND=Agg bash -euo pipefail -c \"$0\"")
    return subprocess.run(["unshare", "--mount", "--propagation", "private", "bash", "-c", inner,
                           script], capture_output=True, text=True, timeout=1800)


def fresh_root(tmp: Path) -> Path:
    """A copy of the cached minimal root (debootstrap --variant=minbase, plus python3,
    python3-venv and ca-certificates), built once."""
    if not (FRESH_ROOT / "usr" / "bin" / "python3").is_file():
        partial = FRESH_ROOT.with_name(FRESH_ROOT.name + ".part")
        shutil.rmtree(partial, ignore_errors=True)
        subprocess.run(["debootstrap", "--variant=minbase",
                        "--include=python3,python3-venv,ca-certificates", "bookworm", str(partial),
                        "http://deb.debian.org/debian"], check=True, capture_output=True)
        partial.rename(FRESH_ROOT)
    root = tmp / "root"
    subprocess.run(["cp", "-a", str(FRESH_ROOT), str(root)], check=True)
    for f in ("/etc/resolv.conf", "/etc/ssl/certs/ca-certificates.crt"):
        shutil.copyfile(f, root / f.lstrip("/"))
    return root


def source_build(args, cwd: Path) -> subprocess.CompletedProcess:
    env = dict(os.environ, PYTHONPATH=str(ROOT / "wrappers" / "python"), MPLBACKEND="Agg")
    return subprocess.run([sys.executable, "-m", "udmap", *args], cwd=cwd, env=env, check=True,
                          capture_output=True, text=True)


def without_paths(obj):
    """A JSON result without what names files or measures time, which differ by design."""
    if isinstance(obj, dict):
        return {k: without_paths(v) for k, v in obj.items()
                if k not in ("out", "files", "case", "elapsed_s", "time_s", "written")}
    if isinstance(obj, list):
        return [without_paths(v) for v in obj]
    return obj


def test_linux_wheel_in_a_fresh_root(linux_wheel, tmp_path):
    if os.geteuid() != 0:
        pytest.fail("the fresh root needs root privileges (debootstrap, chroot)")
    root = fresh_root(tmp_path)
    (root / "w").mkdir()
    shutil.copy(linux_wheel, root / "w")
    shutil.copy(ROOT / "cases" / "blade_a.json", root / "w")
    run = sh(root, f"""
        for tool in gcc cc gfortran; do
          if command -v $tool; then echo "the fresh root has $tool"; exit 1; fi
        done
        if ls /usr/lib/x86_64-linux-gnu/ | grep -E 'lib(lapack|blas|gfortran|arpack)'; then
          echo "the fresh root has LAPACK, BLAS, ARPACK or libgfortran"; exit 1
        fi
        python3 -m venv /v && /v/bin/pip install -q /w/{linux_wheel.name}
        cd /w && /v/bin/udmap demo --out demo > demo.txt
        /v/bin/udmap backbone blade_a.json --forces {FORCES} --harmonics auto --json > bb.json
        /v/bin/udmap fmu blade_a.json --out blade_a.fmu --json > fmu.json
        ldd /v/lib/python3*/site-packages/udmap/libudmap.so > ldd.txt""")
    assert run.returncode == 0, run.stdout + run.stderr
    w = root / "w"
    # the same commands on the source build
    src = tmp_path / "src"
    src.mkdir()
    source_build(["demo", "--out", str(src / "demo")], src)
    bb = source_build(["backbone", str(ROOT / "cases" / "blade_a.json"), "--forces", FORCES,
                       "--harmonics", "auto", "--json"], src).stdout
    wheel_bb = json.loads((w / "bb.json").read_text())
    assert len(wheel_bb["points"]) == 7 and wheel_bb["points"][-1]["gamma_P"] > 0
    assert without_paths(wheel_bb) == without_paths(json.loads(bb))
    assert (without_paths(json.loads((w / "demo" / "summary.json").read_text()))
            == without_paths(json.loads((src / "demo" / "summary.json").read_text())))
    assert (w / "demo" / "backbone.csv").read_bytes() == (src / "demo" / "backbone.csv").read_bytes()
    # the FMU written in the fresh root: both platforms, valid for fmpy
    names = zipfile.ZipFile(w / "blade_a.fmu").namelist()
    assert "binaries/linux64/udmap.so" in names and "binaries/win64/udmap.dll" in names
    from fmpy.validation import validate_fmu
    assert validate_fmu(str(w / "blade_a.fmu")) == []
    # and it runs under Wine as on Linux (the FMUs' Wine test on this FMU, co-simulation)
    result = run_both(2, unpacked_fmu(2, tmp_path / "fmu", w / "blade_a.fmu"), tmp_path, "cs")
    print(f"the wheel's FMU under Wine against Linux: {result['steps']} steps, max rel. diff "
          f"{result['max_relative_difference']:.1e}")
    outside = [ln for ln in (w / "ldd.txt").read_text().splitlines()
               if "udmap.libs" not in ln and not Path(ln.split()[0]).name.startswith(SYSTEM_SO)]
    assert not outside, outside
