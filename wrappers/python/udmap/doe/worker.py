"""One design of experiments' worker: the context it keeps between designs (shared blade, model
and damper), the evaluation of a chunk of designs (one kernel call for a chunk of asymmetric
dampers) and its CSV text. Plain data in and out, so that process pools and Dask workers import
it by name."""
from __future__ import annotations

import os
import threading
from pathlib import Path
from typing import Sequence

import numpy as np

from ..case import Case, build_blade, build_damper, build_model
from ..case.plausibility import blade_checks
from ..damper import ASYMMETRIC_FIELDS, Damper
from ..errors import InputError, PhysicsError, UdmapError
from ..model import (DESIGN_ADMISSIBLE, DESIGN_FAILED_ADMISSIBLE, DESIGN_FAILED_DAMPER,
                     DESIGN_FAILED_LIMIT, DESIGN_FAILED_PEAKS, DESIGN_JUMPS, DESIGN_LIMIT,
                     DESIGN_LIMIT_BACKBONE, DESIGN_PEAKS, DesignBatch)
from .arrow import chunk_payload
from .layout import output_names
from .io import format_chunk
from .parameters import STIFFNESS_SCALE_PATH, with_values

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


#: Output names of ``--outputs`` whose kernel stages (udmap_model_designs) they need; the
#: damper's summary (gamma_b, M_max, M_min, lift_off) comes with every design.
STAGES = {"F_lim": DESIGN_LIMIT, "F_lim_backbone": DESIGN_LIMIT_BACKBONE,
          "gamma_P": DESIGN_PEAKS, "f_res": DESIGN_PEAKS, "sigma_a": DESIGN_PEAKS,
          "hcf_ok": DESIGN_PEAKS, "jump": DESIGN_JUMPS, "F_adm": DESIGN_ADMISSIBLE}
#: Parameters that a shared trace absorbs exactly (PHYSICS.md 2.3).
SCALE_PATHS = (("damper", "CF"), (STIFFNESS_SCALE_PATH))
_FLOATS = ("F_lim", "F_lim_backbone", "gamma_b", "M_max", "M_min", "F_adm")
_KERNEL_STATUS = {2: STATUS_INPUT, 3: STATUS_PHYSICS}


def stages_of(outputs) -> int:
    """The kernel stages the chosen outputs need (all of them for the default outputs)."""
    stages = 0
    for name in outputs:
        stages |= STAGES.get(name, 0)
    return stages


class ChunkRows:
    """The results of a chunk of designs as columns (what :func:`udmap.doe.io.format_chunk`
    writes): floats NaN where missing, flags -1 where missing, per-force columns (n, forces)."""

    def __init__(self, n: int, nf: int):
        self.n = n
        self.num = {k: np.full(n, np.nan) for k in _FLOATS}
        self.lift_off = np.full(n, -1, dtype=np.int8)
        self.force = {k: np.full((n, nf), np.nan) for k in ("gamma_P", "f_res", "sigma_a")}
        self.flags = {k: np.full((n, nf), -1, dtype=np.int8) for k in ("hcf_ok", "jump")}
        self.status = [STATUS_OK] * n
        self.message = [""] * n
        #: Plausibility warnings (udmap.case.plausibility) counted per kind over the designs.
        self.warnings: dict = {}

    def warn(self, kinds, count: int = 1) -> None:
        """Counts each kind in ``kinds`` ``count`` times."""
        for kind in kinds:
            if count:
                self.warnings[kind] = self.warnings.get(kind, 0) + int(count)


class DesignContext:
    """What one worker keeps between the designs of a run, so that a design costs the kernel's
    work and little else:

    - the blade, built once when no blade parameter varies (a model only reads it);
    - the model, when neither blade nor analysis parameters vary: one model for the run, which
      keeps the bare-blade data; a chunk of asymmetric dampers then goes to the kernel in one
      call (udmap_model_designs) as parameter blocks, with no Python per design;
    - traced dampers: a design whose damper differs from its reference only in CF and a
      common factor of the contact stiffnesses (``stiffness_scale``) takes the reference's
      tracing rescaled exactly (PHYSICS.md 2.3); the run decides the references
      (:func:`design_references`), so a row does not depend on the chunk or the worker.

    A shared model is first used once with a fixed Jenkins damper, so that the one-off direct
    eigen-solve of its first backbone table is behind it, and every design then goes through
    the same sequence of kernel calls on a freshly rebuilt table, whichever worker and
    whichever design came before.
    """

    def __init__(self, spec: dict):
        self.spec = spec
        self.case = Case(blade=spec["blade"], damper=spec["damper"],
                         analysis=spec["analysis"], name=spec["name"],
                         base_dir=Path(spec["base_dir"]))
        self.paths = [tuple(p) for p in spec["paths"]]
        self.forces = np.array(spec["forces"], dtype=float)
        self.outputs = output_names(spec)
        self.stages = stages_of(self.outputs)
        sections = {p[0] for p in self.paths}
        self.blade_varies = "blade" in sections
        self.analysis_varies = "analysis" in sections
        self.band_varies = any(p in (("analysis", "f_min"), ("analysis", "f_max"))
                               for p in self.paths)
        damper_paths = [p for p in self.paths if p[0] == "damper"]
        self.damper_varies = bool(damper_paths)
        # designs built one by one whose damper differs in CF alone: one tracing, set_CF
        self.cf_index = None
        if self.case.damper["kind"] == "asymmetric" and damper_paths == [("damper", "CF")]:
            self.cf_index = self.paths.index(("damper", "CF"))
        self.damper_only = not (self.blade_varies or self.analysis_varies)
        # an asymmetric damper on the shared model: whole chunks in one kernel call
        self._asym = None
        if self.damper_only and self.damper_varies and \
                self.case.damper["kind"] == "asymmetric":
            self._asym = _AsymmetricBlocks(self.case.damper, self.paths)
            # only CF and the stiffness factor vary: one tracing (the nominal) serves all
            self.nominal_reference = all(p in SCALE_PATHS for p in damper_paths)
        self._cache: dict = {}
        self._batch = DesignBatch(self.forces)
        self.traces = 0

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

    def _blade_warnings(self, case: Case, blade) -> list[str]:
        """The kinds of the plausibility warnings of a design's blade and band (the platform,
        the bare first mode in the band): once per run when neither varies. For the designs
        whose damper fails; the others get every check from the kernel."""
        def kinds(c, b):
            return [k for k, _ in blade_checks(b, c.analysis["f_min"], c.analysis["f_max"])]

        if self.blade_varies or self.band_varies:
            return kinds(case, blade)
        return self._shared("blade_warnings", lambda: kinds(self.case, blade))

    def _built_damper(self, case: Case):
        if case.damper["kind"] == "asymmetric":
            self.traces += 1
        return build_damper(case)

    def _damper(self, case: Case, values):
        if self.cf_index is not None:
            damper = self._shared("damper", lambda: self._built_damper(self.case))
            damper.set_CF(values[self.cf_index])
            return damper
        if not self.damper_varies:
            return self._shared("damper", lambda: self._built_damper(self.case))
        return self._built_damper(case)

    def _model_for(self, case: Case, blade, damper):
        if self.blade_varies or self.analysis_varies:
            return build_model(case, blade, damper)
        model = self._shared_model(blade)
        model.set_damper(damper)
        return model

    def _shared_model(self, blade):
        """The run's model (no blade or analysis parameter varies), primed."""
        def primed():
            model = build_model(self.case, blade, Damper.jenkins(1.0, 1e-3))
            try:  # the first backbone table of a model starts from a direct eigen-solve
                model.backbone_curve([1e-4])
            except UdmapError:
                pass
            return model

        return self._shared("model", primed)

    # -- a chunk
    def evaluate_chunk(self, values: Sequence, refs=None) -> ChunkRows:
        """The rows of a chunk of designs; ``refs`` per design the parameter values of its
        reference (None: its own), see :func:`design_references`."""
        rows = ChunkRows(len(values), len(self.forces))
        if not len(values):
            return rows
        if self._asym is not None:
            try:
                model = self._shared_model(self._blade(self.case))
            except UdmapError as exc:
                for i in range(rows.n):
                    self._fail(rows, i, exc, "")
                return rows
            blocks = self._asym.blocks(values)
            if self.nominal_reference:
                reference = np.repeat(self._asym.base[None, :], rows.n, axis=0)
            elif refs is not None:
                reference = blocks.copy()
                for i, r in enumerate(refs):
                    if r is not None:
                        reference[i] = self._asym.blocks([r])[0]
            else:
                reference = None
            # with every plausibility check of each design, the stuck peak included
            r = self._batch.run(model, self.stages, blocks, reference, warnings=True)
            self.traces += r["traces"]
            self._take(rows, slice(0, rows.n), r, model.has_stress)
            blade_kinds = None
            for kinds in r["warnings"]:
                if kinds is None:  # its damper failed: the checks of the blade and band alone
                    if blade_kinds is None:
                        blade_kinds = self._blade_warnings(self.case, model.blade)
                    kinds = blade_kinds
                rows.warn(kinds)
        else:
            for i, v in enumerate(values):
                self._evaluate_one(rows, i, v)
        return rows

    def _evaluate_one(self, rows: ChunkRows, i: int, values) -> None:
        """Design i of the chunk through Python objects (a blade or analysis parameter varies,
        or a damper of another kind), its kernel stages in one udmap_model_designs call."""
        try:
            case = with_values(self.case, self.paths, values)
            a = case.analysis
            if self.band_varies and not a["f_max"] > a["f_min"]:
                raise InputError(f"analysis.f_max ({a['f_max']}) must exceed analysis.f_min "
                                 f"({a['f_min']})")
            damper = self._damper(case, values)
            info = damper.info()
            rows.num["gamma_b"][i], rows.num["M_max"][i], rows.num["M_min"][i] = \
                info.gamma_b, info.M_max, info.M_min
            rows.lift_off[i] = bool(info.lift_off)
            blade = self._blade(case)
            model = self._model_for(case, blade, damper)
        except Exception as exc:  # recorded per design; the run goes on
            self._fail(rows, i, exc, "")
            return
        r = self._batch.run(model, self.stages)
        self._take(rows, slice(i, i + 1), r, model.has_stress)
        # every check of the design, the stuck peak included (after its stages: the check's
        # backbone point does not touch them)
        rows.warn(sorted({kind for kind, _ in model.warnings()}))

    def _take(self, rows: ChunkRows, at: slice, r: dict, has_stress: bool) -> None:
        """Rows ``at`` from the kernel's arrays ``r``: what each design got before a failure,
        its status and message."""
        status, stage = r["status"], r["stage"]
        ok = status == 0
        reached = lambda s: ok | (stage > s)  # noqa: E731  (the stage after s was started)
        has_damper = reached(DESIGN_FAILED_DAMPER)
        for k in ("gamma_b", "M_max", "M_min"):
            rows.num[k][at] = np.where(has_damper, r[k], rows.num[k][at])
        rows.lift_off[at] = np.where(has_damper, r["lift_off"] != 0, rows.lift_off[at])
        if self.stages & (DESIGN_LIMIT | DESIGN_LIMIT_BACKBONE | DESIGN_ADMISSIBLE):
            has_limit = reached(DESIGN_FAILED_LIMIT)
            for k in ("F_lim", "F_lim_backbone"):
                rows.num[k][at] = np.where(has_limit, r[k], np.nan)
        nf = len(self.forces)
        peaks = bool(self.stages & (DESIGN_PEAKS | DESIGN_JUMPS)) and nf > 0
        if peaks:
            has_peaks = reached(DESIGN_FAILED_PEAKS)[:, None]
            unbounded = r["unbounded"] != 0
            for k in ("gamma_P", "f_res", "sigma_a"):
                v = np.where(unbounded, np.nan, r[k])
                if k == "sigma_a" and not has_stress:
                    v = np.full_like(v, np.nan)
                rows.force[k][at] = np.where(has_peaks, v, np.nan)
            for k in ("hcf_ok", "jump"):
                rows.flags[k][at] = np.where(has_peaks, r[k] != 0, -1)
        adm = bool(self.stages & DESIGN_ADMISSIBLE)
        if adm:
            rows.num["F_adm"][at] = np.where(ok, r["F_adm"], np.nan)
        offset = at.start
        labels = self.spec["labels"]
        # messages: the failures, and the notes of designs with an unbounded point, F_adm = 0
        # or no stress rows (few designs: Python per such design only)
        need = ~ok
        if peaks:
            need |= ok & unbounded.any(axis=1)
        if adm:
            need |= ok & ((r["F_adm"] == 0) | (not has_stress))
        for j in np.flatnonzero(need):
            i = offset + j
            if not ok[j]:
                rows.status[i] = _KERNEL_STATUS.get(int(status[j]), STATUS_NUMERIC)
                prefix = "F_adm: " if stage[j] == DESIGN_FAILED_ADMISSIBLE else ""
                rows.message[i] = prefix + (self._batch.message(j) or
                                            f"udmap error {int(status[j])}")
                continue
            notes = []
            if peaks:
                for f in np.flatnonzero(unbounded[j]):
                    notes.append(f"F_E = {labels[f]} N: unbounded (zeta = 0 and F_E at or above "
                                 "F_lim or the backbone's asymptote)")
            if adm and has_stress and r["F_adm"][j] == 0:
                F_lim = min(float(r["F_lim"][j]), float(r["F_lim_backbone"][j]))
                notes.append(f"F_adm = 0: sigma_a exceeds sigma_all down to F_E = "
                             f"{ADM_TINY * admissible_grid(0.5 * F_lim)[0]:.3g} N")
            elif adm and not has_stress:
                notes.append("no stress rows: F_adm = F_lim/2, sigma_a not checked")
            rows.message[i] = "; ".join(notes)

    @staticmethod
    def _fail(rows: ChunkRows, i: int, exc: BaseException, stage: str) -> None:
        rows.status[i] = _status_of(exc)
        text = str(exc) or type(exc).__name__
        rows.message[i] = stage + (text if isinstance(exc, UdmapError) else
                                   f"{type(exc).__name__}: {text}")


def design_references(spec: dict, values) -> np.ndarray | None:
    """Per design the index of its reference design, or -1 (its own damper is traced): designs
    whose varied parameters agree but for CF and ``stiffness_scale`` form a group, and every
    design of a group of several takes the tracing of its first design (in design order),
    rescaled exactly (PHYSICS.md 2.3). Decided for the whole run, so that a row does not
    depend on how the designs are cut into chunks. None when no design shares a tracing (or
    the run has no asymmetric damper on a shared model, or only CF and the factor vary: then
    the nominal damper's tracing serves every design)."""
    paths = [tuple(p) for p in spec["paths"]]
    sections = {p[0] for p in paths}
    damper_paths = [p for p in paths if p[0] == "damper"]
    if spec["damper"].get("kind") != "asymmetric" or sections != {"damper"} or \
            not any(p in SCALE_PATHS for p in paths) or all(p in SCALE_PATHS for p in damper_paths):
        return None
    key_cols = [j for j, p in enumerate(paths) if p not in SCALE_PATHS]
    x = values.x[:, key_cols]
    _, first, inverse, counts = np.unique(x, axis=0, return_index=True, return_inverse=True,
                                          return_counts=True)
    inverse = inverse.ravel()
    refs = np.where(counts[inverse] > 1, first[inverse], -1)
    return refs if (refs >= 0).any() else None


class _AsymmetricBlocks:
    """The asymmetric damper parameter blocks of designs (what :func:`udmap.case.build_damper`
    passes to the kernel, without the case dictionaries in between): the nominal block with the
    varied entries replaced, ``stiffness_scale`` multiplying the four contact stiffnesses."""

    def __init__(self, damper: dict, paths):
        (f1x, f1y), (f2x, f2y) = damper["flat_points"]
        fields = {"flat1_x": f1x, "flat1_y": f1y, "flat2_x": f2x, "flat2_y": f2y,
                  "curved_x": damper["curved_point"][0], "curved_y": damper["curved_point"][1]}
        names = list(ASYMMETRIC_FIELDS)
        self.base = np.array([float(fields[n] if n in fields else damper[n]) for n in names])
        self.slots = []
        self.scale = None
        self.stiffness = [names.index(n) for n in ("kn_flat", "kt_flat", "kn_curved",
                                                   "kt_curved")]
        for j, path in enumerate(paths):
            if path == STIFFNESS_SCALE_PATH:
                self.scale = j
                continue
            if path[1] == "flat_points":
                name = f"flat{path[2] + 1}_{'xy'[path[3]]}"
            elif path[1] == "curved_point":
                name = f"curved_{'xy'[path[2]]}"
            else:
                name = path[1]
            self.slots.append((j, names.index(name)))

    def blocks(self, values) -> np.ndarray:
        """The (n, 16) blocks of the designs with these values."""
        x = np.asarray(values, dtype=float).reshape(len(values), -1)
        out = np.repeat(self.base[None, :], len(values), axis=0)
        for j, slot in self.slots:
            out[:, slot] = x[:, j]
        if self.scale is not None:
            out[:, self.stiffness] = out[:, self.stiffness] * x[:, self.scale][:, None]
        return out


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


def run_chunk(spec: dict, start: int, values: Sequence[tuple], refs=None) -> tuple:
    """Evaluates designs ``start, start + 1, ...`` with the given parameter values (``refs``:
    per design the values of its reference design or None, see :func:`design_references`) and
    returns ``(start, count, csv_text, counts)`` (with Parquet alone the chunk's Arrow stream
    instead of the text; counts: see :func:`udmap.doe.io.tally`, plus
    ``traces``, the dampers traced, and ``warnings``, the plausibility warnings per kind): the chunk's rows already formatted, so that the writer
    only appends text and the result is independent of where it was computed."""
    ctx = context_for(spec)
    traces = ctx.traces
    rows = ctx.evaluate_chunk(values, refs)
    if spec.get("rows") == "arrow":  # --format parquet: the columns as an Arrow batch
        text, counts = chunk_payload(spec, start, values, rows)
    else:
        text, counts = format_chunk(spec, start, values, rows)
    counts["traces"] = ctx.traces - traces
    counts["warnings"] = rows.warnings
    return start, rows.n, text, counts
