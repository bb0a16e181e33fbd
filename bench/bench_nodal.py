#!/usr/bin/env python3
"""Traveling waves (PHYSICS.md 2.6) on blade A (make bench): the cost of a peak at phi != 0
against the in-phase one, the nodal-diameter sweep, and the error of the layered peaks against
the standard method at the same phase and harmonics.

Timed the same way on both sides: through the Python objects over the C API, from the damper
parameters on (a new damper and model per call, so every table is built inside the timed
call), medians of repeated runs. The in-phase gg10 carries the same Python overhead per call,
which favours the ratio to it by a few percent at most (one call per gg10).

Records (INTERFACES.md "Benchmark output"), method "nodal":
  gg10_phi0_H1          the 10 peaks F_E = 1..10 N in phase (the reference of the ratios)
  gg10_phi90_H1         the same at N = 4, EO = 1 (phi = 90 deg), H = 1; extras
                        "ratio_to_in_phase"; errors against the standard method (H = 1)
  gg10_phi90_H3         the same with H = 3; errors against the standard method (H = 3)
  sweep24x10_H1         all 24 engine orders of a 24-blade wheel at the ten forces, H = 1, on
                        nodal's threads (the CPUs), and on one (sweep24x10_H1_one_thread)
  same_equations_H<H>   the acceptance matrix of issue 19: N = 4, EO = 1, 2, 3 and N = 24,
                        EO = 1, 6, 12, 23; F_E = 1, 2, 5, 10 N; layered against the standard
                        method with the same harmonics, the largest relative differences;
                        timings are the layered method's per phase (extra "seconds_standard")
Usage: bench_nodal.py [--json FILE] [--quick]
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "wrappers" / "python"))
sys.path.insert(0, str(ROOT / "bench"))

from timing import measure, record  # noqa: E402
from udmap import hbm  # noqa: E402
from udmap.case import build_blade, build_damper, load_case  # noqa: E402
from udmap.model import Model  # noqa: E402
from udmap.nodal import ibpa_of, sweep  # noqa: E402

FORCES = [float(F) for F in range(1, 11)]


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--json", default=None)
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    case = load_case(str(ROOT / "cases" / "blade_a.json"))
    a = case.analysis
    blade = build_blade(case)

    def gg10(ibpa, harmonics=1):
        damper = build_damper(case)
        model = Model(blade, damper, a["f_min"], a["f_max"], harmonics=harmonics, ibpa_deg=ibpa)
        return model.backbone(FORCES)

    records = []
    t0 = measure(lambda: gg10(0.0), repeats=5 if args.quick else 41, warmup=2)
    records.append(record("blade_a", "nodal", "gg10_phi0_H1", t0))
    for H, reps in ((1, 3 if args.quick else 7), (3, 1 if args.quick else 3)):
        points = gg10(90.0, H)
        t = measure(lambda: gg10(90.0, H), repeats=reps, warmup=0)
        # the standard method climbs down to its own peak from 1 % above the layered one
        ref = hbm.wave_hbm(blade, build_damper(case), a["f_min"], a["f_max"], 90.0, FORCES,
                           [1.01 * p["f_res"] for p in points], harmonics=H)
        err = {k: max(abs(p[k] / r[k] - 1) for p, r in zip(points, ref))
               for k in ("gamma_P", "sigma_a", "f_res")}
        records.append(record("blade_a", "nodal", f"gg10_phi90_H{H}", t,
                              error_gamma_P=err["gamma_P"], error_sigma_a=err["sigma_a"],
                              error_f_res=err["f_res"],
                              ratio_to_in_phase=t["seconds_median"] / t0["seconds_median"]))
        print(f"bench_nodal: gg10 at phi = 90 deg, H = {H}: {t['seconds_median']:.3f} s "
              f"({t['seconds_median'] / t0['seconds_median']:.0f} x in phase); against the "
              f"standard method {err}", flush=True)
    if not args.quick:
        phases = sorted({ibpa_of(eo, n) for n, eos in ((4, (1, 2, 3)), (24, (1, 6, 12, 23)))
                         for eo in eos})
        forces = [1.0, 2.0, 5.0, 10.0]
        damper = build_damper(case)
        for H in (1, 3, 9):
            worst = {"gamma_P": 0.0, "f_res": 0.0, "sigma_a": 0.0}
            t_layer = t_std = 0.0
            for ibpa in phases:
                t1 = time.perf_counter()
                model = Model(blade, damper, a["f_min"], a["f_max"], harmonics=H, ibpa_deg=ibpa)
                points = model.backbone(forces)
                t2 = time.perf_counter()
                ref = hbm.wave_hbm(blade, damper, a["f_min"], a["f_max"], ibpa, forces,
                                   [1.01 * p["f_res"] for p in points], harmonics=H)
                t3 = time.perf_counter()
                t_layer += t2 - t1
                t_std += t3 - t2
                for k in worst:
                    worst[k] = max([worst[k]] + [abs(p[k] / r[k] - 1)
                                                 for p, r in zip(points, ref)])
            n = len(phases)
            records.append(record("blade_a", "nodal", f"same_equations_H{H}",
                                  {"seconds_median": t_layer / n, "seconds_min": t_layer / n,
                                   "seconds_max": t_layer / n, "repeats": 1},
                                  error_gamma_P=worst["gamma_P"], error_sigma_a=worst["sigma_a"],
                                  error_f_res=worst["f_res"], seconds_standard=t_std / n,
                                  phases_deg=phases))
            print(f"bench_nodal: layered = standard, H = {H}, {n} phases x 4 forces: largest "
                  f"differences {worst}; per phase {t_layer / n:.2f} s layered, "
                  f"{t_std / n:.2f} s standard", flush=True)
        damper = build_damper(case)
        for workers, name in ((None, "sweep24x10_H1"), (1, "sweep24x10_H1_one_thread")):
            t = measure(lambda: sweep(blade, damper, a | {"harmonics": 1}, 24, FORCES,
                                      workers=workers), repeats=5, warmup=1)
            records.append(record("blade_a", "nodal", name, t))
            print(f"bench_nodal: 24 engine orders x 10 forces, H = 1, "
                  f"{'one thread' if workers else 'nodal threads'}: "
                  f"{t['seconds_median']:.3f} s median of 5", flush=True)
    text = json.dumps(records, indent=1, allow_nan=False) + "\n"
    if args.json:
        Path(args.json).write_text(text)
    else:
        print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
