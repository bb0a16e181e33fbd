"""The nodal-diameter sweep (PHYSICS.md 2.6): every engine order 0..N-1 of a wheel of N
blades drives a traveling wave with the interblade phase phi = 2 pi EO/N; the damper between two
blades feels their phase, so each engine order has its own peaks. For each force the worst
engine order (the largest stress) is marked: a damper is signed off on it, not on the in-phase
family. Used by ``udmap nodal`` and the demo."""
from __future__ import annotations

import os
import threading
from concurrent.futures import ThreadPoolExecutor

from .model import Model


def ibpa_of(engine_order: int, blades: int) -> float:
    """The interblade phase angle [deg] of engine order EO on N blades, in (-180, 180]:
    EO above N/2 is the backward wave of N - EO."""
    eo = engine_order % blades
    deg = 360.0 * eo / blades
    return deg - 360.0 if deg > 180.0 else deg


def nodal_diameter(engine_order: int, blades: int) -> int:
    eo = engine_order % blades
    return min(eo, blades - eo)


def _engine_order(model: Model, blades: int, forces, eo: int) -> list[dict]:
    """The points of one engine order, on a model of the wheel's blade and damper."""
    ibpa = ibpa_of(eo, blades)
    model.set_ibpa(ibpa)
    F_lim = model.limit_force()
    out = []
    for p in model.backbone(forces):
        unbounded = bool(p.get("unbounded"))
        out.append({
            "engine_order": eo, "ibpa_deg": ibpa, "nodal_diameter": nodal_diameter(eo, blades),
            "F_E": p["F_E"], "gamma_P": None if unbounded else p["gamma_P"],
            "f_res": None if unbounded else p["f_res"],
            "sigma_a": None if unbounded else p["sigma_a"],
            "sigma_max": None if unbounded else p.get("sigma_max", p["sigma_a"]),
            "F_lim": F_lim, "hcf_ok": bool(p["hcf_ok"]), "unbounded": unbounded,
            "harmonics": p.get("harmonics", 1)})
    return out


def sweep(blade, damper, analysis: dict, blades: int, forces, progress=None,
          workers: int | None = None) -> dict:
    """The sweep's points (one per engine order and force, engine order first) and the worst
    engine order of each force. The engine orders run on ``workers`` threads (default: the
    CPUs): the kernel keeps no global state and releases Python's lock in its calls, and the
    blade and damper are only read. Each thread has one model, moved from engine order to
    engine order (set_ibpa): the bare-blade data and the in-phase backbone table that starts
    every traveling peak are built once a thread, not once an engine order."""
    workers = max(1, min(workers or os.cpu_count() or 1, blades))
    local = threading.local()

    def task(eo: int) -> list[dict]:
        if not hasattr(local, "model"):
            local.model = Model(blade, damper, analysis["f_min"], analysis["f_max"],
                                sigma_all=analysis["sigma_all"], rtol=analysis["rtol"],
                                grid_per_decade=analysis["grid_per_decade"],
                                harmonics=analysis["harmonics"],
                                harmonic_tol=analysis["harmonic_tol"])
        return _engine_order(local.model, blades, forces, eo)

    with ThreadPoolExecutor(max_workers=workers) as pool:
        futures = [pool.submit(task, eo) for eo in range(blades)]
        points = []
        for future in futures:  # in engine-order order, whatever finishes first
            points += future.result()
            if progress is not None:
                progress(1)
    worst = []
    for F in forces:
        rows = [p for p in points if p["F_E"] == F]
        # an unbounded answer is the worst there is; else the largest stress excursion
        key = (lambda p: (p["unbounded"], p["sigma_max"] or 0.0))
        w = max(rows, key=key)
        worst.append({"F_E": F, "engine_order": w["engine_order"],
                      "nodal_diameter": w["nodal_diameter"], "ibpa_deg": w["ibpa_deg"],
                      "sigma_max": w["sigma_max"]})
        w_eo = w["engine_order"]
        for p in rows:
            p["worst"] = p["engine_order"] == w_eo
    return {"blades": blades, "points": points, "worst": worst}
