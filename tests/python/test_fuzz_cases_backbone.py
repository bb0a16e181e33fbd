"""Hostile case files through `backbone` (fuzz_cases.py; the loader alone and real processes:
test_fuzz_cases.py): of 2,000 seeded mutations of every file in cases/, 200 (half of them
valid) through the command line in this process. Exit status 0, 2, 3 or 4 only, never a
traceback, never a non-finite number in the JSON, every status-2 message names a field."""
import json

import pytest

import fuzz_cases

MUTATIONS, SAMPLE, SEED = 2000, 200, 20241125
COMMAND = next(c for c in fuzz_cases.COMMANDS if c[0] == "backbone")


@pytest.mark.parametrize("case_file", fuzz_cases.CASES, ids=lambda p: p.stem)
def test_mutated_cases_fail_cleanly_in_backbone(case_file, tmp_path):
    r = fuzz_cases.fuzz(case_file, MUTATIONS, SAMPLE, SEED, tmp_path, commands=(COMMAND,))
    print(json.dumps({k: v for k, v in r.items() if k != "problems"}))
    assert r["problems"] == [], "\n".join(r["problems"][:20])
    counts = r["cli"]["backbone"]
    assert sum(counts.values()) == SAMPLE, counts
    # valid cases that compute and rejected ones, not only one kind
    assert counts[0] >= SAMPLE // 4 and counts[2] >= SAMPLE // 4, counts
