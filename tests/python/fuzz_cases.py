"""Hostile case files: seeded random mutations of the files in cases/, run through the case
loader and the command line. Shared by tests/python/test_fuzz_*.py (make test) and
bench/bench_fuzz.py (make bench, the longer run).

A mutation applies one to three edits to a case: a wrong JSON type (string, list, object,
null, Boolean, nested garbage) at any node, an extreme or non-finite number (0, negatives,
1e300, 1e-300, the largest and smallest doubles, integers beyond the double range, NaN and
Infinity literals), a plausible rescaling (x 10^[-3, 3], so that many designs reach the
kernel), a swap of a ``kind`` into another kind, an unknown one, a list, an object, null or a
Boolean, a deletion, an unknown field, a section swapped with another one, and integer/float
swaps. Everything is drawn from ``random.Random(seed)``: a run is reproducible.
"""
from __future__ import annotations

import contextlib
import copy
import io
import json
import math
import random
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CASES = sorted((ROOT / "cases").glob("*.json"))

GARBAGE = ["", "abc", "1e3", "NaN", "beam", [], [1, 2], [[1, 2], [3, 4]], {}, {"a": 1},
           {"kind": "beam"}, None, True, False, 0, -1, 1.5, [None], [[[[[]]]]],
           {"x": {"y": {"z": [1, "2", None]}}}, "\u00e9\u4e2d", "\ud800", "x" * 200]
EXTREMES = [0, 0.0, -0.0, -1, -1.0, 1e300, -1e300, 1e-300, 5e-324, 1.7976931348623157e308,
            -1.7976931348623157e308, 10**400, -(10**400), 2**63, 2**31, 1e-12, 1e12, 1e6,
            float("nan"), float("inf"), float("-inf")]
OTHER_KINDS = ["beam", "matrices", "asymmetric", "jenkins", "table", "fe", "shell", "", "BEAM",
               ["beam"], {"beam": 1}, None, True, False, 1, 0.0]
SECTIONS = ("blade", "damper", "analysis")


def _nodes(node, path=()):
    """Every (path, value) of a JSON document (the root excluded)."""
    if isinstance(node, dict):
        for key, value in node.items():
            yield path + (key,), value
            yield from _nodes(value, path + (key,))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            yield path + (i,), value
            yield from _nodes(value, path + (i,))


def _parent(doc, path):
    node = doc
    for key in path[:-1]:
        node = node[key]
    return node


def _deep(rng: random.Random, depth: int):
    """Nested garbage: lists and objects of lists and objects."""
    if depth == 0:
        return rng.choice(GARBAGE[:6] + [1.0, None])
    if rng.random() < 0.5:
        return [_deep(rng, depth - 1) for _ in range(rng.randint(0, 2))]
    return {rng.choice(["a", "kind", "E", "L"]): _deep(rng, depth - 1)}


def _edit(doc: dict, rng: random.Random) -> str:
    """One edit of ``doc`` in place; returns its name (for the statistics)."""
    nodes = list(_nodes(doc))
    numbers = [(p, v) for p, v in nodes
               if isinstance(v, (int, float)) and not isinstance(v, bool)]
    kinds = [(p, v) for p, v in nodes if p and p[-1] == "kind"]
    dicts = [()] + [p for p, v in nodes if isinstance(v, dict)]
    op = rng.choice(["type", "type", "extreme", "extreme", "scale", "scale", "scale", "kind",
                     "delete", "unknown", "garbage", "swap", "intfloat"])
    if op in ("extreme", "scale", "intfloat") and not numbers:
        op = "type"
    if op == "kind" and not kinds:
        op = "type"
    if op == "type" and nodes:
        path, _ = rng.choice(nodes)
        _parent(doc, path)[path[-1]] = copy.deepcopy(rng.choice(GARBAGE))
    elif op == "extreme":
        path, _ = rng.choice(numbers)
        _parent(doc, path)[path[-1]] = rng.choice(EXTREMES)
    elif op == "scale":
        path, v = rng.choice(numbers)
        try:
            v = float(v) * 10 ** rng.uniform(-3, 3) if v else rng.uniform(-1, 1)
        except OverflowError:
            v = rng.uniform(-1, 1)
        _parent(doc, path)[path[-1]] = v
    elif op == "intfloat":
        path, v = rng.choice(numbers)
        if isinstance(v, int):
            v = float(v) if abs(v) < 2**53 else v + 1
        elif math.isfinite(v):
            v = rng.choice([int(v), v + 0.5, float(round(v))])
        _parent(doc, path)[path[-1]] = v
    elif op == "kind":
        path, _ = rng.choice(kinds)
        _parent(doc, path)[path[-1]] = copy.deepcopy(rng.choice(OTHER_KINDS))
    elif op == "delete" and nodes:
        path, _ = rng.choice(nodes)
        parent = _parent(doc, path)
        if isinstance(parent, dict):
            del parent[path[-1]]
        else:
            parent.pop(path[-1])
    elif op == "unknown":
        path = rng.choice(dicts)
        target = _parent(doc, path + ("x",))
        target[rng.choice(["foo", "Kind", "e", "elements", "zeta2", "kind"])] = \
            copy.deepcopy(rng.choice(GARBAGE + EXTREMES))
    elif op == "garbage" and nodes:
        path, _ = rng.choice(nodes)
        _parent(doc, path)[path[-1]] = _deep(rng, rng.randint(1, 6))
    elif op == "swap":
        a, b = rng.sample(SECTIONS, 2)
        if a in doc and b in doc:
            doc[a], doc[b] = doc[b], doc[a]
    return op


def mutations(base: dict, count: int, seed: int):
    """``count`` mutated copies of ``base`` (each one to three edits) with the edits' names."""
    rng = random.Random(seed)
    for _ in range(count):
        doc = copy.deepcopy(base)
        ops = [_edit(doc, rng) for _ in range(rng.choice([1, 1, 1, 2, 3]))]
        yield doc, ops


def dumps(doc) -> str:
    """The JSON text of a mutated case (NaN and Infinity written as the literals they are)."""
    return json.dumps(doc, allow_nan=True)


_FIELD = re.compile(r"(?<![\w.])(blade|damper|analysis)((\.[A-Za-z_]\w*)|(\[\d+\]))+")


def names_a_field(message: str, doc) -> bool:
    """True when ``message`` names a field: a dotted path into a section (blade.neck.L,
    damper.flat_points[0][1], damper.kind) or a top-level key of the document (name, or an
    unknown or missing section) at its start."""
    if _FIELD.search(message):
        return True
    m = re.match(r"(?:udmap: error: )?(\w+)(?::| must)", message)
    return bool(m) and (m.group(1) in SECTIONS or (isinstance(doc, dict) and m.group(1) in doc)
                        or m.group(1) in ("name", "description"))


def load_outcome(doc, base_dir: Path):
    """(status, message) of the case loader: 0 valid, 2 InputError; anything else raises."""
    from udmap import InputError
    from udmap.case import loads_case
    try:
        loads_case(dumps(doc), base_dir)
    except InputError as exc:
        return 2, str(exc)
    return 0, ""


def _finite_json(value) -> bool:
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, dict):
        return all(_finite_json(v) for v in value.values())
    if isinstance(value, list):
        return all(_finite_json(v) for v in value)
    return True


def _reject_constant(name):
    raise ValueError(f"non-finite number {name} in the JSON output")


#: The command lines run on a mutated case (CASE is replaced by its file).
COMMANDS = (("backbone", "CASE", "--forces", "0.5,2,5,20", "--json"),
            ("response", "CASE", "--forces", "2,8", "--freq", "190", "--json"),
            ("table", "CASE", "--gammas", "1e-6,1e-4,1e-3,1e-2,0.5", "--json"))


def check_run(status: int, stdout: str, stderr: str, doc) -> str | None:
    """What is wrong with one command-line run, or None: the status must be 0, 2, 3 or 4; a
    success prints finite JSON, a failure a message, and status 2 names a field."""
    if status not in (0, 2, 3, 4):
        return f"exit status {status}: {stderr[-2000:]}"
    if "Traceback" in stderr:
        return f"traceback with status {status}: {stderr[-2000:]}"
    if status == 0:
        try:
            data = json.loads(stdout, parse_constant=_reject_constant)
        except ValueError as exc:
            return f"bad JSON output: {exc}"
        if not _finite_json(data):
            return "non-finite number in the JSON output"
        return None
    if stdout:
        return f"status {status} but output written: {stdout[:200]}"
    if not stderr.strip():
        return f"status {status} without a message"
    if status == 2 and not names_a_field(stderr.strip(), doc):
        return f"status 2 message names no field: {stderr.strip()}"
    return None


def run_inprocess(argv: list[str]) -> tuple[int, str, str]:
    """The command line in this process: (exit status, stdout, stderr); an uncaught exception
    is status 1 with its traceback, as ``python3 -m udmap`` would give."""
    import traceback
    from udmap.cli import main
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main(argv)
        except SystemExit as exc:  # argparse
            status = exc.code if isinstance(exc.code, int) else 1
        except BaseException:  # noqa: BLE001 - a crash is what this looks for
            traceback.print_exc()
            status = 1
    return status, out.getvalue(), err.getvalue()


def run_subprocess(argv: list[str], timeout: float = 120) -> tuple[int, str, str]:
    r = subprocess.run([sys.executable, "-m", "udmap", *argv], capture_output=True, text=True,
                       cwd=ROOT, timeout=timeout)
    return r.returncode, r.stdout, r.stderr


def fuzz(case_file: Path, count: int, sample: int, seed: int, workdir: Path,
         commands=COMMANDS, subprocesses: int = 0, progress=None) -> dict:
    """The fuzz of one case file: ``count`` mutations through the loader, ``sample`` of them
    (about half valid, half not, when there are enough) through ``commands`` (of COMMANDS) in
    this process and the first ``subprocesses`` of those through ``python3 -m udmap`` (the
    commands of COMMANDS in turn). Returns counts per exit status and the list of problems
    (empty when all is well)."""
    base = json.loads(case_file.read_text())
    loader = {0: 0, 2: 0}
    problems: list[str] = []
    valid, invalid = [], []
    for i, (doc, ops) in enumerate(mutations(base, count, seed)):
        try:
            status, message = load_outcome(doc, case_file.parent)
        except Exception as exc:  # noqa: BLE001 - a crash is what this looks for
            problems.append(f"loader crash on mutation {i} ({ops}): {type(exc).__name__}: {exc}")
            continue
        loader[status] += 1
        if status == 2 and not names_a_field(message, doc):
            problems.append(f"loader message names no field (mutation {i}, {ops}): {message}")
        (valid if status == 0 else invalid).append((i, doc))
    rng = random.Random(seed + 1)
    half = min(len(valid), sample // 2)
    chosen = rng.sample(valid, half) + rng.sample(invalid, min(len(invalid), sample - half))
    chosen.sort(key=lambda item: item[0])
    cli = {c[0]: {s: 0 for s in (0, 2, 3, 4)} for c in commands}
    sub = {s: 0 for s in (0, 2, 3, 4)}
    workdir.mkdir(parents=True, exist_ok=True)
    for n, (i, doc) in enumerate(chosen):
        path = workdir / f"mutation_{i}.json"
        path.write_text(dumps(doc))
        for command in commands:
            argv = [str(path) if a == "CASE" else a for a in command]
            status, out, err = run_inprocess(argv)
            problem = check_run(status, out, err, doc)
            if problem:
                problems.append(f"{command[0]} on mutation {i}: {problem}")
            else:
                cli[command[0]][status] += 1
        if n < subprocesses:
            argv = [str(path) if a == "CASE" else a for a in COMMANDS[n % len(COMMANDS)]]
            status, out, err = run_subprocess(argv)
            problem = check_run(status, out, err, doc)
            if problem:
                problems.append(f"python3 -m udmap {argv[0]} on mutation {i}: {problem}")
            else:
                sub[status] += 1
        if progress:
            progress(n + 1, len(chosen))
    return {"case": case_file.stem, "mutations": count, "seed": seed, "loader": loader,
            "cli": cli, "subprocess": sub, "problems": problems}


#: The sample through one command (test_fuzz_cases_<command>.py): 200 of 2,000 mutations.
COMMAND_MUTATIONS, COMMAND_SAMPLE, COMMAND_SEED = 2000, 200, 20241125


def command_test(name: str):
    """The test of one command on the hostile cases, one ctest entry per command: of 2,000
    seeded mutations of every file in cases/, 200 (half of them valid) through the command
    line in this process. Exit status 0, 2, 3 or 4 only, never a traceback, never a non-finite
    number in the JSON, every status-2 message names a field."""
    import pytest
    command = next(c for c in COMMANDS if c[0] == name)

    @pytest.mark.parametrize("case_file", CASES, ids=lambda p: p.stem)
    def test(case_file, tmp_path):
        r = fuzz(case_file, COMMAND_MUTATIONS, COMMAND_SAMPLE, COMMAND_SEED, tmp_path,
                 commands=(command,))
        print(json.dumps({k: v for k, v in r.items() if k != "problems"}))
        assert r["problems"] == [], "\n".join(r["problems"][:20])
        counts = r["cli"][name]
        assert sum(counts.values()) == COMMAND_SAMPLE, counts
        # valid cases that compute and rejected ones, not only one kind
        assert counts[0] >= COMMAND_SAMPLE // 4 and counts[2] >= COMMAND_SAMPLE // 4, counts

    test.__name__ = f"test_mutated_cases_fail_cleanly_in_{name}"
    return test
