"""The ``fe`` case through the command line: ``udmap reduce``, every command on the ``fe`` case
directly (same results as on its reduced ``matrices`` case), the reduction done once and cached
by the content of its inputs. The blade is a fresh CalculiX export of the test deck."""
from __future__ import annotations

import json
import re
import shutil
import subprocess

import numpy as np
import pytest

from fe_case_fixtures import FORCES, export, run, work  # noqa: F401  (fixtures)
from fe_deck import make_deck, write_inp


def backbones(cases, capsys) -> list[dict]:
    """The JSON of `backbone` on each case file (asserting exit status 0)."""
    out = []
    for c in cases:
        status, text, err = run(["backbone", c, "--forces", FORCES, "--json"], capsys)
        assert status == 0, err
        out.append(json.loads(text))
    return out


def test_reduce_writes_a_matrices_case(work, capsys):
    d, deck, case, calls = work
    (d / "file").write_text("")
    status, out, err = run(["reduce", d / "case.json", "--out", d / "file" / "r.json"], capsys)
    assert status == 2 and "is a file, not a directory" in err and calls == []
    # a missing --out directory is made
    status, out, err = run(["reduce", d / "case.json", "--out", d / "red" / "r.json", "--json"],
                           capsys)
    assert status == 0, err
    info = json.loads(out)
    new = json.loads((d / "red" / "r.json").read_text())
    assert new["blade"] == {"kind": "matrices", "M": "r_M.mtx", "K": "r_K.mtx",
                            "stress_K": "r_stress_K.mtx", "gamma_dof": info["gamma_dof"],
                            "exc_dof": info["exc_dof"], "zeta": 0.002}
    assert new["damper"] == case["damper"] and new["analysis"] == case["analysis"]
    assert sorted(p.name for p in (d / "red").iterdir()) == [
        "r.json", "r_K.mtx", "r_M.mtx", "r_stress_K.mtx"]
    assert info["n_full"] == 3 * (len(deck.node_ids) - len(deck.clamp))
    # Full (rigid platform) and reduced eigenfrequencies in [0, 3 f_max].
    ff, fr = np.array(info["freqs_full"]), np.array(info["freqs_reduced"])
    assert len(ff) == len(fr) >= 2 and ff[-1] <= 9000
    np.testing.assert_allclose(fr, ff, rtol=1e-6)
    assert calls == [1] and not info["cached"]
    # The readable form prints both columns.
    status, out, _ = run(["reduce", d / "case.json", "--out", d / "red" / "r.json"], capsys)
    assert status == 0 and "full [Hz]" in out and "from the cache" in out and calls == [1]


def test_every_command_takes_the_fe_case(work, capsys):
    d, _, _, calls = work
    (d / "red").mkdir()
    assert run(["reduce", d / "case.json", "--out", d / "red" / "r.json"], capsys)[0] == 0
    for cmd, extra in (("backbone", ["--forces", FORCES]),
                       ("response", ["--forces", FORCES, "--freq", "2650"]),
                       ("curves", ["--forces", "0.2", "--layers", "40"]),
                       ("table", ["--gammas", "1e-6,1e-4"])):
        results = []
        for case in (d / "case.json", d / "red" / "r.json"):
            status, out, err = run([cmd, case, *extra, "--json"], capsys)
            assert status == 0, err
            results.append(json.loads(out))
        a, b = results

        def close(x, y):
            if isinstance(x, dict):
                assert x.keys() == y.keys()
                for k in x:
                    close(x[k], y[k])
            elif isinstance(x, list):
                assert len(x) == len(y)
                for u, v in zip(x, y):
                    close(u, v)
            elif isinstance(x, float) and isinstance(y, float):
                assert x == pytest.approx(y, rel=1e-12, abs=0)
            else:
                assert x == y
        close(a, b)
        if cmd == "backbone":
            assert a["points"][0]["sigma_a"] > 0 and 2400 < a["points"][0]["f_res"] < 3000
    assert calls == [1]   # one reduction for all commands


def test_cache_is_keyed_by_content(work, capsys, monkeypatch):
    d, _, case, calls = work
    args = ["backbone", d / "case.json", "--forces", FORCES, "--json"]
    assert run(args, capsys)[0] == 0 and calls == [1]
    assert run(args, capsys)[0] == 0 and calls == [1]          # second run: no reduction
    case["blade"]["zeta"] = 0.004                                 # damping is not reduced
    (d / "case.json").write_text(json.dumps(case))
    assert run(args, capsys)[0] == 0 and calls == [1]
    moved = d / "other"
    moved.mkdir()                                                 # same content elsewhere
    for name in ("blade.sti", "blade.mas", "blade.dof", "blade.inp", "case.json"):
        shutil.copy(d / name, moved / name)
    assert run(["backbone", moved / "case.json", "--forces", FORCES], capsys)[0] == 0
    assert calls == [1]
    with open(d / "blade.inp", "a") as f:                         # content changed: reduce
        f.write("** edited\n")
    assert run(args, capsys)[0] == 0 and calls == [1, 1]
    case["blade"]["excitation"]["direction"] = [1, 0.1, 0]        # input changed: reduce
    (d / "case.json").write_text(json.dumps(case))
    assert run(args, capsys)[0] == 0 and calls == [1, 1, 1]
    entries = [p for p in (d / "cache" / "fe").iterdir()]
    assert len(entries) == 3 and not any(p.name.startswith(".tmp") for p in entries)
    for p in entries:
        assert sorted(x.name for x in p.iterdir()) == ["K.mtx", "M.mtx", "reduced.json",
                                                       "stress_K.mtx"]


def test_units_mm_t_s(work, capsys):
    """The same blade exported by CalculiX in mm, t, s, N, MPa gives the same results."""
    d, deck, case, calls = work
    mm = make_deck()
    mm.xyz, mm.h = mm.xyz * 1e3, mm.h * 1e3
    sub = d / "mm"
    sub.mkdir()
    write_inp(mm, sub / "blade.inp", "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP",
              E=2.0e5, rho=7.8e-9)
    subprocess.run(["ccx", "-i", "blade"], cwd=sub, check=True, capture_output=True, timeout=100)
    mcase = json.loads(json.dumps(case))
    mcase["blade"]["units"] = "mm-t-s"
    mcase["blade"]["platform"]["ref_point"] = [x * 1e3 for x in deck.ref_point]
    mcase["blade"]["stress"]["E"] = 2.0e5
    (sub / "case.json").write_text(json.dumps(mcase))
    out = backbones([d / "case.json", sub / "case.json"], capsys)
    assert calls == [1, 1]
    a, b = out
    # Two reductions: the fixed-interface modes of this symmetric blade come in degenerate pairs,
    # so the kept subspace (and the truncation error, ~1e-8 on f1) may differ between them.
    assert b["f1_bare"] == pytest.approx(a["f1_bare"], rel=1e-7)
    for p, q in zip(a["points"], b["points"]):
        for key in ("f_res", "gamma_P", "sigma_a", "u_E"):
            assert q[key] == pytest.approx(p[key], rel=1e-5), key


def test_stress_recovery_row_equals_the_gauge(work, capsys):
    """A stress-recovery row file over the model's DOFs, here the gauge's own row (PHYSICS.md
    1.3: sigma = E ((u_b - u_a) . e) / |x_b - x_a|, checked entry by entry), gives the gauge's
    stress."""
    from udmap.fe import read_fe
    from udmap.case.fe import gauge_row
    d, deck, case, calls = work
    fe = read_fe(case["blade"], d)
    a, b = deck.gauge
    row = gauge_row(fe, a, b, 2.0e11).toarray().ravel()
    xa, xb = fe.coords(a), fe.coords(b)
    L = np.linalg.norm(xb - xa)
    e = (xb - xa) / L
    index = fe.dof_index()
    expect = np.zeros(fe.n)
    for c in range(3):
        expect[index[(a, c + 1)]] -= 2.0e11 * e[c] / L
        expect[index[(b, c + 1)]] += 2.0e11 * e[c] / L
    np.testing.assert_array_equal(row, expect)
    with open(d / "row.mtx", "w") as f:
        f.write(f"%%MatrixMarket matrix array real general\n{fe.n} 1\n")
        f.writelines(f"{v:.17g}\n" for v in row)
    rcase = json.loads(json.dumps(case))
    rcase["blade"]["stress"] = {"row": "row.mtx"}
    (d / "row.json").write_text(json.dumps(rcase))
    out = backbones([d / "case.json", d / "row.json"], capsys)
    for p, q in zip(out[0]["points"], out[1]["points"]):   # two reductions (see mm-t-s test)
        assert q["sigma_a"] == pytest.approx(p["sigma_a"], rel=1e-5)
        assert q["f_res"] == pytest.approx(p["f_res"], rel=1e-7)
    (d / "short.mtx").write_text(f"%%MatrixMarket matrix array real general\n{fe.n - 1} 1\n" +
                                 "0\n" * (fe.n - 1))
    rcase["blade"]["stress"] = {"row": "short.mtx"}
    (d / "row.json").write_text(json.dumps(rcase))
    status, _, err = run(["backbone", d / "row.json", "--forces", FORCES], capsys)
    assert status == 2 and re.search(r"blade\.stress\.row: .*short\.mtx has \d+ entries but "
                                     r"the matrices are", err), err


def test_reduce_keeps_a_table_damper_file_reachable(work, capsys):
    """A measured table damper keeps pointing at its CSV from the reduced case's directory."""
    d, _, case, _ = work
    (d / "k.csv").write_text("gamma,k_re,k_im\n1e-6,1.0e5,0\n1e-4,5.0e4,2.0e4\n1e-2,1.0e3,5.0e2\n")
    case["damper"] = {"kind": "table", "file": "k.csv"}
    (d / "case.json").write_text(json.dumps(case))
    (d / "elsewhere" / "deeper").mkdir(parents=True)
    out = d / "elsewhere" / "deeper" / "r.json"
    assert run(["reduce", d / "case.json", "--out", out], capsys)[0] == 0
    new = json.loads(out.read_text())
    assert new["damper"] == {"kind": "table", "file": "../../k.csv"}
    tables = []
    for c in (d / "case.json", out):
        status, text, err = run(["table", c, "--gammas", "1e-5,1e-3", "--json"], capsys)
        assert status == 0, err
        tables.append(json.loads(text))
    assert tables[0] == tables[1]


def test_fmu_of_the_fe_case(work, capsys, tmp_path):
    # `udmap fmu` on an fe case with blade A's asymmetric damper: the FMU holds the reduced
    # matrices blade, passes fmpy's validation, and over a sequence of F_E, mu and CF its outputs
    # are the command line's on the fe case, co-simulation and model exchange, FMI 2.0 and 3.0
    from fmpy import simulate_fmu

    from fmu_harness import CASE

    d, _, case, calls = work
    case["damper"] = json.loads(CASE.read_text())["damper"]
    (d / "asym.json").write_text(json.dumps(case))
    sequence = [(0.3, 900.0, 0.05), (0.3, 900.0, 1.0), (0.25, 900.0, 1.0), (0.25, 1200.0, 0.2)]
    ref = {}
    for mu, CF, F in sequence:
        case["damper"].update(mu=mu, CF=CF)
        (d / "one.json").write_text(json.dumps(case))
        status, out, err = run(["backbone", d / "one.json", "--forces", F, "--json"], capsys)
        assert status == 0, err
        ref[(mu, CF, F)] = json.loads(out)["points"][0]
    rows, t = [], 0.0
    for mu, CF, F in sequence:
        rows += [(t, F, mu, CF), (t + 0.5, F, mu, CF)]
        t += 0.5
    table = np.array(rows, dtype=[("time", float), ("F_E", float), ("mu", float), ("CF", float)])
    for fmi in (2, 3):
        fmu = tmp_path / f"fe{fmi}.fmu"
        status, _, err = run(["fmu", d / "asym.json", "--out", fmu, "--fmi", fmi], capsys)
        assert status == 0, err
        for kind in ("CoSimulation", "ModelExchange"):
            res = simulate_fmu(str(fmu), fmi_type=kind, stop_time=t - 1e-9, output_interval=0.25,
                               input=table, validate=True,
                               output=["F_E", "mu", "CF", "gamma_P", "sigma_a", "f_res"])
            seen = set()
            for row in res:
                key = (float(row["mu"]), float(row["CF"]), float(row["F_E"]))
                p = ref[key]
                seen.add(key)
                for name in ("gamma_P", "sigma_a", "f_res"):
                    assert row[name] == pytest.approx(p[name], rel=1e-10, abs=0), (fmi, kind, key)
            assert seen == set(ref)
    assert calls == [1]   # one reduction for every command and both FMUs (the cache)
