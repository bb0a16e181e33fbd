"""Hostile case files (fuzz_cases.py): 2,000 seeded random mutations of every file in cases/
through the case loader, a sample of 200 of them through `backbone`, `response` and `table`
(the command line in this process) and a few through `python3 -m udmap`. Exit status 0, 2, 3
or 4 only, never a traceback, never a non-finite number in the JSON, every status-2 message
names a field. The longer run (10^4 mutations) is bench/bench_fuzz.py."""
import json

import pytest

import fuzz_cases

MUTATIONS, SAMPLE, SUBPROCESSES, SEED = 2000, 200, 6, 20241125


@pytest.mark.parametrize("case_file", fuzz_cases.CASES, ids=lambda p: p.stem)
def test_mutated_cases_fail_cleanly(case_file, tmp_path):
    r = fuzz_cases.fuzz(case_file, MUTATIONS, SAMPLE, SEED, tmp_path, subprocesses=SUBPROCESSES)
    print(json.dumps({k: v for k, v in r.items() if k != "problems"}))
    assert r["problems"] == [], "\n".join(r["problems"][:20])
    assert sum(r["loader"].values()) == MUTATIONS
    # the mutations reach every outcome: valid cases that compute, and rejected ones
    assert r["loader"][0] >= MUTATIONS // 10 and r["loader"][2] >= MUTATIONS // 2, r["loader"]
    for command, counts in r["cli"].items():
        assert sum(counts.values()) == SAMPLE, (command, counts)
        assert counts[0] >= SAMPLE // 4 and counts[2] >= SAMPLE // 4, (command, counts)
    assert sum(r["subprocess"].values()) == SUBPROCESSES


def test_the_mutations_are_reproducible():
    base = json.loads(fuzz_cases.CASES[0].read_text())
    a = [fuzz_cases.dumps(d) for d, _ in fuzz_cases.mutations(base, 50, 3)]
    b = [fuzz_cases.dumps(d) for d, _ in fuzz_cases.mutations(base, 50, 3)]
    c = [fuzz_cases.dumps(d) for d, _ in fuzz_cases.mutations(base, 50, 4)]
    assert a == b and a != c
    assert len(set(a)) > 45  # distinct mutations, not the same one again


@pytest.mark.parametrize("message,ok", [
    ("blade.neck.L must be in [0.0001, 3] m, got 100000", True),
    ("udmap: error: damper.flat_points[0][1] must be in [-1, 1] m, got 5", True),
    ("damper.kind must be one of asymmetric, jenkins, table, got null", True),
    ("bladez: unknown top-level field (allowed: ...)", True),
    ("udmap: error: analysis: the band [f_min, f_max] contains the bare mode", True),
    ("udmap: error: numerical trouble", False),
    ("must be positive", False),
])
def test_the_field_check_itself(message, ok):
    assert fuzz_cases.names_a_field(message, {"bladez": {}}) is ok
