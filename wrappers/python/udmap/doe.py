"""Design of experiments: ``python3 -m udmap doe`` (INTERFACES.md "Design of experiments output").

A design is the case with some blade, damper or analysis parameters changed. The designs are
sampled with :mod:`scipy.stats.qmc` (Sobol, Latin hypercube) or on a full grid, evaluated in
chunks by a serial, process-pool, thread-pool or Dask executor, and streamed in design order to a
CSV file (plus Parquet when pyarrow is installed). A worker reuses what the varied parameters
leave unchanged (the blade, the model's bare-blade data, a damper whose CF alone varies; see
:class:`DesignContext`), and every design goes through the same kernel calls on the same state
whichever worker computes it and whatever it computed before, so serial, pooled and Dask runs
give the same file byte for byte for the same seed.

Parameter names (``--vary NAME=LO:HI``): a dotted path into the case (``damper.mu``,
``blade.airfoil.h``, ``airfoil.h`` when the section is unambiguous, ``damper.flat_points[0][1]``)
or a flat FMU name (``mu``, ``CF``, ``kt_flat``, ``beta_L_deg``, ``neck_L``, ``platform_m``,
``airfoil_elements``, ``E``, ``flat1_x``, ``curved_y``, ``f_min``, ``sigma_all``, ...). Integer
parameters (element counts) are rounded, ``airfoil.elements`` to an even number.
``NAME=LO:HI:log`` samples ``ln(value)`` uniformly (stiffnesses spanning decades).
"""
from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import re
import sys
import time
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

import numpy as np

from ._lib import InputError, PhysicsError, UdmapError
from .case import Case, load_case, validate

SECTIONS = ("blade", "damper", "analysis")
METHODS = ("sobol", "lhs", "grid")
#: Per-design status values of the ``status`` column.
STATUS_OK, STATUS_INPUT, STATUS_PHYSICS, STATUS_NUMERIC, STATUS_ERROR = (
    "ok", "input", "physics", "numeric", "error")
# Numeric leaves that are identifiers or data, not design parameters.
_NOT_PARAMETERS = {("blade", "gamma_dof"), ("blade", "exc_dof")}


# ------------------------------------------------------------------------------- parameters

@dataclass(frozen=True)
class Parameter:
    """One varied parameter: ``name`` as the user wrote it (the output column), ``path`` into
    the case dictionaries, ``lo``/``hi`` bounds, ``scale`` 'linear' or 'log', and ``integer``
    0 (real), 1 (integer) or 2 (even integer)."""
    name: str
    path: tuple
    lo: float
    hi: float
    scale: str = "linear"
    integer: int = 0

    @property
    def dotted(self) -> str:
        """The path as text, e.g. ``damper.flat_points[0][1]``."""
        out = self.path[0]
        for key in self.path[1:]:
            out += f"[{key}]" if isinstance(key, int) else f".{key}"
        return out

    def cast(self, x: float):
        """The value a design uses for the sample ``x`` (rounded for integer parameters)."""
        if self.integer == 2:
            return 2 * int(round(x / 2.0))
        if self.integer == 1:
            return int(round(x))
        return float(x)


def _leaves(node, path=()):
    """Yields (path, value) for every numeric leaf of a case section."""
    if isinstance(node, dict):
        for key, value in node.items():
            if key in ("kind", "rows", "file", "name"):
                continue
            yield from _leaves(value, path + (key,))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            yield from _leaves(value, path + (i,))
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        if path not in _NOT_PARAMETERS:
            yield path, node


def parameter_names(case: Case) -> dict[str, tuple]:
    """Every name a parameter of ``case`` can be varied by, mapped to its path: the dotted paths
    (``damper.flat_points.0.1`` spelled ``damper.flat_points[0][1]``) and the FMU names."""
    names: dict[str, tuple] = {}
    sections = {"blade": case.blade, "damper": case.damper, "analysis": case.analysis}
    for section, data in sections.items():
        for path, _ in _leaves(data, (section,)):
            names[Parameter("", path, 0, 0).dotted] = path
    # FMU names (INTERFACES.md "FMU"): underscores for the beam parts, flatN_x/curved_y for the
    # damper contact points, the other scalars of every section by their own names.
    for section, data in sections.items():
        for key, value in data.items():
            if isinstance(value, dict):
                for sub, v in value.items():
                    if isinstance(v, (int, float)) and not isinstance(v, bool):
                        names.setdefault(f"{key}_{sub}", (section, key, sub))
            elif isinstance(value, (int, float)) and not isinstance(value, bool):
                if (section, key) not in _NOT_PARAMETERS:
                    names.setdefault(key, (section, key))
    if "flat_points" in case.damper:
        for i in range(len(case.damper["flat_points"])):
            for j, axis in enumerate("xy"):
                names[f"flat{i + 1}_{axis}"] = ("damper", "flat_points", i, j)
    if "curved_point" in case.damper:
        for j, axis in enumerate("xy"):
            names[f"curved_{axis}"] = ("damper", "curved_point", j)
    return names


def resolve_name(case: Case, name: str) -> tuple:
    """The path of parameter ``name`` in ``case``; InputError listing the known names if none."""
    names = parameter_names(case)
    if name in names:
        return names[name]
    # Dotted spellings: damper.flat_points.0.1, flat_points[0][1], airfoil.h (section implied).
    norm = re.sub(r"\[(\d+)\]", r".\1", name)
    tokens = tuple(int(t) if t.isdigit() else t for t in norm.split(".") if t != "")
    candidates = [tokens] if tokens and tokens[0] in SECTIONS else [
        (s,) + tokens for s in SECTIONS]
    found = [p for p in candidates if p in names.values()]
    if len(found) == 1:
        return found[0]
    if len(found) > 1:
        raise InputError(f"--vary {name}: ambiguous, say which section: "
                         + ", ".join(Parameter("", p, 0, 0).dotted for p in found))
    flat = sorted(n for n in names if "." not in n and "[" not in n)
    raise InputError(f"--vary {name}: not a parameter of this case (names: {', '.join(flat)}; "
                     "or a dotted path such as damper.mu or blade.airfoil.h)")


def _get(case_dicts: dict, path: tuple):
    node = case_dicts[path[0]]
    for key in path[1:]:
        node = node[key]
    return node


def _set_copied(root: dict, path: tuple, value) -> dict:
    """A copy of ``root`` with the leaf at ``path`` set; only the containers on the path are
    copied (the rest is shared, never modified)."""
    top = dict(root)
    node = top
    for key in path[:-1]:
        child = node[key]
        child = dict(child) if isinstance(child, dict) else list(child)
        node[key] = child
        node = child
    node[path[-1]] = value
    return top


def _case_dicts(case: Case) -> dict:
    return {"blade": case.blade, "damper": case.damper, "analysis": case.analysis}


def with_values(case: Case, paths: Sequence[tuple], values: Sequence) -> Case:
    """``case`` with the parameters at ``paths`` set to ``values`` (no validation, no deep copy:
    the untouched parts are shared with ``case``)."""
    sections = _case_dicts(case)
    for path, value in zip(paths, values):
        sections[path[0]] = _set_copied(sections[path[0]], path[1:], value)
    return Case(blade=sections["blade"], damper=sections["damper"],
                analysis=sections["analysis"], name=case.name, base_dir=case.base_dir)


def _validation_dict(case: Case) -> dict:
    """The case as the input dictionary :func:`validate` accepts."""
    data = case.to_dict()
    if data["damper"].get("kind") == "table":
        data["damper"].pop("rows", None)
    return data


def parse_vary(case: Case, specs: Sequence) -> list[Parameter]:
    """Parses ``NAME=LO:HI[:log]`` items (strings with commas allowed, or (name, lo, hi) tuples)
    into parameters, validating the case at both ends of every range: a bad name, range or value
    raises InputError naming it."""
    items = []
    for spec in specs:
        if isinstance(spec, str):
            items.extend(s.strip() for s in spec.split(",") if s.strip())
        else:
            items.append(tuple(spec))
    if not items:
        raise InputError("--vary: at least one NAME=LO:HI is needed")
    params: list[Parameter] = []
    for item in items:
        if isinstance(item, tuple):
            name, lo, hi, *rest = item
            scale = rest[0] if rest else "linear"
            text = f"{name}={lo}:{hi}"
        else:
            text = item
            name, sep, rng = item.partition("=")
            parts = rng.split(":")
            if not sep or not name.strip() or len(parts) not in (2, 3):
                raise InputError(f"--vary {item}: expected NAME=LO:HI or NAME=LO:HI:log")
            name = name.strip()
            scale = parts[2].strip() if len(parts) == 3 else "linear"
            try:
                lo, hi = float(parts[0]), float(parts[1])
            except ValueError:
                raise InputError(f"--vary {item}: LO and HI must be numbers") from None
        try:
            lo, hi = float(lo), float(hi)
        except (TypeError, ValueError):
            raise InputError(f"--vary {text}: LO and HI must be numbers") from None
        if scale not in ("linear", "log"):
            raise InputError(f"--vary {text}: the scale must be 'log' or omitted, got {scale!r}")
        if not (math.isfinite(lo) and math.isfinite(hi)):
            raise InputError(f"--vary {text}: LO and HI must be finite")
        if not lo < hi:
            raise InputError(f"--vary {text}: LO must be below HI")
        if scale == "log" and not lo > 0:
            raise InputError(f"--vary {text}: a log range needs LO > 0")
        path = resolve_name(case, name)
        current = _get(_case_dicts(case), path)
        integer = 0
        if isinstance(current, int):
            integer = 2 if path == ("blade", "airfoil", "elements") else 1
        p = Parameter(name=name, path=path, lo=lo, hi=hi, scale=scale, integer=integer)
        for other in params:
            if other.path == p.path:
                raise InputError(f"--vary {name}: the same parameter as {other.name} "
                                 f"({p.dotted})")
        # Every check of a single value is an interval, so both ends valid means all valid.
        for end in (lo, hi):
            try:
                validate(_validation_dict(with_values(case, [path], [p.cast(end)])),
                         case.base_dir)
            except InputError as exc:
                raise InputError(f"--vary {text}: {exc}") from None
        params.append(p)
    return params


# ------------------------------------------------------------------------------- sampling

def unit_sample(method: str, n: int, d: int, seed: int):
    """``n`` points in the unit cube ``[0, 1)^d`` (grid: ``[0, 1]^d``) as an (n, d) array:
    scrambled Sobol or Latin hypercube from :mod:`scipy.stats.qmc` seeded with ``seed``, or a
    full factorial grid with ``n = k^d`` (last parameter fastest)."""
    import numpy as np
    if method == "grid":
        k = int(round(n ** (1.0 / d)))
        if k ** d != n:
            lo = max(int(math.floor(n ** (1.0 / d))), 1)
            raise InputError(f"--samples {n}: a grid over {d} parameters needs k^{d} designs "
                             f"(e.g. {lo ** d} or {(lo + 1) ** d})")
        levels = np.linspace(0.0, 1.0, k) if k > 1 else np.array([0.5])
        mesh = np.meshgrid(*([levels] * d), indexing="ij")
        return np.stack([m.ravel() for m in mesh], axis=1)
    from scipy.stats import qmc
    cls = {"sobol": qmc.Sobol, "lhs": qmc.LatinHypercube}.get(method)
    if cls is None:
        raise InputError(f"--method must be one of {', '.join(METHODS)}, got {method!r}")
    try:
        engine = cls(d, rng=seed)
    except TypeError:  # SciPy < 1.15 spells the seed 'seed'
        engine = cls(d, seed=seed)
    with warnings.catch_warnings():
        # Sobol balance wants n = 2^m; any n is still a valid (prefix of a) Sobol sequence.
        warnings.simplefilter("ignore", UserWarning)
        return engine.random(n)


class DesignValues:
    """The parameter values of every design, computed once from the unit-cube samples as one
    float array (8 bytes per value, so millions of designs fit) and handed out as tuples (rounded
    where the parameter is an integer): ``values[i]``, ``values[a:b]`` (a list), ``len``,
    iteration."""

    def __init__(self, params: Sequence[Parameter], unit):
        unit = np.asarray(unit, dtype=float)
        self.x = np.empty_like(unit)
        for j, p in enumerate(params):
            u = unit[:, j]
            if p.scale == "log":
                x = np.exp(math.log(p.lo) + u * (math.log(p.hi) - math.log(p.lo)))
            else:
                x = p.lo + u * (p.hi - p.lo)
            self.x[:, j] = np.clip(x, p.lo, p.hi)
        self._casts = [p.cast if p.integer else None for p in params]

    def _rows(self, block) -> list[tuple]:
        rows = block.tolist()
        if any(self._casts):
            casts = [c or float for c in self._casts]
            rows = [[c(v) for c, v in zip(casts, r)] for r in rows]
        return [tuple(r) for r in rows]

    def __len__(self) -> int:
        return self.x.shape[0]

    def __getitem__(self, i):
        if isinstance(i, slice):
            return self._rows(self.x[i])
        return self._rows(self.x[i:i + 1] if i >= 0 else self.x[i:len(self) + i + 1])[0]

    def __iter__(self):
        for start in range(0, len(self), 4096):
            yield from self[start:start + 4096]


def design_values(params: Sequence[Parameter], unit) -> DesignValues:
    """The parameter values of every design from unit-cube samples (rounded where integer)."""
    return DesignValues(params, unit)


# ------------------------------------------------------------------------------- one design

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
            self._asym = _AsymmetricBuilder(self.case.damper, self.paths)
        self._cache: dict = {}
        self._points = _PointBuffer(max(len(self.forces), 1))

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
        from .case import build_blade
        if self.blade_varies:
            return build_blade(case)
        return self._shared("blade", lambda: build_blade(self.case))

    def _damper(self, case: Case, values):
        from .case import build_damper
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
        from .case import build_model
        if self.blade_varies or self.analysis_varies:
            return build_model(case, blade, damper)

        def primed():
            from .damper import Damper
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
        """One design: a dict with the fields of a row (see :func:`udmap.doe_io.row_cells`)."""
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
            info = damper._info()
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


class _AsymmetricBuilder:
    """Builds the asymmetric damper of a design from the nominal C parameter block with the
    varied entries replaced (what :func:`udmap.case.build_damper` passes to the kernel, without
    the case dictionaries in between); one error handle serves all its dampers."""

    def __init__(self, damper: dict, paths):
        from ._lib import ErrorHandle
        from .damper import _AsymmetricParams
        (f1x, f1y), (f2x, f2y) = damper["flat_points"]
        fields = {"flat1_x": f1x, "flat1_y": f1y, "flat2_x": f2x, "flat2_y": f2y,
                  "curved_x": damper["curved_point"][0], "curved_y": damper["curved_point"][1]}
        names = [name for name, _ in _AsymmetricParams._fields_]
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
        self.err = ErrorHandle()

    def build(self, values):
        import ctypes
        from .damper import Damper, _AsymmetricParams, _new_asym
        block = list(self.base)
        for slot, value in zip(self.slots, values):
            block[slot] = float(value)
        params = _AsymmetricParams(*block)
        ptr = ctypes.c_void_p()
        self.err.check(_new_asym(self.err.ptr, ctypes.byref(params), ctypes.byref(ptr)))
        return Damper(ptr, self.err, "asymmetric")


class _PointBuffer:
    """Reusable arrays of kernel backbone points (``udmap_point``) seen as numpy record arrays,
    so that a design's backbone costs one C call and no Python object per point."""

    def __init__(self, size: int):
        import ctypes
        from .model import _Point, c_double_p
        self._size = size
        self._buf = (_Point * size)()
        self._view = np.ctypeslib.as_array(self._buf)
        self._forces = np.zeros(size)
        self._forces_ptr = self._forces.ctypes.data_as(c_double_p)
        self._jumps = (ctypes.c_int * size)()

    def backbone(self, model, forces):
        """The points of ``model`` for ``forces`` (a view valid until the next call)."""
        from .model import _backbone
        n = len(forces)
        if n > self._size:
            self.__init__(n)
        self._forces[:n] = forces
        status = _backbone(model._err.ptr, model._ptr, n, self._forces_ptr, self._buf)
        if status:
            model._err.check(status)
        return self._view[:n]

    def jumps(self, model, n: int) -> list[bool]:
        """Per point of the last :meth:`backbone` call: gamma_P at a jump of k."""
        from .model import _backbone_jumps
        status = _backbone_jumps(model._err.ptr, model._ptr, n, self._jumps)
        if status:
            model._err.check(status)
        return [f != 0 for f in self._jumps[:n]]


_CONTEXTS: dict = {}


def context_for(spec: dict) -> DesignContext:
    """The worker's context for a run (one per run token, process and thread: a forked worker
    does not inherit its parent's)."""
    import threading
    key = (spec["token"], os.getpid(), threading.get_ident())
    ctx = _CONTEXTS.get(key)
    if ctx is None:
        if len(_CONTEXTS) > 64:
            _CONTEXTS.clear()
        ctx = _CONTEXTS[key] = DesignContext(spec)
    return ctx


def run_chunk(spec: dict, start: int, values: Sequence[tuple]) -> tuple:
    """Evaluates designs ``start, start + 1, ...`` with the given parameter values and returns
    ``(start, count, csv_text, counts)`` (counts: see :func:`udmap.doe_io.tally`): the chunk's
    rows already formatted, so that the writer only appends text and the result is independent
    of where it was computed."""
    from .doe_io import format_rows
    ctx = context_for(spec)
    rows = [ctx.evaluate(v) for v in values]
    text, counts = format_rows(spec, start, values, rows)
    return start, len(rows), text, counts


# ------------------------------------------------------------------------------- a whole run

def parse_forces(text) -> tuple[list[float], list[str]]:
    """``'1,2.5'`` (or a list of numbers) into forces and their column labels as written."""
    if text is None:
        return [], []
    items = [s.strip() for s in text.split(",")] if isinstance(text, str) else list(text)
    forces, labels = [], []
    for item in items:
        if item == "":
            continue
        try:
            f = float(item)
        except (TypeError, ValueError):
            raise InputError(f"--forces: expected comma-separated numbers, got {item!r}") from None
        if not (math.isfinite(f) and f > 0):
            raise InputError(f"--forces: forces must be positive finite numbers, got {item}")
        label = item if isinstance(item, str) else repr(float(item)).removesuffix(".0")
        if label in labels:
            raise InputError(f"--forces: {label} is given twice")
        forces.append(f)
        labels.append(label)
    if not forces:
        raise InputError("--forces: expected at least one number")
    return forces, labels


def make_spec(case: Case, params: Sequence[Parameter], forces: Sequence[float],
              labels: Sequence[str], samples: int, method: str, seed: int) -> dict:
    """The run description: everything a worker needs (plain data, picklable) plus what a
    resumed run must match; ``token`` identifies it."""
    spec = {
        "name": case.name, "base_dir": str(case.base_dir),
        "blade": case.blade, "damper": case.damper, "analysis": case.analysis,
        "params": [{"name": p.name, "path": p.dotted, "lo": p.lo, "hi": p.hi, "scale": p.scale,
                    "integer": p.integer} for p in params],
        "paths": [list(p.path) for p in params],
        "forces": list(forces), "labels": list(labels),
        "samples": int(samples), "method": method, "seed": int(seed),
    }
    text = json.dumps(spec, sort_keys=True, default=str)
    spec["token"] = hashlib.sha256(text.encode()).hexdigest()[:16]
    return spec


def default_workers() -> int:
    """The cores this process may run on."""
    try:
        return max(len(os.sched_getaffinity(0)), 1)
    except AttributeError:
        return max(os.cpu_count() or 1, 1)


def run_doe(case, vary, samples: int, out, *, method: str = "sobol", forces=None,
            seed: int = 0, workers: int | None = None, threads: bool = False,
            dask: str | None = None, chunk: int | None = None, resume: bool = False,
            overwrite: bool = False, progress: bool = True, plot: bool = False,
            stream=None) -> dict:
    """Runs a design of experiments and returns a summary dict.

    ``case``: a :class:`~udmap.case.Case`, a path or None (the embedded blade A); ``vary``:
    ``NAME=LO:HI[:log]`` strings or (name, lo, hi) tuples; ``forces``: '1,2' or numbers (the
    per-force columns); ``workers``: processes (default all cores; 1 runs in this process),
    ``threads=True`` for threads instead; ``dask``: 'local:K' or 'tcp://HOST:PORT';
    ``chunk``: designs per task and per write; ``resume``: continue ``out``.
    """
    from . import doe_exec, doe_io
    from .progress import Progress
    if not isinstance(case, Case):
        case = load_case(case)
    if isinstance(samples, bool) or not isinstance(samples, int) or samples < 1:
        raise InputError(f"--samples must be a positive integer, got {samples!r}")
    if method not in METHODS:
        raise InputError(f"--method must be one of {', '.join(METHODS)}, got {method!r}")
    params = parse_vary(case, vary)
    force_values, labels = parse_forces(forces) if forces not in (None, "", []) else ([], [])
    values = design_values(params, unit_sample(method, samples, len(params), seed))
    spec = make_spec(case, params, force_values, labels, samples, method, seed)
    executor = doe_exec.make_executor(workers=workers, threads=threads, dask=dask)
    if chunk is None:
        chunk = doe_exec.default_chunk(samples, executor.workers)
    if chunk < 1:
        raise InputError(f"--chunk must be at least 1, got {chunk}")
    output = doe_io.Output(out, spec, values)
    first = output.open(resume=resume, overwrite=overwrite)  # InputError before any work
    t0 = time.perf_counter()
    counts = dict(output.counts)
    bounds = doe_exec.chunk_ranges(first, samples, output.held, chunk)
    todo = sum(e - s for s, e in bounds)
    ranges = ((s, values[s:e]) for s, e in bounds)  # the values of a chunk when it is sent
    computed = 0
    interrupted = False
    try:
        if todo > 0:
            label = "doe" if first == 0 else f"doe (resumed at {first})"
            with Progress(todo, label, stream=stream) as bar:
                bar.enabled = bar.enabled and progress
                with executor:
                    for start, n, text, chunk_counts in executor.run(spec, ranges):
                        output.put(start, n, text)
                        computed += n
                        for k, v in chunk_counts.items():
                            counts[k] = counts.get(k, 0) + v
                        bar.update(n)
    except KeyboardInterrupt:
        interrupted = True
    finally:
        output.close()
    seconds = time.perf_counter() - t0
    summary = {"out": str(output.path), "designs": samples, "written": output.written,
               "computed": computed, "resumed_at": first,
               "recovered": sum(n for _, n in output.held),
               "status": doe_io.split_counts(counts)[0], "seconds": seconds,
               "designs_per_second": computed / seconds if seconds > 0 and computed else None,
               "workers": executor.workers, "executor": executor.kind,
               "startup_seconds": executor.startup_seconds, "interrupted": interrupted}
    if interrupted:
        return summary
    summary["parquet"] = output.finish()
    summary.update(doe_io.pass_shares(counts, samples, labels))
    if plot:
        from .doe_plot import plot_doe
        summary["plots"] = [str(p) for p in plot_doe(output.path, [p.name for p in params],
                                                     labels, [p.path for p in params])]
    return summary


# ------------------------------------------------------------------------------- command line

def add_doe_parser(sub) -> argparse.ArgumentParser:
    """Adds the ``doe`` subcommand to the CLI's subparsers."""
    h = ("design of experiments: sample damper, blade and analysis parameters, compute F_lim, "
         "the resonances and the admissible force of every design")
    p = sub.add_parser("doe", help=h, description=h + ". " + __doc__.split("\n\n")[-1],
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("case", metavar="CASE", help="case file (JSON)")
    p.add_argument("--vary", action="append", required=True, metavar="NAME=LO:HI[,...]",
                   help="parameters and ranges, comma-separated or repeated; NAME=LO:HI:log "
                        "for a logarithmic scale")
    p.add_argument("--samples", type=int, required=True, metavar="N",
                   help="number of designs (grid: k^d)")
    p.add_argument("--method", choices=METHODS, default="sobol",
                   help="scrambled Sobol (default), Latin hypercube, or full grid")
    p.add_argument("--forces", default=None, metavar="F1,...",
                   help="forces F_E [N] with per-force columns gamma_P@F, f_res@F, sigma_a@F, "
                        "hcf_ok@F, jump@F")
    p.add_argument("--seed", type=int, default=0, help="sampling seed (default 0)")
    p.add_argument("--harmonics", default=None, metavar="H|auto",
                   help="harmonics of the platform rotation: 1 (single-harmonic), H (harmonics "
                        "0..H in multi-harmonic layers) or auto; overrides analysis.harmonics "
                        "(with H > 1 hcf_ok and F_adm take sigma_max)")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--workers", type=int, default=None, metavar="K",
                   help="worker processes (default: all cores; 1 runs serially)")
    g.add_argument("--threads", type=int, default=None, metavar="K",
                   help="worker threads instead of processes (the kernel releases the GIL)")
    g.add_argument("--dask", default=None, metavar="local:K|tcp://HOST:PORT",
                   help="run on Dask distributed: a local cluster of K worker processes or "
                        "the scheduler at an address")
    p.add_argument("--chunk", type=int, default=None, metavar="C",
                   help="designs per task and per write (default: from N and the workers)")
    p.add_argument("--out", required=True, metavar="FILE",
                   help="output CSV (a Parquet copy FILE.parquet when pyarrow is installed; "
                        "FILE.meta.json describes the run for --resume)")
    p.add_argument("--resume", action="store_true",
                   help="continue an interrupted run in FILE")
    p.add_argument("--force", action="store_true", help="overwrite an existing FILE")
    p.add_argument("--plot", action="store_true",
                   help="write design-space plots next to FILE (PNG)")
    p.add_argument("--json", action="store_true", help="print the run summary as JSON")
    p.set_defaults(func=cmd_doe)
    return p


def cmd_doe(args) -> None:
    """The ``doe`` subcommand."""
    if args.samples < 1:
        raise InputError(f"--samples must be at least 1, got {args.samples}")
    for opt in ("workers", "threads", "chunk"):
        v = getattr(args, opt)
        if v is not None and v < 1:
            raise InputError(f"--{opt} must be at least 1, got {v}")
    case = load_case(args.case)
    if args.harmonics is not None:
        from .cli import _harmonics
        try:
            case.analysis["harmonics"] = _harmonics(args.harmonics)
        except argparse.ArgumentTypeError as exc:
            raise InputError(f"--harmonics: {exc}") from None
    summary = run_doe(
        case, args.vary, args.samples, args.out, method=args.method,
        forces=args.forces, seed=args.seed,
        workers=args.threads if args.threads is not None else args.workers,
        threads=args.threads is not None, dask=args.dask, chunk=args.chunk,
        resume=args.resume, overwrite=args.force, plot=args.plot)
    if summary["interrupted"]:
        print(f"udmap: interrupted: {summary['written']} of {summary['designs']} designs are in "
              f"{summary['out']} (finished chunks waiting for an earlier one in "
              f"{summary['out']}.pending); run again with --resume to continue", file=sys.stderr)
        raise SystemExit(130)
    if args.json:
        json.dump(summary, sys.stdout, indent=2, allow_nan=False)
        sys.stdout.write("\n")
        return
    rate = summary["designs_per_second"]
    recovered = f", {summary['recovered']} recovered" if summary["recovered"] else ""
    print(f"{summary['designs']} designs in {summary['out']} "
          f"({summary['computed']} computed{recovered} in {summary['seconds']:.2f} s"
          + (f", {rate:.0f} designs/s, {summary['workers']} {summary['executor']} worker"
             + ("s" if summary["workers"] > 1 else "") if rate else "") + ")")
    print("status: " + ", ".join(f"{k} {v}" for k, v in sorted(summary["status"].items())))
    for label, share in summary.get("hcf_share", {}).items():
        print(f"hcf_ok at F_E = {label} N: {100 * share:.1f} % of the designs")
    if summary.get("parquet"):
        print(f"parquet: {summary['parquet']}")
    for path in summary.get("plots", []):
        print(f"plot: {path}")
