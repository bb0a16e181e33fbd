"""Loads the kernel library and declares the C API (wrappers/c/udmap.h) for ctypes.

The library is found through ``UDMAP_LIBRARY``, then inside this package (``pip install .``
puts it there), then ``UDMAP_BUILD_DIR/kernel``, then the build tree of this checkout, then
``UDMAP_PREFIX/lib``, then the system loader path. :func:`fmu_path` finds the generic FMUs the
same way.
"""
from __future__ import annotations

import ctypes
import os
from pathlib import Path

c_double_p = ctypes.POINTER(ctypes.c_double)
c_int_p = ctypes.POINTER(ctypes.c_int)


class UdmapError(Exception):
    """An error reported by the kernel; ``status`` is 2 (input), 3 (physics) or 4 (numerics)."""

    def __init__(self, message: str, status: int = 2):
        super().__init__(message)
        self.status = status


class InputError(UdmapError):
    """Bad input: a parameter, file or argument is invalid (exit status 2)."""

    def __init__(self, message: str):
        super().__init__(message, 2)


class PhysicsError(UdmapError):
    """A physics failure: jammed damper, no resonance in the band (exit status 3)."""

    def __init__(self, message: str):
        super().__init__(message, 3)


_HERE = Path(__file__).resolve().parent


def _build_dirs():
    """The build trees to look in: ``UDMAP_BUILD_DIR``, then the checkout's ``build/`` (when
    this package is wrappers/python/udmap of a checkout)."""
    build = os.environ.get("UDMAP_BUILD_DIR")
    if build:
        yield Path(build)
    if len(_HERE.parents) > 2:
        yield _HERE.parents[2] / "build"


def _candidates():
    env = os.environ.get("UDMAP_LIBRARY")
    if env:
        yield Path(env)
    yield _HERE / "libudmap.so"
    for build in _build_dirs():
        yield build / "kernel" / "libudmap.so"
    prefix = os.environ.get("UDMAP_PREFIX")
    if prefix:
        for sub in ("lib", "lib64", "lib/x86_64-linux-gnu"):
            yield Path(prefix) / sub / "libudmap.so"


def _load() -> ctypes.CDLL:
    tried = []
    for path in _candidates():
        tried.append(str(path))
        if path.is_file():
            return ctypes.CDLL(str(path))
    try:
        return ctypes.CDLL("libudmap.so")
    except OSError:
        tried.append("libudmap.so (system loader path)")
    raise ImportError("udmap: kernel library not found; build it with 'make build' or set "
                      "UDMAP_LIBRARY. Tried: " + ", ".join(tried))


lib = _load()

FMU_NAMES = {2: "udmap.fmu", 3: "udmap-fmi3.fmu"}


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
    tried = [_HERE / "fmu" / name] + [build / name for build in _build_dirs()]
    prefix = os.environ.get("UDMAP_PREFIX")
    if prefix:
        tried.append(Path(prefix) / "share" / "udmap" / name)
    for path in tried:
        if path.is_file():
            return path
    raise InputError(f"the FMI {version} FMU {name} was not found; build it with 'make "
                     "build' (or pip install .) or set UDMAP_BUILD_DIR. Tried: "
                     + ", ".join(str(p) for p in tried))


lib.udmap_get_version.restype = ctypes.c_int
lib.udmap_get_version.argtypes = []
lib.udmap_new_error.restype = ctypes.c_void_p
lib.udmap_new_error.argtypes = []
lib.udmap_delete_error.restype = None
lib.udmap_delete_error.argtypes = [ctypes.POINTER(ctypes.c_void_p)]
lib.udmap_check_error.restype = ctypes.c_int
lib.udmap_check_error.argtypes = [ctypes.c_void_p]
lib.udmap_get_error.restype = None
lib.udmap_get_error.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]


def declare(name: str, argtypes, restype=ctypes.c_int):
    """Declares a C API function's signature and returns it."""
    fn = getattr(lib, name)
    fn.argtypes = argtypes
    fn.restype = restype
    return fn


class ErrorHandle:
    """Owns one udmap_error; ``check(status)`` raises the kernel's message on failure."""

    def __init__(self):
        self.ptr = ctypes.c_void_p(lib.udmap_new_error())

    def __del__(self):
        if getattr(self, "ptr", None) is not None and lib is not None:
            lib.udmap_delete_error(ctypes.byref(self.ptr))

    def check(self, status: int) -> None:
        if status == 0:
            return
        buf = ctypes.create_string_buffer(4096)
        lib.udmap_get_error(self.ptr, buf, len(buf))
        message = buf.value.decode("utf-8", "replace") or f"udmap error {status}"
        if status == 2:
            raise InputError(message)
        if status == 3:
            raise PhysicsError(message)
        raise UdmapError(message, status)


def version() -> str:
    """The kernel version string 'major.minor.patch'."""
    v = lib.udmap_get_version()
    return f"{v // 10000}.{(v // 100) % 100}.{v % 100}"


def as_doubles(values) -> "tuple[ctypes.Array, int]":
    """A contiguous float64 numpy array and a ctypes pointer to it (keep the array alive)."""
    import numpy as np
    arr = np.ascontiguousarray(values, dtype=np.float64)
    return arr, arr.ctypes.data_as(c_double_p)
