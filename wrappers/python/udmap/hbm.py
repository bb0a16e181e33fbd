"""The standard convergence-based method and the time-domain ground truth (PHYSICS.md 6, 7).

``hbm``: harmonic balance (harmonics 1..H, optionally 0) with the damper moment by alternating
frequency-time on the contact model (its loading history replayed, events traced exactly),
Newton-Raphson and arc-length continuation over the band for each force, the peak of the first
harmonic of gamma_P located on the continued curve. ``dti``: Newmark integration of the whole
blade with the quasi-static damper from rest to a true steady state.

The damper enters as a :class:`Contact`, its contact law in time (not the stiffness table);
:func:`udmap.case.build_contact` makes one from the ``damper`` section of a case.
"""
from __future__ import annotations

import ctypes
from typing import Iterable

import numpy as np

from . import _capi
from ._capi import ErrorHandle, as_doubles
from .blade import Blade
from .damper import Damper, asymmetric_params
from .errors import InputError, PhysicsError
from .model import Model

CONDENSED, FULL = 0, 1
MAX_ROOTS = _capi.MAX_ROOTS
MAX_HARMONICS = _capi.MAX_HARMONICS
VARIANTS = {"condensed": CONDENSED, "standard_condensed": CONDENSED,
            "full": FULL, "standard_full": FULL}
HbmSettings = _capi.HbmSettings
HbmPoint = _capi.HbmPoint
DtiSettings = _capi.DtiSettings
DtiPoint = _capi.DtiPoint
DtiWheelPoint = _capi.DtiWheelPoint
_c_double_p = _capi.c_double_p


def _blade_ptr(blade: Blade) -> ctypes.c_void_p:
    """The udmap_blade handle of a Blade."""
    if not isinstance(blade, Blade):
        raise InputError("hbm: 'blade' must be a udmap Blade")
    return blade.handle


class Contact:
    """The damper's contact law in time: a hysteretic element driven along gamma(t). Build it
    with :meth:`jenkins` or :meth:`asymmetric` (from a case: :func:`udmap.case.build_contact`)."""

    def __init__(self, ptr: ctypes.c_void_p):
        self.ptr = ptr

    @classmethod
    def jenkins(cls, kt: float, M_slip: float) -> "Contact":
        """Rotational Jenkins element (PHYSICS.md 2.4): kt [N m/rad], M_slip [N m]."""
        err = ErrorHandle()
        ptr = ctypes.c_void_p()
        err.check(_capi.new_contact_jenkins(err.ptr, float(kt), float(M_slip), ctypes.byref(ptr)))
        return cls(ptr)

    @classmethod
    def asymmetric(cls, CF, mu, pitch, y_P, beta_L_deg, beta_R_deg, flat_points, curved_point,
                   kn_flat, kt_flat, kn_curved, kt_curved) -> "Contact":
        """The asymmetric flat/curved damper (PHYSICS.md 2.1), parameters as in
        :meth:`udmap.Damper.asymmetric`."""
        params = asymmetric_params(CF, mu, pitch, y_P, beta_L_deg, beta_R_deg, flat_points,
                                   curved_point, kn_flat, kt_flat, kn_curved, kt_curved)
        err = ErrorHandle()
        ptr = ctypes.c_void_p()
        err.check(_capi.new_contact_asymmetric(err.ptr, ctypes.byref(params), ctypes.byref(ptr)))
        return cls(ptr)

    def __del__(self):
        if getattr(self, "ptr", None) is not None and _capi is not None and _capi.lib is not None:
            _capi.delete_contact(ctypes.byref(self.ptr))

    def aft(self, G, G0: float = 0.0, samples: int = 0):
        """The steady moment for gamma(tau) = G0 + Re(sum_h G[h-1] e^{i h tau}) with the loading
        history: (M0, M (complex, per harmonic), gamma_max)."""
        G = np.atleast_1d(np.asarray(G, dtype=complex))
        H = len(G)
        g, gp = as_doubles(np.column_stack([G.real, G.imag]).ravel())
        M = np.zeros(2*H)
        mp = M.ctypes.data_as(_c_double_p)
        M0, gmax = ctypes.c_double(), ctypes.c_double()
        err = ErrorHandle()
        err.check(_capi.contact_aft(err.ptr, self.ptr, H, float(G0), gp, int(samples),
                                    ctypes.byref(M0), mp, ctypes.byref(gmax)))
        return M0.value, M[0::2] + 1j*M[1::2], gmax.value


def _contact(contact) -> Contact:
    if isinstance(contact, Contact):
        return contact
    raise InputError("hbm: 'damper' must be a Contact (udmap.case.build_contact makes one from "
                     "the damper section of a case)")


def hbm_settings(harmonics: int = 1, variant: str = "condensed", **kw) -> HbmSettings:
    """Kernel defaults, with `harmonics`, `variant` and any field of udmap_hbm_settings."""
    s = HbmSettings()
    _capi.hbm_defaults(ctypes.byref(s))
    if variant not in VARIANTS:
        raise InputError(f"hbm: variant must be 'condensed' or 'full', got {variant!r}")
    s.harmonics = int(harmonics)
    s.variant = VARIANTS[variant]
    for key, value in kw.items():
        if key not in dict(HbmSettings._fields_):
            raise InputError(f"hbm: unknown setting {key!r}")
        setattr(s, key, int(value) if isinstance(value, bool) else value)
    return s


def dti_settings(**kw) -> DtiSettings:
    """Kernel defaults, with any field of udmap_dti_settings."""
    s = DtiSettings()
    _capi.dti_defaults(ctypes.byref(s))
    for key, value in kw.items():
        if key not in dict(DtiSettings._fields_):
            raise InputError(f"dti: unknown setting {key!r}")
        setattr(s, key, value)
    return s


def _forces(F_E) -> tuple[np.ndarray, ctypes.POINTER(ctypes.c_double)]:
    arr, ptr = as_doubles(np.atleast_1d(np.asarray(F_E, dtype=float)))
    if arr.ndim != 1 or not np.all(np.isfinite(arr)):
        raise InputError("F_E must be finite numbers")
    return arr, ptr


def _hbm_dict(p: HbmPoint) -> dict:
    n = max(0, min(p.npeaks, MAX_ROOTS))
    return {"F_E": p.F_E, "gamma_P": p.gamma_P, "f_res": p.f_res, "sigma_a": p.sigma_a,
            "u_E": p.u_E, "k_re": p.k_re, "k_im": p.k_im,
            "roots": [p.peaks[i] for i in range(n)],
            "peak_f": [p.peak_f[i] for i in range(n)],
            "gamma_max": p.gamma_max,
            "gamma_h": [p.gamma_h[i] for i in range(max(0, min(p.harmonics, MAX_HARMONICS)))],
            "lift_off": bool(p.lift_off),
            "steps": p.steps, "iterations": p.iterations, "aft_calls": p.aft_calls,
            "seconds": p.seconds}


def hbm(blade, contact, f_min: float, f_max: float, F_E: Iterable[float], harmonics: int = 1,
        variant: str = "condensed", sigma_all: float = 80e6, damper: "Damper | None" = None,
        progress=None, **settings) -> list[dict]:
    """Peaks of the response by the standard method for each force.

    blade: a udmap Blade; contact: a Contact; band [f_min, f_max] in Hz; variant 'condensed'
    or 'full'; settings: fields of udmap_hbm_settings (tol, tol_path, ds_max, aft_samples,
    harmonic0, jacobian_reuse, warm_start, ...; with warm_start the forces go to the kernel in
    one call, in the order given, each started from the previous one's peak).
    Returns per force the backbone fields (F_E, gamma_P, f_res, sigma_a, u_E, k_re, k_im,
    roots: every local maximum of gamma_1, ascending; with ``damper``, the same damper's
    k(gamma) face (a udmap Damper), also F_lim, regime and hcf_ok from F_lim, gamma_s,
    gamma_b) plus gamma_max, gamma_h (|Gamma_h|), peak_f, lift_off, steps, iterations,
    aft_calls and seconds (kernel wall time of that force). A response the standard method
    finds unbounded (at or above F_lim without enough damping) is a point with unbounded=True
    and a message, as for the backbone.
    progress: optional callable, called with 1 after each force (e.g. Progress.update)."""
    contact = _contact(contact)
    s = hbm_settings(harmonics, variant, **settings)
    arr, _ = _forces(F_E)
    out = []
    if s.warm_start and len(arr) > 1:
        # one kernel call: each force starts from the previous one's peak
        ptr = as_doubles(arr)[1]
        pts = (HbmPoint * len(arr))()
        err = ErrorHandle()
        try:
            err.check(_capi.hbm_peaks(err.ptr, _blade_ptr(blade), contact.ptr, float(f_min),
                                      float(f_max), ctypes.byref(s), len(arr), ptr, pts))
        except PhysicsError as exc:
            if "unbounded" not in str(exc):
                raise
            # an unbounded force stops the chain: the forces one by one, cold
            s.warm_start = 0
        else:
            out = [_hbm_dict(pts[i]) for i in range(len(arr))]
            if progress is not None:
                progress(len(arr))
    for F in (arr if not out else []):
        one, ptr = as_doubles(np.array([F]))
        pts = (HbmPoint * 1)()
        err = ErrorHandle()
        try:
            err.check(_capi.hbm_peaks(err.ptr, _blade_ptr(blade), contact.ptr, float(f_min),
                                      float(f_max), ctypes.byref(s), 1, ptr, pts))
        except PhysicsError as exc:
            if "unbounded" not in str(exc):
                raise
            out.append({"F_E": float(F), "unbounded": True, "message": str(exc)})
        else:
            out.append(_hbm_dict(pts[0]))
        if progress is not None:
            progress(1)
    if damper is not None:
        classify(blade, damper, f_min, f_max, sigma_all, out)
    return out


def classify(blade: Blade, damper: Damper, f_min, f_max, sigma_all, points: list[dict]) -> None:
    """Adds F_lim, regime (0 stuck, 1 partial slip, 2 full slip, 3 at or above F_lim) and hcf_ok
    (F_E <= 0.5 F_lim and sigma_a <= sigma_all) as the backbone defines them, by the kernel's
    rule (udmap_model_classify) on the kernel's F_lim."""
    model = Model(blade, damper, f_min, f_max, sigma_all=sigma_all)
    F_lim = model.limit_force()
    unbounded = [bool(p.get("unbounded")) for p in points]
    regime, hcf_ok = model.classify(
        F_lim, [p["F_E"] for p in points],
        [0.0 if u else p["gamma_P"] for p, u in zip(points, unbounded)],
        [0.0 if u else p["sigma_a"] for p, u in zip(points, unbounded)], unbounded)
    for p, r, h in zip(points, regime, hcf_ok):
        p["F_lim"] = F_lim
        p["regime"] = r
        p["hcf_ok"] = h


def hbm_response(blade, contact, f_min: float, f_exc: float, F_E: Iterable[float],
                 harmonics: int = 1, variant: str = "condensed", **settings) -> list[dict]:
    """The response at f_exc [Hz] for each force, reached by continuation from f_min."""
    contact = _contact(contact)
    s = hbm_settings(harmonics, variant, **settings)
    arr, ptr = _forces(F_E)
    pts = (HbmPoint * max(1, len(arr)))()
    err = ErrorHandle()
    err.check(_capi.hbm_response(err.ptr, _blade_ptr(blade), contact.ptr, float(f_min),
                                 float(f_exc),
                                 ctypes.byref(s), len(arr), ptr, pts))
    return [_hbm_dict(pts[i]) for i in range(len(arr))]


def hbm_curve(blade, contact, f_min: float, f_max: float, F_E: float, harmonics: int = 1,
              variant: str = "condensed", **settings) -> dict:
    """The continued response curve of one force: arrays f [Hz], gamma_1, sigma_1, gamma_max."""
    contact = _contact(contact)
    s = hbm_settings(harmonics, variant, **settings)
    cap = 4096
    while True:
        bufs = [np.zeros(cap) for _ in range(4)]
        n = ctypes.c_int()
        err = ErrorHandle()
        err.check(_capi.hbm_curve(err.ptr, _blade_ptr(blade), contact.ptr, float(f_min),
                                  float(f_max), ctypes.byref(s), float(F_E), cap, ctypes.byref(n),
                                  *[b.ctypes.data_as(_c_double_p) for b in bufs]))
        if n.value <= cap:
            break
        cap = n.value
    m = n.value
    return {"F_E": float(F_E), "f": bufs[0][:m], "gamma_1": bufs[1][:m],
            "sigma_1": bufs[2][:m], "gamma_max": bufs[3][:m]}


def dti(blade, contact, F_E: Iterable[float], freq: float | None = None, peak: bool = False,
        f_min: float | None = None, f_max: float | None = None, progress=None,
        **settings) -> list[dict]:
    """Time integration to steady state for each force, at `freq` [Hz] or, with peak=True, at
    the frequency of the largest gamma_1 near the single-harmonic peak in [f_min, f_max].
    settings: fields of udmap_dti_settings (steps_per_period, ss_tol, ...); progress: optional
    callable, called with 1 after each force.
    Returns dicts {F_E, f, gamma_1, sigma_1, gamma_max, gamma_0, ss_error, periods, runs,
    seconds, lift_off}."""
    def call(err, s, ptr, pts):
        if peak:
            return _capi.dti_peak(err.ptr, _blade_ptr(blade), contact.ptr, ctypes.byref(s),
                                  float(f_min), float(f_max), 1, ptr, pts)
        return _capi.dti_response(err.ptr, _blade_ptr(blade), contact.ptr, ctypes.byref(s),
                                  float(freq), 1, ptr, pts)
    contact = _contact(contact)
    points = _dti_points(F_E, freq, peak, f_min, f_max, progress, settings, DtiPoint, call)
    return [_dti_dict(p) for p in points]


def dti_wheel(blade, contact, F_E: Iterable[float], blades: int, engine_order: int,
              freq: float | None = None, peak: bool = False, f_min: float | None = None,
              f_max: float | None = None, f_center: float | None = None, progress=None,
              **settings) -> list[dict]:
    """The whole wheel in time (PHYSICS.md 2.6, 7): `blades` blades and dampers, blade j under
    F_E sin(2 pi f t + j phi), phi = 2 pi engine_order/blades, from rest to steady state, at
    `freq` [Hz] or, with peak=True, at the frequency of blade 0's largest gamma_1 searched
    around `f_center` (default: the in-phase single-harmonic peak in [f_min, f_max]).
    Returns dicts with blade 0's fields of :func:`dti` and blades, engine_order, phi [rad],
    gamma_spread, sigma_spread (the largest relative difference of the blades' first-harmonic
    amplitudes), blade_spread (the larger of the two) and phase_spread (the largest deviation
    of the phase step between neighbours from phi [rad])."""
    def call(err, s, ptr, pts):
        if peak:
            return _capi.dti_wheel_peak(err.ptr, _blade_ptr(blade), contact.ptr, ctypes.byref(s),
                                        float(f_min), float(f_max), float(f_center or 0.0),
                                        int(blades), int(engine_order), 1, ptr, pts)
        return _capi.dti_wheel_response(err.ptr, _blade_ptr(blade), contact.ptr,
                                        ctypes.byref(s), float(freq), int(blades),
                                        int(engine_order), 1, ptr, pts)
    contact = _contact(contact)
    points = _dti_points(F_E, freq, peak, f_min, f_max, progress, settings, DtiWheelPoint,
                         call)
    out = []
    for w in points:
        p = _dti_dict(w.blade0)
        for k, _ in DtiWheelPoint._fields_[1:]:
            p[k] = getattr(w, k)
        p["blade_spread"] = max(p["gamma_spread"], p["sigma_spread"])
        out.append(p)
    return out


def _dti_points(F_E, freq, peak, f_min, f_max, progress, settings, point_type, call) -> list:
    """The kernel's points of `call(err, settings, F_E pointer, points)`, one force a call."""
    s = dti_settings(**settings)
    arr, _ = _forces(F_E)
    if peak and (f_min is None or f_max is None):
        raise InputError("dti: the peak search needs the band f_min, f_max")
    if not peak and freq is None:
        raise InputError("dti: give freq or peak=True")
    out = []
    for F in arr:
        one, ptr = as_doubles(np.array([F]))
        pts = (point_type * 1)()
        err = ErrorHandle()
        err.check(call(err, s, ptr, pts))
        out.append(pts[0])
        if progress is not None:
            progress(1)
    return out


def _dti_dict(point) -> dict:
    p = {k: getattr(point, k) for k, _ in DtiPoint._fields_}
    p["lift_off"] = bool(p["lift_off"])
    return p


def wave_hbm(blade: Blade, damper: Damper, f_min: float, f_max: float, ibpa_deg: float,
             F_E: Iterable[float], f_start: Iterable[float], harmonics: int = 1) -> list[dict]:
    """Peaks of a traveling wave at the interblade phase ``ibpa_deg`` [deg] by the standard
    method (PHYSICS.md 2.6 and 6): for each force [N], continuation down from ``f_start`` [Hz]
    (above the peak: the friction damper softens the blade) and the maximum of |Gamma_1| over
    frequency. ``harmonics``: 1, or H up to 64
    (harmonics 0..H). Returns per force F_E, gamma_P [rad], f_res [Hz], sigma_a [Pa], u_E [m]
    and the Newton iterations."""
    arr, ptr = _forces(F_E)
    starts = np.ascontiguousarray(np.asarray(list(f_start), dtype=float))
    if starts.shape != arr.shape:
        raise InputError("wave_hbm: 'f_start' needs one frequency per force")
    n = len(arr)
    outs = [np.zeros(n) for _ in range(4)]
    its = np.zeros(n, dtype=np.intc)
    dp = ctypes.POINTER(ctypes.c_double)
    err = ErrorHandle()
    err.check(_capi.wave_hbm_peaks(
        err.ptr, _blade_ptr(blade), damper.handle, float(f_min), float(f_max), float(ibpa_deg),
        int(harmonics), n, ptr, starts.ctypes.data_as(dp),
        *[o.ctypes.data_as(dp) for o in outs], its.ctypes.data_as(ctypes.POINTER(ctypes.c_int))))
    return [{"F_E": float(arr[i]), "gamma_P": float(outs[0][i]), "f_res": float(outs[1][i]),
             "sigma_a": float(outs[2][i]), "u_E": float(outs[3][i]),
             "iterations": int(its[i])} for i in range(n)]
