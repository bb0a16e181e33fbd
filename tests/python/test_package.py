"""The installed package's layout (`pip install .`, pyproject.toml) without rebuilding: the CMake
component `python` of this build (what scikit-build-core installs into the wheel) installed into
a fresh directory beside a copy of wrappers/python/udmap (the wheel's Python sources). Run there
with a clean environment, the package loads its own library first and finds its own FMUs, and
gives the source tree's results; the source tree finds the build's FMUs; the version is read from
CMakeLists.txt; every third-party import of the package is a dependency. The full `pip install .`
into a fresh venv (three minutes of compiling) is `make test-pip` (README "Install")."""
import ast
import json
import os
import re
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

import udmap
from udmap import InputError, fmu_path

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("UDMAP_BUILD_DIR", ROOT / "build"))
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())
SKBUILD = PYPROJECT["tool"]["scikit-build"]
WHEEL_FILES = {"udmap/libudmap.so", "udmap/fmu/udmap.fmu", "udmap/fmu/udmap-fmi3.fmu"}
FORCES = "0.5,2,8"


def _cmake() -> str:
    cache = (BUILD / "CMakeCache.txt").read_text()
    return re.search(r"^CMAKE_COMMAND:INTERNAL=(.+)$", cache, re.M).group(1)


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    """A directory laid out as the wheel's platlib."""
    site = tmp_path_factory.mktemp("site")
    assert SKBUILD["install"]["components"] == ["python"]
    subprocess.run([_cmake(), "--install", str(BUILD), "--component", "python", "--prefix",
                    str(site)], check=True, capture_output=True, timeout=60)
    installed = {str(p.relative_to(site)) for p in site.rglob("*") if p.is_file()}
    assert installed == WHEEL_FILES  # no headers, .mod files, CMake or pkg-config files
    (package,) = SKBUILD["wheel"]["packages"]
    shutil.copytree(ROOT / package, site / "udmap", dirs_exist_ok=True,
                    ignore=shutil.ignore_patterns("__pycache__"))
    return site


def _run(site, args, extra_env=None):
    env = {k: v for k, v in os.environ.items() if not k.startswith("UDMAP_")}
    env["PYTHONPATH"] = str(site)
    env.update(extra_env or {})
    done = subprocess.run([sys.executable, *args], env=env, cwd=site.parent, capture_output=True,
                          text=True, timeout=90)
    assert done.returncode == 0, done.stderr
    return done.stdout


PROBE = ("import json, udmap; print(json.dumps([udmap.__file__, udmap.library_path(), "
         "str(udmap.fmu_path(2)), str(udmap.fmu_path(3))]))")


@pytest.mark.parametrize("extra_env", [{}, {"UDMAP_BUILD_DIR": str(BUILD)}],
                         ids=["clean", "build-dir-set"])
def test_installed_package_uses_its_own_library_and_fmus(site, extra_env):
    init, lib, fmu2, fmu3 = json.loads(_run(site, ["-c", PROBE], extra_env))
    pkg = site / "udmap"
    assert Path(init).parent == pkg
    assert (Path(lib), Path(fmu2), Path(fmu3)) == (
        pkg / "libudmap.so", pkg / "fmu" / "udmap.fmu", pkg / "fmu" / "udmap-fmi3.fmu")
    assert Path(fmu2).read_bytes() == (BUILD / "udmap.fmu").read_bytes()
    assert Path(fmu3).read_bytes() == (BUILD / "udmap-fmi3.fmu").read_bytes()


def test_installed_package_gives_the_source_trees_results(site):
    args = ["-m", "udmap", "backbone", str(ROOT / "cases" / "blade_a.json"), "--forces", FORCES,
            "--json"]
    installed = json.loads(_run(site, args))
    tree = subprocess.run([sys.executable, *args], capture_output=True, text=True, timeout=90,
                          check=True).stdout
    assert installed == json.loads(tree)
    assert _run(site, ["-m", "udmap", "--version"]).strip() == udmap.version()


def test_repaired_wheel_is_self_contained_and_gives_the_same_results(site, tmp_path):
    """cmake/wheels.py linux (make wheels) on a wheel of this layout: the libraries are
    bundled with RPATH $ORIGIN, the tag is the one auditwheel confirms, and the unpacked wheel,
    with no other library path, gives the source tree's results."""
    raw = tmp_path / "raw"
    shutil.copytree(site, raw)
    info = raw / f"udmap-{udmap.version()}.dist-info"
    info.mkdir()
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: udmap\nVersion: {udmap.version()}\n")
    (info / "WHEEL").write_text("Wheel-Version: 1.0\nGenerator: test\nRoot-Is-Purelib: false\n"
                                "Tag: py3-none-linux_x86_64\n")
    whl = tmp_path / f"udmap-{udmap.version()}-py3-none-linux_x86_64.whl"
    shutil.make_archive(str(whl.with_suffix("")), "zip", raw)
    whl.with_suffix(".zip").rename(whl)
    subprocess.run([sys.executable, str(ROOT / "cmake" / "wheels.py"), "linux", str(whl),
                    "--out", str(tmp_path / "dist")], check=True, capture_output=True, timeout=120)
    (repaired,) = (tmp_path / "dist").glob("udmap-*-py3-none-manylinux_2_*_x86_64.whl")
    shown = subprocess.run([sys.executable, "-m", "auditwheel", "show", str(repaired)],
                           check=True, capture_output=True, text=True, timeout=120).stdout
    tag = re.search(r"manylinux_2_\d+_x86_64", repaired.name).group(0)
    assert f'platform tag: "{tag}"' in " ".join(shown.split())
    out = tmp_path / "site"
    shutil.unpack_archive(repaired, out, "zip")
    lib = out / "udmap" / "libudmap.so"
    ldd = subprocess.run(["ldd", str(lib)], check=True, capture_output=True, text=True).stdout
    for line in ldd.splitlines():
        name, _, path = line.strip().partition(" => ")
        inside = path and Path(path.split()[0]).resolve().parent == out / "udmap.libs"
        assert inside or re.match(r"(linux-vdso|libc|libm|libpthread|libdl)\.so|/lib64/ld-linux",
                                  name), line
    names = {p.name for p in (out / "udmap.libs").iterdir()}
    assert any(n.startswith("libgfortran-") for n in names)
    assert any(n.startswith("liblapack-") for n in names)
    args = ["-m", "udmap", "backbone", str(ROOT / "cases" / "blade_a.json"), "--forces", FORCES,
            "--json"]
    tree = subprocess.run([sys.executable, *args], capture_output=True, text=True, timeout=90,
                          check=True).stdout
    assert json.loads(_run(out, args, {"LD_LIBRARY_PATH": ""})) == json.loads(tree)


def test_source_tree_finds_the_builds_fmus():
    assert fmu_path(2) == BUILD / "udmap.fmu" and fmu_path() == fmu_path(2)
    assert fmu_path(3) == BUILD / "udmap-fmi3.fmu"
    assert fmu_path("3") == fmu_path(3)
    for bad in (4, 2.5, True, "x", None, [2]):
        with pytest.raises(InputError, match=re.escape(f"fmi_version must be 2 or 3, got {bad!r}")):
            fmu_path(bad)


def test_version_is_read_from_cmakelists():
    meta = SKBUILD["metadata"]["version"]
    assert PYPROJECT["project"]["dynamic"] == ["version"] and meta["input"] == "CMakeLists.txt"
    m = re.search(meta["regex"], (ROOT / meta["input"]).read_text())
    assert m and m.group("value") == udmap.version()


def test_every_third_party_import_is_a_dependency():
    required = set(PYPROJECT["project"]["dependencies"])
    optional = {d for deps in PYPROJECT["project"]["optional-dependencies"].values()
                for d in deps}
    # imported only where they are optional: parquet output, the Dask executor
    optional |= {"pyarrow"}
    imports = set()
    for src in (ROOT / "wrappers" / "python" / "udmap").glob("*.py"):
        for node in ast.walk(ast.parse(src.read_text())):
            if isinstance(node, ast.Import):
                imports |= {a.name.split(".")[0] for a in node.names}
            elif isinstance(node, ast.ImportFrom) and node.level == 0:
                imports.add(node.module.split(".")[0])
    third_party = {name for name in imports
                   if name not in sys.stdlib_module_names and name not in ("udmap", "__future__")}
    assert third_party - required - optional == set()
    assert {"numpy", "scipy", "matplotlib"} <= required
