#!/usr/bin/env python3
"""Blade hot path and setup (method "blade_receptances"): runs the Fortran benchmark
bench/blade_receptances.f90 (built as bench_blade_receptances) and turns its JSON lines into
records of INTERFACES.md "Benchmark output" (errors null: accuracy is asserted by the tests).
Usage: python3 bench/bench_blade.py [--json FILE]
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def executable() -> Path:
    build = Path(os.environ.get("UDMAP_BUILD_DIR", ROOT / "build"))
    exe = build / "bench" / "bench_blade_receptances"
    if not exe.is_file():
        raise SystemExit(f"bench_blade: {exe} not found; build first (make build)")
    return exe


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--json", help="write the records to this file")
    args = parser.parse_args()
    out = subprocess.run([str(executable()), "--json"], check=True, capture_output=True, text=True)
    records = []
    for line in out.stdout.splitlines():
        if not line.startswith("{"):
            continue
        m = json.loads(line)
        setting = m.pop("setting")
        case = "beam_2048" if setting.startswith("2048") else "blade_a"
        records.append({"case": case, "method": "blade_receptances", "setting": setting,
                        "seconds_median": m["seconds_median"], "seconds_min": m["seconds_min"],
                        "seconds_max": m["seconds_max"], "repeats": m["repeats"],
                        "error_gamma_P": None, "error_sigma_a": None, "error_f_res": None,
                        "unit": m["unit"]})
    for r in records:
        print(f"{r['setting']:60s} {r['seconds_median']:.3e} s {r['unit']}")
    if args.json:
        Path(args.json).write_text(json.dumps(records, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
