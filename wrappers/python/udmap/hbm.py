"""The standard convergence-based method and the time-domain ground truth (PHYSICS.md 6, 7).

``hbm``: harmonic balance (harmonics 1..H, optionally 0) with the damper moment by alternating
frequency-time on the contact model (its loading history replayed, events traced exactly),
Newton-Raphson and arc-length continuation over the band for each force, the peak of the first
harmonic of gamma_P located on the continued curve. ``dti``: Newmark integration of the whole
blade with the quasi-static damper from rest to a true steady state.

The damper enters through its parameters (the ``damper`` section of a case): these methods
need its contact law in time, not the stiffness table.
"""
from __future__ import annotations

import ctypes
from typing import Iterable

import numpy as np

from ._lib import ErrorHandle, InputError, PhysicsError, as_doubles, declare, lib
from .parameters import AsymmetricParams

_c_double_p = ctypes.POINTER(ctypes.c_double)
_c_int_p = ctypes.POINTER(ctypes.c_int)

CONDENSED, FULL = 0, 1
MAX_ROOTS = 8
MAX_HARMONICS = 64
VARIANTS = {"condensed": CONDENSED, "standard_condensed": CONDENSED,
            "full": FULL, "standard_full": FULL}


class HbmSettings(ctypes.Structure):
    """udmap_hbm_settings (defaults from the kernel)."""
    _fields_ = [("harmonics", ctypes.c_int), ("harmonic0", ctypes.c_int),
                ("variant", ctypes.c_int), ("tol", ctypes.c_double),
                ("max_iter", ctypes.c_int), ("ds_initial", ctypes.c_double),
                ("ds_min", ctypes.c_double), ("ds_max", ctypes.c_double),
                ("target_iter", ctypes.c_int), ("max_angle", ctypes.c_double),
                ("max_steps", ctypes.c_int), ("peak_tol", ctypes.c_double),
                ("aft_samples", ctypes.c_int), ("aft_max_periods", ctypes.c_int),
                ("fd_step", ctypes.c_double), ("gamma_limit", ctypes.c_double),
                ("full_band", ctypes.c_int), ("jacobian_reuse", ctypes.c_int),
                ("tol_path", ctypes.c_double), ("warm_start", ctypes.c_int)]


class HbmPoint(ctypes.Structure):
    """udmap_hbm_point."""
    _fields_ = [("F_E", ctypes.c_double), ("gamma_P", ctypes.c_double),
                ("f_res", ctypes.c_double), ("sigma_a", ctypes.c_double),
                ("u_E", ctypes.c_double), ("k_re", ctypes.c_double), ("k_im", ctypes.c_double),
                ("gamma_max", ctypes.c_double), ("npeaks", ctypes.c_int),
                ("peaks", ctypes.c_double * MAX_ROOTS), ("peak_f", ctypes.c_double * MAX_ROOTS),
                ("harmonics", ctypes.c_int), ("gamma_h", ctypes.c_double * MAX_HARMONICS),
                ("steps", ctypes.c_int), ("iterations", ctypes.c_int),
                ("aft_calls", ctypes.c_int), ("seconds", ctypes.c_double),
                ("lift_off", ctypes.c_int)]


class DtiSettings(ctypes.Structure):
    """udmap_dti_settings (defaults from the kernel)."""
    _fields_ = [("steps_per_period", ctypes.c_int), ("ss_tol", ctypes.c_double),
                ("min_periods", ctypes.c_int), ("max_periods", ctypes.c_int),
                ("peak_rtol", ctypes.c_double), ("peak_window", ctypes.c_double),
                ("gamma_limit", ctypes.c_double)]


class DtiPoint(ctypes.Structure):
    """udmap_dti_point."""
    _fields_ = [("F_E", ctypes.c_double), ("f", ctypes.c_double), ("gamma_1", ctypes.c_double),
                ("sigma_1", ctypes.c_double), ("gamma_max", ctypes.c_double),
                ("gamma_0", ctypes.c_double), ("ss_error", ctypes.c_double),
                ("periods", ctypes.c_int), ("runs", ctypes.c_int), ("seconds", ctypes.c_double),
                ("lift_off", ctypes.c_int)]


_vp = ctypes.c_void_p
_new_jenkins = declare("udmap_new_contact_jenkins",
                       [_vp, ctypes.c_double, ctypes.c_double, ctypes.POINTER(_vp)])
_delete_contact = declare("udmap_delete_contact", [ctypes.POINTER(_vp)], None)
_contact_aft = declare("udmap_contact_aft",
                       [_vp, _vp, ctypes.c_int, ctypes.c_double, _c_double_p, ctypes.c_int,
                        _c_double_p, _c_double_p, _c_double_p])
_hbm_defaults = declare("udmap_hbm_defaults", [ctypes.POINTER(HbmSettings)], None)
_hbm_peaks = declare("udmap_hbm_peaks",
                     [_vp, _vp, _vp, ctypes.c_double, ctypes.c_double,
                      ctypes.POINTER(HbmSettings), ctypes.c_int, _c_double_p,
                      ctypes.POINTER(HbmPoint)])
_hbm_response = declare("udmap_hbm_response",
                        [_vp, _vp, _vp, ctypes.c_double, ctypes.c_double,
                         ctypes.POINTER(HbmSettings), ctypes.c_int, _c_double_p,
                         ctypes.POINTER(HbmPoint)])
_hbm_curve = declare("udmap_hbm_curve",
                     [_vp, _vp, _vp, ctypes.c_double, ctypes.c_double,
                      ctypes.POINTER(HbmSettings), ctypes.c_double, ctypes.c_int, _c_int_p,
                      _c_double_p, _c_double_p, _c_double_p, _c_double_p])
_dti_defaults = declare("udmap_dti_defaults", [ctypes.POINTER(DtiSettings)], None)
_dti_response = declare("udmap_dti_response",
                        [_vp, _vp, _vp, ctypes.POINTER(DtiSettings), ctypes.c_double,
                         ctypes.c_int, _c_double_p, ctypes.POINTER(DtiPoint)])
_dti_peak = declare("udmap_dti_peak",
                    [_vp, _vp, _vp, ctypes.POINTER(DtiSettings), ctypes.c_double,
                     ctypes.c_double, ctypes.c_int, _c_double_p, ctypes.POINTER(DtiPoint)])


_AsymmetricParams = AsymmetricParams  # udmap_asymmetric_params (wrappers/c/udmap.h)


def _asymmetric_params(damper: dict) -> _AsymmetricParams:
    """udmap_asymmetric_params from the damper section of a case."""
    try:
        (f1x, f1y), (f2x, f2y) = damper["flat_points"]
        cx, cy = damper["curved_point"]
        return _AsymmetricParams(
            *(float(damper[k]) for k in ("CF", "mu", "pitch", "y_P", "beta_L_deg", "beta_R_deg")),
            float(f1x), float(f1y), float(f2x), float(f2y), float(cx), float(cy),
            *(float(damper[k]) for k in ("kn_flat", "kt_flat", "kn_curved", "kt_curved")))
    except (KeyError, TypeError, ValueError) as exc:
        raise InputError(f"damper: asymmetric parameters incomplete or invalid ({exc})")


def _new_asymmetric():
    return declare("udmap_new_contact_asymmetric",
                   [_vp, ctypes.POINTER(_AsymmetricParams), ctypes.POINTER(_vp)])


def _blade_ptr(blade) -> ctypes.c_void_p:
    """The udmap_blade handle of a Blade object (or a raw handle)."""
    for name in ("_handle", "handle", "_ptr", "ptr"):
        ptr = getattr(blade, name, None)
        if ptr is not None:
            return ptr if isinstance(ptr, ctypes.c_void_p) else ctypes.c_void_p(ptr)
    if isinstance(blade, (int, ctypes.c_void_p)):
        return blade if isinstance(blade, ctypes.c_void_p) else ctypes.c_void_p(blade)
    raise InputError("hbm: 'blade' must be a udmap Blade")


class Contact:
    """The damper's contact law in time: a hysteretic element driven along gamma(t)."""

    def __init__(self, ptr: ctypes.c_void_p):
        self.ptr = ptr

    @classmethod
    def jenkins(cls, kt: float, M_slip: float) -> "Contact":
        """Rotational Jenkins element (PHYSICS.md 2.4): kt [N m/rad], M_slip [N m]."""
        err = ErrorHandle()
        ptr = ctypes.c_void_p()
        err.check(_new_jenkins(err.ptr, float(kt), float(M_slip), ctypes.byref(ptr)))
        return cls(ptr)

    @classmethod
    def from_params(cls, damper: dict) -> "Contact":
        """From the ``damper`` section of a case (kinds ``jenkins`` and ``asymmetric``)."""
        kind = damper.get("kind")
        if kind == "jenkins":
            return cls.jenkins(damper["kt"], damper["M_slip"])
        if kind == "asymmetric":
            return cls.asymmetric(damper)
        raise InputError(f"damper.kind '{kind}': the standard method and the time integration "
                         "need a contact model ('asymmetric' or 'jenkins'), not a table")

    @classmethod
    def asymmetric(cls, damper: dict) -> "Contact":
        """The asymmetric flat/curved damper (PHYSICS.md 2.1) from its case parameters (the
        damper section of a case: CF, mu, pitch, y_P, beta_L_deg, beta_R_deg, flat_points,
        curved_point, kn_flat, kt_flat, kn_curved, kt_curved)."""
        params = _asymmetric_params(damper)
        err = ErrorHandle()
        ptr = ctypes.c_void_p()
        err.check(_new_asymmetric()(err.ptr, ctypes.byref(params), ctypes.byref(ptr)))
        return cls(ptr)

    def __del__(self):
        if getattr(self, "ptr", None) is not None and lib is not None:
            _delete_contact(ctypes.byref(self.ptr))

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
        err.check(_contact_aft(err.ptr, self.ptr, H, float(G0), gp, int(samples),
                               ctypes.byref(M0), mp, ctypes.byref(gmax)))
        return M0.value, M[0::2] + 1j*M[1::2], gmax.value


def _contact(damper) -> Contact:
    if isinstance(damper, Contact):
        return damper
    if isinstance(damper, dict):
        return Contact.from_params(damper)
    raise InputError("hbm: 'damper' must be the damper section of a case (dict) or a Contact")


def hbm_settings(harmonics: int = 1, variant: str = "condensed", **kw) -> HbmSettings:
    """Kernel defaults, with `harmonics`, `variant` and any field of udmap_hbm_settings."""
    s = HbmSettings()
    _hbm_defaults(ctypes.byref(s))
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
    _dti_defaults(ctypes.byref(s))
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


def hbm(blade, damper, f_min: float, f_max: float, F_E: Iterable[float], harmonics: int = 1,
        variant: str = "condensed", sigma_all: float = 80e6, classify: bool = True,
        progress=None, **settings) -> list[dict]:
    """Peaks of the response by the standard method for each force.

    blade: a udmap Blade; damper: the case's damper section (dict) or a Contact; band
    [f_min, f_max] in Hz; variant 'condensed' or 'full'; settings: fields of
    udmap_hbm_settings (tol, tol_path, ds_max, aft_samples, harmonic0, jacobian_reuse,
    warm_start, ...; with warm_start the forces go to the kernel in one call, in the order
    given, each started from the previous one's peak).
    Returns per force the backbone fields (F_E, gamma_P, f_res, sigma_a, u_E, k_re, k_im,
    roots: every local maximum of gamma_1, ascending; with classify and a damper dict also
    regime and hcf_ok from F_lim, gamma_s, gamma_b) plus gamma_max, gamma_h (|Gamma_h|),
    peak_f, lift_off, steps, iterations, aft_calls and seconds (kernel wall time of that
    force). A response the standard method finds unbounded (at or above F_lim without enough
    damping) is a point with unbounded=True and a message, as for the backbone.
    progress: optional callable, called with 1 after each force (e.g. Progress.update)."""
    contact = _contact(damper)
    s = hbm_settings(harmonics, variant, **settings)
    arr, _ = _forces(F_E)
    out = []
    if s.warm_start and len(arr) > 1:
        # one kernel call: each force starts from the previous one's peak
        ptr = as_doubles(arr)[1]
        pts = (HbmPoint * len(arr))()
        err = ErrorHandle()
        try:
            err.check(_hbm_peaks(err.ptr, _blade_ptr(blade), contact.ptr, float(f_min),
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
            err.check(_hbm_peaks(err.ptr, _blade_ptr(blade), contact.ptr, float(f_min),
                                 float(f_max), ctypes.byref(s), 1, ptr, pts))
        except PhysicsError as exc:
            if "unbounded" not in str(exc):
                raise
            out.append({"F_E": float(F), "unbounded": True, "message": str(exc)})
        else:
            out.append(_hbm_dict(pts[0]))
        if progress is not None:
            progress(1)
    if classify and isinstance(damper, dict):
        _classify(blade, damper, f_min, f_max, sigma_all, out)
    return out


def _classify(blade, damper: dict, f_min, f_max, sigma_all, points: list[dict]) -> None:
    """Adds regime (0 stuck, 1 partial slip, 2 full slip, 3 at or above F_lim) and hcf_ok
    (F_E <= 0.5 F_lim and sigma_a <= sigma_all) as the backbone defines them."""
    from .case import Case, build_damper
    from .model import Model
    kd = build_damper(Case(blade={}, damper=damper, analysis={}))
    F_lim = Model(blade, kd, f_min, f_max, sigma_all=sigma_all).limit_force()
    gamma_s, gamma_b = kd.gamma_s, kd.gamma_b
    for p in points:
        p["F_lim"] = F_lim
        if p["F_E"] >= F_lim:
            p["regime"] = 3
        elif p.get("unbounded"):
            p["regime"] = 3
        elif p["gamma_P"] <= gamma_s:
            p["regime"] = 0
        elif p["gamma_P"] < gamma_b:
            p["regime"] = 1
        else:
            p["regime"] = 2
        p["hcf_ok"] = bool(not p.get("unbounded") and p["F_E"] <= 0.5 * F_lim
                           and p["sigma_a"] <= sigma_all)


def hbm_response(blade, damper, f_min: float, f_exc: float, F_E: Iterable[float],
                 harmonics: int = 1, variant: str = "condensed", **settings) -> list[dict]:
    """The response at f_exc [Hz] for each force, reached by continuation from f_min."""
    contact = _contact(damper)
    s = hbm_settings(harmonics, variant, **settings)
    arr, ptr = _forces(F_E)
    pts = (HbmPoint * max(1, len(arr)))()
    err = ErrorHandle()
    err.check(_hbm_response(err.ptr, _blade_ptr(blade), contact.ptr, float(f_min), float(f_exc),
                            ctypes.byref(s), len(arr), ptr, pts))
    return [_hbm_dict(pts[i]) for i in range(len(arr))]


def hbm_curve(blade, damper, f_min: float, f_max: float, F_E: float, harmonics: int = 1,
              variant: str = "condensed", **settings) -> dict:
    """The continued response curve of one force: arrays f [Hz], gamma_1, sigma_1, gamma_max."""
    contact = _contact(damper)
    s = hbm_settings(harmonics, variant, **settings)
    cap = 4096
    while True:
        bufs = [np.zeros(cap) for _ in range(4)]
        n = ctypes.c_int()
        err = ErrorHandle()
        err.check(_hbm_curve(err.ptr, _blade_ptr(blade), contact.ptr, float(f_min),
                             float(f_max), ctypes.byref(s), float(F_E), cap, ctypes.byref(n),
                             *[b.ctypes.data_as(_c_double_p) for b in bufs]))
        if n.value <= cap:
            break
        cap = n.value
    m = n.value
    return {"F_E": float(F_E), "f": bufs[0][:m], "gamma_1": bufs[1][:m],
            "sigma_1": bufs[2][:m], "gamma_max": bufs[3][:m]}


def dti(blade, damper, F_E: Iterable[float], freq: float | None = None, peak: bool = False,
        f_min: float | None = None, f_max: float | None = None, progress=None,
        **settings) -> list[dict]:
    """Time integration to steady state for each force, at `freq` [Hz] or, with peak=True, at
    the frequency of the largest gamma_1 near the single-harmonic peak in [f_min, f_max].
    settings: fields of udmap_dti_settings (steps_per_period, ss_tol, ...); progress: optional
    callable, called with 1 after each force.
    Returns dicts {F_E, f, gamma_1, sigma_1, gamma_max, gamma_0, ss_error, periods, runs,
    seconds, lift_off}."""
    contact = _contact(damper)
    s = dti_settings(**settings)
    arr, _ = _forces(F_E)
    if peak and (f_min is None or f_max is None):
        raise InputError("dti: the peak search needs the band f_min, f_max")
    if not peak and freq is None:
        raise InputError("dti: give freq or peak=True")
    keys = [k for k, _ in DtiPoint._fields_]
    out = []
    for F in arr:
        one, ptr = as_doubles(np.array([F]))
        pts = (DtiPoint * 1)()
        err = ErrorHandle()
        if peak:
            err.check(_dti_peak(err.ptr, _blade_ptr(blade), contact.ptr, ctypes.byref(s),
                                float(f_min), float(f_max), 1, ptr, pts))
        else:
            err.check(_dti_response(err.ptr, _blade_ptr(blade), contact.ptr, ctypes.byref(s),
                                    float(freq), 1, ptr, pts))
        p = {k: getattr(pts[0], k) for k in keys}
        p["lift_off"] = bool(p["lift_off"])
        out.append(p)
        if progress is not None:
            progress(1)
    return out
