#!/usr/bin/env python3
"""Growth of the cost with the model size (make bench): beam blades with the proportions of
blade A (a quarter of the elements in the neck, three quarters in the airfoil) and 32 (blade A
itself), 256, 2048 and 8192 elements, exported with Blade.export as matrices cases and timed
through the C API (bench/gg10_timing.c):

  blade_build / matrices_import   udmap_new_blade_matrices: reading the Matrix Market files and
                                  the bare modes
  backbone / setup_gg10           udmap_new_model + the first gg10 (the bare-blade data of the
                                  band, once per blade)
  backbone / gg10                 gg10 from the damper parameters on (the model exists)
  standard_condensed / gg10       the standard method with H = 1 at the equal-accuracy setting
  standard_full / gg10            of bench_gg10 (out/bench/ratios.json; warm starts, tol 1e-3
                                  if that file is missing)

Errors are relative to a tight backbone (rtol 1e-14) of the same blade. The exponent p of
cost ~ ndof^p is fitted (least squares in log-log) over the sizes; the records carry it as
"scaling_exponent" along with "ndof" and "elements".
Usage: bench_scaling.py [--json FILE] [--sizes 32,256,2048,8192] [--quick]
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "wrappers" / "python"))
sys.path.insert(0, str(ROOT / "bench"))

import harness  # noqa: E402
from timing import record  # noqa: E402
from udmap import Blade  # noqa: E402
from udmap.case import beam_params, load_case  # noqa: E402

OUT = ROOT / "out" / "bench"
FALLBACK_KNOBS = {"warm_start": 2, "tol": 1e-3, "tol_path": 1e-3, "peak_tol": 1e-3}


def standard_knobs() -> dict:
    """The standard method's equal-accuracy setting of bench_gg10 (same for both variants)."""
    try:
        ratios = json.loads((OUT / "ratios.json").read_text())
        return {m: ratios["methods"][m]["knobs"] for m in ("standard_condensed",
                                                           "standard_full")}
    except (OSError, KeyError, ValueError):
        return {m: FALLBACK_KNOBS for m in ("standard_condensed", "standard_full")}


def exponent(n: list[float], t: list[float]) -> float:
    """Slope of log t against log n (least squares)."""
    x = [math.log(v) for v in n]
    y = [math.log(v) for v in t]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--json", type=Path, default=None)
    ap.add_argument("--sizes", default="32,256,2048,8192")
    ap.add_argument("--quick", action="store_true", help="fewer repeats")
    args = ap.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    case = load_case(ROOT / "cases" / "blade_a.json")
    base = beam_params(case.blade)
    knobs = standard_knobs()
    records = []
    series: dict[tuple[str, str], list[tuple[int, float]]] = {}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        exe = harness.compile_harness(tmp)
        for n_el in sizes:
            if n_el % 8:
                raise SystemExit("bench_scaling: sizes must be multiples of 8")
            p = dict(base, neck_elements=n_el // 4, airfoil_elements=3 * n_el // 4)
            blade = Blade.beam(**p)
            ndof = blade.ndof
            d = tmp / f"beam_{n_el}"
            d.mkdir()
            blade.export(d)
            del blade
            section = json.loads((d / "blade.json").read_text())
            (d / "case.json").write_text(json.dumps({
                "name": f"beam_{n_el}", "blade": section, "damper": case.damper,
                "analysis": {k: case.analysis[k] for k in ("f_min", "f_max", "sigma_all")}},
                indent=1))
            head = "\n".join([harness.matrices_line(section, d), harness.damper_line(case.damper),
                              harness.band_line(case.analysis)])
            big = ndof > 5000
            rep = (lambda r: max(1, r // 4)) if args.quick else (lambda r: r)
            jobs = [f"build build {rep(1 if big else 5)}",
                    f"setup setup {rep(1 if big else 5)}",
                    "backbone reference 0 1e-14 96",
                    f"backbone backbone {rep(21)} 1e-12 24"]
            for method, variant in (("standard_condensed", 0), ("standard_full", 1)):
                jobs.append(harness.standard_job(method, rep(1 if big else 5), variant,
                                                 knobs[method]))
            print(f"bench_scaling: {n_el} elements, {ndof} DOFs ...", flush=True)
            runs = harness.run_jobs(exe, head, jobs)
            ref = runs["reference"]
            name = f"beam_{n_el}"
            extra = {"ndof": ndof, "elements": n_el}
            rows = [("blade_build", "matrices_import", runs["build"], None, {}),
                    ("backbone", "setup_gg10", runs["setup"], ref, {}),
                    ("backbone", "gg10", runs["backbone"], ref, {})]
            for method in ("standard_condensed", "standard_full"):
                rows.append((method, "gg10", runs[method], ref,
                             {"knobs": knobs[method], "harmonics": 1}))
            for method, setting, r, rf, more in rows:
                if "failed" in r:
                    print(f"  {method} {setting}: failed: {r['failed']}")
                    continue
                err = harness.rel_errors(r, rf) if rf is not None else {}
                records.append(record(name, method, setting, harness.timing(r), **err,
                                      **extra, **more))
                series.setdefault((method, setting), []).append((ndof, r["seconds_median"]))
                print(f"  {method:>18} {setting:<16} median {r['seconds_median']*1e3:10.3f} ms"
                      + (f"  error {max(err.values()):.1e}" if err else ""), flush=True)
    for (method, setting), pts in series.items():
        if len(pts) < 2:
            continue
        p = exponent([a for a, _ in pts], [b for _, b in pts])
        for r in records:
            if r["method"] == method and r["setting"] == setting:
                r["scaling_exponent"] = p
        print(f"  exponent of {method} {setting}: {p:.2f}")
    if args.json:
        args.json.write_text(json.dumps(records, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
