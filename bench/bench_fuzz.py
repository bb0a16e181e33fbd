#!/usr/bin/env python3
"""Hostile case files, the long run (tests/python/fuzz_cases.py; the short one is
tests/python/test_fuzz_cases.py in make test): 10^4 seeded mutations of every file in cases/
through the case loader, 1,000 of them through `backbone`, `response` and `table` in this
process and 20 through `python3 -m udmap`.

Writes out/bench/fuzz_cases.json (the counts per exit status, the problems found) and the
block between <!-- fuzz:begin --> and <!-- fuzz:end --> of docs/case-files.md; records for
bench.json with the time of the run. Exits with status 1 if any run crashed, printed a non-finite number
or gave an exit status 2 without naming a field.

    python3 bench/bench_fuzz.py --json OUT [--mutations N] [--sample S] [--seed SEED]
"""
from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "python"))
import fuzz_cases  # noqa: E402
from doc_block import replace_block  # noqa: E402


def readme_block(results: list[dict]) -> list[str]:
    """The lines of the fuzz block of docs/case-files.md."""
    lines = ["", "Counts per exit status, measured by `make bench` (`bench/bench_fuzz.py`):",
             "", "| case | mutations | seed | loader 0 / 2 | run through | backbone 0 / 2 / 3 / 4 "
             "| response 0 / 2 / 3 / 4 | table 0 / 2 / 3 / 4 | `python3 -m udmap` 0 / 2 / 3 / 4 "
             "| problems |", "| --- | ---: | ---: | --- | ---: | --- | --- | --- | --- | ---: |"]

    def counts(c):
        return " / ".join(str(c[s]) for s in sorted(c))
    for r in results:
        lines.append(f"| {r['case']} | {r['mutations']} | {r['seed']} | {counts(r['loader'])} | "
                     f"{sum(r['cli']['backbone'].values())} | {counts(r['cli']['backbone'])} | "
                     f"{counts(r['cli']['response'])} | {counts(r['cli']['table'])} | "
                     f"{counts(r['subprocess'])} | {len(r['problems'])} |")
    return lines + [""]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", required=True, help="records for out/bench/bench.json")
    ap.add_argument("--mutations", type=int, default=10000)
    ap.add_argument("--sample", type=int, default=1000)
    ap.add_argument("--subprocesses", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    results, records = [], []
    for case_file in fuzz_cases.CASES:
        t0 = time.perf_counter()
        with tempfile.TemporaryDirectory() as tmp:
            r = fuzz_cases.fuzz(case_file, args.mutations, args.sample, args.seed, Path(tmp),
                                subprocesses=args.subprocesses)
        seconds = time.perf_counter() - t0
        results.append(r)
        print(f"bench_fuzz: {r['case']}: loader {r['loader']}, cli {r['cli']}, "
              f"subprocess {r['subprocess']}, {len(r['problems'])} problems, {seconds:.1f} s",
              flush=True)
        for p in r["problems"][:20]:
            print(f"  {p}", flush=True)
        records.append({"case": r["case"], "method": "fuzz_cases",
                        "setting": f"{args.mutations} mutations, {args.sample} run",
                        "seconds_median": seconds, "seconds_min": seconds,
                        "seconds_max": seconds, "repeats": 1, "error_gamma_P": None,
                        "error_sigma_a": None, "error_f_res": None,
                        "counts": {"loader": r["loader"], "cli": r["cli"],
                                   "subprocess": r["subprocess"]},
                        "problems": len(r["problems"])})
    out = ROOT / "out" / "bench"
    out.mkdir(parents=True, exist_ok=True)
    (out / "fuzz_cases.json").write_text(json.dumps(results, indent=1) + "\n")
    Path(args.json).write_text(json.dumps(records, indent=1, allow_nan=False) + "\n")
    replace_block(ROOT / "docs" / "case-files.md", "fuzz", readme_block(results))
    return 1 if any(r["problems"] for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
