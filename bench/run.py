#!/usr/bin/env python3
"""`make bench`: runs every bench/bench_*.py, collects out/bench/bench.json, plots, and
rewrites docs/benchmarks.md ("Speed and accuracy") from the measured records.

Each bench_*.py is called as `python3 bench/bench_X.py --json FILE` and writes a JSON array of
records with the fields of INTERFACES.md "Benchmark output" (plus optional extras).
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "out" / "bench"
FIELDS = ("case", "method", "setting", "seconds_median", "seconds_min", "seconds_max",
          "repeats", "error_gamma_P", "error_sigma_a", "error_f_res")


def run_component(script: Path) -> list[dict]:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "records.json"
        env = dict(os.environ, PYTHONPATH=str(ROOT / "wrappers" / "python"))
        print(f"bench: {script.name} ...", flush=True)
        r = subprocess.run([sys.executable, str(script), "--json", str(out)], cwd=ROOT, env=env)
        if r.returncode != 0:
            raise SystemExit(f"bench: {script.name} failed with status {r.returncode}")
        records = json.loads(out.read_text())
    for rec in records:
        missing = [f for f in FIELDS if f not in rec]
        if missing:
            raise SystemExit(f"bench: {script.name}: record lacks {missing}: {rec}")
    return records


def main() -> int:
    OUT.mkdir(parents=True, exist_ok=True)
    only = set(sys.argv[1:])
    records = []
    for script in sorted((ROOT / "bench").glob("bench_*.py")):
        if only and script.stem not in only:
            continue
        records += run_component(script)
    (OUT / "bench.json").write_text(json.dumps(records, indent=1, allow_nan=False) + "\n")
    print(f"bench: {len(records)} records in {OUT / 'bench.json'}")
    report = ROOT / "bench" / "report.py"
    if report.exists():
        subprocess.run([sys.executable, str(report)], cwd=ROOT, check=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
