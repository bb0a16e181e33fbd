"""Where the kernel library and the generic FMUs are found.

The library (``libudmap.so``, or ``udmap.dll`` from the Windows wheel) is found through
``UDMAP_LIBRARY``, then inside this package (``pip install .`` and the wheels put it there),
then ``UDMAP_BUILD_DIR/kernel``, then the build tree of this checkout, then ``UDMAP_PREFIX/lib``,
then the system loader path. :func:`fmu_path` finds the generic FMUs the
same way.
"""
from __future__ import annotations

import os
from pathlib import Path

from .errors import InputError

__all__ = ["PACKAGE_DIR", "LIBRARY_NAME", "FMU_NAMES", "build_dirs", "library_candidates",
           "fmu_path"]

#: The directory of this package (wrappers/python/udmap in a checkout).
PACKAGE_DIR = Path(__file__).resolve().parent

#: The kernel library's file name: the Windows wheel carries the MinGW-built udmap.dll.
LIBRARY_NAME = "udmap.dll" if os.name == "nt" else "libudmap.so"

FMU_NAMES = {2: "udmap.fmu", 3: "udmap-fmi3.fmu"}


def build_dirs():
    """The build trees to look in: ``UDMAP_BUILD_DIR``, then the checkout's ``build/`` (when
    this package is wrappers/python/udmap of a checkout)."""
    build = os.environ.get("UDMAP_BUILD_DIR")
    if build:
        yield Path(build)
    if len(PACKAGE_DIR.parents) > 2:
        yield PACKAGE_DIR.parents[2] / "build"


def library_candidates():
    """The paths of the kernel library to try, in order (the system loader path comes after
    them)."""
    env = os.environ.get("UDMAP_LIBRARY")
    if env:
        yield Path(env)
    yield PACKAGE_DIR / LIBRARY_NAME
    for build in build_dirs():
        yield build / "kernel" / LIBRARY_NAME
    prefix = os.environ.get("UDMAP_PREFIX")
    if prefix:
        for sub in ("bin", "lib") if os.name == "nt" else ("lib", "lib64", "lib/x86_64-linux-gnu"):
            yield Path(prefix) / sub / LIBRARY_NAME


def fmu_path(fmi_version: int = 2) -> Path:
    """The generic FMU of the kernel for FMI ``fmi_version`` (2 or 3): inside this package
    (``udmap/fmu/``, installed by ``pip install .``), else in ``UDMAP_BUILD_DIR`` or the
    checkout's ``build/``, else ``UDMAP_PREFIX/share/udmap`` (``cmake --install``)."""
    version = fmi_version
    if isinstance(version, str):
        version = {"2": 2, "3": 3}.get(version.strip())
    if not isinstance(version, int) or isinstance(version, bool) or version not in FMU_NAMES:
        raise InputError(f"fmi_version must be 2 or 3, got {fmi_version!r}")
    name = FMU_NAMES[version]
    tried = [PACKAGE_DIR / "fmu" / name] + [build / name for build in build_dirs()]
    prefix = os.environ.get("UDMAP_PREFIX")
    if prefix:
        tried.append(Path(prefix) / "share" / "udmap" / name)
    for path in tried:
        if path.is_file():
            return path
    raise InputError(f"the FMI {version} FMU {name} was not found; build it with 'make "
                     "build' (or pip install .) or set UDMAP_BUILD_DIR. Tried: "
                     + ", ".join(str(p) for p in tried))
