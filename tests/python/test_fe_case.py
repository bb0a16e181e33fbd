"""The ``fe`` case through the command line: ``udmap reduce``, every command on the ``fe`` case
directly (same results as on its reduced ``matrices`` case), the reduction done once and cached
by the content of its inputs, and bad input (exit 2 naming the field and the file, nothing
half-written). The blade is a fresh CalculiX export of the test deck."""
from __future__ import annotations

import importlib
import json
import re
import shutil
import subprocess

import numpy as np
import pytest

import fe_reference as ref
from fe_deck import make_deck, write_inp
from udmap.cli import main

ref.install()
#: The project's reduction module, or the reference stand-in until it lands.
REDUCTION = importlib.import_module("udmap.reduction")

FORCES = "0.05,0.2,1"


@pytest.fixture(scope="module")
def export(tmp_path_factory):
    d = tmp_path_factory.mktemp("fe_export")
    deck = make_deck()
    write_inp(deck, d / "blade.inp", "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP")
    subprocess.run(["ccx", "-i", "blade"], cwd=d, check=True, capture_output=True, timeout=100)
    return d, deck


def case_dict(deck):
    return {"name": "hex8 blade",
            "blade": {"kind": "fe", "format": "calculix",
                      "files": {"sti": "blade.sti", "mas": "blade.mas", "dof": "blade.dof",
                                "inp": "blade.inp"},
                      "platform": {"nodes": list(deck.platform), "ref_point": list(deck.ref_point),
                                   "axis": [0, 1, 0]},
                      "excitation": {"node": deck.exc_node, "direction": [1, 0, 0]},
                      "stress": {"gauge": list(deck.gauge), "E": 2.0e11},
                      "zeta": 0.002},
            "damper": {"kind": "jenkins", "kt": 1.0e5, "M_slip": 0.05},
            "analysis": {"f_min": 2400, "f_max": 3000}}


@pytest.fixture
def work(export, tmp_path, monkeypatch):
    """A case directory with its own copy of the export and an empty cache; counts reductions."""
    d, deck = export
    for name in ("blade.sti", "blade.mas", "blade.dof", "blade.inp"):
        shutil.copy(d / name, tmp_path / name)
    monkeypatch.setenv("UDMAP_CACHE_DIR", str(tmp_path / "cache"))
    calls = []
    real = REDUCTION.platform_centred_reduction

    def counted(*args, **kwargs):
        calls.append(1)
        return real(*args, **kwargs)
    monkeypatch.setattr(REDUCTION, "platform_centred_reduction", counted)
    case = case_dict(deck)
    (tmp_path / "case.json").write_text(json.dumps(case))
    return tmp_path, deck, case, calls


def run(args, capsys):
    status = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return status, out, err


def test_reduce_writes_a_matrices_case(work, capsys):
    d, deck, case, calls = work
    status, out, err = run(["reduce", d / "case.json", "--out", d / "red" / "r.json"], capsys)
    assert status == 2 and "--out: directory not found" in err
    (d / "red").mkdir()
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


def _edit_file(name, edit):
    def apply(d, case):
        path = d / name
        path.write_text(edit(path.read_text()))
    return apply


def _edit_case(edit):
    def apply(d, case):
        edit(case)
    return apply


def _mass_offdiag(text):
    lines = text.splitlines()
    r, c, v = lines[0].split()          # 1 1 m11; (1, 2) made 10 sqrt(m11 m22): indefinite
    return "\n".join([lines[0], f"1 2 {10 * float(v):.6e}"] +
                     [x for x in lines[1:] if x.split()[:2] != ["1", "2"]]) + "\n"


BAD = {
    "node not in the model": (
        _edit_case(lambda c: c["blade"]["platform"]["nodes"].append(999999)),
        r"blade\.platform\.nodes\[\d+\]: node 999999 is not in the model \(nodes of .*blade\.inp\)"),
    "excitation node not in the model": (
        _edit_case(lambda c: c["blade"]["excitation"].update(node=888888)),
        r"blade\.excitation\.node: node 888888 is not in the model .*blade\.inp"),
    "gauge node not in the model": (
        _edit_case(lambda c: c["blade"]["stress"].update(gauge=[1, 777777])),
        r"blade\.stress\.gauge\[1\]: node 777777 is not in the model .*blade\.inp"),
    "empty platform set": (
        _edit_case(lambda c: c["blade"]["platform"].update(nodes=[])),
        r"blade\.platform\.nodes is empty.*\[case file .*case\.json\]"),
    "empty platform box": (
        _edit_case(lambda c: (c["blade"]["platform"].pop("nodes"),
                              c["blade"]["platform"].update(box=[[1, 1, 1], [2, 2, 2]]))),
        r"blade\.platform\.box selects no node of the model \(nodes of .*blade\.inp\)"),
    "zero-length axis": (
        _edit_case(lambda c: c["blade"]["platform"].update(axis=[0, 0, 0])),
        r"blade\.platform\.axis has zero length.*\[case file .*case\.json\]"),
    "zero-length direction": (
        _edit_case(lambda c: c["blade"]["excitation"].update(direction=[0, 0, 0])),
        r"blade\.excitation\.direction has zero length"),
    "DOF map not matching the matrices": (
        _edit_file("blade.dof", lambda t: "\n".join(t.splitlines()[:-1]) + "\n"),
        r"blade\.files\.sti: .*blade\.sti refers to row \d+ but the DOF map .*blade\.dof has "
        r"\d+ rows"),
    "unsymmetric M": (
        _edit_file("blade.mas", lambda t: t + "4 1 1.0e-3\n"),
        r"blade\.files\.mas: the mass matrix is not symmetric \(.*blade\.mas\)"),
    "indefinite M (negative diagonal)": (
        _edit_file("blade.mas", lambda t: "\n".join(
            [(" ".join(x.split()[:2]) + " -1.0") if x.split()[:2] == ["5", "5"] else x
             for x in t.splitlines()]) + "\n"),
        r"blade\.files\.mas: the mass matrix is not positive definite \(.*blade\.mas\)"),
    "indefinite M (off-diagonal)": (
        _edit_file("blade.mas", _mass_offdiag),
        r"blade\.files\.mas: the mass matrix is not positive definite \(.*blade\.mas\)"),
    "gamma_P does not move in the band's mode": (
        _edit_case(lambda c: c["blade"]["platform"].update(axis=[0, 0, 1])),
        r"blade\.platform\.axis: the platform rotation gamma_P about this axis does not move in "
        r"the band's mode\(s\) at 2613\.5\d* Hz .*blade\.inp"),
    "excitation on the platform": (
        _edit_case(lambda c: c["blade"]["excitation"].update(
            node=c["blade"]["platform"]["nodes"][0])),
        r"blade\.excitation\.node: node \d+ must be a free node off the platform"),
    "missing file": (
        _edit_case(lambda c: c["blade"]["files"].update(mas="nope.mas")),
        r"blade\.files\.mas: file not found: .*nope\.mas"),
    "unknown field": (
        _edit_case(lambda c: c["blade"].update(colour="red")),
        r"blade\.colour: unknown field"),
}


@pytest.mark.parametrize("name", list(BAD))
def test_bad_input_exits_2_and_writes_nothing(work, capsys, name):
    d, _, case, calls = work
    apply, pattern = BAD[name]
    apply(d, case)
    (d / "case.json").write_text(json.dumps(case))
    (d / "red").mkdir()
    status, out, err = run(["reduce", d / "case.json", "--out", d / "red" / "r.json"], capsys)
    assert status == 2, err
    assert re.search(pattern, err), err
    assert list((d / "red").iterdir()) == []
    cache = d / "cache" / "fe"
    if cache.exists():     # only a complete entry may be there (inputs checked after it)
        assert not any(p.name.startswith(".tmp") for p in cache.iterdir())
    status, _, err2 = run(["backbone", d / "case.json", "--forces", FORCES], capsys)
    assert status == 2



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
    out = []
    for c in (d / "case.json", sub / "case.json"):
        status, text, err = run(["backbone", c, "--forces", FORCES, "--json"], capsys)
        assert status == 0, err
        out.append(json.loads(text))
    assert calls == [1, 1]
    a, b = out
    assert b["f1_bare"] == pytest.approx(a["f1_bare"], rel=1e-9)
    for p, q in zip(a["points"], b["points"]):
        for key in ("f_res", "gamma_P", "sigma_a", "u_E"):
            assert q[key] == pytest.approx(p[key], rel=1e-7), key


def test_stress_recovery_row_equals_the_gauge(work, capsys):
    """A stress-recovery row file over the model's DOFs, here the gauge's own row (PHYSICS.md
    1.3: sigma = E ((u_b - u_a) . e) / |x_b - x_a|, checked entry by entry), gives the gauge's
    stress."""
    from udmap.fe import read_fe
    from udmap.fe.case import gauge_row
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
    out = []
    for c in (d / "case.json", d / "row.json"):
        status, text, err = run(["backbone", c, "--forces", FORCES, "--json"], capsys)
        assert status == 0, err
        out.append(json.loads(text))
    for p, q in zip(out[0]["points"], out[1]["points"]):
        assert q["sigma_a"] == pytest.approx(p["sigma_a"], rel=1e-9)
        assert q["f_res"] == pytest.approx(p["f_res"], rel=1e-12)
    (d / "short.mtx").write_text(f"%%MatrixMarket matrix array real general\n{fe.n - 1} 1\n" +
                                 "0\n" * (fe.n - 1))
    rcase["blade"]["stress"] = {"row": "short.mtx"}
    (d / "row.json").write_text(json.dumps(rcase))
    status, _, err = run(["backbone", d / "row.json", "--forces", FORCES], capsys)
    assert status == 2 and re.search(r"blade\.stress\.row: .*short\.mtx has \d+ entries but "
                                     r"the matrices are", err), err
