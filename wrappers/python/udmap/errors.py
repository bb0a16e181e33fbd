"""The exceptions of udmap and the map from a kernel status to them (the only one).

A kernel call returns a status: 0 success, 2 bad input, 3 physics failure, 4 numerical failure
(wrappers/c/udmap.h). :func:`error_from_status` turns a failure into :class:`InputError`,
:class:`PhysicsError` or :class:`UdmapError`; the command line maps them back to its exit status.
Pure Python: the Dask scheduler and the FE readers use it without the kernel's declarations.
"""
from __future__ import annotations

__all__ = ["UdmapError", "InputError", "PhysicsError", "error_from_status"]


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


def error_from_status(status: int, message: str) -> UdmapError:
    """The exception of a failed kernel status (2 input, 3 physics, otherwise numerics)."""
    if status == 2:
        return InputError(message)
    if status == 3:
        return PhysicsError(message)
    return UdmapError(message, status)
