"""The linear blade (PHYSICS.md 1 and 3) over the C API: the built-in beam or imported matrices,
natural frequencies, receptances H_gE, H_gg, H_EE, H_sE, H_sg and the Sherman-Morrison layer
response for a damper stiffness k on the platform rotation gamma_P. Frequencies in Hz.
"""
from __future__ import annotations

import ctypes
import os

import numpy as np

from . import _capi
from ._capi import ErrorHandle, as_doubles
from .errors import InputError

__all__ = ["Blade", "BEAM_PARAMETERS"]


#: Keyword arguments of Blade.beam, as in the C struct (case-file fields with underscores).
BEAM_PARAMETERS = tuple(name for name, _ in _capi.BeamParams._fields_)

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
        for name, ctype in _capi.BeamParams._fields_:
            value = params[name]
            if ctype is ctypes.c_int:
                if isinstance(value, bool) or int(value) != value:
                    raise InputError(f"{name} must be an integer, got {value!r}")
                values[name] = int(value)
            else:
                values[name] = float(value)
        error = ErrorHandle()
        handle = ctypes.c_void_p()
        error.check(_capi.new_blade_beam(error.ptr, ctypes.byref(_capi.BeamParams(**values)),
                                         ctypes.byref(handle)))
        return cls(handle, error)

    @classmethod
    def matrices(cls, M, K, gamma_dof: int, exc_dof: int, zeta: float = 0.0, C=None,
                 stress_K=None, stress_M=None, u_dof: "int | None" = None,
                 v_dof: "int | None" = None) -> "Blade":
        """An imported blade (PHYSICS.md 1.2) from Matrix Market files (paths as given;
        gamma_dof, exc_dof 1-based). Without C, damping is beta K from zeta. ``u_dof``,
        ``v_dof`` (1-based, optional): the DOFs of the platform's circumferential and radial
        translations, which a traveling wave needs (PHYSICS.md 2.6; see
        :meth:`set_platform_rows`)."""
        error = ErrorHandle()
        handle = ctypes.c_void_p()
        error.check(_capi.new_blade_matrices(error.ptr, _path(M), _path(K), _path(C),
                                             int(gamma_dof),
                                  int(exc_dof), _path(stress_K), _path(stress_M), float(zeta),
                                             ctypes.byref(handle)))
        blade = cls(handle, error)
        if u_dof is not None:
            blade.set_platform_dofs(u_dof, v_dof, gamma_dof=gamma_dof)
        elif v_dof is not None:
            raise InputError("v_dof needs u_dof (the circumferential translation)")
        return blade

    def __del__(self):
        handle = getattr(self, "_handle", None)
        if handle is not None and handle.value and _capi is not None and _capi.lib is not None:
            _capi.delete_blade(ctypes.byref(handle))

    @property
    def handle(self) -> ctypes.c_void_p:
        """The udmap_blade handle (for the model and the standard method)."""
        return self._handle

    def _size(self) -> "tuple[int, int]":
        ndof, has_stress = ctypes.c_int(), ctypes.c_int()
        self._error.check(_capi.blade_get_size(self._error.ptr, self._handle, ctypes.byref(ndof),
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
        self._error.check(_capi.blade_natural_frequencies(self._error.ptr, self._handle, int(n),
                                                          out.ctypes.data_as(_capi.c_double_p)))
        return out

    def receptances(self, f_hz) -> "dict[str, np.ndarray]":
        """Bare receptances at the frequencies f_hz [Hz]: complex arrays 'gE', 'gg', 'EE',
        'sE', 'sg' of the shape of f_hz."""
        f = np.asarray(f_hz, dtype=np.float64)
        flat, fptr = as_doubles(f.reshape(-1))
        out = np.zeros(10 * flat.size)
        self._error.check(_capi.blade_receptances(self._error.ptr, self._handle, flat.size, fptr,
                                                  out.ctypes.data_as(_capi.c_double_p)))
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
        self._error.check(_capi.blade_layer_response(self._error.ptr, self._handle, flat.size,
                                                     fptr, k.real, k.imag,
                                                     _capi.doubles_ptr(out)))
        pairs = out.reshape(-1, 3, 2)
        g, s, u = ((pairs[:, j, 0] + 1j * pairs[:, j, 1]).reshape(f.shape) for j in range(3))
        return g, s, u

    def set_platform_rows(self, u_row, v_row=None) -> None:
        """Sets the platform translations of a traveling wave (PHYSICS.md 2.6) as rows over
        the DOFs: u_P = u_row . q (circumferential), v_P = v_row . q (radial; None: held)."""
        n = self.ndof
        u, uptr = as_doubles(np.asarray(u_row, dtype=np.float64).ravel())
        v, vptr = (None, None) if v_row is None else \
            as_doubles(np.asarray(v_row, dtype=np.float64).ravel())
        for name, row in (("u_row", u), ("v_row", v)):
            if row is not None and row.size != n:
                raise InputError(f"{name} must have {n} entries (one per DOF of the blade), "
                                 f"got {row.size}")
        self._error.check(_capi.blade_set_platform_rows(self._error.ptr, self._handle, n, uptr,
                                                        vptr))

    def set_platform_dofs(self, u_dof: int, v_dof: "int | None" = None,
                          gamma_dof: "int | None" = None, prefix: str = "") -> None:
        """The platform translations as single DOFs (1-based): u_P = q[u_dof], v_P = q[v_dof]
        (None: held). Each must be a DOF of the blade, the two must differ and differ from
        ``gamma_dof`` when given. Errors name ``u_dof`` or ``v_dof`` (after ``prefix``,
        e.g. ``blade.``)."""
        n = self.ndof
        dofs = {"u_dof": u_dof, "v_dof": v_dof}
        for name, dof in dofs.items():
            if dof is None:
                continue
            if isinstance(dof, bool) or int(dof) != dof or not 1 <= int(dof) <= n:
                raise InputError(f"{prefix}{name} must be a DOF number from 1 to {n}, got "
                                 f"{dof!r}")
            if gamma_dof is not None and int(dof) == int(gamma_dof):
                raise InputError(f"{prefix}{name} must differ from {prefix}gamma_dof "
                                 f"({int(gamma_dof)}): the platform rotation is not a "
                                 "translation")
        if v_dof is not None and int(v_dof) == int(u_dof):
            raise InputError(f"{prefix}v_dof must differ from {prefix}u_dof ({int(u_dof)})")
        u = np.zeros(n)
        u[int(u_dof) - 1] = 1.0
        v = None
        if v_dof is not None:
            v = np.zeros(n)
            v[int(v_dof) - 1] = 1.0
        self.set_platform_rows(u, v)

    def platform_rows(self) -> "tuple[np.ndarray, np.ndarray] | None":
        """The rows (u_row, v_row) of the platform translations, or None when the blade has
        none (a matrices blade without u_dof)."""
        n = self.ndof
        u, v, known = np.zeros(n), np.zeros(n), ctypes.c_int()
        self._error.check(_capi.blade_get_platform_rows(self._error.ptr, self._handle, n,
                                                        _capi.doubles_ptr(u),
                                                        _capi.doubles_ptr(v),
                                                        ctypes.byref(known)))
        return (u, v) if known.value else None

    def export(self, directory) -> None:
        """Writes M.mtx, K.mtx (C.mtx, stress_K.mtx, stress_M.mtx when present) and
        blade.json into the existing directory."""
        self._error.check(_capi.blade_export(self._error.ptr, self._handle, _path(directory)))

    def __repr__(self) -> str:
        ndof, has_stress = self._size()
        return f"Blade(ndof={ndof}, has_stress={bool(has_stress)})"
