#!/usr/bin/env python3
"""Runs the examples against an installed udmap, the way a user would, and checks their output.

ctest calls it (examples/CMakeLists.txt): one `install` step (the fixture) installs the current
build into a fresh prefix with ``cmake --install`` and the Python package into the same prefix
with pip; every other step builds one example against that prefix only (find_package, pkg-config,
the pip-installed package), runs it, and compares the numbers it prints with the CLI of the source
tree (``python3 -m udmap backbone cases/blade_a.json --forces ... --json``) to the printed
precision: one unit in the last printed digit.

By hand, from the repository root after ``make build``:
    python3 examples/harness.py --build build --prefix /tmp/udmap-prefix install
    python3 examples/harness.py --build build --prefix /tmp/udmap-prefix fortran-build
    python3 examples/harness.py --build build --prefix /tmp/udmap-prefix fortran-backbone
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[1]
EXAMPLES = SOURCE / "examples"
#: The forces every backbone example prints (blade A), as the CLI's --forces argument.
FORCES = "1,2,5"
NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?"


class Failure(Exception):
    """A check failed; the message says what and where."""


def run(cmd, env=None, cwd=None, capture=True) -> str:
    """Runs cmd, echoing it; fails with its output if the exit status is not zero."""
    print("+", " ".join(str(c) for c in cmd), flush=True)
    proc = subprocess.run([str(c) for c in cmd], env=env, cwd=cwd, text=True,
                          stdout=subprocess.PIPE if capture else None,
                          stderr=subprocess.STDOUT if capture else None)
    if capture and proc.stdout:
        print(proc.stdout, end="" if proc.stdout.endswith("\n") else "\n", flush=True)
    if proc.returncode != 0:
        raise Failure(f"exit status {proc.returncode}: {' '.join(str(c) for c in cmd)}")
    return proc.stdout or ""


class Harness:
    def __init__(self, build: Path, prefix: Path, work: Path, version: str, cmake: str):
        self.build = build.resolve()
        self.prefix = prefix.resolve()
        self.work = work.resolve()
        self.version = version
        self.cmake = cmake
        self.libdir = self._libdir()
        # Where pip --prefix puts modules and scripts: the interpreter's default scheme (Debian's
        # python3 uses prefix/local/..., other builds prefix/...).
        scheme_vars = {"base": str(self.prefix), "platbase": str(self.prefix)}
        self.site = Path(sysconfig.get_path("purelib", vars=scheme_vars))
        self.scripts = Path(sysconfig.get_path("scripts", vars=scheme_vars))

    def _libdir(self) -> Path:
        for sub in ("lib", "lib64", "lib/x86_64-linux-gnu"):
            if (self.prefix / sub / "pkgconfig" / "udmap.pc").is_file():
                return self.prefix / sub
        return self.prefix / "lib"

    def env(self) -> dict:
        """The environment of a user who installed into the prefix: nothing of the build tree."""
        env = {k: v for k, v in os.environ.items()
               if k not in ("UDMAP_LIBRARY", "UDMAP_BUILD_DIR", "UDMAP_PREFIX", "PYTHONPATH")}
        env["PKG_CONFIG_PATH"] = str(self.libdir / "pkgconfig")
        env["LD_LIBRARY_PATH"] = str(self.libdir) + (
            ":" + env["LD_LIBRARY_PATH"] if env.get("LD_LIBRARY_PATH") else "")
        env["PYTHONPATH"] = str(self.site)
        env["UDMAP_PREFIX"] = str(self.prefix)
        env["PATH"] = str(self.scripts) + ":" + env.get("PATH", "")
        return env

    # ------------------------------------------------------------------ reference and checks

    def cli(self, *args) -> dict:
        """The CLI of the source tree on blade A, --json (the numbers examples must print)."""
        env = dict(os.environ)
        env["PYTHONPATH"] = str(SOURCE / "wrappers" / "python")
        env["UDMAP_LIBRARY"] = str(self.build / "kernel" / "libudmap.so")
        env.pop("UDMAP_BUILD_DIR", None)
        out = run([sys.executable, "-m", "udmap", args[0], SOURCE / "cases" / "blade_a.json",
                   *args[1:], "--json"], env=env, cwd=SOURCE)
        return json.loads(out)

    def reference(self, forces: str = FORCES) -> dict:
        return self.cli("backbone", "--forces", forces)

    def check_linked_from_prefix(self, exe: Path) -> None:
        """The example must load libudmap from the prefix, never from the build tree."""
        out = run(["ldd", exe], env=self.env())
        line = next((l for l in out.splitlines() if "libudmap.so" in l), None)
        if line is None:
            raise Failure(f"{exe} does not link libudmap.so")
        if str(self.prefix) not in line:
            raise Failure(f"{exe} loads libudmap from outside the prefix: {line.strip()}")

    @staticmethod
    def last_digit(token: str) -> float:
        """One unit in the last printed digit of a number token, e.g. 1.2345E+01 -> 1e-4."""
        m = re.fullmatch(r"[-+]?(\d*)(?:\.(\d*))?(?:[eEdD]([-+]?\d+))?", token)
        if not m:
            raise Failure(f"not a number: {token!r}")
        decimals = len(m.group(2) or "")
        exponent = int(m.group(3) or 0)
        return 10.0 ** (exponent - decimals)

    @staticmethod
    def rows(output: str, prefix: str | None, count: int) -> list[list[str]]:
        """Lines of `count` number tokens, after the word `prefix` (None: no word)."""
        rows = []
        for line in output.splitlines():
            tokens = line.split()
            if prefix is not None:
                if not tokens or tokens[0] != prefix:
                    continue
                tokens = tokens[1:]
            if len(tokens) == count and all(re.fullmatch(NUMBER, t) for t in tokens):
                rows.append(tokens)
        return rows

    def compare_backbone(self, output: str, name: str, forces: str = FORCES) -> None:
        """Compares what the example printed with the CLI: the F_lim line and the rows
        'F_E gamma_P f_res sigma_a' (always), and when printed the lines
        'table gamma k_re k_im', 'response f_exc F_E gamma_P sigma_a' and
        'curve F_E points max_gamma_P'."""
        ref = self.reference(forces)
        expected = [(p["F_E"], p["gamma_P"], p["f_res"], p["sigma_a"]) for p in ref["points"]]
        m = re.search(r"^\s*F_lim\s*=?\s*(" + NUMBER + ")", output, re.M)
        if not m:
            raise Failure(f"{name}: no 'F_lim = ...' line in the output")
        checks = [("F_lim", m.group(1), ref["F_lim"])]
        rows = self.rows(output, None, 4)
        if len(rows) != len(expected):
            raise Failure(f"{name}: expected {len(expected)} rows 'F_E gamma_P f_res sigma_a', "
                          f"found {len(rows)}")
        for row, exp in zip(rows, expected):
            for label, token, value in zip(("F_E", "gamma_P", "f_res", "sigma_a"), row, exp):
                checks.append((f"{label}@{exp[0]:g}", token, value))

        table = self.rows(output, "table", 3)
        if table:
            ref = self.cli("table", "--gammas", ",".join(r[0] for r in table))
            for row, p in zip(table, ref["points"]):
                for label, token, key in zip(("gamma", "k_re", "k_im"), row,
                                             ("gamma", "k_re", "k_im")):
                    checks.append((f"table {label}@{row[0]}", token, p[key]))
        response = self.rows(output, "response", 4)
        if response:
            ref = self.cli("response", "--forces", ",".join(r[1] for r in response),
                           "--freq", response[0][0])
            for row, p in zip(response, ref["points"]):
                for label, token, key in zip(("F_E", "gamma_P", "sigma_a"), row[1:],
                                             ("F_E", "gamma_P", "sigma_a")):
                    checks.append((f"response {label}@{row[1]}", token, p[key]))
        curve = self.rows(output, "curve", 3)
        for row in curve:
            c = self.cli("curves", "--forces", row[0])["curves"][0]
            if int(row[1]) != len(c["f"]):
                raise Failure(f"{name}: curve at F_E = {row[0]} has {row[1]} points, the CLI's "
                              f"{len(c['f'])}")
            checks.append((f"curve max gamma_P@{row[0]}", row[2], max(c["gamma_P"])))

        bad = []
        for label, token, value in checks:
            printed = float(token.replace("D", "E").replace("d", "e"))
            tol = self.last_digit(token)
            if value is None or not abs(printed - value) <= tol * (1 + 1e-9):
                bad.append(f"{label}: printed {token}, CLI {value!r} (tolerance {tol:.1e})")
            else:
                print(f"ok {label}: {token} vs CLI {value!r}")
        if bad:
            raise Failure(f"{name}: differs from the CLI:\n  " + "\n  ".join(bad))
        print(f"{name}: {len(checks)} numbers equal the CLI's to the printed precision "
              f"(backbone{', table' if table else ''}{', response' if response else ''}"
              f"{', curve' if curve else ''})")

    # ------------------------------------------------------------------ steps

    def install(self) -> None:
        """cmake --install into a fresh prefix, then pip install the Python package into it."""
        if self.prefix.exists():
            shutil.rmtree(self.prefix)
        run([self.cmake, "--install", self.build, "--prefix", self.prefix])
        self.libdir = self._libdir()
        pc = self.libdir / "pkgconfig" / "udmap.pc"
        wanted = [self.libdir / "libudmap.so", self.libdir / "libudmap.a",
                  self.prefix / "include" / "udmap.h",
                  self.libdir / "cmake" / "udmap" / "udmapConfig.cmake",
                  self.libdir / "cmake" / "udmap" / "udmapConfigVersion.cmake", pc]
        missing = [str(p) for p in wanted if not p.exists()]
        mods = list((self.prefix / "include" / "udmap").glob("*/udmap.mod"))
        if not mods:
            missing.append(str(self.prefix / "include" / "udmap" / "<compiler>-<version>" /
                               "udmap.mod"))
        if missing:
            raise Failure("not installed: " + ", ".join(missing))
        print("installed:", ", ".join(str(p.relative_to(self.prefix)) for p in wanted + mods))

        # pip builds in the source directory: build a copy so the checkout stays clean.
        with tempfile.TemporaryDirectory(prefix="udmap-pip-") as tmp:
            src = Path(tmp) / "python"
            shutil.copytree(SOURCE / "wrappers" / "python", src,
                            ignore=shutil.ignore_patterns("__pycache__", "*.egg-info", "build"))
            run([sys.executable, "-m", "pip", "install", "--no-deps", "--no-build-isolation",
                 "--no-index", "--disable-pip-version-check", "--prefix", self.prefix, src])
        if not (self.site / "udmap" / "data" / "blade_a.json").is_file():
            raise Failure(f"pip did not install udmap with its data into {self.site}")
        text = (SOURCE / "wrappers" / "python" / "pyproject.toml").read_text()
        m = re.search(r'^version\s*=\s*"([^"]+)"', text, re.M)
        if not m or m.group(1) != self.version:
            raise Failure(f"wrappers/python/pyproject.toml version "
                          f"{m.group(1) if m else '?'} differs from the project's {self.version}")

    def fortran_pkgconfig(self) -> None:
        """The acceptance program `use udmap, only: udmap_version`, built with pkg-config."""
        self.work.mkdir(parents=True, exist_ok=True)
        env = self.env()
        flags = run(["pkg-config", "--cflags", "--libs", "udmap"], env=env).split()
        exe = self.work / "version_pkgconfig"
        run(["gfortran", EXAMPLES / "fortran" / "version.f90", *flags, "-o", exe],
            env=env, cwd=self.work)
        self.check_linked_from_prefix(exe)
        self.expect_version(run([exe], env=env), "version_pkgconfig")

    def expect_version(self, output: str, name: str) -> None:
        if output.strip() != self.version:
            raise Failure(f"{name} printed {output.strip()!r}, expected {self.version!r}")
        print(f"{name}: version {self.version} as expected")

    def fortran_build(self) -> None:
        """Configures and builds examples/fortran with find_package(udmap) from the prefix."""
        bdir = self.work / "fortran"
        if bdir.exists():
            shutil.rmtree(bdir)
        env = self.env()
        run([self.cmake, "-S", EXAMPLES / "fortran", "-B", bdir, f"-Dudmap_ROOT={self.prefix}",
             f"-DCMAKE_PREFIX_PATH={self.prefix}", "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON",
             "-DCMAKE_BUILD_TYPE=Release"], env=env)
        run([self.cmake, "--build", bdir, "-j2"], env=env)

    def fortran_run(self, exe_name: str) -> str:
        exe = self.work / "fortran" / exe_name
        if exe_name != "version_static":
            self.check_linked_from_prefix(exe)
        # No LD_LIBRARY_PATH: CMake's build RPATH must be enough for find_package users.
        env = self.env()
        env.pop("LD_LIBRARY_PATH", None)
        return run([exe], env=env, cwd=self.work)

    def c_example(self) -> None:
        """Builds examples/c with its Makefile (pkg-config) and compares with the CLI."""
        cdir = self.work / "c"
        if cdir.exists():
            shutil.rmtree(cdir)
        shutil.copytree(EXAMPLES / "c", cdir)
        env = self.env()
        run(["make", "-C", cdir], env=env)
        self.check_linked_from_prefix(cdir / "backbone")
        self.compare_backbone(run([cdir / "backbone"], env=env, cwd=cdir), "c/backbone")

    def python_example(self) -> None:
        """examples/python/backbone.py with the pip-installed package and library."""
        env = self.env()
        env.pop("LD_LIBRARY_PATH", None)
        out = run([sys.executable, EXAMPLES / "python" / "backbone.py"], env=env, cwd=self.work)
        self.compare_backbone(out, "python/backbone")

    def pip_cli(self) -> None:
        """The pip-installed console script `udmap` gives the source tree's JSON."""
        env = self.env()
        env.pop("LD_LIBRARY_PATH", None)
        script = self.scripts / "udmap"
        self.expect_version(run([script, "--version"], env=env, cwd=self.work), "udmap --version")
        out = run([script, "backbone", SOURCE / "cases" / "blade_a.json", "--forces", FORCES,
                   "--json"], env=env, cwd=self.work)
        if json.loads(out) != self.reference():
            raise Failure("the pip-installed CLI's JSON differs from the source tree's")
        print("pip-installed udmap backbone --json equals the source tree's")

    def fmpy_example(self, fmu: Path) -> None:
        """examples/fmpy/sweep.py on the FMU of the build: its peaks equal the CLI's."""
        env = self.env()
        env.pop("LD_LIBRARY_PATH", None)
        env["MPLBACKEND"] = "Agg"
        self.work.mkdir(parents=True, exist_ok=True)
        png = self.work / "fmpy_sweep.png"
        out = run([sys.executable, EXAMPLES / "fmpy" / "sweep.py", fmu, "--plot", png],
                  env=env, cwd=self.work)
        if not png.is_file() or png.stat().st_size == 0:
            raise Failure(f"fmpy/sweep.py wrote no plot {png}")
        self.compare_backbone(out, "fmpy/sweep")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build", type=Path, default=SOURCE / "build", help="the build directory")
    p.add_argument("--prefix", type=Path, required=True, help="the install prefix (recreated)")
    p.add_argument("--work", type=Path, default=None, help="where examples are built")
    p.add_argument("--version", default=None, help="the expected version (default: CMakeLists)")
    p.add_argument("--cmake", default="cmake", help="the cmake executable")
    p.add_argument("--fmu", type=Path, default=None, help="the FMU for the fmpy step")
    p.add_argument("step", choices=("install", "fortran-pkgconfig", "fortran-build",
                                    "fortran-version-cmake", "fortran-version-static",
                                    "fortran-backbone", "fortran-legacy", "c", "python",
                                    "pip-cli", "fmpy"))
    args = p.parse_args(argv)
    version = args.version
    if version is None:
        m = re.search(r"VERSION\s+(\d+\.\d+\.\d+)", (SOURCE / "CMakeLists.txt").read_text())
        version = m.group(1)
    work = args.work or args.prefix.parent / (args.prefix.name + "-work")
    h = Harness(args.build, args.prefix, work, version, args.cmake)
    try:
        if args.step == "install":
            h.install()
        elif args.step == "fortran-pkgconfig":
            h.fortran_pkgconfig()
        elif args.step == "fortran-build":
            h.fortran_build()
        elif args.step == "fortran-version-cmake":
            h.expect_version(h.fortran_run("version"), "fortran/version (find_package)")
        elif args.step == "fortran-version-static":
            h.expect_version(h.fortran_run("version_static"), "fortran/version_static")
        elif args.step == "fortran-backbone":
            h.compare_backbone(h.fortran_run("backbone"), "fortran/backbone")
        elif args.step == "fortran-legacy":
            h.compare_backbone(h.fortran_run("backbone_legacy"), "fortran/backbone_legacy")
        elif args.step == "c":
            h.c_example()
        elif args.step == "python":
            h.python_example()
        elif args.step == "pip-cli":
            h.pip_cli()
        elif args.step == "fmpy":
            if args.fmu is None:
                p.error("the fmpy step needs --fmu")
            h.fmpy_example(args.fmu)
    except Failure as exc:
        print(f"FAILED: {exc}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
