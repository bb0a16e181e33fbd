"""Sampling the design space: unit-cube samples (scrambled Sobol, Latin hypercube, full grid)
and the parameter values of every design."""
from __future__ import annotations

import math
import warnings
from typing import Sequence

import numpy as np

from ..errors import InputError
from .parameters import Parameter

METHODS = ("sobol", "lhs", "grid")

def unit_sample(method: str, n: int, d: int, seed: int):
    """``n`` points in the unit cube ``[0, 1)^d`` (grid: ``[0, 1]^d``) as an (n, d) array:
    scrambled Sobol or Latin hypercube from :mod:`scipy.stats.qmc` seeded with ``seed``, or a
    full factorial grid with ``n = k^d`` (last parameter fastest)."""
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
