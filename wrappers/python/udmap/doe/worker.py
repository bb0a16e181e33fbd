"""One design of experiments' worker: the context it keeps between designs (shared blade, model
and damper) and the evaluation of a chunk of designs into CSV text. Plain data in and out, so
that process pools and Dask workers import it by name."""
from __future__ import annotations

import os
import threading
from pathlib import Path
from typing import Sequence

import numpy as np

from ..case import Case, build_blade, build_damper, build_model
from ..damper import ASYMMETRIC_FIELDS, AsymmetricBuilder, Damper
from ..errors import InputError, PhysicsError, UdmapError
from ..model import BackbonePoints
from .io import format_rows
from .parameters import with_values

#: Per-design status values of the ``status`` column.
STATUS_OK, STATUS_INPUT, STATUS_PHYSICS, STATUS_NUMERIC, STATUS_ERROR = (
    "ok", "input", "physics", "numeric", "error")
#: The forces at which the kernel's F_adm first samples the resonant stress: ADM_GRID forces
#: spaced geometrically from 10^-ADM_DECADES F_lim/2 to F_lim/2, and below the smallest
#: sample the force (relative to it) where small forces are checked (ADM_TINY); the kernel's
#: n_grid, grid_decades and tiny_ratio (kernel/src/mapping/admissible.f90, which documents how
#: F_adm is found).
ADM_GRID = 16
ADM_DECADES = 3.0
ADM_TINY = 1e-6


def admissible_grid(F_half: float, n: int = ADM_GRID, decades: float = ADM_DECADES):
    """The forces ``F_half 10^(-decades (n-1-i)/(n-1))``, ``i = 0..n-1`` (the last one is
    ``F_half`` exactly)."""
    grid = F_half * 10.0 ** (decades * (np.arange(n, dtype=float) - (n - 1)) / (n - 1))
    grid[-1] = F_half
    return grid


def _status_of(exc: BaseException) -> str:
    if isinstance(exc, InputError):
        return STATUS_INPUT
    if isinstance(exc, PhysicsError):
        return STATUS_PHYSICS
    if isinstance(exc, UdmapError):
        return STATUS_NUMERIC
    return STATUS_ERROR


class DesignContext:
    """What one worker keeps between the designs of a run, so that a design costs the kernel's
    work and little else:

    - the blade, built once when no blade parameter varies (a model only reads it);
    - the model, when neither blade nor analysis parameters vary: one model for the run, which
      keeps the bare-blade data and gets each design's damper by ``set_damper`` (its backbone
      table is rebuilt from scratch for every damper);
    - the damper, when ``CF`` is the only damper parameter that varies: traced once, rescaled
      per design by ``set_CF`` (PHYSICS.md 2.3, exact);
    - ctypes buffers for the backbone points, read through numpy (no dict per point).

    A row depends only on the design's values: a shared model is first used once with a
    fixed Jenkins damper, so that the one-off direct eigen-solve of its first backbone table
    is behind it, and every design then goes through the same sequence of kernel calls on a
    freshly rebuilt table, whichever worker and whichever design came before.
    """

    def __init__(self, spec: dict):
        self.spec = spec
        self.case = Case(blade=spec["blade"], damper=spec["damper"],
                         analysis=spec["analysis"], name=spec["name"],
                         base_dir=Path(spec["base_dir"]))
        self.paths = [tuple(p) for p in spec["paths"]]
        self.forces = np.array(spec["forces"], dtype=float)
        sections = {p[0] for p in self.paths}
        self.blade_varies = "blade" in sections
        self.analysis_varies = "analysis" in sections
        self.band_varies = any(p in (("analysis", "f_min"), ("analysis", "f_max"))
                               for p in self.paths)
        damper_paths = [p for p in self.paths if p[0] == "damper"]
        self.cf_index = None
        if self.case.damper["kind"] == "asymmetric" and damper_paths == [("damper", "CF")]:
            self.cf_index = self.paths.index(("damper", "CF"))
        self.damper_varies = bool(damper_paths)
        # Only damper parameters vary: the nominal case serves every design, and an asymmetric
        # damper is built straight from its C parameter block.
        self.damper_only = not (self.blade_varies or self.analysis_varies)
        self._asym = None
        if self.damper_only and self.damper_varies and self.cf_index is None and \
                self.case.damper["kind"] == "asymmetric":
            self._asym = _AsymmetricBlocks(self.case.damper, self.paths)
        self._cache: dict = {}
        self._points = BackbonePoints(max(len(self.forces), 1))

    # -- shared objects, built on first use; a failure is remembered and raised per design
    def _shared(self, key, build):
        entry = self._cache.get(key)
        if entry is None:
            try:
                entry = (build(), None)
            except UdmapError as exc:
                entry = (None, exc)
            self._cache[key] = entry
        if entry[1] is not None:
            raise entry[1]
        return entry[0]

    def _blade(self, case: Case):
        if self.blade_varies:
            return build_blade(case)
        return self._shared("blade", lambda: build_blade(self.case))

    def _damper(self, case: Case, values):
        if self.cf_index is not None:
            damper = self._shared("damper", lambda: build_damper(self.case))
            damper.set_CF(values[self.cf_index])
            return damper
        if not self.damper_varies:
            return self._shared("damper", lambda: build_damper(self.case))
        if self._asym is not None:
            return self._asym.build(values)
        return build_damper(case)

    def _model_for(self, case: Case, blade, damper):
        if self.blade_varies or self.analysis_varies:
            return build_model(case, blade, damper)

        def primed():
            model = build_model(self.case, blade, Damper.jenkins(1.0, 1e-3))
            try:  # the first backbone table of a model starts from a direct eigen-solve
                model.backbone_curve([1e-4])
            except UdmapError:
                pass
            return model

        model = self._shared("model", primed)
        model.set_damper(damper)
        return model

    def evaluate(self, values: Sequence) -> dict:
        """One design: a dict with the fields of a row (see :func:`udmap.doe.io.row_cells`)."""
        row: dict = {"status": STATUS_OK, "message": ""}
        stage = ""
        try:
            case = self.case if self.damper_only and self._asym is not None else \
                with_values(self.case, self.paths, values)
            a = case.analysis
            if self.band_varies and not a["f_max"] > a["f_min"]:
                raise InputError(f"analysis.f_max ({a['f_max']}) must exceed analysis.f_min "
                                 f"({a['f_min']})")
            damper = self._damper(case, values)
            info = damper.info()
            row["gamma_b"], row["M_max"], row["M_min"] = info.gamma_b, info.M_max, info.M_min
            row["lift_off"] = bool(info.lift_off)
            model = self._model_for(case, self._blade(case), damper)
            row["F_lim"] = model.limit_force()
            # PHYSICS.md 5: with lift-off the backbone may level off below F_lim; F_adm and the
            # HCF check use the smaller limit
            row["F_lim_backbone"] = model.limit_force_backbone()
            F_lim = min(row["F_lim"], row["F_lim_backbone"])
            notes = []
            if len(self.forces):
                p = self._points.backbone(model, self.forces)
                unbounded = p["unbounded"] != 0
                gamma_P, f_res = p["gamma_P"].tolist(), p["f_res"].tolist()
                sigma_a = p["sigma_a"].tolist() if model.has_stress else [None] * len(p)
                for i in np.flatnonzero(unbounded):
                    gamma_P[i] = f_res[i] = sigma_a[i] = None
                    notes.append(f"F_E = {self.spec['labels'][i]} N: unbounded (zeta = 0 and "
                                 "F_E at or above F_lim or the backbone's asymptote)")
                row["gamma_P"], row["f_res"], row["sigma_a"] = gamma_P, f_res, sigma_a
                row["hcf_ok"] = (p["hcf_ok"] != 0).tolist()
                row["jump"] = self._points.jumps(model, len(p))
            stage = "F_adm: "
            if model.has_stress:
                row["F_adm"] = model.admissible_force(F_lim, a["sigma_all"], rtol=a["rtol"])
                if row["F_adm"] == 0:
                    notes.append(f"F_adm = 0: sigma_a exceeds sigma_all down to F_E = "
                                 f"{ADM_TINY * admissible_grid(0.5 * F_lim)[0]:.3g} N")
            else:  # an imported blade without stress rows: only F_E <= F_lim/2 can be checked
                row["F_adm"] = 0.5 * F_lim
                notes.append("no stress rows: F_adm = F_lim/2, sigma_a not checked")
            row["message"] = "; ".join(notes)
        except Exception as exc:  # recorded per design; the run goes on
            row["status"] = _status_of(exc)
            text = str(exc) or type(exc).__name__
            row["message"] = stage + (text if isinstance(exc, UdmapError) else
                                      f"{type(exc).__name__}: {text}")
        return row


class _AsymmetricBlocks:
    """Builds the asymmetric damper of a design from the nominal C parameter block with the
    varied entries replaced (what :func:`udmap.case.build_damper` passes to the kernel, without
    the case dictionaries in between); one error handle serves all its dampers."""

    def __init__(self, damper: dict, paths):
        (f1x, f1y), (f2x, f2y) = damper["flat_points"]
        fields = {"flat1_x": f1x, "flat1_y": f1y, "flat2_x": f2x, "flat2_y": f2y,
                  "curved_x": damper["curved_point"][0], "curved_y": damper["curved_point"][1]}
        names = list(ASYMMETRIC_FIELDS)
        self.base = [float(fields[n] if n in fields else damper[n]) for n in names]
        self.slots = []
        for path in paths:
            if path[1] == "flat_points":
                name = f"flat{path[2] + 1}_{'xy'[path[3]]}"
            elif path[1] == "curved_point":
                name = f"curved_{'xy'[path[2]]}"
            else:
                name = path[1]
            self.slots.append(names.index(name))
        self.builder = AsymmetricBuilder()

    def build(self, values) -> Damper:
        block = list(self.base)
        for slot, value in zip(self.slots, values):
            block[slot] = float(value)
        return self.builder.build(block)


_CONTEXTS: dict = {}


def context_for(spec: dict) -> DesignContext:
    """The worker's context for a run (one per run token, process and thread: a forked worker
    does not inherit its parent's)."""
    key = (spec["token"], os.getpid(), threading.get_ident())
    ctx = _CONTEXTS.get(key)
    if ctx is None:
        if len(_CONTEXTS) > 64:
            _CONTEXTS.clear()
        ctx = _CONTEXTS[key] = DesignContext(spec)
    return ctx


def run_chunk(spec: dict, start: int, values: Sequence[tuple]) -> tuple:
    """Evaluates designs ``start, start + 1, ...`` with the given parameter values and returns
    ``(start, count, csv_text, counts)`` (counts: see :func:`udmap.doe.io.tally`): the chunk's
    rows already formatted, so that the writer only appends text and the result is independent
    of where it was computed."""
    ctx = context_for(spec)
    rows = [ctx.evaluate(v) for v in values]
    text, counts = format_rows(spec, start, values, rows)
    return start, len(rows), text, counts
