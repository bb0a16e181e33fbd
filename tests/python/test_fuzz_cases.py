"""Hostile case files (fuzz_cases.py): 2,000 seeded random mutations of every file in cases/
through the case loader, and a few through `python3 -m udmap` (real exit statuses). The
samples of 200 through `backbone`, `response` and `table` are test_fuzz_cases_<command>.py
(one ctest entry each); the longer run (10^4 mutations) is bench/bench_fuzz.py.
Exit status 0, 2, 3 or 4 only, never a traceback, never a non-finite number in the JSON, every
status-2 message names a field."""
import json

import pytest

import fuzz_cases

MUTATIONS, SUBPROCESSES, SEED = 2000, 6, 20241125


@pytest.mark.parametrize("case_file", fuzz_cases.CASES, ids=lambda p: p.stem)
def test_mutated_cases_fail_cleanly_in_the_loader(case_file, tmp_path):
    r = fuzz_cases.fuzz(case_file, MUTATIONS, SUBPROCESSES, SEED, tmp_path, commands=(),
                        subprocesses=SUBPROCESSES)
    print(json.dumps({k: v for k, v in r.items() if k != "problems"}))
    assert r["problems"] == [], "\n".join(r["problems"][:20])
    assert sum(r["loader"].values()) == MUTATIONS
    # the mutations reach both outcomes: valid cases and rejected ones
    assert r["loader"][0] >= MUTATIONS // 10 and r["loader"][2] >= MUTATIONS // 2, r["loader"]
    # python3 -m udmap: the same exit statuses in a real process, half of them on valid cases
    assert sum(r["subprocess"].values()) == SUBPROCESSES and r["subprocess"][2] >= 2


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


@pytest.mark.parametrize("status,stdout,stderr,ok", [
    (0, '{"a": [1.0, 2]}', "", True),
    (0, '{"a": NaN}', "", False),
    (0, '{"a": [Infinity]}', "", False),
    (1, "", "Traceback (most recent call last):", False),
    (2, "", "udmap: error: blade.E must be in [1e6, 1e13] Pa, got 1e300", True),
    (2, "", "udmap: error: something is wrong", False),
    (2, "{}", "udmap: error: blade.E must be in [1e6, 1e13] Pa, got 1e300", False),
    (3, "", "udmap: physics: damper jams", True),
    (4, "", "", False),
])
def test_the_run_check_itself(status, stdout, stderr, ok):
    assert (fuzz_cases.check_run(status, stdout, stderr, {}) is None) is ok
