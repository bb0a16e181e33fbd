#!/usr/bin/env python3
"""Multi-harmonic layers (PHYSICS.md 4.1, docs/multi-harmonic.md): gg10 (blade A,
F_E = 1..10 N) cold with the layered backbone at H = 1, 3, 5, 9, 17 and auto against the
standard method (condensed, harmonics 0..H, warm-started from peak to peak) timed in the same
run, errors against the standard method at H = 33 (bench/harmonics_timing.f90); the same on a
Jenkins damper; automatic H against the time integration at 1, 2, 5, 10 N
(bench/harmonics_dti.f90); DOE designs per second at auto.

Records: method backbone / standard_condensed, settings gg10_H<H> and gg10_auto (case blade_a
and blade_a_jenkins; extras "harmonics", "ratio_to_H1", "speedup_vs_standard"); method
backbone, setting dti_auto_F<F> (errors against the time integration; extras the values);
method doe, setting auto (extra "designs_per_second").
Also rewrites the tables of docs/multi-harmonic.md (between the markers
harmonics:begin and harmonics:end) from the measured records.
Usage: bench_harmonics.py [--json FILE] [--from FILE (records of an earlier run: the guide only)]
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

from doc_block import replace_block  # noqa: E402
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


def _ms(t) -> str:
    return f"{1e3 * t:.3g} ms" if t < 1 else f"{t:.3g} s"


def gg10_table(records: list[dict], case: str) -> str:
    rows = ["| H | layered backbone, gg10 cold | error vs standard H = 33 (gamma_P, sigma_a, f_res) "
            "| ratio to H = 1 | standard method, same H, warm | its error | layered speed-up |",
            "| --- | ---: | --- | ---: | ---: | --- | ---: |"]
    by = {(r["method"], r["setting"]): r for r in records if r["case"] == case}
    for label in ("H1", "H3", "H5", "H9", "H17", "auto"):
        b = by.get(("backbone", f"gg10_{label}"))
        if b is None:
            continue
        s = by.get(("standard_condensed", f"gg10_{label}"))
        err = f"{b['error_gamma_P']:.1e}, {b['error_sigma_a']:.1e}, {b['error_f_res']:.1e}"
        name = label[1:] if label != "auto" else f"auto (H used up to {b['harmonics']})"
        if s is not None:
            serr = f"{s['error_gamma_P']:.1e}, {s['error_sigma_a']:.1e}, {s['error_f_res']:.1e}"
            rows.append(f"| {name} | {_ms(b['seconds_median'])} | {err} | "
                        f"{b['ratio_to_H1']:.2g} | {_ms(s['seconds_median'])} | {serr} | "
                        f"{b['speedup_vs_standard']:.1f} |")
        else:
            rows.append(f"| {name} | {_ms(b['seconds_median'])} | {err} | "
                        f"{b['ratio_to_H1']:.2g} | | | |")
    ref = by.get(("standard_condensed", "gg10_H33"))
    if ref is not None:
        rows.append(f"\nReference: the standard method at H = 33 took {_ms(ref['seconds_median'])}.")
    return "\n".join(rows)


def dti_table(records: list[dict]) -> str:
    rows = ["| F_E [N] | H used | gamma_P | sigma_a | f_res | H = 1: gamma_P | sigma_a | f_res |",
            "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for r in records:
        if not r["setting"].startswith("dti_auto_F"):
            continue
        rows.append(
            f"| {r['F_E']:g} | {r['harmonics']} | {100 * r['error_gamma_P']:+.2f} % | "
            f"{100 * r['error_sigma_a']:+.2f} % | {r['error_f_res']:+.3f} Hz | "
            f"{100 * (r['h1_gamma_P'] / r['dti_gamma_1'] - 1):+.2f} % | "
            f"{100 * (r['h1_sigma_a'] / r['dti_sigma_1'] - 1):+.2f} % | "
            f"{r['h1_f_res'] - r['dti_f']:+.3f} Hz |")
    return "\n".join(rows)


def readme(records: list[dict]) -> None:
    doe_rec = next((r for r in records if r["method"] == "doe"), None)
    body = ["Measured by `bench/bench_harmonics.py` (part of `make bench`); blade A, 2 shared "
            "cores, times are medians of repeated cold runs (new model and the ten peaks), the "
            "runs of the layered backbone and of the standard method alternating.", "",
            "**gg10, blade A's asymmetric damper** (F_E = 1..10 N; errors: the largest over the "
            "ten forces, relative, against the standard method at H = 33):", "",
            gg10_table(records, "blade_a"), "",
            "**gg10, a Jenkins damper** (blade A with kt = the asymmetric damper's stuck "
            "stiffness, M_slip = half its moment range):", "",
            gg10_table(records, "blade_a_jenkins"), "",
            "**Automatic H against the time integration** at its peak (PHYSICS.md 7, 512 steps "
            "per period; deviations of the layered result and of the single-harmonic backbone):",
            "", dti_table(records)]
    if doe_rec is not None:
        body += ["",
                 f"DOE at auto (`doe --harmonics auto`, 8 designs varying mu and CF, one force): "
                 f"{doe_rec['designs_per_second']:.2g} designs per second on one worker."]
    replace_block(ROOT / "docs" / "multi-harmonic.md", "harmonics", body)


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--json", default=None)
    ap.add_argument("--from", dest="source", default=None)
    args = ap.parse_args()
    if args.source:
        records = json.loads(Path(args.source).read_text())
    else:
        records = gg10("blade_a", "0") + gg10("blade_a_jenkins", "1") + dti() + doe()
    text = json.dumps(records, indent=1, allow_nan=False)
    if args.json:
        Path(args.json).write_text(text + "\n")
    elif not args.source:
        print(text)
    readme(records)
    return 0


if __name__ == "__main__":
    sys.exit(main())
