"""The damper as a complex stiffness k(gamma) (PHYSICS.md section 2), over the C API.

>>> d = Damper.asymmetric(CF=900.0, mu=0.3, pitch=0.026, y_P=0.006, beta_L_deg=45.0,
...                       beta_R_deg=45.0, flat_points=[[-6.724e-3, -1.724e-3],
...                       [-1.068e-3, 3.932e-3]], curved_point=[3.268e-3, 1.768e-3],
...                       kn_flat=60e6, kt_flat=40e6, kn_curved=80e6, kt_curved=50e6)
>>> round(d.M_max, 5), d.lift_off
(6.44037, False)
"""
from __future__ import annotations

import ctypes

import numpy as np

from ._lib import ErrorHandle, InputError, as_doubles, c_double_p, declare, lib
from .parameters import AsymmetricParams

__all__ = ["Damper"]

_vp = ctypes.c_void_p


_AsymmetricParams = AsymmetricParams  # udmap_asymmetric_params


class _Info(ctypes.Structure):
    _fields_ = [("gamma_b", ctypes.c_double), ("gamma_s", ctypes.c_double),
                ("M_max", ctypes.c_double), ("M_min", ctypes.c_double),
                ("k_stuck", ctypes.c_double), ("lift_off", ctypes.c_int)]


_new_asym = declare("udmap_new_damper_asymmetric",
                    [_vp, ctypes.POINTER(_AsymmetricParams), ctypes.POINTER(_vp)])
_new_jenkins = declare("udmap_new_damper_jenkins",
                       [_vp, ctypes.c_double, ctypes.c_double, ctypes.POINTER(_vp)])
_new_table = declare("udmap_new_damper_table",
                     [_vp, ctypes.c_int, c_double_p, c_double_p, c_double_p, ctypes.c_int,
                      ctypes.c_double, ctypes.POINTER(_vp)])
_delete = declare("udmap_delete_damper", [ctypes.POINTER(_vp)], None)
_get_info = declare("udmap_damper_get_info", [_vp, _vp, ctypes.POINTER(_Info)])
_stiffness = declare("udmap_damper_stiffness",
                     [_vp, _vp, ctypes.c_int, c_double_p, c_double_p, c_double_p])
_stiffness_derivative = declare("udmap_damper_stiffness_derivative",
                                [_vp, _vp, ctypes.c_int, c_double_p, c_double_p, c_double_p])
_loop = declare("udmap_damper_loop",
                [_vp, _vp, ctypes.c_double, ctypes.c_int, c_double_p, c_double_p])
_set_CF = declare("udmap_damper_set_CF", [_vp, _vp, ctypes.c_double])
_jump_count = declare("udmap_damper_jump_count", [_vp, _vp, ctypes.POINTER(ctypes.c_int)])
_jump_get = declare("udmap_damper_jump_get", [_vp, _vp, ctypes.c_int, c_double_p,
                                              ctypes.c_double * 2, ctypes.c_double * 2])


def _number(name: str, value) -> float:
    try:
        return float(value)
    except (TypeError, ValueError):
        raise InputError(f"damper parameter '{name}' must be a number, got {value!r}") from None


def _point(name: str, value) -> tuple[float, float]:
    try:
        x, y = value
    except (TypeError, ValueError):
        raise InputError(f"damper parameter '{name}' must be a pair [x, y]") from None
    return _number(f"{name}[0]", x), _number(f"{name}[1]", y)


class Damper:
    """A damper handle: asymmetric flat/curved (traced exactly and tabulated on creation),
    rotational Jenkins element, or measured table. Create it with the classmethods."""

    def __init__(self, ptr: ctypes.c_void_p, err: ErrorHandle, kind: str):
        self._ptr = ptr
        self._err = err
        self.kind = kind

    def __del__(self):
        ptr = getattr(self, "_ptr", None)
        if ptr is not None and lib is not None:
            _delete(ctypes.byref(ptr))

    @property
    def ptr(self) -> ctypes.c_void_p:
        """The udmap_damper handle (for the model and other C API calls)."""
        return self._ptr

    # ------------------------------------------------------------------ creation
    @classmethod
    def asymmetric(cls, CF, mu, pitch, y_P, beta_L_deg, beta_R_deg, flat_points, curved_point,
                   kn_flat, kt_flat, kn_curved, kt_curved) -> "Damper":
        """The asymmetric damper of PHYSICS.md 2.1 (SI units, angles in degrees)."""
        try:
            f1, f2 = flat_points
        except (TypeError, ValueError):
            raise InputError("damper parameter 'flat_points' must be two pairs [[x, y], [x, y]]") \
                from None
        p = _AsymmetricParams(
            _number("CF", CF), _number("mu", mu), _number("pitch", pitch), _number("y_P", y_P),
            _number("beta_L_deg", beta_L_deg), _number("beta_R_deg", beta_R_deg),
            *_point("flat_points[0]", f1), *_point("flat_points[1]", f2),
            *_point("curved_point", curved_point),
            _number("kn_flat", kn_flat), _number("kt_flat", kt_flat),
            _number("kn_curved", kn_curved), _number("kt_curved", kt_curved))
        err = ErrorHandle()
        ptr = _vp()
        err.check(_new_asym(err.ptr, ctypes.byref(p), ctypes.byref(ptr)))
        return cls(ptr, err, "asymmetric")

    @classmethod
    def jenkins(cls, kt, M_slip) -> "Damper":
        """A rotational Jenkins element: kt [N m/rad], slip moment M_slip [N m]."""
        err = ErrorHandle()
        ptr = _vp()
        err.check(_new_jenkins(err.ptr, _number("kt", kt), _number("M_slip", M_slip),
                               ctypes.byref(ptr)))
        return cls(ptr, err, "jenkins")

    @classmethod
    def table(cls, gamma, k_re, k_im, delta_M=None) -> "Damper":
        """A measured table (PHYSICS.md 2.4): rows gamma [rad] ascending, k_re, k_im
        [N m/rad]; delta_M [N m] enables the extrapolation beyond the last row."""
        try:
            g, gp = as_doubles(np.asarray(gamma, dtype=float).ravel())
            r, rp = as_doubles(np.asarray(k_re, dtype=float).ravel())
            i, ip = as_doubles(np.asarray(k_im, dtype=float).ravel())
        except (TypeError, ValueError):
            raise InputError("damper table: 'gamma', 'k_re' and 'k_im' must be numbers") from None
        if not (g.size == r.size == i.size):
            raise InputError("damper table: 'gamma', 'k_re' and 'k_im' differ in length")
        has = delta_M is not None
        dM = _number("delta_M", delta_M) if has else 0.0
        err = ErrorHandle()
        ptr = _vp()
        err.check(_new_table(err.ptr, g.size, gp, rp, ip, int(has), dM, ctypes.byref(ptr)))
        return cls(ptr, err, "table")

    # ------------------------------------------------------------------ base-cycle data
    def _info(self) -> _Info:
        info = _Info()
        self._err.check(_get_info(self._err.ptr, self._ptr, ctypes.byref(info)))
        return info

    @property
    def gamma_b(self) -> float:
        """Base-cycle amplitude [rad]."""
        return self._info().gamma_b

    @property
    def gamma_s(self) -> float:
        """Largest amplitude whose loop has no slip [rad]."""
        return self._info().gamma_s

    @property
    def M_max(self) -> float:
        """Upward plateau moment [N m]."""
        return self._info().M_max

    @property
    def M_min(self) -> float:
        """Downward plateau moment [N m]."""
        return self._info().M_min

    @property
    def k_stuck(self) -> float:
        """Stuck stiffness, k_Re at small amplitude [N m/rad]."""
        return self._info().k_stuck

    @property
    def lift_off(self) -> bool:
        """A contact opens during the cycle (the damper left its design envelope)."""
        return bool(self._info().lift_off)

    # ------------------------------------------------------------------ evaluation
    def _eval(self, fn, gamma):
        try:
            g = np.asarray(gamma, dtype=float)
        except (TypeError, ValueError):
            raise InputError("damper: amplitudes 'gamma' must be numbers") from None
        flat = np.ascontiguousarray(g.ravel())
        re = np.empty_like(flat)
        im = np.empty_like(flat)
        self._err.check(fn(self._err.ptr, self._ptr, flat.size,
                           flat.ctypes.data_as(c_double_p), re.ctypes.data_as(c_double_p),
                           im.ctypes.data_as(c_double_p)))
        out = (re + 1j * im).reshape(g.shape)
        return out[()] if out.ndim == 0 else out

    def stiffness(self, gamma):
        """k(gamma) = k_re + i k_im [N m/rad] for amplitudes gamma [rad] (array or scalar)."""
        return self._eval(_stiffness, gamma)

    def stiffness_derivative(self, gamma):
        """dk/dgamma [N m/rad^2] (exact for the asymmetric and Jenkins kinds)."""
        return self._eval(_stiffness_derivative, gamma)

    def loop(self, gamma_a, n: int = 256):
        """The steady loop at amplitude gamma_a: (tau, M_r) at n equally spaced tau in
        [0, 2 pi), gamma = gamma_a cos(tau) (asymmetric and jenkins kinds)."""
        n = int(n)
        if n < 1:
            raise InputError("loop: 'n' must be at least 1")
        tau = np.empty(n)
        M = np.empty(n)
        self._err.check(_loop(self._err.ptr, self._ptr, _number("gamma_a", gamma_a), n,
                              tau.ctypes.data_as(c_double_p), M.ctypes.data_as(c_double_p)))
        return tau, M

    @property
    def jumps(self) -> list[dict]:
        """The jumps of k(gamma) (PHYSICS.md 2.5; with lift-off the steady loop can change its
        shape abruptly): per jump ``gamma_c`` [rad] and the one-sided stiffnesses ``k_minus``,
        ``k_plus`` (complex, N m/rad) below and above it, ascending; empty without."""
        n = ctypes.c_int()
        self._err.check(_jump_count(self._err.ptr, self._ptr, ctypes.byref(n)))
        out = []
        for i in range(n.value):
            g = ctypes.c_double()
            km, kp = (ctypes.c_double * 2)(), (ctypes.c_double * 2)()
            self._err.check(_jump_get(self._err.ptr, self._ptr, i, ctypes.byref(g), km, kp))
            out.append({"gamma_c": g.value, "k_minus": complex(km[0], km[1]),
                        "k_plus": complex(kp[0], kp[1])})
        return out

    def set_CF(self, CF) -> None:
        """New centrifugal load [N] (asymmetric kind): rescales, no new tracing."""
        self._err.check(_set_CF(self._err.ptr, self._ptr, _number("CF", CF)))

    def __repr__(self) -> str:
        i = self._info()
        return (f"Damper({self.kind}: gamma_b={i.gamma_b:.6g} rad, gamma_s={i.gamma_s:.6g} rad, "
                f"M_max={i.M_max:.6g} N m, M_min={i.M_min:.6g} N m, k_stuck={i.k_stuck:.6g} "
                f"N m/rad, lift_off={bool(i.lift_off)})")

