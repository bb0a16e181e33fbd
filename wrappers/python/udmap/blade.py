"""The linear blade (PHYSICS.md 1 and 3) over the C API: the built-in beam or imported matrices,
natural frequencies, receptances H_gE, H_gg, H_EE, H_sE, H_sg and the Sherman-Morrison layer
response for a damper stiffness k on the platform rotation gamma_P. Frequencies in Hz.
"""
from __future__ import annotations

import ctypes
import os

import numpy as np

from ._lib import ErrorHandle, InputError, as_doubles, c_double_p, c_int_p, declare
from .parameters import BeamParams

__all__ = ["Blade", "BEAM_PARAMETERS"]


_BeamParams = BeamParams  # udmap_beam_params: 12 doubles then 2 ints

#: Keyword arguments of Blade.beam, as in the C struct (case-file fields with underscores).
BEAM_PARAMETERS = tuple(name for name, _ in _BeamParams._fields_)

_handle_p = ctypes.POINTER(ctypes.c_void_p)
_new_beam = declare("udmap_new_blade_beam",
                    [ctypes.c_void_p, ctypes.POINTER(_BeamParams), _handle_p])
_new_matrices = declare("udmap_new_blade_matrices",
                        [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p,
                         ctypes.c_int, ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p,
                         ctypes.c_double, _handle_p])
_delete = declare("udmap_delete_blade", [_handle_p], None)
_get_size = declare("udmap_blade_get_size", [ctypes.c_void_p, ctypes.c_void_p, c_int_p, c_int_p])
_natural_frequencies = declare("udmap_blade_natural_frequencies",
                               [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int, c_double_p])
_receptances = declare("udmap_blade_receptances",
                       [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int, c_double_p, c_double_p])
_layer_response = declare("udmap_blade_layer_response",
                          [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int, c_double_p,
                           ctypes.c_double, ctypes.c_double, c_double_p])
_export = declare("udmap_blade_export", [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char_p])

_RECEPTANCES = ("gE", "gg", "EE", "sE", "sg")


def _path(p) -> "bytes | None":
    return None if p is None else os.fsencode(os.fspath(p))


class Blade:
    """A linear blade held by the kernel (a udmap_blade handle, freed with the object).

    Build it with :meth:`beam` or :meth:`matrices`. Errors raise ``InputError`` (status 2)
    with the kernel's message naming the field or file.
    """

    def __init__(self, handle: ctypes.c_void_p, error: ErrorHandle):
        self._handle = handle
        self._error = error

    @classmethod
    def beam(cls, **params) -> "Blade":
        """The built-in beam blade (PHYSICS.md 1.1); keywords as in BEAM_PARAMETERS."""
        unknown = sorted(set(params) - set(BEAM_PARAMETERS))
        missing = [name for name in BEAM_PARAMETERS if name not in params]
        if unknown or missing:
            parts = []
            if unknown:
                parts.append("unknown beam parameter(s) " + ", ".join(unknown))
            if missing:
                parts.append("missing beam parameter(s) " + ", ".join(missing))
            raise InputError("; ".join(parts))
        values = {}
        for name, ctype in _BeamParams._fields_:
            value = params[name]
            if ctype is ctypes.c_int:
                if isinstance(value, bool) or int(value) != value:
                    raise InputError(f"{name} must be an integer, got {value!r}")
                values[name] = int(value)
            else:
                values[name] = float(value)
        error = ErrorHandle()
        handle = ctypes.c_void_p()
        error.check(_new_beam(error.ptr, ctypes.byref(_BeamParams(**values)), ctypes.byref(handle)))
        return cls(handle, error)

    @classmethod
    def matrices(cls, M, K, gamma_dof: int, exc_dof: int, zeta: float = 0.0, C=None,
                 stress_K=None, stress_M=None) -> "Blade":
        """An imported blade (PHYSICS.md 1.2) from Matrix Market files (paths as given;
        gamma_dof, exc_dof 1-based). Without C, damping is beta K from zeta."""
        error = ErrorHandle()
        handle = ctypes.c_void_p()
        error.check(_new_matrices(error.ptr, _path(M), _path(K), _path(C), int(gamma_dof),
                                  int(exc_dof), _path(stress_K), _path(stress_M), float(zeta),
                                  ctypes.byref(handle)))
        return cls(handle, error)

    def __del__(self):
        handle = getattr(self, "_handle", None)
        if handle is not None and handle.value and _delete is not None:
            _delete(ctypes.byref(handle))

    def _size(self) -> "tuple[int, int]":
        ndof, has_stress = ctypes.c_int(), ctypes.c_int()
        self._error.check(_get_size(self._error.ptr, self._handle, ctypes.byref(ndof),
                                    ctypes.byref(has_stress)))
        return ndof.value, has_stress.value

    @property
    def ndof(self) -> int:
        """Number of DOFs."""
        return self._size()[0]

    @property
    def has_stress(self) -> bool:
        """Whether the blade has stress rows (else stress receptances are 0)."""
        return bool(self._size()[1])

    def natural_frequencies(self, n: int) -> np.ndarray:
        """The lowest n bare natural frequencies [Hz], ascending."""
        out = np.zeros(max(int(n), 1))
        self._error.check(_natural_frequencies(self._error.ptr, self._handle, int(n),
                                               out.ctypes.data_as(c_double_p)))
        return out

    def receptances(self, f_hz) -> "dict[str, np.ndarray]":
        """Bare receptances at the frequencies f_hz [Hz]: complex arrays 'gE', 'gg', 'EE',
        'sE', 'sg' of the shape of f_hz."""
        f = np.asarray(f_hz, dtype=np.float64)
        flat, fptr = as_doubles(f.reshape(-1))
        out = np.zeros(10 * flat.size)
        self._error.check(_receptances(self._error.ptr, self._handle, flat.size, fptr,
                                       out.ctypes.data_as(c_double_p)))
        pairs = out.reshape(-1, 5, 2)
        return {name: (pairs[:, j, 0] + 1j * pairs[:, j, 1]).reshape(f.shape)
                for j, name in enumerate(_RECEPTANCES)}

    def layer_response(self, f_hz, k: complex) -> "tuple[np.ndarray, np.ndarray, np.ndarray]":
        """Response to a unit force at E with damper stiffness k on gamma_P (Sherman-Morrison):
        complex arrays (g~, s~, u~_E) of the shape of f_hz."""
        f = np.asarray(f_hz, dtype=np.float64)
        flat, fptr = as_doubles(f.reshape(-1))
        k = complex(k)
        out = np.zeros(6 * flat.size)
        self._error.check(_layer_response(self._error.ptr, self._handle, flat.size, fptr,
                                          k.real, k.imag, out.ctypes.data_as(c_double_p)))
        pairs = out.reshape(-1, 3, 2)
        g, s, u = ((pairs[:, j, 0] + 1j * pairs[:, j, 1]).reshape(f.shape) for j in range(3))
        return g, s, u

    def export(self, directory) -> None:
        """Writes M.mtx, K.mtx (C.mtx, stress_K.mtx, stress_M.mtx when present) and
        blade.json into the existing directory."""
        self._error.check(_export(self._error.ptr, self._handle, _path(directory)))

    def __repr__(self) -> str:
        ndof, has_stress = self._size()
        return f"Blade(ndof={ndof}, has_stress={bool(has_stress)})"
