#!/usr/bin/env python3
"""Benchmark of the design of experiments: designs per second per core for blade A with the ten
forces of the GG diagram (F_E = 1..10 N), mu and CF varied, so the damper table is traced again
for every design; F_lim, the ten peaks and the continuous F_adm of every design, streamed to CSV.

    python3 bench/bench_doe.py --json OUT [--designs N] [--repeats R]

Records (INTERFACES.md "Benchmark output", method "doe"): seconds per design (wall clock of
the whole run divided by the designs, start-up of the pool or cluster included) for the serial,
process-pool and Dask runs, with the extras designs, cores, designs_per_second_per_core. The
errors compare the rows of the first designs with the backbone of the same design computed at
the tightest tolerance (rtol 1e-14)."""
from __future__ import annotations

import argparse
import csv
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "wrappers" / "python"))
sys.path.insert(0, str(ROOT / "bench"))

from timing import record  # noqa: E402
from udmap import doe  # noqa: E402
from udmap.case import build_model, load_case  # noqa: E402

VARY = ["mu=0.2:0.6", "CF=600:1200"]
FORCES = ",".join(str(f) for f in range(1, 11))


def timed_runs(case, designs, repeats, tmp, **options):
    samples = []
    for r in range(repeats):
        out = Path(tmp) / f"doe_{options.get('dask') or options.get('workers')}_{r}.csv"
        t0 = time.perf_counter()
        summary = doe.run_doe(case, VARY, designs, out, forces=FORCES, overwrite=True,
                              progress=False, **options)
        samples.append((time.perf_counter() - t0) / designs)
        assert summary["written"] == designs
    return samples, summary, out


def accuracy(case, out, designs=8):
    """Largest relative differences of gamma_P, sigma_a, f_res against rtol = 1e-14."""
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))[:designs]
    params = doe.parse_vary(case, VARY)
    err = {"gamma_P": 0.0, "sigma_a": 0.0, "f_res": 0.0}
    forces = [float(f) for f in FORCES.split(",")]
    for row in rows:
        if row["status"] != "ok":
            continue
        c = doe.with_values(case, [p.path for p in params], [float(row[p.name]) for p in params])
        c.analysis = dict(c.analysis, rtol=1e-14)
        points = build_model(c).backbone(forces)
        for p, F in zip(points, FORCES.split(",")):
            for key in err:
                ref, got = p[key], float(row[f"{key}@{F}"])
                err[key] = max(err[key], abs(got - ref) / abs(ref))
    return err


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--json", required=True, help="output file (JSON array of records)")
    ap.add_argument("--designs", type=int, default=1024)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--no-dask", action="store_true", help="skip the Dask LocalCluster run")
    args = ap.parse_args()
    case = load_case(ROOT / "cases" / "blade_a.json")
    cores = doe.default_workers()
    configs = [("gg10_serial", 1, {"workers": 1}),
               (f"gg10_processes{cores}", cores, {"workers": cores})]
    if not args.no_dask:
        configs.append((f"gg10_dask_local{cores}", cores, {"dask": f"local:{cores}"}))
    records = []
    with tempfile.TemporaryDirectory() as tmp:
        for setting, k, options in configs:
            # the parallel runs start a pool or cluster each time: give them more designs
            n = args.designs * (1 if k == 1 else 2 * k)
            samples, summary, out = timed_runs(case, n, args.repeats, tmp, **options)
            err = accuracy(case, out)
            med = statistics.median(samples)
            rec = record("blade_a", "doe", setting,
                         {"seconds_median": med, "seconds_min": min(samples),
                          "seconds_max": max(samples), "repeats": args.repeats},
                         error_gamma_P=err["gamma_P"], error_sigma_a=err["sigma_a"],
                         error_f_res=err["f_res"], designs=n, cores=k,
                         designs_per_second_per_core=1.0 / (med * k),
                         status=summary["status"])
            records.append(rec)
            print(f"bench_doe: {setting}: {n} designs, {1 / med:.0f} designs/s, "
                  f"{1 / (med * k):.0f} designs/s/core (goal 2000)", flush=True)
    Path(args.json).write_text(json.dumps(records, indent=1, allow_nan=False) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
