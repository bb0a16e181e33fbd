#!/usr/bin/env python3
"""Damper stiffness table benchmark (blade_a): runs build/bench/bench_table on one core and
writes its records (INTERFACES.md "Benchmark output", method "table").

Settings: full_table (what udmap builds: ramp, base cycle, topology intervals, Chebyshev
pieces), base_cycle_plus_40_loops (the reference workload: base cycle and 40 loops below
gamma_b, each with its own history), eval_* (one k(gamma) call in each regime).
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--json", required=True, help="output file for the records")
    args = ap.parse_args()
    exe = Path(os.environ.get("UDMAP_BUILD_DIR", ROOT / "build")) / "bench" / "bench_table"
    if not exe.is_file():
        raise SystemExit(f"bench_table: {exe} not built (cmake -DUDMAP_BUILD_BENCH=ON)")
    cmd = [str(exe)]
    if shutil.which("taskset"):
        cmd = ["taskset", "-c", "0"] + cmd
    records = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    for rec in records:
        print(f"  table {rec['setting']:>26}: median {rec['seconds_median'] * 1e6:10.3f} us")
    Path(args.json).write_text(json.dumps(records, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
