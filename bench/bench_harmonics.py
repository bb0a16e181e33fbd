#!/usr/bin/env python3
"""Multi-harmonic layers (PHYSICS.md 4.1, README "Multi-harmonic layers"): gg10 (blade A,
F_E = 1..10 N) cold with the layered backbone at H = 1, 3, 5, 9, 17 and auto against the
standard method (condensed, harmonics 0..H, warm-started from peak to peak) timed in the same
run, errors against the standard method at H = 33 (bench/harmonics_timing.f90); the same on a
Jenkins damper; automatic H against the time integration at 1, 2, 5, 10 N
(bench/harmonics_dti.f90); DOE designs per second at auto.

Records: method backbone / standard_condensed, settings gg10_H<H> and gg10_auto (case blade_a
and blade_a_jenkins; extras "harmonics", "ratio_to_H1", "speedup_vs_standard"); method
backbone, setting dti_auto_F<F> (errors against the time integration; extras the values);
method doe, setting auto (extra "designs_per_second").
Usage: bench_harmonics.py [--json FILE]
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "wrappers" / "python"))
sys.path.insert(0, str(ROOT / "bench"))

from timing import record  # noqa: E402


def build_dir() -> Path:
    import os
    return Path(os.environ.get("UDMAP_BUILD_DIR", ROOT / "build"))


def run_lines(exe: str, *args) -> list[dict]:
    path = build_dir() / "bench" / exe
    r = subprocess.run([str(path), *args], capture_output=True, text=True, check=True)
    lines = [json.loads(line) for line in r.stdout.splitlines() if line.startswith("{")]
    for line in lines:
        if "error" in line:
            raise SystemExit(f"bench_harmonics: {exe}: {line['error']}")
    return lines


def gg10(case: str, kind: str) -> list[dict]:
    rows = run_lines("bench_harmonics_timing", kind)
    h1 = next(r for r in rows if r["method"] == "backbone" and r["setting"] == "gg10_H1")
    std = {r["setting"]: r for r in rows if r["method"] == "standard_condensed"}
    out = []
    for r in rows:
        t_min, t_med, t_max = r["times"]
        timing = {"seconds_median": t_med, "seconds_min": t_min, "seconds_max": t_max,
                  "repeats": r["repeats"]}
        extra = {"harmonics": r["harmonics"]}
        if r["method"] == "backbone":
            extra["ratio_to_H1"] = t_med / h1["times"][1]
            if r["setting"] in std:
                extra["speedup_vs_standard"] = std[r["setting"]]["times"][1] / t_med
        e = r["errors"]
        out.append(record(case, r["method"], r["setting"], timing, e[0], e[1], e[2], **extra))
    return out


def dti() -> list[dict]:
    out = []
    for r in run_lines("bench_harmonics_dti"):
        out.append(record("blade_a", "backbone", f"dti_auto_F{r['F_E']:g}",
                          {"seconds_median": None, "seconds_min": None, "seconds_max": None,
                           "repeats": 0},
                          r["gamma_P"] / r["dti_gamma_1"] - 1, r["sigma_a"] / r["dti_sigma_1"] - 1,
                          r["f_res"] - r["dti_f"], error_f_res_unit="Hz", **r))
    return out


def doe() -> list[dict]:
    from udmap.case import load_case
    from udmap.doe import run_doe
    case = load_case(ROOT / "cases" / "blade_a.json")
    case.analysis["harmonics"] = "auto"
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        s = run_doe(case, ["mu=0.3:0.6", "CF=700:1100"], 8, Path(tmp) / "doe.csv", forces="5",
                    workers=1, overwrite=True)
        seconds = time.perf_counter() - t0
    return [record("blade_a", "doe", "auto", {"seconds_median": seconds, "seconds_min": seconds,
                                             "seconds_max": seconds, "repeats": 1},
                   designs=s["designs"], designs_per_second=s["designs_per_second"],
                   status=s["status"])]


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    records = gg10("blade_a", "0") + gg10("blade_a_jenkins", "1") + dti() + doe()
    text = json.dumps(records, indent=1, allow_nan=False)
    if args.json:
        Path(args.json).write_text(text + "\n")
    else:
        print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
