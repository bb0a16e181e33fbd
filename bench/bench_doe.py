#!/usr/bin/env python3
"""Benchmark of the design of experiments: designs per second per core for blade A with the ten
forces of the GG diagram (F_E = 1..10 N), mu and CF varied, so the damper table is traced again
for every design; F_lim, the ten peaks and the continuous F_adm of every design, streamed to CSV
(and Parquet when pyarrow is installed), timed as whole runs of ``udmap.doe.run_doe`` (one
kernel call per chunk of designs, udmap_model_designs).

    python3 bench/bench_doe.py --json OUT [--designs N] [--repeats R] [--no-dask]

Two design spaces:
  gg10          mu 0.15..0.35, CF 600..1200 N: around blade A's damper, no contact lifts off
  gg10_liftoff  mu 0.2..0.6, CF 600..1200 N: above mu ~ 0.35 a contact lifts off and the
                kernel's damper tracing alone costs 1-2 ms per design
each serially (``_serial``), on all cores (``_processes<K>``) and, for gg10, on a Dask
LocalCluster (``_dask_local<K>``); and serially
  gg10_F_adm    the gg10 space with ``--outputs F_adm`` (no peaks at the ten forces, no F_lim
                columns: only the stages F_adm needs)
  gg10_scaled   mu fixed, CF 600..1200 N and stiffness_scale 0.5..2: designs that differ only
                in CF and a common factor of the contact stiffnesses share one tracing
                (PHYSICS.md 2.3), so the run traces once.
Records (INTERFACES.md "Benchmark output", method "doe"):
seconds per design = wall clock of the run / designs (pool or cluster start-up included), with
extras designs, cores, designs_per_second_per_core, designs_per_cpu_second (designs over the
CPU time of this process and its finished children: the per-core rate that other load on a
shared machine does not distort; the Dask scheduler's and workers' housekeeping included),
and a large run (``gg10_1e6_processes<K>``, --million designs, default 10^6, once, on all
cores, Parquet alone) with its wall_seconds (goal: under 120 s on two workers),
startup_seconds (the Dask cluster's start), designs_per_second_per_core_after_startup, traces
(dampers traced by the first run) and outputs (the --outputs of the run, null: all), and,
for the serial runs, the split of a
design's time into the kernel's C calls and the Python around them (kernel_seconds,
python_seconds, measured in a separate run that times every C call). The errors compare the
first designs' rows with the backbone of the same design at the tightest tolerance
(rtol 1e-14). Goal (issue 22): 8000 designs per second per core.
"""
from __future__ import annotations

import argparse
import csv
import json
import resource
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
from udmap import _capi  # noqa: E402
from udmap.case import build_model, load_case  # noqa: E402

SPACES = {"gg10": ["mu=0.15:0.35", "CF=600:1200"],
          "gg10_liftoff": ["mu=0.2:0.6", "CF=600:1200"],
          "gg10_F_adm": ["mu=0.15:0.35", "CF=600:1200"],
          "gg10_scaled": ["CF=600:1200", "stiffness_scale=0.5:2"]}
#: --outputs per design space (default: all)
OUTPUTS = {"gg10_F_adm": "F_adm"}
FORCES = ",".join(str(f) for f in range(1, 11))
GOAL = 8000.0
# The C entry points a design calls (ctypes function objects, looked up by the doe module at
# call time), timed for the kernel/Python split.
_KERNEL_CALLS = [(_capi, "new_damper_asymmetric"), (_capi, "damper_get_info"),
                 (_capi, "delete_damper"), (_capi, "damper_set_CF"), (_capi, "model_backbone"),
                 (_capi, "model_limit_force"), (_capi, "model_set_damper"),
                 (_capi, "new_model"), (_capi, "delete_model"), (_capi, "model_designs"),
                 (_capi, "model_designs_warnings")]


def _cpu_seconds() -> float:
    """CPU time of this process and of its finished children (pool workers, and the Dask
    nannies with the workers they waited for)."""
    total = 0.0
    for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN):
        r = resource.getrusage(who)
        total += r.ru_utime + r.ru_stime
    return total


def run(case, vary, designs, out, **options):
    """Seconds per design (wall clock) and the summary; the summary gets cpu_seconds too."""
    c0, t0 = _cpu_seconds(), time.perf_counter()
    forces = None if options.get("outputs") == "F_adm" else FORCES
    summary = doe.run_doe(case, vary, designs, out, forces=forces, overwrite=True,
                          progress=False, **options)
    seconds = time.perf_counter() - t0
    summary["cpu_seconds"] = _cpu_seconds() - c0
    assert summary["written"] == designs, summary
    return seconds / designs, summary


def kernel_split(case, vary, designs, out, **options):
    """(seconds per design in the kernel's C calls, in total) for a serial run."""
    spent = [0.0]
    saved = []
    for mod, name in _KERNEL_CALLS:
        fn = getattr(mod, name)
        saved.append((mod, name, fn))

        def timed(*args, _fn=fn):
            t0 = time.perf_counter()
            try:
                return _fn(*args)
            finally:
                spent[0] += time.perf_counter() - t0
        setattr(mod, name, timed)
    try:
        total, _ = run(case, vary, designs, out, workers=1, **options)
    finally:
        for mod, name, fn in saved:
            setattr(mod, name, fn)
    return spent[0] / designs, total


def accuracy(case, vary, out, designs=8):
    """Largest relative differences of gamma_P, sigma_a, f_res against rtol = 1e-14."""
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))[:designs]
    params = doe.parse_vary(case, vary)
    err = {"gamma_P": 0.0, "sigma_a": 0.0, "f_res": 0.0}
    labels = FORCES.split(",")
    if f"gamma_P@{labels[0]}" not in rows[0]:  # --outputs without the peaks
        return {k: None for k in err}
    for row in rows:
        if row["status"] != "ok":
            continue
        c = doe.with_values(case, [p.path for p in params], [float(row[p.name]) for p in params])
        c.analysis = dict(c.analysis, rtol=1e-14)
        points = build_model(c).backbone([float(f) for f in labels])
        for p, label in zip(points, labels):
            for key in err:
                ref, got = p[key], float(row[f"{key}@{label}"])
                err[key] = max(err[key], abs(got - ref) / abs(ref))
    return err


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--json", required=True, help="output file (JSON array of records)")
    ap.add_argument("--designs", type=int, default=2048, help="designs per serial run")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--no-dask", action="store_true", help="skip the Dask LocalCluster run")
    ap.add_argument("--million", type=int, default=10**6,
                    help="designs of the large run on all cores, Parquet alone (0: none)")
    args = ap.parse_args()
    case = load_case(ROOT / "cases" / "blade_a.json")
    cores = doe.default_workers()
    records = []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "doe.csv"
        run(case, SPACES["gg10"], 16, out, workers=1)  # imports and library loading
        for space, vary in SPACES.items():
            serial = {"workers": 1}
            if space in OUTPUTS:
                serial["outputs"] = OUTPUTS[space]
            configs = [("serial", 1, serial)]
            if cores > 1 and space in ("gg10", "gg10_liftoff"):
                configs.append((f"processes{cores}", cores, {"workers": cores}))
            if space == "gg10" and not args.no_dask:
                configs.append((f"dask_local{cores}", cores, {"dask": f"local:{cores}"}))
            for name, k, options in configs:
                # parallel runs start a pool or a cluster each time: give them more designs
                n = args.designs * (1 if k == 1 else 2 * k)
                if space == "gg10_liftoff":
                    n //= 4  # the kernel alone takes 5 times longer per design
                samples, startup, cpu, traces = [], [], [], []
                for _ in range(args.repeats):
                    per_design, summary = run(case, vary, n, out, **options)
                    samples.append(per_design)
                    startup.append(summary["startup_seconds"])
                    cpu.append(summary["cpu_seconds"])
                    traces.append(summary["traces"])
                err = accuracy(case, vary, out)
                med = statistics.median(samples)
                extra = {"designs": n, "cores": k, "design_space": " ".join(vary),
                         "designs_per_second_per_core": 1.0 / (med * k),
                         "designs_per_cpu_second": n / statistics.median(cpu),
                         "startup_seconds": statistics.median(startup),
                         "designs_per_second_per_core_after_startup":
                             n / ((med * n - statistics.median(startup)) * k),
                         "goal_designs_per_second_per_core": GOAL,
                         # the first run's: later repeats find the tracings of the warm
                         # worker's model (a serial run keeps its context between runs)
                         "traces": traces[0],
                         "outputs": options.get("outputs"),
                         "status": summary["status"]}
                if k == 1:
                    kernel, total = kernel_split(case, vary, n, out,
                                                 **{k: v for k, v in options.items()
                                                    if k != "workers"})
                    extra.update(kernel_seconds=kernel, python_seconds=max(total - kernel, 0.0))
                rec = record("blade_a", "doe", f"{space}_{name}",
                             {"seconds_median": med, "seconds_min": min(samples),
                              "seconds_max": max(samples), "repeats": args.repeats},
                             error_gamma_P=err["gamma_P"], error_sigma_a=err["sigma_a"],
                             error_f_res=err["f_res"], **extra)
                records.append(rec)
                split = (f"; per design kernel {1e6 * extra['kernel_seconds']:.0f} us + Python "
                         f"{1e6 * extra['python_seconds']:.0f} us" if k == 1 else "")
                start = (f"; {extra['designs_per_second_per_core_after_startup']:.0f} after a "
                         f"start-up of {extra['startup_seconds']:.2f} s"
                         if extra["startup_seconds"] > 0.05 else "")
                print(f"bench_doe: {space}_{name}: {n} designs, {1 / med:.0f} designs/s, "
                      f"{1 / (med * k):.0f} designs/s/core (best {1 / (min(samples) * k):.0f}; "
                      f"goal {GOAL:.0f}), {extra['designs_per_cpu_second']:.0f} designs per "
                      f"CPU second, {extra['traces']:.0f} tracings{start}{split}", flush=True)
        if args.million:
            records.append(large_run(case, args.million, cores, Path(tmp) / "large.parquet"))
    Path(args.json).write_text(json.dumps(records, indent=1, allow_nan=False) + "\n")
    return 0


def large_run(case, designs: int, cores: int, out: Path) -> dict:
    """One run of ``designs`` gg10 designs on all cores, written as Parquet alone (what a large
    study writes: Dask and pandas read it directly): its wall time, rate and tracings."""
    per_design, summary = run(case, SPACES["gg10"], designs, out, workers=cores,
                              format="parquet")
    wall = per_design * designs
    rec = record("blade_a", "doe", f"gg10_{designs:.0e}_processes{cores}".replace("+0", ""),
                 {"seconds_median": per_design, "seconds_min": per_design,
                  "seconds_max": per_design, "repeats": 1},
                 designs=designs, cores=cores, design_space=" ".join(SPACES["gg10"]),
                 wall_seconds=wall, designs_per_second_per_core=1.0 / (per_design * cores),
                 designs_per_cpu_second=designs / summary["cpu_seconds"],
                 traces=summary["traces"], format="parquet",
                 parquet_bytes=out.stat().st_size, goal_wall_seconds=120.0,
                 goal_designs_per_second_per_core=GOAL, status=summary["status"])
    print(f"bench_doe: gg10, {designs} designs on {cores} workers, Parquet alone: wall "
          f"{wall:.1f} s (goal 120 s), {1.0 / (per_design * cores):.0f} designs/s/core, "
          f"{rec['designs_per_cpu_second']:.0f} designs per CPU second, "
          f"{summary['traces']} tracings, {out.stat().st_size / 1e6:.0f} MB", flush=True)
    return rec


if __name__ == "__main__":
    sys.exit(main())
