"""The mapping: a blade and a damper coupled over a band (PHYSICS.md 3-5).

>>> model = Model(blade, damper, f_min=150.0, f_max=230.0)
>>> model.limit_force()                      # F_lim [N]
>>> model.backbone([1, 2, 5])                # peaks: list of dicts (JSON field names)
>>> model.response(190.0, [1, 2, 5])         # at a given excitation frequency [Hz]
>>> model.backbone_curve(np.geomspace(1e-5, 1e-2, 50))   # F_bb [N], f_res [Hz]
>>> model.curves([1, 2, 5], layers=200)      # response curves by layered force mapping
"""
from __future__ import annotations

import ctypes
import math

import numpy as np

from . import _capi
from ._capi import ErrorHandle, as_doubles
from .errors import InputError

REGIME_NAMES = {0: "stuck", 1: "partial slip", 2: "full slip", 3: "at or above F_lim"}
BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING = 0, 1, 2
MAX_ROOTS = _capi.MAX_ROOTS
UNBOUNDED_MESSAGE = ("without structural damping (zeta = 0) friction cannot bound the response "
                     "to this force (F_E >= F_lim, or above the asymptote of the backbone): the "
                     "amplitude is unbounded")


#: The kinds of plausibility warning, as :meth:`Model.warnings` and
#: :func:`plausibility_warnings` name them.
WARNING_KINDS = tuple(_capi.WARNING_KINDS.values())


def plausibility_warnings(blade, f_min: float, f_max: float,
                          damper=None) -> list[tuple[str, str]]:
    """The plausibility warnings of a blade, a damper (None: its check left out) and a band
    [Hz] without a model (the band against the bare first mode; no stuck-peak checks): (kind,
    text) pairs (docs/case-files.md, "Plausibility")."""
    err = ErrorHandle()
    handle = None if damper is None else damper.handle
    return _capi.warnings_of(lambda *out: _capi.plausibility_warnings(
        err.ptr, blade.handle, handle, float(f_min), float(f_max), *out), err)


def harmonics_code(harmonics) -> int:
    """The kernel code of a harmonics setting: an integer 1..64, or "auto" (0)."""
    if harmonics == "auto":
        return 0
    if isinstance(harmonics, bool) or not isinstance(harmonics, (int, np.integer)) \
            or not 1 <= int(harmonics) <= 64:
        raise InputError(f"harmonics must be an integer from 1 to 64 or 'auto', got {harmonics!r}")
    return int(harmonics)


def _forces(F_E) -> tuple[np.ndarray, ctypes.Array]:
    arr, ptr = as_doubles(np.atleast_1d(np.asarray(F_E, dtype=float)).ravel())
    return arr, ptr


class Model:
    """A blade and a damper coupled over the band [f_min, f_max] Hz.

    The model borrows ``blade`` and ``damper`` (it keeps references to them) and caches what it
    derives: the bare-blade data for good, the backbone table until the damper changes.

    Settings: ``sigma_all`` allowable alternating stress [Pa]; ``rtol`` relative tolerance of
    every peak and root refinement; ``grid_per_decade`` amplitude grid on which all roots are
    bracketed; ``eigen_method`` 0 auto, 1 direct solver for every layer, 2 secular equation only;
    ``dense_max`` largest ndof for the dense eigen-solver (ARPACK above); ``sweep_points``
    bare-blade samples over the band for the response curves; ``harmonics`` 1 (the paper's
    single-harmonic method), an integer H up to 64 (harmonics 0..H in multi-harmonic layers,
    PHYSICS.md 4.1) or "auto" (H raised until the outputs change by less than
    ``harmonic_tol``); ``ibpa_deg`` the interblade phase angle [deg] of a traveling wave
    (PHYSICS.md 2.6; 0, the default, in phase), which needs the blade's platform translations
    (:meth:`udmap.Blade.set_platform_rows`).
    """

    def __init__(self, blade, damper, f_min: float, f_max: float, sigma_all: float = 80e6,
                 rtol: float = 1e-12, grid_per_decade: int = 24, eigen_method: int = 0,
                 dense_max: int = 200, sweep_points: int = 400, harmonics=1,
                 harmonic_tol: float = 1e-3, ibpa_deg: float = 0.0):
        self._err = ErrorHandle()
        self._ptr = ctypes.c_void_p()
        self.blade = blade
        self.damper = damper
        a = _capi.Analysis()
        _capi.analysis_defaults(ctypes.byref(a))
        a.f_min, a.f_max, a.sigma_all, a.rtol = f_min, f_max, sigma_all, rtol
        a.grid_per_decade, a.eigen_method = int(grid_per_decade), int(eigen_method)
        a.dense_max, a.sweep_points = int(dense_max), int(sweep_points)
        a.harmonics, a.harmonic_tol = harmonics_code(harmonics), float(harmonic_tol)
        ibpa_deg = float(ibpa_deg)
        if not math.isfinite(ibpa_deg):
            raise InputError(f"ibpa_deg must be a finite angle [deg], got {ibpa_deg!r}")
        if ibpa_deg != 0.0:     # 0: the kernel's default, in phase
            a.ibpa_deg = ibpa_deg
        self.ibpa_deg = a.ibpa_deg
        self.f_min, self.f_max, self.sigma_all = float(f_min), float(f_max), float(sigma_all)
        self._err.check(_capi.new_model(self._err.ptr, blade.handle, damper.handle,
                                        ctypes.byref(a), ctypes.byref(self._ptr)))
        ndof, has_stress = ctypes.c_int(), ctypes.c_int()
        self._err.check(_capi.blade_get_size(self._err.ptr, blade.handle, ctypes.byref(ndof),
                                             ctypes.byref(has_stress)))
        self.has_stress = bool(has_stress.value)

    def __del__(self):
        ptr = getattr(self, "_ptr", None)
        if ptr is not None and ptr.value and _capi is not None and _capi.lib is not None:
            _capi.delete_model(ctypes.byref(ptr))

    def set_damper(self, damper) -> None:
        """Couples another damper (e.g. after a change of its parameters): the bare-blade data
        are kept, the backbone table is rebuilt on next use."""
        self._err.check(_capi.model_set_damper(self._err.ptr, self._ptr, damper.handle))
        self.damper = damper

    def set_harmonics(self, harmonics, harmonic_tol: float = 1e-3) -> None:
        """Harmonics for the next calls (1, H up to 64, or "auto"), keeping every cache."""
        self._err.check(_capi.model_set_harmonics(self._err.ptr, self._ptr,
                                                  harmonics_code(harmonics),
                                                  float(harmonic_tol)))

    def set_ibpa(self, ibpa_deg: float) -> None:
        """The interblade phase angle [deg] for the next calls (as ``ibpa_deg`` of the
        constructor), keeping every cache: a sweep over engine orders builds the bare-blade data
        and the in-phase backbone table once."""
        ibpa_deg = float(ibpa_deg)
        if not math.isfinite(ibpa_deg):
            raise InputError(f"ibpa_deg must be a finite angle [deg], got {ibpa_deg!r}")
        self._err.check(_capi.model_set_ibpa(self._err.ptr, self._ptr, ibpa_deg))
        self.ibpa_deg = ibpa_deg

    def set_force_table(self, on: bool = True) -> None:
        """Backbone points at harmonics != 1 from the force table (as the FMU after a change of
        F_E alone): interpolated to harmonic_tol/1000 where a verified panel of exact points
        holds F_E, solved exactly elsewhere."""
        self._err.check(_capi.model_set_force_table(self._err.ptr, self._ptr, int(bool(on))))

    def cover_forces(self, F_min: float, F_max: float) -> None:
        """Prepares the backbone for every force in [F_min, F_max] N at the current harmonics
        (the single-harmonic table to F_max; with the force table on and harmonics != 1 every
        panel of the range), so that later backbone calls in the range build nothing."""
        self._err.check(_capi.model_cover_forces(self._err.ptr, self._ptr, float(F_min),
                                                 float(F_max)))

    def force_table_info(self) -> dict:
        """What the force table holds: exact points, leaves, exact leaves."""
        n = [ctypes.c_int() for _ in range(3)]
        self._err.check(_capi.model_force_table_info(self._err.ptr, self._ptr,
                                                     *(ctypes.byref(x) for x in n)))
        return dict(zip(("points", "leaves", "exact_leaves"), (x.value for x in n)))

    def admissible_force(self, F_lim: float, sigma_all: float, rtol: float = 1e-12) -> float:
        """F_adm [N]: the largest F_E <= F_lim/2 whose resonant stress (sigma_a, sigma_max with
        more than one harmonic) is at most sigma_all [Pa], refined to rtol; pass the smaller of
        F_lim and F_lim_backbone (PHYSICS.md 5). Solved in the kernel
        (kernel/src/mapping/admissible.f90)."""
        out = ctypes.c_double()
        self._err.check(_capi.model_admissible_force(self._err.ptr, self._ptr, float(F_lim),
                                                     float(sigma_all),
                                                     float(rtol), ctypes.byref(out)))
        return out.value

    def classify(self, F_lim: float, F_E, gamma_P, sigma, unbounded) -> tuple[list, list]:
        """The regime (0..3) and hcf_ok of points computed elsewhere (e.g. by the standard
        method), as :meth:`backbone` gives them (the kernel's rule): regime 3 at or above
        F_lim, else by gamma_P [rad] against the damper's gamma_s and gamma_b; hcf_ok when
        F_E <= F_lim/2 and the stress ``sigma`` [Pa] <= sigma_all; an unbounded point is regime
        3 and not admissible. F_lim [N] as the caller takes it."""
        F, Fp = as_doubles(np.atleast_1d(np.asarray(F_E, dtype=float)).ravel())
        g, gp = as_doubles(np.atleast_1d(np.asarray(gamma_P, dtype=float)).ravel())
        s, sp = as_doubles(np.atleast_1d(np.asarray(sigma, dtype=float)).ravel())
        u = np.ascontiguousarray(np.atleast_1d(unbounded).ravel(), dtype=np.intc)
        if not len(F) == len(g) == len(s) == len(u):
            raise InputError("classify: F_E, gamma_P, sigma and unbounded must have one length")
        regime = np.zeros(max(len(F), 1), dtype=np.intc)
        hcf_ok = np.zeros(max(len(F), 1), dtype=np.intc)
        self._err.check(_capi.model_classify(self._err.ptr, self._ptr, float(F_lim), len(F), Fp,
                                             gp, sp, _capi.ints_ptr(u), _capi.ints_ptr(regime),
                                             _capi.ints_ptr(hcf_ok)))
        return [int(r) for r in regime[:len(F)]], [bool(h) for h in hcf_ok[:len(F)]]

    def limit_force(self) -> float:
        """F_lim = 2 Delta_M / (pi |phi_E/phi_g|) [N] (PHYSICS.md 5)."""
        value = ctypes.c_double()
        self._err.check(_capi.model_limit_force(self._err.ptr, self._ptr, ctypes.byref(value)))
        return value.value

    def limit_force_backbone(self) -> float:
        """F_lim_backbone [N] (PHYSICS.md 5): the level the backbone approaches at large
        amplitude without structural damping; F_lim unless lift-off lowers it. The unbounded
        flag, hcf_ok and the regime of the points use the smaller of the two."""
        value = ctypes.c_double()
        self._err.check(_capi.model_limit_force_backbone(self._err.ptr, self._ptr,
                                                         ctypes.byref(value)))
        return value.value

    def warnings(self) -> list[tuple[str, str]]:
        """The plausibility warnings of the model's blade, damper and band, with the stuck
        peak (docs/case-files.md, "Plausibility"): (kind, text) pairs, kind one of
        :data:`WARNING_KINDS`. The stuck peak is a backbone point, computed as
        :meth:`backbone_curve` would."""
        return _capi.warnings_of(lambda *out: _capi.model_warnings(self._err.ptr, self._ptr,
                                                                   *out), self._err)

    def backbone_curve(self, gamma) -> tuple[np.ndarray, np.ndarray]:
        """F_bb(gamma) [N] and the peak frequency [Hz] for amplitudes gamma [rad]."""
        g, gp = as_doubles(np.atleast_1d(np.asarray(gamma, dtype=float)).ravel())
        F_bb = np.zeros_like(g)
        f_res = np.zeros_like(g)
        self._err.check(_capi.model_backbone_curve(self._err.ptr, self._ptr, len(g), gp,
                                                   F_bb.ctypes.data_as(_capi.c_double_p),
                                                   f_res.ctypes.data_as(_capi.c_double_p)))
        return F_bb, f_res

    def _points(self, fn, *args) -> list[dict]:
        F, Fp = _forces(args[-1])
        out = (_capi.Point * max(len(F), 1))()
        self._err.check(fn(self._err.ptr, self._ptr, *args[:-1], len(F), Fp, out))
        points = [self._point_dict(out[i]) for i in range(len(F))]
        for i, d in enumerate(points):
            if d["harmonics"] > 1 and not d["unbounded"]:
                d["harmonic_content"] = self._harmonic_content(i, d["harmonics"])
        return points

    def _harmonic_content(self, i: int, H: int) -> dict:
        """|Gamma_h| [rad] and |sigma_h| [Pa], h = 0..H, of point i of the last call."""
        g, s = np.zeros(H + 1), np.zeros(H + 1)
        nh = ctypes.c_int()
        self._err.check(_capi.model_point_harmonics(self._err.ptr, self._ptr, i, H + 1,
                                                    g.ctypes.data_as(_capi.c_double_p),
                                         s.ctypes.data_as(_capi.c_double_p), ctypes.byref(nh)))
        return {"gamma_h": [float(x) for x in g[:nh.value]],
                "sigma_h": [float(x) for x in s[:nh.value]] if self.has_stress else None}

    def _point_dict(self, p: "_capi.Point") -> dict:
        d = {"F_E": p.F_E, "gamma_P": p.gamma_P, "f_res": p.f_res,
             "sigma_a": p.sigma_a if self.has_stress else None, "u_E": p.u_E,
             "k_re": p.k_re, "k_im": p.k_im, "regime": p.regime,
             "regime_name": REGIME_NAMES.get(p.regime, ""), "hcf_ok": bool(p.hcf_ok),
             "roots": [p.roots[i] for i in range(p.nroots)], "unbounded": bool(p.unbounded),
             "gamma_max": p.gamma_max, "sigma_max": p.sigma_max if self.has_stress else None,
             "harmonics": p.harmonics,
             "hcf_stress": "sigma_max" if p.harmonics > 1 else "sigma_a"}
        if d["unbounded"]:
            for key in ("gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im", "gamma_max",
                        "sigma_max"):
                d[key] = None
            d["roots"] = []
            d["message"] = UNBOUNDED_MESSAGE
        return d

    def backbone(self, F_E) -> list[dict]:
        """The peaks of the non-linear response for the forces F_E [N] (PHYSICS.md 4): per
        force a dict with F_E, gamma_P [rad], f_res [Hz], sigma_a [Pa] (None without stress
        rows), u_E [m], k_re, k_im [N m/rad], regime (0..3) and regime_name, hcf_ok, roots (every
        gamma_P root, ascending), unbounded (with a message; the numbers are then None),
        jump (gamma_P is the amplitude of a jump of k(gamma), k interpolated between its
        one-sided values so that the layer peaks at F_E; PHYSICS.md 2.5); gamma_max, sigma_max
        (largest excursions from the mean), harmonics (H used), hcf_stress (the stress hcf_ok
        compares with sigma_all: sigma_max when H > 1) and, when H > 1, harmonic_content
        {gamma_h, sigma_h} (amplitudes of harmonics 0..H)."""
        points = self._points(_capi.model_backbone, F_E)
        jumps = np.zeros(max(len(points), 1), dtype=np.intc)
        self._err.check(_capi.model_backbone_jumps(self._err.ptr, self._ptr, len(points),
                                                   jumps.ctypes.data_as(_capi.c_int_p)))
        for p, j in zip(points, jumps):
            p["jump"] = bool(j)
        return points

    def response(self, f_exc: float, F_E) -> list[dict]:
        """The response at the excitation frequency f_exc [Hz] (inside the band) to the forces
        F_E [N]: same fields as :meth:`backbone`, f_res = f_exc."""
        return self._points(_capi.model_response, ctypes.c_double(f_exc), F_E)

    def curves(self, F_E, layers: int | None = None) -> list[dict]:
        """Response curves by amplitude layered force mapping (PHYSICS.md 3): per force a dict
        with F_E and arrays f [Hz], gamma_P [rad], sigma_a [Pa], branch (0 below the layer's peak
        frequency, 1 above, 2 turning point on the backbone) and part (1 main curve, 2... detached
        parts), in path order. ``layers``: initial amplitude layers (default 200)."""
        F, Fp = _forces(F_E)
        layers = 200 if layers is None else int(layers)
        self._err.check(_capi.model_curves(self._err.ptr, self._ptr, len(F), Fp, layers))
        result = []
        for i in range(len(F)):
            n = ctypes.c_int()
            self._err.check(_capi.model_curve_size(self._err.ptr, self._ptr, i, ctypes.byref(n)))
            f, g, s = (np.zeros(n.value) for _ in range(3))
            branch, part = np.zeros(n.value, dtype=np.intc), np.zeros(n.value, dtype=np.intc)
            self._err.check(_capi.model_curve_get(self._err.ptr, self._ptr, i, n.value,
                                                  _capi.doubles_ptr(f), _capi.doubles_ptr(g),
                                                  s.ctypes.data_as(_capi.c_double_p),
                                                  branch.ctypes.data_as(_capi.c_int_p),
                                                  part.ctypes.data_as(_capi.c_int_p)))
            result.append({"F_E": float(F[i]), "f": f, "gamma_P": g,
                           "sigma_a": s if self.has_stress else np.full(n.value, math.nan),
                           "branch": branch.astype(int), "part": part.astype(int)})
        return result


class BackbonePoints:
    """Reusable arrays of kernel backbone points (``udmap_point``) seen as numpy record arrays,
    so that a backbone costs one C call and no Python object per point (a design of
    experiments evaluates millions of them)."""

    def __init__(self, size: int):
        self._size = size
        self._buf = (_capi.Point * size)()
        self._view = np.ctypeslib.as_array(self._buf)
        self._forces = np.zeros(size)
        self._forces_ptr = self._forces.ctypes.data_as(_capi.c_double_p)
        self._jumps = (ctypes.c_int * size)()

    def backbone(self, model: Model, forces):
        """The points of ``model`` for ``forces`` (a view valid until the next call)."""
        n = len(forces)
        if n > self._size:
            self.__init__(n)
        self._forces[:n] = forces
        status = _capi.model_backbone(model._err.ptr, model._ptr, n, self._forces_ptr, self._buf)
        if status:
            model._err.check(status)
        return self._view[:n]

    def jumps(self, model: Model, n: int) -> list[bool]:
        """Per point of the last :meth:`backbone` call: gamma_P at a jump of k."""
        status = _capi.model_backbone_jumps(model._err.ptr, model._ptr, n, self._jumps)
        if status:
            model._err.check(status)
        return [f != 0 for f in self._jumps[:n]]


#: Stages of :meth:`DesignBatch.run` (udmap_model_designs, wrappers/c/udmap.h).
DESIGN_LIMIT, DESIGN_LIMIT_BACKBONE, DESIGN_PEAKS, DESIGN_JUMPS, DESIGN_ADMISSIBLE = \
    1, 2, 4, 8, 16
#: Where a design failed (``stage``): the damper, its coupling or F_lim, the peaks, F_adm.
DESIGN_FAILED_DAMPER, DESIGN_FAILED_LIMIT, DESIGN_FAILED_PEAKS, DESIGN_FAILED_ADMISSIBLE = \
    1, 2, 3, 4


class DesignBatch:
    """Many designs on one model in one kernel call (``udmap_model_designs``): arrays in,
    arrays out, only the stages asked for, each design's numbers those of the single calls bit
    for bit. Designs given with a reference parameter block (equal but for CF and a common
    factor of the four contact stiffnesses) share the damper traced for it, rescaled exactly
    (PHYSICS.md 2.3). The output arrays are reused from call to call."""

    MESSAGE_LEN = 4096

    def __init__(self, forces):
        self.forces, self._forces_ptr = as_doubles(np.asarray(forces, dtype=float).ravel())
        self._n = -1

    def _alloc(self, n: int) -> None:
        nf = len(self.forces)
        self.out = {k: np.zeros(n) for k in ("F_lim", "F_lim_backbone", "gamma_b", "M_max",
                                             "M_min", "F_adm")}
        self.out.update({k: np.zeros((n, nf)) for k in ("gamma_P", "f_res", "sigma_a")})
        self.out.update({k: np.zeros((n, nf), dtype=np.intc)
                         for k in ("unbounded", "hcf_ok", "jump")})
        self.out.update({k: np.zeros(n, dtype=np.intc) for k in ("lift_off", "status", "stage")})
        self._messages = ctypes.create_string_buffer(max(n, 1) * self.MESSAGE_LEN)
        s = _capi.DesignOutputs()
        for name, arr in self.out.items():
            setattr(s, name, arr.ctypes.data_as(_capi.c_int_p if arr.dtype == np.intc
                                                else _capi.c_double_p))
        s.message = ctypes.cast(self._messages, ctypes.c_char_p)
        s.message_len = self.MESSAGE_LEN
        self._struct = s
        self._n = n

    def run(self, model: Model, stages: int, params=None, reference=None,
            warnings: bool = False) -> dict:
        """The designs: ``params`` an (n, 16) array of asymmetric parameter blocks (or None:
        one design with the model's own damper), ``reference`` the same shape or None (each
        design traced for its own block). Returns the output arrays (views valid until the
        next call; missing stages keep stale values, see ``status`` and ``stage``) and
        ``traces`` (dampers traced by this call). With ``warnings``, also ``warnings``: per
        design the kinds of its plausibility warnings (:data:`WARNING_KINDS`, the stuck peak
        included; ``udmap_model_designs_warnings``), None where its damper failed."""
        if params is None:
            n, pp, rp = 1, None, None
        else:
            params = np.ascontiguousarray(params, dtype=np.float64)
            n = params.shape[0]
            pp = params.ctypes.data
            rp = None
            if reference is not None:
                reference = np.ascontiguousarray(reference, dtype=np.float64)
                rp = reference.ctypes.data
        if n != self._n:
            self._alloc(n)
        if warnings:
            bits = np.zeros(max(n, 1), dtype=np.intc)
            status = _capi.model_designs_warnings(
                model._err.ptr, model._ptr, n, pp, rp, len(self.forces), self._forces_ptr,
                int(stages), ctypes.byref(self._struct), bits.ctypes.data_as(_capi.c_int_p))
        else:
            status = _capi.model_designs(model._err.ptr, model._ptr, n, pp, rp, len(self.forces),
                                         self._forces_ptr, int(stages), ctypes.byref(self._struct))
        if status:
            model._err.check(status)
        result = dict(self.out)
        result["traces"] = self._struct.traces
        if warnings:
            result["warnings"] = [None if b < 0 else
                                  [k for j, k in enumerate(WARNING_KINDS) if b >> j & 1]
                                  for b in bits[:n]]
        return result

    def message(self, i: int) -> str:
        """The failure message of design i of the last call."""
        raw = self._messages.raw[i * self.MESSAGE_LEN:(i + 1) * self.MESSAGE_LEN]
        return raw.split(b"\0", 1)[0].decode("utf-8", "replace")
